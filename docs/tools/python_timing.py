"""numpy → image in Python beside the CLI, on the same data and flags, measured in one run
(docs/PYTHON.md "Timing"): the CLI's wall time per command (process, device, load, render,
PNG) against the Python module's first render (device, upload, pipelines) and its later frames
(the prepared renderer). Usage: python docs/tools/python_timing.py [SIZE] (default 256);
needs the release CLI (cargo build --release -p autostereo-cli), `bash data/fetch` and the
module installed (pip install ./python)."""

import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

import autostereo as ast

ROOT = pathlib.Path(__file__).resolve().parents[2]
CLI = ROOT / "target" / "release" / "autostereo"
SIZE = int(sys.argv[1]) if len(sys.argv) > 1 else 256
FETCHED = ROOT / "data" / "fetched"


def nifti_array(path):
    """Colin27 as numpy (Z, Y, X), read by the library's loader is not the point here: the
    array a nibabel user holds. Read with the standard library (gzip, NIfTI-1 int16/uint8)."""
    import gzip
    import struct

    raw = gzip.open(path).read()
    dims = struct.unpack_from("<8h", raw, 40)
    datatype, _ = struct.unpack_from("<hh", raw, 70)
    pixdim = struct.unpack_from("<8f", raw, 76)
    offset = int(struct.unpack_from("<f", raw, 108)[0])
    dtype = {2: np.uint8, 4: np.int16, 16: np.float32, 512: np.uint16}[datatype]
    x, y, z = dims[1:4]
    data = np.frombuffer(raw, dtype, count=x * y * z, offset=offset).reshape(z, y, x)
    return data, tuple(float(p) for p in pixdim[1:4])


def cli_ms(args, repeats=3):
    best = []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(repeats):
            start = time.perf_counter()
            subprocess.run([str(CLI), *args, "--display", "hubner8", "--size", f"{SIZE}x{SIZE}",
                            "--out", f"{tmp}/o.png"], check=True, capture_output=True)
            best.append((time.perf_counter() - start) * 1e3)
    return min(best)


def python_ms(make, frames=5):
    start = time.perf_counter()
    scene = make()
    r = ast.Renderer(ast.Display("hubner8"), size=(SIZE, SIZE))
    r.render(scene)
    first = (time.perf_counter() - start) * 1e3
    later = []
    for k in range(frames):
        start = time.perf_counter()
        r.render(scene, camera=ast.Camera.orbit(yaw=5 * (k + 1)))
        later.append((time.perf_counter() - start) * 1e3)
    return first, float(np.median(later))


def mesh_arrays(path):
    v, f = [], []
    for line in open(path):
        if line.startswith("v "):
            v.append([float(c) for c in line.split()[1:4]])
        elif line.startswith("f "):
            f.append([int(c.split("/")[0]) - 1 for c in line.split()[1:4]])
    return np.asarray(v, np.float32), np.asarray(f, np.int64)


def main():
    rows = []
    ch2 = FETCHED / "mricron" / "ch2.nii.gz"
    vol, spacing = nifti_array(ch2)
    rows.append(("volume ch2.nii.gz " + "×".join(map(str, vol.shape[::-1])),
                 cli_ms(["volume", str(ch2), "--tf", "mri"]),
                 *python_ms(lambda: ast.Volume(vol, spacing=spacing, tf="mri"))))
    bunny = FETCHED / "bunny.obj"
    v, f = mesh_arrays(bunny)
    rows.append((f"mesh bunny.obj {len(f)} triangles", cli_ms(["mesh", str(bunny)]),
                 *python_ms(lambda: ast.Mesh(v, f))))
    rows.append((f"points bunny's {len(v)} vertices", None,
                 *python_ms(lambda: ast.Points(v))))
    print(f"hubner8 {SIZE}x{SIZE}, adapter as WGPU_BACKEND picks; ms")
    print("| data | CLI (whole command) | Python first render | Python later frames |")
    print("|---|---|---|---|")
    for name, c, first, later in rows:
        print(f"| {name} | {'—' if c is None else f'{c:.0f}'} | {first:.0f} | {later:.1f} |")


if __name__ == "__main__":
    main()
