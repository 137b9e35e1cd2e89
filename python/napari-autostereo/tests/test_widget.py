"""The widget headless (QT_QPA_PLATFORM=offscreen, under Xvfb for the window): a 3D image layer
and a points layer render as autostereo renders the same numpy data through the same camera;
the quilt file gets Looking Glass's name; the window opens on the layer."""

import numpy as np

import autostereo as ast
from napari_autostereo import AutostereoWidget, camera_of


def head(n=24):
    z, y, x = np.mgrid[0:n - 4, 0:n, 0:n + 4].astype(np.float32)
    r = np.sqrt((x - (n + 4) / 2) ** 2 + (y - n / 2) ** 2 + (z - (n - 4) / 2) ** 2)
    return np.where(r < 6, 0.35, np.where(r < 8, 0.9, 0.05)).astype(np.float32)


def test_the_widget_renders_a_layer_as_the_renderer_does(make_napari_viewer, tmp_path):
    viewer = make_napari_viewer()
    viewer.dims.ndisplay = 3
    data = head()
    layer = viewer.add_image(data, scale=(1.2, 1.0, 1.0))
    viewer.camera.angles = (10, -30, 80)
    widget = AutostereoWidget(viewer)
    widget.width_.setValue(64)
    widget.height_.setValue(48)
    image = widget.render()
    camera = camera_of(viewer, layer)
    expected = ast.Renderer(ast.Display("hubner8"), size=(64, 48)).render(
        ast.Volume(data, spacing=(1.0, 1.0, 1.2)), camera=camera)
    assert (image[..., :3] != 0).any(), "the layer is visible"
    np.testing.assert_array_equal(image, expected)
    viewer.camera.angles = (0, 0, 90)
    assert (widget.render() != image).any(), "the render follows napari's camera"

    widget.quilt_path.setText(str(tmp_path / "layer.png"))
    path = widget.write_quilt()
    assert path.name.startswith("layer_qs") and path.is_file()

    rng = np.random.default_rng(1)
    points = rng.normal(size=(300, 3))
    points /= np.linalg.norm(points, axis=1, keepdims=True)
    player = viewer.add_points(points * 10, size=1)
    image = widget.render()
    expected = ast.Renderer(ast.Display("hubner8"), size=(64, 48)).render(
        ast.Points(points[:, ::-1] * 10, colors=np.asarray(player.face_color)[:, :3]),
        camera=camera_of(viewer, player))
    np.testing.assert_array_equal(image, expected)

    window = widget.show_window(frames=2)
    assert window.wait(timeout=120)["frames"] >= 2
