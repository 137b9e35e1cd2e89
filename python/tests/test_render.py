"""The Python module against the CLI: a numpy volume renders bit for bit as `autostereo
volume` renders the same samples written to a raw file with the same flags; bad input raises
the right exception with the library's message; a renderer's second frame reuses its prepared
state (the times are printed, not asserted)."""

import os
import pathlib
import subprocess
import time

import numpy as np
import pytest

import autostereo as ast

ROOT = pathlib.Path(__file__).resolve().parents[2]


def cli():
    """The CLI binary: $AUTOSTEREO_BIN, else the workspace's release or debug build."""
    given = os.environ.get("AUTOSTEREO_BIN")
    candidates = [pathlib.Path(given)] if given else [
        ROOT / "target" / "release" / "autostereo",
        ROOT / "target" / "debug" / "autostereo",
    ]
    for path in candidates:
        if path.is_file():
            return str(path)
    raise AssertionError(
        f"no autostereo binary at {[str(c) for c in candidates]}: `cargo build -p autostereo-cli` "
        "first, or set AUTOSTEREO_BIN"
    )


def read_png(path):
    from PIL import Image

    return np.asarray(Image.open(path).convert("RGB"))


def head(n=24):
    """A sphere of 'tissue' in a shell of 'bone' in air, (Z, Y, X) float32, not cubic."""
    z, y, x = np.mgrid[0:n - 4, 0:n, 0:n + 4].astype(np.float32)
    r = np.sqrt((x - (n + 4) / 2) ** 2 + (y - n / 2) ** 2 + (z - (n - 4) / 2) ** 2)
    v = np.where(r < 6, 0.35, np.where(r < 8, 0.9, 0.05)).astype(np.float32)
    return v


@pytest.mark.parametrize("dtype", [np.float32, np.uint8, np.int16])
def test_a_numpy_volume_renders_as_the_cli_renders_its_raw_file(tmp_path, dtype):
    v = head()
    if dtype == np.uint8:
        v = (v * 255).astype(np.uint8)
    elif dtype == np.int16:
        v = (v * 4000 - 1000).astype(np.int16)
    spacing = (1.0, 1.5, 2.0)
    raw = tmp_path / "head.raw"
    v.tofile(raw)
    png = tmp_path / "cli.png"
    z, y, x = v.shape
    kind = {np.float32: "f32", np.uint8: "u8", np.int16: "i16"}[dtype]
    subprocess.run(
        [cli(), "volume", str(raw), "--raw-dims", f"{x},{y},{z}", "--raw-type", kind,
         "--spacing", ",".join(map(str, spacing)), "--display", "hubner8", "--size", "64x48",
         "--out", str(png)],
        check=True, capture_output=True,
    )
    image = ast.Renderer(ast.Display("hubner8"), size=(64, 48)).render(
        ast.Volume(v, spacing=spacing)
    )
    assert image.shape == (48, 64, 4) and image.dtype == np.uint8
    assert (image[..., 3] == 255).all()
    expected = read_png(png)
    assert (image[..., :3] != 0).any(), "the volume is visible"
    np.testing.assert_array_equal(image[..., :3], expected)


def test_bad_input_raises_the_right_exception_with_the_librarys_message():
    with pytest.raises(TypeError, match="real numbers"):
        ast.Volume(np.zeros((4, 4, 4), np.complex64))
    with pytest.raises(ValueError, match="3-dimensional"):
        ast.Volume(np.zeros((4, 4), np.float32))
    with pytest.raises(ValueError, match="dimension"):
        ast.Volume(np.zeros((0, 4, 4), np.float32))
    with pytest.raises(ValueError, match="unknown preset"):
        ast.Volume(np.zeros((4, 4, 4), np.float32), tf="nope")
    with pytest.raises(ValueError, match="display"):
        ast.Display("no-such-display:3")
    with pytest.raises(ValueError, match="unknown method"):
        ast.Renderer(ast.Display("hubner8"), size=(32, 32), method="fastest")


def test_a_second_frame_reuses_the_prepared_renderer():
    r = ast.Renderer(ast.Display("hubner8"), size=(64, 64))
    vol = ast.Volume(head())
    times = []
    for _ in range(2):
        start = time.perf_counter()
        image = r.render(vol)
        times.append(time.perf_counter() - start)
    print(f"first frame {times[0] * 1e3:.1f} ms (upload, pipelines), second {times[1] * 1e3:.1f} ms")
    assert image.shape == (64, 64, 4)


def torus(n=24, m=12):
    """A torus, (V, 3) float32 vertices and (F, 3) int64 faces."""
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, n, endpoint=False),
                       np.linspace(0, 2 * np.pi, m, endpoint=False), indexing="ij")
    x = (1 + 0.4 * np.cos(v)) * np.cos(u)
    y = 0.4 * np.sin(v)
    z = (1 + 0.4 * np.cos(v)) * np.sin(u)
    vertices = np.stack([x, y, z], -1).reshape(-1, 3).astype(np.float32)
    faces = []
    for i in range(n):
        for j in range(m):
            a, b = i * m + j, ((i + 1) % n) * m + j
            c, d = ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
            faces += [(a, b, c), (a, c, d)]
    return vertices, np.array(faces, np.int64)


def write_obj(path, vertices, faces):
    with open(path, "w") as f:
        for p in vertices:
            f.write("v " + " ".join(repr(float(c)) for c in p) + "\n")
        for t in faces:
            f.write("f " + " ".join(str(i + 1) for i in t) + "\n")


def cli_render(tmp_path, command, path, display="hubner8", size="64x48"):
    png = tmp_path / f"{command}.png"
    subprocess.run([cli(), command, str(path), "--display", display, "--size", size,
                    "--out", str(png)], check=True, capture_output=True)
    return read_png(png)


def test_a_numpy_mesh_and_a_loaded_file_render_as_the_cli_renders_the_obj(tmp_path):
    vertices, faces = torus()
    obj = tmp_path / "torus.obj"
    write_obj(obj, vertices, faces)
    expected = cli_render(tmp_path, "mesh", obj)
    r = ast.Renderer(ast.Display("hubner8"), size=(64, 48))
    mesh = ast.Mesh(vertices, faces)
    assert mesh.triangles == len(faces) and mesh.kind == "mesh"
    image = r.render(mesh)
    assert (image[..., :3] != 0).any()
    np.testing.assert_array_equal(image[..., :3], expected)
    loaded = ast.load(str(obj))
    assert loaded.kind == "mesh"
    np.testing.assert_array_equal(r.render(loaded)[..., :3], expected)


def test_numpy_points_render_as_the_cli_renders_the_ply(tmp_path):
    rng = np.random.default_rng(7)
    p = rng.normal(size=(400, 3))
    p = (p / np.linalg.norm(p, axis=1, keepdims=True)).astype(np.float32)
    ply = tmp_path / "ball.ply"
    with open(ply, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(p)}\n"
                "property float x\nproperty float y\nproperty float z\nend_header\n")
        for q in p:
            f.write(" ".join(repr(float(c)) for c in q) + "\n")
    expected = cli_render(tmp_path, "points", ply)
    points = ast.Points(p)
    assert len(points) == 400
    image = ast.Renderer(ast.Display("hubner8"), size=(64, 48)).render(points)
    assert (image[..., :3] != 0).any()
    np.testing.assert_array_equal(image[..., :3], expected)


def test_bad_geometry_raises_with_the_librarys_message():
    vertices, faces = torus(6, 4)
    with pytest.raises(ValueError, match=r"\(N, 3\)"):
        ast.Mesh(vertices[:, :2], faces)
    with pytest.raises(ValueError, match="not a vertex"):
        ast.Mesh(vertices, faces + len(vertices))
    bad = vertices.copy()
    bad[0, 0] = np.nan
    with pytest.raises(ValueError, match="finite|NaN|non-finite"):
        ast.Mesh(bad, faces)
    with pytest.raises(TypeError, match="real numbers"):
        ast.Points(np.zeros((4, 3), np.complex64))
    with pytest.raises(OSError):
        ast.load("/no/such/file.obj")


def test_a_calibration_and_the_one_call_form_are_the_same_display_and_image():
    calibration = ROOT / "data" / "lkg_sample_visual.json"
    a = ast.Display.from_calibration(str(calibration))
    b = ast.Display(f"lkg:{calibration}")
    assert a.views == b.views > 1
    with pytest.raises(ValueError, match="no-such.json"):
        ast.Display.from_calibration("/no-such.json")
    vertices, faces = torus()
    mesh = ast.Mesh(vertices, faces)
    one_call = ast.render(mesh, display="lenticular:4", size=(48, 32))
    expected = ast.Renderer(ast.Display("lenticular:4"), size=(48, 32)).render(mesh)
    np.testing.assert_array_equal(one_call, expected)
