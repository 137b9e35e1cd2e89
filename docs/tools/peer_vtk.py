#!/usr/bin/env python3
"""The renderer users would pick instead, side by side with autostereo: VTK's GPU ray-cast
volume mapper (vtkGPUVolumeRayCastMapper, VTK from PyPI, offscreen through EGL on the same Mesa
llvmpipe that autostereo's GL backend uses; lavapipe for autostereo's default Vulkan backend
is the same LLVM rasteriser) renders the same volume from the same cameras:

- the same scalars (examples/volume_raw.rs writes what autostereo loads), box, rotation
  (-90 deg about x), 512x512, 30 deg vertical field of view, focal plane through the centre;
- the same 8 view offsets with sheared (off-axis) frusta converging on the focal plane
  (vtkCamera window centre), the same transfer function control points (read from
  src/volume/transfer.rs; autostereo's opacity is per voxel of the smallest spacing, so VTK's
  scalar opacity unit distance is that voxel), sample distance half a voxel, autostereo's
  default light (eye-space direction (-0.4, 0.5, 1), ambient 0.15, diffuse 0.75, specular
  0.3, exponent 32), no multisampling;
- the peer's "N-pass": each of the 8 views rendered and read back, then the paper's display
  mask (hubner8, docs/DISPLAYS.md) picks each subpixel's view in numpy.

What cannot be matched is listed in the page it writes (DIFFERENCES below); the PSNRs it
reports (per view, shaded and unshaded) say how close the pictures are.

Writes docs/PEERS.md and docs/images/peers/*.png. Usage (repository root, after data/fetch):
    pip install vtk numpy pillow   # EGL offscreen: tested with VTK 9.7.2
    python3 docs/tools/peer_vtk.py [--frames F] [--bin-dir DIR --no-build]
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
import numpy as np  # noqa: E402
import vtk  # noqa: E402
from PIL import Image  # noqa: E402
from vtk.util import numpy_support  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
IMAGES = ROOT / "docs/images/peers"
SIZE = (512, 512)
VIEWS = 8
# The probing stride through transparent material that docs/USAGE.md suggests
# (SUGGESTED_EMPTY_STRIDE in src/volume/scene.rs): the single pass's approximate row.
STRIDE = 4
FRAME_ARGS = ["--rotate=-90,0,0", "--display", "hubner8", "--size", f"{SIZE[0]}x{SIZE[1]}"]
VOLUMES = [
    # (name, picture stem, file (None: the built-in head), transfer-function preset)
    ("brainsmall.den", "brainsmall", ROOT / "data/fetched/brainsmall.den", "mri"),
    ("head (built-in)", "head", None, "ct-skin"),
]

DIFFERENCES = """\
What differs and cannot be set the same in VTK (the unshaded PSNR shows that geometry, sampling
and transfer function agree; the shaded one adds the lighting differences):

- Classification: VTK classifies each sample (post-classification), autostereo pre-integrates
  each segment between samples; thin transfer-function features (ct-skin's skin band) come out
  differently.
- Box: VTK's box ends at the outer voxel centres, autostereo's half a voxel further out (the
  outer half voxel is nearly transparent here).
- Gradients: VTK takes central differences at every sample, autostereo a precomputed Sobel
  gradient averaged over the segment's two ends: the normals differ most where the data has
  sharp edges (the built-in head).
- Lighting: a light other than the headlight puts VTK on its multi-light path, where the
  ambient term is the light's ambient colour (white here) rather than ambient × the sample's
  colour, the specular term is Phong (reflection vector) in white rather than Blinn-Phong
  (half vector) in the sample's colour, and two-sided lighting takes |n·l| where autostereo
  turns the normal towards the eye and clamps n·l at 0."""


def preset_points(name):
    """A transfer-function preset's control points (scalar, r, g, b, a), read from the library
    source (one place to keep in sync)."""
    src = (ROOT / "src/volume/transfer.rs").read_text()
    block = src.split(f'"{name}" => vec![', 1)[1].split("],", 1)[0] + "]"
    points = []
    for m in re.finditer(r"p\(([-0-9.]+),\s*\[([^\]]*)\]\)", block):
        values = [float(x) for x in m.group(2).split(",")] if "," in m.group(2) else [0.0] * 4
        points.append((float(m.group(1)), *values))
    return points


def hubner8_views(w, h):
    """View of each subpixel (h, w, 3) on the paper's display (docs/DISPLAYS.md)."""
    x = np.arange(w)[None, :]
    y = np.arange(h)[:, None]
    xo = (3 * x) % 8
    yo = (y + 1) % 12
    v_r = ((1 + yo + yo // 3) // 2 + xo) % 8
    return np.stack([v_r, (v_r + 1) % 8, (v_r + 2) % 8], axis=-1)


def timed(frames, draw):
    """Median ms of `draw()` over `frames` calls after 2 warm-up calls, and the last result."""
    for _ in range(2):
        draw()
    times = []
    for _ in range(frames):
        t = time.perf_counter()
        result = draw()
        times.append(1000 * (time.perf_counter() - t))
    return float(np.median(times)), result


def psnr(a, b):
    mse = np.mean((a.astype(np.float64) - b.astype(np.float64)) ** 2)
    return 99.0 if mse == 0 else 10 * np.log10(255.0 ** 2 / mse)


def load_rgb(path):
    return np.asarray(Image.open(path).convert("RGB"))


class Autostereo:
    """`autostereo volume` on one volume, as the script times and pictures it."""

    def __init__(self, binary, input_args, frames):
        self.binary, self.input_args, self.frames = binary, input_args, frames
        self.adapter = None

    def run(self, method, out, *extra):
        """ms/frame (median, GPU timestamps) of `method`, its picture written to `out`."""
        cmd = [str(self.binary), "volume", *self.input_args, *FRAME_ARGS, "--method", method,
               "--frames", str(self.frames), "--out", str(out), *extra]
        text = subprocess.run(cmd, check=True, capture_output=True, text=True).stderr
        m = re.search(r"([0-9.]+) ms/frame \([^)]*\) on (.*)", text)
        self.adapter = m.group(2).strip()
        return float(m.group(1))


class Peer:
    """VTK set up like autostereo's frame of this volume."""

    def __init__(self, raw, meta, tf_points):
        dims, spacing = meta["dims"], meta["spacing"]
        extent = np.array(meta["extent"])
        data = np.fromfile(raw, dtype="<f4")
        image = vtk.vtkImageData()
        image.SetDimensions(*dims)
        image.SetSpacing(*spacing)
        # Voxel i's centre sits at (i + 0.5)·spacing − extent/2, as in autostereo's box.
        image.SetOrigin(*(-extent / 2 + np.array(spacing) / 2))
        image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(data, deep=1))
        mapper = vtk.vtkGPUVolumeRayCastMapper()
        mapper.SetInputData(image)
        mapper.AutoAdjustSampleDistancesOff()
        mapper.LockSampleDistanceToInputSpacingOff()
        voxel = min(spacing)
        mapper.SetSampleDistance(0.5 * voxel)
        colour = vtk.vtkColorTransferFunction()
        opacity = vtk.vtkPiecewiseFunction()
        for s, r, g, b, a in tf_points:
            colour.AddRGBPoint(s, r, g, b)
            opacity.AddPoint(s, a)
        self.prop = vtk.vtkVolumeProperty()
        self.prop.SetColor(colour)
        self.prop.SetScalarOpacity(opacity)
        self.prop.SetScalarOpacityUnitDistance(voxel)
        self.prop.SetInterpolationTypeToLinear()
        self.prop.ShadeOn()
        self.prop.SetAmbient(0.15)
        self.prop.SetDiffuse(0.75)
        self.prop.SetSpecular(0.3)
        self.prop.SetSpecularPower(32.0)
        volume = vtk.vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(self.prop)
        volume.RotateX(-90)
        self.renderer = vtk.vtkRenderer()
        self.renderer.SetBackground(0, 0, 0)
        self.renderer.AddVolume(volume)
        self.renderer.RemoveAllLights()
        # autostereo turns each normal towards the eye; VTK's nearest is two-sided lighting
        # (without it the far side of the translucent skin would go dark).
        self.renderer.TwoSidedLightingOn()
        light = vtk.vtkLight()
        light.SetLightTypeToCameraLight()
        light.SetPosition(-0.4, 0.5, 1.0)
        light.SetFocalPoint(0, 0, 0)
        # On VTK's multi-light path the ambient term is the property's ambient × the light's
        # ambient colour, which defaults to black.
        light.SetAmbientColor(1, 1, 1)
        self.renderer.AddLight(light)
        self.window = vtk.vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        # VTK defaults to 8× multisampling; autostereo renders one sample per pixel.
        self.window.SetMultiSamples(0)
        self.window.SetSize(*SIZE)
        self.window.AddRenderer(self.renderer)
        self.meta = meta

    def view(self, offset):
        """The camera at eye-space offset `offset`, sheared to the shared focal window."""
        m = self.meta
        cam = self.renderer.GetActiveCamera()
        cam.SetPosition(offset, 0, m["distance"])
        cam.SetFocalPoint(offset, 0, 0)
        cam.SetViewUp(0, 1, 0)
        cam.SetViewAngle(m["fov_y_degrees"])
        # The window centre is in units of the half window at the near plane, so −offset on
        # the focal plane is −offset / (distance · tan(fov/2) · aspect).
        aspect = SIZE[0] / SIZE[1]
        half = np.tan(np.radians(m["fov_y_degrees"]) / 2) * aspect
        cam.SetWindowCenter(-offset / (m["distance"] * half), 0.0)
        cam.SetClippingRange(m["near"], m["far"])

    def read(self):
        """The frame (the read-back waits for it to finish): (h, w, 3) uint8, top row first."""
        pixels = vtk.vtkUnsignedCharArray()
        self.window.GetPixelData(0, 0, SIZE[0] - 1, SIZE[1] - 1, 1, pixels, 0)
        rgb = numpy_support.vtk_to_numpy(pixels).reshape(SIZE[1], SIZE[0], 3)
        return rgb[::-1]

    def render(self):
        self.window.Render()
        return self.read()

    def batched(self, frames):
        """ms per frame of `frames` renders followed by a single read-back, after 2 warm-up
        frames: what VTK costs when nothing waits for each frame."""
        for _ in range(2):
            self.window.Render()
        t = time.perf_counter()
        for _ in range(frames):
            self.window.Render()
        self.read()
        return 1000 * (time.perf_counter() - t) / frames


def measure(name, stem, path, preset, tools, frames, tmp):
    """Time and picture one volume with both renderers; the numbers of its table column."""
    raw = tmp / f"{stem}.raw"
    meta = json.loads(subprocess.run(
        [str(tools["volume_raw"]), str(path) if path else "--builtin", str(raw), str(VIEWS),
         f"{SIZE[0]}x{SIZE[1]}"], check=True, capture_output=True, text=True).stdout)
    peer = Peer(raw, meta, preset_points(preset))
    offsets = [(i - (VIEWS - 1) / 2) * meta["separation"] for i in range(VIEWS)]
    mask = hubner8_views(*SIZE)
    rows, cols = np.meshgrid(np.arange(SIZE[1]), np.arange(SIZE[0]), indexing="ij")

    def all_views():
        views = []
        for o in offsets:
            peer.view(o)
            views.append(peer.render())
        stack = np.stack(views)  # (N, h, w, 3)
        spatial = np.stack([stack[mask[..., c], rows, cols, c] for c in range(3)], axis=-1)
        return views, spatial

    r = {"name": name, "stem": stem, "dims": meta["dims"], "vtk": {}, "ours": {},
         "load": os.getloadavg()[0]}
    peer.view(0.0)
    r["vtk"]["one"], vtk_centre = timed(frames, peer.render)
    r["vtk"]["read-back"], _ = timed(frames, peer.read)
    r["vtk"]["batched"] = peer.batched(frames)
    peer.prop.ShadeOff()
    r["vtk"]["flat"], vtk_flat = timed(frames, peer.render)
    peer.prop.ShadeOn()
    r["vtk"]["views"], (vtk_views, vtk_spatial) = timed(frames, all_views)
    r["gl"] = re.search(r"OpenGL renderer string:\s*(.*)",
                        peer.window.ReportCapabilities()).group(1).strip()

    ours = Autostereo(tools["autostereo"], ([str(path)] if path else []) + ["--tf", preset],
                      frames)
    views_dir = tmp / f"{stem}_views"
    views_dir.mkdir()
    r["ours"]["one"] = ours.run("single-view", IMAGES / f"{stem}_ours_single-view.png")
    r["ours"]["flat"] = ours.run("single-view", tmp / f"{stem}_flat.png", "--no-shading")
    r["ours"]["single-pass"] = ours.run("single-pass", IMAGES / f"{stem}_ours_single-pass.png")
    r["ours"]["stride"] = ours.run("single-pass", tmp / f"{stem}_stride.png",
                                   "--empty-stride", str(STRIDE))
    r["ours"]["n-pass"] = ours.run("n-pass", tmp / f"{stem}_npass.png")
    # Every N-pass view alone (views_dir/view_00.png …), untimed.
    ours.run("n-pass", views_dir / "view.png", "--output", "views")
    r["adapter"] = ours.adapter
    r["load"] = max(r["load"], os.getloadavg()[0])

    Image.fromarray(vtk_centre).save(IMAGES / f"{stem}_vtk_centre.png")
    Image.fromarray(vtk_spatial).save(IMAGES / f"{stem}_vtk_spatial.png")
    r["psnr"] = {
        "flat": psnr(vtk_flat, load_rgb(tmp / f"{stem}_flat.png")),
        "centre": psnr(vtk_centre, load_rgb(IMAGES / f"{stem}_ours_single-view.png")),
        "views": [psnr(v, load_rgb(views_dir / f"view_{i:02}.png"))
                  for i, v in enumerate(vtk_views)],
        "spatial": psnr(vtk_spatial, load_rgb(IMAGES / f"{stem}_ours_single-pass.png")),
        "stride": psnr(load_rgb(tmp / f"{stem}_stride.png"),
                       load_rgb(IMAGES / f"{stem}_ours_single-pass.png")),
    }
    print(json.dumps(r), file=sys.stderr)
    return r


def conclusion(r, frames):
    """Whether the 8-view single pass beats VTK's single view, and what VTK's time is made of."""
    vtk_t, ours = r["vtk"], r["ours"]
    # VTK's better timing of its single view, so that the comparison cannot favour autostereo.
    peer = min(vtk_t["one"], vtk_t["batched"])
    single_pass = ours["single-pass"]
    if single_pass < peer:
        verdict = (f"yes: autostereo's 8-view single pass ({single_pass:.0f} ms) is "
                   f"{peer / single_pass:.1f}× faster than VTK's single view ({peer:.0f} ms)")
    else:
        verdict = (f"no: autostereo's 8-view single pass ({single_pass:.0f} ms) is "
                   f"{single_pass / peer:.1f}× slower than VTK's single view ({peer:.0f} ms), "
                   f"because it traces a ray per subpixel, 3 views per pixel, "
                   f"{single_pass / ours['one']:.1f}× its own single view, while VTK's single "
                   f"view costs only {peer / ours['one']:.1f}× autostereo's")
    shading = vtk_t["one"] - vtk_t["flat"]
    ours_shading = ours["one"] - ours["flat"]
    # A difference smaller than the run-to-run spread of this machine (10-15 %) is no share.
    if ours_shading > 0.15 * ours["one"]:
        ours_part = f"{ours_shading / ours['one']:.0%} of autostereo's"
    else:
        ours_part = (f"within the noise of autostereo's ({ours['one']:.0f} ms shaded, "
                     f"{ours['flat']:.0f} unshaded)")
    return (f"**{r['name']}**: {verdict}. Shading is {shading / vtk_t['one']:.0%} of VTK's "
            f"single view ({shading:.0f} of {vtk_t['one']:.0f} ms: VTK takes the gradient by "
            f"central differences at every sample, six more trilinear fetches) and "
            f"{ours_part} (gradients precomputed in the volume texture); reading the finished frame back takes VTK "
            f"{vtk_t['read-back']:.1f} ms ({vtk_t['read-back'] / vtk_t['one']:.2%} of its single "
            f"view), and {frames} renders before one read-back cost {vtk_t['batched']:.0f} ms "
            f"per frame.")


def write(results, frames):
    vtk_version = vtk.vtkVersion.GetVTKVersion()
    command = shlex.join(["python3", "docs/tools/peer_vtk.py", *sys.argv[1:]])
    head = "| ms per frame, 512×512 | " + " | ".join(
        f"{r['name']} ({'×'.join(map(str, r['dims']))})" for r in results) + " |"
    rule = "|---|" + "---:|" * len(results)

    def row(label, value):
        return f"| {label} | " + " | ".join(value(r) for r in results) + " |"

    def para(text):
        return textwrap.fill(text, 96, break_on_hyphens=False, break_long_words=False)

    load = max(r["load"] for r in results)
    lines = [
        "# Against the renderer users would pick instead",
        "",
        para("VTK's GPU ray-cast volume mapper, the volume renderer of ParaView, 3D Slicer and "
             "most scientific viewers, renders the same volumes from the same cameras as "
             "autostereo (docs/tools/peer_vtk.py's docstring lists what is matched). This page, "
             "its numbers and pictures come from one run of"),
        "",
        f"    {command}",
        "",
        para("(repository root, after `data/fetch` and `pip install vtk numpy pillow`; without "
             f"`--bin-dir`/`--no-build` it builds target/release first). VTK {vtk_version} on "
             f"{results[0]['gl']} (OpenGL through EGL, offscreen); autostereo on "
             f"{results[0]['adapter']}: the same LLVM rasteriser on the same "
             f"{os.cpu_count()} CPU cores (highest 1-minute load average seen during the run: "
             f"{load:.1f}). {SIZE[0]}×{SIZE[1]}, the paper's 8-view display (hubner8), median "
             f"of {frames} frames after 2 warm-up frames. VTK's times are wall time of "
             "`Render()` plus the read-back of the frame (which waits for it to finish); "
             "autostereo's are GPU timestamps of the frame. The peer has no single-pass "
             "multi-view renderer: for the display it renders each of the 8 views, reads each "
             "back and interleaves them with the display mask in numpy (timed with it)."),
        "",
        head,
        rule,
        row("VTK, one view (render + read-back)", lambda r: f"{r['vtk']['one']:.0f}"),
        row("VTK, the read-back alone", lambda r: f"{r['vtk']['read-back']:.1f}"),
        row(f"VTK, one view ({frames} renders, then one read-back; per frame)",
            lambda r: f"{r['vtk']['batched']:.0f}"),
        row("VTK, one view, unshaded", lambda r: f"{r['vtk']['flat']:.0f}"),
        row("VTK, 8 views + mask (spatial image)", lambda r: f"{r['vtk']['views']:.0f}"),
        row("autostereo, single view", lambda r: f"{r['ours']['one']:.0f}"),
        row("autostereo, single view, unshaded", lambda r: f"{r['ours']['flat']:.0f}"),
        row("autostereo, single pass (8 views, spatial image)",
            lambda r: f"{r['ours']['single-pass']:.0f}"),
        row(f"autostereo, single pass with `--empty-stride {STRIDE}` (approximate; PSNR against "
            "the exact single pass in brackets)",
            lambda r: f"{r['ours']['stride']:.0f} ({r['psnr']['stride']:.1f} dB)"),
        row("autostereo, N-pass (8 views + mask)", lambda r: f"{r['ours']['n-pass']:.0f}"),
        "",
        "Is autostereo's 8-view single pass faster than VTK's single view of the same volume?",
        "",
    ]
    lines += [line for r in results for line in [para(conclusion(r, frames)), ""]]
    lines += [
        "How close the pictures are (PSNR, VTK against autostereo):",
        "",
        head.replace("ms per frame, 512×512", "PSNR, dB"),
        rule,
        row("centre view, unshaded (emission–absorption)", lambda r: f"{r['psnr']['flat']:.1f}"),
        row("centre view, shaded", lambda r: f"{r['psnr']['centre']:.1f}"),
        row("views 0–7, shaded (VTK's against autostereo's N-pass views)",
            lambda r: "–".join(f"{f(r['psnr']['views']):.1f}" for f in (min, max))),
        row("spatial image (VTK 8 views + mask against autostereo's single pass)",
            lambda r: f"{r['psnr']['spatial']:.1f}"),
        "",
        DIFFERENCES,
        "",
    ]
    for r in results:
        stem = r["stem"]
        lines += [
            f"### {r['name']}", "",
            "| VTK, centre view | autostereo, centre view (single view) |", "|---|---|",
            f"| ![](images/peers/{stem}_vtk_centre.png) | "
            f"![](images/peers/{stem}_ours_single-view.png) |",
            "| **VTK, 8 views + mask (spatial image)** | "
            "**autostereo single pass (spatial image)** |",
            f"| ![](images/peers/{stem}_vtk_spatial.png) | "
            f"![](images/peers/{stem}_ours_single-pass.png) |", ""]
    (ROOT / "docs/PEERS.md").write_text("\n".join(lines))
    print("wrote docs/PEERS.md", file=sys.stderr)


def tools_in(bin_dir):
    """autostereo and volume_raw in `bin_dir` (volume_raw also in its examples/)."""
    tools = {"autostereo": bin_dir / "autostereo"}
    tools["volume_raw"] = next(
        (p for p in [bin_dir / "volume_raw", bin_dir / "examples/volume_raw"] if p.is_file()),
        None)
    missing = [name for name, p in tools.items() if p is None or not p.is_file()]
    if missing:
        sys.exit(f"{', '.join(missing)} not found in {bin_dir} (or its examples/)")
    return tools


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--bin-dir", type=Path, default=ROOT / "target/release",
                        help="where autostereo and volume_raw (or examples/volume_raw) are")
    parser.add_argument("--no-build", action="store_true",
                        help="use the binaries in --bin-dir as they are (no cargo build)")
    opts = parser.parse_args()
    if not opts.no_build:
        subprocess.run(["cargo", "build", "--release", "--quiet", "--bin", "autostereo",
                        "--example", "volume_raw"], cwd=ROOT, check=True)
    tools = tools_in(opts.bin_dir)
    IMAGES.mkdir(parents=True, exist_ok=True)
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, stem, path, preset in VOLUMES:
            if path and not path.is_file():
                print(f"{name}: not found (run data/fetch): skipped", file=sys.stderr)
                continue
            results.append(measure(name, stem, path, preset, tools, opts.frames, Path(tmp)))
    write(results, opts.frames)


if __name__ == "__main__":
    main()
