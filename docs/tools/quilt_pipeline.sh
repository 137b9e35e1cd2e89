#!/usr/bin/env bash
# The pipeline Looking Glass owners run today against the single pass, on a 16" Spatial Display
# (3840×2160, 49 views: data/lkg_sample_16in_landscape_gen3_visual.json, subpixel cells):
#   quilt    every view rendered into the family's default quilt (5999², 7×7 tiles of 857×857,
#            each tile seeing the panel's 16:9 through square texels, as Looking Glass's
#            renderers make it), then interleaved: the tiled method at --view-size 857x857 (its
#            atlas is that quilt; the compositing samples the tiles bilinearly, as Looking
#            Glass's lenticular shader does);
#   single   the single pass at the panel's size (one ray per subpixel);
# each against the N-pass at full resolution (--compare: PSNR), for meshes, points and volumes;
# time (one timed frame, a software rasteriser's: compare the rows, not machines) and the GPU
# memory the render holds (gpu_bytes). Writes docs/quilt_pipeline.md and its plot.
#
# Usage: docs/tools/quilt_pipeline.sh   (release build; data/fetched/ where present; ≈ 20 min
#        on lavapipe, most of it the full-resolution N-pass oracles)
set -euo pipefail
cd "$(dirname "$0")/../.."
bin="${AUTOSTEREO_BIN:-target/release/autostereo}"
[ -x "$bin" ] || cargo build --release --quiet
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
cal=data/lkg_sample_16in_landscape_gen3_visual.json

declare -A input=([mesh]="" [points]="" [volume]="")
[ -f data/fetched/bunny.obj ] && input[mesh]=data/fetched/bunny.obj
[ -f data/fetched/dragon_vrip_res2.ply ] && input[points]=data/fetched/dragon_vrip_res2.ply
[ -f data/fetched/brainsmall.den ] && input[volume]=data/fetched/brainsmall.den

rows="$out/rows.jsonl"
for kind in mesh points volume; do
  file="${input[$kind]}"
  for pipeline in quilt single; do
    args=("$kind")
    [ -n "$file" ] && args+=("$file")
    args+=(--display "lkg:$cal" --compare --json --out "$out/x.png")
    case $pipeline in
      quilt) args+=(--method tiled --view-size 857x857) ;;
      single) args+=(--method single-pass) ;;
    esac
    echo "$kind $pipeline" >&2
    "$bin" "${args[@]}" | python3 -c "
import json, sys
d = json.load(sys.stdin)
d['kind'], d['pipeline'], d['input'] = '$kind', '$pipeline', '${file:-built-in}'.split('/')[-1]
print(json.dumps(d))" >>"$rows"
  done
done

python3 docs/tools/quilt_pipeline_report.py "$rows" docs/quilt_pipeline.md docs/images/quilt_pipeline.svg
