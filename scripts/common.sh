# Shared by scripts/run.sh and scripts/test.sh: install what is missing, configure, build.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# SHADOWMAPS_STACK: host (the machine's own Debian 12), trixie or sid
# (scripts/stacks.sh); scripts/test.sh without it tests all three.
STACK="${SHADOWMAPS_STACK:-host}"
if [ "$STACK" = host ]; then
  BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
else
  BUILD_DIR="${BUILD_DIR:-$ROOT/build-$STACK}"
fi
source "$ROOT/scripts/stacks.sh"

PACKAGES=(
  cmake ninja-build g++ pkg-config git
  libvtk9-dev python3-vtk9 python3-dev
  libglm-dev
  libopenimageio-dev openimageio-tools python3-imath
  libgtest-dev
  libembree-dev assimp-testmodels
  xvfb xauth libgl1-mesa-dri
)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

# Installs what is missing of the given packages (default: PACKAGES).
install_missing_packages() {
  local wanted=("$@")
  [ "${#wanted[@]}" -gt 0 ] || wanted=("${PACKAGES[@]}")
  local missing=()
  for package in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    echo "Installing: ${missing[*]}"
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
}

configure_and_build() {
  # Debian's VTK Python bindings belong to /usr/bin/python3; another python3 on
  # PATH may lack them. VTK_DIR=... builds against a VTK of one's own.
  cmake -S "$ROOT" -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 ${VTK_DIR:+"-DVTK_DIR=$VTK_DIR"} &&
    cmake --build "$BUILD_DIR"
}

# Re-runs the calling script inside the root of SHADOWMAPS_STACK (trixie or
# sid), made first if missing or stale; returns on the host stack.
#   run_in_stack_if_asked "$0" "$@"
run_in_stack_if_asked() {
  [ "$STACK" = host ] || [ "${SHADOWMAPS_IN_STACK:-0}" = 1 ] && return 0
  local status=0
  ensure_stack "$STACK" || status=$?
  [ "$status" -ne "$STACK_UNAVAILABLE" ] || stack_unavailable "$STACK"
  [ "$status" -eq 0 ] || exit "$status"
  # The repository is at its own path in the root.
  in_stack "$STACK" bash "$ROOT/scripts/$(basename "$1")" "${@:2}"
  exit $?
}

# Debian's VTK is X-only. -noreset: Xvfb otherwise resets whenever its last
# client disconnects, and a test connecting during the reset aborts.
with_display() {
  xvfb-run -a -s "-noreset -screen 0 1280x1024x24" "$@"
}
