#!/usr/bin/env bash
# Measures what `--method auto`'s cost model (src/render/auto/costs.rs) is fitted to and checked
# against: per case, the frame's counts (from an auto run's --json) and the time of every
# candidate method, into docs/auto/measurements.json. Fit and report: docs/tools/auto_fit.py.
# Needs the release build and data/fetch's files.
# Usage: docs/tools/auto_measure.sh [BIN [OUT]]   (default OUT docs/auto/measurements.json)
# ONLY=REGEX measures only the cases whose names match and replaces them in the file.
set -euo pipefail
cd "$(dirname "$0")/../.."
bin="${1:-target/release/autostereo}"
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-/tmp/xdg}"
mkdir -p "$XDG_RUNTIME_DIR"
lkg16="--display lkg:data/lkg_sample_16in_landscape_gen3_visual.json --size 3840x2160"
h8="--display hubner8 --size 512x512"
f=data/fetched
out="${2:-docs/auto/measurements.json}"
tmp="$(mktemp)"
# case: name | command and input | display flags | methods | frames
cases=(
  "bunny 16in|mesh $f/bunny.obj|$lkg16|single-pass n-pass tiled|2"
  "dragon_res2 16in|mesh $f/dragon_vrip_res2.obj|$lkg16|single-pass n-pass tiled|1"
  "dragon_res3 16in|mesh $f/dragon_vrip_res3.obj|$lkg16|single-pass n-pass tiled|2"
  "bunny hubner8|mesh $f/bunny.obj|$h8|single-pass n-pass|3"
  "dragon_res2 hubner8|mesh $f/dragon_vrip_res2.obj|$h8|single-pass n-pass|3"
  "dragon hubner8|mesh $f/dragon_vrip.obj|$h8|single-pass n-pass|2"
  "torus hubner8|mesh|$h8|single-pass n-pass|3"
  "brainsmall 16in|volume $f/brainsmall.den|$lkg16|single-pass tiled|1"
  "brainsmall hubner8|volume $f/brainsmall.den|$h8|single-pass n-pass|2"
  "dragon_res2 points 16in|points $f/dragon_vrip_res2.ply|$lkg16|single-pass tiled|1"
  "dragon_res2 points hubner8|points $f/dragon_vrip_res2.ply|$h8|single-pass n-pass|2"
  "gaussians 16in|gaussians|$lkg16|single-pass|1"
  "gaussians hubner8|gaussians|$h8|single-pass n-pass|2"
)
echo "[" > "$tmp"
first=1
for c in "${cases[@]}"; do
  IFS='|' read -r name input display methods frames <<< "$c"
  [[ "$name" =~ ${ONLY:-.} ]] || continue
  # shellcheck disable=SC2086
  auto=$("$bin" $input $display --min-psnr 1 --frames 1 --json 2>/dev/null)
  times="{"
  sep=""
  for m in $methods; do
    extra=""
    [ "$m" = tiled ] && extra="--view-size $(echo "$auto" | python3 -c '
import json,sys
d=json.load(sys.stdin)
print("x".join(map(str,[c for c in d["auto"]["candidates"] if c["method"]=="tiled"][0]["view_size"])))')"
    # shellcheck disable=SC2086
    ms=$("$bin" $input $display --method "$m" $extra --frames "$frames" --json 2>/dev/null \
      | python3 -c 'import json,sys; print(json.load(sys.stdin)["ms"])')
    times="$times$sep\"$m\": $ms"
    sep=", "
    echo "$name $m $ms ms" >&2
  done
  times="$times}"
  [ $first = 1 ] || echo "," >> "$tmp"
  first=0
  echo "$auto" | python3 -c '
import json,sys
d=json.load(sys.stdin); a=d["auto"]
print(json.dumps({"case": sys.argv[1], "kind": sys.argv[2], "size": d["size"], "views": d["views"],
  "views_per_pixel": d["views_per_pixel"], "coverage": a["coverage"], "census": a["census"],
  "candidates": [{k: c[k] for k in ("method", "view_size", "psnr_db")} for c in a["candidates"]],
  "measured_ms": json.loads(sys.argv[3]), "adapter": d["adapter"]}))' "$name" "${input%% *}" "$times" >> "$tmp"
done
echo "]" >> "$tmp"
python3 - "$tmp" "$out" <<'PY'
import json, os, sys
new = json.load(open(sys.argv[1]))
old = json.load(open(sys.argv[2])) if os.path.exists(sys.argv[2]) and os.environ.get("ONLY") else []
names = [c["case"] for c in new]
merged = [c for c in old if c["case"] not in names] + new
json.dump(merged, open(sys.argv[2], "w"), indent=1)
PY
rm -f "$tmp"
echo "wrote $out" >&2
