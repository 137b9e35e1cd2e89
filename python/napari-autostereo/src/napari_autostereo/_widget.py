"""The dock widget "Render to autostereo display": the selected (else the top) 3D image or
points layer, through napari's camera, to the viewer window on the panel or to a quilt file."""

import pathlib

from qtpy.QtWidgets import (QComboBox, QFormLayout, QLabel, QLineEdit, QPushButton, QSpinBox,
                            QWidget)

import autostereo as ast

from ._scene import camera_of, scene_of


class AutostereoWidget(QWidget):
    """Display spec, size and method; buttons to open the window or write the quilt."""

    def __init__(self, napari_viewer):
        super().__init__()
        self.viewer = napari_viewer
        self.display = QLineEdit("hubner8")
        self.width_ = QSpinBox(maximum=16384, value=512)
        self.height_ = QSpinBox(maximum=16384, value=512)
        self.method = QComboBox()
        self.method.addItems(["single-pass", "npass", "tiled"])
        self.quilt_path = QLineEdit("quilt.png")
        self.status = QLabel("")
        show = QPushButton("Show on the display")
        show.clicked.connect(self.show_window)
        quilt = QPushButton("Write the quilt")
        quilt.clicked.connect(self.write_quilt)
        form = QFormLayout(self)
        form.addRow("display", self.display)
        form.addRow("width", self.width_)
        form.addRow("height", self.height_)
        form.addRow("method", self.method)
        form.addRow(show)
        form.addRow("quilt file", self.quilt_path)
        form.addRow(quilt)
        form.addRow(self.status)
        self.window = None

    def layer(self):
        """The selected layer, else the top one."""
        layers = self.viewer.layers
        chosen = layers.selection.active or (layers[-1] if len(layers) else None)
        if chosen is None:
            raise ValueError("no layer to render")
        return chosen

    def _parts(self):
        layer = self.layer()
        size = (self.width_.value(), self.height_.value())
        renderer = ast.Renderer(ast.Display(self.display.text()), size=size,
                                method=self.method.currentText())
        return layer, scene_of(layer), camera_of(self.viewer, layer), renderer, size

    def render(self):
        """The spatial image of the layer through napari's camera, (H, W, 4) uint8."""
        _, scene, camera, renderer, _ = self._parts()
        return renderer.render(scene, camera=camera)

    def write_quilt(self):
        """The layer's quilt, saved under Looking Glass's name (`…_qs{c}x{r}a{aspect}.png`)."""
        from PIL import Image

        _, scene, camera, renderer, _ = self._parts()
        quilt, suffix = renderer.quilt(scene, camera=camera)
        path = pathlib.Path(self.quilt_path.text())
        path = path.with_name(path.stem + suffix + ".png")
        Image.fromarray(quilt[..., :3]).save(path)
        self.status.setText(f"wrote {path}")
        return path

    def show_window(self, frames=None):
        """The viewer window on the layer (non-blocking); `frames` closes it after so many."""
        _, scene, camera, _, size = self._parts()
        self.window = ast.show(scene, display=self.display.text(), size=size,
                               method=self.method.currentText(), camera=camera,
                               frames=frames or None)
        self.status.setText("window open")
        return self.window
