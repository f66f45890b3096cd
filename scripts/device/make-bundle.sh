#!/usr/bin/env bash
# Rebuild .device/ from nothing (a new checkout has none), for scripts/device/pending-h200.sh:
# the loader and validation-layer packages and env.sh (../shared/tools/device/bundle.sh), Sponza's
# geometry, the box whose light hides above a panel (as tests/render_caustic.rs builds it),
# DamagedHelmet, the sharper Cornell reference as .device/ref.exr, and this checkout's release
# build as .device/bidir-NAME.gz for each NAME given; NAME=PATCH builds with
# scripts/device/PATCH applied (and reverted after). Run from the repository root with
# CARGO_TARGET_DIR and SHADERC_LIB_DIR set (scripts/setup.sh). It empties .device/ first: a
# part's test binary (.device/test-traversal.gz) is gzipped into it afterwards.
#   bash scripts/device/make-bundle.sh ls fe=s47a-full-entries.patch
set -euo pipefail
root=$(git rev-parse --show-toplevel)
cd "$root"
shared="$root/../shared"
tgt=${CARGO_TARGET_DIR:-$root/target}

bash "$shared/tools/device/bundle.sh" --geometry-only sponza > /dev/null
rm -f .device/bidir

mkdir -p .device/scenes/hidden .device/scenes/gltf
cp -r "$shared/scenes/gltf-samples/DamagedHelmet" .device/scenes/gltf/
cp "$shared/references/cornell-box/reference-bidir-h200.exr" .device/ref.exr
cp assets/cornell-box.mtl .device/scenes/hidden/
n=$(grep -c '^v ' assets/cornell-box.obj)
{
  cat assets/cornell-box.obj
  printf 'o panel\nusemtl floor\nv 400 500 170\nv 150 500 170\nv 150 500 390\nv 400 500 390\n'
  printf 'f %d %d %d\nf %d %d %d\n' $((n + 1)) $((n + 2)) $((n + 3)) $((n + 1)) $((n + 3)) $((n + 4))
} > .device/scenes/hidden/hidden.obj

for spec in "$@"; do
  name=${spec%%=*}
  patch=""
  [ "$spec" != "$name" ] && patch=scripts/device/${spec#*=}
  [ -n "$patch" ] && git apply "$patch"
  touch src/main.rs
  if ! cargo build --release --quiet; then
    [ -n "$patch" ] && git apply -R "$patch"
    exit 1
  fi
  [ -n "$patch" ] && git apply -R "$patch"
  strip -o "/tmp/bidir-$name" "$tgt/release/bidir"
  gzip -c "/tmp/bidir-$name" > ".device/bidir-$name.gz"
done
du -sh .device
