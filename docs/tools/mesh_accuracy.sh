#!/usr/bin/env bash
# Accuracy of every single-pass mesh mode against the N-pass oracle (markdown table on stdout).
# Usage: docs/tools/mesh_accuracy.sh [autostereo binary]   (needs data/fetch for the dragon)
set -euo pipefail
bin="${1:-target/release/autostereo}"
echo "| scene | display | visibility | bounds | PSNR dB | max abs err | share off > 2/255 |"
echo "|---|---|---|---|---:|---:|---:|"
for scene in torus data/fetched/dragon_vrip_res2.obj; do
  file=""; [ "$scene" != torus ] && file="$scene"
  for display in hubner8 lenticular:8; do
    for mode in "compute exact" "atomic exact" "exact exact" "fast exact" "compute paper"; do
      set -- $mode
      json=$("$bin" mesh $file --display "$display" --visibility "$1" --bounds "$2" --compare --json 2>/dev/null)
      python3 - "$json" "$(basename "$scene" .obj)" "$display" "$1" "$2" <<'PY'
import json, sys
j = json.loads(sys.argv[1])
print(f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]} | {sys.argv[5]} | {j['psnr_db']:.1f} | {j['max_abs_err']} | {100 * j['frac_off_2']:.4f} % |")
PY
    done
  done
done
