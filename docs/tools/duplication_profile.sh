#!/usr/bin/env bash
# Where the mesh duplication methods spend their time (markdown table on stdout): the tiled
# method on the dragon res2 at a tiny size (vertex + triangle setup of N copies, almost no
# fill), at 512² and 1920×1080 (+ fill), and on a one-triangle mesh (clear + compositing only);
# the single pass and N-pass beside it. Same process per row, 5 timed frames each.
# Usage: docs/tools/duplication_profile.sh [autostereo binary]   (needs data/fetch)
set -euo pipefail
bin="${1:-target/release/autostereo}"
dragon=data/fetched/dragon_vrip_res2.obj
tri=$(mktemp --suffix=.obj)
trap 'rm -f "$tri"' EXIT
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$tri"
ms() { "$bin" mesh "$@" --frames 5 --json 2>/dev/null | python3 -c "import json,sys; print(f\"{json.load(sys.stdin)['ms']:.1f}\")"; }
echo "| size | tiled, dragon | tiled, one triangle (clear + composite) | single pass (compute) | N-pass |"
echo "|---|---:|---:|---:|---:|"
for size in 64x64 512x512 1920x1080; do
  echo "| $size | $(ms "$dragon" --method tiled --size "$size") | $(ms "$tri" --method tiled --size "$size") | $(ms "$dragon" --method single-pass --visibility compute --size "$size") | $(ms "$dragon" --method n-pass --size "$size") |"
done
