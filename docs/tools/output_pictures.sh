#!/usr/bin/env bash
# Regenerate docs/images/outputs: one picture per --output format (docs/USAGE.md "Outputs"),
# the dragon (res3) on the paper's 8-view display, eyes 2 and 5.
# Usage: docs/tools/output_pictures.sh   (from the repository root; BIN= to use another build)
set -euo pipefail
cd "$(dirname "$0")/../.."
data/fetch >/dev/null
if [ -z "${BIN:-}" ]; then
  cargo build --release --quiet
  BIN=target/release/autostereo
fi
img=docs/images/outputs
mkdir -p "$img"
rm -f "$img"/*.png
mesh=data/fetched/dragon_vrip_res3.obj
for format in spatial anaglyph anaglyph-half anaglyph-dubois side-by-side side-by-side-half \
  top-bottom top-bottom-half rows columns checkerboard; do
  "$BIN" mesh "$mesh" --size 192x144 --output "$format" --eyes 2,5 --out "$img/$format.png"
done
"$BIN" mesh "$mesh" --size 96x72 --output quilt --out "$img/quilt.png"
echo "pictures written to $img"
