#!/usr/bin/env bash
# Every primitive's default method at the panels' sizes: 1920×1080, 3840×2160 (a 16" Looking
# Glass), 7680×4320 (32"/65"), the hubner8 display (K = 3). Prints a Markdown table of the GPU
# memory the render holds (`gpu_bytes`: scene, renderer, target), whether it was split into
# bands (src/render/bands.rs) and the frame time (a software rasteriser's: compare sizes, not
# machines). Uses data/fetched/ (data/fetch) where present: the bunny, the dragon at res2
# (100,250 points), the MRI brain; else the built-in scenes, and says so.
#
# Usage: docs/tools/panel_sizes.sh > docs/panel_sizes.md   (release build; ≈ 4 min on lavapipe)
set -euo pipefail
cd "$(dirname "$0")/../.."
bin="${AUTOSTEREO_BIN:-target/release/autostereo}"
[ -x "$bin" ] || cargo build --release --quiet
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

declare -A input=([mesh]="" [points]="" [volume]="")
[ -f data/fetched/bunny.obj ] && input[mesh]=data/fetched/bunny.obj
[ -f data/fetched/dragon_vrip_res2.ply ] && input[points]=data/fetched/dragon_vrip_res2.ply
[ -f data/fetched/brainsmall.den ] && input[volume]=data/fetched/brainsmall.den

adapter=$(RUST_LOG=info "$bin" volume --size 16x16 --out "$out/probe.png" 2>&1 |
  grep -o 'adapter: .*' | head -n 1 || true)
echo "Default method (single pass), hubner8, one timed frame; ${adapter:-adapter: unknown}."
echo
echo "| primitive | input | size | GPU memory (MiB) | bands | ms/frame |"
echo "|---|---|---|---:|---|---:|"
for size in 1920x1080 3840x2160 7680x4320; do
  for kind in mesh points volume; do
    file="${input[$kind]}"
    args=("$kind")
    [ -n "$file" ] && args+=("$file")
    json=$("$bin" "${args[@]}" --size "$size" --json --out "$out/x.png" 2>"$out/err") || {
      echo "| $kind | ${file:-built-in} | $size | failed: $(tail -n 1 "$out/err") | | |"
      continue
    }
    python3 - "$kind" "${file:-built-in}" "$size" "$json" <<'EOF'
import json, sys
kind, name, size, text = sys.argv[1:]
d = json.loads(text)
how = d.get("rendered") or ""
bands = how[how.index("in "):how.index(" (")] if "bands" in how else "whole"
print(f"| {kind} | {name.split('/')[-1]} | {size} | {d['gpu_bytes'] / 2**20:.1f} | {bands} | {d['ms']:.0f} |")
EOF
  done
done
