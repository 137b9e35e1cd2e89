#!/usr/bin/env bash
# Accuracy (and speed) of the single-pass splat settings against the N-pass oracle with the same
# groups and ε (markdown table on stdout): depth mode, group count, ε.
# Usage: docs/tools/points_accuracy.sh [autostereo binary]   (needs data/fetch for the dragon)
set -euo pipefail
bin="${1:-target/release/autostereo}"
echo "| scene | display | depth | groups | ε (× depth) | K groups | PSNR dB | share off > 2/255 | ms |"
echo "|---|---|---|---|---:|---:|---:|---:|---:|"
for scene in torus data/fetched/dragon_vrip_res2.ply; do
  file=""; [ "$scene" != torus ] && file="$scene"
  for setting in "hubner8 exact auto 0.01" "hubner8 paper auto 0.01" "lenticular:8 exact auto 0.01" \
                 "hubner8 exact 4 0.01" "hubner8 exact 2 0.01" "hubner8 exact auto 0.001" "hubner8 exact auto 0.05"; do
    set -- $setting
    json=$("$bin" points $file --display "$1" --depth "$2" --groups "$3" --epsilon "$4" --frames 3 --compare --json 2>/dev/null)
    python3 - "$json" "$(basename "$scene" .ply)" "$@" <<'PY'
import json, sys
j = json.loads(sys.argv[1])
scene, display, depth, groups, eps = sys.argv[2:7]
print(f"| {scene} | {display} | {depth} | {groups} | {eps} | {j['groups']} | {j['psnr_db']:.1f} | {100 * j['frac_off_2']:.3f} % | {j['ms']:.0f} |")
PY
  done
done
