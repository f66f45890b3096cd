#!/usr/bin/env bash
# Sourced by scripts/bidir, scripts/test and .ci/run. Makes a fresh Debian/Ubuntu machine
# ready to build and run bidir, doing only what is missing:
#   1. apt packages: Vulkan loader, lavapipe (mesa-vulkan-drivers), Khronos validation layers,
#      Debian's shaderc/glslang/SPIRV-Tools static libraries, Xvfb and X11 libraries (viewer);
#   2. the fast shaderc path: Debian's static archives merged into one libshaderc_combined.a
#      (Debian's own libshaderc_combined.a lacks the glslang and SPIRV-Tools symbols), and
#      SHADERC_LIB_DIR pointed at it. If that cannot be done, the fallback builds shaderc from
#      C++ source (~13 min once; needs cmake, git, python3, g++) via --features shaderc-from-source;
#   3. CARGO_TARGET_DIR outside the clone (default ~/.cache/bidir/target) so rebuilds are warm,
#      and BIDIR_SPV_CACHE (~/.cache/bidir/spv) for build.rs's compiled kernels.
# Exports: SHADERC_LIB_DIR (fast path), BIDIR_CARGO_FEATURES (fallback), CARGO_TARGET_DIR,
# BIDIR_SPV_CACHE.

bidir_cache=${BIDIR_CACHE:-$HOME/.cache/bidir}
mkdir -p "$bidir_cache"

bidir_sudo() { if [ "$(id -u)" = 0 ]; then "$@"; elif command -v sudo >/dev/null; then sudo "$@"; else "$@"; fi; }

bidir_apt_install() {
  local missing=()
  for p in "$@"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
  [ ${#missing[@]} -eq 0 ] && return 0
  if ! command -v apt-get >/dev/null; then
    echo "setup: please install: ${missing[*]} (no apt-get on this machine)" >&2; return 1
  fi
  echo "setup: installing ${missing[*]}" >&2
  bidir_sudo apt-get update -qq >/dev/null 2>&1 || true
  DEBIAN_FRONTEND=noninteractive bidir_sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

if ! command -v cargo >/dev/null; then
  [ -x "$HOME/.cargo/bin/cargo" ] && export PATH="$HOME/.cargo/bin:$PATH"
fi
command -v cargo >/dev/null || { echo "setup: cargo not found; install Rust (https://rustup.rs) first" >&2; return 1 2>/dev/null || exit 1; }

bidir_apt_install libvulkan1 libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers pkg-config \
  || { echo "setup: could not install the Vulkan packages" >&2; return 1 2>/dev/null || exit 1; }

# The viewer (`bidir view`): the X11 libraries winit loads at run time, and Xvfb (with
# xauth, which xvfb-run needs) so its tests have a display on machines without one. Not
# fatal: without them only the viewer's window test is skipped.
bidir_apt_install xvfb xauth libx11-xcb1 libxcursor1 libxrandr2 libxi6 libxkbcommon-x11-0 \
  || echo "setup: could not install Xvfb and the X11 libraries; the viewer's window test will be skipped" >&2

export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$bidir_cache/target}
# build.rs keeps compiled kernels here, keyed by their preprocessed source: a fresh clone (CI)
# or clippy's build compiles only the kernels that changed. Empty: no cache.
export BIDIR_SPV_CACHE=${BIDIR_SPV_CACHE-$bidir_cache/spv}
export BIDIR_CARGO_FEATURES=${BIDIR_CARGO_FEATURES:-}

bidir_merge_shaderc() {
  local lib=/usr/lib/$(gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
  local out="$bidir_cache/shaderc"
  local libs="libshaderc_combined libglslang libMachineIndependent libGenericCodeGen libOSDependent
              libOGLCompiler libHLSL libSPIRV libglslang-default-resource-limits libSPIRV-Tools-opt libSPIRV-Tools"
  local stamp; stamp=$(for l in $libs; do [ -f "$lib/$l.a" ] && stat -c '%n %s %Y' "$lib/$l.a"; done | md5sum | cut -c1-16)
  if [ -f "$out/libshaderc_combined.a" ] && [ "$(cat "$out/stamp" 2>/dev/null)" = "$stamp" ]; then
    export SHADERC_LIB_DIR=$out; return 0
  fi
  mkdir -p "$out"
  local script="CREATE $out/libshaderc_combined.a.tmp"
  for l in $libs; do
    [ -f "$lib/$l.a" ] || { echo "setup: $lib/$l.a missing" >&2; return 1; }
    script+=$'\n'"ADDLIB $lib/$l.a"
  done
  script+=$'\nSAVE\nEND'
  printf '%s\n' "$script" | ar -M || return 1
  mv "$out/libshaderc_combined.a.tmp" "$out/libshaderc_combined.a"
  echo "$stamp" > "$out/stamp"
  export SHADERC_LIB_DIR=$out
}

if [ -z "${SHADERC_LIB_DIR:-}" ] && [ -z "$BIDIR_CARGO_FEATURES" ]; then
  if bidir_apt_install libshaderc-dev glslang-dev spirv-tools && bidir_merge_shaderc; then
    :
  else
    echo "setup: fast shaderc path unavailable; building shaderc from source (slow, once)" >&2
    bidir_apt_install cmake git python3 g++ ninja-build || true
    export BIDIR_CARGO_FEATURES="--features shaderc-from-source"
  fi
fi
