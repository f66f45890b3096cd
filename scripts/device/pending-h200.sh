#!/usr/bin/env bash
# The measurements issues #13, #15 and #16 wait for, in one run on a lent GPU (see
# ../shared/tools/device/README.md): build here, bundle, and run from the repository root
#   source .device/env.sh; bash scripts/device/pending-h200.sh PART > $OUT/log 2>&1
# with .device/bidir (this commit), .device/bidir-base (built at 1e41285, the last commit
# measured on the H200) and .device/ref.exr (../shared/references/cornell-box/
# reference-bidir-h200.exr). PART is one of: speed, vcm, rough (each under 10 minutes).
set -u
B=${B:-$PWD/.device/bidir}
BASE=${BASE:-$PWD/.device/bidir-base}
REF=${REF:-$PWD/.device/ref.exr}
OUT=${OUT:-/tmp/pending}
mkdir -p "$OUT"
CB="--width 256 --height 256"
case "${1:-speed}" in
speed)
  # #16/#13: path regeneration, the 128-byte GpuMaterial, the alpha-only first-hit pass.
  for i in pt-nee bdpt; do
    for b in "$BASE" "$B" "$BASE" "$B"; do
      echo "== $i $(basename "$b")"
      "$b" bench render $CB --integrator "$i" --spp 1024 --warmup 2 --runs 5 | head -4
    done
  done
  for b in "$BASE" "$B"; do
    echo "== $(basename "$b") pt-nee --first-hit alpha"
    "$b" bench render $CB --integrator pt-nee --spp 1024 --first-hit alpha | head -4
  done
  for i in pt-nee bdpt; do
    for t in 0.1 2; do
      for b in "$BASE" "$B"; do
        for o in png exr; do
          echo "== $i $(basename "$b") --time $t -> $o"
          "$b" render --integrator "$i" --time "$t" --reference "$REF" -o "/tmp/x.$o" 2>&1 | grep -E "spp in|RMSE"
        done
      done
    done
  done
  "$B" info --kernels 2>&1 | grep -iE "pt|bdpt" | head -20
  ;;
vcm)
  # #15: the commands of docs/results.md, "VCM on the H200".
  SDS="assets/scenes/sds/sds.obj --eye 0.9,1.3,-3.2 --target -0.4,0.4,0 --up 0,1,0 --fov 50 --width 256 --height 256"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  for t in 1 10; do
    "$B" converge --reference "$REF" --integrators pt-nee,bdpt,vcm --time $t --seeds 2 --out "$OUT/cornell-$t" 2>&1 | grep -iE "rmse|stability"
    "$B" converge $SDS --reference assets/scenes/sds/reference-h200-vcm.exr --integrators pt-nee,bdpt,vcm --time $t --seeds 2 --out "$OUT/sds-$t" 2>&1 | grep -iE "rmse|stability"
    "$B" converge $CAU --reference assets/scenes/caustic/reference.exr --integrators pt-nee,bdpt,vcm --time $t --seeds 2 --out "$OUT/caustic-$t" 2>&1 | grep -iE "rmse|stability"
  done
  for b in "$BASE" "$B"; do for i in bdpt vcm; do
    echo "== $(basename "$b") $i"
    "$b" bench render $CB --integrator $i --spp 1024 | head -8
  done; done
  ;;
rough)
  # #13: the rough Cornell box against Mitsuba 3 at its size, then the convergence chart.
  RC="assets/scenes/rough-cornell/rough-cornell.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077"
  for i in pt-nee bdpt; do
    "$B" render $RC --width 64 --height 64 --integrator $i --spp 65536 --reference assets/scenes/rough-cornell/reference.exr -o "$OUT/rough-$i.exr" 2>&1 | grep -E "spp in|RMSE"
  done
  "$B" render $RC --width 256 --height 256 --integrator bdpt --time 120 --seed 4242 -o "$OUT/rough-ref.exr" 2>&1 | grep -E "spp in"
  "$B" converge $RC --width 256 --height 256 --reference "$OUT/rough-ref.exr" --integrators pt-nee,bdpt --time 10 --seeds 2 --out "$OUT/rough-chart" 2>&1 | grep -iE "rmse|stability"
  ;;
*) echo "usage: $0 speed|vcm|rough" >&2; exit 2 ;;
esac
