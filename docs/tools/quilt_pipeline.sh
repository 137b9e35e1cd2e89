#!/usr/bin/env bash
# The pipeline Looking Glass owners run today against the single pass and `--method auto`, on
# two calibrations: a 16" Spatial Display (3840×2160, 49 views) and a Go (1440×2560, 66 views),
# both subpixel cells (data/lkg_sample_{16in_landscape,go}_gen3_visual.json). Pipelines:
#   quilt      every view rendered into the family's quilt (the 16": 5999², 7×7 tiles of
#              857×857; each tile sees the panel's aspect through its own, as Looking Glass's
#              renderers make it), then interleaved: the tiled method at the family's tile;
#   single     the single pass at the panel's size (one ray per subpixel);
#   clustered  meshes: the compute single pass in 7 view clusters (exact);
#   auto       the default, `--method auto` (exact methods only);
#   auto ≥ 40  `--method auto --min-psnr 40`;
# for meshes (bunny), points (the dragon's 100k), volumes (brainsmall) and Gaussians (131,072,
# docs/tools/gaussians_ply.py), each against the N-pass at full resolution (--compare; an auto
# row takes the PSNR of the row that rendered the same method). Also the mesh single pass's time
# against its view clusters C on the 16". Times are one frame on whatever adapter renders: compare
# rows, not machines. Writes docs/quilt_pipeline.md and its plots.
#
# Usage: docs/tools/quilt_pipeline.sh   (release build; data/fetched/ where present; numpy for
#        the Gaussians' file; ≈ 60 min on lavapipe, most of it the full-resolution N-pass oracles)
#        CALS="16in_landscape go", KINDS="mesh points volume gaussians", CLUSTERS=1 choose what
#        runs; ROWS=FILE keeps the rows (appended) and the report reads them all.
set -euo pipefail
cd "$(dirname "$0")/../.."
bin="${AUTOSTEREO_BIN:-target/release/autostereo}"
[ -x "$bin" ] || cargo build --release --quiet
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$out}"

declare -A input=([mesh]="" [points]="" [volume]="" [gaussians]="")
[ -f data/fetched/bunny.obj ] && input[mesh]=data/fetched/bunny.obj
[ -f data/fetched/dragon_vrip_res2.ply ] && input[points]=data/fetched/dragon_vrip_res2.ply
[ -f data/fetched/brainsmall.den ] && input[volume]=data/fetched/brainsmall.den
python3 docs/tools/gaussians_ply.py 131072 "$out/gaussians_131k.ply" && input[gaussians]="$out/gaussians_131k.ply"

rows="${ROWS:-$out/rows.jsonl}"
record() { # record CAL KIND PIPELINE ARGS…: one row of the table
  local cal=$1 kind=$2 pipeline=$3
  shift 3
  echo "$cal $kind $pipeline" >&2
  local json
  if ! json=$("$bin" "$@" --json --out "$out/x.png" 2>"$out/err"); then
    echo "  failed: $(tail -n 1 "$out/err")" >&2
    json="{\"failed\": $(tail -n 1 "$out/err" | python3 -c 'import json,sys; print(json.dumps(sys.stdin.read().strip()))')}"
  fi
  echo "$json" | python3 -c "
import json, sys
d = json.load(sys.stdin)
d['calibration'], d['kind'], d['pipeline'] = '$cal', '$kind', '$pipeline'
d['input'] = '${file:-built-in}'.split('/')[-1]
print(json.dumps(d))" >>"$rows"
}

for cal in ${CALS:-16in_landscape go}; do
  display=(--display "lkg:data/lkg_sample_${cal}_gen3_visual.json")
  # The family's tile, from auto's candidates (it depends on the display only).
  tile=$("$bin" mesh "${display[@]}" --min-psnr 1 --json 2>/dev/null | python3 -c '
import json, sys
c = [c for c in json.load(sys.stdin)["auto"]["candidates"] if c["method"] == "tiled"][0]
print(c["label"].split("tiles of ")[1].split(",")[0])')
  for kind in ${KINDS:-mesh points volume gaussians}; do
    file="${input[$kind]}"
    base=("$kind")
    [ -n "$file" ] && base+=("$file")
    base+=("${display[@]}")
    record "$cal" "$kind" quilt "${base[@]}" --method tiled --view-size "$tile" --compare
    record "$cal" "$kind" single "${base[@]}" --method single-pass --compare
    [ "$kind" = mesh ] &&
      record "$cal" "$kind" clustered "${base[@]}" --method single-pass --visibility compute --clusters 7 --compare
    record "$cal" "$kind" auto "${base[@]}"
    record "$cal" "$kind" auto40 "${base[@]}" --min-psnr 40
  done
done
# Time against view clusters: the mesh single pass on the 16" (exact at every C).
file="${input[mesh]}"
[ "${CLUSTERS:-1}" = 1 ] && for c in 1 2 4 7 13 25 49; do
  record 16in_landscape mesh "C=$c" mesh $file --display lkg:data/lkg_sample_16in_landscape_gen3_visual.json \
    --method single-pass --visibility compute --clusters "$c" --frames 2
done

python3 docs/tools/quilt_pipeline_report.py "$rows" docs/quilt_pipeline.md docs/images
