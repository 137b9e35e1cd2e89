#!/usr/bin/env bash
# The benchmarks that mean something only on a real GPU, in one short run: the quick bench
# (every primitive and method at 256², N = 2, 8, 64) and the volume table (`autostereo-bench --volumes`:
# the head and brainsmall at 512², N = 8 and 64, every method, the approximations' curves) and
# the mesh view clusters against the quilt pipeline at 3840×2160, 49 views, and the cases of
# `--method auto`'s cost model (docs/AUTO.md), on
# whatever adapter wgpu picks (WGPU_BACKEND / WGPU_ADAPTER_NAME choose another). About 3–8
# minutes on a discrete GPU; on lavapipe ≈ 20 minutes.
#
# It installs nothing. It uses, in this order: $AUTOSTEREO_BIN, target/release/autostereo (a
# build carried from another x86-64 machine works), or `cargo build --release` where cargo is
# on the PATH; otherwise it says what is missing and stops. Without data/fetched/ (data/fetch
# needs the network) the bench uses its generated stand-ins and says so in each table.
#
# Usage: docs/tools/gpu_bench.sh [OUT]   (default OUT = gpu_bench/; writes OUT/GPU.md, then
#        OUT/quick/ and OUT/volumes/ with their BENCHMARKS.md and bench_*.json). Commit the
#        printed GPU.md as docs/GPU.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
out="${1:-gpu_bench}"
mkdir -p "$out"

bin="${AUTOSTEREO_BIN:-target/release/autostereo}"
bench="${AUTOSTEREO_BENCH_BIN:-target/release/autostereo-bench}"
if [ ! -x "$bin" ] || [ ! -x "$bench" ]; then
  if command -v cargo >/dev/null 2>&1; then
    echo "building target/release/autostereo and autostereo-bench (cargo build --release --workspace)"
    cargo build --release --workspace --quiet
  else
    echo "gpu_bench.sh: no autostereo binaries ($bin, $bench) and no cargo on the PATH: build them" >&2
    echo "  elsewhere (cargo build --release --workspace) and bring target/release/autostereo and" >&2
    echo "  target/release/autostereo-bench, or install Rust" >&2
    exit 1
  fi
fi
[ -d data/fetched ] || echo "note: no data/fetched/ (data/fetch not run): generated stand-ins only"

# Which adapter: the first line the renderer logs.
adapter=$(RUST_LOG=info "$bin" volume --size 16x16 --out "$out/probe.png" 2>&1 |
  grep -o 'adapter: .*' | head -n 1 || true)
rm -f "$out/probe.png"
echo "${adapter:-adapter: unknown (the probe render failed; see below)}"

start=$(date +%s)
"$bench" --quick --report "$out/quick"
"$bench" --volumes --frames 10 --report "$out/volumes"
# View clusters of the compute single pass against the quilt pipeline, 16" Spatial Display
# calibration, 3840×2160, 49 views (docs/MESHES.md "View clusters").
mesh=data/fetched/bunny.obj
[ -f "$mesh" ] || mesh=""
cal=lkg:data/lkg_sample_16in_landscape_gen3_visual.json
ms() { "$bin" mesh $mesh --display "$cal" --size 3840x2160 "$@" --frames 10 --json 2>/dev/null |
  grep -o '"ms": *[0-9.]*' | grep -o '[0-9.]*$' || echo failed; }
{
  echo "| ${mesh:-torus scene}, 16\" calibration, 3840×2160, 49 views | ms/frame |"
  echo "|---|---:|"
  for c in 1 2 7 49 auto; do
    echo "| single pass, compute, --clusters $c | $(ms --visibility compute --clusters "$c") |"
  done
  echo "| tiled quilt 857×857 (--method tiled --view-size 857x857) | $(ms --method tiled --view-size 857x857) |"
} > "$out/clusters.md"
# `--method auto`'s cost model: every candidate timed on the cases of docs/AUTO.md, the model's
# choices against them and the constants refitted for this adapter.
if [ -d data/fetched ]; then
  docs/tools/auto_measure.sh "$bin" "$out/auto_measurements.json"
  python3 docs/tools/auto_fit.py --measurements "$out/auto_measurements.json" > "$out/auto.md" ||
    echo "(auto_fit.py needs numpy)" > "$out/auto.md"
else
  echo "(no data/fetched/: the auto cases need the fetched data)" > "$out/auto.md"
fi
seconds=$(( $(date +%s) - start ))

{
  echo "# Benchmarks on a GPU"
  echo
  echo "Made by \`docs/tools/gpu_bench.sh\` in ${seconds} s on $(date -u +%Y-%m-%d)."
  echo "${adapter:-adapter: unknown}; CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')."
  echo
  echo "Absolute times mean something here, unlike on the software rasterisers of CI."
  echo
  echo "## View clusters (meshes, compute visibility)"
  echo
  cat "$out/clusters.md"
  echo
  echo "## \`--method auto\`: the cost model's choices (docs/AUTO.md's cases)"
  echo
  cat "$out/auto.md"
  echo
  echo "## Volumes (\`autostereo-bench --volumes --frames 10\`)"
  echo
  sed -e '1,/^## /{/^## /!d}' -e 's/^#/##/' "$out/volumes/BENCHMARKS.md" | sed 's#(images/#(gpu/volumes/images/#g'
  echo
  echo "## Quick run (\`autostereo-bench --quick\`)"
  echo
  sed -e '1,/^## /{/^## /!d}' -e 's/^#/##/' "$out/quick/BENCHMARKS.md" | sed 's#(images/#(gpu/quick/images/#g'
} > "$out/GPU.md"
cat "$out/GPU.md"
