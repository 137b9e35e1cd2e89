#!/usr/bin/env python3
"""Regenerate docs/images/cameras and print the table of docs/DESIGN.md §2 "Camera models".

A 5×4 grid of white squares on the focal plane, seen by the outermost views (0 and 7 of 8) of
each camera model, rendered by the CLI (`mesh --display view:8,V --camera MODEL`); each
square's centroid is measured in both views and the table gives the largest vertical and
horizontal parallax between them (pixels), and the keystone: how much taller the grid's right
column is than its left one in view 0. A red-cyan anaglyph of the two views per model shows it.

Usage: python3 docs/tools/camera_pictures.py   (from the repository root; BIN= another build)
"""
import os
import subprocess
import sys

import numpy as np
from PIL import Image

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
OUT = os.path.join(ROOT, "docs", "images", "cameras")
BIN = os.environ.get("BIN") or os.path.join(ROOT, "target", "release", "autostereo")
SIZE = (320, 240)
COLS, ROWS = 5, 4
SEPARATION = "0.35"  # scene units; the grid is 10 × 7.5 units


def grid_obj(path):
    """COLS × ROWS squares of side 0.8 on z = 0, spaced 2 units, plus a speck at z = ±1 so
    that the framing (focal plane through the bounds' centre) puts the focal plane on z = 0."""
    lines, n = [], 0

    def quad(x0, y0, x1, y1, z):
        nonlocal n
        for x, y in [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]:
            lines.append(f"v {x} {y} {z}")
        lines.append(f"f {n + 1} {n + 2} {n + 3}")
        lines.append(f"f {n + 1} {n + 3} {n + 4}")
        n += 4

    for r in range(ROWS):
        for c in range(COLS):
            x, y = (c - (COLS - 1) / 2) * 2.0, (r - (ROWS - 1) / 2) * 2.0
            quad(x - 0.4, y - 0.4, x + 0.4, y + 0.4, 0.0)
    quad(-0.01, -0.01, 0.01, 0.01, 1.0)
    quad(-0.01, -0.01, 0.01, 0.01, -1.0)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def render(obj, model, extra, out):
    subprocess.run(
        [BIN, "mesh", obj, "--size", f"{SIZE[0]}x{SIZE[1]}", "--camera", model,
         "--separation", SEPARATION, "--fov", "40", "--out", out] + extra,
        check=True, stderr=subprocess.DEVNULL, env={**os.environ, "RUST_LOG": "off"})


def centroids(path):
    """Centroid (x, y) of each square: bright pixels split into the grid's cells by the gaps."""
    img = np.asarray(Image.open(path).convert("L")).astype(float)
    ys, xs = np.nonzero(img > 100)
    weights = img[ys, xs]
    out = {}
    # Squares are 2 units apart: assign each pixel to the nearest grid cell by rank of gaps.
    col_edges = np.quantile(xs, np.linspace(0, 1, COLS + 1)[1:-1])
    row_edges = np.quantile(ys, np.linspace(0, 1, ROWS + 1)[1:-1])
    cols, rows = np.searchsorted(col_edges, xs), np.searchsorted(row_edges, ys)
    for r in range(ROWS):
        for c in range(COLS):
            m = (cols == c) & (rows == r)
            w = weights[m]
            out[(c, r)] = (np.sum(xs[m] * w) / np.sum(w) + 0.5, np.sum(ys[m] * w) / np.sum(w) + 0.5)
    return out


def main():
    os.makedirs(OUT, exist_ok=True)
    obj = os.path.join(OUT, "grid.obj")
    grid_obj(obj)
    print("| camera | vertical parallax, max (px) | horizontal parallax, max (px) | keystone, view 0 (px) |")
    print("|---|---:|---:|---:|")
    for model in ["skewed", "parallel", "toe-in"]:
        views = []
        for v in (0, 7):
            path = os.path.join(OUT, f"{model}_view{v}.png")
            render(obj, model, ["--display", f"view:8,{v}"], path)
            views.append(centroids(path))
            os.remove(path)
        a, b = views
        vertical = max(abs(a[k][1] - b[k][1]) for k in a)
        horizontal = max(abs(a[k][0] - b[k][0]) for k in a)
        height = lambda c: a[(c, ROWS - 1)][1] - a[(c, 0)][1]
        keystone = height(COLS - 1) - height(0)
        print(f"| {model} | {vertical:.2f} | {horizontal:.2f} | {keystone:.2f} |")
        render(obj, model, ["--output", "anaglyph", "--eyes", "0,7"],
               os.path.join(OUT, f"{model}_anaglyph.png"))
    os.remove(obj)
    print(f"pictures written to {os.path.relpath(OUT, ROOT)}", file=sys.stderr)


if __name__ == "__main__":
    main()
