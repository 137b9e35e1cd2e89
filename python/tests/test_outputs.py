"""Quilts, views, stereo previews, cameras and Gaussians from Python against the CLI: each
equals the CLI's `--output` of the same data with the same flags, bit for bit; an orbit turns
the camera as the sides say; Jupyter's picture is the preview's PNG."""

import io
import struct
import subprocess

import numpy as np
import pytest

import autostereo as ast
from test_render import cli, read_png, torus, write_obj


def cli_out(tmp_path, command, path, *flags, name="out.png"):
    out = tmp_path / name
    subprocess.run([cli(), command, str(path), "--display", "hubner8", "--size", "64x48",
                    "--out", str(out), *flags], check=True, capture_output=True)
    return out


@pytest.fixture()
def torus_obj(tmp_path):
    vertices, faces = torus()
    obj = tmp_path / "torus.obj"
    write_obj(obj, vertices, faces)
    return obj, ast.Mesh(vertices, faces)


def renderer():
    return ast.Renderer(ast.Display("hubner8"), size=(64, 48))


def test_the_quilt_equals_the_clis_output_quilt(tmp_path, torus_obj):
    obj, mesh = torus_obj
    cli_out(tmp_path, "mesh", obj, "--output", "quilt", name="q.png")
    (written,) = list(tmp_path.glob("q_qs*.png"))
    quilt, suffix = renderer().quilt(mesh)
    assert written.name == f"q{suffix}.png"
    np.testing.assert_array_equal(quilt[..., :3], read_png(written))
    grid, suffix = renderer().quilt(mesh, grid=(2, 4))
    assert suffix.startswith("_qs2x4"), suffix
    with pytest.raises(ValueError, match="grid|quilt"):
        renderer().quilt(mesh, grid=(1, 2))


def test_the_views_equal_the_clis_output_views(tmp_path, torus_obj):
    obj, mesh = torus_obj
    cli_out(tmp_path, "mesh", obj, "--output", "views", name="v.png")
    views = renderer().views(mesh)
    assert views.shape == (8, 48, 64, 4)
    for v in range(8):
        np.testing.assert_array_equal(views[v, ..., :3], read_png(tmp_path / f"v_{v:02}.png"))
    assert (views[0] != views[7]).any(), "the views differ"


def test_the_preview_equals_the_clis_stereo_output(tmp_path, torus_obj):
    obj, mesh = torus_obj
    for fmt, flags in [("anaglyph-dubois", []), ("side-by-side", ["--eyes", "1,6"])]:
        out = cli_out(tmp_path, "mesh", obj, "--output", fmt, *flags, name=f"{fmt}.png")
        eyes = (1, 6) if flags else None
        image = renderer().preview(mesh, format=fmt, eyes=eyes)
        np.testing.assert_array_equal(image[..., :3], read_png(out))
    with pytest.raises(ValueError, match="unknown stereo format"):
        renderer().preview(mesh, format="wiggle")
    with pytest.raises(ValueError, match="views 0 to 7"):
        renderer().preview(mesh, eyes=(0, 8))


def test_jupyter_shows_the_scene_as_an_anaglyph_png(torus_obj):
    from PIL import Image

    _, mesh = torus_obj
    png = mesh._repr_png_()
    image = np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))
    expected = ast.Renderer(ast.Display("hubner8"), size=(480, 360)).preview(mesh)
    np.testing.assert_array_equal(image, expected[..., :3])


def test_cameras_equal_the_clis_camera_flags(tmp_path, torus_obj):
    obj, mesh = torus_obj
    r = renderer()
    for camera, flags in [
        (ast.Camera(look_from=(1.0, 2.5, 4.0)), ["--look-from", "1,2.5,4"]),
        (ast.Camera(view="right", fov=40), ["--view", "right", "--fov", "40"]),
        (ast.Camera(baseline=0.6, focal_scale=0.9), ["--baseline", "0.6", "--focal-scale", "0.9"]),
        (ast.Camera(model="toe-in"), ["--camera", "toe-in"]),
    ]:
        out = cli_out(tmp_path, "mesh", obj, *flags, name="camera.png")
        np.testing.assert_array_equal(r.render(mesh, camera=camera)[..., :3], read_png(out),
                                      err_msg=str(flags))
    with pytest.raises(ValueError, match="fov"):
        ast.Camera(fov=180)
    with pytest.raises(ValueError, match="view"):
        ast.Camera(view="under")
    with pytest.raises(ValueError, match="give one"):
        ast.Camera(separation=0.1, baseline=0.5)


def test_an_orbit_turns_the_framing_as_the_sides_say(torus_obj):
    _, mesh = torus_obj
    r = renderer()
    front = r.render(mesh)
    np.testing.assert_array_equal(r.render(mesh, camera=ast.Camera.orbit()), front)
    for (yaw, pitch), side in [((90, 0), "right"), ((-90, 0), "left"), ((0, 90), "top")]:
        turned = r.render(mesh, camera=ast.Camera.orbit(yaw=yaw, pitch=pitch))
        expected = r.render(mesh, camera=ast.Camera(view=side))
        # The same camera up to rounding (a rotation by 90° is not exact in floats).
        off = np.abs(turned.astype(int) - expected.astype(int)) > 2
        assert off.mean() < 0.01, f"{side}: {off.mean():.2%} of subpixels differ"
    # The torus turns into itself about y; a pitch shows it turned.
    assert (r.render(mesh, camera=ast.Camera.orbit(pitch=30)) != front).any()
    closer = r.render(mesh, camera=ast.Camera.orbit(zoom=1))
    assert (closer[..., :3] != 0).sum() > (front[..., :3] != 0).sum(), "zoom 1 is closer"


def write_splat(path, positions, scales, colors, opacities, rotations):
    with open(path, "wb") as f:
        for p, s, c, a, q in zip(positions, scales, colors, opacities, rotations):
            f.write(struct.pack("<6f", *p, *s))
            f.write(bytes([*c, a, *q]))


def test_numpy_gaussians_render_as_the_cli_renders_their_splat_file(tmp_path):
    rng = np.random.default_rng(3)
    n = 300
    positions = rng.normal(size=(n, 3)).astype(np.float32)
    scales = rng.uniform(0.05, 0.2, size=(n, 3)).astype(np.float32)
    colors = rng.integers(0, 256, size=(n, 3), dtype=np.uint8)
    alpha = rng.integers(64, 256, size=n, dtype=np.uint8)
    quat = rng.integers(0, 256, size=(n, 4), dtype=np.uint8)
    quat[:, 0] = 255  # keep w away from zero
    splat = tmp_path / "cloud.splat"
    write_splat(splat, positions, scales, colors, alpha, quat)
    out = cli_out(tmp_path, "gaussians", splat, name="g.png")
    gs = ast.Gaussians(positions, scales, (quat.astype(np.float64) - 128) / 128,
                       alpha / 255.0, colors=colors / 255.0)
    assert len(gs) == n and gs.kind == "gaussians"
    image = renderer().render(gs)
    assert (image[..., :3] != 0).any()
    np.testing.assert_array_equal(image[..., :3], read_png(out))
    np.testing.assert_array_equal(renderer().render(ast.load(str(splat))), image)
    sh = np.zeros((n, 4, 3), np.float32)
    assert len(ast.Gaussians(positions, scales, quat / 255.0, alpha / 255.0, sh=sh)) == n
    with pytest.raises(ValueError, match="rotation"):
        ast.Gaussians(positions, scales, np.zeros((n, 4)), alpha / 255.0)
    with pytest.raises(ValueError, match="opacit"):
        ast.Gaussians(positions, scales, quat / 255.0, np.full(n, 2.0))
    with pytest.raises(ValueError, match="K = 1, 4, 9 or 16"):
        ast.Gaussians(positions, scales, quat / 255.0, alpha / 255.0, sh=np.zeros((n, 3, 3)))


def test_a_renderer_takes_a_looking_glass_view_count():
    from test_render import ROOT

    display = ast.Display.from_calibration(str(ROOT / "data" / "lkg_sample_visual.json"))
    r = ast.Renderer(display, size=(96, 64), views=12)
    assert r.view_count == 12
    vertices, faces = torus(8, 6)
    assert r.views(ast.Mesh(vertices, faces)).shape == (12, 64, 96, 4)
    with pytest.raises(ValueError, match="views"):
        ast.Renderer(ast.Display("hubner8"), size=(32, 32), views=5)
