#!/usr/bin/env bash
# Regenerate the pictures in docs/images that are renders (not benchmark plots): spatial images
# for the paper's 8-view display (hubner8), red/cyan anaglyphs of two of their views, and the
# viewer's window.
# Needs the fetched data (data/fetch). Usage: docs/tools/pictures.sh   (from the repository root)
set -euo pipefail
cd "$(dirname "$0")/../.."
data/fetch >/dev/null
cargo build --release --quiet
bin=target/release/autostereo
img=docs/images

# Meshes: the full dragon (871k triangles), single pass with exact visibility and with the
# paper's one depth per pixel.
$bin mesh data/fetched/dragon_vrip.obj --size 384x256 --out $img/dragon_spatial_hubner8.png
$bin views $img/dragon_spatial_hubner8.png --eyes 1,6 --out $img/dragon_anaglyph.png
$bin mesh data/fetched/dragon_vrip.obj --size 384x256 --visibility fast \
  --out $img/dragon_fast_visibility.png

# Point splats: the dragon's 437k vertices (normals and radii estimated).
$bin points data/fetched/dragon_vrip.ply --size 512x512 --out $img/points_dragon_hubner8.png

# Volumes: the built-in head (ct-skin) and VolPack's MRI brain (mri), compute path.
$bin volume --size 384x384 --out $img/volume_head_hubner8.png
$bin views $img/volume_head_hubner8.png --eyes 3,4 --out $img/volume_head_anaglyph.png
$bin volume data/fetched/brainsmall.den --rotate=-90,0,0 --size 384x384 \
  --out $img/volume_brainsmall_hubner8.png
# The viewer's window (README "The viewer"): the built-in head, presented frames read back, in
# a virtual X server (apt-get install -y xvfb xauth).
shot() { xvfb-run -a "$bin" view --quit-after-frames 5 --screenshot "$img/$1.png" "${@:2}"; }
shot viewer --size 320x320
shot viewer_side_by_side --size 320x160 --preview side-by-side
shot viewer_anaglyph --size 240x240 --preview anaglyph
shot viewer_quilt --size 400x300 --preview quilt
echo "pictures written to $img"
