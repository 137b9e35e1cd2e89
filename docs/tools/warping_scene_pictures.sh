#!/usr/bin/env bash
# Regenerate the scene pictures of docs/WARPING.md: single views of the dragon mesh and the
# built-in head synthesised by `--method warp` next to the N-pass's, and the warp's hole masks.
# A `view:N,V` display shows view V of N on every pixel, so any method renders that one view at
# full resolution. Needs data/fetch (the dragon). Usage: docs/tools/warping_scene_pictures.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release --quiet
bin=target/release/autostereo
img=docs/images/warp
mesh=data/fetched/dragon_vrip_res2.obj
size=320x320
mkdir -p "$img"
for v in 3 7; do
  common=(--display "view:8,$v" --size "$size")
  $bin mesh "$mesh" "${common[@]}" --method n-pass --out "$img/dragon_npass_v$v.png"
  $bin volume "${common[@]}" --method n-pass --out "$img/head_npass_v$v.png"
  for r in 1 2; do
    $bin mesh "$mesh" "${common[@]}" --method warp --references $r --compare \
      --out "$img/dragon_r${r}_v$v.png" --hole-mask "$img/dragon_r${r}_v${v}_holes.png"
    $bin volume "${common[@]}" --method warp --references $r --compare \
      --out "$img/head_r${r}_v$v.png" --hole-mask "$img/head_r${r}_v${v}_holes.png"
  done
done
echo "pictures written to $img"
