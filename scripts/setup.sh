#!/usr/bin/env bash
# SkillCoach setup: installs the Debian 12 packages it needs (apt-get, only what is missing), builds
# Release into build/, then either starts the trainer (`run`) or runs the whole test suite (`test`).
#   scripts/setup.sh run     # install + build + start the trainer (headless demo when there is no display)
#   scripts/setup.sh test    # install + build + ctest
#   scripts/setup.sh install PKG...   # only install those Debian packages when missing
set -euo pipefail

mode="${1:-run}"
shift || true
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SKILLCOACH_BUILD_DIR:-$root/build}"

packages=(
  cmake g++ make ninja-build pkg-config
  libsdl2-dev libimgui-dev libstb-dev
  libgl-dev libegl-dev libosmesa6-dev libgl1-mesa-dri
  libeigen3-dev libbox2d-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libtorch-dev libopenblas0-pthread
  libsqlite3-dev nlohmann-json3-dev libcli11-dev
  libpq-dev postgresql  # the shared store's client; the server for its tests (docs/database.md)
  fonts-dejavu-core xvfb xauth
)

# Installs those of the given Debian packages that are missing (root or sudo needed only then).
install_missing() {
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "==> installing ${#missing[@]} Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# `install PKG...`: only that (used by .ci/run for the tools of its optional steps, e.g. clang).
if [ "$mode" = install ]; then
  install_missing "$@"
  exit 0
fi
install_missing "${packages[@]}"

# Torch is ~5x slower on the reference BLAS: make OpenBLAS the active libblas if both are installed.
if [ -e /usr/lib/x86_64-linux-gnu/openblas-pthread/libblas.so.3 ] && [ "$(id -u)" -eq 0 ]; then
  update-alternatives --set libblas.so.3-x86_64-linux-gnu \
    /usr/lib/x86_64-linux-gnu/openblas-pthread/libblas.so.3 >/dev/null 2>&1 || true
fi

jobs="$(nproc)"
echo "==> configuring and building (Release, $jobs jobs) in $build"
# Ninja schedules the ~400 build steps with less overhead than recursive Makefiles; a build folder that
# was configured earlier keeps its generator (CMake refuses to switch it).
generator=(-G Ninja)
[ -f "$build/CMakeCache.txt" ] && generator=()
cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$jobs"

export OPENBLAS_NUM_THREADS=1
case "$mode" in
  run)
    if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
      exec "$build/skillcoach" "$@"
    fi
    echo "==> no display found (DISPLAY and WAYLAND_DISPLAY are unset): running the headless demo instead"
    exec "$build/skillcoach" demo --out "$build/skillcoach-demo.png"
    ;;
  test)
    export GALLIUM_DRIVER=llvmpipe
    cd "$build"
    exec ctest --output-on-failure -j "$jobs" "$@"
    ;;
  *)
    echo "usage: scripts/setup.sh run|test" >&2
    exit 2
    ;;
esac
