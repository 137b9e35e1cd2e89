#!/usr/bin/env python3
"""Fits and reports `--method auto`'s cost model (src/render/auto/costs.rs) from
docs/auto/measurements.json (docs/tools/auto_measure.sh), and writes docs/AUTO.md's table:
each case's measured and predicted time per method, and whether the model's choice is the
measured fastest. The features are the ones costs.rs multiplies its constants with; the
constants it prints are what costs.rs holds (copied by hand, so a refit is a reviewed change).
Usage: docs/tools/auto_fit.py [--write] [--measurements PATH]   (needs numpy; PATH: another
adapter's measurements, e.g. docs/tools/gpu_bench.sh's, reported but not written)"""
import json
import math
import re
import sys
from pathlib import Path

import numpy as np

root = Path(__file__).resolve().parents[2]
measurements = root / "docs/auto/measurements.json"
if "--measurements" in sys.argv:
    measurements = Path(sys.argv[sys.argv.index("--measurements") + 1])
cases = json.loads(measurements.read_text())
costs = (root / "src/render/auto/costs.rs").read_text()


def const(name):
    m = re.search(rf"const {name}: (?:\[f64; 2\]|f64) = ([^;]+);", costs)
    v = m.group(1).strip()
    return json.loads(v) if v.startswith("[") else float(v)


C = {n: const(n) for n in ["MESH_SP_SUBPIXEL", "MESH_SP_COVER", "MESH_SP_TRIANGLE", "VIEW_PIXEL",
                           "VIEW_TRIANGLE", "VIEW_EDGE", "INTERLEAVE_SUBPIXEL", "VOLUME_RAY",
                           "POINTS_RAY", "GAUSSIANS_RAY"]}
RAYS = {"volume": "VOLUME_RAY", "points": "POINTS_RAY", "gaussians": "GAUSSIANS_RAY"}


def features(case, method, view_size):
    """ns-weighted features of one method: a dict constant name -> multiplier."""
    w, h = case["size"]
    pixels, k, n, cov = w * h, case["views_per_pixel"], case["views"], case["coverage"]
    sub = pixels * k
    kind = case["kind"]
    if method == "single-pass":
        if kind == "mesh":
            m = case["census"]
            return {"MESH_SP_SUBPIXEL": sub, "MESH_SP_COVER": m["cover_pixels"] * k,
                    "MESH_SP_TRIANGLE": m["triangles"]}
        return {(RAYS[kind], 0): sub * cov}
    view = view_size[0] * view_size[1]
    f = {"VIEW_PIXEL": n * view}
    if list(view_size) != list(case["size"]):
        f["INTERLEAVE_SUBPIXEL"] = sub
    if kind == "mesh":
        m = case["census"]
        f["VIEW_TRIANGLE"] = n * m["triangles"]
        f["VIEW_EDGE"] = n * math.sqrt(m["triangle_pixels"] * view / pixels * m["triangles"])
    else:
        f[(RAYS[kind], 1)] = n * view * cov
    return f


def value(name):
    return C[name[0]][name[1]] if isinstance(name, tuple) else C[name]


rows = []
for case in cases:
    for c in case["candidates"]:
        ms = case["measured_ms"].get(c["method"])
        if ms is None:
            continue
        f = features(case, c["method"], c["view_size"])
        predicted = sum(v * value(k) for k, v in f.items()) * 1e-6
        rows.append((case, c, ms, predicted, f))

# Refit: least squares on relative error, each constant ≥ 0 (clipped, then refitted without).
names = sorted({k for r in rows for k in r[4]}, key=str)
A = np.array([[r[4].get(k, 0.0) * 1e-6 / r[2] for k in names] for r in rows])
y = np.ones(len(rows))
active = list(range(len(names)))
while True:
    x, *_ = np.linalg.lstsq(A[:, active], y, rcond=None)
    if (x >= 0).all():
        break
    active = [a for a, v in zip(active, x) if v >= 0]
fit = dict.fromkeys(names, 0.0)
for a, v in zip(active, x):
    fit[names[a]] = v

out = ["| case | method | measured ms | predicted ms | PSNR (dB) |", "|---|---|---:|---:|---|"]
choices = []
for case in cases:
    mine = [r for r in rows if r[0] is case]
    for _, c, ms, pred, _ in mine:
        psnr = "exact" if c["psnr_db"] is None else f'{c["psnr_db"]}'
        out.append(f'| {case["case"]} | {c["method"]} | {ms:.0f} | {pred:.0f} | {psnr} |')
    for exact in (True, False):
        s = [r for r in mine if r[1]["psnr_db"] is None or not exact]
        pick = min(s, key=lambda r: r[3])
        best = min(s, key=lambda r: r[2])
        choices.append(f'| {case["case"]} | {"exact" if exact else "any"} | {pick[1]["method"]} '
                       f'({pick[2]:.0f} ms) | {best[1]["method"]} ({best[2]:.0f} ms) | '
                       f'{pick[2] / best[2]:.2f} |')
table = "\n".join(out)
choice_table = "\n".join(["| case | floor | auto picks (measured) | fastest measured | ratio |",
                          "|---|---|---|---|---:|"] + choices)
consts = "\n".join(f"- `{k if isinstance(k, str) else k[0] + '[' + str(k[1]) + ']'}`: "
                   f"{value(k):.4g} ns in costs.rs, {fit[k]:.4g} ns refitted" for k in names)
print(choice_table)
print(consts)
if "--write" in sys.argv:
    adapter = cases[0]["adapter"]
    doc = root / "docs/AUTO.md"
    text = doc.read_text()
    start, end = "<!-- auto_fit.py: begin -->", "<!-- auto_fit.py: end -->"
    body = (f"{start}\nMeasured on {adapter} by `docs/tools/auto_measure.sh` "
            f"(docs/auto/measurements.json), reported by `docs/tools/auto_fit.py --write`.\n\n"
            f"### Choices\n\n{choice_table}\n\n### Times\n\n{table}\n\n### Constants\n\n"
            f"{consts}\n{end}")
    a, b = text.index(start), text.index(end) + len(end)
    doc.write_text(text[:a] + body + text[b:])
    print(f"wrote {doc}")
