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
