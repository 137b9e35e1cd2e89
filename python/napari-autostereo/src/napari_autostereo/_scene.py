"""A napari layer as an autostereo scene, and napari's 3D camera as an autostereo camera.

napari's world axes are (…, z, y, x); autostereo's (and vispy's, which draws napari's canvas)
are (x, y, z): the same space written in the other order, so directions reverse their
components and nothing is mirrored."""

import math

import numpy as np

import autostereo as ast


def _xyz(v):
    """napari's (z, y, x) (the last three of an N-d vector) as (x, y, z)."""
    v = np.asarray(v, dtype=float)[-3:]
    return tuple(float(c) for c in v[::-1])


def scene_of(layer):
    """The scene of `layer`: an Image layer's 3D data (its last three axes, at the current
    slice of any others) as a Volume with the layer's scale as spacing; a Points layer's
    positions as Points (the face colours as colours)."""
    import napari.layers

    if isinstance(layer, napari.layers.Image):
        data = np.asarray(layer.data)
        if data.ndim < 3 or layer.rgb:
            raise ValueError(f"layer {layer.name!r}: a 3D scalar image is needed, not {data.shape}")
        while data.ndim > 3:
            data = data[0]
        spacing = _xyz(layer.scale)
        return ast.Volume(np.ascontiguousarray(data), spacing=spacing)
    if isinstance(layer, napari.layers.Points):
        data = np.asarray(layer.data, dtype=np.float64)
        if data.ndim != 2 or data.shape[1] < 3 or len(data) == 0:
            raise ValueError(f"layer {layer.name!r}: 3D points are needed, not {data.shape}")
        positions = data[:, -3:][:, ::-1] * np.asarray(layer.scale[-3:][::-1])
        colors = np.asarray(layer.face_color)[:, :3] if len(layer.face_color) == len(data) else None
        return ast.Points(positions, colors=colors)
    raise ValueError(f"layer {layer.name!r}: an Image or Points layer is needed, "
                     f"not {type(layer).__name__}")


def camera_of(viewer, layer, fov=30.0):
    """An autostereo camera looking as napari's 3D camera does: along its view direction, its
    up direction up, at the layer's centre, from the distance that fits the layer's extent in
    `fov` degrees."""
    scene = getattr(viewer, "scene", None)  # napari ≥ 0.9 moved the camera there
    cam = getattr(scene, "camera", None) or viewer.camera
    view = np.asarray(_xyz(cam.view_direction))
    up = _xyz(cam.up_direction)
    extent = np.asarray(layer.extent.world, dtype=float)[:, -3:][:, ::-1]  # (min, max) as x, y, z
    centre = extent.mean(axis=0)
    radius = 0.5 * float(np.linalg.norm(extent[1] - extent[0])) or 1.0
    distance = radius / math.sin(math.radians(fov) / 2)
    eye = centre - view / (np.linalg.norm(view) or 1.0) * distance
    return ast.Camera(look_from=tuple(map(float, eye)), look_at=tuple(map(float, centre)),
                      up=up, fov=fov)
