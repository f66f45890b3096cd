#!/usr/bin/env bash
# H200 measurements for the open issues, in parts of under 10 minutes each (see
# ../shared/tools/device/README.md): build here, bundle (`../shared/tools/device/bundle.sh
# --geometry-only sponza`, then strip .device/bidir), and run from the repository root
#   source .device/env.sh; bash scripts/device/pending-h200.sh PART > $OUT/log 2>&1
# with .device/bidir (this commit), .device/bidir-base (a build of the commit to compare
# with), .device/ref.exr (../shared/references/cornell-box/reference-bidir-h200.exr) and,
# for some parts, .device/bidir-prev / .device/bidir-pre.
#
# Each session's parts (what ran, on which card, and what was left prepared), newest first:
# scripts/device/HISTORY.md; add a line there for each session that runs or prepares one.
# Rerun `final` against the commit that changes a default, with BASE = the commit before it.
# The device tool brings back at most 8 files: archive CSVs (see vcm-first).
set -u
B=${B:-$PWD/.device/bidir}
BASE=${BASE:-$PWD/.device/bidir-base}
REF=${REF:-$PWD/.device/ref.exr}
# optional: a build from before the materials merge (fc01b5d), for #13's 2 % budget
PRE=${PRE:-$PWD/.device/bidir-pre}
OUT=${OUT:-/tmp/pending}
mkdir -p "$OUT"
CB="--width 256 --height 256"
# The scenes of sessions 37 and 38's parts: the box whose light hides above a panel (built as
# tests/render_caustic.rs builds it), the caustic scene at its test's camera, Sponza's geometry
# under sun and sky, the rough Cornell box.
HID=".device/scenes/hidden/hidden.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
SP=".device/scenes/sponza/Sponza.gltf --sponza-sun-sky --camera CameraMain --width 640 --height 360"
# Session 48's: the caustic scene at 64², DamagedHelmet under an environment and a sun.
CAU64="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 64 --height 64"
HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
RC="assets/scenes/rough-cornell/rough-cornell.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
# Sponza's CameraMain at build quality 5 through the 4-wide BVH (issue #17's setting) with the
# binary $1 and any further options: the primary, shadow and diffuse lines of its report.
sponza_q5() {
  local b=$1; shift
  timeout -k 5 60 "$b" bench traversal "$PWD/.device/scenes/sponza/Sponza.gltf" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 "$@" 2>&1 | grep -E "^(primary|shadow|diffuse) "
}
# $1 rounds of sponza_q5 over the binaries $2..., lockstep and with --refill 24, the binaries
# interleaved within each round (code layout moves the figures ~1 % between builds and starts).
sponza_rounds() {
  local n=$1; shift
  for r in $(seq "$n"); do
    for c in "" "--refill 24"; do
      for b in "$@"; do
        echo "== $(basename "$b") $c $(date +%T)"; sponza_q5 "$b" $c
      done
    done
  done
}
# Session 39's parts: unpack .device/bidir-NAME.gz for each NAME given (the binary is then
# .device/bidir-NAME).
# A time-budgeted render with the binary $1 for $2 seconds and the further options, against
# $REF (or REFERENCE=FILE): its samples, time and RMSE on one line.
at_time() {
  local b=$1 t=$2; shift 2
  echo "$(timeout -k 5 60 "$b" render "$@" --time "$t" -o /tmp/at_time.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$b" diff /tmp/at_time.exr "${REFERENCE:-$REF}" 2>&1 | grep -E '^RMSE ')"
}
# `bench render` with the binary $1 and the further options, warmed up, three runs: its GPU ms.
gpu_ms() {
  local b=$1; shift
  timeout -k 5 60 "$b" bench render "$@" --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms'
}
# `bench render` with the binary $1 and the further options, warmed up, three runs: its GPU ms
# and the ms per run of BDPT's wavefront path kernels (the table's column; not the build times
# of their pipelines printed before it, which have one decimal).
kernel_ms() {
  local b=$1; shift
  timeout -k 5 60 "$b" bench render "$@" --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront {2,}[0-9]+\.[0-9]{3}' | tr -s ' ' | tr '\n' ' '
}
# One round's BDPT `bench render` lines of the binary $1, named $2: its GPU ms and the kernel
# lines that match $3, on the Cornell box and the hidden light (1024 spp), on $HB (DamagedHelmet
# as the calling part sets it; 256 spp) and on Sponza with 8 candidates (64 spp).
bdpt_scene_benches() {
  local F=$1 n=$2 k=$3
  echo "== $n cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
  echo "== $n hidden: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
  echo "== $n helmet: $(timeout -k 5 60 "$F" bench render $HB --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
  echo "== $n sponza 8: $(timeout -k 5 60 "$F" bench render $SP --integrator bdpt --connection-candidates 8 --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
}
# The binary $1's wavefront image against its megakernels' (16 spp, seed 3) with the further
# options (a scene and the integrator), as one RMSE line.
wf_vs_mega() {
  local b=$1; shift
  rm -f /tmp/m.exr /tmp/w.exr # (a render that fails compares nothing, not the last call's images)
  timeout -k 5 60 "$b" render "$@" --wavefront off --spp 16 --seed 3 -o /tmp/m.exr > /dev/null 2>&1
  timeout -k 5 60 "$b" render "$@" --wavefront on --spp 16 --seed 3 -o /tmp/w.exr > /dev/null 2>&1
  "$b" diff /tmp/w.exr /tmp/m.exr 2>&1 | grep -E '^RMSE'
}
# Sets g to the GPU's name and prints it as the part's first line.
device_line() {
  g=$(nvidia-smi --query-gpu=name --format=csv,noheader | head -1)
  echo "== device: $g"
}
unpack() {
  for n in "$@"; do gunzip -kf ".device/bidir-$n.gz"; chmod +x ".device/bidir-$n"; done
}
# Session 52's parts: on an H200 (device_line's $g) first issue #16's ratio with HEAD's slices
# (s51q, .device/bidir-sf.gz) and #17's Sponza round with the same build; elsewhere nothing.
# $1: this script.
h200_first() {
  case "$g" in *H200*) timeout -k 5 90 bash "$1" s51q; unpack sf; timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-sf" ;; esac
}
# One round of BDPT's cost with the binary $1: `bench render` GPU ms and the camera kernel's
# share on the Cornell box and the hidden light's box (1024 spp), with `sponza` as $2 also
# Sponza's geometry under sun and sky with 8 candidates (64 spp), and with `time` as $2 or $3
# the Cornell box at 1 s against .device/ref.exr.
bdpt_round() {
  local b=$1; shift
  local costs='GPU [0-9.]+ ms|bdpt_camera_wavefront +[0-9.]+'
  echo "== $(basename "$b") $(date +%T)"
  echo "   cornell: $(timeout -k 5 60 "$b" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$costs" | tr '\n' ' ')"
  echo "   hidden: $(timeout -k 5 60 "$b" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$costs" | tr '\n' ' ')"
  for what in "$@"; do
    case $what in
      sponza) echo "   sponza 8: $(timeout -k 5 60 "$b" bench render $SP --integrator bdpt --connection-candidates 8 --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE "$costs" | tr '\n' ' ')" ;;
      time) echo "   1 s: $(timeout -k 5 60 "$b" render $CB --integrator bdpt --time 1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$b" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E '^RMSE' | tr '\n' ' ')" ;;
    esac
  done
}
# Two rounds of bdpt_round over the builds .device/bidir-NAME for each NAME given, interleaved,
# Sponza in both and the Cornell box at 1 s in the second.
bdpt_rounds() {
  for r in 1 2; do
    for n in "$@"; do
      if [ "$r" = 2 ]; then bdpt_round "$PWD/.device/bidir-$n" sponza time; else bdpt_round "$PWD/.device/bidir-$n" sponza; fi
    done
  done
}
# The trace kernels of the binary $1 as the driver compiled them, archived as $OUT/$2 (read
# with scripts/device/sass.py).
shader_cache() {
  local d=/tmp/nvcache-$2; rm -rf "$d"; mkdir -p "$d"
  __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$d __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 timeout -k 5 60 "$1" bench traversal --bvh bvh4 --leaf-size 3 --reps 5 --warmup 0 > /dev/null 2>&1
  tar czf "$OUT/$2" -C "$d" .
}
# Session 59's: the driver's compiled trace kernels of .device/bidir-NAME for each NAME given
# (bench traversal lockstep and with --refill 24, into one cache) as $OUT/cache-NAME.tgz, for
# scripts/device/sass.py.
trace_caches() {
  local b d m
  for b in "$@"; do
    d=/tmp/nvcache-r$b; rm -rf "$d"; mkdir -p "$d"
    for m in "" "--refill 24"; do
      __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$d __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 timeout -k 5 60 "$PWD/.device/bidir-$b" bench traversal --bvh bvh4 --leaf-size 3 $m --reps 5 --warmup 0 > /dev/null 2>&1
    done
    tar czf "$OUT/cache-$b.tgz" -C "$d" .
  done
}
# Session 58's parts: the hit-for-hit traversal tests of .device/test-traversal.gz (a test
# binary built with the patch under test, named $1 in the output) under the validation layers,
# Sponza's geometry where the tests look for it.
traversal_tests() {
  gunzip -kf .device/test-traversal.gz; chmod +x .device/test-traversal
  mkdir -p ../shared/scenes && ln -sfn $PWD/.device/scenes/sponza ../shared/scenes/sponza
  echo "== tests ($1)"; BIDIR_VALIDATION=1 timeout -k 5 200 .device/test-traversal 2>&1 | grep -E "^test |result|panicked|VUID|sponza \[" | head -40
}
# pt-nee's and bdpt's GPU ms with .device/bidir-NAME for each NAME given: Sponza under its sun
# and sky (64 spp), and unless SHORT is set the Cornell box (1024 spp).
integrator_lines() {
  for b in "$@"; do
    for i in pt-nee bdpt; do
      echo "== $b sponza $i: $(gpu_ms "$PWD/.device/bidir-$b" $SP --integrator $i --spp 64)"
      [ -n "${SHORT:-}" ] && continue
      echo "== $b cornell $i: $(gpu_ms "$PWD/.device/bidir-$b" $CB --integrator $i --spp 1024)"
    done
  done
}
# Issue #16's ratio with the binary $1 on the Cornell box: pt-nee's GPU ms and bdpt's with its
# path kernels' ms (1024 spp), then both at 1 s against $REF.
ratio_lines() {
  echo "== $(basename "$1") cornell pt-nee: $(gpu_ms "$1" $CB --integrator pt-nee --spp 1024) bdpt: $(kernel_ms "$1" $CB --integrator bdpt --spp 1024)"
  echo "== $(basename "$1") 1 s pt-nee: $(at_time "$1" 1 $CB --integrator pt-nee) bdpt: $(at_time "$1" 1 $CB --integrator bdpt)"
}
case "${1:-speed}" in
s63a)
  # Session 63 for the next (no device was lent in session 63): what the clear coat
  # (KHR_materials_clearcoat, SPEC_HAS_CLEARCOAT; GpuMaterial 128 -> 144 bytes) costs scenes
  # without one. hd (s60a's build, before it) against cc (a build of the commit that adds it;
  # its trace kernels are hd's), two rounds interleaved, GPU ms of pt-nee and bdpt on Sponza
  # under sun and sky (64 spp), DamagedHelmet under env and sun (256 spp) and the Cornell box
  # (1024 spp). Expected level within the runs' spread. Bundle: .device/bidir-cc.gz (a
  # stripped, gzipped release build of the clear coat's commit) beside hd.
  device_line
  unpack hd cc
  for r in 1 2; do
    for b in hd cc; do
      for i in pt-nee bdpt; do
        echo "== $b $i sponza: $(gpu_ms "$PWD/.device/bidir-$b" $SP --integrator $i --spp 64) helmet: $(gpu_ms "$PWD/.device/bidir-$b" $HB --integrator $i --spp 256) cornell: $(gpu_ms "$PWD/.device/bidir-$b" $CB --integrator $i --spp 1024)"
      done
    done
  done
  ;;
s62a)
  # Ran in session 62 on an H100 (ROUNDS=3): --packet 2.4 % slower than the lockstep loops on
  # primary rays, 22 % on shadow rays, 3.4x on diffuse rays; the tests passed (docs/traversal.md,
  # "Packet traversal"). As prepared: packet traversal (`--packet`, trace_bvh4_packet.comp: the
  # subgroup's rays walk the 4-wide tree together, a node at a time) against the lockstep
  # loops. pkt is a build of the commit that adds it (its default kernels' SPIR-V is hd's);
  # Sponza CameraMain quality 5, ROUNDS rounds (3) of hd and pkt lockstep and pkt --packet,
  # interleaved; pkt's hit-for-hit tests (.device/test-traversal.gz, built with it: the packet
  # variant among the others). Bundle: .device/bidir-pkt.gz beside s60a's hd (a stripped,
  # gzipped release build).
  device_line
  unpack hd pkt
  for r in $(seq "${ROUNDS:-3}"); do
    for b in hd pkt; do
      echo "== $b lockstep $(date +%T)"; sponza_q5 "$PWD/.device/bidir-$b"
    done
    echo "== pkt --packet $(date +%T)"; sponza_q5 "$PWD/.device/bidir-pkt" --packet
  done
  traversal_tests pkt
  ;;
s60b)
  # Ran in session 60 on an H100: pk and pb 5-20 % slower than hd, not kept (docs/traversal.md,
  # "One load fewer a node step, bought with decoding").
  # Session 59 for the next, a measurement build: pk (scripts/device/s60b-packed-children.patch)
  # packs each child pointer into the low bits of its six planes (XOR of each axis's pair:
  # 11 + 11 + 10 bits; the planes moved outward to the nearest float with those bits), so a
  # node step issues six 16-byte loads instead of seven, for about 24 more integer
  # instructions and boxes grown by up to 2^-12 of their coordinates' magnitude. Against hd
  # (HEAD). Sponza CameraMain quality 5, lockstep and --refill 24, ROUNDS rounds (2), then the
  # integrators on Sponza. Not a candidate as it stands: the growth is 2^11 ulps, 32 units at
  # tests/traversal.rs's scene 2^17 from the origin (6 units wide), whose persistent variants
  # then fail on lavapipe (every box covers the scene, each ray visits all 2,571 nodes, and 32
  # batches of 8 such rays overrun llvmpipe's 65,535 loop iterations: docs/traversal.md,
  # "llvmpipe loop limiter"); it asks what one load fewer a step is worth. pb
  # (s60c-packed-bytes.patch): the pointer's four bytes in the low bytes of the x and y planes,
  # lower and upper told apart by the ray's nx and ny (more shifts a step, boxes grown by at
  # most 256 ulps; the same lavapipe failure, its any-hit verdicts). Bundles: `bash
  # scripts/device/make-bundle.sh hd pk=s60b-packed-children.patch pb=s60c-packed-bytes.patch`.
  device_line
  unpack hd pk pb
  sponza_rounds "${ROUNDS:-2}" "$PWD/.device/bidir-hd" "$PWD/.device/bidir-pk" "$PWD/.device/bidir-pb"
  SHORT=1 integrator_lines hd pk pb
  ;;
s60a)
  # Session 59 for the next: issue #17's figures with HEAD (hd, a build of 0fbbcb7 or later,
  # which holds kd: dynamic fetch's closest-hit step reads the children's pointers only where
  # a child was hit). On an H200 this is the issue's measurement; on an H100 it repeats
  # session 59's. Sponza CameraMain quality 5, lockstep and --refill 24, ROUNDS rounds (3);
  # diffuse rays at --refill 20 and 28 (the best refill may have moved with kd); hd's
  # hit-for-hit tests; the integrators (SHORT=1: Sponza only). Bundle: `bash
  # scripts/device/make-bundle.sh hd`, then the test binary (`cargo test --release --test
  # traversal --no-run`, the binary it names stripped and gzipped as .device/test-traversal.gz).
  device_line
  unpack hd
  sponza_rounds "${ROUNDS:-3}" "$PWD/.device/bidir-hd"
  for r in 20 28; do
    echo "== hd --refill $r diffuse"; sponza_q5 "$PWD/.device/bidir-hd" --refill $r --rays diffuse
  done
  traversal_tests hd
  integrator_lines hd
  ;;
s59b)
  # Session 59: the stack's top entry kept in registers (a push stores the old top, a pop takes
  # the register and reloads it from local memory off the critical path), on top of kd:
  # rt (scripts/device/s59b-top-register.patch: the reload only where a step pops) and rl
  # (s59c-top-register-load.patch: the entry below loaded every step, taken where it pops),
  # against HEAD (base) and kd (s59a); Sponza CameraMain quality 5, lockstep and --refill 24,
  # ROUNDS rounds (2) interleaved; rl's hit-for-hit tests (.device/test-traversal.gz, built
  # with s59c); rt's and rl's machine code; the integrators on Sponza (SHORT=1) and the
  # Cornell box. Bundles as run, on 84ae5a7: base, kd=s59a-kid-dynamic.patch; rt and rl its
  # patches with kd's change in them. Since 163516e kd is the tree and the patches apply to it:
  # `bash scripts/device/make-bundle.sh kd rt=s59b-top-register.patch
  # rl=s59c-top-register-load.patch` (base then a build of 84ae5a7).
  device_line
  unpack base kd rt rl
  sponza_rounds "${ROUNDS:-2}" "$PWD/.device/bidir-base" "$PWD/.device/bidir-kd" "$PWD/.device/bidir-rt" "$PWD/.device/bidir-rl"
  traversal_tests rl
  trace_caches rt rl
  integrator_lines base kd rt rl
  ;;
s59a)
  # Session 59: s58d's kid (the children's pointers read after the box tests, only where a
  # child was hit) won diffuse rays 1 % at --refill 24 on an H100 but cost shadow rays 1.5 %
  # and the lockstep kernel's primary rays 5 %. kd (scripts/device/s59a-kid-dynamic.patch):
  # that read in the dynamic-fetch closest-hit step alone, against HEAD (base) and kid; Sponza
  # CameraMain quality 5, lockstep and --refill 24, ROUNDS rounds (3) interleaved; kd's
  # hit-for-hit tests (.device/test-traversal.gz, built with s59a); the integrators on Sponza
  # and the Cornell box. Bundles: `bash scripts/device/make-bundle.sh base
  # kd=s59a-kid-dynamic.patch kid=s58f-kid.patch` in a checkout of 84ae5a7 (both patches
  # change the children's read that 163516e, kd itself, changed: they apply to 84ae5a7 only);
  # the test binary as s58d's, with s59a.
  device_line
  unpack base kd kid
  sponza_rounds "${ROUNDS:-3}" "$PWD/.device/bidir-base" "$PWD/.device/bidir-kd" "$PWD/.device/bidir-kid"
  traversal_tests kd
  integrator_lines base kd
  ;;
s58d)
  # Session 58: fewer loads a node step. s58b's diagnostic (one more 16-byte load a step, the
  # distances unchanged) cost dynamic fetch's diffuse rays 8.5 % on an H100: the step is bound
  # by its memory requests. top (scripts/device/s58d-toppred.patch): the stack's top read only
  # where no child was hit (before: every step); tk (s58e-top-kid.patch): that, and the
  # children's pointers read only where a child was hit; kid (s58f-kid.patch) the second
  # alone; xu (s58g-extra-uniform.patch, a diagnostic): s58c's extra load with every lane on
  # one word, to tell a cost per divergent line (xu cheap: cooperative node fetches could pay)
  # from a cost per load instruction (xu as dear as s58c's 8.5 %). Against HEAD (base),
  # Sponza CameraMain quality 5, lockstep and --refill 24, ROUNDS rounds (2) interleaved; tk's
  # hit-for-hit tests (.device/test-traversal.gz, built with s58e); top's and tk's machine
  # code; the integrators (SHORT=1: Sponza only). Bundles: `bash scripts/device/make-bundle.sh
  # base top=s58d-toppred.patch tk=s58e-top-kid.patch kid=s58f-kid.patch
  # xu=s58g-extra-uniform.patch` in a checkout of 84ae5a7 (s58e, s58f and s58g change the
  # children's read that 163516e changed: they apply to 84ae5a7 only); the test binary: s58e
  # applied, `cargo test --release --test traversal --no-run`, the binary it names stripped
  # and gzipped as .device/test-traversal.gz after make-bundle.sh (which empties .device/).
  device_line
  unpack base top tk kid xu
  sponza_rounds "${ROUNDS:-2}" "$PWD/.device/bidir-base" "$PWD/.device/bidir-top" "$PWD/.device/bidir-tk" "$PWD/.device/bidir-kid" "$PWD/.device/bidir-xu"
  traversal_tests tk
  trace_caches top tk xu
  integrator_lines base top tk
  ;;
s58b)
  # Session 58: the closest-hit leaf loop of the trace kernels' lockstep loops (dynamic fetch's
  # diffuse rays) loading a leaf's next triangle while it tests the current one
  # (scripts/device/s58b-pipe.patch, .device/bidir-pipe.gz) against HEAD (.device/bidir-base.gz),
  # and extra (scripts/device/s58c-extra.patch, a diagnostic): one more 16-byte load a node step
  # from the node's own line, the distances unchanged: what one more divergent load costs
  # (s58c applies to 84ae5a7 and earlier, before 163516e changed the children's read).
  # Sponza CameraMain quality 5, lockstep and --refill 24, two rounds interleaved; the pipe
  # patch's hit-for-hit tests (.device/test-traversal.gz, built with it); the integrators; the
  # refill count; the dynamic-fetch kernels' machine code.
  device_line
  unpack base pipe extra
  sponza_rounds 2 "$PWD/.device/bidir-base" "$PWD/.device/bidir-pipe" "$PWD/.device/bidir-extra"
  traversal_tests pipe
  integrator_lines base pipe
  for r in 20 28; do
    for b in base pipe; do echo "== $b --refill $r diffuse"; sponza_q5 "$PWD/.device/bidir-$b" --refill $r --rays diffuse; done
  done
  for b in base pipe; do
    d=/tmp/nvcache-r$b; rm -rf "$d"; mkdir -p "$d"
    __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$d __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 timeout -k 5 60 "$PWD/.device/bidir-$b" bench traversal --bvh bvh4 --leaf-size 3 --refill 24 --reps 5 --warmup 0 > /dev/null 2>&1
    tar czf "$OUT/cache-r$b.tgz" -C "$d" .
  done
  ;;
s58a)
  # Session 58: the 4-wide node step's pushes at known places above the stack's top, each
  # store predicated on its child being hit, the top moved once (scripts/device/s58a-push.patch,
  # .device/bidir-push.gz) against HEAD (.device/bidir-base.gz): Sponza CameraMain quality 5,
  # lockstep and --refill 24, three rounds interleaved; the integrators on Sponza and the
  # Cornell box; both builds' machine code; the patch's hit-for-hit tests under the validation
  # layers (.device/test-traversal.gz, built with the patch).
  device_line
  unpack base push
  sponza_rounds 3 "$PWD/.device/bidir-base" "$PWD/.device/bidir-push"
  integrator_lines base push
  shader_cache "$PWD/.device/bidir-base" cache-base.tgz
  shader_cache "$PWD/.device/bidir-push" cache-push.tgz
  traversal_tests push
  ;;
s57d)
  # Session 57: issue #16's aims as the issue measures them: `bidir converge --time 1` of pt-nee
  # and bdpt against $REF with cv (6351338: converge's BDPT with its own Russian roulette depth,
  # 3, where it had taken pt's 5) and with sp (the same passes, converge still at depth 5), twice
  # each; the curves' CSVs to $OUT.
  device_line
  unpack cv sp
  for r in 1 2; do
    for n in cv sp; do
      timeout -k 5 60 .device/bidir-$n converge --reference "$REF" --integrators pt-nee,bdpt --time 1 --points 3 --out /tmp/conv-$n-$r > /dev/null 2>&1
      cp /tmp/conv-$n-$r/convergence.csv "$OUT/conv-$n-$r.csv"
      echo "== r$r $n: $(tr '\n' ' ' < /tmp/conv-$n-$r/convergence.csv)"
    done
  done
  ;;
s57c)
  # Session 57: sp (the passes side by side, N = 4 by default, the next camera pass's first
  # launch beside the light pass's first launch after this camera pass's end and its trace beside
  # the light pass's finishing launch) against sb with --wavefront-overlap 4 (the first launch
  # and its trace beside the light pass's last two steps), two rounds, the order reversed in the
  # second; pt-nee in both; the 1 s counts; sp's wavefront image against its megakernels'. On an
  # H200 first the ratio with sp and the Sponza traversal round.
  device_line
  unpack sb sp
  case "$g" in
    *H200*) ratio_lines "$PWD/.device/bidir-sp"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-sp" ;;
  esac
  for r in 1 2; do
    order="sp sb"; [ $r = 2 ] && order="sb sp"
    for n in $order; do
      o=""; [ $n = sb ] && o="--wavefront-overlap 4"
      echo "== r$r $n cornell: $(gpu_ms .device/bidir-$n $CB --integrator bdpt --spp 1024 $o | tr '\n' ' ') hidden: $(gpu_ms .device/bidir-$n $HID --integrator bdpt --spp 1024 $o | tr '\n' ' ')"
    done
    echo "== r$r pt-nee: $(gpu_ms .device/bidir-sp $CB --integrator pt-nee --spp 1024)"
  done
  echo "== 1 s pt-nee: $(at_time .device/bidir-sp 1 $CB --integrator pt-nee) sp: $(at_time .device/bidir-sp 1 $CB --integrator bdpt)"
  echo "== sp wf/mega cornell: $(wf_vs_mega .device/bidir-sp $CB --integrator bdpt)"
  ;;
s57b)
  # Session 57: s57a's core for short device time: on an H200 the ratio with sb; sb against the
  # same build with --wavefront-overlap off and ov, two rounds (the order reversed in the second),
  # GPU and wall ms on the Cornell box; N = 2 and 12; the 1 s counts; sb's wavefront image
  # against its megakernels'.
  device_line
  unpack ov sb
  case "$g" in *H200*) ratio_lines "$PWD/.device/bidir-sb" ;; esac
  k='GPU [0-9.]+ ms|wall [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9]+\.[0-9]{3}'
  km() { local b=$1; shift; timeout -k 5 60 "$b" bench render "$@" --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr -s ' ' | tr '\n' ' '; }
  for r in 1 2; do
    order="sb off ov"; [ $r = 2 ] && order="ov off sb"
    for n in $order; do
      b=.device/bidir-$n; o=""; [ $n = off ] && b=.device/bidir-sb && o="--wavefront-overlap off"
      echo "== r$r $n cornell: $(km $b $CB --integrator bdpt --spp 1024 $o)"
    done
  done
  for n in 2 12; do
    echo "== sb --wavefront-overlap $n cornell: $(gpu_ms .device/bidir-sb $CB --integrator bdpt --spp 1024 --wavefront-overlap $n | tr '\n' ' ')"
  done
  echo "== 1 s pt-nee: $(at_time .device/bidir-sb 1 $CB --integrator pt-nee) sb: $(at_time .device/bidir-sb 1 $CB --integrator bdpt) off: $(at_time .device/bidir-sb 1 $CB --integrator bdpt --wavefront-overlap off)"
  echo "== sb wf/mega cornell: $(wf_vs_mega .device/bidir-sb $CB --integrator bdpt)"
  ;;
s57a)
  # Session 57: sb (the passes side by side: each camera pass's last N launches beside the next
  # light pass, its first launch and trace beside that light pass's tail, over two light-vertex
  # stores; each pass with its own slots; --wavefront-overlap N, default 6) against the same
  # build with --wavefront-overlap off (each pass alone) and ov (7f6a412, session 56's HEAD), two
  # rounds, the order reversed in the second, GPU and wall ms; N = 2, 4, 8, 12; the 1 s counts;
  # the wavefront images against the megakernels'; DamagedHelmet and Sponza with sb and off. On
  # an H200 first the ratio with sb and the Sponza traversal round.
  device_line
  unpack ov sb
  case "$g" in
    *H200*) ratio_lines "$PWD/.device/bidir-sb"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-sb" ;;
  esac
  k='GPU [0-9.]+ ms|wall [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9]+\.[0-9]{3}'
  km() { local b=$1; shift; timeout -k 5 60 "$b" bench render "$@" --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr -s ' ' | tr '\n' ' '; }
  for r in 1 2; do
    order="sb off ov"; [ $r = 2 ] && order="ov off sb"
    for n in $order; do
      b=.device/bidir-$n; o=""; [ $n = off ] && b=.device/bidir-sb && o="--wavefront-overlap off"
      h=""; [ $r = 1 ] && h="hidden: $(km $b $HID --integrator bdpt --spp 1024 $o)"
      echo "== r$r $n cornell: $(km $b $CB --integrator bdpt --spp 1024 $o) $h"
    done
  done
  for n in 2 4 8 12; do
    echo "== sb --wavefront-overlap $n cornell: $(gpu_ms .device/bidir-sb $CB --integrator bdpt --spp 1024 --wavefront-overlap $n | tr '\n' ' ')"
  done
  for f in 8 14; do
    echo "== sb --wavefront-finish $f cornell: $(gpu_ms .device/bidir-sb $CB --integrator bdpt --spp 1024 --wavefront-finish $f | tr '\n' ' ')"
  done
  echo "== 1 s pt-nee: $(at_time .device/bidir-sb 1 $CB --integrator pt-nee) sb: $(at_time .device/bidir-sb 1 $CB --integrator bdpt) off: $(at_time .device/bidir-sb 1 $CB --integrator bdpt --wavefront-overlap off)"
  echo "== sb wf/mega cornell: $(wf_vs_mega .device/bidir-sb $CB --integrator bdpt) hidden: $(wf_vs_mega .device/bidir-sb $HID --integrator bdpt)"
  for o in 6 off; do
    echo "== overlap $o helmet: $(km .device/bidir-sb $HB --integrator bdpt --spp 256 --wavefront-overlap $o) sponza 8: $(km .device/bidir-sb $SP --integrator bdpt --connection-candidates 8 --spp 64 --wavefront-overlap $o)"
  done
  echo "== 1 s pt-nee again: $(at_time .device/bidir-sb 1 $CB --integrator pt-nee)"
  ;;
s56f)
  # Session 56: f2 (fr with the first launch's sizes written by its first invocation, no workgroup
  # counting itself; the batch's three fills behind one barrier), w128 (f2 with BDPT's wavefront
  # kernels in workgroups of 128: half the workgroups' atomics at the same occupancy) and ov (f2
  # with each pass submitted behind the one before when that one's first batch ends it: no host
  # round trip between passes; a build of 7f6a412, HEAD's code at session 56's end) and a64 (ov
  # with scripts/device/s56g-counts64.patch: a launch's segment and shadow-ray counts in one
  # 64-bit atomic a subgroup instead of two 32-bit ones) against h55, two rounds, the order
  # reversed in the second, GPU and wall ms; the 1 s counts; the finishing launch's place with
  # f2; f2's dispatches (BIDIR_PROFILE_LOG) to $OUT. On an H200 first the ratio with ov and h55,
  # the Sponza round with ov.
  device_line
  unpack h55 f2 w128 ov a64
  case "$g" in
    *H200*) ratio_lines "$PWD/.device/bidir-ov"; ratio_lines "$PWD/.device/bidir-h55"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-ov" ;;
  esac
  k='GPU [0-9.]+ ms|wall [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9]+\.[0-9]{3}'
  km() { local b=$1; shift; timeout -k 5 60 "$b" bench render "$@" --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr -s ' ' | tr '\n' ' '; }
  for r in 1 2; do
    order="h55 f2 w128 ov a64"; [ $r = 2 ] && order="a64 ov w128 f2 h55"
    for n in $order; do
      h=""; [ $r = 1 ] && [ $n != w128 ] && [ $n != f2 ] && h="hidden: $(km .device/bidir-$n $HID --integrator bdpt --spp 1024)"
      echo "== r$r $n cornell: $(km .device/bidir-$n $CB --integrator bdpt --spp 1024) $h"
    done
  done
  for r in 1 2; do
    echo "== r$r 1 s pt-nee: $(at_time .device/bidir-ov 1 $CB --integrator pt-nee) f2: $(at_time .device/bidir-f2 1 $CB --integrator bdpt) ov: $(at_time .device/bidir-ov 1 $CB --integrator bdpt)"
  done
  for f in 6 8 10 auto; do
    echo "== f2 --wavefront-finish $f cornell: $(gpu_ms .device/bidir-f2 $CB --integrator bdpt --spp 1024 --wavefront-finish $f)"
  done
  BIDIR_PROFILE_LOG=1 timeout -k 5 60 .device/bidir-f2 bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 1 > "$OUT/profile-f2.txt" 2>&1
  echo "== ov wf/mega cornell: $(wf_vs_mega .device/bidir-ov $CB --integrator bdpt)"
  ;;
s56e)
  # Session 56: BDPT's passes without the first launch's atomics (fr: a build of the working tree
  # after s56d, the first launch counting and listing nothing, the launch after it running every
  # slot) against h55, two rounds, the order reversed in the second; fr's dispatches one by one
  # (BIDIR_PROFILE_LOG) to $OUT; its wavefront images against its megakernels'. On an H200 first
  # the ratio with fr and h55 and the Sponza round with fr.
  device_line
  unpack h55 fr
  case "$g" in
    *H200*) ratio_lines "$PWD/.device/bidir-fr"; ratio_lines "$PWD/.device/bidir-h55"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-fr" ;;
  esac
  for r in 1 2; do
    order="h55 fr"; [ $r = 2 ] && order="fr h55"
    for n in $order; do
      bdpt_scene_benches .device/bidir-$n "r$r $n" 'GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9]+\.[0-9]{3}|trace_bvh4 +[0-9]+\.[0-9]{3}'
    done
  done
  BIDIR_PROFILE_LOG=1 timeout -k 5 60 .device/bidir-fr bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 1 > "$OUT/profile-fr.txt" 2>&1
  echo "== fr wf/mega cornell: $(wf_vs_mega .device/bidir-fr $CB --integrator bdpt) hidden: $(wf_vs_mega .device/bidir-fr $HID --integrator bdpt)"
  echo "== fr 1 s bdpt: $(at_time .device/bidir-fr 1 $CB --integrator bdpt) pt-nee: $(at_time .device/bidir-fr 1 $CB --integrator pt-nee)"
  ;;
s56d)
  # Session 56: each dispatch's GPU time in turn (BIDIR_PROFILE_LOG, pl: a build of HEAD with it):
  # one profiled run of BDPT's and pt-nee's Cornell box, 1024 spp, and BDPT's hidden light, each
  # log to $OUT (the device tool's folder, else /tmp/pending). On an H200 first s56a's ratio and
  # Sponza round with pl.
  device_line
  unpack pl
  case "$g" in
    *H200*) ratio_lines "$PWD/.device/bidir-pl"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-pl" ;;
  esac
  for i in bdpt pt-nee; do
    BIDIR_PROFILE_LOG=1 timeout -k 5 60 .device/bidir-pl bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 1 > "$OUT/profile-$i.txt" 2>&1
    echo "== $i: $(grep -oE 'GPU [0-9.]+ ms' "$OUT/profile-$i.txt" | head -1), $(grep -c '^profile ' "$OUT/profile-$i.txt") intervals"
  done
  BIDIR_PROFILE_LOG=1 timeout -k 5 60 .device/bidir-pl bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 1 > "$OUT/profile-hidden.txt" 2>&1
  echo "== hidden: $(grep -oE 'GPU [0-9.]+ ms' "$OUT/profile-hidden.txt" | head -1)"
  ;;
s56c)
  # Session 56: the megakernels (pt_kernel.glsl's, pt-nee's pt_queue among them; bdpt_camera.comp,
  # bdpt_light.comp) in workgroups of 1024, which holds NVIDIA's compiler to 64 registers: mg, a
  # build of HEAD with scripts/device/s56c-mega-1024.patch (the shadow queue's kernels dispatched
  # over as many invocations). On an H200 first s56a's ratio and Sponza round with h55. Registers,
  # then two rounds, the order reversed in the second: GPU ms and the kernels' ms.
  device_line
  unpack h55 mg
  case "$g" in
    *H200*) ratio_lines "$PWD/.device/bidir-h55"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-h55" ;;
  esac
  timeout -k 5 60 .device/bidir-mg info --kernels 2>&1 | grep -E "^(pt-nee|bdpt:full) " | sed "s/^/mg /" | cut -c1-70,130-
  k='GPU [0-9.]+ ms|(pt_queue|shadow_queue|shadow_queue_splat|bdpt_camera|bdpt_light)_cwbvh +[0-9]+\.[0-9]{3}'
  km() { local b=$1; shift; timeout -k 5 60 "$b" bench render "$@" --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr -s ' ' | tr '\n' ' '; }
  for r in 1 2; do
    order="h55 mg"; [ $r = 2 ] && order="mg h55"
    for n in $order; do
      F=.device/bidir-$n
      echo "== r$r $n cornell pt-nee: $(km $F $CB --integrator pt-nee --spp 1024)"
      echo "== r$r $n cornell bdpt mega: $(km $F $CB --integrator bdpt --wavefront off --spp 1024)"
      echo "== r$r $n hidden bdpt mega: $(km $F $HID --integrator bdpt --wavefront off --spp 1024)"
      echo "== r$r $n helmet pt-nee: $(km $F $HB --integrator pt-nee --spp 256) sponza pt-nee: $(km $F $SP --integrator pt-nee --spp 64)"
    done
  done
  for i in pt-nee bdpt; do
    rm -f /tmp/a.exr /tmp/b.exr
    .device/bidir-h55 render $CB --integrator $i --wavefront off --spp 16 --seed 3 -o /tmp/a.exr > /dev/null 2>&1
    .device/bidir-mg render $CB --integrator $i --wavefront off --spp 16 --seed 3 -o /tmp/b.exr > /dev/null 2>&1
    echo "== mg against h55 $i megakernel: $(.device/bidir-mg diff /tmp/b.exr /tmp/a.exr 2>&1 | grep -E '^RMSE')"
  done
  echo "== 1 s pt-nee h55: $(at_time .device/bidir-h55 1 $CB --integrator pt-nee) mg: $(at_time .device/bidir-mg 1 $CB --integrator pt-nee)"
  echo "== 1 s bdpt mega h55: $(at_time .device/bidir-h55 1 $CB --integrator bdpt --wavefront off) mg: $(at_time .device/bidir-mg 1 $CB --integrator bdpt --wavefront off)"
  ;;
s56b)
  # Session 56: the wavefront camera kernel (and its finishing launch) in workgroups of 1024,
  # which holds NVIDIA's compiler to 64 registers (1024 x 64 = the SM's 65,536): wk, a build of
  # HEAD with `#define WF_WG_SIZE 1024` in bdpt_camera_wavefront.glsl; pq, wk with pt_kernel.glsl's
  # megakernels (pt-nee's pt_queue) in workgroups of 1024 too. On an H200 first s56a's ratio and
  # Sponza round with h55. Registers (`info --kernels`), then two rounds, the order reversed in
  # the second: bdpt on the Cornell box and the hidden light (GPU ms, path kernels' ms), pt-nee
  # on the Cornell box; the images against their megakernels'.
  device_line
  unpack h55 wk pq
  case "$g" in
    *H200*) ratio_lines "$PWD/.device/bidir-h55"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-h55" ;;
  esac
  for n in wk pq; do
    timeout -k 5 60 .device/bidir-$n info --kernels 2>&1 | grep -E "bdpt_camera_(wavefront|finish_bvh4)|pt_queue_cwbvh" | sed "s/^/$n /" | cut -c1-60,120-
  done
  for r in 1 2; do
    order="h55 wk pq"; [ $r = 2 ] && order="pq wk h55"
    for n in $order; do
      echo "== r$r $n cornell: $(kernel_ms .device/bidir-$n $CB --integrator bdpt --spp 1024) hidden: $(kernel_ms .device/bidir-$n $HID --integrator bdpt --spp 1024)"
      echo "== r$r $n pt-nee: $(gpu_ms .device/bidir-$n $CB --integrator pt-nee --spp 1024) helmet bdpt: $(gpu_ms .device/bidir-$n $HB --integrator bdpt --spp 256)"
    done
  done
  echo "== wk wf/mega cornell bdpt: $(wf_vs_mega .device/bidir-wk $CB --integrator bdpt)"
  echo "== pq 1 s pt-nee: $(at_time .device/bidir-pq 1 $CB --integrator pt-nee) wk bdpt: $(at_time .device/bidir-wk 1 $CB --integrator bdpt)"
  ;;
s56a)
  # Session 56's tries for an H200: there, issue #16's ratio with h55 (a build of e340ce5, HEAD's
  # code) and #17's Sponza round; on any card `info --kernels` (its resident-warps line, never yet
  # seen on a GPU) and the ratio with h55, to tie this card to session 55's figures.
  device_line
  unpack h55
  case "$g" in
    *H200*) ratio_lines "$PWD/.device/bidir-h55"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-h55"
      echo "== h55 again pt-nee: $(gpu_ms .device/bidir-h55 $CB --integrator pt-nee --spp 1024) bdpt: $(gpu_ms .device/bidir-h55 $CB --integrator bdpt --spp 1024)" ;;
    *) timeout -k 5 60 .device/bidir-h55 info --kernels 2>&1 | tail -40
      ratio_lines "$PWD/.device/bidir-h55" ;;
  esac
  ;;
s54)
  # Session 54's start: on an H200 first issue #16's ratio with .device/bidir-hd.gz (8aeb81a,
  # HEAD's kernels: pt-nee and bdpt, 1024 spp and 1 s) and #17's Sponza round; then on any card
  # the camera kernel's shadow-ray contributions in 8 bytes (pk, a build of what became
  # glsl/common/packed_contrib.glsl, each channel rounded to 13-14 bits of mantissa) and in 12 (c12, s54-contrib-12.patch, exact)
  # against 16 (hd): two rounds, the order reversed in the second, GPU ms and the path kernels'
  # ms per run on the Cornell box and where the light hides; pk's wavefront image against its
  # megakernels'; the 1 s counts.
  device_line
  unpack hd pk c12
  H=$PWD/.device/bidir-hd
  case "$g" in
    *H200*) ratio_lines "$H"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $H" ;;
  esac
  for r in 1 2; do
    order="hd pk c12"; [ $r = 2 ] && order="c12 pk hd"
    for n in $order; do
      echo "== r$r $n cornell: $(kernel_ms .device/bidir-$n $CB --integrator bdpt --spp 1024) hidden: $(kernel_ms .device/bidir-$n $HID --integrator bdpt --spp 1024)"
    done
  done
  echo "== pk wavefront against megakernels: $(wf_vs_mega .device/bidir-pk $CB --integrator bdpt)"
  for n in hd pk c12; do echo "== $n 1 s bdpt: $(at_time .device/bidir-$n 1 $CB --integrator bdpt)"; done
  case "$g" in *H200*) ;; *) echo "== hd 1 s pt-nee: $(at_time "$H" 1 $CB --integrator pt-nee)" ;; esac
  ;;
s55h)
  # Session 55: s55g's build with bit 3 (the connection's read candidates in shared memory
  # instead of the reading lanes' registers): registers, then GPU ms, two rounds.
  device_line
  unpack xc
  for e in 0 8; do
    echo "== exp $e: $(BIDIR_EXP_CAMERA=$e timeout -k 5 60 .device/bidir-xc info --kernels 2>&1 | grep -E '^bdpt:lvc=1 / bdpt_camera_wavefront' | grep -oE '(Register Count|Local Memory Size|Shared Memory Size) [0-9]+' | tr '\n' ' ')"
  done
  for e in 0 8 8 0; do
    echo "== exp $e cornell: $(export BIDIR_EXP_CAMERA=$e; kernel_ms .device/bidir-xc $CB --integrator bdpt --spp 1024) hidden: $(export BIDIR_EXP_CAMERA=$e; kernel_ms .device/bidir-xc $HID --integrator bdpt --spp 1024)"
  done
  ;;
s55g)
  # Session 55: the camera kernel's registers (a measurement build, xc:
  # scripts/device/s55g-exp-camera.patch, BIDIR_EXP_CAMERA bit 0 leaves out the light sample,
  # bit 1 the connections, bit 2 recomputes the film's place from the slot at the end):
  # `info --kernels` per setting, then GPU ms and the path kernels' ms on the Cornell box.
  device_line
  unpack xc
  for e in 0 1 2 3 4; do
    echo "== exp $e: $(BIDIR_EXP_CAMERA=$e timeout -k 5 60 .device/bidir-xc info --kernels 2>&1 | grep -E '^bdpt:lvc=1 / bdpt_camera_wavefront' | grep -oE '(Register Count|Local Memory Size|Shared Memory Size|Stack Size) [0-9]+' | tr '\n' ' ')"
  done
  for e in 0 4 1 2 0 4; do
    echo "== exp $e cornell: $(export BIDIR_EXP_CAMERA=$e; kernel_ms .device/bidir-xc $CB --integrator bdpt --spp 1024)"
  done
  ;;
s55f)
  # Session 55: the finishing launch's threshold where the wavefront traces are not persistent
  # (fb: what the device keeps resident, not a quarter of the queue's slots) against rw, with
  # --wavefront-finish off beside them: BDPT on the Cornell box over cwbvh and bvh2 and over the
  # default bvh4 (unchanged); the wavefront path tracer over cwbvh on Sponza and the Cornell box.
  device_line
  unpack rw fb
  for bvh in cwbvh bvh2 bvh4; do
    for n in rw fb; do
      echo "== $n cornell bdpt --bvh $bvh: $(kernel_ms .device/bidir-$n $CB --integrator bdpt --spp 1024 --bvh $bvh --wavefront on)"
    done
  done
  echo "== off cornell bdpt --bvh cwbvh: $(kernel_ms .device/bidir-fb $CB --integrator bdpt --spp 1024 --bvh cwbvh --wavefront on --wavefront-finish off)"
  for n in rw fb; do
    echo "== $n pt-nee --bvh cwbvh --wavefront on: sponza $(gpu_ms .device/bidir-$n $SP --integrator pt-nee --spp 64 --bvh cwbvh --wavefront on) cornell $(gpu_ms .device/bidir-$n $CB --integrator pt-nee --spp 1024 --bvh cwbvh --wavefront on)"
  done
  echo "== off pt-nee --bvh cwbvh --wavefront on: sponza $(gpu_ms .device/bidir-fb $SP --integrator pt-nee --spp 64 --bvh cwbvh --wavefront on --wavefront-finish off) cornell $(gpu_ms .device/bidir-fb $CB --integrator pt-nee --spp 1024 --bvh cwbvh --wavefront on --wavefront-finish off)"
  echo "== fb wf-vs-mega cornell bdpt --bvh cwbvh: $(wf_vs_mega .device/bidir-fb $CB --integrator bdpt --bvh cwbvh)"
  ;;
s55e)
  # Session 55's tries for an H200: there, issue #16's ratio with rw (HEAD's kernels since
  # a7a2f8a, the compact rays) and with hd (3935d5d), then #17's Sponza round with rw; on any
  # other card nothing (the call only tells which card came).
  device_line
  case "$g" in
    *H200*) unpack rw hd
      ratio_lines "$PWD/.device/bidir-rw"
      ratio_lines "$PWD/.device/bidir-hd"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-rw"
      echo "== rw again pt-nee: $(gpu_ms .device/bidir-rw $CB --integrator pt-nee --spp 1024) bdpt: $(gpu_ms .device/bidir-rw $CB --integrator bdpt --spp 1024)" ;;
    *) unpack rw
      # Sponza's pt-nee: the wavefront image against the megakernels' over one BVH (the defaults
      # differ by RMSE 0.018640 on an H100, the megakernel over cwbvh, the wavefront over bvh4).
      # BDPT's wavefront passes over layouts whose traces are not persistent (cwbvh, bvh2): the
      # finishing launch's automatic threshold (a quarter of the queue's slots there) against none.
      for bvh in cwbvh bvh2; do
        for f in auto off; do
          echo "== rw cornell bdpt --bvh $bvh --wavefront-finish $f: $(kernel_ms .device/bidir-rw $CB --integrator bdpt --spp 1024 --bvh $bvh --wavefront on --wavefront-finish $f)"
        done
      done ;;
  esac
  ;;
s55d)
  # Session 55: the wavefront passes' trace loops (a measurement build of rw, tx:
  # BIDIR_EXP_WF_TRACE = lockstep (one ray per invocation), persistent (batches, no refill) or
  # refill=N (dynamic fetch at N lanes; the default 16)): GPU ms and the trace kernels' ms per run.
  device_line
  unpack tx
  k='GPU [0-9.]+ ms|trace_[a-z0-9_]+ +[0-9]+\.[0-9]{3}'
  for v in default lockstep persistent refill=8 refill=24 default; do
    e=""; [ $v != default ] && e="BIDIR_EXP_WF_TRACE=$v"
    echo "== $v cornell: $(env $e timeout -k 5 60 .device/bidir-tx bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr -s ' ' | tr '\n' ' ')"
    echo "== $v hidden: $(env $e timeout -k 5 60 .device/bidir-tx bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr -s ' ' | tr '\n' ' ')"
    echo "== $v helmet: $(env $e timeout -k 5 60 .device/bidir-tx bench render $HB --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr -s ' ' | tr '\n' ' ')"
    echo "== $v sponza pt-nee: $(env $e timeout -k 5 60 .device/bidir-tx bench render $SP --integrator pt-nee --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr -s ' ' | tr '\n' ' ')"
  done
  ;;
s55c)
  # Session 55: on an H200 first issue #16's ratio with hd and with rw (the compact ray forms),
  # #17's Sponza round with rw; then on any card session 51's question left open: the camera kernel's
  # early reads with the connection's candidates asked for early too (pf, s51b-early-reads.patch
  # with WF_LVC_PREFETCH) against the early reads alone (er), two rounds, the order reversed in
  # the second, with their wavefront images against their megakernels'.
  device_line
  unpack rw er pf
  case "$g" in
    *H200*) unpack hd; ratio_lines "$PWD/.device/bidir-hd"; ratio_lines "$PWD/.device/bidir-rw"
      timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-rw" ;;
  esac
  for r in 1 2; do
    order="er pf"; [ $r = 2 ] && order="pf er"
    for n in $order; do
      F=.device/bidir-$n
      echo "== r$r $n cornell: $(kernel_ms $F $CB --integrator bdpt --spp 1024) hidden: $(kernel_ms $F $HID --integrator bdpt --spp 1024)"
    done
  done
  echo "== pf wf-vs-mega cornell bdpt: $(wf_vs_mega .device/bidir-pf $CB --integrator bdpt)"
  ;;
s55b)
  # Session 55: the wavefront passes' rays in compact forms (rw: segments in 24 bytes, shadow
  # rays in 28, glsl/common/ray_words.glsl) against HEAD before them (hd): two rounds, the order
  # reversed in the second, BDPT on the Cornell box, where the light hides and on DamagedHelmet,
  # pt-nee on Sponza under sun and sky (the wavefront path tracer); rw's wavefront images against
  # its megakernels'; issue #16's ratio with rw.
  device_line
  unpack hd rw
  for r in 1 2; do
    order="hd rw"; [ $r = 2 ] && order="rw hd"
    for n in $order; do
      F=.device/bidir-$n
      echo "== r$r $n cornell: $(kernel_ms $F $CB --integrator bdpt --spp 1024) hidden: $(kernel_ms $F $HID --integrator bdpt --spp 1024)"
      echo "== r$r $n helmet: $(kernel_ms $F $HB --integrator bdpt --spp 256) sponza pt-nee: $(gpu_ms $F $SP --integrator pt-nee --spp 64)"
    done
  done
  echo "== rw wf-vs-mega cornell bdpt: $(wf_vs_mega .device/bidir-rw $CB --integrator bdpt) sponza pt-nee: $(wf_vs_mega .device/bidir-rw $SP --integrator pt-nee)"
  ratio_lines "$PWD/.device/bidir-rw"
  ;;
s55)
  # The next start: .device/bidir-hd.gz is a build of HEAD (session 54's packed contributions).
  # On an H200 issue #16's ratio (pt-nee and bdpt, 1024 spp and 1 s) and #17's Sponza round;
  # on any card the same ratio and BDPT's path kernels' ms; then what the megakernels' rounding
  # of shadow-ray contributions costs vcm (and costs nothing, bdpt:full): hd against h53
  # (8aeb81a, session 53's kernels), two rounds.
  device_line
  unpack hd h53
  H=$PWD/.device/bidir-hd
  ratio_lines "$H"
  case "$g" in
    *H200*) timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $H"
      echo "== hd again pt-nee: $(gpu_ms "$H" $CB --integrator pt-nee --spp 1024) bdpt: $(gpu_ms "$H" $CB --integrator bdpt --spp 1024)" ;;
  esac
  for n in hd h53 h53 hd; do
    echo "== $n vcm: $(gpu_ms .device/bidir-$n $CB --integrator vcm --spp 256) bdpt:full: $(gpu_ms .device/bidir-$n $CB --integrator bdpt:full --spp 256) bdpt megakernels: $(gpu_ms .device/bidir-$n $CB --integrator bdpt --wavefront off --spp 256)"
  done
  ;;
s53)
  # Ran in session 53 (an H100); its cs and ci2 builds are in /work/device-spare now.
  # Session 53's start, whatever card comes: on an H200 first s51q and #17's Sponza round
  # (h200_first); then .device/bidir-cs.gz, two changes to two kernels: the camera kernel's
  # pending shadow rays written and read at constant indices (scripts/device/s53-const-index.patch:
  # the loops unrolled, so that no Function array indexed at run time is left in
  # bdpt_camera_wavefront's SPIR-V), and the BDPT light kernels optimised by spirv-opt (shaderc's
  # SPIRV-Tools 2023.1 skips its passes on modules that declare SPV_EXT_shader_atomic_float_add,
  # so they reach the driver as glslang wrote them: a measurement hack then, built into
  # build.rs since fe42f3d, that hides the extension from spirv-opt -O), against .device/bidir-sf.gz (c2075a7, which behaves like HEAD): two rounds in alternating
  # order, GPU ms and the camera kernel's ms on the Cornell box (bdpt and bdpt:lvc=3, whose
  # four rays fill the arrays), where the light hides and Sponza, beside .device/bidir-ci2.gz (the
  # same with BDPT_WF_SHADOW_RAYS = 2: the default join's two rays only, so fewer registers; its
  # lvc=3 is not the wavefront's and is left out); the images (RMSE 0 on
  # lavapipe); both builds' whole statistics of the camera kernel (Local Memory Size); the
  # Cornell box at 1 s against .device/ref.exr; then pt-nee for the ratio and s51b.
  device_line
  h200_first "$0"
  unpack sf cs ci2
  k='GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9.]+'
  for r in 1 2; do
    order="sf cs ci2"; [ $r = 2 ] && order="ci2 cs sf"
    for n in $order; do
      F=$PWD/.device/bidir-$n
      l3=""; [ $n != ci2 ] && l3="lvc=3: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt:lvc=3 --spp 512 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== r$r $n cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ') $l3"
      echo "== r$r $n hidden: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ') sponza 8: $(timeout -k 5 60 "$F" bench render $SP --integrator bdpt --connection-candidates 8 --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
    done
  done
  for n in sf cs; do
    timeout -k 5 60 .device/bidir-$n render $CB --integrator bdpt --spp 64 --seed 3 -o /tmp/i-$n.exr > /dev/null 2>&1
    timeout -k 5 60 .device/bidir-$n render $CB --integrator bdpt:lvc=3 --spp 64 --seed 3 -o /tmp/j-$n.exr > /dev/null 2>&1
  done
  echo "== images cs/sf: $(.device/bidir-sf diff /tmp/i-cs.exr /tmp/i-sf.exr 2>&1 | grep -E '^RMSE' | tr '\n' ' ') lvc=3: $(.device/bidir-sf diff /tmp/j-cs.exr /tmp/j-sf.exr 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
  for n in sf cs ci2; do
    echo "== $n statistics:"; timeout -k 5 60 .device/bidir-$n info $CB --kernels 2>&1 | grep -E '^(bdpt:lvc=1 / bdpt_(camera|light)_(wavefront|finish)|pt-nee / pt_queue)'
  done
  for n in cs sf; do
    echo "== $n cornell bdpt 1 s: $(at_time .device/bidir-$n 1 $CB --integrator bdpt)"
  done
  echo "== sf cornell pt-nee: $(gpu_ms .device/bidir-sf $CB --integrator pt-nee --spp 1024) 1 s: $(at_time .device/bidir-sf 1 $CB --integrator pt-nee)"
  timeout -k 5 200 bash "$0" s51b
  ;;
s52)
  # Session 52's start, whatever card comes: on an H200 s51q (issue #16's ratio with HEAD's
  # slices, .device/bidir-sf.gz) and #17's Sponza round with sf; then s51b; on another card
  # then sf's pt-nee and s51q's BDPT of sf (241 slices) against nd (213); on every card last
  # the camera kernel's and pt-nee's whole driver statistics.
  device_line
  h200_first "$0"
  timeout -k 5 240 bash "$0" s51b
  case "$g" in
    *H200*) ;;
    *) unpack sf; echo "== sf cornell pt-nee: $(gpu_ms .device/bidir-sf $CB --integrator pt-nee --spp 1024)"; timeout -k 5 90 bash "$0" s51q ;;
  esac
  # The camera kernel's and pt-nee's whole statistics (local memory: the shadow rays' arrays).
  timeout -k 5 60 .device/bidir-sf info $CB --kernels 2>&1 | grep -E '^(bdpt:lvc=1 / bdpt_camera_wavefront|pt-nee / pt_queue)'
  ;;
s51q)
  # Session 51's last seconds of device time: on an H200 issue #16's ratio with 0.4 light paths
  # (.device/bidir-sf.gz, c2075a7: 241 slices; then .device/bidir-nd.gz, 0e1ada9: 213), else the
  # two builds' BDPT against each other.
  device_line
  unpack sf nd
  case "$g" in *H200*) echo "== sf cornell pt-nee: $(gpu_ms .device/bidir-sf $CB --integrator pt-nee --spp 1024)" ;; esac
  for n in sf nd; do
    echo "== $n cornell bdpt: $(gpu_ms .device/bidir-$n $CB --integrator bdpt --spp 1024)"
  done
  for n in sf nd; do
    echo "== $n cornell bdpt 1 s: $(at_time .device/bidir-$n 1 $CB --integrator bdpt)"
  done
  ;;
s51b)
  # Session 51 (prepared; no start ran it): BDPT's wavefront launches reading the hit, the
  # trace words and the contributions at once, and the wavefront path tracer's likewise
  # (.device/bidir-er.gz: a release build with `git apply scripts/device/s51b-early-reads.patch`),
  # and with the connection's candidates asked for early too (.device/bidir-pf.gz: the same with
  # WF_LVC_PREFETCH = true in glsl/common/wf_ray.glsl), against a build of the same commit without
  # the patch (.device/bidir-nd.gz): two rounds in alternating order, GPU ms and the path
  # kernels' lines; pt-nee over the wavefront path tracer (the caustic scene, DamagedHelmet);
  # each build's image against nd's (the patch moves reads, not terms: RMSE 0).
  device_line
  # pf only where it was carried (it stays in /work/device-spare while the carry is full).
  abc="nd er"; [ -f .device/bidir-pf.gz ] && abc="nd er pf"
  unpack $abc
  k='GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9.]+'
  for r in 1 2; do
    order="$abc"; [ $r = 2 ] && order=$(echo $abc | tr ' ' '\n' | tac | tr '\n' ' ')
    for n in $order; do
      F=$PWD/.device/bidir-$n
      echo "== r$r $n cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ') hidden: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
    done
  done
  for r in 1 2; do
    order="nd er"; [ $r = 2 ] && order="er nd"
    for n in $order; do
      F=$PWD/.device/bidir-$n
      echo "== r$r $n pt-nee caustic 1024 spp: $(gpu_ms "$F" $CAU --integrator pt-nee --spp 1024) helmet 256 spp: $(gpu_ms "$F" $HB --integrator pt-nee --spp 256)"
    done
  done
  for n in $abc; do
    timeout -k 5 60 .device/bidir-$n render $CB --integrator bdpt --spp 64 --seed 3 -o /tmp/i-$n.exr > /dev/null 2>&1
  done
  for n in nd er; do
    timeout -k 5 60 .device/bidir-$n render $CAU --integrator pt-nee --spp 64 --seed 3 -o /tmp/c-$n.exr > /dev/null 2>&1
  done
  echo "== caustic pt-nee images er/nd: $(.device/bidir-nd diff /tmp/c-er.exr /tmp/c-nd.exr 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
  echo "== images er/nd: $(.device/bidir-nd diff /tmp/i-er.exr /tmp/i-nd.exr 2>&1 | grep -E '^RMSE' | tr '\n' ' ') pf/nd: $(.device/bidir-nd diff /tmp/i-pf.exr /tmp/i-nd.exr 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
  for n in $abc; do
    echo "== $n registers: $(timeout -k 5 60 .device/bidir-$n info $CB --kernels 2>&1 | grep -E '^(bdpt:lvc=1|pt-nee) ' | grep -oE '/ [a-z_0-9]+|Register Count [0-9]+' | tr '\n' ' ')"
  done
  F=$PWD/.device/bidir-er
  echo "== er cornell bdpt 1 s: $(at_time "$F" 1 $CB --integrator bdpt)"
  # 241 slices by hand (HEAD's default since c2075a7; a build of 0e1ada9 as nd took 213).
  echo "== er cornell bdpt 241 slices 1 s: $(at_time "$F" 1 $CB --integrator bdpt --sample-slices 241) 1024 spp: $(gpu_ms "$F" $CB --integrator bdpt --sample-slices 241 --spp 1024)"
  ;;
s51)
  # Session 51's start, whatever card comes: on an H200 first s50d (issue #16's ratio with the
  # 0.4 default) and #17's Sponza round, then s51b; on another card s51b alone.
  device_line
  case "$g" in *H200*) timeout -k 5 100 bash "$0" s50d; unpack nd; timeout -k 5 70 bash -c "$(declare -f sponza_q5 sponza_rounds); sponza_rounds 1 $PWD/.device/bidir-nd" ;; esac
  timeout -k 5 200 bash "$0" s51b
  ;;
s51a)
  # Session 51: where a BDPT sample's time goes now (0.4 light paths, 8 candidates;
  # .device/bidir-nd.gz): `bench render`'s kernel tables for bdpt and pt-nee on the Cornell box,
  # bdpt at 256 slices (4 whole iterations of 1024 spp), and the driver's kernel statistics.
  device_line
  unpack nd
  F=$PWD/.device/bidir-nd
  for o in "--integrator bdpt" "--integrator pt-nee" "--integrator bdpt --sample-slices 256" "--integrator bdpt --sample-slices 205"; do
    echo "== cornell $o"; timeout -k 5 60 "$F" bench render $CB $o --spp 1024 --warmup 1 --runs 3 2>&1 | tail -n 30
  done
  echo "== hidden bdpt"; timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | tail -n 30
  echo "== pass log: $(BIDIR_PASS_LOG=1 timeout -k 5 60 "$F" render $CB --integrator bdpt --spp 1024 -o /tmp/p.exr 2>&1 | grep -m1 'slices')"
  for sl in "" "--sample-slices 256" "--sample-slices 320"; do
    echo "== cornell bdpt 1920 spp [$sl]: $(gpu_ms "$F" $CB --integrator bdpt $sl --spp 1920)"
  done
  timeout -k 5 120 "$F" info $CB --kernels 2>&1 | head -n 120
  ;;
s50d)
  # Session 50, short of device time: s50c's first round only (the ratio by `bench render`,
  # .device/bidir-bs.gz's 0.5 light paths against .device/bidir-nd.gz's 0.4), then the 1 s
  # counts of the new build.
  device_line
  unpack nd bs
  for c in "bs|" "nd|" "nd|--connection-candidates 4"; do
    IFS='|' read -r n o <<< "$c"
    F=$PWD/.device/bidir-$n
    echo "== $n [$o] cornell pt-nee: $(gpu_ms "$F" $CB --integrator pt-nee --spp 1024) bdpt: $(gpu_ms "$F" $CB --integrator bdpt $o --spp 1024) hidden bdpt: $(gpu_ms "$F" $HID --integrator bdpt $o --spp 1024)"
  done
  F=$PWD/.device/bidir-nd
  for i in pt-nee bdpt; do
    echo "== nd cornell $i 1 s: $(at_time "$F" 1 $CB --integrator $i)"
  done
  ;;
s50c)
  # Session 50: the new default (0.4 light paths per pixel in scenes with only diffuse
  # surfaces, 8 candidates; .device/bidir-nd.gz) against session 49's HEAD (.device/bidir-bs.gz,
  # 0.5), and the new build with 4 candidates, two rounds in alternating order: issue #16's
  # ratio by `bench render` and by the 1 s counts, the Cornell box's RMSE at 1 s (seeds 1, 2),
  # the hidden light's seed pair at 1 s; then the rest of #16's table with the new build, and
  # on an H200 #17's Sponza figures.
  device_line
  unpack nd bs
  confs=("bs|" "nd|" "nd|--connection-candidates 4")
  for r in 1 2; do
    for i in 0 1 2; do
      [ $r = 2 ] && i=$((2 - i))
      IFS='|' read -r n o <<< "${confs[$i]}"
      F=$PWD/.device/bidir-$n
      echo "== r$r $n [$o] cornell pt-nee: $(gpu_ms "$F" $CB --integrator pt-nee --spp 1024) bdpt: $(gpu_ms "$F" $CB --integrator bdpt $o --spp 1024) hidden bdpt: $(gpu_ms "$F" $HID --integrator bdpt $o --spp 1024)"
    done
  done
  for c in "${confs[@]}"; do
    IFS='|' read -r n o <<< "$c"
    F=$PWD/.device/bidir-$n
    for i in pt-nee bdpt; do
      [ $i = pt-nee ] && [ -n "$o" ] && continue
      for sd in 1 2; do
        echo "== $n [$o] cornell $i seed $sd 1 s: $(timeout -k 5 60 "$F" render $CB --integrator $i $o --seed $sd --time 1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
      done
    done
    for sd in 1 2; do
      echo "== $n [$o] hidden bdpt seed $sd: $(timeout -k 5 60 "$F" render $HID --integrator bdpt $o --time 1 --seed $sd -o /tmp/h$sd.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
    done
    echo "== $n [$o] hidden bdpt seeds 1-2: $("$F" diff /tmp/h1.exr /tmp/h2.exr --below 1 2>&1 | grep -E '^(RMSE|relMSE)' | tr '\n' ' ')"
  done
  F=$PWD/.device/bidir-nd
  for i in pt-nee bdpt; do
    echo "== nd cornell $i 0.1 s: $(at_time "$F" 0.1 $CB --integrator $i)"
    echo "== nd caustic $i 1 s: $(REFERENCE=assets/scenes/caustic/reference.exr at_time "$F" 1 $CAU --integrator $i)"
  done
  echo "== nd cornell pt 1024 spp: $(gpu_ms "$F" $CB --integrator pt --spp 1024)"
  echo "== nd cornell bdpt:full 1024 spp: $(gpu_ms "$F" $CB --integrator bdpt:full --spp 1024)"
  case "$g" in *H200*) sponza_rounds 1 "$F" ;; esac
  ;;
s50b)
  # Session 50: what each light-paths / candidates trade costs a BDPT sample on this card
  # (HEAD's build, .device/bidir-bs.gz), `bench render` ms per 1024 spp, two rounds, the
  # Cornell box and the hidden light's box; their variance per sample was measured on lavapipe
  # (64², 2048 spp, 16 slices, three seed pairs), so these times give the equal-time MSE.
  device_line
  unpack bs
  F=$PWD/.device/bidir-bs
  for r in 1 2; do
    echo "== r$r cornell pt-nee: $(gpu_ms "$F" $CB --integrator pt-nee --spp 1024)"
    for cfg in "0.5 8" "0.4 8" "0.5 4" "0.4 4" "0.375 8" "0.375 4"; do
      set -- $cfg
      echo "== r$r lp $1 cand $2 cornell: $(gpu_ms "$F" $CB --integrator bdpt --light-paths $1 --connection-candidates $2 --spp 1024) hidden: $(gpu_ms "$F" $HID --integrator bdpt --light-paths $1 --connection-candidates $2 --spp 1024)"
    done
  done
  ;;
s50a)
  # Prepared in session 49 for the next: first s49d (the caustic scene's bdpt on the H200), then
  # the trade session 49 measured on the H200 in one round (docs/results.md, "Issues #16 and #17
  # on the H200 again"), with more seeds: 4 candidates were level with 8 on the Cornell box at
  # 4 % less time, 0.375 light paths per pixel 6 % better there and 11 % worse where the light
  # hides. HEAD's build (.device/bidir-bs.gz): `bench render` ms, the Cornell box at 1 s (seeds
  # 1, 2, against .device/ref.exr, every pixel and below 1), the hidden light's seed pairs 1-2
  # and 3-4 at 1 s (RMSE between them, every pixel and below 1).
  timeout -k 5 200 bash "$0" s49d
  unpack bs
  F=$PWD/.device/bidir-bs
  for o in "" "--connection-candidates 4" "--light-paths 0.4" "--light-paths 0.4 --connection-candidates 4"; do
    echo "== cornell bdpt [$o]: $(gpu_ms "$F" $CB --integrator bdpt $o --spp 1024)"
    for sd in 1 2; do
      echo "== cornell bdpt [$o] seed $sd 1 s: $(timeout -k 5 60 "$F" render $CB --integrator bdpt $o --seed $sd --time 1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
    done
    for p in "1 2" "3 4"; do
      set -- $p
      for sd in $1 $2; do
        echo "== hidden [$o] seed $sd: $(timeout -k 5 60 "$F" render $HID --integrator bdpt $o --time 1 --seed $sd -o /tmp/h$sd.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
      done
      echo "== hidden [$o] seeds $1-$2: $("$F" diff /tmp/h$1.exr /tmp/h$2.exr --below 1 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
    done
  done
  echo "== cornell pt-nee: $(gpu_ms "$F" $CB --integrator pt-nee --spp 1024)"
  # BDPT's slots on this card in whole iterations (session 49's H200: 205 slices 98.33 ms per
  # 1024 spp, five whole iterations, against 100.5 at the default 241, 4.25 iterations).
  for sl in 160 192 240; do
    echo "== cornell bdpt 1920 spp, $sl slices: $(gpu_ms "$F" $CB --integrator bdpt --sample-slices $sl --spp 1920)"
  done
  ;;
s49d)
  # Session 49: the caustic scene's bdpt took 23,518 spp in 1 s on the H200 with HEAD's build
  # (.device/bidir-bs.gz), where session 43's H200 took 28,638 and session 46's H100 30,811:
  # c1c12e7 (.device/bidir-ls.gz), f7ed307 (bidir-mi.gz) and HEAD's build in turn, `bench
  # render` (256 spp, kernel lines) and 1 s with the passes' log (their slices).
  device_line
  unpack ls mi bs
  for r in 1 2; do
    for n in ls mi bs; do
      F=$PWD/.device/bidir-$n
      echo "== r$r $n caustic bdpt 256: $(timeout -k 5 60 "$F" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms|(bdpt|lvc|trace)_[a-z0-9_]+ +[0-9.]+' | tr '\n' ' ')"
      echo "== r$r $n caustic bdpt 1 s: $(REFERENCE=assets/scenes/caustic/reference.exr at_time "$F" 1 $CAU --integrator bdpt)"
    done
  done
  BIDIR_PASS_LOG=1 timeout -k 5 60 $PWD/.device/bidir-bs render $CAU --integrator bdpt --time 1 -o /tmp/c.exr 2>&1 | head -8
  BIDIR_PASS_LOG=1 timeout -k 5 60 $PWD/.device/bidir-ls render $CAU --integrator bdpt --time 1 -o /tmp/c.exr 2>&1 | head -8
  ;;
s49c)
  # Session 49: the path tracers' megakernels (`--wavefront off`, 2^20 invocations a launch
  # since f7ed307) against their wavefront form where it is the default (glass, glossy and
  # textured scenes; measured when the megakernels took 2^18), HEAD's build (.device/bidir-bs.gz),
  # two rounds.
  device_line
  unpack bs
  F=$PWD/.device/bidir-bs
  for r in 1 2; do
    for sc in "caustic|$CAU|1024" "helmet|$HB|256" "sponza|$SP|64" "rough|$RC|1024"; do
      IFS='|' read -r name args spp <<< "$sc"
      for i in pt-nee pt; do
        for w in on off; do
          echo "== r$r $name $i wavefront $w: $(gpu_ms "$F" $args --integrator $i --wavefront $w --spp $spp)"
        done
      done
    done
  done
  ;;
s49b)
  # Session 49: BDPT's default join in its megakernels (`--wavefront off`) now that megakernel
  # launches take 2^20 invocations (f7ed307; bdpt:full's megakernels gained 21 %), against its
  # wavefront passes (the default since session 27, 164.0 against 175.1 ms then), HEAD's build
  # (.device/bidir-bs.gz); two rounds, then each at 1 s; on an H200 first s45k. Then s49a's
  # sweep.
  device_line
  unpack bs
  F=$PWD/.device/bidir-bs
  case "$g" in *H200*) HB_NAME=bs timeout -k 5 330 bash "$0" s45k ;; esac
  k='GPU [0-9.]+ ms|bdpt_[a-z_]+ +[0-9.]+'
  for r in 1 2; do
    for o in "--wavefront on" "--wavefront off" "--wavefront off --sample-slices 32" "--wavefront off --sample-slices 8"; do
      echo "== r$r cornell bdpt $o: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt $o --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== r$r hidden bdpt $o: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt $o --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  for o in "--wavefront on" "--wavefront off"; do
    echo "== cornell bdpt $o 1 s: $(at_time "$F" 1 $CB --integrator bdpt $o)"
  done
  echo "== cornell pt-nee 1 s: $(at_time "$F" 1 $CB --integrator pt-nee)"
  SKIP45K=1 timeout -k 5 200 bash "$0" s49a
  ;;
s49a)
  # Prepared in session 48 for the next (.device/bidir-bs.gz, a build of edc0213 or later: `bash
  # scripts/device/make-bundle.sh bs` in a new checkout): on an H200 first s45k with it (issue
  # #16's ratio, #17's Sponza round, #16's table); then, on any card, the wavefront path
  # tracer's slots by sample slices (s48b's forced slices gave the caustic scene 18.03 ms at 128
  # slices, 2 M slots, against 18.4 at its default 511, 8 M): pt-nee where it runs wavefronts.
  device_line
  unpack bs
  case "$g" in *H200*) [ -z "${SKIP45K:-}" ] && HB_NAME=bs timeout -k 5 330 bash "$0" s45k ;; esac
  F=$PWD/.device/bidir-bs
  for r in 1 2; do
    for n in 0 64 128 256; do
      o=""; [ "$n" != 0 ] && o="--sample-slices $n"
      echo "== r$r slices $n caustic pt-nee: $(gpu_ms "$F" $CAU --integrator pt-nee $o --spp 1024)"
    done
    for n in 0 14 28; do
      o=""; [ "$n" != 0 ] && o="--sample-slices $n"
      echo "== r$r slices $n helmet pt-nee: $(gpu_ms "$F" $HB --integrator pt-nee $o --spp 1008)"
    done
    for n in 0 9 18; do
      o=""; [ "$n" != 0 ] && o="--sample-slices $n"
      echo "== r$r slices $n sponza pt-nee: $(gpu_ms "$F" $SP --integrator pt-nee $o --spp 72)"
    done
  done
  ;;
s48d)
  # Session 48: BDPT's wavefront passes aiming at 16 M slots (bdpt_wavefront::TARGET_SLOTS; the
  # Cornell box then takes 241 slices, the memory budget's cap) as built from the working tree
  # (.device/bidir-bs.gz) against 8 M (.device/bidir-mi.gz, f7ed307), two rounds in alternating
  # order, then equal time; on an H200 first s45k with the new build.
  device_line
  unpack mi bs
  case "$g" in *H200*) HB_NAME=bs timeout -k 5 150 bash "$0" s45k ;; esac
  for order in "mi bs" "bs mi"; do
    for n in $order; do
      F=$PWD/.device/bidir-$n
      echo "== $n cornell bdpt: $(gpu_ms "$F" $CB --integrator bdpt --spp 1024)"
      echo "== $n hidden bdpt: $(gpu_ms "$F" $HID --integrator bdpt --spp 1024)"
      echo "== $n helmet bdpt: $(gpu_ms "$F" $HB --integrator bdpt --spp 256)"
      echo "== $n cornell pt-nee: $(gpu_ms "$F" $CB --integrator pt-nee --spp 1024)"
    done
  done
  for n in mi bs; do
    F=$PWD/.device/bidir-$n
    for i in bdpt pt-nee; do echo "== $n cornell $i 1 s: $(at_time "$F" 1 $CB --integrator $i)"; done
  done
  ;;
s48c)
  # Session 48: megakernel launches of 2^20 invocations (render::TARGET_INVOCATIONS, and up to
  # 256 slices for small images) as built from this commit's working tree (.device/bidir-mi.gz)
  # against 2^18 (.device/bidir-ls.gz, c1c12e7), each at its defaults, two rounds in alternating
  # order; then equal time. On an H200 first issue #16's ratio, #17's Sponza round and #16's
  # table with the new build (s45k).
  device_line
  unpack ls mi
  case "$g" in *H200*) HB_NAME=mi timeout -k 5 330 bash "$0" s45k ;; esac
  for order in "ls mi" "mi ls"; do
    for n in $order; do
      F=$PWD/.device/bidir-$n
      echo "== $n cornell pt-nee: $(gpu_ms "$F" $CB --integrator pt-nee --spp 1024)"
      echo "== $n cornell pt: $(gpu_ms "$F" $CB --integrator pt --spp 1024)"
      echo "== $n cornell bdpt: $(gpu_ms "$F" $CB --integrator bdpt --spp 1024)"
      echo "== $n cornell bdpt:full: $(gpu_ms "$F" $CB --integrator bdpt:full --spp 256)"
      echo "== $n cornell vcm: $(gpu_ms "$F" $CB --integrator vcm --spp 256)"
      echo "== $n hidden pt-nee: $(gpu_ms "$F" $HID --integrator pt-nee --spp 1024)"
      echo "== $n caustic pt-nee: $(gpu_ms "$F" $CAU --integrator pt-nee --spp 1024)"
      echo "== $n caustic64 pt-nee: $(gpu_ms "$F" $CAU64 --integrator pt-nee --spp 1024)"
      echo "== $n sponza-geometry pt-nee: $(gpu_ms "$F" $SP --integrator pt-nee --spp 64)"
    done
  done
  for n in ls mi; do
    F=$PWD/.device/bidir-$n
    for t in 0.1 1; do
      echo "== $n cornell pt-nee $t s: $(at_time "$F" $t $CB --integrator pt-nee)"
    done
    echo "== $n cornell bdpt:full 1 s: $(at_time "$F" 1 $CB --integrator bdpt:full)"
    echo "== $n caustic pt-nee 1 s: $(REFERENCE=assets/scenes/caustic/reference.exr at_time "$F" 1 $CAU --integrator pt-nee)"
  done
  # BDPT's wavefront passes past their 128 slices on the box (s48a: fewer were slower).
  for n in 128 192 240; do
    echo "== mi slices $n cornell bdpt: $(gpu_ms "$PWD/.device/bidir-mi" $CB --integrator bdpt --sample-slices $n --spp 1920)"
    echo "== mi slices $n hidden bdpt: $(gpu_ms "$PWD/.device/bidir-mi" $HID --integrator bdpt --sample-slices $n --spp 1920)"
  done
  ;;
s48b)
  # Session 48: s48a found the megakernel pt-nee on the Cornell box faster with more sample
  # slices than its default 4 (2^18 invocations a pass, `render::TARGET_INVOCATIONS`, set in
  # session 1): 46.90 ms per 1024 spp at 16 against 53.1 at 4. The megakernels' slices swept
  # (GPU ms; two rounds where marked), then equal time at the best against the default. On an
  # H200 first s46f, as s48a.
  device_line
  case "$g" in *H200*) HB_NAME=ls timeout -k 5 330 bash "$0" s45k ;; esac
  unpack ls
  F=$PWD/.device/bidir-ls
  for r in 1 2; do
    for n in 4 8 12 16 24 32; do
      echo "== r$r slices $n cornell pt-nee: $(gpu_ms "$F" $CB --integrator pt-nee --sample-slices $n --spp 1024)"
    done
    for n in 16 32 64 128; do
      echo "== r$r slices $n caustic pt-nee: $(gpu_ms "$F" $CAU --integrator pt-nee --sample-slices $n --spp 1024)"
    done
  done
  for n in 4 16 32; do
    echo "== slices $n cornell pt: $(gpu_ms "$F" $CB --integrator pt --sample-slices $n --spp 1024)"
    echo "== slices $n hidden pt-nee: $(gpu_ms "$F" $HID --integrator pt-nee --sample-slices $n --spp 1024)"
    echo "== slices $n cornell bdpt:full: $(gpu_ms "$F" $CB --integrator bdpt:full --sample-slices $n --spp 256)"
    echo "== slices $n cornell vcm: $(gpu_ms "$F" $CB --integrator vcm --sample-slices $n --spp 256)"
  done
  for qs in 64/16 96/24 128/32 192/48; do
    echo "== slices 16 queue $qs cornell pt-nee: $(gpu_ms "$F" $CB --integrator pt-nee --sample-slices 16 --shadow-queue $qs --spp 1024)"
  done
  for n in 2 4 8; do
    echo "== slices $n sponza-geometry pt-nee: $(gpu_ms "$F" $SP --integrator pt-nee --sample-slices $n --spp 64)"
  done
  for n in 4 16; do
    for t in 0.1 1; do
      echo "== slices $n cornell pt-nee $t s: $(at_time "$F" $t $CB --integrator pt-nee --sample-slices $n)"
    done
  done
  echo "== default cornell pt-nee 0.1 s: $(at_time "$F" 0.1 $CB --integrator pt-nee)"
  ;;
s48a)
  # Session 48: on an H200 first s46f (issue #16's ratio, #17's Sponza round and #16's table
  # with .device/bidir-ls.gz, c1c12e7's code = HEAD's kernels); then, on any card, BDPT's and
  # pt-nee's cost by sample slices (slots = pixels x slices; the default aims at 8 M, chosen in
  # session 22 when a slot's state was twice today's): fewer slices bring the light vertex store
  # (the Cornell box's: 33.6 M slots at its 128 slices), the listing and the film's slices
  # nearer the L2's 50 MB, at more launches of fewer paths.
  device_line
  case "$g" in *H200*) HB_NAME=ls timeout -k 5 330 bash "$0" s45k ;; esac
  unpack ls
  F=$PWD/.device/bidir-ls
  k='GPU [0-9.]+ ms|bdpt_[a-z_]+ +[0-9.]+|lvc_compact +[0-9.]+|trace_[a-z0-9_]+ +[0-9.]+'
  for r in 1 2; do
    for n in 128 64 32 16 8; do
      echo "== slices $n cornell bdpt: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --sample-slices $n --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== slices $n hidden bdpt: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --sample-slices $n --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  for n in 128 64 32 16; do
    echo "== slices $n cornell pt-nee: $(timeout -k 5 60 "$F" bench render $CB --integrator pt-nee --sample-slices $n --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  done
  for n in 57 32 16; do
    echo "== slices $n helmet bdpt: $(timeout -k 5 60 "$F" bench render $HB --integrator bdpt --sample-slices $n --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  done
  for n in 24 16 8; do
    echo "== slices $n sponza bdpt: $(timeout -k 5 60 "$F" bench render $SP --integrator bdpt --sample-slices $n --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  done
  for n in 128 32 16; do
    echo "== slices $n cornell bdpt 1 s: $(at_time "$F" 1 $CB --integrator bdpt --sample-slices $n)"
  done
  ;;
s46b)
  # Prepared in session 45, not run: where the wavefront camera kernel's time goes now, by a
  # measurement build (scripts/device/s46b-exp-camera.patch on e7624e5, .device/bidir-xc.gz:
  # BIDIR_EXP_CAMERA bit 0 leaves out the camera step's light sample, bit 1 its connections;
  # the images change), beside one candidate per connection (an option). Kernel tables' camera
  # and trace ms, two rounds.
  unpack xc
  F=$PWD/.device/bidir-xc
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  k='GPU [0-9.]+ ms|bdpt_camera_wavefront +[0-9.]+|trace_[a-z0-9]+ +[0-9.]+'
  for r in 1 2; do
    for e in 0 1 2 3 c1; do
      if [ "$e" = c1 ]; then x=0; o="--connection-candidates 1"; else x=$e; o=""; fi
      echo "== exp $e cornell: $(BIDIR_EXP_CAMERA=$x timeout -k 5 60 "$F" bench render $CB --integrator bdpt $o --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== exp $e helmet: $(BIDIR_EXP_CAMERA=$x timeout -k 5 60 "$F" bench render $HB --integrator bdpt $o --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
    done
  done
  ;;
s46c)
  # Session 46's first call: on an H200, s45k with a build of 76b4312 (.device/bidir-hh.gz,
  # HEAD then), then s46a; on any other card s46b and s46a.
  device_line
  case "$g" in
    *H200*) HB_NAME=hh timeout -k 5 300 bash "$0" s45k; bash "$0" s46a ;;
    *) bash "$0" s46b; bash "$0" s46a ;;
  esac
  ;;
s47b)
  # Session 47's first call: on an H200 first s46f (issue #16's ratio, #17's Sponza round and
  # #16's table with 6422f5a's code, .device/bidir-ls.gz), then s47a on any card. The bundle:
  # `bash scripts/device/make-bundle.sh ls fe=s47a-full-entries.patch`.
  device_line
  case "$g" in *H200*) HB_NAME=ls timeout -k 5 330 bash "$0" s45k ;; esac
  bash "$0" s47a
  ;;
s47a)
  # Prepared in session 46, not run: resampled cache entries that carry the whole compact vertex
  # (scripts/device/s47a-full-entries.patch on 7a3b284, .device/bidir-fe.gz), so that the kept
  # candidate's exact estimate reads its entry from L1 instead of its vertex from memory, against
  # 6422f5a (.device/bidir-ls.gz; the code of 7a3b284). Two rounds, the builds' order alternating
  # (session 46's s46e always ran its base first); the camera kernel's and the listing's ms.
  # lavapipe: the reference tests pass, a build that halved the entry's pick fails four of them.
  unpack ls fe
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  k='GPU [0-9.]+ ms|bdpt_camera_wavefront +[0-9.]+|lvc_compact +[0-9.]+'
  echo "== fe cornell wavefront vs megakernel: $(wf_vs_mega "$PWD/.device/bidir-fe" --width 64 --height 64 --integrator bdpt --sample-slices 16)"
  for order in "ls fe" "fe ls"; do
    for n in $order; do
      F=$PWD/.device/bidir-$n
      echo "== $n cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n hidden: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n helmet 8: $(timeout -k 5 60 "$F" bench render $HB --integrator bdpt --connection-candidates 8 --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n cornell 1 s: $(at_time "$F" 1 $CB --integrator bdpt)"
    done
  done
  ;;
s46f)
  # Session 46's last device time (about 260 s): only on an H200, issue #16's ratio with
  # 6422f5a (.device/bidir-ls.gz), then #17's Sponza round; on any other card nothing.
  device_line
  case "$g" in *H200*) HB_NAME=ls bash "$0" s45k ;; esac
  ;;
s46e)
  # Session 46's last call: the light vertex cache's listing per slot on GPUs with resampled
  # entries as committed (.device/bidir-ls.gz) against 76b4312 (.device/bidir-hh.gz). On an
  # H200 first s45k with it (issue #16's ratio, #17's Sponza round; as far as 140 s take it),
  # then one round of the comparison; on any other card the round and the Cornell box at 1 s.
  device_line
  unpack hh ls
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  k='GPU [0-9.]+ ms|lvc_compact +[0-9.]+'
  rounds=1
  case "$g" in *H200*) HB_NAME=ls timeout -k 5 140 bash "$0" s45k ;; esac
  echo "== ls cornell wavefront vs megakernel: $(wf_vs_mega "$PWD/.device/bidir-ls" --width 64 --height 64 --integrator bdpt --sample-slices 16)"
  for r in $(seq $rounds); do
    for n in hh ls; do
      F=$PWD/.device/bidir-$n
      bdpt_scene_benches "$F" "$n" "$k"
    done
  done
  case "$g" in *H200*) ;; *)
    F=$PWD/.device/bidir-ls
    echo "== ls cornell pt-nee: $(timeout -k 5 60 "$F" bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    for i in pt-nee bdpt; do echo "== ls cornell $i 1 s: $(at_time "$F" 1 $CB --integrator $i)"; done ;;
  esac
  ;;
s46a)
  # Prepared in session 45, not run: the light vertex cache's listing with an invocation per
  # slot of the store (scripts/device/s46a-lvc-compact.patch on e7624e5, .device/bidir-lc.gz),
  # against e7624e5 (.device/bidir-hd.gz). On lavapipe it lists the same entries (the images
  # are bit-equal) but is slower (128², 64 spp: lvc_compact 50-52 ms against 31), so a GPU win
  # would be kept for GPUs only. Two rounds; lvc_compact's ms in each line.
  unpack hd lc
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  echo "== lc cornell bdpt wavefront vs megakernel: $(wf_vs_mega "$PWD/.device/bidir-lc" --width 64 --height 64 --integrator bdpt --sample-slices 16)"
  k='GPU [0-9.]+ ms|lvc_compact +[0-9.]+'
  for r in 1 2; do
    for n in hd lc; do
      F=$PWD/.device/bidir-$n
      bdpt_scene_benches "$F" "$n" "$k"
    done
  done
  ;;
s45k)
  # Session 45's last device time (run on an H100 with b616e89; .device/bidir-hd.gz is now a
  # build of e7624e5, the keep decisions' seed off the sampler's chain), the most wanted first: the
  # Cornell box's pt-nee and bdpt (issue #16's ratio), #17's Sponza figures (one round), then
  # the rest of #16's table, then s45j's sampler comparison.
  unpack ${HB_NAME:-hd}
  F=$PWD/.device/bidir-${HB_NAME:-hd}
  for i in pt-nee bdpt; do
    echo "== cornell $i 1024 spp: $(timeout -k 5 60 "$F" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    echo "== cornell $i 1 s: $(at_time "$F" 1 $CB --integrator $i)"
  done
  sponza_rounds 1 "$F"
  for i in pt-nee bdpt; do
    echo "== cornell $i 0.1 s: $(at_time "$F" 0.1 $CB --integrator $i)"
    echo "== caustic $i 1 s: $(REFERENCE=assets/scenes/caustic/reference.exr at_time "$F" 1 $CAU --integrator $i)"
  done
  echo "== cornell pt 1024 spp: $(timeout -k 5 60 "$F" bench render $CB --integrator pt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  echo "== cornell bdpt:full 1024 spp: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt:full --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  echo "== hidden bdpt: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  for smp in sobol independent; do
    echo "== $smp cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --sampler $smp --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    echo "== $smp cornell bdpt 1 s: $(at_time "$F" 1 $CB --integrator bdpt --sampler $smp)"
  done
  ;;
s45j)
  # Session 45: what the sampler's Sobol' numbers cost BDPT on the Cornell box and what they
  # buy at equal time (b616e89's build, .device/bidir-rv.gz's code with the review's shared
  # helpers: .device/bidir-hd.gz): `--sampler independent` against the default.
  unpack hd
  F=$PWD/.device/bidir-hd
  for r in 1 2; do
    for smp in sobol independent; do
      echo "== $smp cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --sampler $smp --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms|bdpt_camera_wavefront +[0-9.]+' | tr '\n' ' ')"
      echo "== $smp cornell bdpt 1 s: $(at_time "$F" 1 $CB --integrator bdpt --sampler $smp)"
    done
  done
  echo "== pt-nee cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then
    SPONZA=1 B=$F bash "$0" s44d
  fi
  ;;
s45i)
  # Session 45's review (.device/bidir-rv.gz: one start helper per pass for both of its first
  # launches, the path tracer's contributions no longer cleared each pass) against 11be3fd
  # (.device/bidir-fk.gz): wavefront images against megakernels (also at 100 x 77, no multiple
  # of the tiles), one round of timings; on an H200 then issue #16's table and #17's figures.
  unpack fk rv
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for sc in "cornell|--width 64 --height 64" "odd|--width 100 --height 77" "helmet|$HB" "caustic|$CAU"; do
    for i in bdpt pt-nee; do
      echo "== rv ${sc%%|*} $i wavefront vs megakernel: $(wf_vs_mega "$PWD/.device/bidir-rv" ${sc#*|} --integrator $i --sample-slices 16)"
    done
  done
  for n in fk rv; do
    F=$PWD/.device/bidir-$n
    echo "== $n cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    echo "== $n hidden: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    echo "== $n helmet: $(timeout -k 5 60 "$F" bench render $HB --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    echo "== $n helmet pt-nee: $(timeout -k 5 60 "$F" bench render $HB --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    echo "== $n caustic pt-nee: $(timeout -k 5 60 "$F" bench render $CAU --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  done
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then
    SPONZA=1 B=$PWD/.device/bidir-rv bash "$0" s44d
  fi
  ;;
s45h)
  # Session 45, a measurement build (.device/bidir-st.gz: the queues' any-hit and closest-hit
  # traces configurable, BIDIR_EXP_SHADOW_TRACE / BIDIR_EXP_EXT_TRACE = lockstep | plain |
  # refillN): the wavefront integrators with the shadow rays' trace kernel run otherwise.
  unpack st
  F=$PWD/.device/bidir-st
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for sc in "cornell|--width 64 --height 64" "helmet|$HB"; do
    echo "== st lockstep ${sc%%|*} bdpt wavefront vs megakernel: $(BIDIR_EXP_SHADOW_TRACE=lockstep wf_vs_mega "$F" ${sc#*|} --integrator bdpt --sample-slices 16)"
  done
  k='GPU [0-9.]+ ms|trace_[a-z0-9_]+ +[0-9.]+'
  for r in 1 2; do
    for v in default lockstep plain refill8 refill24 ext-lockstep; do
      case $v in
        default) e="" ;;
        ext-lockstep) e="BIDIR_EXP_EXT_TRACE=lockstep" ;;
        *) e="BIDIR_EXP_SHADOW_TRACE=$v" ;;
      esac
      echo "== $v cornell: $(env $e timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      if [ "$v" = default ] || [ "$v" = lockstep ] || [ "$v" = plain ]; then
        echo "== $v hidden: $(env $e timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
        echo "== $v helmet: $(env $e timeout -k 5 60 "$F" bench render $HB --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
        echo "== $v sponza 8: $(env $e timeout -k 5 60 "$F" bench render $SP --integrator bdpt --connection-candidates 8 --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
        echo "== $v caustic: $(env $e timeout -k 5 60 "$F" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
        echo "== $v helmet pt-nee: $(env $e timeout -k 5 60 "$F" bench render $HB --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
      fi
    done
  done
  ;;
s45g)
  # Session 45: issue #16's table with 11be3fd (.device/bidir-fk.gz, the same binary) on
  # whatever card this is; #17's figures too on an H200.
  unpack fk
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then s=1; else s=0; fi
  SPONZA=$s B=$PWD/.device/bidir-fk bash "$0" s44d
  ;;
s45f)
  # Session 45: the lists of live slots carry each slot's segment place, so a launch reads its
  # hit beside its state (.device/bidir-ls.gz, on fk) against fk (.device/bidir-fk.gz):
  # wavefront images against megakernels, two rounds interleaved; the trace kernels alone on
  # the Cornell box at 2048 x 2048 (bench traversal), beside what they do inside BDPT.
  unpack fk ls
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for sc in "cornell|--width 64 --height 64" "helmet|$HB" "caustic|$CAU"; do
    echo "== ls ${sc%%|*} bdpt wavefront vs megakernel: $(wf_vs_mega "$PWD/.device/bidir-ls" ${sc#*|} --integrator bdpt --sample-slices 16)"
  done
  k='GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9.]+'
  for r in 1 2; do
    for n in fk ls; do
      F=$PWD/.device/bidir-$n
      bdpt_scene_benches "$F" "$n" "$k"
      echo "== $n caustic: $(timeout -k 5 60 "$F" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  echo "== ls cornell bdpt 1 s: $(at_time "$PWD/.device/bidir-ls" 1 $CB --integrator bdpt)"
  for o in "" "--refill 24"; do
    echo "== cornell traversal 2048x2048 bvh4 $o"; timeout -k 5 60 "$PWD/.device/bidir-fk" bench traversal --width 2048 --height 2048 --bvh bvh4 --leaf-size 3 --quality 4 --reps 5 $o 2>&1 | grep -E "^(primary|shadow|diffuse) "
  done
  ;;
s45e)
  # Session 45: BDPT's passes start their paths again in the launch after the first instead of
  # storing and reading their states (.device/bidir-fh.gz), and with it the connection's keep
  # decisions drawn from a hash chain of one number (.device/bidir-fk.gz), against b67eec1
  # (.device/bidir-head45.gz): wavefront images against megakernels, two rounds interleaved,
  # then the Cornell box at 1 s.
  unpack head45 fh fk
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for n in fh fk; do
    for sc in "cornell|--width 64 --height 64" "helmet|$HB" "caustic|$CAU"; do
      echo "== $n ${sc%%|*} bdpt wavefront vs megakernel: $(wf_vs_mega "$PWD/.device/bidir-$n" ${sc#*|} --integrator bdpt --sample-slices 16)"
    done
  done
  k='GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9.]+'
  for r in 1 2; do
    for n in head45 fh fk; do
      F=$PWD/.device/bidir-$n
      bdpt_scene_benches "$F" "$n" "$k"
      echo "== $n caustic: $(timeout -k 5 60 "$F" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  for n in head45 fh fk; do
    echo "== $n cornell bdpt 1 s: $(at_time "$PWD/.device/bidir-$n" 1 $CB --integrator bdpt)"
  done
  echo "== pt-nee cornell 1 s: $(at_time "$PWD/.device/bidir-head45" 1 $CB --integrator pt-nee)"
  echo "== pt-nee cornell: $(timeout -k 5 60 "$PWD/.device/bidir-head45" bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  ;;
s45d)
  # Session 45: the Cornell box's BDPT over each BVH layout and leaf size (existing options,
  # b67eec1), and the trace kernels alone on the box (bench traversal), to see whether its
  # traces (27 % of a BDPT sample there) have an easier form for a scene of 36 triangles.
  unpack head45
  F=$PWD/.device/bidir-head45
  k='GPU [0-9.]+ ms|trace_[a-z0-9]+ +[0-9.]+'
  for r in 1 2; do
    for o in "--bvh bvh4" "--bvh cwbvh" "--bvh bvh2" "--bvh bvh4 --bvh-leaf-size 1" "--bvh bvh4 --bvh-leaf-size 2" "--bvh bvh4 --bvh-leaf-size 6" "--bvh bvh4 --bvh-no-occlusion-copy" "--bvh bvh2 --bvh-leaf-size 8" "--bvh cwbvh --bvh-leaf-size 2"; do
      echo "== $o: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt $o --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
    done
  done
  for o in "--bvh bvh4 --leaf-size 3" "--bvh cwbvh" "--bvh bvh2" "--bvh bvh4 --leaf-size 1"; do
    echo "== traversal $o"; timeout -k 5 60 "$F" bench traversal $o --quality 4 --reps 5 2>&1 | grep -E "^(primary|shadow|diffuse) "
  done
  ;;
s45c)
  # Session 45: where a BDPT sample's time goes at b67eec1 (.device/bidir-head45.gz), kernel
  # by kernel, beside pt-nee's, on the Cornell box; the kernels' registers; BDPT's megakernels
  # on the box; one iteration's launches (BIDIR_WF_LOG).
  unpack head45
  F=$PWD/.device/bidir-head45
  timeout -k 5 120 "$F" info --kernels 2>&1 | grep -E "bdpt|pt_|trace|lvc|Registers|registers" | head -60
  for i in bdpt pt-nee; do
    echo "== cornell $i"; timeout -k 5 60 "$F" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 2>&1 | tail -25
  done
  echo "== cornell bdpt megakernels"; timeout -k 5 60 "$F" bench render $CB --integrator bdpt --wavefront off --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms'
  echo "== hidden bdpt"; timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | tail -25
  echo "== one iteration"; BIDIR_WF_LOG=1 BIDIR_PASS_LOG=1 timeout -k 5 60 "$F" render $CB --integrator bdpt --spp 256 -o /tmp/it.exr 2>&1 | tail -40
  ;;
s45a)
  # Prepared in session 44, not run: the wavefront path tracer's film sums carried in the path
  # (scripts/device/s45a-pt-film.patch on 1dc2453: the last launch's clear light sample added
  # to the path's radiance where a path goes on, so the film is read and written once a sample,
  # not each launch; .device/bidir-ptf.gz), and with it its path state in 64 bytes
  # (scripts/device/s45b-pt-state.patch on 4a8dfff, which includes s45a's change: no origin, the
  # queue places and status beside the random numbers, no index buffer, the contribution at the
  # shadow ray's place in halves of alternate parity; .device/bidir-pts.gz) against 1dc2453
  # (.device/bidir-head44.gz): wavefront
  # images against megakernels, two rounds interleaved of pt-nee and pt on DamagedHelmet and the
  # caustic scene and pt-nee on the Cornell box in its wavefront form; then issue #16's table
  # with 1dc2453 (s44d; #17's figures too on an H200).
  unpack head44 ptf pts
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for n in ptf pts; do
    F=$PWD/.device/bidir-$n
    for sc in "cornell|--width 64 --height 64" "helmet|$HB" "caustic|$CAU"; do
      for i in pt-nee pt; do
        echo "== $n ${sc%%|*} $i wavefront vs megakernel: $(wf_vs_mega "$F" ${sc#*|} --integrator $i)"
      done
    done
  done
  for r in 1 2; do
    for n in head44 ptf pts; do
      F=$PWD/.device/bidir-$n
      for i in pt-nee pt; do
        echo "== $n helmet $i: $(timeout -k 5 60 "$F" bench render $HB --integrator $i --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms|pt_wavefront +[0-9.]+' | tr '\n' ' ')"
        echo "== $n caustic $i: $(timeout -k 5 60 "$F" bench render $CAU --integrator $i --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms' | tr '\n' ' ')"
      done
      echo "== $n cornell pt-nee wavefront: $(timeout -k 5 60 "$F" bench render $CB --integrator pt-nee --wavefront on --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms' | tr '\n' ' ')"
    done
  done
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then s=1; else s=0; fi
  SPONZA=$s B=$PWD/.device/bidir-head44 bash "$0" s44d
  ;;
s44k)
  # Session 44: the light state without the origin, 64 bytes without medium and alpha
  # (.device/bidir-l64.gz) against 77a31a5 (bidir-carry.gz): wavefront images against
  # megakernels, two rounds interleaved, bdpt at 1 s; on an H200 then issue #16's table with
  # bidir-l64 (no #17 figures: too little device time).
  unpack carry l64
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  F=$PWD/.device/bidir-l64
  for sc in "cornell|--width 64 --height 64" "helmet|$HB" "caustic|$CAU"; do
    timeout -k 5 60 "$F" render ${sc#*|} --integrator bdpt --wavefront off --spp 16 --seed 3 --sample-slices 16 -o /tmp/m.exr > /dev/null 2>&1
    timeout -k 5 60 "$F" render ${sc#*|} --integrator bdpt --wavefront on --spp 16 --seed 3 --sample-slices 16 -o /tmp/w.exr > /dev/null 2>&1
    echo "== l64 ${sc%%|*} bdpt wavefront vs megakernel: $("$F" diff /tmp/w.exr /tmp/m.exr 2>&1 | grep -E '^RMSE')"
  done
  k='GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9.]+'
  for r in 1 2; do
    for n in carry l64; do
      F=$PWD/.device/bidir-$n
      bdpt_scene_benches "$F" "$n" "$k"
      echo "== $n caustic: $(timeout -k 5 60 "$F" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  echo "== l64 cornell bdpt 1 s: $(at_time "$PWD/.device/bidir-l64" 1 $CB --integrator bdpt)"
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then
    SPONZA=0 B=$PWD/.device/bidir-l64 bash "$0" s44d
  fi
  ;;
s44i)
  # Session 44: the camera state carries the sample's sum and goes to the film once (no origin
  # kept; .device/bidir-carry.gz) against 8f63d90 (bidir-s44l.gz) and s44g's build without film
  # sums (bidir-xfilm.gz): wavefront images against megakernels, three rounds interleaved, then
  # issue #16's Cornell figures for both; on an H200 then s44d with bidir-carry.
  unpack s44l carry xfilm
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  F=$PWD/.device/bidir-carry
  for sc in "cornell|--width 64 --height 64" "cornell256|$CB" "helmet|$HB" "caustic|$CAU"; do
    timeout -k 5 60 "$F" render ${sc#*|} --integrator bdpt --wavefront off --spp 16 --seed 3 --sample-slices 16 -o /tmp/m.exr > /dev/null 2>&1
    timeout -k 5 60 "$F" render ${sc#*|} --integrator bdpt --wavefront on --spp 16 --seed 3 --sample-slices 16 -o /tmp/w.exr > /dev/null 2>&1
    echo "== carry ${sc%%|*} bdpt wavefront vs megakernel: $("$F" diff /tmp/w.exr /tmp/m.exr 2>&1 | grep -E '^RMSE')"
  done
  k='GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9.]+'
  for r in 1 2 3; do
    for n in s44l carry xfilm; do
      F=$PWD/.device/bidir-$n
      echo "== $n cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n hidden: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      [ $r = 3 ] && continue
      [ $n = xfilm ] && continue
      echo "== $n helmet: $(timeout -k 5 60 "$F" bench render $HB --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n sponza 8: $(timeout -k 5 60 "$F" bench render $SP --integrator bdpt --connection-candidates 8 --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n caustic: $(timeout -k 5 60 "$F" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  for n in s44l carry; do
    for t in 0.1 1; do
      echo "== $n cornell bdpt $t s: $(at_time "$PWD/.device/bidir-$n" $t $CB --integrator bdpt)"
    done
  done
  echo "== cornell pt-nee 1024 spp: $(timeout -k 5 60 .device/bidir-carry bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  echo "== cornell pt-nee 1 s: $(at_time "$PWD/.device/bidir-carry" 1 $CB --integrator pt-nee)"
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then
    B=$PWD/.device/bidir-carry bash "$0" s44d
  fi
  ;;
s44h)
  # Session 44: the camera kernel's film sums added in place (atomicAdd: RED, no read back;
  # .device/bidir-red.gz) against 8f63d90 (bidir-s44l.gz) and s44g's build without film sums
  # (bidir-xfilm.gz), three rounds interleaved (the Cornell box, the hidden light, DamagedHelmet,
  # Sponza); each build's wavefront images against its megakernels; then on an H200 s44d with
  # bidir-red.
  unpack s44l red xfilm
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  F=$PWD/.device/bidir-red
  for sc in "cornell|--width 64 --height 64" "cornell256|$CB" "helmet|$HB" "caustic|$CAU"; do
    timeout -k 5 60 "$F" render ${sc#*|} --integrator bdpt --wavefront off --spp 16 --seed 3 --sample-slices 16 -o /tmp/m.exr > /dev/null 2>&1
    timeout -k 5 60 "$F" render ${sc#*|} --integrator bdpt --wavefront on --spp 16 --seed 3 --sample-slices 16 -o /tmp/w.exr > /dev/null 2>&1
    echo "== red ${sc%%|*} bdpt wavefront vs megakernel: $("$F" diff /tmp/w.exr /tmp/m.exr 2>&1 | grep -E '^RMSE')"
  done
  k='GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9.]+'
  for r in 1 2 3; do
    for n in s44l red xfilm; do
      F=$PWD/.device/bidir-$n
      echo "== $n cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n hidden: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      [ $r = 3 ] && continue
      echo "== $n helmet: $(timeout -k 5 60 "$F" bench render $HB --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n sponza 8: $(timeout -k 5 60 "$F" bench render $SP --integrator bdpt --connection-candidates 8 --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
    done
  done
  for n in s44l red; do
    for t in 0.1 1; do
      echo "== $n cornell bdpt $t s: $(at_time "$PWD/.device/bidir-$n" $t $CB --integrator bdpt)"
    done
  done
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then
    B=$PWD/.device/bidir-red bash "$0" s44d
  fi
  ;;
s44g)
  # Session 44: what each memory stream of BDPT's wavefront passes costs, left out by a
  # measurement build (scripts/device/s44g-exp.patch on 8f63d90; each stream skipped behind a
  # condition on the seed that never holds, so that the arithmetic it feeds stays): the camera
  # kernel's film sums (.device/bidir-xfilm.gz), its shadow rays' contributions written and read
  # back (bidir-xcontrib.gz), the light kernel's splats (bidir-xsplat.gz), against 8f63d90
  # (bidir-s44l.gz); two rounds interleaved, GPU ms and the camera and light kernels' ms. Then,
  # on an H200, s44d with 8f63d90.
  unpack s44l xfilm xcontrib xsplat
  k='GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9.]+'
  for r in 1 2; do
    for n in s44l xfilm xcontrib xsplat; do
      F=$PWD/.device/bidir-$n
      echo "== $n cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n hidden: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
    done
  done
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then
    B=$PWD/.device/bidir-s44l bash "$0" s44d
  fi
  ;;
s44f)
  # Session 44: s44c's question with more processes: 8f63d90 (.device/bidir-s44l.gz, warm-up runs
  # of at least 1 s) in twelve fresh processes without the shader cache, e6697aa
  # (.device/bidir-head43.gz, one warm-up run) in six, interleaved; GPU and wall ms.
  unpack head43 s44l
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2 3 4 5 6; do
    for n in s44l head43 s44l; do
      echo "== $n helmet pt-nee, a fresh process, no shader cache: $(__GL_SHADER_DISK_CACHE=0 timeout -k 5 60 .device/bidir-$n bench render $HB --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    done
  done
  ;;
s44e)
  # Session 44: s44c again with e6697aa alone, six fresh processes without the shader cache,
  # each with its passes (BIDIR_WF_LOG) and the SM clock sampled every 20 ms while it runs (CLK:
  # other nvidia-smi fields, e.g. CLK=clocks.mem,pstate).
  unpack head43
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2 3 4 5 6; do
    nvidia-smi --query-gpu=${CLK:-clocks.sm} --format=csv,noheader,nounits -lms 20 > /tmp/clk.txt 2>&1 &
    p=$!
    __GL_SHADER_DISK_CACHE=0 BIDIR_WF_LOG=1 timeout -k 5 60 .device/bidir-head43 bench render $HB --integrator pt-nee --spp 256 --warmup 1 --runs 3 > /tmp/run.txt 2>&1
    kill $p; wait $p 2>/dev/null
    echo "== head43 run $r: $(grep -oE 'GPU [0-9.]+ ms' /tmp/run.txt); ${CLK:-clocks.sm} samples: $(uniq -c < /tmp/clk.txt | tr '\n' ' ' | tr -s ' ' | cut -c1-${CLKW:-900})"
    grep -E 'pass over' /tmp/run.txt | sed -E 's/wavefront path tracing pass over ([0-9]+) slots, ([0-9]+) samples each: finished after ([0-9]+) launches.*next: ([0-9.]+).*/\1:\2:\3:\4/' | tr '\n' ' '; echo
  done
  ;;
s44c)
  # Session 44: whether a cold pipeline build idles the GPU into a slow benchmark: DamagedHelmet's
  # pt-nee in fresh processes with the driver's shader cache off (every process compiles its
  # pipelines), e6697aa (.device/bidir-head43.gz: one warm-up run) against 8f63d90
  # (.device/bidir-s44l.gz: warm-up runs of at least 1 s), four rounds interleaved, with the
  # SM clock as a fresh process starts; on an H200 then issue #16's table and #17's figures
  # with 8f63d90.
  unpack head43 s44l
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2 3 4; do
    for n in head43 s44l; do
      c=$(nvidia-smi --query-gpu=clocks.sm --format=csv,noheader)
      echo "== $n helmet pt-nee, a fresh process, no shader cache (SM clock before: $c): $(__GL_SHADER_DISK_CACHE=0 timeout -k 5 60 .device/bidir-$n bench render $HB --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then
    B=$PWD/.device/bidir-s44l bash "$0" s44d
  fi
  ;;
s44d)
  # Issue #16's table and #17's figures with the binary $B (s44b's).
  F=$B
  for i in pt pt-nee bdpt bdpt:full; do
    echo "== cornell $i 1024 spp: $(timeout -k 5 60 "$F" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    for t in 0.1 1; do
      echo "== cornell $i $t s: $(at_time "$F" $t $CB --integrator $i)"
    done
  done
  for i in pt-nee bdpt; do
    for t in 0.1 1; do
      echo "== caustic $i $t s: $(REFERENCE=assets/scenes/caustic/reference.exr at_time "$F" $t $CAU --integrator $i)"
    done
  done
  echo "== hidden bdpt: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  [ "${SPONZA:-1}" = 1 ] && sponza_rounds 2 "$F"
  ;;
s44j)
  # Session 44: issue #16's table with 77a31a5 (.device/bidir-carry.gz) on whatever card this
  # is; #17's figures too on an H200.
  unpack carry
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then s=1; else s=0; fi
  SPONZA=$s B=$PWD/.device/bidir-carry bash "$0" s44d
  ;;
s44b)
  # Session 44: 002c466 (.device/bidir-s44q.gz: both passes' queue places in their states, bench
  # render's warm-up of at least 1 s) against 8f63d90 (.device/bidir-s44l.gz: the light pass's
  # state in 80 bytes): wavefront images against megakernels on this GPU, s43c's rounds with
  # pt-nee's, issue #16's table with s44l, then e6697aa (.device/bidir-head43.gz, a warm-up of
  # one run) against s44q on DamagedHelmet's pt-nee in fresh processes; on an H200 also #17's
  # figures.
  unpack s44q s44l head43
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  F=$PWD/.device/bidir-s44l
  for sc in "cornell|--width 64 --height 64" "helmet|$HB" "caustic|$CAU"; do
    timeout -k 5 60 "$F" render ${sc#*|} --integrator bdpt --wavefront off --spp 16 --seed 3 --sample-slices 16 -o /tmp/m.exr > /dev/null 2>&1
    timeout -k 5 60 "$F" render ${sc#*|} --integrator bdpt --wavefront on --spp 16 --seed 3 --sample-slices 16 -o /tmp/w.exr > /dev/null 2>&1
    echo "== s44l ${sc%%|*} bdpt wavefront vs megakernel: $("$F" diff /tmp/w.exr /tmp/m.exr 2>&1 | grep -E '^RMSE')"
  done
  B43="s44q s44l" PT43=1 bash "$0" s43c
  for i in pt pt-nee bdpt bdpt:full; do
    echo "== cornell $i 1024 spp: $(timeout -k 5 60 "$F" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    for t in 0.1 1; do
      echo "== cornell $i $t s: $(at_time "$F" $t $CB --integrator $i)"
    done
  done
  for i in pt-nee bdpt; do
    for t in 0.1 1; do
      echo "== caustic $i $t s: $(REFERENCE=assets/scenes/caustic/reference.exr at_time "$F" $t $CAU --integrator $i)"
    done
  done
  for r in 1 2 3 4; do
    for n in head43 s44q; do
      echo "== $n helmet pt-nee, a fresh process: $(timeout -k 5 60 .device/bidir-$n bench render $HB --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  if nvidia-smi --query-gpu=name --format=csv,noheader | grep -q H200; then
    sponza_rounds 2 "$F"
  fi
  ;;
s44a)
  # Prepared in session 43, not run: the wavefront passes' queue places kept in their path
  # states, so that a launch reads them with the path and not from the index buffer:
  # scripts/device/s44a.patch (the camera pass: in its state's fourth word, the random numbers'
  # sample index recomputed, the status read from the vertex count; .device/bidir-s44a.gz),
  # s44b.patch (the light pass: a sixth word) with s44a.patch (.device/bidir-s44ab.gz), each on
  # 91d877d, against 0c9bd92's kernels (.device/bidir-wrd2.gz): each build's wavefront images
  # against its megakernels on this GPU, s43c's rounds, then issue #16's Cornell figures (0.1 s
  # and 1 s) and pt-nee's; then e6697aa (.device/bidir-head43.gz: the wavefront path tracer's
  # finishing threshold scaled to the pass's slots) against 0c9bd92 on DamagedHelmet's pt-nee in
  # fresh processes (session 43 saw 28-72 ms instead of 19 in some).
  unpack wrd2 s44a s44ab head43
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for n in wrd2 s44ab; do
    F=$PWD/.device/bidir-$n
    for sc in "cornell|--width 64 --height 64" "helmet|$HB"; do
      timeout -k 5 60 "$F" render ${sc#*|} --integrator bdpt --wavefront off --spp 16 --seed 3 --sample-slices 16 -o /tmp/m.exr > /dev/null 2>&1
      timeout -k 5 60 "$F" render ${sc#*|} --integrator bdpt --wavefront on --spp 16 --seed 3 --sample-slices 16 -o /tmp/w.exr > /dev/null 2>&1
      echo "== $n ${sc%%|*} bdpt wavefront vs megakernel: $("$F" diff /tmp/w.exr /tmp/m.exr 2>&1 | grep -E '^RMSE')"
    done
  done
  B43="wrd2 s44a s44ab" bash "$0" s43c
  for n in wrd2 s44ab; do
    F=$PWD/.device/bidir-$n
    for t in 0.1 1; do
      echo "== $n cornell bdpt $t s: $(at_time "$F" $t $CB --integrator bdpt)"
    done
  done
  F=$PWD/.device/bidir-wrd2
  echo "== cornell pt-nee 1024 spp: $(timeout -k 5 60 "$F" bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  for t in 0.1 1; do
    echo "== cornell pt-nee $t s: $(at_time "$F" $t $CB --integrator pt-nee)"
  done
  for r in 1 2 3 4; do
    for n in wrd2 head43; do
      echo "== $n helmet pt-nee, a fresh process: $(timeout -k 5 60 .device/bidir-$n bench render $HB --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  echo "== head43 helmet pt-nee passes"; BIDIR_WF_LOG=1 timeout -k 5 60 .device/bidir-head43 bench render $HB --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -E "pass over|GPU" | cut -c1-200 | head -20
  ;;
s43g)
  # Session 43: 0c9bd92 (.device/bidir-wrd2.gz, the same kernels) for issue #16's table on
  # whatever card this is, beside 3dc4982 (.device/bidir-s43.gz): the Cornell box's bdpt and
  # pt-nee (1024-spp cost, 0.1 s and 1 s), the hidden light, the caustic scene; and whether
  # 3dc4982's BDPT wavefront image of the caustic scene differs from its megakernels' too.
  unpack s43 wrd2
  F=$PWD/.device/bidir-s43
  timeout -k 5 60 "$F" render $CAU --integrator bdpt --spp 64 --seed 3 --wavefront off -o /tmp/m.exr > /dev/null 2>&1
  timeout -k 5 60 "$F" render $CAU --integrator bdpt --spp 64 --seed 3 --wavefront on -o /tmp/w.exr > /dev/null 2>&1
  echo "== s43 bdpt caustic wavefront vs megakernel: $("$F" diff /tmp/w.exr /tmp/m.exr 2>&1 | grep -E '^RMSE')"
  timeout -k 5 60 "$F" render $CAU --integrator bdpt --spp 64 --seed 3 --wavefront off --bvh bvh4 -o /tmp/m.exr > /dev/null 2>&1
  echo "== s43 bdpt caustic wavefront vs megakernel over bvh4: $("$F" diff /tmp/w.exr /tmp/m.exr 2>&1 | grep -E '^RMSE')"
  for n in s43 wrd2; do
    F=$PWD/.device/bidir-$n
    for i in pt-nee bdpt; do
      echo "== $n cornell $i 1024 spp: $(timeout -k 5 60 "$F" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
    echo "== $n hidden bdpt: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  done
  F=$PWD/.device/bidir-wrd2
  for i in bdpt pt-nee; do
    for t in 0.1 1; do
      echo "== wrd2 cornell $i $t s: $(at_time "$F" $t $CB --integrator $i)"
      echo "== wrd2 caustic $i $t s: $(REFERENCE=assets/scenes/caustic/reference.exr at_time "$F" $t $CAU --integrator $i)"
    done
  done
  ;;
s43f)
  # Session 43: the one-word any-hit results as parts of uvec4s (.device/bidir-wrd2.gz; s43e's
  # aliased blocks were not bound on NVIDIA): each build's wavefront images against its
  # megakernels on this GPU, then s43c's rounds over 3dc4982 (s43), the index packing (idx) and
  # wrd2, then the Cornell box at 0.1 s and 1 s with wrd2.
  unpack s43 idx wrd2
  for n in idx wrd2; do
    F=$PWD/.device/bidir-$n
    for i in bdpt pt-nee; do
      timeout -k 5 60 "$F" render $CAU --integrator $i --spp 64 --seed 3 --wavefront off -o /tmp/m.exr > /dev/null 2>&1
      timeout -k 5 60 "$F" render $CAU --integrator $i --spp 64 --seed 3 --wavefront on -o /tmp/w.exr > /dev/null 2>&1
      echo "== $n $i caustic wavefront vs megakernel: $("$F" diff /tmp/w.exr /tmp/m.exr 2>&1 | grep -E '^RMSE')"
    done
    timeout -k 5 60 "$F" render --width 64 --height 64 --integrator bdpt --wavefront off --spp 64 --seed 3 -o /tmp/m.exr > /dev/null 2>&1
    timeout -k 5 60 "$F" render --width 64 --height 64 --integrator bdpt --wavefront on --spp 64 --seed 3 -o /tmp/w.exr > /dev/null 2>&1
    echo "== $n cornell bdpt wavefront vs megakernel: $("$F" diff /tmp/w.exr /tmp/m.exr 2>&1 | grep -E '^RMSE')"
  done
  PT43=1 B43="s43 idx wrd2" bash "$0" s43c
  F=$PWD/.device/bidir-wrd2
  for i in bdpt pt-nee; do
    for t in 0.1 1; do
      echo "== wrd2 cornell $i $t s: $(timeout -k 5 60 "$F" render $CB --integrator $i --time $t -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/q.exr "$REF" 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
    done
  done
  ;;
s43e)
  # Session 43: why the build with one-word any-hit results (.device/bidir-wrd.gz) ran slow on
  # an H100 in s43c, against the index packing alone (.device/bidir-idx.gz) and aos64: a 64 x 64
  # render of each in either form against the megakernels, the launches' counts, kernel tables.
  unpack aos64 idx wrd
  for n in aos64 idx wrd; do
    F=$PWD/.device/bidir-$n
    timeout -k 5 60 "$F" render --width 64 --height 64 --integrator bdpt --wavefront off --spp 64 --seed 3 -o /tmp/m-$n.exr > /dev/null 2>&1
    BIDIR_WF_LOG=1 timeout -k 5 60 "$F" render --width 64 --height 64 --integrator bdpt --wavefront on --spp 64 --seed 3 -o /tmp/w-$n.exr 2>&1 | grep -E "batch|spp in|rror" | cut -c1-300 | head -8
    echo "== $n wavefront vs megakernel: $("$F" diff /tmp/w-$n.exr /tmp/m-$n.exr 2>&1 | grep -E '^(RMSE|mean)' | tr '\n' ' ')"
    echo "== $n pt-nee caustic: $(timeout -k 5 60 "$F" render $CAU --integrator pt-nee --spp 64 --seed 3 --wavefront on -o /tmp/c-$n.exr 2>&1 | grep -E 'spp in|rror') $(timeout -k 5 60 "$F" render $CAU --integrator pt-nee --spp 64 --seed 3 --wavefront off -o /tmp/cm-$n.exr >/dev/null 2>&1; "$F" diff /tmp/c-$n.exr /tmp/cm-$n.exr 2>&1 | grep -E '^RMSE')"
    echo "== $n kernel table cornell"; timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -E -A8 "^kernel|GPU [0-9.]+ ms|rror"
  done
  ;;
s43c)
  # Session 43: BDPT's wavefront path states word by word (.device/bidir-soa.gz; the medium's
  # word left out where a scene has none) against 3dc4982's structs (.device/bidir-s43.gz):
  # bench render GPU ms and the camera and light kernels' ms, two rounds interleaved.
  B43=${B43:-s43 soa}
  unpack $B43
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  k='GPU [0-9.]+ ms|bdpt_(camera|light)_wavefront +[0-9.]+'
  for r in 1 2; do
    for n in $B43; do
      F=$PWD/.device/bidir-$n
      echo "== $n cornell: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n hidden: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n sponza 8: $(timeout -k 5 60 "$F" bench render $SP --integrator bdpt --connection-candidates 8 --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      echo "== $n helmet: $(timeout -k 5 60 "$F" bench render $HB --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE "$k" | tr '\n' ' ')"
      if [ -n "${PT43:-}" ]; then
        echo "== $n helmet pt-nee: $(timeout -k 5 60 "$F" bench render $HB --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
        echo "== $n caustic pt-nee: $(timeout -k 5 60 "$F" bench render $CAU --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
        echo "== $n caustic bdpt: $(timeout -k 5 60 "$F" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
      fi
    done
  done
  ;;
s43b)
  # Session 43: where a BDPT sample's time goes with the finishing launch (kernel tables of
  # bench render on the Cornell box: bdpt auto, 1 candidate, pt-nee), and the finishing
  # launch after 2, 4, 6, 8 launches (.device/bidir-s43.gz).
  unpack s43
  F=$PWD/.device/bidir-s43
  for a in "bdpt|" "bdpt|--connection-candidates 1" "pt-nee|" "bdpt|--light-paths 0.25"; do
    echo "== kernel table ${a%%|*} ${a#*|}"
    timeout -k 5 60 "$F" bench render $CB --integrator ${a%%|*} ${a#*|} --spp 1024 --warmup 1 --runs 3 2>&1 | grep -E -A24 "^kernel|GPU [0-9.]+ ms"
  done
  for f in 2 4 6 8 auto; do
    echo "== cornell finish $f: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 --wavefront-finish $f 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
  done
  echo "== registers"; timeout -k 5 45 "$F" info --kernels 2>&1 | grep -E "bdpt_(camera|light)|pt_nee|trace" | cut -c1-200 | head -24
  ;;
s43a)
  # Session 43 (.device/bidir-s43.gz, a build of 3dc4982 with a measurement hook,
  # BIDIR_EXP_BUILD: obvhs' pre-split thresholds from BIDIR_EXP_SPLIT=low,flow,fhigh,iters).
  # Issue #16's table on whatever card this is: pt, pt-nee, bdpt, bdpt:full on the Cornell box
  # (1024-spp cost, 0.1 s and 1 s against .device/ref.exr), the caustic scene's bdpt; then
  # issue #17's figures (two rounds), then pre-split settings at quality 5.
  unpack s43
  F=$PWD/.device/bidir-s43
  for i in pt pt-nee bdpt bdpt:full; do
    echo "== cornell $i 1024 spp: $(timeout -k 5 60 "$F" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    for t in 0.1 1; do
      echo "== cornell $i $t s: $(timeout -k 5 60 "$F" render $CB --integrator $i --time $t -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/q.exr "$REF" 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
    done
  done
  echo "== hidden bdpt: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
  for i in pt-nee bdpt; do
    echo "== caustic $i 256 spp: $(timeout -k 5 60 "$F" bench render $CAU --integrator $i --spp 256 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    for t in 0.1 1; do
      echo "== caustic $i $t s: $(timeout -k 5 60 "$F" render $CAU --integrator $i --time $t -o /tmp/c.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/c.exr assets/scenes/caustic/reference.exr 2>&1 | grep -E '^RMSE ')"
    done
  done
  sponza_rounds 2 "$F"
  [ "${NO_SPLITS:-}" = 1 ] && exit 0
  for sp in "0.75,1.3,1.2,16" "1,1.3,1.2,16" "0.5,1.3,1.2,16" "3,1.8,1.6,12"; do
    for c in "" "--refill 24"; do
      echo "== split $sp $c"; BIDIR_EXP_BUILD=1 BIDIR_EXP_SPLIT=$sp sponza_q5 "$F" $c
    done
  done
  ;;
s42g)
  # Session 42, for an H200 if one comes: issue #16's figures with the finishing launch
  # (.device/bidir-fin4.gz) against none (off): the Cornell box, the hidden light, pt-nee, 1 s.
  unpack fin4
  F=$PWD/.device/bidir-fin4
  for f in off auto; do
    for sc in "cornell|$CB" "hidden|$HID"; do
      echo "== ${sc%%|*} bdpt $f: $(timeout -k 5 60 "$F" bench render ${sc#*|} --integrator bdpt --spp 1024 --warmup 1 --runs 3 --wavefront-finish $f 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    done
  done
  echo "== cornell pt-nee: $(timeout -k 5 60 "$F" bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
  for i in bdpt pt-nee; do
    echo "== cornell $i 1 s: $(timeout -k 5 60 "$F" render $CB --integrator $i --time 1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/q.exr "$REF" 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
    echo "== cornell $i 0.1 s: $(timeout -k 5 60 "$F" render $CB --integrator $i --time 0.1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/q.exr "$REF" 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
  done
  ;;
s42f)
  # Session 42: the finishing launch's count scaled by the pass's slots (.device/bidir-fin4.gz)
  # against the count learnt unscaled (.device/bidir-fin3.gz), where passes of other sizes follow
  # each other (a time-budgeted render's first tenth of a second), and the steady cost; then, on
  # whatever card this is, the finishing launch against none (off) for issue #16's figures: the
  # Cornell box, the hidden light, Sponza, pt-nee, 1 s.
  unpack fin3 fin4
  for r in 1 2; do
    for n in fin3 fin4; do
      echo "== $n bdpt 0.1 s: $(BIDIR_PASS_LOG=1 timeout -k 5 60 .device/bidir-$n render $CB --integrator bdpt --time 0.1 -o /tmp/q.exr 2>&1 | grep -E "pass:|spp in" | sed -E 's/pass: samples //; s/, slices [0-9]+//; s/ submissions//; s/predicted [-0-9. ms]+, //' | cut -c1-60 | tr '\n' '|')"
    done
  done
  F=$PWD/.device/bidir-fin4
  for r in 1; do
    for f in off auto; do
      for sc in "cornell|$CB|1024" "hidden|$HID|1024"; do
        n=${sc%%|*}; rest=${sc#*|}; S=${rest%|*}; spp=${rest##*|}
        echo "== $n bdpt $f: $(timeout -k 5 60 "$F" bench render $S --integrator bdpt --spp $spp --warmup 1 --runs 3 --wavefront-finish $f 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
      done
    done
    echo "== cornell pt-nee: $(timeout -k 5 60 "$F" bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    for i in "bdpt|auto" "pt-nee|auto"; do
      echo "== cornell ${i%%|*} ${i#*|} 1 s: $(timeout -k 5 60 "$F" render $CB --integrator ${i%%|*} --wavefront-finish ${i#*|} --time 1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
    done
  done
  ;;
s42e)
  # Session 42: whether the wavefront path tracer with its finishing launch (.device/bidir-fin3.gz)
  # now beats the megakernel where the megakernel is the default (the diffuse Cornell box, the
  # caustic scene's smooth glass, the hidden light's box): bench render, two rounds, and the
  # Cornell box at 1 s.
  unpack fin3
  F=$PWD/.device/bidir-fin3
  for r in 1 2; do
    for sc in "cornell|$CB|1024" "hidden|$HID|1024" "caustic|$CAU|1024"; do
      n=${sc%%|*}; rest=${sc#*|}; S=${rest%|*}; spp=${rest##*|}
      for i in pt-nee pt; do
        for w in off on; do
          echo "== $n $i wavefront $w: $(timeout -k 5 60 "$F" bench render $S --integrator $i --spp $spp --warmup 1 --runs 3 --wavefront $w 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
        done
      done
    done
  done
  for w in off on off on; do
    echo "== cornell pt-nee 1 s wavefront $w: $(timeout -k 5 60 "$F" render $CB --integrator pt-nee --time 1 --wavefront $w -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/q.exr "$REF" 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
  done
  ;;
s42d)
  # Session 42: .device/bidir-fin3.gz (the finishing launch for BDPT's passes and the wavefront
  # path tracer's). Issue #16's table: pt, pt-nee, bdpt and bdpt:full on the Cornell box at
  # 0.1 s and 1 s against .device/ref.exr, and their 1024-spp cost; the caustic scene's bdpt
  # with and without the finishing launch (cost, and 0.1 / 1 s against its reference); the
  # wavefront path tracer on DamagedHelmet (its launches, pt-nee and pt off / auto, the
  # megakernel, pt-nee at --max-depth 16).
  unpack fin3
  F=$PWD/.device/bidir-fin3
  HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  echo "== helmet pt-nee launches (64 spp), off then auto"
  for f in off auto; do BIDIR_WF_LOG=1 timeout -k 5 60 "$F" render $HB --integrator pt-nee --spp 64 --wavefront-finish $f -o /tmp/q.exr 2>&1 | grep -E "wavefront batch|spp in" | cut -c1-900; done
  for r in 1 2; do
    for o in "pt-nee|--wavefront-finish off" "pt-nee|" "pt-nee|--wavefront off" "pt-nee|--wavefront-finish off --max-depth 16" "pt|--wavefront-finish off" "pt|" "bdpt|--wavefront-finish off" "bdpt|"; do
      i=${o%%|*}; a=${o#*|}
      echo "== helmet $i 256 spp [$a]: $(timeout -k 5 60 "$F" bench render $HB --integrator $i --spp 256 --warmup 1 --runs 3 $a 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    done
  done
  for i in pt pt-nee bdpt bdpt:full; do
    echo "== cornell $i 1024 spp: $(timeout -k 5 60 "$F" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    for t in 0.1 1; do
      echo "== cornell $i $t s: $(timeout -k 5 60 "$F" render $CB --integrator $i --time $t -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/q.exr "$REF" 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
    done
  done
  for f in off auto; do
    echo "== caustic bdpt $f 256 spp: $(timeout -k 5 60 "$F" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 --wavefront-finish $f 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    for t in 0.1 1; do
      echo "== caustic bdpt $f $t s: $(timeout -k 5 60 "$F" render $CAU --integrator bdpt --time $t --wavefront-finish $f -o /tmp/c.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/c.exr assets/scenes/caustic/reference.exr 2>&1 | grep -E '^RMSE ')"
    done
  done
  ;;
s42c)
  # Session 42: BDPT's passes ended by a finishing launch (--wavefront-finish; .device/bidir-fin2.gz,
  # the working tree of that change): off (launches until one queues no ray, as before), auto,
  # and fixed counts of launches; GPU and wall ms of bench render, two rounds interleaved; the
  # Cornell box at 1 s and 0.1 s; the launches auto chose (BIDIR_WF_LOG).
  unpack fin2
  F=$PWD/.device/bidir-fin2
  for r in 1 2; do
    for f in off auto 6 8 10 12 14 16; do
      echo "== cornell finish $f: $(timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 --wavefront-finish $f 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    done
    for f in off auto 8 12; do
      echo "== hidden finish $f: $(timeout -k 5 60 "$F" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 --wavefront-finish $f 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    done
    for f in off auto; do
      echo "== sponza 8 finish $f: $(timeout -k 5 60 "$F" bench render $SP --integrator bdpt --connection-candidates 8 --spp 64 --warmup 1 --runs 3 --wavefront-finish $f 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
      echo "== cornell 1 s finish $f: $(timeout -k 5 60 "$F" render $CB --integrator bdpt --time 1 --wavefront-finish $f -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$F" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
    done
    echo "== pt-nee 1024 spp: $(timeout -k 5 60 "$F" bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    # DamagedHelmet (its metal keeps light paths long: about 190 launches a pass in session 20).
    HB="$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
    for f in off auto; do
      echo "== helmet finish $f: $(timeout -k 5 60 "$F" bench render $HB --integrator bdpt --spp 256 --warmup 1 --runs 3 --wavefront-finish $f 2>&1 | grep -oE '(GPU|wall) [0-9.]+ ms' | tr '\n' ' ')"
    done
  done
  for f in off auto off auto; do echo "== bdpt 0.1 s finish $f: $(BIDIR_PASS_LOG=1 timeout -k 5 60 "$F" render $CB --integrator bdpt --time 0.1 --wavefront-finish $f -o /tmp/q.exr 2>&1 | grep -E "pass:|spp in" | sed -E 's/pass: samples //; s/, slices [0-9]+//; s/ submissions//' | tr '\n' '|')"; done
  echo "== auto's launches (Cornell, 256 spp)"
  BIDIR_WF_LOG=1 timeout -k 5 60 "$F" render $CB --integrator bdpt --spp 256 -o /tmp/q.exr 2>&1 | grep -E "wavefront batch|spp in" | cut -c1-400
  echo "== kernel table, auto"
  timeout -k 5 60 "$F" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -A14 "^kernel"
  echo "== registers"; timeout -k 5 45 "$F" info --kernels 2>&1 | grep -E "bdpt_(camera|light)_(wavefront|finish)" | cut -c1-240 | head -8
  ;;
s42b)
  # Session 42: what BDPT's pass tails cost. .device/bidir-log.gz (9de66d8 with BIDIR_WF_LOG:
  # each batch prints the rays each launch queued). bench render at --max-depth 8 / 12 / 16
  # against unbounded (0): the time the long paths' launches take beyond their work (an upper
  # bound on what finishing them in one launch could save); the launches of one iteration;
  # the kernel table (dispatches per kernel).
  unpack log
  L=$PWD/.device/bidir-log
  for r in 1 2; do
    for md in 0 8 12 16; do
      echo "== cornell bdpt max-depth $md: $(timeout -k 5 60 "$L" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 --max-depth $md 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
      echo "== hidden bdpt max-depth $md: $(timeout -k 5 60 "$L" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 --max-depth $md 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
    echo "== cornell pt-nee: $(timeout -k 5 60 "$L" bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  done
  echo "== one iteration's launches (Cornell, 128 spp)"
  BIDIR_WF_LOG=1 timeout -k 5 60 "$L" render $CB --integrator bdpt --spp 128 -o /tmp/q.exr 2>&1 | grep -E "wavefront batch|spp in" | cut -c1-1500
  echo "== kernel table"
  timeout -k 5 60 "$L" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | tail -25
  ;;
s42a)
  # Prepared in session 41 (not run): a measurement build, scripts/device/s42-partial.patch on
  # the commit that adds lvc_candidate_entry (.device/bidir-part.gz): where a subgroup holds more candidate groups than its lanes
  # can read at once (k N > lanes; Sponza's camera kernel still 16 % above the lanes' pools),
  # the first floor(lanes / N) groups share their reads and only the others read their own,
  # where 264f878 makes every lane read its own. The same images (lavapipe, 2/3/4/8
  # candidates, both forms, RMSE 0.000000). Against .device/bidir-fin.gz (264f878) and the
  # pools (.device/bidir-base.gz): two rounds interleaved, the Cornell box at 1 s in the
  # second; registers. Keep it if Sponza gains and the boxes and registers stay.
  unpack base fin part
  bdpt_rounds base fin part
  for n in base fin part; do echo "$n: $(timeout -k 5 45 ".device/bidir-$n" info --kernels 2>&1 | grep -E "bdpt:lvc=1 / bdpt_camera_wavefront" | head -1 | grep -oE "Register Count [0-9]+")"; done
  ;;
s41e)
  # Session 41: the kept form (.device/bidir-fin.gz, a build of the commit that keeps the
  # groups' candidates in one loop of N trips over 16 x 8 blocks) against the pools (base) and
  # the groups in passes (c41): two rounds interleaved, the Cornell box at 1 s in the second;
  # pt-nee's 1024 spp; bdpt at 0.1 s in three fresh processes (the ramp).
  unpack base c41 fin
  bdpt_rounds base c41 fin
  echo "== fin registers: $(timeout -k 5 45 .device/bidir-fin info --kernels 2>&1 | grep -E "bdpt:lvc=1 / bdpt_camera_wavefront" | head -1 | grep -oE "Register Count [0-9]+")"
  echo "== pt-nee 1024 spp: $(timeout -k 5 60 .device/bidir-fin bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  echo "== pt-nee 1 s: $(timeout -k 5 60 .device/bidir-fin render $CB --integrator pt-nee --time 1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $(.device/bidir-fin diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
  for r in 1 2 3; do echo "== fin bdpt 0.1 s ($r): $(BIDIR_PASS_LOG=1 timeout -k 5 60 .device/bidir-fin render $CB --integrator bdpt --time 0.1 -o /tmp/q.exr 2>&1 | grep -E "pass:|spp in" | sed -E 's/pass: samples //; s/, slices [0-9]+//; s/ submissions//' | tr '\n' '|')"; done
  ;;
s41d)
  # Session 41: the camera kernel's registers (s41b: 72 with the lanes' pools, 96 with every
  # form of the groups). nd (scripts/device/s41-cursor.patch on 1fce64e): where the subgroup's
  # connecting lanes can read every group's N candidates at once (k N <= lanes) the lane of
  # rank g N + i reads group g's candidate i and each lane takes its group's by a cursor over
  # the N lanes from rank g N, N trips of a fixed count as the pools had; else every lane reads
  # its own N (the same entries). nd16: the same with groups of 16 x 8 (s39f.patch); against the
  # pools (base), the groups (c41) and their 16 x 8 form (g16c); two rounds interleaved, the
  # Cornell box at 1 s in the second; registers.
  unpack base c41 g16c nd nd16
  bdpt_rounds base c41 g16c nd nd16
  echo "== info --kernels"
  for n in base c41 g16c nd nd16; do echo "$n: $(timeout -k 5 45 ".device/bidir-$n" info --kernels 2>&1 | grep -E "bdpt:lvc=1 / bdpt_camera_wavefront" | head -1 | grep -oE "Register Count [0-9]+")"; done
  echo "== pt-nee 1024 spp: $(timeout -k 5 60 .device/bidir-c41 bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  ;;
s41c)
  # Session 41 (run on an H100; the model reverted, 1fce64e): the pass model with pieces (.device/bidir-pace.gz, 0ce278d: a pass
  # costs overhead x pieces + per_spp x spp, a held pass ends on an iteration's boundary)
  # against c41's one overhead a pass: bdpt at 0.1 s, four fresh processes each, interleaved;
  # pt-nee at 0.1 s (one piece a pass: unchanged); bdpt at 1 s.
  unpack c41 pace
  for r in 1 2 3 4; do
    for n in c41 pace; do echo "== $n bdpt 0.1 s ($r): $(BIDIR_PASS_LOG=1 timeout -k 5 60 .device/bidir-$n render $CB --integrator bdpt --time 0.1 -o /tmp/q.exr 2>&1 | grep -E "pass:|spp in" | sed -E 's/pass: samples //; s/, slices [0-9]+//; s/ submissions//' | tr '\n' '|')"; done
  done
  for n in c41 pace; do echo "== $n pt-nee 0.1 s: $(timeout -k 5 60 .device/bidir-$n render $CB --integrator pt-nee --time 0.1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"; done
  for n in c41 pace; do echo "== $n bdpt 1 s: $(timeout -k 5 60 .device/bidir-$n render $CB --integrator bdpt --time 1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"; done
  ;;
s41b)
  # Session 41: what the candidate groups cost on the H200 (s41a: the lanes' pools c821483
  # 129.3 ms on the Cornell box against 137.4-137.7 for the groups), and three measurement
  # builds on 0becd4b: fp (scripts/device/s41-one-key.patch: a subgroup of one key skips the key
  # loop by one vote), g16c (s39f.patch: groups of 16 x 8 pixels) and g16f (both); two rounds
  # interleaved, the Cornell box at 1 s in the second; every build's camera kernel registers;
  # pt-nee's 1024 spp for the ratio.
  unpack base new c41 fp g16c g16f
  bdpt_rounds base new c41 fp g16c g16f
  echo "== info --kernels"
  for n in base new c41 fp g16c g16f; do echo "$n: $(timeout -k 5 45 ".device/bidir-$n" info --kernels 2>&1 | grep -E "bdpt:lvc=1 / bdpt_camera_wavefront" | head -1 | grep -oE "Register Count [0-9]+")"; done
  echo "== pt-nee 1024 spp: $(timeout -k 5 60 .device/bidir-c41 bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  # BDPT's iterations: a pass piece costs about 3 ms beyond its samples (s41a's pass log:
  # t = 3.0 ms x pieces + 0.12 ms x spp), the launches' tails; larger iterations amortise it.
  for sl in 64 128 256 512 1024; do
    echo "== slices $sl: cornell $(timeout -k 5 60 .device/bidir-c41 bench render $CB --integrator bdpt --sample-slices $sl --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms|wall [0-9.]+ ms' | tr '\n' ' ') hidden $(timeout -k 5 60 .device/bidir-c41 bench render $HID --integrator bdpt --sample-slices $sl --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms' | tr '\n' ' ')"
  done
  for sl in 32 64; do echo "== sponza slices $sl: $(timeout -k 5 60 .device/bidir-c41 bench render $SP --integrator bdpt --sample-slices $sl --spp 128 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms|wall [0-9.]+ ms|error.*' | tr '\n' ' ')"; done
  echo "== sponza default: $(timeout -k 5 60 .device/bidir-c41 bench render $SP --integrator bdpt --spp 128 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms|wall [0-9.]+ ms|[0-9]+ slices' | tr '\n' ' ')"
  for sl in 128 256 512; do echo "== 1 s slices $sl: $(timeout -k 5 60 .device/bidir-c41 render $CB --integrator bdpt --sample-slices $sl --time 1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $(.device/bidir-c41 diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"; done
  ;;
s41a)
  # Session 41: s40a (session 40's candidate reads, never run), then what a time-budgeted
  # render's passes spend (.device/bidir-c41.gz, a build of 0becd4b or later, whose
  # BIDIR_PASS_LOG gives each pass's submissions and slices): bdpt at 0.1 s in three fresh
  # processes and at 1 s, pt-nee at 0.1 s, the Cornell box; bdpt's kernel table at 1024 spp.
  # (s40a without g16 and rd1t, whose binaries no longer fit the carry beside c41 and sw.)
  unpack base new rd2e cur
  bdpt_rounds base new rd2e cur
  echo "== info --kernels"
  for n in new cur; do echo "$n: $(timeout -k 5 45 ".device/bidir-$n" info --kernels 2>&1 | grep -E "bdpt:lvc=1 / bdpt_camera_wavefront" | head -2 | tr '\n' ' ')"; done
  unpack c41
  b=$PWD/.device/bidir-c41
  for r in 1 2 3; do echo "== bdpt 0.1 s ($r)"; BIDIR_PASS_LOG=1 timeout -k 5 60 "$b" render $CB --integrator bdpt --time 0.1 -o /tmp/q.exr 2>&1 | grep -E "pass:|spp in"; done
  echo "== bdpt 1 s"; BIDIR_PASS_LOG=1 timeout -k 5 60 "$b" render $CB --integrator bdpt --time 1 -o /tmp/q.exr 2>&1 | grep -E "pass:|spp in"
  echo "== pt-nee 0.1 s"; BIDIR_PASS_LOG=1 timeout -k 5 60 "$b" render $CB --integrator pt-nee --time 0.1 -o /tmp/q.exr 2>&1 | grep -E "pass:|spp in"
  echo "== bdpt bench 1024 spp"; timeout -k 5 60 "$b" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | tail -25
  # A measurement build (scripts/device/s41-state-write.patch on 0becd4b, .device/bidir-sw.gz):
  # the camera wavefront's state written without its medium and opacity seed where the scene
  # has neither (16 of 80 bytes a step), against c41, two rounds interleaved.
  unpack sw
  for r in 1 2; do for n in c41 sw; do bdpt_round "$PWD/.device/bidir-$n" sponza; done; done
  ;;
s40b)
  # Session 40: s40a cut short: one round of the builds (Cornell box, the hidden light's box,
  # Sponza), then session 39's groups and this commit's reads again, interleaved, with the
  # Cornell box at 1 s.
  unpack base new g16 rd1t rd2e cur
  for n in base new g16 rd1t rd2e cur; do bdpt_round "$PWD/.device/bidir-$n" sponza; done
  for n in new cur; do bdpt_round "$PWD/.device/bidir-$n" sponza time; done
  ;;
s40a)
  # Session 40: the candidate groups' reads shared by every connecting lane of the subgroup
  # (in a pass from virtual entry `first` the lane of rank r reads entry first + r):
  # .device/bidir-cur.gz a build of bf1cb13 or later (for k groups, group g's candidate i is
  # entry i k + g, each pass serving every group alike), .device/bidir-rd1t.gz fb09d7b's (g N +
  # i: group after group), .device/bidir-rd2e.gz a form with passes of two entries per lane
  # (scripts/device/s40a-two-sets.patch on c111b56); against session 39's reads per group
  # (.device/bidir-new.gz, 3a6688e; .device/bidir-g16.gz its 16 x 8 groups, s39f.patch) and the
  # lanes' pools (.device/bidir-base.gz, c821483): `bench render` GPU ms on the Cornell box,
  # the hidden light's box and Sponza, two rounds interleaved; the Cornell box at 1 s in the
  # second; the camera kernel's registers. (16 x 8 groups over the shared reads: bundle a build
  # of HEAD with s39f.patch as .device/bidir-curg16.gz and add it to the list.)
  unpack base new g16 rd1t rd2e cur
  bdpt_rounds base new g16 rd1t rd2e cur
  echo "== info --kernels"
  for n in new cur; do echo "$n: $(timeout -k 5 45 ".device/bidir-$n" info --kernels 2>&1 | grep -E "bdpt:lvc=1 / bdpt_camera_wavefront" | head -2 | tr '\n' ' ')"; done
  ;;
s39f)
  # Session 39: candidate groups of 16 x 8 pixels (a measurement build, scripts/device/s39f.patch
  # on 38264bd, .device/bidir-g16.gz) against 8 x 4 (.device/bidir-new.gz): in the wavefront form
  # compaction puts the live slots of a block or two in a subgroup, and larger groups would read
  # less; `bench render` GPU ms, two rounds interleaved, and the Cornell box at 1 s (the per-pixel
  # variance on lavapipe was level: RMSE between seeds 1-2 at 64², 1,024 spp 0.001547 / 0.001112
  # off the edge, against 0.001537 / 0.001096).
  unpack new g16
  for r in 1 2; do
    for n in new g16; do bdpt_round "$PWD/.device/bidir-$n" time; done
  done
  ;;
s39e)
  # Session 39's candidate groups (each 8 x 4 block of pixels, sample and vertex count draws
  # its candidates by hashes; the lanes connecting for one group share the reads) against
  # session 38's lanes' pools (.device/bidir-base.gz, a build of c821483): `bench render` GPU ms
  # (two rounds interleaved: the Cornell box 256² and the hidden light's box at 1024 spp,
  # Sponza's geometry under sun and sky with 8 candidates at 64 spp), `render --time 1` on the
  # Cornell box against .device/ref.exr, and whether a seed gives one image in the wavefront
  # form now (two renders of 64 spp, seed 1) and the megakernels' image.
  unpack new base
  N=$PWD/.device/bidir-new
  for r in 1 2; do
    for n in base new; do bdpt_round "$PWD/.device/bidir-$n" sponza time; done
  done
  for k in 1 2; do timeout -k 5 60 "$N" render $CB --integrator bdpt --spp 64 --seed 1 -o /tmp/d$k.exr > /dev/null 2>&1; done
  echo "== same seed twice, wavefront, 8 candidates: $("$N" diff /tmp/d1.exr /tmp/d2.exr 2>&1 | grep -E '^RMSE ')"
  timeout -k 5 60 "$N" render $CB --integrator bdpt --wavefront off --spp 64 --seed 1 -o /tmp/d3.exr > /dev/null 2>&1
  echo "== the megakernels' image of that seed: $("$N" diff /tmp/d1.exr /tmp/d3.exr 2>&1 | grep -E '^RMSE ')"
  ;;
s39d)
  # Session 39, issue #16: a measurement build (scripts/device/s39d.patch on c821483, as
  # .device/bidir-exp.gz) whose camera step draws the light vertex cache's first entry beside
  # the random stream at the vertex's start, so its read overlaps the BSDF and the light sample,
  # against c821483's own build (.device/bidir-base.gz): `bench render` GPU ms, two rounds
  # interleaved, and the camera kernel's registers.
  unpack base exp
  for r in 1 2; do
    for n in base exp; do bdpt_round "$PWD/.device/bidir-$n" sponza; done
  done
  echo "== info --kernels"
  for n in base exp; do timeout -k 5 120 ".device/bidir-$n" info --kernels 2>&1 | grep -E "bdpt:lvc=1 / bdpt_camera_wavefront"; done
  ;;
s39c)
  # Session 39, issue #16: the time-budgeted render's passes (BIDIR_PASS_LOG=1: samples, the
  # model's prediction, the time taken) for bdpt and pt-nee at 0.1 s (three fresh processes
  # each) and bdpt at 1 s, Cornell box 256²; the caustic scene's bdpt at 0.1 s.
  N=$PWD/.device/bidir-new
  gunzip -kf .device/bidir-new.gz; chmod +x "$N"
  for i in bdpt pt-nee bdpt pt-nee bdpt pt-nee; do
    echo "== 0.1 s $i"; BIDIR_PASS_LOG=1 timeout -k 5 60 "$N" render $CB --integrator $i --time 0.1 -o /tmp/q.exr 2>&1 | grep -vE "^(Wrote|wrote)"
  done
  echo "== 1 s bdpt"; BIDIR_PASS_LOG=1 timeout -k 5 60 "$N" render $CB --integrator bdpt --time 1 -o /tmp/q.exr 2>&1 | tail -12
  echo "== caustic 0.1 s bdpt"; BIDIR_PASS_LOG=1 timeout -k 5 60 "$N" render $CAU --integrator bdpt --time 0.1 -o /tmp/q.exr 2>&1
  ;;
s39b)
  # Session 39, issue #16: fewer light paths per pixel with more shared candidates on the
  # Cornell box: `bench render` ms per 1024 spp and 1 s RMSE against .device/ref.exr (two runs).
  N=$PWD/.device/bidir-new
  gunzip -kf .device/bidir-new.gz; chmod +x "$N"
  for o in "--light-paths 0.25 --connection-candidates 32" "--light-paths 0.125 --connection-candidates 16" "--light-paths 0.125 --connection-candidates 32" "--light-paths 0.0625 --connection-candidates 32"; do
    echo "== bench $o: $(timeout -k 5 60 "$N" bench render $CB --integrator bdpt $o --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    for r in 1 2; do
      echo "   1 s: $(timeout -k 5 60 "$N" render $CB --integrator bdpt $o --time 1 --seed $r -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$N" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
    done
  done
  echo "== bench pt-nee: $(timeout -k 5 60 "$N" bench render $CB --integrator pt-nee --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
  ;;
s39a)
  # Session 39, issue #16: where a BDPT sample's time goes under session 38's defaults (8 shared
  # candidates, half a light path per pixel), kernel by kernel, against pt-nee and against one
  # light path per pixel and one candidate; the kernels' registers; fewer light paths with 16
  # candidates at equal time on the Cornell box and where the light hides.
  N=$PWD/.device/bidir-new
  gunzip -kf .device/bidir-new.gz; chmod +x "$N"
  timeout -k 5 120 "$N" info --kernels 2>&1 | grep -iE "bdpt|pt_|trace|kernel|regist" | head -40
  for o in "--integrator pt-nee" "--integrator bdpt" "--integrator bdpt --connection-candidates 1" "--integrator bdpt --connection-candidates 1 --light-paths 1" "--integrator bdpt --light-paths 0.33 --connection-candidates 16" "--integrator bdpt --light-paths 0.25 --connection-candidates 16"; do
    echo "== bench $o"; timeout -k 5 60 "$N" bench render $CB $o --spp 1024 --warmup 1 --runs 3 2>&1 | grep -vE "^setup"
  done
  for r in 1 2; do
    for o in "--integrator pt-nee" "--integrator bdpt" "--integrator bdpt --light-paths 0.33 --connection-candidates 16" "--integrator bdpt --light-paths 0.25 --connection-candidates 16"; do
      echo "== 1 s $o: $(timeout -k 5 60 "$N" render $CB $o --time 1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$N" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E '^RMSE' | tr '\n' ' ')"
    done
  done
  for o in "" "--light-paths 0.33 --connection-candidates 16" "--light-paths 0.25 --connection-candidates 16"; do
    for s in 1 2; do
      echo "== hidden $o seed $s: $(timeout -k 5 60 "$N" render $HID --integrator bdpt --time 1 --seed $s -o /tmp/h$s.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
    done
    "$N" diff /tmp/h1.exr /tmp/h2.exr --below 1 2>&1 | grep -E "^RMSE"
  done
  ;;
s38f)
  # Session 38: under the new defaults (8 shared candidates, half a light path per pixel on
  # diffuse scenes), whether a seed gives one image (two renders of 64 spp, seed 1, each form:
  # the wavefront form's live-slot lists are filled in the order subgroups reach an atomic, so
  # which slots share a subgroup after a pass's first launch may vary), and BDPT's megakernels
  # against its wavefront form: `bench render` ms per 1024 spp and `render --time 1` against
  # .device/ref.exr on the Cornell box, two rounds.
  N=$PWD/.device/bidir-new
  gunzip -kf .device/bidir-new.gz; chmod +x "$N"
  for w in on off; do
    for k in 1 2; do timeout -k 5 60 "$N" render $CB --integrator bdpt --wavefront $w --spp 64 --seed 1 -o /tmp/d$k.exr > /dev/null 2>&1; done
    echo "== same seed twice, --wavefront $w: $("$N" diff /tmp/d1.exr /tmp/d2.exr 2>&1 | grep -E '^RMSE ')"
  done
  for k in 1 2; do timeout -k 5 60 "$N" render $CB --integrator bdpt --connection-candidates 1 --spp 64 --seed 1 -o /tmp/d$k.exr > /dev/null 2>&1; done
  echo "== same seed twice, wavefront, 1 candidate: $("$N" diff /tmp/d1.exr /tmp/d2.exr 2>&1 | grep -E '^RMSE ')"
  for r in 1 2; do
    for w in on off; do
      echo "== bench --wavefront $w: $(timeout -k 5 60 "$N" bench render $CB --integrator bdpt --wavefront $w --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
      echo "== 1 s --wavefront $w: $(timeout -k 5 60 "$N" render $CB --integrator bdpt --wavefront $w --time 1 -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$N" diff /tmp/q.exr "$REF" 2>&1 | grep -E '^RMSE ')"
    done
  done
  ;;
s38e)
  # Session 38, issue #16's table: pt, pt-nee, bdpt and bdpt:full on the Cornell box (256²,
  # against .device/ref.exr) and the caustic scene (128², against its reference), `bench render`
  # Msamples/s and `render --time 0.1 / 1`, with this commit's build (.device/bidir-new.gz) and
  # bdpt also with f824783's (.device/bidir-head.gz: the uniform draw, one light path per pixel).
  N=$PWD/.device/bidir-new; H=$PWD/.device/bidir-head
  for f in .device/bidir-new.gz .device/bidir-head.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  for run in "$N|pt" "$N|pt-nee" "$H|bdpt" "$N|bdpt" "$N|bdpt:full"; do
    b=${run%%|*}; i=${run#*|}
    for sc in cornell caustic; do
      if [ $sc = cornell ]; then S="$CB"; R="$REF"; else S="$CAU"; R=assets/scenes/caustic/reference.exr; fi
      echo "== $sc $i $(basename $b): $(timeout -k 5 60 "$b" bench render $S --integrator $i --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms \([0-9.]+ Msamples/s\)')"
      for t in 0.1 1; do
        echo "   $t s: $(timeout -k 5 60 "$b" render $S --integrator $i --time $t -o /tmp/q.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$b" diff /tmp/q.exr "$R" 2>&1 | grep -E '^RMSE ')"
      done
    done
  done
  ;;
s38d)
  # Session 38: light paths per pixel with 8 shared candidates where the light hides above a
  # panel (seed pairs 1-2 and 3-4, RMSE between them over every pixel and off the bright
  # region) and on the Cornell box (1 s against .device/ref.exr, two rounds).
  N=$PWD/.device/bidir-new
  gunzip -kf .device/bidir-new.gz; chmod +x "$N"
  for o in "--connection-candidates 1 --light-paths 1" "--light-paths 1" "--light-paths 0.75" "--light-paths 0.5"; do
    for p in "1 2" "3 4"; do
      set -- $p
      for s in $1 $2; do
        echo "== hidden $o seed $s: $(timeout -k 5 60 "$N" render $HID --integrator bdpt --time 1 --seed $s -o /tmp/h$s.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
      done
      "$N" diff /tmp/h$1.exr /tmp/h$2.exr --below 1 2>&1 | grep -E "^RMSE"
    done
  done
  for r in 1 2; do
    for run in "pt-nee|" "bdpt|--light-paths 1" "bdpt|--light-paths 0.75" "bdpt|"; do
      i=${run%%|*}; o=${run#*|}
      echo "== cornell 1 s $i $o: $(timeout -k 5 60 "$N" render $CB --integrator $i --time 1 -o /tmp/q.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
      "$N" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
    done
  done
  ;;
s38c)
  # Session 38, shared candidates (.device/bidir-new.gz: bdpt's default in diffuse scenes is 8
  # candidates and 0.5 light paths per pixel) with fewer light paths per pixel: the
  # Cornell box at 1 s and 0.1 s against .device/ref.exr, two rounds; the hidden light's box
  # (seed pairs, 1 s); `bench render` ms per 1024 spp; a 10 s render against the reference in
  # blocks (bias beside noise).
  N=$PWD/.device/bidir-new
  gunzip -kf .device/bidir-new.gz; chmod +x "$N"
  for r in 1 2; do
    for run in "pt-nee|" "bdpt|--connection-candidates 1 --light-paths 1" "bdpt|" "bdpt|--connection-candidates 16 --light-paths 0.5" "bdpt|--connection-candidates 8 --light-paths 0.33" "bdpt|--connection-candidates 16 --light-paths 0.33" "bdpt|--connection-candidates 16 --light-paths 0.25"; do
      i=${run%%|*}; o=${run#*|}
      for t in 1 0.1; do
        echo "== cornell $t s $i $o: $(timeout -k 5 60 "$N" render $CB --integrator $i --time $t -o /tmp/q.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
        "$N" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
      done
    done
  done
  for o in "--connection-candidates 1 --light-paths 1" "" "--connection-candidates 16 --light-paths 0.5" "--connection-candidates 16 --light-paths 0.33"; do
    for s in 1 2; do
      echo "== hidden $o seed $s: $(timeout -k 5 60 "$N" render $HID --integrator bdpt --time 1 --seed $s -o /tmp/h$s.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
    done
    "$N" diff /tmp/h1.exr /tmp/h2.exr --below 1 2>&1 | grep -E "^RMSE"
  done
  echo "== hidden pt-nee: $(timeout -k 5 60 "$N" render $HID --integrator pt-nee --time 1 --seed 1 -o /tmp/h1.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $(timeout -k 5 60 "$N" render $HID --integrator pt-nee --time 1 --seed 2 -o /tmp/h2.exr 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
  "$N" diff /tmp/h1.exr /tmp/h2.exr --below 1 2>&1 | grep -E "^RMSE"
  for run in "pt-nee|" "bdpt|--connection-candidates 1 --light-paths 1" "bdpt|" "bdpt|--connection-candidates 16 --light-paths 0.33"; do
    i=${run%%|*}; o=${run#*|}
    echo "== bench $i $o: $(timeout -k 5 60 "$N" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 $o 2>&1 | grep -E 'GPU' | head -1)"
  done
  echo "== 10 s, 8 candidates, light paths 0.5"
  timeout -k 5 60 "$N" render $CB --integrator bdpt --time 10 --seed 3 -o /tmp/s10.exr 2>&1 | grep -E "spp in"
  "$N" diff /tmp/s10.exr "$REF" --below 1 --blocks 32 2>&1 | grep -vE "^(relMSE)"
  ;;
s38b)
  # Session 38, shared candidates (.device/bidir-new.gz): the Cornell box at 1 s and 0.1 s
  # against .device/ref.exr with 8 candidates and fewer light paths per pixel; the caustic
  # scene over four more seeds at 1 / 4 / 8 candidates; seed pairs (the variance between
  # them) on Sponza's geometry under sun and sky (2 s) and the rough Cornell box (1 s); then
  # issue #17's traversal figures (one round).
  # Run before the diffuse scenes' defaults changed (7064d96); the options now pin what its
  # rows meant then (the uniform draw and one light path per pixel unless said).
  N=$PWD/.device/bidir-new
  gunzip -kf .device/bidir-new.gz; chmod +x "$N"
  for r in 1 2; do
    for run in "pt-nee|" "bdpt|--connection-candidates 1 --light-paths 1" "bdpt|--connection-candidates 8 --light-paths 1" "bdpt|--connection-candidates 8 --light-paths 0.5" "bdpt|--connection-candidates 8 --light-paths 0.75"; do
      i=${run%%|*}; o=${run#*|}
      for t in 1 0.1; do
        echo "== cornell $t s $i $o: $(timeout -k 5 60 "$N" render $CB --integrator $i --time $t -o /tmp/q.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
        "$N" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
      done
    done
  done
  for s in 3 4 5 6; do
    for o in "" "--connection-candidates 4" "--connection-candidates 8"; do
      echo "== caustic seed $s $o: $(timeout -k 5 60 "$N" render $CAU --integrator bdpt --time 1 --seed $s -o /tmp/c.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$N" diff /tmp/c.exr assets/scenes/caustic/reference.exr 2>&1 | grep -E '^RMSE ')"
    done
  done
  for o in "" "--connection-candidates 8"; do
    for s in 1 2; do
      echo "== sponza $o seed $s: $(timeout -k 5 90 "$N" render $SP --integrator bdpt --time 2 --seed $s -o /tmp/s$s.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s|rror.*')"
      echo "== rough $o seed $s: $(timeout -k 5 60 "$N" render $RC --integrator bdpt --time 1 --seed $s -o /tmp/r$s.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s|rror.*')"
    done
    "$N" diff /tmp/s1.exr /tmp/s2.exr --below 1 2>&1 | grep -E "^RMSE"
    "$N" diff /tmp/r1.exr /tmp/r2.exr --below 1 2>&1 | grep -E "^RMSE"
  done
  sponza_rounds 1 "$N"
  ;;
s38a)
  # Session 38: the resampled connection's candidates shared within the subgroup (one entry read
  # per connecting lane, the candidates by shuffles; .device/bidir-new.gz) against the first
  # design (a 32-byte read per candidate; .device/bidir-head.gz = f824783). `bench render` ms
  # per 1024 spp on the Cornell box (bdpt, vcm) at 1 / 4 / 8 / 16 / 32 candidates, two rounds
  # interleaved; then equal time (1 s) against .device/ref.exr, whole image and off the light's
  # edge, and pt-nee; the hidden light's box (seeds 1, 2) and the caustic scene.
  # Run before the diffuse scenes' defaults changed (7064d96); the options now pin what its
  # rows meant then (the uniform draw and one light path per pixel unless said).
  N=$PWD/.device/bidir-new; H=$PWD/.device/bidir-head
  for f in .device/bidir-new.gz .device/bidir-head.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  for r in 1 2; do
    for n in 1 4 8 16 32; do
      for b in "$H" "$N"; do
        [ "$b" = "$H" ] && [ $n -gt 8 ] && continue
        echo "== $(basename $b) bdpt $n: $(timeout -k 5 60 "$b" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 --connection-candidates $n --light-paths 1 2>&1 | grep -E 'GPU' | head -1)"
      done
    done
  done
  for n in 1 8; do
    for b in "$H" "$N"; do
      echo "== $(basename $b) sponza bdpt $n: $(timeout -k 5 90 "$b" bench render $SP --integrator bdpt --spp 64 --warmup 1 --runs 3 --connection-candidates $n --light-paths 1 2>&1 | grep -E 'GPU' | head -1)"
    done
  done
  for n in 1 4 8; do
    for b in "$H" "$N"; do
      echo "== $(basename $b) vcm $n: $(timeout -k 5 60 "$b" bench render $CB --integrator vcm --spp 256 --warmup 1 --runs 3 --connection-candidates $n --light-paths 1 2>&1 | grep -E 'GPU' | head -1)"
    done
  done
  for r in 1 2; do
    for run in "pt-nee|" "bdpt|--connection-candidates 1 --light-paths 1" "bdpt|--connection-candidates 4 --light-paths 1" "bdpt|--connection-candidates 8 --light-paths 1" "bdpt|--connection-candidates 16 --light-paths 1"; do
      i=${run%%|*}; o=${run#*|}
      echo "== cornell 1 s $i $o: $(timeout -k 5 60 "$N" render $CB --integrator $i --time 1 -o /tmp/q.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
      "$N" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
    done
  done
  for o in "--connection-candidates 1 --light-paths 1" "--connection-candidates 8 --light-paths 1"; do
    for s in 1 2; do
      echo "== hidden $o seed $s: $(timeout -k 5 60 "$N" render $HID --integrator bdpt --time 1 --seed $s -o /tmp/h$s.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
      echo "== caustic $o seed $s: $(timeout -k 5 60 "$N" render $CAU --integrator bdpt --time 1 --seed $s -o /tmp/c$s.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$N" diff /tmp/c$s.exr assets/scenes/caustic/reference.exr 2>&1 | grep -E '^RMSE ')"
    done
    "$N" diff /tmp/h1.exr /tmp/h2.exr --below 1 2>&1 | grep -E "^RMSE"
  done
  ;;
s37g)
  # Session 37 (run as one call beside s37f): Sponza's geometry under sun and sky, 640 x 360,
  # `render --time 2`, and the hidden light's box at seeds 3 and 4, the uniform draw against 4
  # candidates; RMSE between the seeds. In the H100's run the Sponza render with 4 candidates at
  # seed 2 printed no result: this part keeps every message of that render.
  N=$PWD/.device/bidir-new
  gunzip -kf .device/bidir-new.gz; chmod +x "$N"
  for o in "" "--connection-candidates 4"; do
    for s in 1 2; do
      echo "== sponza $o seed $s"; rm -f /tmp/s$s.exr
      timeout -k 5 90 "$N" render $SP --integrator bdpt --time 2 --seed $s -o /tmp/s$s.exr $o 2>&1 | grep -v "not found"; echo "rc=${PIPESTATUS[0]}"
    done
    "$N" diff /tmp/s1.exr /tmp/s2.exr 2>&1 | grep -E "^RMSE"
    for s in 3 4; do
      echo "== hidden $o seed $s: $(timeout -k 5 60 "$N" render $HID --integrator bdpt --time 1 --seed $s -o /tmp/h$s.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
    done
    "$N" diff /tmp/h3.exr /tmp/h4.exr --below 1 2>&1 | grep -E "^RMSE"
  done
  ;;
s37f)
  # Session 37: the caustic scene at equal time, 4 resampled candidates against the uniform
  # draw, seeds 3 to 6 (1 s, 128², RMSE against its reference), with the committed build.
  N=$PWD/.device/bidir-new
  gunzip -kf .device/bidir-new.gz; chmod +x "$N"
  for s in 3 4 5 6; do
    for o in "" "--connection-candidates 4"; do
      echo "== caustic seed $s $o: $(timeout -k 5 60 "$N" render $CAU --integrator bdpt --time 1 --seed $s -o /tmp/c.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s') $("$N" diff /tmp/c.exr assets/scenes/caustic/reference.exr 2>&1 | grep -E '^RMSE ')"
    done
  done
  ;;
s37e)
  # Session 37, the committed build (.device/bidir-new.gz): equal time with 4 resampled
  # candidates against the uniform draw (the default) and pt-nee: the Cornell box 1 s against
  # .device/ref.exr, two rounds; the hidden light's box and the caustic scene, seeds 1 and 2
  # (RMSE between them; the caustic scene also against its reference).
  N=$PWD/.device/bidir-new
  gunzip -kf .device/bidir-new.gz; chmod +x "$N"
  for r in 1 2; do
    for run in "bdpt|" "bdpt|--connection-candidates 4" "pt-nee|"; do
      i=${run%%|*}; o=${run#*|}
      echo "== cornell $i $o: $(timeout -k 5 60 "$N" render $CB --integrator $i --time 1 -o /tmp/q.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
      "$N" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
    done
  done
  for o in "" "--connection-candidates 4"; do
    for s in 1 2; do
      echo "== hidden $o seed $s: $(timeout -k 5 60 "$N" render $HID --integrator bdpt --time 1 --seed $s -o /tmp/h$s.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
      echo "== caustic $o seed $s: $(timeout -k 5 60 "$N" render $CAU --integrator bdpt --time 1 --seed $s -o /tmp/c$s.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
      "$N" diff /tmp/c$s.exr assets/scenes/caustic/reference.exr 2>&1 | grep -E "^RMSE "
    done
    "$N" diff /tmp/h1.exr /tmp/h2.exr --below 1 2>&1 | grep -E "^RMSE"
    "$N" diff /tmp/c1.exr /tmp/c2.exr 2>&1 | grep -E "^RMSE "
  done
  ;;
s37d)
  # Session 37: a light vertex cache entry carrying its path's seen / stored beside the slot
  # (.device/bidir-new.gz, this commit), so a connection reads the entry and the vertex and not
  # the path's counts; against .device/bidir.gz (ff286b1) and, with 4 candidates, the
  # measurement build (.device/bidir-exp.gz, BIDIR_EXP_RIS=4). ms per 1024 spp (Cornell box,
  # the hidden light's box, vcm) and per 64 spp (Sponza's geometry, sun and sky), two rounds
  # interleaved; then `render --time 1` against .device/ref.exr.
  N=$PWD/.device/bidir-new; E=$PWD/.device/bidir-exp
  for f in .device/bidir.gz .device/bidir-new.gz .device/bidir-exp.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  g() { grep -oE 'GPU [0-9.]+ ms'; }
  for r in 1 2; do
    for run in "$B|" "$N|" "$N|--connection-candidates 2" "$N|--connection-candidates 4" "$E|RIS4"; do
      b=${run%%|*}; o=${run#*|}; e=""
      [ "$o" = RIS4 ] && { o=""; e="BIDIR_EXP_RIS=4"; }
      echo "== $(basename "$b") $o $e: cornell $(env $e timeout -k 5 60 "$b" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 $o 2>&1 | g) hidden $(env $e timeout -k 5 60 "$b" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 $o 2>&1 | g) vcm $(env $e timeout -k 5 60 "$b" bench render $CB --integrator vcm --spp 1024 --warmup 1 --runs 3 $o 2>&1 | g) sponza $(env $e timeout -k 5 90 "$b" bench render $SP --integrator bdpt --spp 64 --warmup 1 --runs 3 $o 2>&1 | g)"
    done
  done
  for run in "$B|" "$N|" "$N|--connection-candidates 2" "$B|" "$N|" "$N|--connection-candidates 2"; do
    b=${run%%|*}; o=${run#*|}
    echo "== $(basename "$b") $o: $(timeout -k 5 60 "$b" render $CB --integrator bdpt --time 1 -o /tmp/q.exr $o 2>&1 | grep -oE '[0-9]+ spp in [0-9.]+ s')"
    "$b" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
  done
  ;;
s37c)
  # Session 37, the same measurement build (.device/bidir-exp.gz): the resampled connection's
  # loads reordered, BIDIR_EXP_PREFETCH 1 (every candidate's index read first), 2 (and each
  # next vertex loaded before the current one is evaluated); the same images as 0. ms per
  # 1024 spp (Cornell box) and per 64 spp (Sponza's geometry under sun and sky).
  E=$PWD/.device/bidir-exp
  gunzip -kf .device/bidir-exp.gz; chmod +x "$E"
  for r in 1 2; do
    for m in 1 2 4; do
      for p in 0 1 2; do
        [ "$m" = 1 ] && [ "$p" != 0 ] && continue
        echo "== RIS $m prefetch $p: cornell $(BIDIR_EXP_RIS=$m BIDIR_EXP_PREFETCH=$p timeout -k 5 60 "$E" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
      done
    done
  done
  for m in 1 4; do
    for p in 0 2; do
      [ "$m" = 1 ] && [ "$p" != 0 ] && continue
      echo "== RIS $m prefetch $p: sponza $(BIDIR_EXP_RIS=$m BIDIR_EXP_PREFETCH=$p timeout -k 5 90 "$E" bench render $SP --integrator bdpt --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  ;;
s37b)
  # Session 37, a measurement build (.device/bidir-exp.gz, not committed): the light vertex
  # cache's connection resampled (RIS) from BIDIR_EXP_RIS uniform candidates by their
  # unshadowed contribution (1: the committed uniform draw). Cornell box: `bench render` ms per
  # 1024 spp, `render --time 1` against .device/ref.exr (whole, off the light's ring); the box
  # whose light hides above a panel: 1 s, seeds 1 and 2; the caustic scene 128² 1 s against its
  # reference; Sponza's geometry under sun and sky (glossy: 96-byte vertices), ms per 64 spp.
  E=$PWD/.device/bidir-exp
  gunzip -kf .device/bidir-exp.gz; chmod +x "$E"
  for r in 1 2; do
    for m in 1 2 4 8; do
      export BIDIR_EXP_RIS=$m
      echo "== RIS $m cornell: $(timeout -k 5 60 "$E" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
      timeout -k 5 60 "$E" render $CB --integrator bdpt --time 1 -o /tmp/q.exr 2>&1 | grep -E "spp in"
      "$E" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
    done
  done
  for m in 1 4; do
    export BIDIR_EXP_RIS=$m
    echo "== RIS $m hidden: $(timeout -k 5 60 "$E" bench render $HID --integrator bdpt --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    for s in 1 2; do timeout -k 5 60 "$E" render $HID --integrator bdpt --time 1 --seed $s -o /tmp/h$s.exr 2>&1 | grep -E "spp in"; done
    "$E" diff /tmp/h1.exr /tmp/h2.exr --below 1 2>&1 | grep -E "^RMSE"
    echo "== RIS $m caustic"
    timeout -k 5 60 "$E" render $CAU --integrator bdpt --time 1 -o /tmp/c.exr 2>&1 | grep -E "spp in"
    "$E" diff /tmp/c.exr assets/scenes/caustic/reference.exr 2>&1 | grep -E "^RMSE"
    echo "== RIS $m sponza: $(timeout -k 5 90 "$E" bench render $SP --integrator bdpt --spp 64 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    echo "== RIS $m cornell vcm: $(timeout -k 5 60 "$E" bench render $CB --integrator vcm --spp 1024 --warmup 1 --runs 3 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    timeout -k 5 60 "$E" render $CB --integrator vcm --time 1 -o /tmp/q.exr 2>&1 | grep -E "spp in"
    "$E" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
  done
  unset BIDIR_EXP_RIS
  ;;
s37a)
  # Session 37, issue #16's equal-time error split at the light's edge: bdpt (the balance
  # heuristic on the diffuse box, session 36) against `--mis power` and pt-nee, `bench render`
  # ms per 1024 spp, `render --time 0.1` and `--time 1` against .device/ref.exr, over the whole
  # image and off the light's ring (`diff --below 1`: pixels over 1.0 and two around them
  # masked), two rounds interleaved; then bdpt's light paths per pixel under the balance heuristic.
  for f in .device/bidir.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  for r in 1 2; do
    for run in "bdpt|" "bdpt|--mis power" "pt-nee|"; do
      i=${run%%|*}; o=${run#*|}
      echo "== $i $o"; timeout -k 5 60 "$B" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 $o 2>&1 | grep -E "GPU"
      for t in 0.1 1; do
        timeout -k 5 60 "$B" render $CB --integrator $i --time $t -o /tmp/q.exr $o 2>&1 | grep -E "spp in"
        "$B" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
      done
    done
  done
  # Bias beside noise: a second seed's 1 s render (the seed-to-seed RMSE^2 / 2 is the
  # variance), and 10 s renders against the reference (noise alone would fall ~10x in MSE).
  for i in bdpt pt-nee; do
    echo "== $i seeds 1 and 2, 1 s; then 10 s"
    timeout -k 5 60 "$B" render $CB --integrator $i --time 1 --seed 1 -o /tmp/s1.exr 2>&1 | grep -E "spp in"
    timeout -k 5 60 "$B" render $CB --integrator $i --time 1 --seed 2 -o /tmp/s2.exr 2>&1 | grep -E "spp in"
    "$B" diff /tmp/s1.exr /tmp/s2.exr --below 1 2>&1 | grep -E "^RMSE"
    "$B" diff /tmp/s1.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
    timeout -k 5 60 "$B" render $CB --integrator $i --time 10 --seed 3 -o /tmp/s10.exr 2>&1 | grep -E "spp in"
    "$B" diff /tmp/s10.exr "$REF" --below 1 --blocks 32 2>&1 | grep -vE "^(relMSE|mean)"
  done
  for l in 0.5 2; do
    echo "== bdpt --light-paths $l"
    timeout -k 5 60 "$B" render $CB --integrator bdpt --time 1 --light-paths $l -o /tmp/q.exr 2>&1 | grep -E "spp in"
    "$B" diff /tmp/q.exr "$REF" --below 1 2>&1 | grep -E "^RMSE"
  done
  ;;
s36c)
  # Session 36, BDPT's MIS heuristic (the balance heuristic by default in scenes with only
  # diffuse surfaces since this commit; lavapipe: 6-8 % less variance off the Cornell box's
  # light edge at equal cost): `bench render` ms per 1024 spp and `render --time 1` against
  # .device/ref.exr, the default against `--mis power`, and pt-nee, two rounds interleaved.
  for f in .device/bidir.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  for r in 1 2; do
    for run in "bdpt|" "bdpt|--mis power" "pt-nee|"; do
      i=${run%%|*}; o=${run#*|}
      echo "== $i $o"; timeout -k 5 60 "$B" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 $o 2>&1 | grep -E "GPU"
      timeout -k 5 60 "$B" render $CB --integrator $i --time 1 -o /tmp/q.exr $o 2>&1 | grep -E "spp in"
      "$B" diff /tmp/q.exr "$REF" 2>&1 | head -1
    done
  done
  ;;
s36b)
  # Session 36, after the binary and compressed wide BVHs went to build quality 4 on GPUs
  # (.device/bidir.gz; .device/bidir-base.gz is fb05dc5, quality 2): BDPT's two forms on the
  # plain Cornell box (the H100 put the megakernels 12 % ahead of the wavefront form, the H200
  # had them 7 % behind in session 27), pt-nee, three rounds of `bench render`; then issue #16's
  # equal-time table, `render --time 1` and pt-nee's 0.1 s, RMSE against .device/ref.exr.
  # .device/bidir-exp.gz: a measurement build whose wavefront BDPT kernels neither load nor
  # store the path state's sigma/seed word where the scene has no volume or alpha (16 of 80 and
  # of 96 bytes a launch).
  for f in .device/bidir.gz .device/bidir-base.gz .device/bidir-exp.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  X=$PWD/.device/bidir-exp
  for r in 1 2 3; do
    for run in "$B|pt-nee|" "$B|bdpt|" "$X|bdpt|" "$B|bdpt|--wavefront off" "$BASE|bdpt|--wavefront off"; do
      b=${run%%|*}; rest=${run#*|}; i=${rest%%|*}; o=${rest#*|}
      echo "== $i $(basename $b) $o"; timeout -k 5 60 "$b" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 $o 2>&1 | grep -E "GPU"
    done
  done
  for r in 1 2; do
    for run in "pt-nee|--time 0.1" "pt-nee|--time 1" "bdpt|--time 1" "bdpt|--time 1 --wavefront off"; do
      i=${run%%|*}; o=${run#*|}
      echo "== $i $o"; timeout -k 5 60 "$B" render $CB --integrator $i -o /tmp/q.exr $o 2>&1 | grep -E "spp in"
      "$B" diff /tmp/q.exr "$REF" 2>&1 | head -1
    done
  done
  SPB="$PWD/.device/scenes/sponza/Sponza.gltf --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for r in 1 2; do
    for b in "$B" "$X"; do
      echo "== sponza bdpt $(basename $b)"; timeout -k 5 60 "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "GPU"
    done
  done
  # Issue #17's diffuse rays (2.482-2.494 Grays/s with --refill 24 in s34a): the quality-5
  # tree's leaf size, 3 (the default) against 2 and 4, two rounds interleaved.
  mkdir -p ../shared/scenes && ln -sfn $PWD/.device/scenes/sponza ../shared/scenes/sponza
  for r in 1 2; do
    for l in 3 2 4; do
      echo "== sponza leaf $l --refill 24"; timeout -k 5 60 "$B" bench traversal "$PWD/.device/scenes/sponza/Sponza.gltf" --camera CameraMain --bvh bvh4 --leaf-size $l --quality 5 --refill 24 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  ;;
s36a)
  # Session 36. (1) s35a found the compressed wide BVH at build quality 4 7 % faster for pt-nee
  # and pt on the Cornell box, and the binary BVH at 4 15 % faster for pt-nee on the caustic
  # scene: which quality and leaf size to make the GPUs' default (HEAD, `bench render` ms per
  # 1024 spp, two rounds interleaved). (2) BDPT's 4-wide BVH on the Cornell box at quality 5
  # and other leaf sizes, and its megakernels over the compressed wide BVH at quality 4.
  # (3) Issue #16's equal-time table at quality 4: `render --time 1`, RMSE against .device/ref.exr
  # to three digits (`bidir diff`).
  for f in .device/bidir.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  CA="$PWD/.device/scenes/caustic/caustic.obj"
  for r in 1 2; do
    for o in "" "--bvh-quality 3" "--bvh-quality 4" "--bvh-quality 4 --bvh-leaf-size 2"; do
      for i in pt-nee pt; do
        echo "== $i: $o"; timeout -k 5 60 "$B" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 $o 2>&1 | grep -E "GPU"
      done
    done
    for o in "" "--bvh-quality 3" "--bvh-quality 4" "--bvh-quality 4 --bvh-leaf-size 2" "--bvh-quality 4 --bvh-leaf-size 8"; do
      echo "== caustic pt-nee: $o"; timeout -k 5 60 "$B" bench render "$CA" --width 128 --height 128 --integrator pt-nee --spp 1024 --warmup 1 --runs 3 $o 2>&1 | grep -E "GPU"
    done
    for o in "" "--bvh-quality 5" "--bvh-leaf-size 2" "--bvh-leaf-size 4" "--wavefront off" "--wavefront off --bvh cwbvh --bvh-quality 4"; do
      echo "== bdpt: $o"; timeout -k 5 60 "$B" bench render $CB --integrator bdpt --spp 1024 --warmup 1 --runs 3 $o 2>&1 | grep -vE "^setup|^kernel "
    done
  done
  for run in "pt-nee|" "pt-nee|--bvh-quality 4" "bdpt|" "bdpt|--bvh-quality 5" "pt-nee|--bvh-quality 4" "bdpt|"; do
    i=${run%%|*}; o=${run#*|}
    echo "== $i 1 s: $o"; timeout -k 5 60 "$B" render $CB --integrator $i --time 1 -o /tmp/q.exr $o 2>&1 | grep -E "spp in"
    "$B" diff /tmp/q.exr "$REF" 2>&1 | head -1
  done
  ;;
s35a)
  # Session 35, two questions (no device was lent that session). (1) The megakernel path
  # tracer's three loop forms are a module each since 0d0ba13 (pt.comp, pt_loop.comp,
  # pt_queue.comp; lavapipe's pipeline for pt-nee 0.44 -> 0.13 s of setup, the same images):
  # does the H200's code run as before? HEAD (.device/bidir.gz) against .device/bidir-pre35.gz
  # (a build of 2b2e99d, the GPU kernels of ee766f1), `bench render` ms per 1024 spp, three
  # rounds interleaved (with each kernel's pipeline build time, which `bench render` prints since
  # 16b50e7; the pre35 build prints none): pt-nee (the queue's module, over cwbvh) and pt (regeneration) on the
  # Cornell box, pt-nee on the caustic scene (glass: no regeneration, pt_loop), and bdpt there
  # (its steps' mirror and glass scattering is one function since 4b55b94); then the setup
  # and samples of `render --time 0.1`. (2) The compressed wide BVH's build quality, which CPU
  # devices take at 4 since 2b2e99d (lavapipe: the Cornell box 7-9 % faster): HEAD at quality
  # 2 (the GPU default) and 4, the same commands. Keep 4 on GPUs too if it is ahead in both.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  P=${PRE35:-$PWD/.device/bidir-pre35}
  CA="$PWD/.device/scenes/caustic/caustic.obj"
  for r in 1 2 3; do
    for run in "$P|" "$B|" "$B|--bvh-quality 4"; do
      b=${run%%|*}; o=${run#*|}
      for i in pt-nee pt; do
        echo "== $i: $(basename "$b") $o"; timeout -k 5 60 "$b" bench render $CB --integrator $i --spp 1024 --warmup 1 --runs 3 $o 2>&1 | grep -E "GPU|^pt|^setup"
      done
      for i in pt-nee bdpt; do
        echo "== caustic $i: $(basename "$b") $o"; timeout -k 5 60 "$b" bench render "$CA" --width 128 --height 128 --integrator $i --spp 1024 --warmup 1 --runs 3 $o 2>&1 | grep -E "GPU|^pt|^bdpt|^setup"
      done
    done
  done
  for t in 0.1 1; do
    for run in "$P|" "$B|" "$B|--bvh-quality 4" "$P|" "$B|" "$B|--bvh-quality 4"; do
      b=${run%%|*}; o=${run#*|}
      echo "== pt-nee $t s: $(basename "$b") $o"; timeout -k 5 60 "$b" render $CB --integrator pt-nee --time $t --reference "$REF" -o /tmp/q.exr $o 2>&1 | grep -E "spp in|RMSE"
    done
  done
  ;;
s34a)
  # Session 34 (no device that session; prepared for the next): the 4-wide step's far planes
  # with the exit's widening folded into their slab terms (scripts/device/s34a.patch, a
  # measurement build, .device/bidir-fold.gz; four multiplies a node step fewer, three
  # registers more), its hit-for-hit tests under the validation layers (.device/test-traversal.gz,
  # built with the patch), then HEAD (.device/bidir), s33d's build (.device/bidir-exp.gz: the fma()
  # shear with the distance as before) and the fold, CameraMain quality 5, lockstep and
  # --refill 24, two runs interleaved; the integrators on Sponza, HEAD against the fold.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  mkdir -p ../shared/scenes && ln -sfn $PWD/.device/scenes/sponza ../shared/scenes/sponza
  echo "== tests (fold)"; BIDIR_VALIDATION=1 timeout -k 5 200 .device/test-traversal 2>&1 | grep -E "^test |result|panicked|VUID|sponza \[" | head -40
  sponza_rounds 2 "$B" "$PWD/.device/bidir-exp" "$PWD/.device/bidir-fold"
  SPB="$PWD/.device/scenes/sponza/Sponza.gltf --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for i in pt-nee bdpt; do
    for b in "$B" "$PWD/.device/bidir-fold"; do
      echo "== sponza $i $(basename $b)"; timeout -k 5 60 "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s34b)
  # Session 34: s34a's three builds again in another start of the machine (code layout moves
  # primary rays ~1 % between starts) and a fourth with both patches (.device/bidir-both.gz:
  # s33d.patch and s34a.patch applied together; its hit-for-hit tests pass on lavapipe), two
  # runs interleaved, and the fold's machine code (nvcache-bidir-fold.tgz).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  sponza_rounds 2 "$PWD/.device/bidir-fold" "$PWD/.device/bidir-both" "$PWD/.device/bidir-exp" "$B"
  shader_cache "$PWD/.device/bidir-fold" nvcache-bidir-fold.tgz
  ;;
s33d)
  # Session 33 (not run: no device time left): the fma() shear with the distance as before
  # (scripts/device/s33d.patch, a measurement build, .device/bidir-exp.gz: git apply, build,
  # strip, gzip, revert; level with d0dafcc on lavapipe, where the committed distance costs bvh4
  # primary rays 8-10 %) against the committed build and .device/bidir-base (3a677c3's code),
  # CameraMain quality 5, lockstep and --refill 24, three runs interleaved. If it keeps the
  # committed form's lockstep primary figure (6.01-6.03 in s33c), take it.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  for r in 1 2 3; do
    for c in "" "--refill 24"; do
      for b in "$BASE" "$B" "$PWD/.device/bidir-exp"; do
        echo "== $(basename $b) $c"; sponza_q5 "$b" $c
      done
    done
  done
  ;;
s33c)
  # Session 33: s33b's committed build (the shear's slopes stored negated) was level with
  # the base on primary rays where s33a's measurement build (negated in the loop) had been 1 %
  # ahead: the three builds interleaved, lockstep, three runs, and the machine code of the two
  # new ones (nvcache-bidir.tgz, nvcache-bidir-exp.tgz). .device/bidir-exp = this commit with the
  # negations in the loop.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  for r in 1 2 3; do
    for b in "$BASE" "$B" "$PWD/.device/bidir-exp"; do
      echo "== $(basename $b)"; sponza_q5 "$b"
    done
  done
  for b in "$B" "$PWD/.device/bidir-exp"; do shader_cache "$b" "nvcache-$(basename $b).tgz"; done
  ;;
s33b)
  # Session 33, the committed build (.device/bidir; .device/bidir-base = 3a677c3's code): the
  # hit-for-hit tests and the fma probe on the H200 (.device/test-*.gz, this commit's test
  # binaries, under the validation layers; Sponza's from .device/scenes/sponza); CameraMain
  # quality 5, lockstep and --refill 24, three runs interleaved; the integrators on Sponza and
  # the Cornell box.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  mkdir -p ../shared/scenes && ln -sfn $PWD/.device/scenes/sponza ../shared/scenes/sponza
  echo "== tests"; BIDIR_VALIDATION=1 timeout -k 5 60 .device/test-sampling precise 2>&1 | grep -E "^test |result|device's|VUID" 
  BIDIR_VALIDATION=1 timeout -k 5 200 .device/test-traversal 2>&1 | grep -E "^test |result|panicked|VUID|sponza \[" | head -40
  T="timeout -k 5 60"
  for r in 1 2 3; do
    for c in "" "--refill 24"; do
      for b in "$BASE" "$B"; do
        echo "== $(basename $b) $c"; sponza_q5 "$b" $c
      done
    done
  done
  SPB="$PWD/.device/scenes/sponza/Sponza.gltf --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for i in pt-nee bdpt; do
    for b in "$BASE" "$B"; do
      echo "== sponza $i $(basename $b)"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      echo "== cornell $i $(basename $b)"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s33a)
  # Session 33: the watertight triangle test with its shear and its distance as fused
  # multiply-adds (a measurement build, .device/bidir-exp.gz: glsl/common/intersect.glsl's
  # ax..cy as fma(-s, a_kz, a_kx), t as fma(u, a_kz, fma(v, b_kz, w c_kz)) s_z / det), against
  # the committed build, CameraMain quality 5, lockstep and --refill 24, three runs interleaved;
  # then the measurement build's machine code (nvcache-fma.tgz).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  for r in 1 2 3; do
    for c in "" "--refill 24"; do
      for b in "$B" "$PWD/.device/bidir-exp"; do
        echo "== $(basename $b) $c"; sponza_q5 "$b" $c
      done
    done
  done
  shader_cache "$PWD/.device/bidir-exp" nvcache-fma.tgz
  ;;
s32d)
  # Session 32 (run in session 33: no machine could be started in session 32; a measurement
  # build, .device/bidir-exp.gz, from scripts/device/s32d.patch): what the ~66 us a
  # 1920 x 1080 launch costs beyond its rays is (s32c: 960 x 540 0.137 ms, 1080p 0.348, 4K
  # 1.195). BIDIR_EXP_TWICE: w = an untimed launch of the same rays just before the timed one
  # (the tree warm in L2), c = two launches timed without a barrier between them (the second's
  # start fills the first's end), s = two launches with the barrier. CameraMain quality 5,
  # lockstep, two runs. Then BIDIR_EXP_NT=1: the trace kernels' ray loads
  # and hit stores marked Nontemporal in their SPIR-V (streamed past L2, if the driver
  # honours it), two runs, and their machine code (nvcache-nt.tgz).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  X=$PWD/.device/bidir-exp
  T="timeout -k 5 60"
  Q="--camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5"
  for r in 1 2; do
    for e in "" w c s; do
      echo "== lockstep twice=$e"; BIDIR_EXP_TWICE=$e $T "$X" bench traversal "$SP" $Q 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  for r in 1 2; do
    for c in "" "--refill 24"; do
      echo "== nontemporal rays and hits $c"; BIDIR_EXP_NT=1 $T "$X" bench traversal "$SP" $Q $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  BIDIR_EXP_NT=1 __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$X" bench traversal --bvh bvh4 --leaf-size 3 --reps 5 --warmup 0 > /dev/null 2>&1
  tar czf "$OUT/nvcache-nt.tgz" -C $D .
  ;;
s32c)
  # Session 32: launch settings around issue #17's figures, CameraMain quality 5, two runs
  # interleaved: diffuse rays with dynamic fetch at refill counts 16-30 and with as many
  # persistent workgroups as can be resident (132 x 36 warps / 2 = 2,376) or twice that,
  # against the default 4,224; primary rays with two rays per invocation in the lockstep kernel, and at 4 and 1/4 the
  # pixels (what a launch's start and end cost).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 60"
  Q="--camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5"
  for r in 1 2; do
    for c in "--refill 24" "--refill 16" "--refill 20" "--refill 26" "--refill 30" "--refill 24 --persistent-groups 2376" "--refill 24 --persistent-groups 4752"; do
      echo "== diffuse $c"; $T "$B" bench traversal "$SP" $Q --rays diffuse $c 2>&1 | grep -E "^diffuse "
    done
    for c in "" "--rays-per-invocation 2" "--width 3840 --height 2160" "--width 960 --height 540"; do
      echo "== primary lockstep $c"; $T "$B" bench traversal "$SP" $Q --rays primary $c 2>&1 | grep -E "^primary "
    done
  done
  ;;
s32b)
  # Session 32 (a measurement build, .device/bidir-exp.gz, not committed: BIDIR_EXP_LAYOUT
  # permutes the 4-wide node's 16-byte slots at upload and the kernels read them through a
  # flat vec4 view: 0 as now [xlo xhi ylo yhi zlo zhi C R], 1 [xlo xhi ylo yhi zlo C zhi R],
  # 2 [xlo C xhi ylo yhi zlo zhi R]): the compiler issues the children's load after the planes
  # have come back, and in the committed layout they sit in a 32-byte sector of their own, a
  # second trip to L2 in each node step; with 1 or 2 a plane load fetches their sector too.
  # CameraMain quality 5, lockstep and --refill 24, the committed build as control, two runs
  # interleaved; then the machine code of layouts 1 and 2 (nvcache-1.tgz, nvcache-2.tgz).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  X=$PWD/.device/bidir-exp
  T="timeout -k 5 60"
  for r in 1 2; do
    for c in "" "--refill 24"; do
      echo "== committed $c"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
      for l in 0 1 2; do
        echo "== layout $l $c"; BIDIR_EXP_LAYOUT=$l $T "$X" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
      done
    done
  done
  for l in 1 2; do
    D=/tmp/nvcache-$l; rm -rf $D; mkdir -p $D
    for c in "" "--refill 24"; do
      BIDIR_EXP_LAYOUT=$l __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$X" bench traversal --bvh bvh4 --leaf-size 3 $c --reps 5 --warmup 0 > /dev/null 2>&1
    done
    tar czf "$OUT/nvcache-$l.tgz" -C $D .
  done
  ;;
s32a)
  # Session 32: the machine code of the 4-wide trace kernels as the driver compiles them now
  # (one ray per invocation in lockstep, trace_bvh4_lockstep.comp; dynamic fetch at --refill
  # 24, trace_bvh4.comp): the shader disk cache comes back as $OUT/nvcache.tgz for
  # scripts/device/sass.py; then part s31a.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  for c in "" "--refill 24"; do
    __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 timeout -k 5 120 "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 4 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
  done
  tar czf "$OUT/nvcache.tgz" -C $D .
  bash "$0" s31a
  ;;
s31b)
  # Session 31 (not yet run): alias-table cells from the high word of a 32-bit product
  # (index_below) against the 24-bit float before (.device/bidir-base, b7eee84), which never
  # draws half the cells of an 8192 x 4096 map: a white plane (albedo 0.8) under a smooth sky
  # of that size (radiance 0.05 + 0.05 cos theta, .device/scenes/env8k, made by
  # scripts/device/make_env8k.py), seen from above; its radiance is 0.8 / pi x 0.2618 = 0.066667
  # (const.exr), so `mean ratio` is the bias. pt (BSDF sampling only) as the control.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  E=.device/scenes/env8k
  T="timeout -k 5 120"
  for b in "$B" "$BASE"; do
    for i in pt-nee pt bdpt; do
      echo "== env8k $i $(basename $b)"; $T "$b" render $E/plane.obj --env $E/sky8k-smooth.exr --eye 0,2,0.01 --target 0,0,0 --fov 30 --width 128 --height 128 --integrator $i --spp 256 --reference $E/const.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse|error"
    done
  done
  ;;
s31a)
  # Session 31 (not yet run: no machine was lent): each sampling decision in a group of Sobol'
  # dimensions of its own, Sobol' for the pixel and the first vertex (rng_start_group,
  # rng_start_vertex) against the build before it (.device/bidir-base, b7eee84: the first 8
  # dimensions, no groups), interleaved, one run each: issue #16's Cornell table
  # (time-budgeted renders against the sharper reference, the caustic scene at the test's
  # camera, `bench render` rates). On the Cornell box as many Sobol' points or fewer are
  # computed (pt-nee 7 against 8, bdpt's camera path 8, its light path 7 against 8), so the
  # rates should stay level and the errors follow the variance per sample measured on
  # lavapipe (docs/results.md, "A group of Sobol' dimensions per sampling decision").
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  T="timeout -k 5 60"
  for t in 0.1 1; do
    for i in pt pt-nee bdpt; do
      for b in "$B" "$BASE"; do
        echo "== cornell $i --time $t $(basename $b)"; $T "$b" render $CB --integrator $i --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
        echo "== caustic $i --time $t $(basename $b)"; $T "$b" render $CAU --width 128 --height 128 --integrator $i --time $t --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      done
    done
  done
  for i in pt pt-nee bdpt; do
    for b in "$B" "$BASE"; do
      echo "== cornell $i $(basename $b)"; $T "$b" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
    done
  done
  ;;
s30e)
  # Session 30 (not run: no machine was lent after s30d): the leaf phase's triangle tests
  # shared among the subgroup's lanes (`--share-leaves`, trace_bvh4_share.comp) against the
  # lockstep kernel and dynamic fetch without it, CameraMain quality 5, one ray per invocation,
  # --refill 24 and 28, two runs interleaved; the shader cache comes back
  # (scripts/device/sass.py: registers, the instructions of a round).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 60"
  for r in 1 2; do
    for c in "" "--refill 24" "--refill 28"; do
      for e in "" --share-leaves; do
        echo "== CameraMain quality 5 $c $e"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c $e 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
      done
    done
  done
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  for c in "" "--refill 24"; do
    __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$B" bench traversal --bvh bvh4 --leaf-size 3 $c --share-leaves 2>&1 | grep -E "Register"
  done
  tar czf "$OUT/nvcache.tgz" -C $D .
  ;;
s30d)
  # Session 30: the committed build (.device/bidir, 86b2dfe) against s30a's measurement build
  # with its bits off (.device/bidir-exp, BIDIR_EXP_BITS=0), which gave primary rays 6.01-6.03
  # in two other starts: CameraMain quality 5, lockstep, three runs interleaved; each build's
  # shader cache comes back (nvcache-B.tgz, nvcache-exp.tgz) for scripts/device/sass.py.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 60"
  for r in 1 2 3; do
    for b in "$B" .device/bidir-exp; do
      echo "== CameraMain quality 5 $(basename $b)"; $T "$b" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
    done
  done
  for b in "$B" .device/bidir-exp; do
    D=/tmp/nvcache-$(basename $b); rm -rf $D; mkdir -p $D
    __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$b" bench traversal --bvh bvh4 --leaf-size 3 2>&1 | grep -E "Register"
    tar czf "$OUT/nvcache-$(basename $b).tgz" -C $D .
  done
  ;;
s30c)
  # Session 30: the committed build (86b2dfe) for issue #17's figures in this session's machine
  # start: CameraMain quality 5, lockstep and `--refill 24`, three runs interleaved, diffuse
  # rays at `--refill 28` once.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 60"
  for r in 1 2 3; do
    for c in "" "--refill 24"; do
      echo "== CameraMain quality 5 $c"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
    done
  done
  echo "== CameraMain quality 5 --refill 28"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 --refill 28 --rays diffuse 2>&1 | grep -E "^(primary|shadow|diffuse) "
  ;;
s30b)
  # Session 30: measurement builds, not committed: .device/bidir-exp logs each buffer's
  # alignment and offset (BIDIR_EXP_ALIGN_LOG) and aligns every buffer to 256 bytes
  # (BIDIR_EXP_ALIGN); .device/bidir-expr the same with the node and triangle buffers
  # declared `restrict readonly`. CameraMain quality 5, two runs interleaved; the shader cache
  # of bidir-expr comes back as $OUT/nvcache.tgz (scripts/device/sass.py).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 60"
  BIDIR_EXP_ALIGN_LOG=1 $T .device/bidir-exp bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 --rays primary --reps 5 --warmup 0 2>&1 | grep -E "EXP buffer '(bvh|bench)"
  for r in 1 2; do
    for c in "" "--refill 24"; do
      for x in exp expr; do
        for a in "" BIDIR_EXP_ALIGN=1; do
          echo "== CameraMain $c $x $a"; $T env $a .device/bidir-$x bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
        done
      done
    done
  done
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  for c in "" "--refill 24"; do
    __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T .device/bidir-expr bench traversal --bvh bvh4 --leaf-size 3 $c 2>&1 | grep -E "Register"
  done
  tar czf "$OUT/nvcache.tgz" -C $D .
  ;;
s30a)
  # Session 30: a measurement build (.device/bidir-exp, BIDIR_EXP_BITS, not committed) of the
  # lockstep kernel: bit 1 keeps the rest of the prepared ray (tmin, shear, axes) in shared
  # memory beside the origin, bit 2 the hit's triangle and barycentrics; bit 8 runs dynamic
  # fetch in that kernel (the origin in shared memory there too). CameraMain quality 5.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  X=$PWD/.device/bidir-exp
  T="timeout -k 5 60"
  for r in 1 2; do
    for e in 0 1 2 3; do
      echo "== CameraMain lockstep BIDIR_EXP_BITS=$e"; $T env BIDIR_EXP_BITS=$e "$X" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
    done
  done
  for e in 0 8 9 11; do
    echo "== CameraMain --refill 24 BIDIR_EXP_BITS=$e"; $T env BIDIR_EXP_BITS=$e "$X" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 --refill 24 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
  done
  ;;
s29j)
  # Session 29: the 4-wide lockstep kernel with the origin in shared memory and one leaf loop
  # for every ray (trace_bvh4_lockstep.comp) against .device/bidir-prev (3c1fc4e): CameraMain
  # quality 5, two runs interleaved, the other cameras once, dynamic fetch once (its kernel
  # is unchanged).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  P=$PWD/.device/bidir-prev
  T="timeout -k 5 60"
  for r in 1 2; do
    for b in "$P" "$B"; do
      echo "== CameraMain quality 5 $(basename $b)"; $T "$b" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
    done
  done
  for cam in CameraAlternate CameraBalcony CameraAlcove; do
    for b in "$P" "$B"; do
      echo "== $cam quality 5 $(basename $b)"; $T "$b" bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 5 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  echo "== CameraMain quality 5 --refill 24"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 --refill 24 2>&1 | grep -E "^(primary|shadow|diffuse) "
  ;;
s29i)
  # Session 29: a measurement build (.device/bidir-exp, BIDIR_EXP_BITS) of the lockstep kernel:
  # bit 1 keeps each ray's origin in shared memory for its leaf tests (session 16's variant,
  # again over today's tree), bit 2 gives closest-hit rays the one loop over triangles too;
  # CameraMain quality 5, lockstep only (bit 1 is not wired into dynamic fetch), two runs.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  X=$PWD/.device/bidir-exp
  T="timeout -k 5 90"
  for r in 1 2; do
    for e in 0 1 2 3; do
      echo "== CameraMain quality 5 BIDIR_EXP_BITS=$e"; $T env BIDIR_EXP_BITS=$e "$X" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
    done
  done
  for cam in CameraAlternate CameraBalcony CameraAlcove; do
    for e in 0 3; do
      echo "== $cam quality 5 BIDIR_EXP_BITS=$e"; $T env BIDIR_EXP_BITS=$e "$X" bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 5 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  ;;
s29h)
  # Session 29: BDPT's passes, megakernels against wavefronts, kernel by kernel (Cornell box,
  # Sponza under its sun and sky): would a light pass as a megakernel beside the camera pass's
  # wavefront pay?
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  T="timeout -k 5 120"
  for w in off on; do
    echo "== cornell bdpt --wavefront $w"; $T "$B" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt --wavefront $w 2>&1 | tail -14
    echo "== sponza bdpt --wavefront $w --bvh bvh4"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt --wavefront $w --bvh bvh4 2>&1 | tail -14
  done
  ;;
s29g)
  # Session 29: a measurement build (.device/bidir-exp, BIDIR_EXP_BITS=1): dynamic fetch without
  # the refill cap's count (llvmpipe's; unlimited on GPUs), to see whether the closest-hit
  # refill kernel's 56 registers drop; CameraMain quality 5 --refill 28 and 24, two runs.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  X=$PWD/.device/bidir-exp
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "--refill 28" "--refill 24"; do
      for e in 0 1; do
        echo "== CameraMain quality 5 $c BIDIR_EXP_BITS=$e"; $T env BIDIR_EXP_BITS=$e "$X" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
      done
    done
  done
  ;;
s29f)
  # Session 29: the machine code of the 4-wide trace kernels (lockstep and --refill 28) as the
  # driver compiled them: the shader disk cache comes back as $OUT/nvcache.tgz, for
  # scripts/device/sass.py here.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  export __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1
  for c in "" "--refill 28"; do
    timeout -k 5 120 "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 4 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
  done
  tar czf "$OUT/nvcache.tgz" -C $D .
  ;;
s29e)
  # Session 29, the final build: any-hit rays' leaf phase as one loop over triangles, against
  # .device/bidir-prev (901598a, session 28's last commit): CameraMain quality 5, lockstep and
  # --refill 28 (diffuse also 24), two runs interleaved; the other cameras' shadow rays; the
  # integrators on Sponza and the Cornell box.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  P=$PWD/.device/bidir-prev
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "" "--refill 28" "--refill 24"; do
      for b in "$P" "$B"; do
        echo "== CameraMain quality 5 $c $(basename $b)"; $T "$b" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
      done
    done
  done
  echo "== CameraMain quality 5 leaf size 2"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 2 --quality 5 2>&1 | grep -E "^(primary|shadow|diffuse) "
  for cam in CameraAlternate CameraBalcony CameraAlcove; do
    for b in "$P" "$B"; do
      echo "== $cam quality 5 $(basename $b)"; $T "$b" bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 5 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for i in pt-nee bdpt; do
    for b in "$P" "$B"; do
      echo "== sponza $i $(basename $b)"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      echo "== cornell $i $(basename $b)"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
    done
  done
  for i in pt-nee bdpt; do
    echo "== cornell $i --time 1"; $T "$B" render $CB --integrator $i --time 1 -o /tmp/c.exr 2>&1 | grep -E "spp in" ; $T "$B" diff /tmp/c.exr "$REF" 2>&1 | grep -i rmse | head -2
  done
  ;;
s29d)
  # Session 29: (1) a measurement build, BIDIR_EXP_FLAT=1: the lockstep leaf phase as one loop
  # over triangles (a lane moves to its next leaf as soon as it is done with one) instead of a
  # loop over leaves around a loop over their triangles; CameraMain quality 5, two runs
  # interleaved. (2) Issue #17's last bullet: the integrators on Sponza under its sun and sky
  # at the commit before the issue's work (.device/bidir-base, 3e429eb) and now, defaults, two
  # runs interleaved.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "" "--refill 28"; do
      for e in 0 1; do
        echo "== CameraMain quality 5 $c BIDIR_EXP_FLAT=$e"; $T env BIDIR_EXP_FLAT=$e "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
      done
    done
  done
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for r in 1 2; do
    for i in pt-nee bdpt pt; do
      for b in "$BASE" "$B"; do
        echo "== sponza $i $(basename $b)"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
    done
  done
  for b in "$BASE" "$B"; do
    for i in pt-nee bdpt; do
      echo "== sponza $i $(basename $b) --time 1"; $T "$b" render $SPB --integrator $i --time 1 -o /tmp/s.exr 2>&1 | grep -i -E "spp|samples" | tail -2
    done
  done
  ;;
s29c)
  # Session 29: where a BDPT sample's time goes now on the Cornell box (kernels, rays per
  # sample), beside pt-nee's.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 120"
  for i in bdpt pt-nee "bdpt --rr-depth 5" "pt-nee --rr-depth 3"; do
    echo "== cornell $i"; $T "$B" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator $i 2>&1 | tail -22
  done
  for i in bdpt pt-nee; do
    echo "== cornell $i --count"; $T "$B" bench render $CB --spp 64 --warmup 1 --runs 1 --integrator $i --count 2>&1 | tail -12
  done
  ;;
s29b)
  # Session 29: regions of rays with a region taken over from the nearest open one (the
  # subgroup's lanes read the counters together) instead of s29a's one-by-one scan; homed on
  # the multiprocessor or (BIDIR_EXP_NO_SMID, a measurement switch) on the workgroup.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "" "--refill 28"; do
      for g in "" "--regions 132" "--regions 132 NO" "--regions 264" "--regions 33"; do
        [ $r = 2 ] && { [ "$g" = "--regions 264" ] || [ "$g" = "--regions 33" ]; } && continue
        e=""; case "$g" in *NO) e="BIDIR_EXP_NO_SMID=1"; g=${g% NO};; esac
        echo "== CameraMain quality 5 $c $g $e"; $T env $e "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c $g 2>&1 | grep -E "^(primary|shadow|diffuse) |regions" | sed 's/.*bvh4 //; s/^device.*workgroups/workgroups/'
      done
    done
  done
  ;;
s29a)
  # Session 29: regions of rays homed on the multiprocessors (--regions N; gl_SMIDNV), Sponza
  # CameraMain quality 5, lockstep one ray per invocation and --refill 28, against the launch
  # order, two runs interleaved.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  "$B" info 2>&1 | grep -i -E "SM|multiproc" | head -3
  for r in 1 2; do
    for c in "" "--refill 28"; do
      for g in "" "--regions 132" "--regions 264" "--regions 66"; do
        [ -n "$c" ] && [ "$g" = "--regions 66" ] && continue
        echo "== CameraMain quality 5 $c $g"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c $g 2>&1 | grep -E "^(primary|shadow|diffuse) |regions" | sed 's/.*bvh4 //; s/^device.*workgroups/workgroups/'
      done
    done
  done
  ;;
s28g)
  # Session 28: the surface area collapse's binary tree without obvhs' second reinsertion pass
  # (which at one triangle per leaf runs over the same tree again): a measurement build of
  # d5ec1a9, BIDIR_EXP_NO_SECOND, not committed; CameraMain quality 4 and 5 and the integrators
  # on Sponza, two runs interleaved, build times.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for r in 1 2; do
    for e in "" "BIDIR_EXP_NO_SECOND=1"; do
      for q in 5 4; do
        for c in "" "--refill 28"; do
          [ $q = 4 ] && [ -n "$c" ] && continue
          echo "== CameraMain quality $q $c $e"; $T env $e "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality $q $c 2>&1 | grep -E "^(primary|shadow|diffuse) |SAH" | sed 's/.*bvh4 //'
        done
      done
      for i in pt-nee bdpt; do
        echo "== sponza $i $e"; $T env $e "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
    done
  done
  ;;
s28f)
  # Session 28, the final build: Cornell box bdpt and pt-nee by default (bdpt's wavefront form
  # over bvh4 now has the surface area collapse) against --bvh-collapse greedy, ms per 1024 spp
  # and RMSE at 1 s against the sharper reference, two runs; issue #17's figures once more.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for r in 1 2; do
    for i in bdpt pt-nee; do
      for v in sah greedy; do
        echo "== cornell $i $v"; $T "$B" bench render $CB --integrator $i --spp 1024 --bvh-collapse $v 2>&1 | grep -E "Msamples"
      done
    done
    for v in sah greedy; do
      echo "== cornell bdpt --time 1 $v"; $T "$B" render $CB --integrator bdpt --time 1 --bvh-collapse $v --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
  done
  for c in "" "--refill 28"; do
    echo "== CameraMain quality 5 $c"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |SAH" | sed 's/.*build (/(/'
  done
  ;;
s28e)
  # Session 28: diffuse rays' refill count over the default collapse (two runs), and a leaf's
  # cost of 0.75 and 1 (every kind, lockstep and --refill 28): CameraMain, quality 5.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for r in 1 2; do
    for n in 16 20 24 28 31; do
      echo "== CameraMain quality 5 diffuse --refill $n"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 --rays diffuse --refill $n 2>&1 | grep -E "^diffuse "
    done
  done
  for c in "" "--refill 28"; do
    for v in sah:0.5,0.75 sah:0.5,1; do
      echo "== CameraMain quality 5 $c $v"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c --collapse $v 2>&1 | grep -E "^(primary|shadow|diffuse) |SAH" | sed 's/.*build (/(/'
    done
  done
  ;;
s28d)
  # Session 28: the surface area collapse with a leaf's own cost (the default sah = sah:0.5,0.5)
  # against sah:0.5,0 and greedy: CameraMain, quality 5, lockstep and --refill 28, two runs
  # interleaved; the other cameras; the integrators on Sponza under the sun and sky.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "" "--refill 28"; do
      for v in sah sah:0.5,0 greedy; do
        echo "== CameraMain quality 5 $c $v"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c --collapse $v 2>&1 | grep -E "^(primary|shadow|diffuse) |SAH" | sed 's/.*build (/(/'
      done
    done
  done
  for cam in CameraAlternate CameraBalcony CameraAlcove; do
    for v in sah sah:0.5,0; do
      echo "== $cam quality 5 $v"; $T "$B" bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 5 --collapse $v 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for i in pt-nee bdpt; do
    for v in "sah" "sah:0.5,0" "greedy" "sah --bvh-quality 5"; do
      echo "== sponza $i $v"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i --bvh bvh4 --bvh-collapse $v 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s28c)
  # Session 28: the surface area collapse's leaf size and a cost per leaf visited (a
  # measurement build of 2548db0, BIDIR_EXP_LEAF, not committed): CameraMain, quality 5,
  # lockstep and --refill 28, one run.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for c in "" "--refill 28"; do
    for v in "3 0" "2 0" "4 0" "6 0" "3 0.25" "3 0.5" "4 0.5"; do
      set -- $v
      echo "== CameraMain quality 5 $c leaf size $1, leaf cost $2"; $T env BIDIR_EXP_LEAF=$2 "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size $1 --quality 5 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |SAH" | sed 's/.*build (/(/'
    done
  done
  ;;
s28b)
  # Session 28: the surface area collapse again: CameraMain, quality 5, greedy / sah:0.5 /
  # sah:0.3, lockstep and --refill 28, two runs interleaved; the other cameras; the integrators
  # over bvh4 on Sponza under the sun and sky (their default quality 4, and 5).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "" "--refill 28"; do
      for v in greedy sah:0.5 sah:0.3; do
        echo "== CameraMain quality 5 $c $v"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c --collapse $v 2>&1 | grep -E "^(primary|shadow|diffuse) |SAH"
      done
    done
  done
  for cam in CameraAlternate CameraBalcony CameraAlcove; do
    for v in greedy sah:0.5; do
      echo "== $cam quality 5 $v"; $T "$B" bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 5 --collapse $v 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for i in pt-nee bdpt; do
    for v in "greedy" "sah:0.5" "sah:0.5 --bvh-quality 5" "greedy --bvh-quality 5"; do
      echo "== sponza $i $v"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i --bvh bvh4 --bvh-collapse $v 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s28a)
  # Session 28: the 4-wide collapse of least surface area cost (--collapse sah:TRI) against
  # the greedy one, every ray kind from CameraMain at quality 5 (lockstep and --refill 28) and
  # 4; a measurement build's variants: obvhs' leaves kept (BIDIR_EXP_KEEP_LEAVES), slots by
  # decreasing area (BIDIR_EXP_ORDER).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for q in 5 4; do
    for c in "" "--refill 28"; do
      [ $q = 4 ] && [ -n "$c" ] && continue
      for v in greedy sah:0.3 sah:0.5 sah:1 keep order; do
        case $v in keep) e="env BIDIR_EXP_KEEP_LEAVES=1"; col=sah:1;; order) e="env BIDIR_EXP_ORDER=1"; col=sah:1;; *) e=""; col=$v;; esac
        echo "== CameraMain quality $q $c $v"; $T $e "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality $q $c --collapse $col 2>&1 | grep -E "^(primary|shadow|diffuse) |SAH"
      done
    done
  done
  ;;
s27g)
  # Session 27: BDPT's wavefront form on the Cornell box and the hidden-light box at other
  # sample-slice counts than the default's (which its slot budget caps), two runs.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  HID=".device/scenes/hidden/hidden.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  for r in 1 2; do
    for s in 72 88 96 104 112 127; do
      echo "== slices $s: cornell $("$B" bench render $CB --integrator bdpt --spp 1024 --sample-slices $s 2>&1 | grep -oE 'GPU [0-9.]+ ms')  hidden $("$B" bench render $HID --integrator bdpt --spp 1024 --sample-slices $s 2>&1 | grep -oE 'GPU [0-9.]+ ms')"
    done
  done
  ;;
s27f)
  # Session 27: BDPT on the plain Cornell box by default (megakernels) and in its wavefront
  # form, equal time against the sharper reference, two runs each; pt-nee beside them; the
  # other joins the wavefront form has (lvc=2, 3) timed both ways.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  HID=".device/scenes/hidden/hidden.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  T="timeout -k 5 60"
  for r in 1 2; do
    for t in 0.1 1; do
      for f in "--wavefront off" "--wavefront on"; do
        echo "== cornell bdpt --time $t $f"; $T "$B" render $CB --integrator bdpt $f --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      done
      echo "== cornell pt-nee --time $t"; $T "$B" render $CB --integrator pt-nee --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
  done
  for j in bdpt:lvc=2 bdpt:lvc=3; do
    for f in "--wavefront off" "--wavefront on"; do
      echo "== cornell $j $f"; $T "$B" bench render $CB --integrator $j --spp 1024 $f 2>&1 | grep -E "Msamples"
      echo "== hidden $j $f"; $T "$B" bench render $HID --integrator $j --spp 1024 $f 2>&1 | grep -E "Msamples"
    done
  done
  for s in 1 2; do
    for f in "--wavefront off" "--wavefront on"; do
      $T "$B" render $HID --integrator bdpt $f --time 1 --seed $s -o /tmp/h$s${f##* }.exr 2>&1 | grep -iE "spp in"
    done
  done
  for f in off on; do
    echo "== hidden bdpt --time 1 --wavefront $f, seed 1 against seed 2: $("$B" diff /tmp/h1$f.exr /tmp/h2$f.exr 2>&1 | grep -i rmse)"
  done
  ;;
s27e)
  # Session 27: the integrators where shadow rays are often occluded: pt-nee and bdpt on the
  # Cornell box and on the box whose light hides above a panel (.device/scenes/hidden, as
  # tests/render_caustic.rs builds it), 256², by default (megakernels over cwbvh) and in their
  # wavefront forms over bvh4 with the any-hit copy and without, interleaved, two runs.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  HID=".device/scenes/hidden/hidden.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  T="timeout -k 5 60"
  for r in 1 2; do
    for i in pt-nee bdpt; do
      for f in "" "--wavefront on" "--wavefront on --bvh-no-occlusion-copy"; do
        echo "== cornell $i $f"; $T "$B" bench render $CB --integrator $i --spp 1024 $f 2>&1 | grep -E "Msamples"
        echo "== hidden $i $f"; $T "$B" bench render $HID --integrator $i --spp 1024 $f 2>&1 | grep -E "Msamples"
      done
    done
  done
  ;;
s27d)
  # Session 27: this commit, Sponza CameraMain at quality 5: every ray kind lockstep and with
  # --refill 28, two runs; shadow rays with the any-hit copy at other refill counts.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "" "--refill 28"; do
      echo "== CameraMain quality 5 $c"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |^device"
    done
  done
  for n in 8 16 20 24 31; do
    echo "== CameraMain quality 5 --refill $n"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 --rays shadow --refill $n 2>&1 | grep -E "^shadow "
  done
  ;;
s27c)
  # Session 27: a measurement build (.device/bidir-exp.gz, not committed): the any-hit copy's
  # order by p / C with C the expected work of an occlusion ray crossing the child, children
  # visited in that order (Ize & Hansen's RTSAH recursion; key 7: p = the triangles' area over
  # the box's, capped at 1, as key 0; key 6: p composed from the children's), against key 0
  # (p / C with C the closest-hit SAH: this commit). Shadow rays, quality 5, four cameras.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  X=.device/bidir-exp
  T="timeout -k 5 90"
  for r in 1 2; do
    for cam in CameraMain CameraAlternate CameraBalcony CameraAlcove; do
      for c in "" "--refill 28"; do
        [ $cam != CameraMain ] && [ -n "$c" ] && continue
        for k in 0 6 7; do
          echo "== $cam quality 5 $c key $k"; BIDIR_EXP_OCC_KEY=$k $T $X bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 5 --rays shadow $c 2>&1 | grep -E "^shadow "
        done
      done
    done
  done
  for k in 0 7; do
    echo "== CameraMain quality 4 key $k"; BIDIR_EXP_OCC_KEY=$k $T $X bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 4 --rays shadow 2>&1 | grep -E "^shadow "
  done
  ;;
s27b)
  # Session 27: a measurement build (.device/bidir-exp.gz, not committed). Shadow rays: the
  # any-hit copy ordered by p / C (key 0) or 1 / C (key 2), its pushed children popped in slot
  # order (pop 0, this commit) or highest slot first (pop 1, session 26's ca3372c). Primary and
  # diffuse rays: boxes entered at tmin ordered by slot (tie 0, this commit), exit nearest
  # first (2), entry farthest behind first (3), entry nearest behind first (4).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  X=.device/bidir-exp
  T="timeout -k 5 90"
  for cam in CameraMain CameraAlternate CameraAlcove; do
    for c in "" "--refill 28"; do
      [ $cam != CameraMain ] && [ -n "$c" ] && continue
      for k in 0 2; do
        for pop in 0 1; do
          echo "== $cam quality 5 $c key $k pop $pop"; BIDIR_EXP_OCC_KEY=$k BIDIR_EXP_POP=$pop $T $X bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 5 --rays shadow $c 2>&1 | grep -E "^shadow "
        done
      done
    done
  done
  for r in 1 2; do
    for c in "" "--refill 28"; do
      for t in 0 2 3 4; do
        echo "== CameraMain quality 5 $c tie $t"; BIDIR_EXP_TIE=$t $T $X bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 5 $c 2>&1 | grep -E "^(primary|diffuse) "
      done
    done
  done
  ;;
s27a)
  # Session 27: any-hit rays over their own copy of the 4-wide nodes, slots in occlusion order
  # (this commit), against the one tree (--no-occlusion-copy), interleaved: every ray kind from
  # CameraMain at quality 4 and 5, lockstep and --refill 28, two runs; shadow rays from the
  # other cameras; the integrators over bvh4 on Sponza under the sun and sky, and by default.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for r in 1 2; do
    for q in 4 5; do
      for c in "" "--refill 28"; do
        for occ in "" "--no-occlusion-copy"; do
          echo "== CameraMain quality $q $c $occ"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality $q $c $occ 2>&1 | grep -E "^(primary|shadow|diffuse) "
        done
      done
    done
  done
  for cam in CameraAlternate CameraBalcony CameraAlcove; do
    for occ in "" "--no-occlusion-copy"; do
      echo "== $cam quality 5 $occ"; $T "$B" bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 5 $occ 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for i in pt-nee bdpt; do
    for occ in "" "--bvh-no-occlusion-copy"; do
      echo "== sponza $i bvh4 $occ"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i --bvh bvh4 $occ 2>&1 | grep -E "Msamples"
    done
    echo "== sponza $i default"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
  done
  ;;
s26j)
  # Session 26: s26h again with the occlusion order as the slot order and the closest-hit
  # rays' distance ties broken in reverse slot order.
  bash "$0" s26h
  ;;
s26i)
  # Session 26: s26h again with the occlusion order kept beside the slots (Bvh4Node::any_hit):
  # in s26h, as the slot order, it slowed the closest-hit rays (their ties break by slot).
  bash "$0" s26h
  ;;
s26h)
  # Session 26: this commit (occlusion order, quality 5, the 1 s warm-up) on every ray kind,
  # Sponza's four cameras, quality 4 and 5; the integrators on Sponza and the Cornell box.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for r in 1 2; do
    for q in 4 5; do
      for c in "" "--refill 28"; do
        echo "== CameraMain quality $q $c"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality $q $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
      done
    done
  done
  for cam in CameraAlternate CameraBalcony CameraAlcove; do
    for q in 4 5; do
      echo "== $cam quality $q"; $T "$B" bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality $q 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for i in pt-nee bdpt; do
    echo "== sponza $i"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
    echo "== cornell $i"; $T "$B" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples"
  done
  ;;
s26g)
  # Session 26: a measurement build (.device/bidir-exp.gz, not committed): the 4-wide nodes'
  # slots ordered for any-hit rays by p / C (BIDIR_EXP_OCC=1; Ize & Hansen 2011) and the any-hit
  # step's pushes highest slot first, against this commit (.device/bidir.gz): shadow rays on
  # Sponza's four cameras at quality 4 and 5, and the integrators on Sponza under the sun and sky.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for cam in CameraMain CameraAlternate CameraBalcony CameraAlcove; do
    for q in 4 5; do
      for c in "" "--refill 28"; do
        [ $cam != CameraMain ] && [ -n "$c" ] && continue
        echo "== $cam quality $q $c head"; $T "$B" bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality $q --rays shadow $c 2>&1 | grep -E "^shadow "
        for occ in 0 1; do
          echo "== $cam quality $q $c exp occ $occ"; BIDIR_EXP_OCC=$occ $T .device/bidir-exp bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality $q --rays shadow $c 2>&1 | grep -E "^shadow "
        done
      done
    done
  done
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for r in 1 2; do
    for i in pt-nee bdpt; do
      echo "== sponza $i head"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      echo "== sponza $i exp occ 1"; BIDIR_EXP_OCC=1 $T .device/bidir-exp bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s26f)
  # Session 26: the tree lottery (s26b) again with this commit's binary: the sixteen trees of
  # build quality 5's candidates (`--ploc DISTANCE,DEPTH` at quality 4), each with its SAH, on
  # Sponza's four cameras, lockstep, the warm-up at least 1 s (s26b's exp build warmed up 3
  # runs only, after a build and a CPU-side ray sample of seconds: some of its runs were timed
  # at a low clock).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 60"
  for s in 6 14 24 32; do
    for d in 0 1 2 3; do
      for cam in CameraMain CameraAlternate CameraBalcony CameraAlcove; do
        echo "== ploc $s,$d $cam"; $T "$B" bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 4 --ploc $s,$d 2>&1 | grep -E "^(primary|shadow|diffuse) |ms build" | sed -e 's/.*bvh4 /bvh4 /'
      done
    done
  done
  ;;
s26e)
  # Session 26: s26d again, the warm-up at least 1 s (after 0.25 s some runs were still at a
  # low clock), and quality 3 beside it.
  bash "$0" s26d
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  for c in "" "--refill 28"; do
    echo "== CameraMain quality 3 $c"; timeout -k 5 90 "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
  done
  ;;
s26d)
  # Session 26: s26c's traversal runs again, with the warm-up that lasts at least 0.25 s (in
  # s26c quality 5's 5.8 s build left the GPU at its idle clock through the timed runs).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  for r in 1 2; do
    for q in 4 5; do
      for c in "" "--refill 28"; do
        echo "== CameraMain quality $q $c"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality $q $c 2>&1 | grep -E "^(primary|shadow|diffuse) |ms build" | sed -e 's/.*bvh4 /bvh4 /'
      done
    done
  done
  for cam in CameraAlternate CameraBalcony CameraAlcove; do
    for q in 4 5; do
      echo "== $cam quality $q"; $T "$B" bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality $q 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  ;;
s26c)
  # Session 26: build quality 5 (sixteen quality-4 trees, the one of least SAH kept) against
  # quality 4: the traversal benchmark on Sponza's four cameras, and the integrators on Sponza
  # under the sun and sky (geometry only: .device/scenes/sponza has no textures).
  # The traversal runs are s26d's (run here with the 3-run warm-up of that day's binary).
  bash "$0" s26d
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 90"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for r in 1 2; do
    for i in pt-nee bdpt; do
      for q in 4 5; do
        echo "== sponza $i --bvh-quality $q"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i --bvh-quality $q 2>&1 | grep -E "Msamples|ms per"
      done
    done
  done
  ;;
s26b)
  # Session 26: the tree lottery, wider: sixteen trees (PLOC search distance x the depth below
  # which it searches one neighbour; quality 4's other settings) on Sponza's four cameras,
  # lockstep, with each tree's SAH and its camera-free sampled cost (.device/bidir-exp.gz).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 60"
  for s in 6 14 24 32; do
    for d in 0 1 2 3; do
      for cam in CameraMain CameraAlternate CameraBalcony CameraAlcove; do
        echo "== search $s depth $d $cam"; BIDIR_EXP_BUILD=1 BIDIR_EXP_SEARCH=$s BIDIR_EXP_DEPTH=$d $T .device/bidir-exp bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 4 --reps 5 --warmup 2 2>&1 | grep -E "^(primary|shadow|diffuse) |exp: (SAH|sampled)"
      done
    done
  done
  ;;
s26a)
  # Session 26: the tree lottery. A measurement build (.device/bidir-exp.gz, not committed:
  # BIDIR_EXP_BUILD and BIDIR_EXP_SEARCH / _DEPTH set obvhs' PLOC search distance and the depth
  # below which it searches one neighbour) beside this commit's quality-4 build, on Sponza's
  # four cameras, geometry only (.device/scenes/sponza).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza/Sponza.gltf
  T="timeout -k 5 60"
  for cam in CameraMain CameraAlternate CameraBalcony CameraAlcove; do
    R='""'; [ $cam = CameraMain ] && R='"" "--refill 28"'
    for v in "base" "14 2" "24 3" "6 3" "32 3"; do
      eval "set -- $R"
      for c in "$@"; do
        if [ "$v" = base ]; then
          echo "== $cam base $c"; $T .device/bidir bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 4 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
        else
          set -- $v
          echo "== $cam search $1 depth $2 $c"; BIDIR_EXP_BUILD=1 BIDIR_EXP_SEARCH=$1 BIDIR_EXP_DEPTH=$2 $T .device/bidir-exp bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 4 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
        fi
      done
    done
    [ $cam = CameraMain ] && for c in "" "--refill 28"; do echo "== $cam base quality 3 $c"; $T .device/bidir bench traversal "$SP" --camera $cam --bvh bvh4 --leaf-size 3 --quality 3 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "; done
  done
  ;;
s24f)
  # Session 24: issue #16's table at this commit (time-budgeted renders, the Cornell box against
  # the sharper reference, the caustic scene at the test's 128² camera against its committed
  # reference; the rates), and the registers of s24e's measurement build (.device/bidir-exp.gz)
  # with one and two postponed-leaf slots.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  T="timeout -k 5 60"
  for t in 0.1 1; do
    for i in pt pt-nee bdpt bdpt:full; do
      echo "== cornell $i --time $t"; $T "$B" render $CB --integrator $i --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      echo "== caustic $i --time $t"; $T "$B" render $CAU --width 128 --height 128 --integrator $i --time $t --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
  done
  for i in pt pt-nee bdpt bdpt:full vcm; do
    echo "== cornell $i"; $T "$B" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
  done
  for i in pt-nee bdpt; do
    echo "== caustic $i"; $T "$B" bench render $CAU --width 256 --height 256 --integrator $i --spp 256 2>&1 | grep -E "Msamples" | head -1
  done
  if [ -x .device/bidir-exp ] && [ -d .device/scenes/sponza-full ]; then
    for ls in 1 2; do
      echo "== exp slots $ls"; BIDIR_EXP_LEAF_SLOTS=$ls $T .device/bidir-exp bench traversal .device/scenes/sponza-full/Sponza.gltf --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 4 --rays diffuse --reps 5 --warmup 1 2>&1 | grep -vE "^\s*$" | tail -4 | cut -c1-400
    done
  fi
  ;;
s24e)
  # Session 24: a measurement build (.device/bidir-exp.gz, not committed; counts as in s24c):
  # the lockstep loops with a second postponed-leaf slot (BIDIR_EXP_LEAF_SLOTS=2) against one,
  # interleaved, two runs.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  for r in 1 2; do
    for c in "--quality 4" "--quality 4 --refill 28" "--quality 3 --refill 28"; do
      for ls in 1 2; do
        echo "== slots $ls $c"; BIDIR_EXP_LEAF_SLOTS=$ls $T .device/bidir-exp bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
      done
    done
  done
  ;;
s24c)
  # Session 24: a measurement build (.device/bidir-exp.gz, not committed) whose traversal
  # counts, in the lockstep loops, every lane's descent iterations (working or idle) as
  # "nodes/ray" and the subgroup's longest leaf phase (triangle tests) per lane as "tris/ray";
  # against the node steps and triangle tests of s24a, the subgroups' SIMD efficiency.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  for q in 4 3; do
    echo "== exp q$q"; $T .device/bidir-exp bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality $q --reps 5 --warmup 1 2>&1 | grep -E "^(primary|shadow|diffuse) "
    echo "== exp q$q sort-local 8,1024"; $T .device/bidir-exp bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality $q --reps 5 --warmup 1 --sort-local 8,1024 2>&1 | grep -E "^(primary|shadow|diffuse) "
  done
  ;;
s24d)
  # Session 24: the measurement build of s24c, its dynamic fetch counted too (iterations per
  # lane of the descent, the subgroup's longest leaf phase), refills of 4 to 32 lanes.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  for r in 4 8 16 28 32; do
    echo "== exp q4 refill $r"; $T .device/bidir-exp bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 4 --reps 5 --warmup 1 --refill $r 2>&1 | grep -E "^(primary|shadow|diffuse) "
  done
  ;;
s24b)
  # Session 24: where the wavefront path tracer's pass goes on the textured Sponza: the
  # kernel table (launches = the path kernel's dispatches) at 16, 64 and 256 spp.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  T="timeout -k 5 60"
  for i in pt-nee pt; do
    for n in 16 64 256; do
      echo "== sponza $i $n spp"; $T "$B" bench render $SPB --spp $n --warmup 1 --runs 3 --integrator $i 2>&1 | grep -vE "^\s*$" | tail -12
    done
  done
  ;;
s24a)
  # Session 24: shadow and diffuse rays sorted within blocks of consecutive rays by direction
  # (--sort-local GRID,BLOCK, one pass) against unsorted and the global sort (--sort); the
  # 4-wide BVH at leaf size 3, quality 4 and 3; one run each.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  for q in 4 3; do
    for c in "" "--refill 28" "--sort" "--sort-local 4,1024" "--sort-local 8,1024" "--sort-local 4,4096" \
             "--sort-local 8,4096" "--sort-local 16,4096" "--sort-local 2,256" "--sort-local 4,256" \
             "--sort-local 4,1024 --refill 28" "--sort-local 8,4096 --refill 28"; do
      echo "== q$q $c"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality $q $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  ;;
s23g)
  # Session 23, the final commit: the scenes the session's changes should leave alone or speed
  # up (Cornell box and caustic scene: no alpha, their own layouts; MetalRoughSpheres and
  # DamagedHelmet: 4-wide BVH at quality 4 now), against the figures of session 22.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 60"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  H=$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb
  M=$PWD/.device/scenes/gltf/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb
  L="--width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for i in pt-nee bdpt; do
    echo "== cornell $i"; $T "$B" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator $i 2>&1 | grep -E "Msamples"
    echo "== helmet $i"; $T "$B" bench render $H $L --spp 256 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
    echo "== spheres $i"; $T "$B" bench render $M $L --spp 256 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
  done
  echo "== caustic 128 bdpt"; $T "$B" bench render $CAU --width 128 --height 128 --spp 1024 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
  echo "== caustic 256 bdpt"; $T "$B" bench render $CAU $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
  for i in pt-nee bdpt; do
    echo "== cornell $i 1 s"; $T "$B" render $CB --time 1 --integrator $i --reference $REF -o /tmp/c.exr 2>&1 | grep -iE "spp in|RMSE" | head -2
  done
  ;;
s23f)
  # Session 23: the watertight triangles' marks carry the material (its load beside the
  # vertices'; .device/bidir.gz) against marks that only flag (.device/bidir-base.gz, 0d5c9ee's
  # code at the quality-3 default: both run --bvh-quality 4 here), interleaved, two runs; the same image.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --bvh-quality 4"
  T="timeout -k 5 60"
  for r in 1 2; do
    for b in "$BASE" "$B"; do
      n=$(basename $b)
      for c in "--alpha" "--alpha --refill 16"; do
        echo "== trace $n bvh4 leaf 3 q4 $c"; $T "$b" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 4 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
      done
      for i in pt-nee pt bdpt; do
        echo "== sponza $n $i"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
    done
  done
  for b in "$BASE" "$B"; do
    $T "$b" render $SPB --spp 16 --integrator pt-nee -o /tmp/$(basename $b).exr > /dev/null 2>&1
  done
  echo "== same image pt-nee"; $T "$B" diff /tmp/bidir.exr /tmp/bidir-base.exr 2>&1 | head -3
  ;;
s23e)
  # Session 23: obvhs's parallel build (rayon): the same tree as on 2 cores (counts at 64x36),
  # the build times, the integrators at quality 3 (the default) and 4, setup times at 1 s,
  # `bench traversal` over the new trees.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  H=$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb
  HB="$H --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  T="timeout -k 5 60"
  nproc
  for q in 2 3 4; do
    echo "== tree q$q"; $T "$B" bench traversal "$SP" --camera CameraMain --width 64 --height 36 --bvh bvh4 --leaf-size 3 --quality $q --reps 1 --warmup 0 2>&1 | grep -E "build|^(primary|shadow|diffuse) " | cut -c1-200
  done
  for r in 1 2; do
    for c in "" "--bvh-quality 4"; do
      for i in pt-nee pt bdpt; do
        echo "== sponza $i [$c]"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i $c 2>&1 | grep -E "Msamples"
      done
      echo "== helmet pt-nee [$c]"; $T "$B" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator pt-nee $c 2>&1 | grep -E "Msamples"
    done
  done
  for c in "" "--bvh-quality 4"; do
    for i in pt-nee bdpt; do
      echo "== sponza $i 1 s [$c]"; $T "$B" render $SPB --time 1 --integrator $i $c -o /tmp/s.exr 2>&1 | grep -iE "spp in" | head -1
    done
  done
  for c in "--quality 3" "--quality 3 --refill 28" "--quality 4" "--quality 4 --refill 28"; do
    echo "== trace bvh4 leaf 3 $c"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |build" | cut -c1-200
  done
  ;;
s23d)
  # Session 23, the commit after s23c: the integrators at the new defaults (4-wide BVH at leaf
  # size 3, quality 3; alpha-marked triangles), two runs; quality 4 beside them; the
  # megakernels (--wavefront off) for today's ratio; 1 s renders; the 4-wide BVH's build time.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  H=$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb
  HB="$H --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  T="timeout -k 5 60"
  for r in 1 2; do
    for c in "" "--bvh-quality 4" "--wavefront off"; do
      for i in pt-nee pt bdpt; do
        echo "== sponza $i [$c]"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i $c 2>&1 | grep -E "Msamples"
      done
    done
    for i in pt-nee bdpt; do
      echo "== helmet $i"; $T "$B" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
    done
  done
  for i in pt-nee bdpt; do
    echo "== sponza $i 1 s"; $T "$B" render $SPB --time 1 --integrator $i -o /tmp/s.exr 2>&1 | grep -iE "spp|samples" | head -2
  done
  for q in 2 3 4; do
    echo "== build q$q"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality $q --reps 1 --warmup 0 2>&1 | grep -E "build" | cut -c1-200
  done
  ;;
s23c)
  # Session 23: watertight triangles marked when their material may turn a hit away, so the
  # alpha-tested kernels look up no material for opaque ones (.device/bidir.gz) against the
  # build before (.device/bidir-base.gz), interleaved, two runs; the integrators also over leaf
  # size 3, quality 3; the same image.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  T="timeout -k 5 60"
  for r in 1 2; do
    for b in "$BASE" "$B"; do
      n=$(basename $b)
      for c in "--alpha" "--alpha --refill 16"; do
        echo "== trace $n bvh4 leaf 3 q3 $c"; $T "$b" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
      done
      for c in "" "--bvh-leaf-size 3 --bvh-quality 3"; do
        for i in pt-nee pt bdpt; do
          echo "== sponza $n $i [$c]"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i $c 2>&1 | grep -E "Msamples"
        done
      done
    done
  done
  for b in "$BASE" "$B"; do
    $T "$b" render $SPB --spp 16 --integrator pt-nee -o /tmp/$(basename $b).exr > /dev/null 2>&1
    $T "$b" render $SPB --spp 4 --integrator bdpt -o /tmp/$(basename $b)-bdpt.exr > /dev/null 2>&1
  done
  echo "== same image pt-nee"; $T "$B" diff /tmp/bidir.exr /tmp/bidir-base.exr 2>&1 | head -3
  echo "== same image bdpt"; $T "$B" diff /tmp/bidir-bdpt.exr /tmp/bidir-base-bdpt.exr 2>&1 | head -3
  ;;
s23b)
  # Session 23: what alpha masks cost the 4-wide trace kernels (textured Sponza, the kernels
  # the integrators run) and registers; the integrators over the bench's best build (leaf size
  # 3, quality 3 or 4) against their default (leaf size 4, quality 2), interleaved, two runs.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  H=$PWD/.device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb
  HB="$H --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  T="timeout -k 5 60"
  for c in "" "--alpha" "--refill 16" "--alpha --refill 16"; do
    echo "== trace bvh4 leaf 3 q3 $c"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |^trace" | sed -E 's/; (Binary|Shader|Stack)[^;]*//g' | cut -c1-220
  done
  for r in 1 2; do
    for c in "" "--bvh-leaf-size 3" "--bvh-leaf-size 3 --bvh-quality 3" "--bvh-leaf-size 3 --bvh-quality 4"; do
      for i in pt-nee pt bdpt; do
        echo "== sponza $i [$c]"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i $c 2>&1 | grep -E "Msamples"
      done
      echo "== helmet pt-nee [$c]"; $T "$B" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator pt-nee $c 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s23a)
  # Session 23: the 4-wide BVH with half-precision boxes (--bvh bvh4h, 64-byte nodes) against
  # full precision (bvh4, 128 bytes), interleaved, two runs, quality 3 and 4, lockstep and
  # dynamic fetch; the kernels' registers. Then s22k (the same binaries).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  for r in 1 2; do
    for q in 3 4; do
      for c in "--leaf-size 3 --quality $q" "--leaf-size 3 --quality $q --refill 28"; do
        for l in bvh4 bvh4h; do
          echo "== sponza --bvh $l $c"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh $l $c 2>&1 | grep -E "^(primary|shadow|diffuse) |registers" | cut -c1-200
        done
      done
    done
  done
  ;;
s22k)
  # Pending (session 22 had no device time left): BDPT's wavefront camera kernel in workgroups
  # of 512 (a build with `#define WF_WG_SIZE 512` before bdpt_camera_wavefront.comp's includes,
  # as .device/bidir.gz) against 64
  # (.device/bidir-final.gz, a build of this commit), interleaved (s22c, with the size as a
  # specialisation constant: Sponza 72.3 -> 70.8 ms at 512, one run).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  F=$PWD/.device/bidir-final
  T="timeout -k 5 40"
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  for r in 1 2; do
    for b in "$F" "$B"; do
      n=$(basename $b)
      echo "== sponza bdpt $n"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples|camera_wavefront"
      echo "== caustic 256 bdpt $n"; $T "$b" bench render $CAU $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      echo "== caustic 128 bdpt $n"; $T "$b" bench render $CAU --width 128 --height 128 --spp 1024 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      echo "== cornell bdpt wavefront $n"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt --wavefront on 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s22j)
  # Session 22: the camera pass's connections to the light vertex cache in a kernel of their own
  # (bdpt_connect_wavefront.comp; .device/bidir.gz) against the build before it
  # (.device/bidir-final.gz, 6d21abf: 8 M slots), interleaved; registers; the same image.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  F=$PWD/.device/bidir-final
  T="timeout -k 5 60"
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  echo "== info"; $T "$B" info --kernels $SP --sponza-sun-sky 2>&1 | grep -E "^bdpt:lvc=1 / bdpt_(camera|connect)_wavefront" | sed -E 's/; (Binary|Shader|Stack)[^;]*//g' | cut -c1-300
  for r in 1 2; do
    for b in "$F" "$B"; do
      n=$(basename $b)
      echo "== sponza bdpt $n"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples|_wavefront|trace"
      echo "== caustic 256 bdpt $n"; $T "$b" bench render $CAU $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      echo "== cornell bdpt wavefront $n"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt --wavefront on 2>&1 | grep -E "Msamples"
    done
  done
  for b in "$F" "$B"; do
    echo "== sponza bdpt --time 1 $(basename $b)"; $T "$b" render $SPB --integrator bdpt --time 1 -o /tmp/t.exr 2>&1 | grep -E "spp in"
    $T "$b" render $SPB --integrator bdpt --spp 48 -o /tmp/s-$(basename "$b").exr 2>&1 | grep -E "spp in"
  done
  echo "== same image"; "$B" diff /tmp/s-bidir-final.exr /tmp/s-bidir.exr | head -2
  ;;
s22i)
  # Session 22, the s22h measurement build (BIDIR_EXP_TARGET_SLOTS): (1) with 8 M slots, does
  # BDPT's wavefront form now beat the megakernels on the diffuse Cornell box (185.4 against
  # 174.9 ms per 1024 spp at 4 M, session 21)? (2) 16 M slots where memory allows.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 60"
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  MR=".device/scenes/gltf/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2; do
    for t in 8388608 16777216; do
      echo "== cornell bdpt wavefront target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt --wavefront on 2>&1 | grep -E "Msamples"
      echo "== cornell pt-nee wavefront target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator pt-nee --wavefront on 2>&1 | grep -E "Msamples"
      echo "== caustic 256 bdpt target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $CAU $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      echo "== helmet pt-nee target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $HB --spp 456 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
      echo "== spheres pt-nee target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $MR --spp 456 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
      echo "== sponza pt-nee target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $SPB --spp 456 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
    done
    echo "== cornell bdpt megakernels"; $T "$B" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
  done
  for s in 1 2; do
    echo "== cornell bdpt --time 1 wavefront 8M seed $s"; BIDIR_EXP_TARGET_SLOTS=8388608 $T "$B" render $CB --integrator bdpt --wavefront on --time 1 --seed $s --reference "$REF" -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
    echo "== cornell bdpt --time 1 megakernels seed $s"; $T "$B" render $CB --integrator bdpt --time 1 --seed $s --reference "$REF" -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
  done
  ;;
s22h)
  # Session 22, a measurement build (BIDIR_EXP_TARGET_SLOTS): the wavefront forms' target
  # slots 4 M (TARGET_SLOTS) against 8 M, interleaved, where s22g found more slots faster
  # (DamagedHelmet pt-nee 384² 85.1 -> 76.6 ms at 57 slices, Sponza bdpt 502 -> 488 at 24).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 60"
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  MR=".device/scenes/gltf/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2; do
    for t in 4194304 8388608; do
      for i in bdpt pt-nee pt; do
        echo "== sponza 640x360 $i target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $SPB --width 640 --height 360 --spp 456 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
      echo "== sponza 1920x1080 pt-nee target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $SPB --width 1920 --height 1080 --spp 60 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
      for i in bdpt pt-nee; do
        echo "== helmet 384 $i target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $HB --width 384 --height 384 --spp 456 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
        echo "== helmet 128 $i target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $HB --width 128 --height 128 --spp 1024 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
        echo "== spheres 384 $i target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $MR --width 384 --height 384 --spp 456 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
      for px in 128 256; do
        echo "== caustic $px bdpt target $t"; BIDIR_EXP_TARGET_SLOTS=$t $T "$B" bench render $CAU --width $px --height $px --spp 1024 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      done
    done
  done
  ;;
s22g)
  # Session 22: do more slots than TARGET_SLOTS (4 M) pay in large images? Textured Sponza
  # 640x360 (19 slices by default for both), DamagedHelmet 384² (29): --sample-slices up to
  # twice the slots (BDPT's light-vertex store caps Sponza at 24 slices in 4 GiB).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 60"
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2; do
    for sl in auto 24 32 38; do
      a=""; [ "$sl" != auto ] && a="--sample-slices $sl"
      echo "== sponza pt-nee slices $sl"; $T "$B" bench render $SPB --spp 456 --warmup 1 --runs 3 --integrator pt-nee $a 2>&1 | grep -E "Msamples"
      echo "== sponza pt slices $sl"; $T "$B" bench render $SPB --spp 456 --warmup 1 --runs 3 --integrator pt $a 2>&1 | grep -E "Msamples"
    done
    for sl in auto 24; do
      a=""; [ "$sl" != auto ] && a="--sample-slices $sl"
      echo "== sponza bdpt slices $sl"; $T "$B" bench render $SPB --spp 456 --warmup 1 --runs 3 --integrator bdpt $a 2>&1 | grep -E "Msamples"
    done
    for sl in auto 43 57; do
      a=""; [ "$sl" != auto ] && a="--sample-slices $sl"
      echo "== helmet pt-nee slices $sl"; $T "$B" bench render $HB --spp 1026 --warmup 1 --runs 3 --integrator pt-nee $a 2>&1 | grep -E "Msamples"
      echo "== helmet bdpt slices $sl"; $T "$B" bench render $HB --spp 342 --warmup 1 --runs 3 --integrator bdpt $a 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s22f)
  # Session 22: the wavefront forms' automatic sample slices up to 1024 (were 64), so small
  # images get about TARGET_SLOTS slots too (.device/bidir.gz, a build of that change): new
  # auto against --sample-slices 64 (the old auto below 256²) and the megakernels; then s21k's
  # equal-time question again, and short time budgets.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 60"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  SPS="$SP --sponza-sun-sky --camera CameraMain --width 320 --height 180"
  for r in 1 2; do
    for px in 64 128 192; do
      for sc in "caustic|$CAU|bdpt" "helmet|$HB|bdpt" "helmet|$HB|pt-nee"; do
        IFS='|' read -r n scene integ <<< "$sc"
        for a in "" "--sample-slices 64" "--wavefront off"; do
          echo "== $n $integ $px ${a:-auto}"; $T "$B" bench render $scene --width $px --height $px --spp 1024 --warmup 1 --runs 3 --integrator $integ $a 2>&1 | grep -E "Msamples"
        done
      done
    done
    for integ in bdpt pt-nee; do
      for a in "" "--sample-slices 64"; do
        echo "== sponza 320x180 $integ ${a:-auto}"; $T "$B" bench render $SPS --spp 256 --warmup 1 --runs 3 --integrator $integ $a 2>&1 | grep -E "Msamples"
      done
    done
  done
  for s in 1 2; do
    for wf in auto off; do
      echo "== caustic 128 bdpt --time 1 seed $s wavefront $wf"; $T "$B" render $CAU --width 128 --height 128 --integrator bdpt --time 1 --seed $s --wavefront $wf --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
    done
  done
  for t in 0.05 0.1; do
    for px in 64 128; do
      echo "== caustic $px bdpt --time $t"; $T "$B" render $CAU --width $px --height $px --integrator bdpt --time $t -o /tmp/t.exr 2>&1 | grep -E "spp in"
    done
  done
  ;;
s22e)
  # Session 22: s21k (in s22d) found BDPT's wavefront default slower than the megakernels on
  # the caustic scene at 128² (8,935-9,352 against 14,557-14,602 spp in 1 s), where session 21
  # measured it faster at 256². Its slots are pixels x sample slices, the slices capped at 64:
  # 1 M slots at 128², 4 M (the target) at 256². GPU time per 512 spp by image size and
  # slices, wavefront against megakernels.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 60"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2; do
    for px in 64 128 192 256; do
      for sl in auto 64 128 256; do
        a=""; [ "$sl" != auto ] && a="--sample-slices $sl"
        echo "== caustic $px wavefront slices $sl"; $T "$B" bench render $CAU --width $px --height $px --spp 512 --warmup 1 --runs 3 --integrator bdpt --wavefront on $a 2>&1 | grep -E "Msamples"
      done
      echo "== caustic $px megakernels"; $T "$B" bench render $CAU --width $px --height $px --spp 512 --warmup 1 --runs 3 --integrator bdpt --wavefront off 2>&1 | grep -E "Msamples"
    done
    for px in 128 192; do
      for sl in auto 256; do
        a=""; [ "$sl" != auto ] && a="--sample-slices $sl"
        echo "== helmet $px wavefront slices $sl"; $T "$B" bench render $HB --width $px --height $px --spp 512 --warmup 1 --runs 3 --integrator bdpt --wavefront on $a 2>&1 | grep -E "Msamples"
      done
      echo "== helmet $px megakernels"; $T "$B" bench render $HB --width $px --height $px --spp 512 --warmup 1 --runs 3 --integrator bdpt --wavefront off 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s22d)
  # Session 22, a measurement build (.device/bidir-exp.gz): where bdpt_camera_wavefront's 128
  # registers go. BIDIR_EXP_CAMERA's bits remove a part of the camera step (1: the light sample,
  # s = 1; 2: the connections to the light vertex cache; 4: emitters found, s = 0; 8: the
  # scattering that continues the path); BIDIR_EXP_CAP=1 sizes the pending shadow rays' array
  # by the join (2 for bdpt:lvc=1) instead of BDPT_WF_SHADOW_RAYS (4). Registers, and textured
  # Sponza's time without each part. Then s21k again with this session's build.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  X=$PWD/.device/bidir-exp
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for e in 0 1 2 3 4 8 15; do
    echo "== info exp $e"; BIDIR_EXP_CAMERA=$e $T "$X" info --kernels $SP --sponza-sun-sky 2>&1 | grep -E "^bdpt:lvc=1 / bdpt_camera_wavefront" | cut -c1-400
  done
  echo "== info cap"; BIDIR_EXP_CAP=1 $T "$X" info --kernels $SP --sponza-sun-sky 2>&1 | grep -E "^bdpt:lvc=1 / bdpt_camera_wavefront" | cut -c1-400
  for r in 1 2; do
    for e in 0 1 2 4 8; do
      echo "== sponza bdpt exp $e"; BIDIR_EXP_CAMERA=$e $T "$X" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples|_wavefront|trace"
    done
    echo "== sponza bdpt cap"; BIDIR_EXP_CAP=1 $T "$X" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples|_wavefront|trace"
  done
  for s in 1 2; do
    for wf in auto off; do
      echo "== caustic 128 bdpt --time 1 seed $s wavefront $wf"; $T "$B" render assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128 --integrator bdpt --time 1 --seed $s --wavefront $wf --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
    done
  done
  ;;
s22c)
  # Session 22: (1) the path states as 16-byte words (PtSuspended, BdptCameraState: integers
  # in uint words, floats' bits beside them) against 74e8721 (.device/bidir-b74e.gz, before
  # the integer words; 32eb0ea's vec3 + uint members are s22b's), interleaved;
  # (2) the camera and light wavefront kernels' workgroup sizes again, their launches now
  # sized by a specialisation constant (s22a's were sized as if a workgroup held 1 invocation:
  # shaderc folded gl_WorkGroupSize.x).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2; do
    for b in .device/bidir-b74e "$B"; do
      n=$(basename $b)
      for i in bdpt pt-nee pt; do
        echo "== sponza $i $n"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
      echo "== helmet pt-nee $n"; $T "$b" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
      echo "== cornell pt-nee paused queue $n"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator pt-nee --shadow-queue 192/24/pause 2>&1 | grep -E "Msamples"
      echo "== caustic bdpt $n"; $T "$b" bench render $CAU $CB --spp 256 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
    done
  done
  for w in 128 256 512 768 1024; do
    echo "== info wg $w"; BIDIR_EXP_WG_CAMERA=$w BIDIR_EXP_WG_LIGHT=$w $T "$B" info --kernels $SP --sponza-sun-sky 2>&1 | grep -E "^bdpt:lvc=1 " | grep -E "wavefront" | sed -E 's/; (Binary|Shader|Stack|Local)[^;]*//g' | cut -c1-300
  done
  for w in 128 256 512 768 1024; do
    echo "== sponza bdpt camera wg $w"; BIDIR_EXP_WG_CAMERA=$w $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
    echo "== sponza bdpt light wg $w"; BIDIR_EXP_WG_LIGHT=$w $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
  done
  for b in .device/bidir-b74e "$B"; do
    $T "$b" render $SPB --integrator pt-nee --spp 16 -o /tmp/p-$(basename "$b").exr 2>&1 | grep -E "spp in"
    $T "$b" render $SPB --integrator bdpt --spp 16 -o /tmp/s-$(basename "$b").exr 2>&1 | grep -E "spp in"
  done
  echo "== same images"; "$B" diff /tmp/p-bidir-b74e.exr /tmp/p-bidir.exr | head -1; "$B" diff /tmp/s-bidir-b74e.exr /tmp/s-bidir.exr | head -1
  ;;
s22b)
  # Session 22: s22a measured BDPT's wavefront passes at twice session 21's time (caustic
  # scene 129.8 against 53.8 ms). Which commit: .device/bidir-b74e.gz (74e8721, before the
  # integer words), .device/bidir-head.gz (32eb0ea), .device/bidir.gz (this measurement
  # build, workgroups of 64), interleaved; caustic scene, Cornell box (wavefront), DamagedHelmet.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 60"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for b in .device/bidir-b74e .device/bidir-head "$B"; do
    echo "== info $(basename $b)"; $T "$b" info --kernels $CAU 2>&1 | grep -E "^bdpt:lvc=1 " | grep -E "wavefront" | sed -E 's/; (Binary|Shader|Stack|Local)[^;]*//g' | cut -c1-300
  done
  for r in 1 2; do
    for b in .device/bidir-b74e .device/bidir-head "$B"; do
      n=$(basename $b)
      echo "== caustic bdpt $n"; $T "$b" bench render $CAU $CB --spp 256 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      echo "== cornell bdpt wavefront $n"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt --wavefront on 2>&1 | grep -E "Msamples"
      echo "== helmet bdpt $n"; $T "$b" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      echo "== helmet pt-nee $n"; $T "$b" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s22a)
  # Session 22, a measurement build: the wavefront path kernels' workgroup size
  # (SPEC_WF_WG_SIZE, from BIDIR_EXP_WG_CAMERA / _LIGHT / _PT): a workgroup must fit on one
  # SM, so a larger one caps the registers the driver gives an invocation (1024: 64, 512: 128).
  # Registers per size, then textured Sponza 640x360 64 spp per size; then s21k's caustic runs.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for w in 64 256 512 768 1024; do
    echo "== info wg $w"; BIDIR_EXP_WG_CAMERA=$w BIDIR_EXP_WG_LIGHT=$w BIDIR_EXP_WG_PT=$w $T "$B" info --kernels $SP --sponza-sun-sky 2>&1 | grep -E "^(pt-nee|pt|bdpt:lvc=1) " | grep -E "wavefront" | sed -E 's/; (Binary|Shader|Stack|Local)[^;]*//g' | cut -c1-300
  done
  for r in 1 2; do
    for w in 64 256 512 768 1024; do
      echo "== sponza bdpt camera wg $w"; BIDIR_EXP_WG_CAMERA=$w $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
    done
    for w in 256 1024; do
      echo "== sponza bdpt light wg $w"; BIDIR_EXP_WG_LIGHT=$w $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
    done
    for w in 64 512 1024; do
      for i in pt-nee pt; do
        echo "== sponza $i pt wg $w"; BIDIR_EXP_WG_PT=$w $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
    done
  done
  ;;
s21l)
  # Pending (session 21 had no device time left): PtSuspended and BdptCameraState keep their
  # integers in integer words (0bf3d8a), the same bytes at the same offsets: check
  # that the H200's times did not move, against .device/bidir-base.gz = a build of 74e8721,
  # interleaved; the same images.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 90"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for r in 1 2; do
    for b in "$BASE" "$B"; do
      for i in bdpt pt-nee pt; do
        echo "== sponza $i $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
      echo "== cornell pt-nee $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
      echo "== cornell pt-nee paused queue $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator pt-nee --shadow-queue 192/24/pause 2>&1 | grep -E "Msamples"
    done
  done
  for b in "$BASE" "$B"; do
    $T "$b" render $SPB --integrator bdpt --spp 16 --sample-slices 4 -o /tmp/s-$(basename "$b").exr 2>&1 | grep -E "spp in"
  done
  echo "== same image"; "$B" diff /tmp/s-bidir-base.exr /tmp/s-bidir.exr | head -1
  ;;
s21k)
  # Session 21, the final build (f437688): BDPT's default on the caustic scene is now the
  # wavefront form; against the megakernels at equal time, against its committed reference
  # (the test's 128² camera, and 256²). Carried with the binary alone.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 60"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  CREF=assets/scenes/caustic/reference.exr
  echo "== caustic bdpt default"; $T "$B" bench render $CAU $CB --spp 256 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
  for s in 1 2; do
    for wf in auto off; do
      echo "== caustic 128 bdpt --time 1 seed $s wavefront $wf"; $T "$B" render $CAU --width 128 --height 128 --integrator bdpt --time 1 --seed $s --wavefront $wf --reference $CREF -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
    done
  done
  ;;
s21j)
  # Session 21, after s21i: submissions reuse their fences and command buffers (no vkCreateFence,
  # vkDestroyFence, vkFreeCommandBuffers per submission) against d768fe1's build
  # (.device/bidir-d768.gz), interleaved. Carried with .device/ref.exr, without the glTF samples.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 90"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for r in 1 2; do
    for b in .device/bidir-d768 "$B"; do
      echo "== cornell bdpt wavefront on $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt --wavefront on 2>&1 | grep -E "Msamples"
      echo "== caustic bdpt wavefront on $(basename "$b")"; $T "$b" bench render $CAU $CB --spp 256 --warmup 1 --runs 3 --integrator bdpt --wavefront on 2>&1 | grep -E "Msamples"
      for i in bdpt pt-nee; do
        echo "== sponza $i $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
    done
  done
  for b in .device/bidir-d768 "$B"; do
    echo "== sponza bdpt --time 1 $(basename "$b")"; $T "$b" render $SPB --integrator bdpt --time 1 --seed 1 -o /tmp/t.exr 2>&1 | grep -E "spp in"
    for wf in on off; do
      echo "== cornell bdpt --time 1 wavefront $wf $(basename "$b")"; $T "$b" render --integrator bdpt --time 1 --wavefront $wf --reference "$REF" -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
    done
  done
  ;;
s21i)
  # Session 21, after s21h: the same measurement with the gap split (host work outside
  # Context::execute, inside it before vkQueueSubmit, the submit, the release after the wait).
  # Carried as .device/bidir-s21i.gz alone.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  B=.device/bidir-s21i
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 90"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  echo "== cornell bdpt wavefront on"; BIDIR_HOST_PROFILE=1 $T "$B" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt --wavefront on 2>&1 | grep -E "^run"
  echo "== caustic bdpt wavefront on"; BIDIR_HOST_PROFILE=1 $T "$B" bench render $CAU $CB --spp 256 --warmup 1 --runs 3 --integrator bdpt --wavefront on 2>&1 | grep -E "^run"
  echo "== sponza bdpt wavefront on"; BIDIR_HOST_PROFILE=1 $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "^run"
  ;;
s21h)
  # Session 21, a measurement build (not committed): where the host's time per render goes
  # (BIDIR_HOST_PROFILE=1: submissions, recording, the work done while the GPU runs, the fence
  # waits, and the gaps between a wait's end and the next submission), profiling off.
  # Carried as s21c. The instrumentation was a few atomics in Context::execute and
  # record_commands, printed by bench render per run (docs/results.md).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 90"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for wf in on off; do
    echo "== cornell bdpt wavefront $wf"; BIDIR_HOST_PROFILE=1 $T "$B" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt --wavefront $wf 2>&1 | grep -E "^run|Msamples"
    echo "== caustic bdpt wavefront $wf"; BIDIR_HOST_PROFILE=1 $T "$B" bench render $CAU $CB --spp 256 --warmup 1 --runs 3 --integrator bdpt --wavefront $wf 2>&1 | grep -E "^run|Msamples"
    echo "== sponza bdpt wavefront $wf"; BIDIR_HOST_PROFILE=1 $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt --wavefront $wf 2>&1 | grep -E "^run|Msamples"
    echo "== sponza pt-nee wavefront $wf"; BIDIR_HOST_PROFILE=1 $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator pt-nee --wavefront $wf 2>&1 | grep -E "^run|Msamples"
  done
  ;;
s21g)
  # Session 21, the final build: the wavefront forms against the megakernels where the
  # megakernels are the default (Cornell box, caustic scene, rough Cornell), interleaved; the
  # driver's compile statistics of the textured Sponza's kernels. Carried as s21c.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 90"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  RC="assets/scenes/rough-cornell/rough-cornell.obj"
  for r in 1 2; do
    for wf in off on; do
      for i in bdpt pt-nee; do
        echo "== cornell $i wavefront $wf"; $T "$B" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator $i --wavefront $wf 2>&1 | grep -E "Msamples"
        echo "== caustic $i wavefront $wf"; $T "$B" bench render $CAU $CB --spp 256 --warmup 1 --runs 3 --integrator $i --wavefront $wf 2>&1 | grep -E "Msamples"
        echo "== rough cornell $i wavefront $wf"; $T "$B" bench render $RC $CB --spp 256 --warmup 1 --runs 3 --integrator $i --wavefront $wf 2>&1 | grep -E "Msamples"
      done
    done
  done
  echo "== kernel statistics, textured Sponza"; $T "$B" info --kernels $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 2>&1 | grep -E "^(pt-nee|bdpt:lvc=1) " | grep -iE "wavefront|trace" | sed -E 's/; (Binary|Shader|Stack|Local)[^;]*//g' | head -20
  ;;
s21f)
  # Session 21, the final build (refill 16 in the wavefront integrators' trace kernels)
  # against fc53e19's build (.device/bidir-s20g.gz), interleaved: the integrators, the
  # megakernels in the same run, `bench traversal` (its persistent kernels now reset their own
  # ray counters), `--time 1`. Carried as s21a.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 90"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2; do
    for b in .device/bidir-s20g "$B"; do
      for i in bdpt pt-nee pt; do
        echo "== sponza textured $i $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
      for i in bdpt pt-nee; do
        echo "== DamagedHelmet $i $(basename "$b")"; $T "$b" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
        echo "== cornell $i wavefront on $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator $i --wavefront on 2>&1 | grep -E "Msamples"
      done
    done
  done
  for i in bdpt pt-nee pt; do
    echo "== sponza textured $i megakernels"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i --wavefront off 2>&1 | grep -E "Msamples"
  done
  echo "== cornell bdpt megakernels"; $T "$B" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
  for b in .device/bidir-s20g "$B"; do
    for c in "--bvh bvh4 --leaf-size 3 --quality 4" "--bvh bvh4 --leaf-size 3 --quality 3 --refill 28" "--bvh bvh4 --leaf-size 3 --quality 4 --refill 28"; do
      echo "== traversal sponza $c $(basename "$b")"; $T "$b" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  for s in 1 2; do
    for b in .device/bidir-s20g "$B"; do
      for i in bdpt pt-nee; do
        echo "== sponza textured --time 1 $i seed $s $(basename "$b")"; $T "$b" render $SPB --integrator $i --time 1 --seed $s -o /tmp/t.exr 2>&1 | grep -E "spp in"
      done
    done
  done
  ;;
s21e)
  # Session 21, after s21d (same measurement build): dynamic fetch's refill in the wavefront
  # integrators' trace kernels, 28 (default) against 20, 16 and 12 lanes, on the textured
  # Sponza and DamagedHelmet. Carried as s21c.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2; do
    for l in "" 20 16 12; do
      for i in pt-nee bdpt; do
        echo "== sponza textured $i refill=$l"; BIDIR_WF_REFILL=$l $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
        echo "== DamagedHelmet $i refill=$l"; BIDIR_WF_REFILL=$l $T "$B" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
    done
  done
  ;;
s21d)
  # Session 21, a measurement build (not committed; refill 16 kept): the wavefront integrators' persistent
  # trace kernels' workgroups (BIDIR_WF_GROUPS; default the resident 4,224) and dynamic
  # fetch's refill (BIDIR_WF_REFILL; default 28 lanes), now that a launch's two traces run at
  # once. Carried as s21c.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for r in 1 2; do
    for cfg in "x x" "2112 x" "3168 x" "8448 x" "x 20" "x 24" "x 32"; do
      set -- $cfg; g=$1; l=$2; [ "$g" = x ] && g=; [ "$l" = x ] && l=
      for i in pt-nee bdpt; do
        echo "== sponza textured $i groups=$g refill=$l"; BIDIR_WF_GROUPS=$g BIDIR_WF_REFILL=$l $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
    done
  done
  ;;
s21c)
  # Session 21, a measurement build: the wavefront path tracer's slots as two halves whose
  # launches interleave (each half's path kernel beside the other half's traces;
  # BIDIR_WF_HALVES=1) against one set of slots, same binary, interleaved; the same images.
  # Carried as s21a without bidir-s20g.gz. The halves lost 1-6 % (not kept; docs/results.md).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2; do
    for h in "" 1; do
      for i in pt-nee pt; do
        echo "== sponza textured $i halves=$h"; BIDIR_WF_HALVES=$h $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples|trace|wavefront"
      done
      echo "== DamagedHelmet pt-nee halves=$h"; BIDIR_WF_HALVES=$h $T "$B" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
      echo "== cornell pt-nee wavefront on halves=$h"; BIDIR_WF_HALVES=$h $T "$B" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator pt-nee --wavefront on 2>&1 | grep -E "Msamples"
    done
  done
  for h in "" 1; do
    BIDIR_WF_HALVES=$h $T "$B" render $SPB --integrator pt-nee --spp 16 --sample-slices 4 -o /tmp/p-$h.exr 2>&1 | grep -E "spp in"
  done
  echo "== same image"; "$B" diff /tmp/p-.exr /tmp/p-1.exr | head -1
  for s in 1 2; do
    for h in "" 1; do
      echo "== sponza textured --time 1 pt-nee seed $s halves=$h"; BIDIR_WF_HALVES=$h $T "$B" render $SPB --integrator pt-nee --time 1 --seed $s -o /tmp/t.exr 2>&1 | grep -E "spp in"
    done
  done
  ;;
s21b)
  # Session 21, after s21a: each BDPT launch's last workgroup sizes the next launch and its
  # traces (no sizing kernel), the two traces run without a barrier between them, and the
  # persistent trace kernels leave their ray counters at 0 themselves (the path tracer's kernel
  # no longer resets them); against fc53e19's build (.device/bidir-s20g.gz), interleaved, with
  # the megakernels (`--wavefront off`) in the same run; the same images. Carried as s21a.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2; do
    for b in .device/bidir-s20g "$B"; do
      for i in bdpt pt-nee; do
        echo "== sponza textured $i $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples|trace|wavefront|wf_"
        echo "== DamagedHelmet $i $(basename "$b")"; $T "$b" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples|trace|wavefront|wf_"
        echo "== cornell $i wavefront on $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator $i --wavefront on 2>&1 | grep -E "Msamples"
      done
    done
  done
  for i in bdpt pt-nee; do
    echo "== sponza textured $i megakernels"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i --wavefront off 2>&1 | grep -E "Msamples"
  done
  for wf in off on; do
    $T "$B" render $SPB --integrator bdpt --spp 16 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/s-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render $HB --integrator bdpt --spp 64 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/h-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render $CB --integrator bdpt --spp 64 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/c-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render $SPB --integrator pt-nee --spp 16 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/p-$wf.exr 2>&1 | grep -E "spp in"
  done
  echo "== same image: sponza, helmet, cornell bdpt; sponza pt-nee"; for x in s h c p; do "$B" diff /tmp/$x-on.exr /tmp/$x-off.exr | head -1; done
  for s in 1 2; do
    for b in .device/bidir-s20g "$B"; do
      for i in bdpt pt-nee; do
        echo "== sponza textured --time 1 $i seed $s $(basename "$b")"; $T "$b" render $SPB --integrator $i --time 1 --seed $s -o /tmp/t.exr 2>&1 | grep -E "spp in"
      done
    done
  done
  ;;
s21a)
  # Session 21: the trace kernels of BDPT's wavefront launches dispatched indirectly, sized by
  # wf_dispatch.comp from the rays each launch queued (no full persistent launch in a pass's
  # tail), against fc53e19's build (.device/bidir-s20g.gz), interleaved; the same images.
  # Carried as s20f with bidir-s20g.gz.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384 --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2"
  for r in 1 2; do
    for b in .device/bidir-s20g "$B"; do
      echo "== sponza textured bdpt $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples|trace|wavefront|wf_"
      echo "== DamagedHelmet bdpt $(basename "$b")"; $T "$b" bench render $HB --spp 256 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples|trace|wavefront|wf_"
      echo "== cornell bdpt wavefront on $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 1 --runs 3 --integrator bdpt --wavefront on 2>&1 | grep -E "Msamples"
    done
  done
  for wf in off on; do
    $T "$B" render $SPB --integrator bdpt --spp 16 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/s-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render $HB --integrator bdpt --spp 64 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/h-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render $CB --integrator bdpt --spp 64 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/c-$wf.exr 2>&1 | grep -E "spp in"
  done
  echo "== same image: sponza, helmet, cornell"; for x in s h c; do "$B" diff /tmp/$x-on.exr /tmp/$x-off.exr | head -1; done
  for s in 1 2; do
    for b in .device/bidir-s20g "$B"; do
      echo "== sponza textured --time 1 bdpt seed $s $(basename "$b")"; $T "$b" render $SPB --integrator bdpt --time 1 --seed $s -o /tmp/t.exr 2>&1 | grep -E "spp in"
    done
  done
  ;;
s20g)
  # Session 20, after s20f: the wavefront path tracer's kernel resets the trace kernels' ray
  # counters itself (no fills), against s20f's build (.device/bidir-s20f.gz), interleaved; the
  # same images. Carried as s20f with bidir-s20f.gz.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384"
  for r in 1 2; do
    for b in .device/bidir-s20f "$B"; do
      for i in pt-nee pt; do
        echo "== sponza textured $i $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
      done
      echo "== DamagedHelmet pt-nee $(basename "$b")"; $T "$b" bench render $HB --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --spp 256 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
      echo "== cornell pt-nee wavefront on $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator pt-nee --wavefront on 2>&1 | grep -E "Msamples"
      echo "== sponza textured bdpt $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
    done
  done
  for wf in off on; do
    $T "$B" render $SPB --integrator pt-nee --spp 64 --bvh bvh4 --wavefront $wf -o /tmp/s-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render $CB --integrator pt-nee --spp 256 --bvh bvh4 --wavefront $wf -o /tmp/c-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render $SPB --integrator bdpt --spp 16 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/b-$wf.exr 2>&1 | grep -E "spp in"
  done
  echo "== same image: sponza pt-nee, cornell pt-nee, sponza bdpt"; for x in s c b; do "$B" diff /tmp/$x-on.exr /tmp/$x-off.exr | head -1; done
  for s in 1 2; do
    for b in .device/bidir-s20f "$B"; do
      echo "== sponza textured --time 1 pt-nee seed $s $(basename "$b")"; $T "$b" render $SPB --integrator pt-nee --time 1 --seed $s -o /tmp/t.exr 2>&1 | grep -E "spp in"
    done
  done
  ;;
s20f)
  # Session 20, after s20e: the dispatch-sizing kernel also resets the persistent trace
  # kernels' ray counters (no fill and barrier per trace), against s20e's build
  # (.device/bidir-s20e.gz), interleaved; the same images (lavapipe's trace kernels are not
  # persistent: only this device runs that path). Carried as s20e with bidir-s20e.gz.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384"
  for r in 1 2; do
    for b in .device/bidir-s20e "$B"; do
      echo "== sponza textured bdpt $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      echo "== DamagedHelmet bdpt $(basename "$b")"; $T "$b" bench render $HB --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --spp 256 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
    done
  done
  for wf in off on; do
    $T "$B" render $SPB --integrator bdpt --spp 16 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/s-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render $HB --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --integrator bdpt --spp 64 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/h-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render $CB --integrator bdpt --spp 64 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/c-$wf.exr 2>&1 | grep -E "spp in"
  done
  echo "== same image: sponza, helmet, cornell"; for x in s h c; do "$B" diff /tmp/$x-on.exr /tmp/$x-off.exr | head -1; done
  for s in 1 2; do
    for b in .device/bidir-s20e "$B"; do
      echo "== sponza textured --time 1 bdpt seed $s $(basename "$b")"; $T "$b" render $SPB --integrator bdpt --time 1 --seed $s -o /tmp/t.exr 2>&1 | grep -E "spp in"
    done
  done
  ;;
s20e)
  # Session 20, the final build: the lists of live slots in the shared queues, for BDPT's
  # passes only; against s20c's build, interleaved. Carried as s20d.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384"
  for r in 1 2; do
    for b in .device/bidir-s20c "$B"; do
      echo "== sponza textured pt-nee $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
      echo "== cornell pt-nee wavefront on $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator pt-nee --wavefront on 2>&1 | grep -E "Msamples"
      echo "== sponza textured bdpt $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      echo "== DamagedHelmet bdpt $(basename "$b")"; $T "$b" bench render $HB --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --spp 256 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
    done
  done
  for s in 1 2; do
    for b in .device/bidir-s20c "$B"; do
      echo "== sponza textured --time 1 pt-nee seed $s $(basename "$b")"; $T "$b" render $SPB --integrator pt-nee --time 1 --seed $s -o /tmp/t.exr 2>&1 | grep -E "spp in"
      echo "== sponza textured --time 1 bdpt seed $s $(basename "$b")"; $T "$b" render $SPB --integrator bdpt --time 1 --seed $s -o /tmp/t.exr 2>&1 | grep -E "spp in"
    done
  done
  ;;
s20d)
  # Session 20, after s20c: a measurement build (not kept) in which the wavefront path tracer
  # ran only its live slots too (the queues' slot lists and indirect dispatches, shared with
  # BDPT's passes), against s20c's build (.device/bidir-s20c.gz), interleaved. Carried as s20c
  # with bidir-s20c.gz.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  K="Msamples|^pt|^trace|^wf_"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384"
  RC="assets/scenes/rough-cornell/rough-cornell.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  for r in 1 2; do
    for b in .device/bidir-s20c "$B"; do
      for i in pt-nee pt; do
        echo "== sponza textured $i $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator $i 2>&1 | grep -E "$K"
      done
      echo "== DamagedHelmet pt-nee $(basename "$b")"; $T "$b" bench render $HB --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --spp 256 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
      echo "== rough cornell pt-nee $(basename "$b")"; $T "$b" bench render $RC --spp 1024 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
      echo "== cornell pt-nee wavefront on $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator pt-nee --wavefront on 2>&1 | grep -E "$K"
      echo "== sponza textured bdpt $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
    done
  done
  echo "== cornell pt-nee megakernel"; $T "$B" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator pt-nee 2>&1 | grep -E "Msamples"
  for wf in off on; do
    $T "$B" render $SPB --integrator pt-nee --spp 64 --bvh bvh4 --wavefront $wf -o /tmp/s-$wf.exr 2>&1 | grep -E "spp in"
  done
  echo "== same image: sponza pt-nee"; "$B" diff /tmp/s-on.exr /tmp/s-off.exr | head -5
  for s in 1 2; do
    for b in .device/bidir-s20c "$B"; do
      echo "== sponza textured --time 1 pt-nee seed $s $(basename "$b")"; $T "$b" render $SPB --integrator pt-nee --time 1 --seed $s -o /tmp/t.exr 2>&1 | grep -E "spp in"
    done
  done
  ;;
s20c)
  # Session 20, after s20b: each wavefront pass's first batch recorded while the GPU runs the
  # submission before it, against s20b's build (.device/bidir-s20b.gz), interleaved; wall
  # times and equal time. Carried as s20a with bidir-s20b.gz in place of bidir-s19.gz.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --width 384 --height 384"
  for r in 1 2; do
    for b in .device/bidir-s20b "$B"; do
      echo "== sponza textured bdpt $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      echo "== DamagedHelmet bdpt $(basename "$b")"; $T "$b" bench render $HB --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --spp 256 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      echo "== sponza textured pt-nee $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
    done
  done
  timeout -k 5 120 "$B" render $SPB --integrator pt-nee --time 40 --seed 99 -o /tmp/ref.exr 2>&1 | grep -E "spp in"
  for s in 1 2; do
    for b in .device/bidir-s20b "$B"; do
      echo "== sponza textured --time 1 bdpt seed $s $(basename "$b")"; $T "$b" render $SPB --integrator bdpt --time 1 --seed $s --reference /tmp/ref.exr -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
      echo "== DamagedHelmet --time 1 bdpt seed $s $(basename "$b")"; $T "$b" render $HB --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --integrator bdpt --time 1 --seed $s -o /tmp/t.exr 2>&1 | grep -E "spp in"
    done
  done
  for wf in off on; do
    $T "$B" render $SPB --integrator bdpt --spp 16 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/s-$wf.exr 2>&1 | grep -E "spp in"
  done
  echo "== same image: sponza"; "$B" diff /tmp/s-on.exr /tmp/s-off.exr | head -2
  ;;
s20b)
  # Session 20, after s20a: both wavefront passes run only the slots whose paths are live
  # (slot lists and indirect dispatches). Against session 19's build (camera pass alone) and
  # the megakernels, interleaved; the Cornell box and the caustic scene too. Carried as s20a.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  K="Msamples|^bdpt|^trace|^wf_|^lvc|^scan|^film"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  for r in 1 2; do
    for b in .device/bidir-s19 "$B"; do
      echo "== sponza textured bdpt $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "$K"
      echo "== DamagedHelmet bdpt $(basename "$b")"; $T "$b" bench render .device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --spp 256 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "$K"
    done
    for wf in off on; do
      echo "== cornell bdpt wavefront $wf"; $T "$B" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator bdpt --wavefront $wf 2>&1 | grep -E "$K"
      echo "== caustic bdpt wavefront $wf"; $T "$B" bench render $CAU $CB --spp 256 --warmup 1 --runs 3 --integrator bdpt --wavefront $wf 2>&1 | grep -E "Msamples"
    done
  done
  echo "== sponza textured bdpt megakernels"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt --wavefront off 2>&1 | grep -E "Msamples"
  for sl in 8 12 32; do
    echo "== sponza textured bdpt --sample-slices $sl"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt --sample-slices $sl 2>&1 | grep -E "Msamples"
  done
  for wf in off on; do
    $T "$B" render $SPB --integrator bdpt --spp 16 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/s-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render $CB --integrator bdpt --spp 64 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/c-$wf.exr 2>&1 | grep -E "spp in"
  done
  echo "== same image: sponza, cornell"; "$B" diff /tmp/s-on.exr /tmp/s-off.exr | head -2; "$B" diff /tmp/c-on.exr /tmp/c-off.exr | head -2
  timeout -k 5 120 "$B" render $SPB --integrator pt-nee --time 40 --seed 99 -o /tmp/ref.exr 2>&1 | grep -E "spp in"
  for s in 1 2; do
    for b in .device/bidir-s19 "$B"; do
      echo "== sponza textured --time 1 bdpt seed $s $(basename "$b")"; $T "$b" render $SPB --integrator bdpt --time 1 --seed $s --reference /tmp/ref.exr -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
    done
  done
  ;;
s20a)
  # Session 20: BDPT's light pass as a wavefront too (`--wavefront on`: both passes) against
  # session 19's build (.device/bidir-s19.gz, 72b1857: the camera pass alone), interleaved;
  # carried as s19a. Then slices, the same image on this device, and equal time.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  K="Msamples|^bdpt|^trace|^lvc|^scan|^film"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  HB=".device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun 0.4,1,0.7;2.5,2.5,2.5;2 --width 384 --height 384"
  for r in 1 2; do
    for b in .device/bidir-s19 "$B"; do
      echo "== sponza textured bdpt $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "$K"
      echo "== DamagedHelmet bdpt $(basename "$b")"; $T "$b" bench render .device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --spp 256 --warmup 1 --runs 3 --integrator bdpt 2>&1 | grep -E "Msamples"
      for i in bdpt vcm; do
        echo "== cornell $i $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator $i 2>&1 | grep -E "Msamples"
      done
    done
  done
  for sl in 12 32; do
    echo "== sponza textured bdpt --sample-slices $sl"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt --sample-slices $sl 2>&1 | grep -E "Msamples"
  done
  for wf in off on; do
    $T "$B" render $SPB --integrator bdpt --spp 16 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/s-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render .device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --integrator bdpt --spp 64 --sample-slices 4 --bvh bvh4 --wavefront $wf -o /tmp/h-$wf.exr 2>&1 | grep -E "spp in"
  done
  echo "== same image: sponza, helmet"; "$B" diff /tmp/s-on.exr /tmp/s-off.exr | head -5; "$B" diff /tmp/h-on.exr /tmp/h-off.exr | head -5
  timeout -k 5 120 "$B" render $SPB --integrator pt-nee --time 40 --seed 99 -o /tmp/ref.exr 2>&1 | grep -E "spp in"
  for s in 1 2; do
    for b in .device/bidir-s19 "$B"; do
      echo "== sponza textured --time 1 bdpt seed $s $(basename "$b")"; $T "$b" render $SPB --integrator bdpt --time 1 --seed $s --reference /tmp/ref.exr -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
    done
  done
  ;;
s19b)
  # Session 19: after s19a. The camera megakernel compiled as before (its loop body an
  # included fragment again) against 577dd35's build; the wavefront camera pass's slices on
  # the textured Sponza (the default now lets its light-vertex store grow to a sixteenth of
  # the device's memory); equal time against a 40 s pt-nee reference. Carried as s19a.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPB="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"
  for b in .device/bidir-s18 "$B" .device/bidir-s18 "$B"; do
    for i in bdpt vcm; do
      echo "== cornell $i $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator $i 2>&1 | grep -E "Msamples"
    done
    echo "== sponza textured bdpt megakernel $(basename "$b")"; $T "$b" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt --wavefront off 2>&1 | grep -E "Msamples"
  done
  for r in 1 2; do
    for sl in default 12 32; do
      a=""; [ "$sl" = default ] || a="--sample-slices $sl"
      echo "== sponza textured bdpt wavefront on slices $sl"; $T "$B" bench render $SPB --spp 64 --warmup 1 --runs 3 --integrator bdpt --wavefront on $a 2>&1 | grep -E "Msamples|^bdpt|^trace"
    done
  done
  for wf in off on off on; do
    echo "== DamagedHelmet bdpt wavefront $wf"; $T "$B" bench render .device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --spp 256 --warmup 1 --runs 3 --integrator bdpt --wavefront $wf 2>&1 | grep -E "Msamples"
  done
  timeout -k 5 120 "$B" render $SPB --integrator pt-nee --time 40 --seed 99 -o /tmp/ref.exr 2>&1 | grep -E "spp in"
  for s in 1 2; do
    for i in "bdpt --wavefront off" "bdpt --wavefront on" "pt-nee"; do
      echo "== sponza textured --time 1 $i seed $s"; $T "$B" render $SPB --integrator $i --time 1 --seed $s --reference /tmp/ref.exr -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
    done
  done
  ;;
s19a)
  # Session 19: BDPT's camera pass as a wavefront (`--wavefront on`) against the megakernel,
  # interleaved; carried as s18c (textured Sponza and three glTF samples, no base build):
  # the textured Sponza under sun and sky, DamagedHelmet, the Cornell box and the caustic
  # scene; then the same images (fixed slices) and the Cornell box at equal time.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  K="Msamples|^bdpt|^trace|^shadow|^lvc|^scan|^film"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  for r in 1 2; do
    for wf in off on; do
      echo "== sponza textured 640x360 bdpt wavefront $wf"; $T "$B" bench render $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 64 --warmup 1 --runs 3 --integrator bdpt --wavefront $wf 2>&1 | grep -E "$K"
    done
  done
  for sl in 2 4 12; do
    echo "== sponza textured bdpt wavefront on --sample-slices $sl"; $T "$B" bench render $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 64 --warmup 1 --runs 3 --integrator bdpt --wavefront on --sample-slices $sl 2>&1 | grep -E "Msamples"
  done
  for wf in off on off on; do
    echo "== DamagedHelmet bdpt wavefront $wf"; $T "$B" bench render .device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --spp 256 --warmup 1 --runs 3 --integrator bdpt --wavefront $wf 2>&1 | grep -E "Msamples"
    echo "== cornell bdpt wavefront $wf"; $T "$B" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator bdpt --wavefront $wf 2>&1 | grep -E "$K"
    echo "== caustic bdpt wavefront $wf"; $T "$B" bench render $CAU $CB --spp 256 --warmup 1 --runs 3 --integrator bdpt --wavefront $wf 2>&1 | grep -E "Msamples"
  done
  for wf in off on; do
    $T "$B" render $CB --integrator bdpt --spp 64 --sample-slices 4 --wavefront $wf -o /tmp/c-$wf.exr 2>&1 | grep -E "spp in"
    $T "$B" render .device/scenes/gltf/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --integrator bdpt --spp 64 --sample-slices 4 --wavefront $wf -o /tmp/h-$wf.exr 2>&1 | grep -E "spp in"
  done
  echo "== same image: cornell, helmet"; "$B" diff /tmp/c-on.exr /tmp/c-off.exr | head -5; "$B" diff /tmp/h-on.exr /tmp/h-off.exr | head -5
  for wf in off on off on; do
    echo "== cornell bdpt --time 1 wavefront $wf"; $T "$B" render --integrator bdpt --time 1 --wavefront $wf --reference "$REF" -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
  done
  # The camera megakernel after its path code moved to bdpt_camera_path.glsl, against the
  # build of session 18's last commit (.device/bidir-s18.gz, 577dd35), interleaved.
  if [ -x .device/bidir-s18 ]; then
    for b in .device/bidir-s18 "$B" .device/bidir-s18 "$B"; do
      for i in bdpt vcm; do
        echo "== cornell $i $(basename "$b")"; $T "$b" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator $i 2>&1 | grep -E "Msamples"
      done
      echo "== sponza textured bdpt $(basename "$b")"; $T "$b" bench render $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 64 --warmup 1 --runs 3 --integrator bdpt --wavefront off 2>&1 | grep -E "Msamples"
    done
  fi
  ;;
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
  # #13's budget: before the materials merge (fc01b5d) against this commit, interleaved
  if [ -x "$PRE" ]; then
    for i in pt-nee bdpt; do
      for b in "$PRE" "$B" "$PRE" "$B" "$PRE" "$B"; do
        echo "== $i $(basename "$b") --time 2"
        "$b" render --integrator "$i" --time 2 --reference "$REF" -o /tmp/x.exr 2>&1 | grep -E "spp in|RMSE"
      done
    done
  fi
  # #17: the integrators over the compressed wide BVH on the GPU
  for i in pt-nee bdpt; do
    for l in bvh2 cwbvh; do
      echo "== $i --bvh $l"
      "$B" bench render $CB --integrator "$i" --bvh $l --spp 1024 --warmup 2 --runs 5 | head -4
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
  "$B" converge --reference "$REF" --integrators bdpt,vcm,vcm:no-merge --spp-points 64,1024,8192 --seeds 2 --out "$OUT/cornell-spp" 2>&1 | grep -iE "rmse|stability"
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
    "$B" diff "$OUT/rough-$i.exr" assets/scenes/rough-cornell/reference.exr --blocks 16 2>&1 | tail -24
  done
  "$B" render $RC --width 256 --height 256 --integrator bdpt --time 240 --seed 4242 -o "$OUT/rough-ref.exr" 2>&1 | grep -E "spp in"
  "$B" converge $RC --width 256 --height 256 --reference "$OUT/rough-ref.exr" --integrators pt-nee,bdpt --time 10 --seeds 2 --out "$OUT/rough-chart" 2>&1 | grep -iE "rmse|stability"
  ;;
trav)
  # #17: Sponza traversal (geometry only) and the integrators over either layout.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  for a in "" "--bvh cwbvh" "--bvh cwbvh --tri-test woop"; do
    echo "== bench traversal $a"
    "$B" bench traversal "$SP" --camera CameraMain $a 2>&1 | grep -vE "^\s*$" | tail -14
  done
  for l in bvh2 cwbvh; do
    for i in pt-nee bdpt; do
      echo "== sponza $i --bvh $l"
      "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --bvh $l --spp 64 --warmup 1 --runs 3 2>&1 | grep -v warning | head -4
    done
  done
  ;;
defaults)
  # #16: path regeneration and the BVH layout of the path tracers per scene (the table of
  # docs/results.md, "Cornell box, session 6"), against the last binary measured (BASE);
  # #15: the merge query against PREV (the binary before it) and its radius sensitivity.
  PREV=${PREV:-$PWD/.device/bidir-prev}
  bench() { echo "== $*"; "$@" --spp 1024 --warmup 2 --runs 5 2>&1 | head -4 | grep -E "Msamples|^(pt|bdpt_camera|bdpt_light)"; }
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  SDS="assets/scenes/sds/sds.obj --eye 0.9,1.3,-3.2 --target -0.4,0.4,0 --up 0,1,0 --fov 50 --width 256 --height 256"
  RC="assets/scenes/rough-cornell/rough-cornell.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  for S in "$CB" "$CAU" "$SDS" "$RC"; do
    for i in pt-nee pt; do
      bench "$BASE" bench render $S --integrator $i
      for l in bvh2 cwbvh; do for r in on off; do
        bench "$B" bench render $S --integrator $i --bvh $l --path-regeneration $r
      done; done
    done
  done
  for b in "$PREV" "$B" "$PREV" "$B"; do
    bench "$b" bench render $CB --integrator vcm
  done
  bench "$B" bench render $CB --integrator bdpt
  for rad in 0.0005 0.002; do bench "$B" bench render $CB --integrator vcm --vcm-radius $rad; done
  "$B" info --kernels 2>&1 | grep -E "Register" | cut -c1-90
  "$B" info --kernels $CAU 2>&1 | grep -E "Register" | cut -c1-90
  ;;
final)
  # The defaults chosen from `defaults`: #16's table, #13's budget at equal settings.
  bench() { echo "== $*"; "$@" --spp 1024 --warmup 2 --runs 5 2>&1 | head -4 | grep -E "Msamples"; }
  for i in pt pt-nee bdpt; do bench "$B" bench render $CB --integrator $i; done
  bench "$BASE" bench render $CB --integrator pt-nee
  for i in pt pt-nee bdpt bdpt:full; do for t in 0.1 1 2; do
    echo "== $i --time $t"
    "$B" render --integrator $i --time $t --reference "$REF" -o /tmp/x.png 2>&1 | grep -E "spp in|RMSE"
  done; done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  for b in "$BASE" "$B"; do for i in pt pt-nee bdpt bdpt:full; do
    echo "== caustic $(basename "$b") $i --time 1"
    "$b" render $CAU --integrator $i --time 1 --reference assets/scenes/caustic/reference.exr -o /tmp/x.png 2>&1 | grep -E "spp in|RMSE"
  done; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  for b in "$BASE" "$B"; do
    echo "== sponza pt-nee $(basename "$b")"
    "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 2>&1 | grep Msamples
  done
  if [ -x "$PRE" ]; then
    for a in "" "--bvh bvh2"; do
      for b in "$PRE" "$B" "$PRE" "$B" "$PRE" "$B"; do
        x=""; [ "$b" = "$B" ] && x="$a --rr-depth 3 --sampler sobol:all"
        echo "== pt-nee $(basename "$b") $x --time 2"
        "$b" render --integrator pt-nee $x --time 2 -o /tmp/x.png 2>&1 | grep -E "spp in"
      done
    done
  fi
  "$B" info --kernels 2>&1 | grep -E "Register" | cut -c1-70
  ;;
light-paths)
  # (run in session 7)
  # #16: fewer light paths per iteration for bdpt (the light pass is a third of its GPU time
  # on the Cornell box; per sample the Cornell image is as good with a quarter of them on
  # lavapipe). Equal time, Cornell box and caustic scene, ratio 1 / 0.5 / 0.25.
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  for lp in 1 0.5 0.25; do
    echo "== bdpt --light-paths $lp"
    "$B" bench render $CB --integrator bdpt --light-paths $lp --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples|bdpt_"
    "$B" converge --reference "$REF" --integrators bdpt --light-paths $lp --time 2 --seeds 2 --out "$OUT/cornell-lp$lp" 2>&1 | grep -iE "stability"
    "$B" converge $CAU --reference assets/scenes/caustic/reference.exr --integrators bdpt --light-paths $lp --time 2 --seeds 2 --out "$OUT/caustic-lp$lp" 2>&1 | grep -iE "stability"
  done
  "$B" bench traversal "${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}" --camera CameraMain --quality 3 2>&1 | grep -E "build|primary|shadow|diffuse"
  (cd "$OUT" && tar czf csv.tgz $(find . -name '*.csv'))
  ;;
vcm-first)
  # #15 (session 7): merging at the first continuous camera vertex (`vcm`) against merging at
  # every one (`vcm:merge-all`, session 6's vcm) and bdpt: cost per 1024 spp, then the
  # equal-time charts of docs/results.md, "VCM on the H200", with both.
  SDS="assets/scenes/sds/sds.obj --eye 0.9,1.3,-3.2 --target -0.4,0.4,0 --up 0,1,0 --fov 50 --width 256 --height 256"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  for i in bdpt vcm vcm:merge-all bdpt vcm vcm:merge-all; do
    echo "== $i"
    "$B" bench render $CB --integrator $i --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples|bdpt_|merge"
  done
  for t in ${TIMES:-1 10}; do
    "$B" converge --reference "$REF" --integrators pt-nee,bdpt,vcm,vcm:merge-all --time $t --seeds 2 --out "$OUT/cornell-$t" 2>&1 | grep -iE "rmse|stability"
    "$B" converge $SDS --reference assets/scenes/sds/reference-h200-vcm.exr --integrators pt-nee,bdpt,vcm,vcm:merge-all --time $t --seeds 2 --out "$OUT/sds-$t" 2>&1 | grep -iE "rmse|stability"
    "$B" converge $CAU --reference assets/scenes/caustic/reference.exr --integrators pt-nee,bdpt,vcm,vcm:merge-all --time $t --seeds 2 --out "$OUT/caustic-$t" 2>&1 | grep -iE "rmse|stability"
  done
  "$B" info --kernels 2>&1 | grep -E "Register" | cut -c1-90
  # The device tool brings back at most 8 files: the CSVs in one archive (charts: bidir chart).
  (cd "$OUT" && tar czf csv.tgz $(find . -name '*.csv'))
  ;;
bvh-quality)
  # #17 (session 7): the integrators on Sponza over a BVH built at quality 3 (bench
  # traversal there: diffuse 1.47 against 1.30 Grays/s at quality 2).
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  for q in 2 3 2 3; do for i in pt-nee bdpt; do
    echo "== sponza $i --bvh-quality $q"
    "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --bvh-quality $q --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples|build"
  done; done
  ;;
bdpt-joins)
  # #16 (session 7): connections per camera vertex (lvc: the mean stored per light path,
  # lvc=1: one) against light paths per pixel, at equal time on the Cornell box and the
  # caustic scene; bdpt at its defaults in the same run.
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  for c in "bdpt:lvc 1" "bdpt:lvc=1 1" "bdpt:lvc=1 0.25" "bdpt:lvc=2 0.25"; do
    set -- $c
    echo "== $1 --light-paths $2"
    "$B" bench render $CB --integrator $1 --light-paths $2 --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples|bdpt_"
    "$B" converge --reference "$REF" --integrators $1 --light-paths $2 --time 2 --seeds 2 --out "$OUT/cornell" 2>&1 | grep -E "^bdpt"
    "$B" converge $CAU --reference assets/scenes/caustic/reference.exr --integrators $1 --light-paths $2 --time 2 --seeds 2 --out "$OUT/caustic" 2>&1 | grep -E "^bdpt"
  done
  ;;
join-default)
  # #16/#15 (session 7): bdpt and vcm with one connection per camera vertex (the new default,
  # bdpt = bdpt:lvc=1) against the old default (bdpt:lvc) and pt-nee, 2 s, two seeds.
  SDS="assets/scenes/sds/sds.obj --eye 0.9,1.3,-3.2 --target -0.4,0.4,0 --up 0,1,0 --fov 50 --width 256 --height 256"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  for i in bdpt vcm; do
    echo "== $i"
    "$B" bench render $CB --integrator $i --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples|bdpt_|vcm_"
  done
  "$B" converge --reference "$REF" --integrators pt-nee,bdpt,bdpt:lvc,vcm --time 2 --seeds 2 --out "$OUT/cornell" 2>&1 | grep -E "stability"
  "$B" converge $CAU --reference assets/scenes/caustic/reference.exr --integrators bdpt,bdpt:lvc,vcm --time 2 --seeds 2 --out "$OUT/caustic" 2>&1 | grep -E "stability"
  "$B" converge $SDS --reference assets/scenes/sds/reference-h200-vcm.exr --integrators bdpt,bdpt:lvc,vcm --time 2 --seeds 2 --out "$OUT/sds" 2>&1 | grep -E "stability"
  (cd "$OUT" && tar czf csv.tgz $(find . -name '*.csv'))
  ;;
driver-rt)
  # #17 (session 8): the driver's ray-tracing pipeline as the yardstick in the same run
  # (bench traversal --driver-rt: same rays, hit agreement); whether ncu profiles a Vulkan
  # compute kernel here. Each command under a timeout (a hang must not eat the call).
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 120"
  "$B" info 2>&1 | grep -E "NVIDIA|features"
  echo "== small, validation"
  $T env BIDIR_VALIDATION=1 "$B" bench traversal --driver-rt --width 64 --height 64 --warmup 0 --reps 5 2>&1
  echo "== cornell 1920x1080"
  $T "$B" bench traversal --driver-rt --width 1920 --height 1080 2>&1
  echo "== sponza (bvh2, the default)"
  $T "$B" bench traversal "$SP" --camera CameraMain --driver-rt --json "$OUT/sponza-driver-rt.json" 2>&1
  echo "== sponza, cwbvh woop quality 3"
  $T "$B" bench traversal "$SP" --camera CameraMain --bvh cwbvh --tri-test woop --quality 3 --driver-rt 2>&1
  echo "== ncu on a Vulkan compute kernel"
  timeout -k 5 60 ncu --clock-control none --launch-count 2 "$B" bench traversal --rays primary --warmup 0 --reps 5 2>&1 | tail -25
  ;;
int-slabs)
  # #17 (session 8): the slab tests on the distances' bits as integers (this commit's
  # default) against floats (--float-slabs for bench traversal; BASE = a build of the commit
  # before for the integrators), interleaved; the images must stay bit-identical.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  for r in 1 2; do
    for c in "--float-slabs" "" "--bvh cwbvh --float-slabs" "--bvh cwbvh"; do
      echo "== sponza $c"
      $T "$B" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
    done
  done
  for i in bdpt pt-nee pt; do
    for b in "$BASE" "$B" "$BASE" "$B"; do
      echo "== $(basename "$b") cornell $i"
      $T "$b" bench render $CB --integrator $i --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples"
    done
  done
  for i in pt-nee bdpt; do
    for b in "$BASE" "$B"; do
      echo "== $(basename "$b") sponza $i"
      $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
    done
  done
  for b in "$BASE" "$B"; do $T "$b" render $CB --integrator bdpt --spp 16 -o "/tmp/$(basename "$b").exr" 2>&1 | tail -1; done
  "$B" diff "/tmp/$(basename "$B").exr" "/tmp/$(basename "$BASE").exr" 2>&1 | head -2
  ;;
ffma12)
  # #17 (session 12): the binary and 4-wide slab tests as one multiply-add per plane, the
  # origin term widened by its rounding (slab_origins; B = a build of fead3e2), against PREV
  # (f5c3eb5, where the compiler made it (p - o) idir) and FINAL (c3d2cf6, (p - o) idir as
  # written), interleaved, two runs (cut to fit the session's last device minutes).
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  P=${PREV:-$PWD/.device/bidir-prev}
  T="timeout -k 5 60"
  for r in 1 2; do
    for c in "--bvh bvh4 --leaf-size 3 --quality 3" "--bvh bvh2"; do
      for b in "$B" "$P" ${FINAL:-$PWD/.device/bidir-final}; do
        [ -x "$b" ] || continue
        echo "== sponza $c $(basename "$b")"
        $T "$b" bench traversal "$SP" --camera CameraMain $c --reps 5 --warmup 2 2>&1 | grep -E "^(primary|shadow|diffuse) "
      done
    done
  done
  "$B" render $CAU --integrator pt-nee --spp 64 -o /tmp/new.exr > /dev/null 2>&1
  "$P" render $CAU --integrator pt-nee --spp 64 -o /tmp/prev.exr > /dev/null 2>&1
  echo "== caustic pt-nee 64 spp against PREV:"; "$B" diff /tmp/new.exr /tmp/prev.exr 2>&1 | grep -iE "rmse|ratio"
  ;;
layout12)
  # #16/#17 (session 12): with the culling stack, BDPT (and pt-nee) over bvh4 against the
  # default cwbvh per scene size (Sponza bdpt: 338.7 against 365.0 ms in final12; Cornell box
  # the other way, 230.9 against 204.8 in cull12). Scenes bundled geometry-only.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  for sc in cornell caustic DamagedHelmet MetalRoughSpheresNoTextures CesiumMilkTruck LightsPunctualLamp sponza; do
    case $sc in
      cornell) A="$CB"; S=1024 ;;
      caustic) A="$CAU"; S=256 ;;
      sponza) A="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360"; S=64 ;;
      *) A="$(ls $PWD/.device/scenes/gltf-samples/$sc/*.gl* | head -1) $CB"; S=256 ;;
    esac
    echo "== $sc: $("$B" info $A 2>&1 | grep -E "^triangles" | head -1)"
    for r in 1 2; do
      for i in bdpt pt-nee; do
        for l in cwbvh bvh4 bvh2; do
          [ $i = pt-nee ] && [ $l = bvh2 ] && continue
          echo "-- $sc $i --bvh $l: $($T "$B" bench render $A --integrator $i --spp $S --warmup 1 --runs 3 --bvh $l 2>&1 | grep -oE "GPU [0-9.]+ ms|\([a-z0-9]+, [^)]*\)" | tr '\n' ' ')"
        done
      done
    done
  done
  ;;
final12)
  # #17/#16 (session 12), the final code: any-hit rays keep the plain stack (cull12's shadow
  # rays lost 3-10 % to the distance entries). Trace kernels and integrators against BASE
  # (5234dd2), interleaved, two runs; BDPT over bvh4 beside its default on Sponza.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "--bvh bvh4 --leaf-size 3 --quality 3" "--bvh bvh2" "--bvh bvh4" "--bvh cwbvh"; do
      for b in "$B" "$BASE"; do
        echo "== sponza $c $(basename "$b")"
        $T "$b" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
      done
    done
  done
  for r in 1 2; do
    for b in "$B" "$BASE"; do
      for i in pt pt-nee bdpt vcm; do
        echo "== cornell $i $(basename "$b")"
        $T "$b" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
      done
      for i in pt-nee bdpt; do
        echo "== caustic $i $(basename "$b")"
        $T "$b" bench render $CAU --integrator $i --spp 256 2>&1 | grep -E "Msamples" | head -1
        echo "== sponza $i $(basename "$b")"
        $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
      done
      echo "== sponza bdpt --bvh bvh4 $(basename "$b")"
      $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --bvh bvh4 --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
    done
  done
  for i in pt-nee bdpt; do
    "$B" render $CAU --integrator $i --spp 64 -o /tmp/new-c-$i.exr > /dev/null 2>&1
    "$BASE" render $CAU --integrator $i --spp 64 -o /tmp/base-c-$i.exr > /dev/null 2>&1
    echo "== caustic $i 64 spp, this commit against BASE:"; "$B" diff /tmp/new-c-$i.exr /tmp/base-c-$i.exr 2>&1 | grep -iE "rmse|ratio"
  done
  "$B" render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 16 --integrator bdpt --bvh bvh4 -o /tmp/new-b4.exr > /dev/null 2>&1
  "$BASE" render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 16 --integrator bdpt --bvh bvh4 -o /tmp/base-b4.exr > /dev/null 2>&1
  echo "== sponza bdpt bvh4 16 spp, this commit against BASE:"; "$B" diff /tmp/new-b4.exr /tmp/base-b4.exr 2>&1 | grep -iE "rmse|ratio"
  for t in 0.1 1; do
    for i in pt-nee bdpt; do
      echo "== cornell $i --time $t"
      "$B" render --integrator $i --time $t --reference "$REF" -o /tmp/x.exr 2>&1 | grep -E "spp in|RMSE"
    done
  done
  ;;
cull12)
  # #17 (session 12): stack entries carry their box's entry distance and a pop skips those
  # past the nearest hit (bvh2, bvh2q, bvh4); u8-to-float bit trick reverted (cwbvh lost
  # 5-7 % with it in trav12). Against BASE (5234dd2), interleaved, two runs; then the
  # integrators over each layout (this commit only), to see whether the defaults move.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "--bvh bvh4 --leaf-size 3 --quality 3" "--bvh bvh2" "--bvh cwbvh" "--bvh bvh4" "--bvh bvh2 --quality 3" "--bvh bvh4 --leaf-size 2 --quality 3"; do
      for b in "$B" "$BASE"; do
        [ $r = 2 ] && [ "$c" = "--bvh bvh4" -o "$c" = "--bvh bvh2 --quality 3" -o "$c" = "--bvh bvh4 --leaf-size 2 --quality 3" ] && continue
        echo "== sponza $c $(basename "$b")"
        $T "$b" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
      done
    done
  done
  for l in cwbvh bvh2 bvh4; do
    for i in pt-nee bdpt; do
      echo "== cornell $i --bvh $l"
      $T "$B" bench render $CB --integrator $i --spp 1024 --bvh $l 2>&1 | grep -E "Msamples" | head -1
      echo "== sponza $i --bvh $l"
      $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 --bvh $l 2>&1 | grep -E "Msamples" | head -1
    done
  done
  "$B" info --kernels --bvh bvh4 2>&1 | grep -iE "^ *(pt|bdpt|shadow)" | head -12
  for l in bvh2 bvh4; do
    "$B" render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 16 --bvh $l -o /tmp/new-$l.exr > /dev/null 2>&1
    "$BASE" render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 16 --bvh $l -o /tmp/base-$l.exr > /dev/null 2>&1
    echo "== sponza pt-nee 16 spp --bvh $l, this commit against BASE:"; "$B" diff /tmp/new-$l.exr /tmp/base-$l.exr 2>&1 | grep -iE "rmse|ratio"
  done
  ;;
trav12)
  # #17 (session 12): this commit (every layout's node step without the sunk child load,
  # selects for run-time vector indices, subgroupAny vote, bytes to floats without I2F, no
  # buffer bounds checks) against BASE (5234dd2), interleaved, two runs; the driver's
  # pipeline beside the best layout; the integrators; images against BASE (RMSE).
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "--bvh bvh2" "--bvh bvh4 --leaf-size 3 --quality 3" "--bvh cwbvh" "--bvh bvh2q" "--bvh cwbvh --tri-test woop --quality 3" "--bvh bvh4"; do
      for b in "$B" "$BASE"; do
        [ $r = 2 ] && [ "$c" = "--bvh bvh2q" -o "$c" = "--bvh bvh4" ] && continue
        echo "== sponza $c $(basename "$b")"
        $T "$b" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
      done
    done
  done
  echo "== sponza bvh4 leaf 3 quality 3 --driver-rt"
  $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 --driver-rt 2>&1 | grep -E "^(primary|shadow|diffuse|driver)|agree|x the"
  for c in "--bvh bvh2" "--bvh bvh4" "--bvh cwbvh"; do
    for b in "$B" "$BASE"; do
      echo "== cornell 1920x1080 $c $(basename "$b")"
      $T "$b" bench traversal --width 1920 --height 1080 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  for r in 1 2; do
    for b in "$B" "$BASE"; do
      for i in pt pt-nee bdpt vcm; do
        echo "== cornell $i $(basename "$b")"
        $T "$b" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
      done
      for i in pt-nee bdpt; do
        echo "== sponza $i $(basename "$b")"
        $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
      done
    done
  done
  for i in pt-nee bdpt vcm; do
    "$B" render $CB --integrator $i --spp 64 -o /tmp/new-$i.exr > /dev/null 2>&1
    "$BASE" render $CB --integrator $i --spp 64 -o /tmp/base-$i.exr > /dev/null 2>&1
    echo "== cornell $i 64 spp, this commit against BASE:"; "$B" diff /tmp/new-$i.exr /tmp/base-$i.exr 2>&1 | tail -3
  done
  "$B" render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 16 -o /tmp/new-sp.exr > /dev/null 2>&1
  "$BASE" render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 16 -o /tmp/base-sp.exr > /dev/null 2>&1
  echo "== sponza pt-nee 16 spp, this commit against BASE:"; "$B" diff /tmp/new-sp.exr /tmp/base-sp.exr 2>&1 | tail -3
  D=/tmp/nvc-cw; rm -rf $D; mkdir -p $D
  __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$B" bench traversal "$SP" --camera CameraMain --bvh cwbvh --reps 5 --warmup 1 > /dev/null 2>&1
  mkdir -p "$OUT/cache" && cp $D/GLCache/*/*/*.bin "$OUT/cache/trace-cwbvh.bin"
  D=/tmp/nvc-pt; rm -rf $D; mkdir -p $D
  __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$B" bench render $CB --integrator pt-nee --spp 64 --runs 5 --warmup 1 > /dev/null 2>&1
  cp $D/GLCache/*/*/*.bin "$OUT/cache/cornell-ptnee.bin"
  ;;
exp12b)
  # #17 (session 12): the bvh4 node step's changes as the code (children early, selects,
  # subgroupAny vote; the watertight test's axis picks as selects, every layout) and kernels
  # without buffer bounds checks by default (BIDIR_BUFFER_CHECKS=1 restores them), against
  # BASE (5234dd2); bvh2's vote as subgroupAny (BIDIR_TRAVERSE_EXPERIMENT=4); the
  # integrators; images against BASE; the machine code of bvh2, cwbvh and pt-nee kernels.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 90"
  for r in 1 2; do
    for c in "--bvh bvh4 --leaf-size 3 --quality 3" "--bvh bvh2" "--bvh cwbvh"; do
      for v in "B 0 0" "B 1 0" "BASE 0 0" "B 0 4"; do
        set -- $v
        [ "$3" = 4 ] && [ "$c" != "--bvh bvh2" ] && continue
        b=$B; [ "$1" = BASE ] && b=$BASE
        echo "== sponza $c $(basename "$b") checks $2 experiment $3"
        BIDIR_BUFFER_CHECKS=$2 BIDIR_TRAVERSE_EXPERIMENT=$3 $T "$b" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
      done
    done
  done
  for r in 1 2; do
    for v in "B 0" "B 1" "BASE 0"; do
      set -- $v
      b=$B; [ "$1" = BASE ] && b=$BASE
      for i in pt-nee bdpt; do
        echo "== cornell $i $(basename "$b") checks $2"
        BIDIR_BUFFER_CHECKS=$2 $T "$b" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples|^(bdpt|pt|shadow)" | head -6
        echo "== sponza $i $(basename "$b") checks $2"
        BIDIR_BUFFER_CHECKS=$2 $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples|^(bdpt|pt|shadow)" | head -6
      done
    done
  done
  for i in pt-nee bdpt; do
    "$B" render $CB --integrator $i --spp 64 -o /tmp/new-$i.exr > /dev/null 2>&1
    "$BASE" render $CB --integrator $i --spp 64 -o /tmp/base-$i.exr > /dev/null 2>&1
    echo "== cornell $i 64 spp, this commit against BASE: $("$B" diff /tmp/new-$i.exr /tmp/base-$i.exr 2>&1 | tail -1)"
  done
  for c in bvh2 cwbvh; do
    D=/tmp/nvc-$c; rm -rf $D; mkdir -p $D
    __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$B" bench traversal "$SP" --camera CameraMain --bvh $c --reps 5 --warmup 1 > /dev/null 2>&1
    mkdir -p "$OUT/cache" && cp $D/GLCache/*/*/*.bin "$OUT/cache/trace-$c.bin"
  done
  D=/tmp/nvc-ptnee; rm -rf $D; mkdir -p $D
  __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$B" bench render $CB --integrator pt-nee --spp 64 --runs 5 --warmup 1 > /dev/null 2>&1
  cp $D/GLCache/*/*/*.bin "$OUT/cache/cornell-ptnee.bin"
  ;;
exp12)
  # #17 (session 12): the bvh4 node step as the driver compiles it (SASS, part sass) had the
  # children's load after the box test, dynamic vector indexing as compare chains, and a
  # bounds check per load; BIDIR_TRAVERSE_EXPERIMENT bits (1 children early + selects, 2 the
  # watertight test's axis picks as selects, 4 subgroupAny vote, 8 branch-free pushes) and
  # BIDIR_UNCHECKED_BUFFERS=1 (VK_EXT_pipeline_robustness off) against the default.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  for r in 1 2; do
    for v in "0 0" "1 0" "3 0" "7 0" "11 0" "15 0" "0 1" "3 1" "11 1"; do
      set -- $v
      echo "== sponza bvh4 leaf 3 quality 3, experiment $1, unchecked $2"
      BIDIR_TRAVERSE_EXPERIMENT=$1 BIDIR_UNCHECKED_BUFFERS=$2 $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
    done
  done
  for l in bvh2 cwbvh; do
    for u in 0 1 0 1; do
      echo "== sponza $l unchecked $u"
      BIDIR_UNCHECKED_BUFFERS=$u $T "$B" bench traversal "$SP" --camera CameraMain --bvh $l 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
    done
  done
  for v in "11 0" "11 1"; do
    set -- $v
    D=/tmp/nvcache-$1-$2; rm -rf $D; mkdir -p $D
    __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 BIDIR_TRAVERSE_EXPERIMENT=$1 BIDIR_UNCHECKED_BUFFERS=$2 \
      $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 --reps 5 --warmup 1 > /dev/null 2>&1
    mkdir -p "$OUT/cache" && cp $D/GLCache/*/*/*.bin "$OUT/cache/exp-$1-$2.bin"
  done
  ;;
s14c)
  # Session 14: Sobol' dimensions 2 and 3 as 8 and 9 shift-and-xor steps and a bit reversal
  # (src/gpu/sobol.rs STEPS; the same numbers bit for bit) instead of a test per index bit,
  # and kernels compiled once per context and specialisation. B against BASE (f546c54),
  # interleaved; images compared; time-budgeted renders against the sharper reference.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  T="timeout -k 5 60"
  for r in 1 2; do
    for v in $BASE $B; do
      echo "== cornell pt-nee $(basename $v)"
      $T $v bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples" | head -1
      echo "== cornell bdpt $(basename $v)"
      $T $v bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 2>&1 | sed -n 1,4p
      for i in bdpt pt-nee; do
        echo "== sponza $i $(basename $v)"
        $T $v bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples|camera|light" | head -3
      done
    done
  done
  for v in $BASE $B; do
    for i in pt bdpt:full vcm; do
      echo "== cornell $i $(basename $v)"
      $T $v bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
    done
    for i in pt-nee bdpt; do
      echo "== caustic $i $(basename $v)"
      $T $v bench render $CAU --width 256 --height 256 --integrator $i --spp 256 2>&1 | grep -E "Msamples" | head -1
    done
    echo "== sponza bdpt --bvh bvh4 $(basename $v)"
    $T $v bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --bvh bvh4 --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  done
  for b in "$BASE" "$B"; do
    n=$(basename $b)
    $T $b render --integrator pt-nee --spp 64 -o /tmp/$n-p.exr > /dev/null 2>&1
    $T $b render --integrator bdpt --spp 16 -o /tmp/$n-b.exr > /dev/null 2>&1
    $T $b render --integrator vcm --spp 16 -o /tmp/$n-v.exr > /dev/null 2>&1
    $T $b render "$SP" --sponza-sun-sky --camera CameraMain --width 320 --height 180 --integrator bdpt --spp 4 -o /tmp/$n-s.exr > /dev/null 2>&1
  done
  echo "== B against BASE: pt-nee 64 spp, bdpt 16, vcm 16, Sponza bdpt 4"
  for k in p b v s; do "$BASE" diff /tmp/bidir-$k.exr /tmp/bidir-base-$k.exr 2>&1 | grep -iE "rmse"; done
  for t in 0.1 1; do
    for i in pt-nee bdpt; do
      for b in "$B" "$BASE" "$B"; do
        echo "== cornell $i --time $t $(basename "$b")"; $T "$b" render $CB --integrator $i --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      done
    done
    for i in pt-nee bdpt; do
      echo "== caustic $i --time $t $(basename "$B")"; $T "$B" render $CAU --width 128 --height 128 --integrator $i --time $t --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
  done
  for b in "$BASE" "$B"; do
    echo "== kernels $(basename $b)"
    $T $b info --kernels 2>&1 | grep -E "^(pt-nee|bdpt:lvc=1) " | head -6
  done
  ;;
s14b)
  # Session 14: the Sobol' tables by bytes (bidir-byte: 4 lookups in 4 KiB a dimension) against
  # by nibbles (B: 8 lookups in 512 bytes a dimension, every lookup within one 64-byte run) and
  # BASE (f546c54, a test per index bit), interleaved: s14a found the byte tables faster on the
  # Cornell box and slower on Sponza.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 60"
  V="$BASE .device/bidir-byte $B"
  for r in 1 2; do
    for v in $V; do
      echo "== cornell pt-nee $(basename $v)"
      $T $v bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples" | head -1
      echo "== cornell bdpt $(basename $v)"
      $T $v bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 2>&1 | sed -n 1,4p
      for i in bdpt pt-nee; do
        echo "== sponza $i $(basename $v)"
        $T $v bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples|camera|light" | head -3
      done
    done
  done
  for v in $BASE $B; do
    for i in pt vcm; do
      echo "== cornell $i $(basename $v)"
      $T $v bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
    done
    for i in pt-nee bdpt; do
      echo "== caustic $i $(basename $v)"
      $T $v bench render $CAU --integrator $i --spp 256 2>&1 | grep -E "Msamples" | head -1
    done
  done
  ;;
s14a)
  # Session 14: Sobol' dimensions 2 and 3 from byte tables (four lookups in an 8 KiB buffer
  # instead of a test per index bit; the same numbers bit for bit): B against BASE (f546c54),
  # interleaved; B with --sampler independent as the bound of what the Sobol' points cost.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 60"
  for r in 1 2; do
    for v in "$BASE" "$B" "$B --sampler independent"; do
      echo "== cornell pt-nee $(basename $v)"
      $T $v bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples" | head -1
      echo "== cornell bdpt $(basename $v)"
      $T $v bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 2>&1 | sed -n 1,6p
    done
  done
  for v in "$BASE" "$B"; do
    for i in pt vcm; do
      echo "== cornell $i $(basename $v)"
      $T $v bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
    done
    for i in pt-nee bdpt; do
      echo "== caustic $i $(basename $v)"
      $T $v bench render $CAU --integrator $i --spp 256 2>&1 | grep -E "Msamples" | head -1
      echo "== sponza $i $(basename $v)"
      $T $v bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
    done
  done
  for b in "$BASE" "$B"; do
    n=$(basename $b)
    $T $b render --integrator pt-nee --spp 64 -o /tmp/$n-p.exr > /dev/null 2>&1
    $T $b render --integrator bdpt --spp 16 -o /tmp/$n-b.exr > /dev/null 2>&1
    $T $b render --integrator vcm --spp 16 -o /tmp/$n-v.exr > /dev/null 2>&1
  done
  echo "== B against BASE: pt-nee 64 spp, bdpt 16, vcm 16"
  for k in p b v; do "$BASE" diff /tmp/bidir-$k.exr /tmp/bidir-base-$k.exr 2>&1 | grep -iE "rmse"; done
  for t in 0.1 1; do
    for i in pt-nee bdpt; do
      for b in "$B" "$B"; do
        echo "== cornell $i --time $t $(basename "$b")"; $T "$b" render $CB --integrator $i --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      done
    done
  done
  for b in "$BASE" "$B"; do
    echo "== kernels $(basename $b)"
    $T $b info --kernels 2>&1 | grep -E "^(pt-nee|bdpt:lvc=1) " | head -6
  done
  ;;
s13g)
  # Session 13: the light pass regenerating paths (BIDIR_LIGHT_PATHS_PER_INVOCATION k = 1, 2,
  # 3, 4; B = a build of fd159e5, reverted after this measurement: docs/results.md) against P
  # (f8477ec, a light path per invocation), interleaved; images compared.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  P=.device/bidir-prev
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 60"
  for r in 1 2; do
    echo "== cornell bdpt prev"; $T "$P" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 2>&1 | sed -n 1,6p
    for k in 1 2 3 4; do
      echo "== cornell bdpt k=$k"; BIDIR_LIGHT_PATHS_PER_INVOCATION=$k $T "$B" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 2>&1 | sed -n 1,6p
    done
  done
  for k in 0 1 2 4; do
    if [ $k = 0 ]; then b="$P"; else b="$B"; fi
    export BIDIR_LIGHT_PATHS_PER_INVOCATION=$([ $k = 0 ] && echo 1 || echo $k)
    echo "== k=$k cornell vcm"; $T "$b" bench render $CB --integrator vcm --spp 1024 2>&1 | grep Msamples
    echo "== k=$k caustic bdpt"; $T "$b" bench render $CAU --integrator bdpt --spp 256 2>&1 | grep Msamples
    echo "== k=$k sponza bdpt"; $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 2>&1 | sed -n 1,4p
    $T "$b" render $CB --integrator bdpt --spp 64 -o /tmp/k$k.exr > /dev/null 2>&1
    $T "$b" render $CB --integrator vcm --spp 64 -o /tmp/v$k.exr > /dev/null 2>&1
  done
  unset BIDIR_LIGHT_PATHS_PER_INVOCATION
  for k in 1 2 4; do
    echo "== k=$k against prev: bdpt, vcm 64 spp"
    "$B" diff /tmp/k$k.exr /tmp/k0.exr 2>&1 | grep -iE "rmse"; "$B" diff /tmp/v$k.exr /tmp/v0.exr 2>&1 | grep -iE "rmse"
  done
  for t in 0.1 1; do
    echo "== cornell bdpt --time $t"; $T "$B" render $CB --integrator bdpt --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
  done
  "$B" info --kernels 2>&1 | grep -E "^bdpt:lvc=1 " | head -2
  ;;

s13f)
  # Session 13: budgeted passes grow at most 4x the longest measured (or to a quarter of the
  # budget): B against P (54ab3b4, passes sized by the model alone), fresh processes, 0.1 s,
  # interleaved, four runs; pass logs in $OUT.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  P=.device/bidir-prev
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  T="timeout -k 5 60"
  export BIDIR_PASS_LOG=1
  for r in 1 2 3 4; do
    for i in pt-nee bdpt pt; do
      for sc in cornell caustic; do
        if [ $sc = cornell ]; then A="$CB"; else A="$CAU"; fi
        for b in "$B" "$P"; do
          echo "== $sc $i --time 0.1 run $r $(basename $b)" >> "$OUT/passes.log"
          $T "$b" render $A --integrator $i --time 0.1 --reference $([ $sc = cornell ] && echo "$REF" || echo assets/scenes/caustic/reference.exr) -o /tmp/t.exr >> "$OUT/passes.log" 2>&1
          echo "== $sc $i run $r $(basename $b): $(grep "spp in" "$OUT/passes.log" | tail -1 | sed -E 's/NVIDIA H200 //; s/ \(.*//') $(grep "^RMSE" "$OUT/passes.log" | tail -1 | cut -d, -f1)"
        done
      done
    done
  done
  ;;
s13e)
  # Session 13: does a time-budgeted render's last pass overshoot (#16: at most 10 %)? Fresh
  # processes, 0.1 s, each pass logged (BIDIR_PASS_LOG); the whole log goes to $OUT.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  T="timeout -k 5 60"
  export BIDIR_PASS_LOG=1
  for r in 1 2 3 4; do
    for i in pt-nee bdpt pt; do
      for sc in cornell caustic; do
        if [ $sc = cornell ]; then A="$CB"; else A="$CAU"; fi
        echo "== $sc $i --time 0.1 run $r" >> "$OUT/passes.log"
        $T "$B" render $A --integrator $i --time 0.1 -o /tmp/t.exr >> "$OUT/passes.log" 2>&1
        echo "== $sc $i run $r: $(grep "spp in" "$OUT/passes.log" | tail -1)"
      done
    done
  done
  ;;
s13d)
  # Session 13, a measurement only: BDPT without the in-kernel fallback for shadow rays that
  # find the queue's slots full (M = bidir-m1: such rays dropped, a wrong image if it ever
  # happens), against B (3e954c8): what the second traversal inlined in the light and camera
  # kernels costs them (registers, time), and whether the slots ever run out here.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  M=.device/bidir-m1
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 60"
  for r in 1 2; do
    for b in "$B" "$M"; do
      echo "== cornell bdpt $(basename "$b")"
      $T "$b" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 2>&1 | sed -n 1,6p
    done
  done
  for b in "$B" "$M"; do
    echo "== caustic bdpt $(basename "$b")"
    $T "$b" bench render $CAU --integrator bdpt --spp 256 2>&1 | grep -E "Msamples" | head -1
    echo "== sponza bdpt $(basename "$b")"
    $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 2>&1 | sed -n 1,6p
    echo "== kernels $(basename "$b")"
    $T "$b" info --kernels 2>&1 | grep -E "^bdpt:lvc=1 " | head -4
    $T "$b" render $CB --integrator bdpt --spp 64 -o /tmp/$(basename "$b")-c.exr > /dev/null 2>&1
    $T "$b" render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 16 -o /tmp/$(basename "$b")-s.exr > /dev/null 2>&1
  done
  echo "== images, M against B (0: the slots never ran out)"
  "$B" diff /tmp/bidir-m1-c.exr /tmp/bidir-c.exr 2>&1 | grep -iE "rmse"
  "$B" diff /tmp/bidir-m1-s.exr /tmp/bidir-s.exr 2>&1 | grep -iE "rmse"
  ;;
s16h)
  # Session 16's review: dynamic fetch with the subgroup's lane count taken once.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  for c in "--refill 28" "" "--refill 24"; do
    echo "== sponza l3 q3 $c"; timeout -k 5 40 "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
  done
  ;;
s16g)
  # Session 16: dynamic fetch's launch size (--persistent-groups; the default is the SMs'
  # resident warps: 4224 groups on the H200).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 40"
  L3="--bvh bvh4 --leaf-size 3 --quality 3"
  for g in 4224 1056 2112 8448 16896; do
    echo "== sponza $L3 --refill 28 --persistent-groups $g"; $T "$B" bench traversal "$SP" --camera CameraMain $L3 --refill 28 --persistent-groups $g 2>&1 | grep -E "^(primary|shadow|diffuse) "
  done
  ;;
s18i)
  # Session 18: equal-time error of the wavefront path tracer against the megakernel on the
  # textured Sponza under sun and sky (carried as s18c): a 40 s pt-nee reference (seed 99),
  # then 1 s renders, three seeds each, interleaved.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  S="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee"
  timeout -k 5 120 "$B" render $S --time 40 --seed 99 -o /tmp/ref.exr 2>&1 | grep -E "spp in"
  for s in 1 2 3; do
    for wf in on off; do
      echo "== --time 1 wavefront $wf seed $s"; timeout -k 5 60 "$B" render $S --wavefront $wf --time 1 --seed $s --reference /tmp/ref.exr -o /tmp/t.exr 2>&1 | grep -E "spp in|RMSE"
    done
  done
  ;;
s18h)
  # Session 18 (measurement build, not committed): any-hit rays visit a 4-wide node's hit
  # children in an order fixed per node at build time (a table in the node's last word: leaves,
  # then the largest boxes first) instead of slot order; against s18e/s18f's figures of the same day (5.20 / 6.54 / 2.02 at quality 3,
  # --refill 28 5.06 / 6.73 / 2.12, quality 4 5.63 / 6.22 / 2.10; textured Sponza pt-nee
  # 58.3 ms, pt 44.1). Carried as s18c (textured Sponza), without the glTF samples.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  for r in 1 2; do
    for q in "--quality 3" "--quality 3 --refill 28" "--quality 4" "--quality 4 --refill 28"; do
      echo "== sponza traversal bvh4 leaf 3 $q"; $T "$B" bench traversal $SP --camera CameraMain --bvh bvh4 --leaf-size 3 $q 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  SPR="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 64 --warmup 1 --runs 3"
  for r in 1 2; do
    for i in pt-nee pt; do
      echo "== sponza textured $i default"; $T "$B" bench render $SPR --integrator $i 2>&1 | grep -E "Msamples"
    done
  done
  ;;
s18f)
  # Session 18: the wavefront tracer's trace kernels back to dynamic fetch at 28 lanes on GPUs
  # (s18e ran one invocation per ray: textured Sponza 3-4 % slower than s18c), defaults.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  SPR="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 64 --warmup 1 --runs 3"
  G=.device/scenes/gltf
  for r in 1 2; do
    for i in pt-nee pt; do
      echo "== sponza textured $i default"; $T "$B" bench render $SPR --integrator $i 2>&1 | grep -E "Msamples"
      echo "== DamagedHelmet $i default"; $T "$B" bench render $G/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --spp 256 --warmup 2 --runs 3 --integrator $i 2>&1 | grep -E "Msamples"
    done
  done
  for wf in off on; do
    echo "== sponza textured 1080p pt-nee wavefront $wf"; $T "$B" bench render $SP --sponza-sun-sky --camera CameraMain --width 1920 --height 1080 --spp 16 --warmup 1 --runs 3 --integrator pt-nee --wavefront $wf 2>&1 | grep -E "Msamples"
  done
  for wf in off on; do
    echo "== sponza textured pt-nee --time 0.1 / 1 wavefront $wf"; for t in 0.1 1; do $T "$B" render $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --wavefront $wf --time $t -o /tmp/s.exr 2>&1 | grep -iE "spp in"; done
  done
  ;;
s18e)
  # Session 18, the commit with the wavefront default (pt and pt-nee on GPUs in glossy or
  # textured scenes without smooth mirrors or glass): the trace kernels against session 17's
  # figures (their ray count now a variable that may come from a buffer), the defaults on
  # every scene of s18c/s18d, pt and the rough Cornell box on and off (not measured before),
  # and one image made both ways on this GPU. The textured Sponza as in s18c.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  for q in "--quality 3" "--quality 3 --refill 28" "--quality 4"; do
    echo "== sponza traversal bvh4 leaf 3 $q"; $T "$B" bench traversal $SP --camera CameraMain --bvh bvh4 --leaf-size 3 $q 2>&1 | grep -E "^(primary|shadow|diffuse) "
  done
  SPR="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 64 --warmup 1 --runs 3"
  RC="assets/scenes/rough-cornell/rough-cornell.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  G=.device/scenes/gltf
  for r in 1 2; do
    for i in pt pt-nee bdpt; do
      echo "== cornell $i default"; $T "$B" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator $i 2>&1 | grep -E "Msamples"
      echo "== sponza textured $i default"; $T "$B" bench render $SPR --integrator $i 2>&1 | grep -E "Msamples"
    done
    echo "== caustic pt-nee default"; $T "$B" bench render $CAU --spp 1024 --warmup 1 --runs 3 --integrator pt-nee 2>&1 | grep -E "Msamples"
    for wf in off on; do
      echo "== rough cornell pt-nee wavefront $wf"; $T "$B" bench render $RC --spp 1024 --warmup 1 --runs 3 --integrator pt-nee --wavefront $wf 2>&1 | grep -E "Msamples"
      echo "== sponza textured pt wavefront $wf"; $T "$B" bench render $SPR --integrator pt --wavefront $wf 2>&1 | grep -E "Msamples"
      for m in DamagedHelmet MetalRoughSpheresNoTextures; do
        echo "== $m pt wavefront $wf"; $T "$B" bench render $G/$m/$m.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --spp 256 --warmup 2 --runs 3 --integrator pt --wavefront $wf 2>&1 | grep -E "Msamples"
      done
      echo "== DamagedHelmet pt-nee wavefront $wf"; $T "$B" bench render $G/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --spp 256 --warmup 2 --runs 3 --integrator pt-nee --wavefront $wf 2>&1 | grep -E "Msamples"
    done
  done
  for wf in off on; do
    $T "$B" render $G/DamagedHelmet/DamagedHelmet.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --spp 256 --integrator pt-nee --wavefront $wf -o /tmp/dh$wf.exr 2>&1 | grep -E "spp in"
  done
  echo "== DamagedHelmet pt-nee 256 spp, wavefront against megakernel: $("$B" diff /tmp/dhon.exr /tmp/dhoff.exr 2>&1 | grep -E "RMSE|ratio" | tr '\n' ' ')"
  echo "== sponza textured pt-nee --time 0.1 / 1 default"; for t in 0.1 1; do $T "$B" render $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --time $t -o /tmp/s.exr 2>&1 | grep -iE "spp in"; done
  ;;
s18c)
  # Session 18: the wavefront path tracer (slots now ~4 million by default) on the textured
  # Sponza (.device/scenes/sponza-full: the whole folder, its eight largest PNG textures
  # re-encoded as JPEG (quality 92; none of them alpha-tested) to travel under 64 MiB without
  # the validation layer and the geometry-only copy); megakernel and wavefront interleaved.
  # s18d: three glTF samples under an environment and a sun, the Cornell box and the caustic
  # scene.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=$PWD/.device/scenes/sponza-full/Sponza.gltf
  T="timeout -k 5 60"
  for r in 1 2; do
    for i in pt-nee pt; do
      for wf in off on; do
        echo "== sponza textured 640x360 $i wavefront $wf"; $T "$B" bench render $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 64 --warmup 1 --runs 3 --integrator $i --wavefront $wf 2>&1 | grep -E "Msamples|^pt|^trace|^shadow"
      done
    done
  done
  for wf in off on; do
    echo "== sponza textured 1080p pt-nee wavefront $wf"; $T "$B" bench render $SP --sponza-sun-sky --camera CameraMain --width 1920 --height 1080 --spp 16 --warmup 1 --runs 3 --integrator pt-nee --wavefront $wf 2>&1 | grep -E "Msamples|^pt|^trace|^shadow"
  done
  for wf in off on; do
    echo "== sponza textured pt-nee --time 1 wavefront $wf"; $T "$B" render $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --wavefront $wf --time 1 -o /tmp/s$wf.exr 2>&1 | grep -iE "spp in"
  done
  ;;
s18d)
  # Session 18: see s18c.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 60"
  for m in DamagedHelmet MetalRoughSpheresNoTextures CesiumMilkTruck; do
    for wf in off on off on; do
      echo "== $m pt-nee wavefront $wf"; $T "$B" bench render .device/scenes/gltf/$m/$m.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --spp 256 --warmup 1 --runs 3 --integrator pt-nee --wavefront $wf 2>&1 | grep -E "Msamples"
    done
  done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  for wf in off on off on; do
    echo "== cornell pt-nee wavefront $wf"; $T "$B" bench render $CB --spp 1024 --warmup 2 --runs 5 --integrator pt-nee --wavefront $wf 2>&1 | grep -E "Msamples"
    echo "== caustic pt-nee wavefront $wf"; $T "$B" bench render $CAU $CB --spp 1024 --warmup 1 --runs 3 --integrator pt-nee --wavefront $wf 2>&1 | grep -E "Msamples"
  done
  ;;
s18b)
  # Session 18: s18a again with the wavefront tracer's rays packed into queues (compaction)
  # and done slots leaving at once (measurement build: BIDIR_WF_REFILL, BIDIR_WF_DEBUG).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  SPR="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 64 --warmup 1 --runs 3"
  CBR="$CB --spp 1024 --warmup 2 --runs 5"
  BIDIR_WF_DEBUG=1 $T "$B" render $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --wavefront on --sample-slices 8 --spp 64 -o /tmp/s.exr 2>&1 | grep -E "batch of|spp in" | cut -c1-1500
  for r in 1 2; do
    echo "== sponza pt-nee default"; $T "$B" bench render $SPR --integrator pt-nee 2>&1 | head -3 | tail -1
    for sl in 0 8 16 32; do
      echo "== sponza pt-nee wavefront slices $sl"; $T "$B" bench render $SPR --integrator pt-nee --wavefront on --sample-slices $sl 2>&1 | head -5
    done
  done
  for rf in 0 16 24 32; do
    echo "== sponza pt-nee wavefront slices 8 refill $rf"; BIDIR_WF_REFILL=$rf $T "$B" bench render $SPR --integrator pt-nee --wavefront on --sample-slices 8 2>&1 | head -5
  done
  echo "== sponza pt default"; $T "$B" bench render $SPR --integrator pt 2>&1 | head -3 | tail -1
  echo "== sponza pt wavefront slices 8"; $T "$B" bench render $SPR --integrator pt --wavefront on --sample-slices 8 2>&1 | head -5
  SPH="$SP --sponza-sun-sky --camera CameraMain --width 1920 --height 1080 --spp 16 --warmup 1 --runs 3"
  echo "== sponza 1080p pt-nee default"; $T "$B" bench render $SPH --integrator pt-nee 2>&1 | head -3 | tail -1
  echo "== sponza 1080p pt-nee wavefront"; $T "$B" bench render $SPH --integrator pt-nee --wavefront on 2>&1 | head -5
  echo "== sponza 1080p pt-nee wavefront slices 2"; $T "$B" bench render $SPH --integrator pt-nee --wavefront on --sample-slices 2 2>&1 | head -5
  for i in pt-nee; do
    echo "== cornell $i default"; $T "$B" bench render $CBR --integrator $i 2>&1 | head -3 | tail -1
    for sl in 16 64; do
      echo "== cornell $i wavefront slices $sl"; $T "$B" bench render $CBR --integrator $i --wavefront on --sample-slices $sl 2>&1 | head -5
    done
  done
  ;;
s18a)
  # Session 18: the wavefront path tracer (--wavefront on; measurement build: BIDIR_WF_REFILL
  # sets the trace kernels' dynamic fetch, 0 = no persistent threads) against the megakernels.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  SPR="$SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --spp 64 --warmup 1 --runs 3"
  CBR="$CB --spp 1024 --warmup 2 --runs 5"
  for r in 1 2; do
    echo "== sponza pt-nee default"; $T "$B" bench render $SPR --integrator pt-nee 2>&1 | head -8
    for sl in 0 8 16; do
      echo "== sponza pt-nee wavefront slices $sl"; $T "$B" bench render $SPR --integrator pt-nee --wavefront on --sample-slices $sl 2>&1 | head -6
    done
  done
  for rf in 0 16 32; do
    echo "== sponza pt-nee wavefront slices 8 refill $rf"; BIDIR_WF_REFILL=$rf $T "$B" bench render $SPR --integrator pt-nee --wavefront on --sample-slices 8 2>&1 | head -6
  done
  for l in bvh2 cwbvh; do
    echo "== sponza pt-nee wavefront slices 8 $l"; $T "$B" bench render $SPR --integrator pt-nee --wavefront on --sample-slices 8 --bvh $l 2>&1 | head -6
  done
  echo "== sponza pt default"; $T "$B" bench render $SPR --integrator pt 2>&1 | head -6
  echo "== sponza pt wavefront slices 8"; $T "$B" bench render $SPR --integrator pt --wavefront on --sample-slices 8 2>&1 | head -6
  SPH="$SP --sponza-sun-sky --camera CameraMain --width 1920 --height 1080 --spp 16 --warmup 1 --runs 3"
  echo "== sponza 1080p pt-nee default"; $T "$B" bench render $SPH --integrator pt-nee 2>&1 | head -6
  echo "== sponza 1080p pt-nee wavefront"; $T "$B" bench render $SPH --integrator pt-nee --wavefront on 2>&1 | head -6
  for i in pt-nee pt; do
    echo "== cornell $i default"; $T "$B" bench render $CBR --integrator $i 2>&1 | head -6
    for sl in 0 16 64; do
      echo "== cornell $i wavefront slices $sl"; $T "$B" bench render $CBR --integrator $i --wavefront on --sample-slices $sl 2>&1 | head -6
    done
  done
  echo "== cornell pt-nee wavefront 4096 spp against the reference"; $T "$B" render $CB --integrator pt-nee --wavefront on --spp 4096 --reference "$REF" -o /tmp/w.exr 2>&1 | grep -iE "spp in|rmse|mean"
  echo "== cornell pt-nee megakernel 4096 spp against the reference"; $T "$B" render $CB --integrator pt-nee --spp 4096 --reference "$REF" -o /tmp/m.exr 2>&1 | grep -iE "spp in|rmse|mean"
  echo "== diff"; "$B" diff /tmp/w.exr /tmp/m.exr 2>&1 | head -5
  echo "== sponza pt-nee --time 1 wavefront / default"; $T "$B" render $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --wavefront on --time 1 -o /tmp/sw.exr 2>&1 | grep -iE "spp in"
  $T "$B" render $SP --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --time 1 -o /tmp/sm.exr 2>&1 | grep -iE "spp in"
  ;;
s17e)
  # Session 17: s17d's auto renders again, the pilot now sized once the pass model knows a
  # pass's fixed cost (in s17d the 1-spp calibration pass made every pilot too small to run).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  HID=".device/scenes/hidden/hidden.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  T="timeout -k 5 60"
  for s in 1 2 3; do
    echo "== cornell bdpt --time 1 --light-paths auto seed $s"; $T "$B" render $CB --integrator bdpt --light-paths auto --seed $s --time 1 --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse|light paths per"
    echo "== caustic bdpt --time 2 --light-paths auto seed $s"; $T "$B" render $CAU --integrator bdpt --light-paths auto --seed $s --time 2 --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse|light paths per"
  done
  for pair in "1 2" "3 4" "5 6"; do
    set -- $pair
    for s in $1 $2; do $T "$B" render $HID --integrator bdpt --light-paths auto --seed $s --time 1 -o /tmp/h$s.exr 2>&1 | grep -iE "spp in|light paths per"; done
    echo "== hidden bdpt --time 1 --light-paths auto, seed $1 against seed $2: $("$B" diff /tmp/h$1.exr /tmp/h$2.exr 2>&1 | grep -i rmse)"
  done
  ;;
s17d)
  # Session 17: --light-paths auto (pilot passes at 0.5, 1 and 2 light paths per pixel, then
  # the most efficient) against fixed ratios at equal time: the Cornell box against the
  # sharper reference, the caustic scene at 128² against its reference (2 s: a pilot pass
  # there needs 2^22 samples), the Cornell box whose
  # light hides above a panel (RMSE between two seeds); auto with two seeds (pairs) each.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  HID=".device/scenes/hidden/hidden.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  T="timeout -k 5 60"
  for lp in auto 1 0.5 2; do
    seeds="1"; [ "$lp" = auto ] && seeds="1 2"
    for s in $seeds; do
      echo "== cornell bdpt --time 1 --light-paths $lp seed $s"; $T "$B" render $CB --integrator bdpt --light-paths $lp --seed $s --time 1 --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse|light paths per"
      echo "== caustic bdpt --time 2 --light-paths $lp seed $s"; $T "$B" render $CAU --integrator bdpt --light-paths $lp --seed $s --time 2 --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse|light paths per"
    done
    for pair in "1 2" "3 4"; do
      [ "$lp" != auto ] && [ "$pair" = "3 4" ] && continue
      set -- $pair
      for s in $1 $2; do $T "$B" render $HID --integrator bdpt --light-paths $lp --seed $s --time 1 -o /tmp/h$s.exr 2>&1 | grep -iE "spp in|light paths per"; done
      echo "== hidden bdpt --time 1 --light-paths $lp, seed $1 against seed $2: $("$B" diff /tmp/h$1.exr /tmp/h$2.exr 2>&1 | grep -i rmse)"
    done
  done
  ;;
s17c)
  # Session 17 (measurement build): the lockstep descent ends as soon as BIDIR_EXP_T lanes
  # of the subgroup hold a postponed leaf (0: when every lane that still descends holds one,
  # the speculative traversal of Aila & Laine), 4-wide, Sponza, build quality 3 and 4,
  # lockstep and dynamic fetch; two runs, interleaved.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  for r in 1 2; do
    for c in "--bvh bvh4 --leaf-size 3 --quality 3" "--bvh bvh4 --leaf-size 3 --quality 3 --refill 28" "--bvh bvh4 --leaf-size 3 --quality 4"; do
      for e in 0 4 8 16 24; do
        echo "== sponza $c exp $e"; BIDIR_EXP_T=$e $T "$B" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
      done
    done
  done
  ;;
s17b)
  # Session 17 (measurement build): the slab slack as one multiply-add per plane set (B,
  # BIDIR_EXP_PUSH=0) and, on top, the 4-wide closest-hit step's pushes at fixed offsets below
  # the new top, with no branch between them (BIDIR_EXP_PUSH=1), against 59d1de3 (BASE);
  # build quality 3 and 4, interleaved, two runs; then the machine code of 1.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  for r in 1 2; do
    for q in 3 4; do
      for c in "--bvh bvh4 --leaf-size 3 --quality $q" "--bvh bvh4 --leaf-size 3 --quality $q --refill 28"; do
        echo "== sponza $c base"; $T "$BASE" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
        for e in 0 1; do
          echo "== sponza $c exp $e"; BIDIR_EXP_PUSH=$e $T "$B" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
        done
      done
    done
  done
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  BIDIR_EXP_PUSH=1 __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 --reps 3 --warmup 1 > /dev/null 2>&1
  tar czf "$OUT/nvcache.tgz" -C $D .
  ;;
s17a)
  # Session 17: Bvh4Node's planes in slots whose index flips one bit per axis (each plane's
  # offset from the ray's sign flips by an AND and an OR) and the slab slack as one
  # multiply-add per axis, against 59d1de3 (BASE), interleaved, two runs; build quality 4;
  # then the machine code of the new trace kernels.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  L3="--bvh bvh4 --leaf-size 3 --quality 3"
  for r in 1 2; do
    for c in "$L3" "$L3 --refill 28" "--bvh bvh4"; do
      for b in "$BASE" "$B"; do
        echo "== sponza $c $(basename "$b")"; $T "$b" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
      done
    done
  done
  for c in "--bvh bvh4 --leaf-size 3 --quality 4" "--bvh bvh4 --leaf-size 3 --quality 4 --refill 28"; do
    echo "== sponza $c"; $T "$B" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
  done
  for b in "$BASE" "$B"; do
    echo "== sponza bdpt bvh4 $(basename "$b")"; $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --bvh bvh4 --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  done
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$B" bench traversal "$SP" --camera CameraMain $L3 --reps 3 --warmup 1 > /dev/null 2>&1
  tar czf "$OUT/nvcache.tgz" -C $D .
  ;;
s16f)
  # Session 16's final code: the traversal table (two runs, interleaved) and the integrators
  # (against s16c's exp 0 and s16d: the shared inverse direction and the lockstep function
  # moved, no change intended).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 40"
  L3="--bvh bvh4 --leaf-size 3 --quality 3"
  for r in 1 2; do
    for c in "$L3" "$L3 --divergent-loops" "$L3 --refill 28" "--bvh bvh2" "--bvh bvh2 --divergent-loops" "--bvh cwbvh"; do
      echo "== sponza $c"; $T "$B" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  for i in pt pt-nee bdpt; do
    echo "== cornell $i"; $T "$B" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
  done
  echo "== caustic bdpt"; $T "$B" bench render $CAU --width 256 --height 256 --integrator bdpt --spp 256 2>&1 | grep -E "Msamples" | head -1
  for i in pt-nee bdpt; do
    echo "== sponza $i"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  done
  echo "== sponza bdpt bvh4"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --bvh bvh4 --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  ;;
s16e)
  # Session 16: the lockstep and dynamic-fetch kernels with the secondary rays sorted
  # (--sort, the sort timed apart), other leaf sizes, and the driver's pipeline in the same run.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  L3="--bvh bvh4 --leaf-size 3 --quality 3"
  for c in "$L3 --sort" "$L3 --refill 28 --sort" "$L3" "$L3 --refill 28" "--bvh bvh4 --leaf-size 2 --quality 3" "--bvh bvh4 --leaf-size 4 --quality 3" "--bvh bvh4 --leaf-size 2 --quality 3 --refill 28" "$L3 --driver-rt"; do
    echo "== sponza $c"; $T "$B" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) |sort|driver|agree"
  done
  ;;
s16d)
  # Session 16: the trace kernels' lockstep loops (default) against --divergent-loops (the
  # integrators' loops), persistent threads with batches against dynamic fetch (--refill N),
  # Sponza; then the integrators (unchanged loops: against s16c's exp 0 figures).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 40"
  L3="--bvh bvh4 --leaf-size 3 --quality 3"
  for r in 1 2; do
    for c in "$L3" "$L3 --divergent-loops" "--bvh bvh2" "--bvh bvh2 --divergent-loops" "--bvh bvh4" "$L3 --persistent" "$L3 --refill 8" "$L3 --refill 16" "$L3 --refill 24" "$L3 --refill 28" "$L3 --refill 32"; do
      echo "== sponza $c"; $T "$B" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  for c in "--bvh bvh2" "--bvh bvh4" "--bvh cwbvh"; do
    echo "== cornell 1920x1080 $c"; $T "$B" bench traversal --width 1920 --height 1080 $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
  done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  for i in pt pt-nee bdpt; do
    echo "== cornell $i"; $T "$B" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
  done
  echo "== caustic bdpt"; $T "$B" bench render $CAU --width 256 --height 256 --integrator bdpt --spp 256 2>&1 | grep -E "Msamples" | head -1
  for i in pt-nee bdpt; do
    echo "== sponza $i"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  done
  echo "== sponza bdpt bvh4"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --bvh bvh4 --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  D=/tmp/nvcache16; rm -rf $D; mkdir -p $D
  __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$B" bench traversal "$SP" --camera CameraMain $L3 --refill 8 --reps 3 --warmup 1 > /dev/null 2>&1
  tar czf "$OUT/nvcache-refill.tgz" -C $D .
  ;;
s16c)
  # Session 16 (measurement build): BIDIR_TRAV_EXP 1 (loops the subgroup runs together: votes
  # in uniform control flow) on every layout, 17 (and the ray origin in shared memory for the
  # leaf tests, 4-wide trace kernel only); the trace kernels and the integrators.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 40"
  for r in 1 2; do
    for e in 0 1 17; do
      echo "== sponza bvh4 l3 q3 exp $e"; BIDIR_TRAV_EXP=$e $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
    for l in bvh2 cwbvh bvh4; do
      for e in 0 1; do
        echo "== sponza $l exp $e"; BIDIR_TRAV_EXP=$e $T "$B" bench traversal "$SP" --camera CameraMain --bvh $l 2>&1 | grep -E "^(primary|shadow|diffuse) "
      done
    done
  done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  for e in 0 1 0 1; do
    for i in pt pt-nee bdpt; do
      echo "== cornell $i exp $e"; BIDIR_TRAV_EXP=$e $T "$B" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
    done
    echo "== caustic bdpt exp $e"; BIDIR_TRAV_EXP=$e $T "$B" bench render $CAU --width 256 --height 256 --integrator bdpt --spp 256 2>&1 | grep -E "Msamples" | head -1
    for i in pt-nee bdpt; do
      echo "== sponza $i exp $e"; BIDIR_TRAV_EXP=$e $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
    done
    echo "== sponza bdpt bvh4 exp $e"; BIDIR_TRAV_EXP=$e $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --bvh bvh4 --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  done
  D=/tmp/nvcache17; rm -rf $D; mkdir -p $D
  BIDIR_TRAV_EXP=17 __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 --reps 3 --warmup 1 > /dev/null 2>&1
  tar czf "$OUT/nvcache17.tgz" -C $D .
  ;;
s16b)
  # Session 16 (measurement build): 4-wide traversal experiments by BIDIR_TRAV_EXP bits (1:
  # loops the subgroup runs together, votes in uniform control flow; 2: the watertight
  # test's shear computed per leaf visit; 4: no origin slack, measurement only), Sponza,
  # leaf size 3, quality 3; then the machine code of 1 and 3.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  for r in 1 2; do
    for e in 0 1 2 3 4 6 7; do
      echo "== sponza bvh4 exp $e"; BIDIR_TRAV_EXP=$e $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  echo "== sponza bvh4 --no-speculative"; $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 --no-speculative 2>&1 | grep -E "^(primary|shadow|diffuse) "
  for e in 1 3; do
    D=/tmp/nvcache$e; rm -rf $D; mkdir -p $D
    BIDIR_TRAV_EXP=$e __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1 $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 --reps 3 --warmup 1 > /dev/null 2>&1
    tar czf "$OUT/nvcache$e.tgz" -C $D .
  done
  ;;
s16s)
  # Session 16: the machine code of the 4-wide trace kernels (leaf size 3, quality 3) as the
  # driver compiled them: the shader disk cache comes back as $OUT/nvcache.tgz, for
  # scripts/device/sass.py here. Also the figures of the same run.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  export __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1
  timeout -k 5 120 "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
  tar czf "$OUT/nvcache.tgz" -C $D .
  ;;
s16a)
  # Session 16: light paths per pixel (--light-paths R) against equal-time error, now that
  # light tracing is no longer a strategy of direct lighting (Cornell box, caustic scene,
  # the Cornell box whose light hides above a panel: seed-to-seed RMSE).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  HID=".device/scenes/hidden/hidden.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  T="timeout -k 5 60"
  for t in 0.1 1; do
    echo "== cornell pt-nee --time $t"; $T "$B" render $CB --integrator pt-nee --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
  done
  for r in 2 1 0.5 0.25 0.125 0.0625; do
    echo "== cornell bdpt bench r=$r"; $T "$B" bench render $CB --integrator bdpt --light-paths $r --spp 1024 2>&1 | grep -E "Msamples" | head -1
    for t in 0.1 1; do
      echo "== cornell bdpt --time $t r=$r"; $T "$B" render $CB --integrator bdpt --light-paths $r --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
    echo "== caustic bdpt --time 1 r=$r"; $T "$B" render $CAU --integrator bdpt --light-paths $r --time 1 --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    for s in 1 2; do $T "$B" render $HID --integrator bdpt --light-paths $r --seed $s --time 1 -o /tmp/h$s.exr 2>&1 | grep -iE "spp in"; done
    echo "== hidden bdpt --time 1 r=$r, seed 1 against seed 2: $("$B" diff /tmp/h1.exr /tmp/h2.exr 2>&1 | grep -i rmse)"
  done
  ;;
s15f)
  # Session 15's final code (B) against session 14's (BASE, 2cfbab6): the issue's before/after
  # table (time-budgeted renders, Cornell box against the sharper reference, the caustic scene
  # at the test's 128² camera against its committed reference) and the rates.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  T="timeout -k 5 60"
  for t in 0.1 1; do
    for i in pt pt-nee bdpt bdpt:full; do
      for b in "$B" "$BASE"; do
        echo "== cornell $i --time $t $(basename "$b")"; $T "$b" render $CB --integrator $i --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
        echo "== caustic $i --time $t $(basename "$b")"; $T "$b" render $CAU --width 128 --height 128 --integrator $i --time $t --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      done
    done
  done
  for b in "$B" "$BASE"; do
    for i in pt pt-nee bdpt bdpt:full vcm; do
      echo "== cornell $i $(basename "$b")"; $T "$b" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
    done
    for i in pt-nee bdpt; do
      echo "== caustic $i $(basename "$b")"; $T "$b" bench render $CAU --width 256 --height 256 --integrator $i --spp 256 2>&1 | grep -E "Msamples" | head -1
    done
  done
  ;;
s15e)
  # Session 15 (measurement build): the light vertex cache's draws, per subgroup consecutive
  # entries from one random start (BIDIR_LVC_COHERENT=1) against independent draws.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  for c in 0 1 0 1; do
    echo "== cornell bdpt coherent $c"; BIDIR_LVC_COHERENT=$c $T "$B" bench render $CB --integrator bdpt --spp 1024 2>&1 | grep -E "Msamples|^[a-z_0-9]+ +[0-9]" | head -5
    echo "== sponza bdpt coherent $c"; BIDIR_LVC_COHERENT=$c $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples|^[a-z_0-9]+ +[0-9]" | head -3
  done
  for c in 0 1 0 1; do
    echo "== cornell bdpt --time 1 coherent $c"; BIDIR_LVC_COHERENT=$c $T "$B" render $CB --integrator bdpt --time 1 --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
  done
  ;;
s15d)
  # Session 15: the compact light-vertex store (B) against 2abade7 (BASE, 96-byte vertices),
  # interleaved.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  T="timeout -k 5 60"
  for b in "$BASE" "$B" "$BASE" "$B"; do
    echo "== cornell bdpt $(basename "$b")"; $T "$b" bench render $CB --integrator bdpt --spp 1024 2>&1 | grep -E "Msamples|^[a-z_0-9]+ +[0-9]" | head -5
    echo "== cornell vcm:no-merge $(basename "$b")"; $T "$b" bench render $CB --integrator vcm --no-merge --spp 1024 2>&1 | grep -E "Msamples" | head -1
    echo "== caustic bdpt $(basename "$b")"; $T "$b" bench render $CAU --width 256 --height 256 --integrator bdpt --spp 256 2>&1 | grep -E "Msamples" | head -1
    echo "== sponza bdpt $(basename "$b")"; $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  done
  for b in "$B" "$BASE" "$B"; do
    echo "== cornell bdpt --time 1 $(basename "$b")"; $T "$b" render $CB --integrator bdpt --time 1 --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
  done
  for b in "$B" "$BASE"; do
    $T "$b" render $CB --integrator bdpt --spp 64 -o /tmp/c-$(basename "$b").exr > /dev/null 2>&1
    $T "$b" render $CAU --width 128 --height 128 --integrator bdpt --spp 256 -o /tmp/k-$(basename "$b").exr > /dev/null 2>&1
  done
  echo "== cornell 64 spp, compact against 96-byte: $("$B" diff /tmp/c-bidir.exr /tmp/c-bidir-base.exr 2>&1 | grep -i rmse)"
  echo "== caustic 256 spp, compact against 96-byte: $("$B" diff /tmp/k-bidir.exr /tmp/k-bidir-base.exr 2>&1 | grep -i rmse)"
  ;;
s15c)
  # Session 15: VCM without light tracing for direct lighting (default) against
  # --direct-light-tracing, same binary; bdpt beside it.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  SDS="assets/scenes/sds/sds.obj --eye 0.9,1.3,-3.2 --target -0.4,0.4,0 --up 0,1,0 --fov 50 --width 256 --height 256"
  T="timeout -k 5 60"
  for f in "" "--direct-light-tracing"; do
    echo "== cornell vcm bench '$f'"; $T "$B" bench render $CB --integrator vcm $f --spp 1024 2>&1 | grep -E "Msamples" | head -1
  done
  for i in vcm bdpt; do
    for f in "" "--direct-light-tracing" "" "--direct-light-tracing"; do
      echo "== cornell $i --time 1 '$f'"; $T "$B" render $CB --integrator $i $f --time 1 --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
    for f in "" "--direct-light-tracing"; do
      echo "== sds $i --time 1 '$f'"; $T "$B" render $SDS --integrator $i $f --time 1 --reference assets/scenes/sds/reference-h200-vcm.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      echo "== caustic $i --time 1 '$f'"; $T "$B" render $CAU --integrator $i $f --time 1 --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
  done
  ;;
s15b)
  # Session 15: BDPT without light tracing for direct lighting (the default now) against
  # --direct-light-tracing (the previous behaviour), same binary. .device/scenes/hidden: the
  # Cornell box with a panel under its light (where the light hides).
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  HID=".device/scenes/hidden/hidden.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  RC="assets/scenes/rough-cornell/rough-cornell.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 64 --height 64"
  T="timeout -k 5 60"
  for f in "" "--direct-light-tracing" "" "--direct-light-tracing"; do
    echo "== cornell bdpt bench '$f'"; $T "$B" bench render $CB --integrator bdpt $f --spp 1024 2>&1 | grep -E "Msamples|^[a-z_0-9]+ +[0-9]" | head -6
  done
  for t in 0.1 1; do
    for f in "" "--direct-light-tracing" "" "--direct-light-tracing"; do
      echo "== cornell bdpt --time $t '$f'"; $T "$B" render $CB --integrator bdpt $f --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
    echo "== cornell pt-nee --time $t"; $T "$B" render $CB --integrator pt-nee --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
  done
  for f in "" "--direct-light-tracing"; do
    echo "== caustic bdpt --time 1 '$f'"; $T "$B" render $CAU --integrator bdpt $f --time 1 --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    echo "== rough bdpt --time 1 '$f'"; $T "$B" render $RC --integrator bdpt $f --time 1 --reference assets/scenes/rough-cornell/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    for s in 1 2; do $T "$B" render $HID --integrator bdpt $f --seed $s --time 1 -o /tmp/h$s.exr 2>&1 | grep -iE "spp in"; done
    echo "== hidden bdpt --time 1 '$f', seed 1 against seed 2: $("$B" diff /tmp/h1.exr /tmp/h2.exr 2>&1 | grep -i rmse)"
    echo "== sponza bdpt bench '$f'"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt $f --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  done
  for s in 1 2; do $T "$B" render $HID --integrator pt-nee --seed $s --time 1 -o /tmp/h$s.exr 2>&1 | grep -iE "spp in"; done
  echo "== hidden pt-nee --time 1, seed 1 against seed 2: $("$B" diff /tmp/h1.exr /tmp/h2.exr 2>&1 | grep -i rmse)"
  ;;
s15a)
  # Session 15 (measurement build, not committed): where BDPT's time goes on the Cornell box.
  # BIDIR_BDPT_EXP bits drop parts of the passes (1: the light pass's vertex stores, 2: its
  # joins to the camera, 4: their shadow rays (joins computed, not queued), 8: the camera
  # pass's connections, 16: its light samples); BIDIR_LT_KAPPA scales the light-tracing
  # strategy's sample count in the MIS weights.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  T="timeout -k 5 60"
  for e in 0 1 2 4 8 16 24 0; do
    echo "== cornell bdpt exp $e"; BIDIR_BDPT_EXP=$e $T "$B" bench render $CB --integrator bdpt --spp 1024 2>&1 | grep -E "Msamples|^[a-z_0-9]+ +[0-9]" | head -9
  done
  echo "== cornell pt-nee"; $T "$B" bench render $CB --integrator pt-nee --spp 1024 2>&1 | grep -E "Msamples|^[a-z_0-9]+ +[0-9]" | head -4
  for k in 1 0.5 0.3 1 0.5; do
    for t in 0.1 1; do
      echo "== cornell bdpt kappa $k --time $t"; BIDIR_LT_KAPPA=$k $T "$B" render $CB --integrator bdpt --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
  done
  for k in 1 0.5 0.3; do
    echo "== cornell bdpt kappa $k --spp 8192"; BIDIR_LT_KAPPA=$k $T "$B" render $CB --integrator bdpt --spp 8192 --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
  done
  ;;
s13c)
  # Session 13, the committed code (B) against BASE (d788d86): time-budgeted renders (Cornell
  # box against the sharper reference, the caustic scene at the test's 128² camera against its
  # committed reference), the integrators' rates, the trace kernels; the machine code of BDPT.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35"
  T="timeout -k 5 60"
  for t in 0.1 1; do
    for i in pt pt-nee bdpt bdpt:full; do
      for b in "$B" "$BASE" "$B"; do
        echo "== cornell $i --time $t $(basename "$b")"; $T "$b" render $CB --integrator $i --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
        echo "== caustic $i --time $t $(basename "$b")"; $T "$b" render $CAU --width 128 --height 128 --integrator $i --time $t --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      done
    done
  done
  for b in "$B" "$BASE"; do
    for i in pt pt-nee bdpt bdpt:full vcm; do
      echo "== cornell $i $(basename "$b")"
      $T "$b" bench render $CB --integrator $i --spp 1024 2>&1 | grep -E "Msamples" | head -1
    done
    for i in pt pt-nee bdpt; do
      echo "== caustic $i $(basename "$b")"
      $T "$b" bench render $CAU --width 256 --height 256 --integrator $i --spp 256 2>&1 | grep -E "Msamples" | head -1
    done
    for i in pt-nee bdpt; do
      echo "== sponza $i $(basename "$b")"
      $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
    done
    echo "== sponza bdpt --bvh bvh4 $(basename "$b")"
    $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --bvh bvh4 --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  done
  for c in "--bvh bvh4 --leaf-size 3 --quality 3" "--bvh bvh4" "--bvh bvh2" "--bvh cwbvh"; do
    for b in "$B" "$BASE"; do
      echo "== sponza $c $(basename "$b")"
      $T "$b" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  ( export __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1
    $T "$B" render $CB --integrator bdpt --spp 16 -o /tmp/a.exr > /dev/null 2>&1 )
  tar czf "$OUT/cache-bdpt.tgz" -C $D .
  ;;
s13b)
  # Session 13: cheaper Sobol' numbers (bit for bit the same): v1 = the second dimension as a
  # reversed superset transform and dimensions 3 and 4 as per-bit tests (if form), v1s = the
  # same with selects, v2s = v1s with each group's seed and shuffled index kept in the Rng;
  # all with the 4-wide any-hit step without sorting. Against BASE (d788d86), interleaved.
  for f in .device/*.gz; do gunzip -kf "$f"; chmod +x "${f%.gz}"; done
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 60"
  V=".device/bidir-base .device/bidir-v1 .device/bidir-v1s .device/bidir-v2s"
  for r in 1 2; do
    for b in $V; do
      echo "== cornell pt-nee $(basename $b)"
      $T $b bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 2>&1 | sed -n 1,4p
    done
  done
  for b in $V; do
    echo "== cornell bdpt $(basename $b)"
    $T $b bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 2>&1 | sed -n 1,6p
    echo "== caustic pt-nee $(basename $b)"
    $T $b bench render $CAU --integrator pt-nee --spp 256 2>&1 | grep -E "Msamples" | head -1
    echo "== sponza pt-nee $(basename $b)"
    $T $b bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples" | head -1
  done
  for b in $V; do
    $T $b render --integrator pt-nee --spp 64 -o /tmp/$(basename $b)-p.exr > /dev/null 2>&1
    $T $b render --integrator bdpt --spp 16 -o /tmp/$(basename $b)-b.exr > /dev/null 2>&1
    echo "== $(basename $b) against base: pt-nee 64 spp, bdpt 16 spp"
    .device/bidir-base diff /tmp/$(basename $b)-p.exr /tmp/bidir-base-p.exr 2>&1 | grep -iE "rmse"
    .device/bidir-base diff /tmp/$(basename $b)-b.exr /tmp/bidir-base-b.exr 2>&1 | grep -iE "rmse"
  done
  for b in .device/bidir-v1s .device/bidir-v2s; do
    echo "== kernels $(basename $b)"
    $T $b info --kernels 2>&1 | grep -E "^(pt-nee|bdpt:lvc=1) " | head -6
  done
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  ( export __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1
    $T .device/bidir-v2s render $CB --integrator pt-nee --spp 64 -o /tmp/a.exr > /dev/null 2>&1 )
  tar czf "$OUT/cache-v2s.tgz" -C $D .
  ;;
s13a)
  # Session 13, first look: what Owen-scrambled Sobol' numbers cost pt-nee and bdpt now
  # (samplers against each other, one binary), the 4-wide any-hit step without sorting (B)
  # against BASE, and the driver's shader cache of a pt-nee and a bdpt render (machine code,
  # scripts/device/sass.py here).
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  for r in 1 2; do
    for smp in sobol independent sobol:4 sobol:2; do
      echo "== cornell pt-nee --sampler $smp"
      $T "$BASE" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 --sampler $smp 2>&1 | head -4
    done
  done
  for smp in sobol independent; do
    echo "== cornell bdpt --sampler $smp"
    $T "$BASE" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 --sampler $smp 2>&1 | head -6
  done
  for r in 1 2; do
    for b in "$B" "$BASE"; do
      echo "== sponza bvh4 leaf 3 quality 3 $(basename "$b")"
      $T "$b" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 --reps 5 --warmup 2 2>&1 | grep -E "^(primary|shadow|diffuse) "
    done
  done
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  ( export __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1
    $T "$BASE" render $CB --integrator pt-nee --spp 64 -o /tmp/a.exr > /dev/null 2>&1
    $T "$BASE" info --kernels 2>&1 | grep -iE "pt|regist" | head -20 )
  tar czf "$OUT/cache-ptnee.tgz" -C $D .
  ;;
sass)
  # #17 (session 12): the machine code of the trace kernels, carved from the driver's shader
  # disk cache (scripts/device/sass.py), for bvh4 and bvh2, watertight.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  D=/tmp/nvcache; rm -rf $D; mkdir -p $D
  export __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$D __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1
  which cuobjdump nvdisasm
  timeout -k 5 120 "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 --leaf-size 3 --quality 3 --reps 5 --warmup 1 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
  find $D -type f -exec ls -la {} \;
  python3 scripts/device/sass.py $D "$OUT/sass"
  ;;
bvh4)
  # #17 (session 9): the binary tree collapsed to 4-wide nodes of full-precision boxes
  # (--bvh bvh4) against bvh2 and cwbvh, interleaved, then its options once each.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 60"
  for r in 1 2; do
    for c in "--bvh bvh2" "--bvh bvh4" "--bvh cwbvh" "--bvh bvh4 --float-slabs"; do
      echo "== sponza $c"
      $T "$B" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register|nodes of"
    done
  done
  for c in "--bvh bvh4 --no-speculative" "--bvh bvh4 --leaf-size 2" "--bvh bvh4 --leaf-size 8" "--bvh bvh4 --quality 3" \
           "--bvh bvh4 --tri-test woop --quality 3" "--bvh cwbvh --tri-test woop --quality 3" "--bvh bvh4 --persistent"; do
    echo "== sponza $c"
    $T "$B" bench traversal "$SP" --camera CameraMain $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register|nodes of"
  done
  for c in "--bvh bvh2" "--bvh bvh4" "--bvh cwbvh"; do
    echo "== cornell 1920x1080 $c"
    $T "$B" bench traversal --width 1920 --height 1080 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |Register"
  done
  ;;
bvh4-int)
  # #16/#17 (session 9): the integrators over the 4-wide BVH (--bvh bvh4) against the
  # layouts they use now, interleaved; then the 4-wide tree's leaf size and build quality.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 60"
  for r in 1 2; do
    for l in cwbvh bvh4 bvh2; do
      echo "== cornell pt-nee --bvh $l"; $T "$B" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 --bvh $l 2>&1 | grep -E "Msamples"
    done
    for l in bvh2 bvh4; do
      echo "== cornell bdpt --bvh $l"; $T "$B" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 --bvh $l 2>&1 | grep -E "Msamples"
    done
  done
  for l in cwbvh bvh4; do
    echo "== cornell pt --bvh $l"; $T "$B" bench render $CB --integrator pt --spp 1024 --warmup 2 --runs 5 --bvh $l 2>&1 | grep -E "Msamples"
  done
  for i in pt-nee bdpt; do
    for l in bvh2 bvh4 cwbvh bvh4; do
      echo "== sponza $i --bvh $l"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 --bvh $l 2>&1 | grep -E "Msamples"
    done
    for l in bvh2 bvh4 bvh2 bvh4; do
      echo "== caustic $i --bvh $l"; $T "$B" bench render $CAU --integrator $i --spp 256 --warmup 1 --runs 3 --bvh $l 2>&1 | grep -E "Msamples"
    done
  done
  for c in "--leaf-size 2" "--leaf-size 3" "--leaf-size 2 --quality 3" "--leaf-size 3 --quality 3" "--leaf-size 4"; do
    echo "== sponza --bvh bvh4 $c"
    $T "$B" bench traversal "$SP" --camera CameraMain --bvh bvh4 $c 2>&1 | grep -E "^(primary|shadow|diffuse) |nodes of"
  done
  ;;
glossy-layout)
  # #16 (session 9): pt and pt-nee over the binary and the compressed wide BVH in scenes with
  # GGX lobes but no mirror or glass (the default picks bvh2 there), interleaved. Needs
  # .device/scenes/gltf/{DamagedHelmet,MetalRoughSpheresNoTextures}.glb.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  ROUGH="assets/scenes/rough-cornell/rough-cornell.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  T="timeout -k 5 60"
  for i in pt-nee pt; do
    for l in bvh2 cwbvh bvh2 cwbvh; do
      echo "== sponza $i --bvh $l"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 --bvh $l 2>&1 | grep -E "Msamples"
      echo "== rough-cornell $i --bvh $l"; $T "$B" bench render $ROUGH --integrator $i --spp 256 --warmup 1 --runs 3 --bvh $l 2>&1 | grep -E "Msamples"
      for m in DamagedHelmet MetalRoughSpheresNoTextures; do
        echo "== $m $i --bvh $l"; $T "$B" bench render .device/scenes/gltf/$m.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --integrator $i --spp 256 --warmup 1 --runs 3 --bvh $l 2>&1 | grep -E "Msamples"
      done
    done
  done
  for l in bvh2 cwbvh; do
    timeout -k 5 90 "$B" info --kernels --bvh $l "$SP" --sponza-sun-sky 2>&1 | grep -E "^pt" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
  done
  ;;
counts)
  # #16 (session 9): what the integrator kernels trace per sample (`bench render --count`) and
  # the rate that makes at their timed speed, beside the trace kernel's own on the same scene.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 90"
  for i in pt pt-nee bdpt; do
    echo "== cornell $i"; $T "$B" bench render $CB --integrator $i --spp 1024 --warmup 2 --runs 5 --count 2>&1 | grep -E "Msamples|traversal|^(pt|bdpt)"
  done
  for i in pt-nee bdpt; do
    echo "== sponza $i"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 --count 2>&1 | grep -E "Msamples|traversal|^(pt|bdpt)"
  done
  echo "== sponza pt-nee --bvh bvh2"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 --count --bvh bvh2 2>&1 | grep -E "Msamples|traversal"
  echo "== sponza trace kernels 640x360 (bvh2, cwbvh)"
  for l in bvh2 cwbvh; do $T "$B" bench traversal "$SP" --camera CameraMain --width 640 --height 360 --bvh $l 2>&1 | grep -E "^(primary|shadow|diffuse) "; done
  echo "== cornell trace kernels 256x256 (cwbvh, bvh2)"
  for l in cwbvh bvh2; do $T "$B" bench traversal --width 256 --height 256 --bvh $l 2>&1 | grep -E "^(primary|shadow|diffuse) "; done
  ;;
no-shadow)
  # #16 (session 9): what the shadow rays of NEE and BDPT's connections cost inside the
  # megakernels. EXP = a build of this commit with visible_between (glsl/common/scene.glsl)
  # returning true before its trace (a measurement only: the image is wrong).
  EXP=${EXP:-$PWD/.device/bidir-exp}
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 90"
  for b in "$B" "$EXP" "$B" "$EXP"; do
    for i in pt-nee bdpt; do
      echo "== $(basename "$b") cornell $i"; $T "$b" bench render $CB --integrator $i --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples|^(pt|bdpt)"
      echo "== $(basename "$b") sponza $i"; $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples|^(pt|bdpt)"
    done
  done
  for i in pt-nee bdpt; do
    echo "== exp counts cornell $i"; $T "$EXP" bench render $CB --integrator $i --spp 64 --warmup 0 --runs 1 --count 2>&1 | grep -E "traversal"
    echo "== exp counts sponza $i"; $T "$EXP" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator $i --spp 8 --warmup 0 --runs 1 --count 2>&1 | grep -E "traversal"
  done
  timeout -k 5 90 "$EXP" info --kernels "$SP" --sponza-sun-sky 2>&1 | grep -E "^(pt|bdpt)" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
  timeout -k 5 90 "$B" info --kernels "$SP" --sponza-sun-sky 2>&1 | grep -E "^(pt|bdpt)" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
  ;;
one-trace)
  # #16 (session 9): pt-nee with the extension and the shadow ray through one trace_ray call
  # (NEW) against BASE, interleaved, on the scenes of every light kind.
  NEW=${NEW:-$PWD/.device/bidir-new}
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  ROUGH="assets/scenes/rough-cornell/rough-cornell.obj --eye 278,273,-800 --target 278,273,-799 --up 0,1,0 --fov 39.3077 --width 256 --height 256"
  T="timeout -k 5 90"
  for b in "$BASE" "$NEW" "$BASE" "$NEW"; do
    n=$(basename "$b")
    echo "== $n cornell"; $T "$b" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples"
    echo "== $n cornell bvh2"; $T "$b" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 --bvh bvh2 2>&1 | grep -E "Msamples"
    echo "== $n sponza"; $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
    echo "== $n caustic"; $T "$b" bench render $CAU --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
    [ -n "${QUICK:-}" ] || { echo "== $n rough"; $T "$b" bench render $ROUGH --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"; }
  done
  for b in "$BASE" "$NEW"; do
    echo "== $(basename "$b") kernels"
    timeout -k 5 60 "$b" info --kernels 2>&1 | grep -E "^pt-nee" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
    timeout -k 5 90 "$b" info --kernels "$SP" --sponza-sun-sky 2>&1 | grep -E "^pt-nee" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
  done
  for b in "$BASE" "$NEW"; do $T "$b" render $CB --integrator pt-nee --spp 64 -o "/tmp/$(basename "$b").exr" 2>&1 | tail -1; done
  "$NEW" diff "/tmp/$(basename "$NEW").exr" "/tmp/$(basename "$BASE").exr" 2>&1 | head -3
  ;;
bdpt-one-trace)
  # #16 (session 9): BDPT's camera pass with its shadow rays through the extension rays'
  # trace call (--one-trace on) against off, interleaved, in one binary.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  for r in 1 2; do
    for o in off on; do
      echo "== cornell bdpt --one-trace $o"; $T "$B" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 --one-trace $o 2>&1 | grep -E "Msamples|^bdpt_"
      echo "== sponza bdpt --one-trace $o"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 --one-trace $o 2>&1 | grep -E "Msamples|^bdpt_"
      echo "== caustic bdpt --one-trace $o"; $T "$B" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 --one-trace $o 2>&1 | grep -E "Msamples"
    done
  done
  for o in off on; do
    $T "$B" render $CB --integrator bdpt --spp 64 --one-trace $o -o "/tmp/bdpt-$o.exr" 2>&1 | tail -1
  done
  "$B" diff /tmp/bdpt-on.exr /tmp/bdpt-off.exr 2>&1 | head -3
  ;;
final9)
  # Session 9's defaults on the Cornell box and Sponza (against the session's figures).
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 90"
  for r in 1 2; do
    for i in pt-nee bdpt; do
      echo "== cornell $i"; $T "$B" bench render $CB --integrator $i --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples"
    done
    echo "== sponza pt-nee"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
  done
  ;;
shadow-queue)
  # #16 (session 10): pt-nee's shadow rays queued for their own kernel (--shadow-queue
  # SLOTS/SAMPLES) against none, one binary, interleaved.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  for r in 1 2; do
    for q in ${QUEUES:-off 64/8 64/16 128/16 128/32 32/4}; do
      echo "== cornell --shadow-queue $q"; $T "$B" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 --shadow-queue $q 2>&1 | grep -E "Msamples"
    done
    echo "== cornell --one-trace on --shadow-queue 64/8"; $T "$B" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 --one-trace on --shadow-queue 64/8 2>&1 | grep -E "Msamples"
    for q in off ${SPQ:-64/8 128/16}; do
      echo "== sponza --shadow-queue $q"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "Msamples"
      echo "== caustic --shadow-queue $q"; $T "$B" bench render $CAU --integrator pt-nee --spp 256 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "Msamples"
    done
  done
  timeout -k 5 60 "$B" info --kernels --shadow-queue 64 2>&1 | grep -E "^pt-nee|shadow" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
  timeout -k 5 90 "$B" info --kernels "$SP" --sponza-sun-sky --shadow-queue 64 2>&1 | grep -E "^pt-nee|shadow" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
  for q in off 64/8; do $T "$B" render $CB --integrator pt-nee --spp 64 --shadow-queue $q -o "/tmp/sq-${q%/*}.exr" 2>&1 | tail -1; done
  "$B" diff /tmp/sq-off.exr /tmp/sq-64.exr 2>&1 | head -3
  ;;
queue-exp)
  # #16 (session 10): where the shadow-ray queue's time goes (per-kernel times), and what the
  # megakernel would gain without its fallback trace (DROP: a measurement-only build that
  # drops shadow rays finding the queue full: biased, never committed).
  DROP=${DROP:-$PWD/.device/bidir-drop}
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  K="Msamples|^pt|^shadow"
  for b in "$B" "$DROP"; do
    n=$(basename "$b")
    for q in off 128/16; do
      echo "== $n cornell --shadow-queue $q"; $T "$b" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 --shadow-queue $q 2>&1 | grep -E "$K"
    done
    for o in on off; do
      echo "== $n sponza --one-trace $o --shadow-queue 128/16"; $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 --one-trace $o --shadow-queue 128/16 2>&1 | grep -E "$K"
      echo "== $n caustic --one-trace $o --shadow-queue 128/16"; $T "$b" bench render $CAU --integrator pt-nee --spp 256 --warmup 1 --runs 3 --one-trace $o --shadow-queue 128/16 2>&1 | grep -E "$K"
    done
    timeout -k 5 60 "$b" info --kernels --shadow-queue 128 2>&1 | grep -E "^pt-nee" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
    timeout -k 5 90 "$b" info --kernels "$SP" --sponza-sun-sky --shadow-queue 128 2>&1 | grep -E "^pt-nee" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
  done
  echo "== sponza --shadow-queue off"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 --shadow-queue off 2>&1 | grep -E "$K"
  echo "== sponza counts"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 4 --warmup 0 --runs 1 --count 2>&1 | grep -E "traversal"
  ;;
queue-suspend)
  # #16 (session 10): the shadow-ray queue with paths paused where the slots are full
  # (--shadow-queue SLOTS/SAMPLES) against none, one binary, per-kernel times.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  K="Msamples|^pt|^shadow"
  for r in 1 2; do
    for q in ${QUEUES:-off 64/8 128/16 128/32 256/32 256/64}; do
      echo "== cornell --shadow-queue $q"; $T "$B" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 --shadow-queue $q 2>&1 | grep -E "$K"
    done
    for q in off ${SPQ:-128/16 256/32 128/8}; do
      echo "== sponza --shadow-queue $q"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "$K"
      echo "== caustic --shadow-queue $q"; $T "$B" bench render $CAU --integrator pt-nee --spp 256 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "$K"
    done
  done
  timeout -k 5 60 "$B" info --kernels --shadow-queue 128 2>&1 | grep -E "^pt-nee" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
  timeout -k 5 90 "$B" info --kernels "$SP" --sponza-sun-sky --shadow-queue 128 2>&1 | grep -E "^pt-nee" | sed -E 's/Local Memory Size [0-9]+; //; s/ \([0-9]+ statistics\)//'
  for q in off 128; do $T "$B" render $CB --integrator pt-nee --spp 64 --shadow-queue $q -o "/tmp/sq-$q.exr" 2>&1 | tail -1; done
  "$B" diff /tmp/sq-off.exr /tmp/sq-128.exr 2>&1 | head -3
  ;;
queue-final)
  # #16 (session 10): the shadow-ray queue with a finishing launch; NOSUSP: a measurement-only
  # build whose queue launches never pause (the finishing kernel, with its second traversal,
  # for every launch).
  NOSUSP=${NOSUSP:-$PWD/.device/bidir-nosusp}
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  K="Msamples|^pt|^shadow"
  for r in 1 2; do
    for q in off 128/16 256/32 64/8; do
      echo "== cornell --shadow-queue $q"; $T "$B" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 --shadow-queue $q 2>&1 | grep -E "$K"
    done
    echo "== nosusp cornell --shadow-queue 128/16"; $T "$NOSUSP" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 --shadow-queue 128/16 2>&1 | grep -E "$K"
    for q in off 128/16 128/8 256/32; do
      echo "== sponza --shadow-queue $q"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "$K"
    done
    echo "== nosusp sponza --shadow-queue 128/16"; $T "$NOSUSP" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 --shadow-queue 128/16 2>&1 | grep -E "$K"
    for q in off 128/16; do
      echo "== caustic --shadow-queue $q"; $T "$B" bench render $CAU --integrator pt-nee --spp 256 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "$K"
      echo "== caustic bvh2-regen --shadow-queue $q"; $T "$B" bench render $CAU --integrator pt-nee --spp 256 --warmup 1 --runs 3 --path-regeneration on --shadow-queue $q 2>&1 | grep -E "$K"
    done
  done
  ;;
queue-defaults)
  # #16 (session 10): the shadow-ray queue's shapes and the default (auto) against none, with
  # the slots the memory budget allows printed in the kernel form. glTF models as glossy-layout.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  K="Msamples|^pt|^shadow"
  "$B" info 2>&1 | grep -E "limits|heap" | head -3
  for r in 1 2; do
    for q in off auto 128/16/pause 192/24 64/16; do
      echo "== cornell --shadow-queue $q"; $T "$B" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 --shadow-queue $q 2>&1 | grep -E "$K"
    done
    for q in off auto 128/16 96/12/pause 192/24/pause; do
      echo "== sponza --shadow-queue $q"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "$K"
    done
    for m in DamagedHelmet MetalRoughSpheresNoTextures; do
      for q in off auto; do
        echo "== $m --shadow-queue $q"; $T "$B" bench render .device/scenes/gltf/$m.glb --env 0.6,0.6,0.6 --sun "0.4,1,0.7;2.5,2.5,2.5;2" --width 384 --height 384 --integrator pt-nee --spp 256 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "Msamples"
      done
    done
    echo "== caustic auto"; $T "$B" bench render $CAU --integrator pt-nee --spp 256 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
  done
  for q in off auto; do $T "$B" render $CB --integrator pt-nee --spp 64 --shadow-queue $q -o "/tmp/sq-$q.exr" 2>&1 | tail -1; done
  "$B" diff /tmp/sq-off.exr /tmp/sq-auto.exr 2>&1 | head -3
  ;;
queue-time)
  # #16 (session 10): time-budgeted renders of the Cornell box with the shadow-ray queue (the
  # default) and without, against the sharper reference; then the defaults' rates.
  T="timeout -k 5 90"
  for r in 1 2; do
    for q in auto off; do
      for t in 0.1 1; do
        echo "== pt-nee --time $t --shadow-queue $q"; $T "$B" render $CB --integrator pt-nee --time $t --shadow-queue $q --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      done
    done
  done
  for i in pt-nee bdpt; do
    echo "== cornell $i"; $T "$B" bench render $CB --integrator $i --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples"
  done
  ;;
bdpt-queue)
  # #16 (session 10): BDPT's (and VCM's) camera pass with the shadow-ray queue (--shadow-queue
  # SLOTS) against none; pt-nee's default again; time-budgeted pt-nee renders.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  K="Msamples|^bdpt|^shadow|^pt"
  for r in 1 2; do
    for q in off 8 16 32; do
      echo "== cornell bdpt --shadow-queue $q"; $T "$B" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 --shadow-queue $q 2>&1 | grep -E "$K"
    done
    for q in off 16; do
      echo "== sponza bdpt --shadow-queue $q"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "$K"
      echo "== caustic bdpt --shadow-queue $q"; $T "$B" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "Msamples"
      echo "== cornell vcm --shadow-queue $q"; $T "$B" bench render $CB --integrator vcm --spp 1024 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "Msamples"
    done
    echo "== cornell pt-nee auto"; $T "$B" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples"
    echo "== sponza pt-nee auto"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
    for t in 0.1 1; do
      for q in auto off; do
        echo "== pt-nee --time $t --shadow-queue $q"; $T "$B" render $CB --integrator pt-nee --time $t --shadow-queue $q --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      done
    done
  done
  for q in off 16; do $T "$B" render $CB --integrator bdpt --spp 64 --shadow-queue $q -o "/tmp/bq-$q.exr" 2>&1 | tail -1; done
  "$B" diff /tmp/bq-off.exr /tmp/bq-16.exr 2>&1 | head -3
  ;;
bdpt-queue2)
  # #16 (session 10): bdpt-queue's BDPT and VCM half again (its first run carried a build whose
  # camera pass discarded the queued rays: a mutation test's binary).
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  K="Msamples|^bdpt|^shadow"
  for q in off 16; do $T "$B" render $CB --integrator bdpt --spp 64 --shadow-queue $q -o "/tmp/bq-$q.exr" 2>&1 | tail -1; done
  "$B" diff /tmp/bq-off.exr /tmp/bq-16.exr 2>&1 | head -4
  for r in 1 2; do
    for q in off 16 32; do
      echo "== cornell bdpt --shadow-queue $q"; $T "$B" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 --shadow-queue $q 2>&1 | grep -E "$K"
    done
    for q in off 16; do
      echo "== sponza bdpt --shadow-queue $q"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "$K"
      echo "== caustic bdpt --shadow-queue $q"; $T "$B" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "Msamples"
      echo "== cornell vcm --shadow-queue $q"; $T "$B" bench render $CB --integrator vcm --spp 1024 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "Msamples"
    done
  done
  ;;
joins11)
  # #16 (session 11): with the queue and the wide BVH, BDPT's connections per camera vertex at
  # equal time again (session 7 chose lvc=1): Cornell box against the sharper reference, the
  # caustic scene (128², the test's camera) against its committed reference; two runs.
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 128 --height 128"
  T="timeout -k 5 60"
  for r in 1 2; do
    for j in bdpt:lvc=1 bdpt:lvc=2 bdpt:lvc bdpt:single pt-nee; do
      echo "== cornell $j --time 1"; $T "$B" render $CB --integrator $j --time 1 --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      echo "== caustic $j --time 1"; $T "$B" render $CAU --integrator $j --time 1 --reference assets/scenes/caustic/reference.exr -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
  done
  ;;
bdpt-slots)
  # #16 (session 11): BDPT's and VCM's queue slots over the wide BVH (32 is the default,
  # chosen over the binary BVH in session 10), interleaved.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  K="Msamples|^bdpt_|^shadow"
  for r in 1 2; do
    for q in 8 16 32 64; do
      echo "== cornell bdpt --shadow-queue $q"; $T "$B" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 --shadow-queue $q 2>&1 | grep -E "$K"
    done
  done
  for q in 8 16 32 64; do
    echo "== sponza bdpt --shadow-queue $q"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "$K"
    echo "== caustic bdpt --shadow-queue $q"; $T "$B" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "Msamples"
    echo "== cornell vcm --shadow-queue $q"; $T "$B" bench render $CB --integrator vcm --spp 1024 --warmup 1 --runs 3 --shadow-queue $q 2>&1 | grep -E "Msamples"
  done
  echo "== registers"; "$B" info --kernels 2>&1 | grep -E "^bdpt:lvc=1|^vcm /" | cut -c1-100
  ;;
defaults11)
  # #16 (session 11): the defaults after fcf3c5d (BDPT and VCM over the wide BVH with their
  # shadow rays queued), against BASE = 55e7dbc (session 10's defaults); then bdpt against
  # pt-nee at equal time on the Cornell box (sharper reference), twice.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  T="timeout -k 5 90"
  for b in "$BASE" "$B"; do
    n=$(basename "$b")
    for i in pt-nee bdpt vcm; do
      echo "== $n cornell $i"; $T "$b" bench render $CB --integrator $i --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "Msamples"
    done
    echo "== $n sponza bdpt"; $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
  done
  for r in 1 2; do
    for t in 0.1 1; do
      for i in pt-nee bdpt; do
        echo "== $i --time $t"; $T "$B" render $CB --integrator $i --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
      done
    done
  done
  for i in bdpt vcm; do
    $T "$B" render $CB --integrator $i --spp 64 --bvh bvh2 -o "/tmp/$i-b2.exr" 2>&1 | tail -1
    $T "$B" render $CB --integrator $i --spp 64 -o "/tmp/$i-auto.exr" 2>&1 | tail -1
    "$B" diff "/tmp/$i-b2.exr" "/tmp/$i-auto.exr" 2>&1 | head -2
  done
  ;;
bdpt-layout)
  # #16 (session 11): with both passes' shadow rays queued, BDPT's and VCM's kernels over each
  # BVH layout (bvh2 is their default), interleaved; registers per kernel and layout.
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  K="Msamples|^bdpt_|^shadow"
  for r in 1 2; do
    for l in bvh2 cwbvh bvh4; do
      echo "== cornell bdpt --bvh $l"; $T "$B" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 --bvh $l 2>&1 | grep -E "$K"
    done
  done
  for l in bvh2 cwbvh bvh4; do
    echo "== sponza bdpt --bvh $l"; $T "$B" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 --bvh $l 2>&1 | grep -E "$K"
    echo "== caustic bdpt --bvh $l"; $T "$B" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 --bvh $l 2>&1 | grep -E "Msamples"
    echo "== cornell vcm --bvh $l"; $T "$B" bench render $CB --integrator vcm --spp 1024 --warmup 1 --runs 3 --bvh $l 2>&1 | grep -E "Msamples"
    echo "== registers --bvh $l"; "$B" info --kernels --bvh $l 2>&1 | grep -E "bdpt|shadow" | cut -c1-110
  done
  ;;
light-queue)
  # #16 (session 11): BDPT's light pass queuing its joins to the camera (B) against the camera
  # pass alone queuing (BASE = 55e7dbc), interleaved; the same images; then bdpt against
  # pt-nee at equal time on the Cornell box (sharper reference).
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  K="Msamples|^bdpt_|^shadow"
  for b in "$BASE" "$B" "$BASE" "$B"; do
    n=$(basename "$b")
    echo "== $n cornell bdpt"; $T "$b" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "$K"
    echo "== $n sponza bdpt"; $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "$K"
  done
  for b in "$BASE" "$B"; do
    n=$(basename "$b")
    echo "== $n caustic bdpt"; $T "$b" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
    echo "== $n cornell vcm"; $T "$b" bench render $CB --integrator vcm --spp 1024 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
  done
  for i in bdpt vcm; do
    for q in off auto; do $T "$B" render $CB --integrator $i --spp 64 --shadow-queue $q -o "/tmp/$i-$q.exr" 2>&1 | tail -1; done
    "$B" diff "/tmp/$i-off.exr" "/tmp/$i-auto.exr" 2>&1 | head -2
  done
  for t in 0.1 1; do
    for i in pt-nee bdpt; do
      echo "== $i --time $t"; $T "$B" render $CB --integrator $i --time $t --reference "$REF" -o /tmp/t.exr 2>&1 | grep -iE "spp in|rmse"
    done
  done
  ;;
queue-balanced)
  # #16 (session 10): the queue's kernel sharing a subgroup's rays over its lanes (B) against
  # one lane tracing its own queue (LOOP, the commit before), interleaved; the same images.
  LOOP=${LOOP:-$PWD/.device/bidir-loop}
  SP=${SPONZA:-$PWD/.device/scenes/sponza/Sponza.gltf}
  CAU="assets/scenes/caustic/caustic.obj --eye 0,1.0,-2.0 --target 0,0.15,-0.2 --up 0,1,0 --fov 35 --width 256 --height 256"
  T="timeout -k 5 90"
  K="Msamples|^bdpt_camera|^shadow|^pt"
  for b in "$LOOP" "$B"; do
    n=$(basename "$b")
    echo "== $n cornell pt-nee"; $T "$b" bench render $CB --integrator pt-nee --spp 1024 --warmup 2 --runs 5 2>&1 | grep -E "$K"
    echo "== $n cornell bdpt"; $T "$b" bench render $CB --integrator bdpt --spp 1024 --warmup 2 --runs 5 --shadow-queue 32 2>&1 | grep -E "$K"
    echo "== $n sponza bdpt"; $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator bdpt --spp 64 --warmup 1 --runs 3 --shadow-queue 32 2>&1 | grep -E "$K"
    echo "== $n sponza pt-nee"; $T "$b" bench render "$SP" --sponza-sun-sky --camera CameraMain --width 640 --height 360 --integrator pt-nee --spp 64 --warmup 1 --runs 3 2>&1 | grep -E "$K"
  done
  echo "== caustic bdpt (auto)"; $T "$B" bench render $CAU --integrator bdpt --spp 256 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
  echo "== cornell vcm (auto)"; $T "$B" bench render $CB --integrator vcm --spp 1024 --warmup 1 --runs 3 2>&1 | grep -E "Msamples"
  for i in pt-nee bdpt; do
    for q in off auto; do $T "$B" render $CB --integrator $i --spp 64 --shadow-queue $q -o "/tmp/$i-$q.exr" 2>&1 | tail -1; done
    "$B" diff "/tmp/$i-off.exr" "/tmp/$i-auto.exr" 2>&1 | head -2
  done
  ;;
*) echo "usage: $0 speed|vcm|rough|trav|defaults|final|light-paths|vcm-first|bvh-quality|bdpt-joins|join-default|driver-rt|int-slabs|bvh4|bvh4-int|glossy-layout|counts|no-shadow|one-trace|bdpt-one-trace|final9|shadow-queue|queue-exp|queue-suspend|queue-final|queue-defaults|queue-time|bdpt-queue|bdpt-queue2|queue-balanced" >&2; exit 2 ;;
esac
