"""napari plugin: the current 3D image or points layer rendered for an autostereoscopic
display by autostereo, following napari's camera: to the viewer window on the panel, or to a
Looking Glass quilt file."""

import os

# napari's canvas owns the process's OpenGL contexts; wgpu's GL backend then fails to make its
# own EGL context current (BadAccess, a panic inside wgpu-hal), so the plugin renders on Vulkan
# unless the user chose a backend (docs/PYTHON.md "napari").
os.environ.setdefault("WGPU_BACKEND", "vulkan")

from ._scene import camera_of, scene_of
from ._widget import AutostereoWidget

__all__ = ["AutostereoWidget", "camera_of", "scene_of"]
