#!/usr/bin/env bash
# Regenerate docs/images/gaussians_*.png: the built-in Gaussian scene (Gaussians::generated,
# 4096 Gaussians, SH degree 3) rendered by the single pass for the paper's display, one of its
# views, a red/cyan anaglyph of two views, and a Looking Glass quilt of the 16" gen3 sample
# calibration's 49 views (tiled). Usage: docs/tools/gaussians_pictures.sh (from the repository
# root).
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release --quiet
bin=target/release/autostereo
img=docs/images
rm -f $img/gaussians_quilt_qs*.png
# Seen from above the torus's plane (the explicit camera of every command).
cam="--look-from 0,4.5,9 --look-at 0,-0.2,0"
$bin gaussians $cam --size 384x384 --out $img/gaussians_spatial_hubner8.png
$bin gaussians $cam --size 384x384 --display view:8,3 --out $img/gaussians_view3.png
$bin gaussians $cam --size 384x384 --output anaglyph-dubois --out $img/gaussians_anaglyph.png
$bin gaussians $cam --display lkg:data/lkg_sample_16in_landscape_gen3_visual.json \
  --size 960x540 --method tiled --view-size 112x63 --output quilt --quilt 5x10 \
  --out $img/gaussians_quilt.png
