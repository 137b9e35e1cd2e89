"""`autostereo.show` opens the viewer window without blocking the caller and reports what it
showed; its screenshot of the spatial preview is the renderer's image of the same frame (the
window at the panel's origin). Needs a window system: .ci/run runs pytest under Xvfb."""

import os

import numpy as np
import pytest

import autostereo as ast
from test_render import read_png, torus


def test_show_returns_at_once_and_its_window_shows_the_scene(tmp_path):
    assert os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"), (
        "no window system: run under xvfb-run -a (as .ci/run does)")
    vertices, faces = torus()
    mesh = ast.Mesh(vertices, faces)
    shot = tmp_path / "shot.png"
    window = ast.show(mesh, display="hubner8", size=(64, 48), frames=3, screenshot=str(shot))
    report = window.wait(timeout=120)
    assert window.closed
    assert report["frames"] >= 3 and report["primitive"] == "mesh"
    assert report["window_size"] == [64, 48]
    image = read_png(shot)
    assert image.shape == (48, 64, 3) and (image != 0).any()
    expected = ast.Renderer(ast.Display("hubner8"), size=(64, 48)).render(mesh)
    np.testing.assert_array_equal(image, expected[..., :3])
    # A second window on the same event loop, turned by an orbit, in the anaglyph preview.
    again = ast.show(mesh, size=(64, 48), frames=2, preview="anaglyph",
                     camera=ast.Camera.orbit(pitch=30))
    assert again.wait(timeout=120)["frames"] >= 2
    with pytest.raises(ValueError, match="unknown preview"):
        ast.show(mesh, preview="hologram")
