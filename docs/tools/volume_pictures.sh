#!/usr/bin/env bash
# Regenerate docs/images/volumes (docs/VOLUMES.md "Windows and presets"): a real T1 MRI (the
# Colin27 average, ch2 and its skull-stripped ch2bet from Debian's mricron-data, data/fetch)
# and the built-in CT head in each preset and mode, one view each (view:8,4: an ordinary
# image). Usage: docs/tools/volume_pictures.sh   (from the repository root)
set -euo pipefail
cd "$(dirname "$0")/../.."
data/fetch >/dev/null
cargo build --release --quiet -p autostereo-cli
bin=target/release/autostereo
img=docs/images/volumes
mkdir -p $img
shot() { "$bin" volume "$@" --display view:8,4 --size 256x256 >/dev/null 2>&1; }
mri=data/fetched/mricron/ch2.nii.gz
shot $mri --out $img/mri_preset.png
shot data/fetched/mricron/ch2bet.nii.gz --out $img/mri_bet_preset.png
shot $mri --clip "x<90" --view left --out $img/mri_clip.png
shot $mri --clip "z<100" --view top --out $img/mri_clip_top.png
shot $mri --projection mip --window 200,100 --out $img/mri_mip.png
shot $mri --projection average --window 120,60 --out $img/mri_average.png
shot $mri --projection iso --iso 90 --out $img/mri_iso.png
shot --tf ct-skin --out $img/ct_skin.png
shot --tf ct-bone --out $img/ct_bone.png
shot --projection mip --out $img/ct_mip.png
shot --projection iso --iso 0.8 --out $img/ct_iso.png
shot --clip "x<48" --view left --out $img/ct_clip.png
ls -la $img
