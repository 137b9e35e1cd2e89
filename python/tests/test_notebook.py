"""python/examples/nifti_to_quilt.ipynb runs, cell by cell, on a small NIfTI-1 file written
here (a T1-like head: a bright shell round a darker brain), to a quilt of Looking Glass's name
and the viewer window (under Xvfb, as .ci/run runs pytest)."""

import json
import os
import struct

import numpy as np

from test_render import ROOT, head

NOTEBOOK = ROOT / "python" / "examples" / "nifti_to_quilt.ipynb"


def write_nifti(path, volume_zyx, spacing):
    """A single-file NIfTI-1 (.nii) of uint8 samples, x fastest."""
    z, y, x = volume_zyx.shape
    header = bytearray(348)
    struct.pack_into("<i", header, 0, 348)
    struct.pack_into("<8h", header, 40, 3, x, y, z, 1, 1, 1, 1)
    struct.pack_into("<hh", header, 70, 2, 8)  # datatype uint8, bitpix
    struct.pack_into("<8f", header, 76, 1.0, *spacing, 1, 1, 1, 1)
    struct.pack_into("<f", header, 108, 352.0)  # vox_offset
    struct.pack_into("<f", header, 112, 1.0)  # scl_slope
    header[344:348] = b"n+1\0"
    path.write_bytes(bytes(header) + b"\0" * 4 + volume_zyx.astype(np.uint8).tobytes())


def test_the_notebook_walks_a_nifti_scan_to_a_quilt(tmp_path, monkeypatch):
    scan = tmp_path / "head.nii"
    write_nifti(scan, (head(32) * 255).astype(np.uint8), (1.0, 1.0, 1.2))
    monkeypatch.setenv("AUTOSTEREO_ROOT", str(ROOT))
    monkeypatch.setenv("AUTOSTEREO_NIFTI", str(scan))
    monkeypatch.setenv("AUTOSTEREO_OUT", str(tmp_path))
    monkeypatch.setenv("AUTOSTEREO_FRAMES", "2")
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    scope = {}
    for cell in cells:
        if cell["cell_type"] == "code":
            exec(compile("".join(cell["source"]), str(NOTEBOOK), "exec"), scope)
    assert scope["quilt"].shape[2] == 4 and scope["views"].shape[0] == 12
    (saved,) = list(tmp_path.glob("scan_qs*.png"))
    assert saved.name == f"scan{scope['suffix']}.png"
    assert (scope["spatial"][..., :3] != 0).any(), "the scan is visible"
    assert scope["vol"]._repr_png_().startswith(b"\x89PNG")
    if os.environ.get("DISPLAY"):
        assert scope["window"].wait(timeout=60)["frames"] >= 2
