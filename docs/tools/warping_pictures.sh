#!/usr/bin/env bash
# Regenerate the RGB-D pictures of docs/WARPING.md: a synthetic RGB-D pair (examples/rgbd_scene.rs),
# its spatial image for the paper's display, its outermost views (the disocclusions filled from
# the background) and the same at three times the depthiness (where filling shows: the wall
# stretched behind the thin pole). Usage: docs/tools/warping_pictures.sh (from the repository root)
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release --quiet --example rgbd_scene
cargo build --release --quiet
bin=target/release/autostereo
img=docs/images/rgbd
mkdir -p "$img" "$img/views" "$img/strong"
rgbd=("$img/scene.png" "$img/scene_depth.png" --display hubner8)
target/release/examples/rgbd_scene "$img"
$bin rgbd "${rgbd[@]}" --out "$img/spatial_hubner8.png" --hole-mask "$img/holes.png"
$bin rgbd "${rgbd[@]}" --output views --out "$img/views/view.png"
$bin rgbd "${rgbd[@]}" --depthiness 3 --hole-mask "$img/holes_strong.png"
$bin rgbd "${rgbd[@]}" --depthiness 3 --output views --out "$img/strong/view.png"
# Keep the outermost views only.
for dir in views strong; do
  mv "$img/$dir/view_00.png" "$img/${dir}_left.png"
  mv "$img/$dir/view_07.png" "$img/${dir}_right.png"
  rm -r "${img:?}/$dir"
done
$bin views "$img/spatial_hubner8.png" --eyes 1,6 --out "$img/anaglyph.png"
echo "pictures written to $img"
