#!/usr/bin/env bash
# The RGB-D warp straight into the spatial image against warping every view into its own
# image first (Beck's way), side by side, at a panel's size: the synthetic pair of
# docs/tools/warping_pictures.sh resampled to 1920×1080, N = 8 (hubner8) and N = 45, median of
# 5 frames, each pair measured twice in alternation (lavapipe's speed drifts within a run).
# Usage: docs/tools/warping_speed.sh (from the repository root, after warping_pictures.sh)
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release --quiet
bin=target/release/autostereo
img=docs/images/rgbd
out="$(mktemp -d)"
for display in hubner8 slanted:45,7.5,1/6,0.2; do
  for round in 1 2; do
    for path in direct per-view; do
      ms=$($bin rgbd "$img/scene.png" "$img/scene_depth.png" --display "$display" \
        --size 1920x1080 --warp-path "$path" --frames 5 --out "$out/s.png" 2>&1 \
        | grep -o '[0-9.]* ms/frame' | grep -o '^[0-9.]*')
      echo "$display round $round $path: $ms ms"
    done
  done
done
rm -r "$out"
