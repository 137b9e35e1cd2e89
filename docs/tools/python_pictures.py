"""docs/PYTHON.md's pictures, from the Python module: Colin27's skull-stripped T1
(`ch2bet.nii.gz`, Debian's mricron-data: `bash data/fetch`) as Jupyter shows a scene (the
anaglyph), turned by `Camera.orbit`, and as twelve views of a Looking Glass.
Usage: python docs/tools/python_pictures.py (pip install ./python first)."""

import pathlib

import numpy as np
from PIL import Image

import autostereo as ast

ROOT = pathlib.Path(__file__).resolve().parents[2]
OUT = ROOT / "docs" / "images" / "python"


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    vol = ast.load(str(ROOT / "data" / "fetched" / "mricron" / "ch2bet.nii.gz"))
    r = ast.Renderer(ast.Display("hubner8"), size=(256, 256))
    for name, camera in [("front", ast.Camera.orbit()),
                         ("orbit_yaw-40_pitch15", ast.Camera.orbit(yaw=-40, pitch=15))]:
        image = r.preview(vol, camera=camera)
        Image.fromarray(image[..., :3]).save(OUT / f"ch2bet_anaglyph_{name}.png")
    lkg = ast.Renderer(ast.Display.from_calibration(str(ROOT / "data" / "lkg_sample_visual.json")),
                       size=(128, 128), views=12)
    views = lkg.views(vol)
    rows = [np.concatenate(list(views[k:k + 6, ..., :3]), axis=1) for k in (0, 6)]
    Image.fromarray(np.concatenate(rows, axis=0)).save(OUT / "ch2bet_views_12.png")
    print("wrote", sorted(p.name for p in OUT.iterdir()))


if __name__ == "__main__":
    main()
