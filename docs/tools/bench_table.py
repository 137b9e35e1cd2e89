#!/usr/bin/env python3
"""Markdown tables of a criterion run: median ms per method, and ratios vs N-pass and single view.

Usage: python3 docs/tools/bench_table.py PREFIX   (e.g. `mesh` after `cargo bench --bench mesh`)
Reads target/criterion/**/new/{benchmark,estimates}.json; groups are PREFIX/<scene>/N<views>.
"""
import glob
import json
import os
import sys
from collections import defaultdict

prefix = sys.argv[1] if len(sys.argv) > 1 else "mesh"
root = os.path.join(os.path.dirname(__file__), "..", "..", "target", "criterion")
groups = defaultdict(dict)
for path in glob.glob(os.path.join(root, "**", "new", "benchmark.json"), recursive=True):
    bench = json.load(open(path))
    if not bench["group_id"].startswith(prefix + "/"):
        continue
    estimates = json.load(open(os.path.join(os.path.dirname(path), "estimates.json")))
    method = bench["function_id"] + (f" ({bench['value_str']})" if bench.get("value_str") else "")
    groups[bench["group_id"]][method] = estimates["median"]["point_estimate"] / 1e6

if not groups:
    sys.exit(f"no criterion results for '{prefix}' under {root}")

print("| scene | N | method | median ms | N-pass / this | this / single view |")
print("|---|---|---|---:|---:|---:|")
for group in sorted(groups, key=lambda g: (g.split("/")[1], int(g.split("/")[2][1:]))):
    _, scene, views = group.split("/")
    results = groups[group]
    npass, sv = results.get("n-pass"), results.get("single-view")
    for method, ms in sorted(results.items(), key=lambda kv: kv[1]):
        vs_npass = f"{npass / ms:.2f}×" if npass else "–"
        vs_sv = f"{ms / sv:.2f}×" if sv else "–"
        print(f"| {scene} | {views[1:]} | {method} | {ms:.1f} | {vs_npass} | {vs_sv} |")
