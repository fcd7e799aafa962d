#!/usr/bin/env bash
# The ParaView half of the tests (scripts/test.sh runs it after the VTK half):
# builds the ShadowMaps plugin (ParaView/) against ParaView's own VTK and runs
# its tests in pvpython and, on three MPI ranks, pvbatch and pvserver. Debian's
# python3-paraview, which pvpython, pvbatch and the plugin's wrapping need,
# conflicts with python3-vtk9 (and so with libvtk9-dev) in Debian 12 and 13:
# there this script swaps them in and, whatever happens, back out, leaving the
# packages the README's main command needs. In sid (ParaView 6.1 on the
# system's VTK 9.6) the two coexist and nothing is swapped.
#
#   bash scripts/paraview.sh --run COMMAND...
# installs and builds as for the tests, then runs COMMAND instead of them (under a
# display; @PLUGIN@ in its words becomes the plugin's path), for measurements.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
RUN=()
if [ "${1:-}" = --run ]; then
  shift
  RUN=("$@")
  [ "${#RUN[@]}" -gt 0 ] || { echo "usage: $0 --run COMMAND..." >&2; exit 2; }
fi

if [ "$STACK" = host ]; then
  PARAVIEW_BUILD_DIR="${PARAVIEW_BUILD_DIR:-$ROOT/build-paraview}"
else
  PARAVIEW_BUILD_DIR="${PARAVIEW_BUILD_DIR:-$ROOT/build-paraview-$STACK}"
fi
# libprotobuf-dev: the headers of the server-manager messages (vtkSIShadowRoleProperty).
PARAVIEW_PACKAGES=(paraview paraview-dev python3-paraview openmpi-bin libprotobuf-dev)

apt_install() {
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@" ||
    { as_root apt-get update -qq &&
      as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@"; }
}

# What installing ParaView's packages would remove (python3-vtk9, libvtk9-dev
# and what depends on them, python3-pyvista among them): nothing in sid.
packages_paraview_removes() {
  local plan
  plan="$(apt-get -s install "${PARAVIEW_PACKAGES[@]}" 2>/dev/null)" ||
    { as_root apt-get update -qq && plan="$(apt-get -s install "${PARAVIEW_PACKAGES[@]}")"; } ||
    { echo "apt cannot plan the install of ${PARAVIEW_PACKAGES[*]}" >&2; exit 1; }
  sed -n 's/^Remv \([^ ]*\).*/\1/p' <<< "$plan"
}

# Debian's paraview-dev 5.13 (trixie) and 6.1 (sid) export ParaView's and its
# VTK's Python modules as <name>.so while python3-paraview installs them as
# <name>.cpython-3XY-<arch>.so, and CMake refuses to import targets whose
# files are missing: find_package(ParaView) fails in any project. Link each
# missing name to the installed file (nothing is linked where they agree, as
# in Debian 12).
link_paraview_python_modules() {
  local configs file candidate installed linked=0
  mapfile -t configs < <(find /usr/lib/*/cmake/paraview-* -name '*-targets-*.cmake' 2>/dev/null)
  [ "${#configs[@]}" -gt 0 ] || return 0
  for file in $(sed -n 's|.*"${_IMPORT_PREFIX}\(/lib/python3/dist-packages/[^"]*\.so\)".*|/usr\1|p' \
    "${configs[@]}" | sort -u); do
    [ -e "$file" ] && continue
    installed=""
    for candidate in "${file%.so}".cpython-*.so; do
      [ -e "$candidate" ] && { installed="$candidate"; break; }
    done
    [ -n "$installed" ] || continue
    as_root ln -s "$(basename "$installed")" "$file"
    linked=$((linked + 1))
  done
  [ "$linked" -eq 0 ] ||
    echo "Linked $linked of ParaView's Python modules to the names its CMake package exports"
}

swap_back() {
  echo "Restoring ${VTK_PACKAGES[*]} (removes python3-paraview)"
  apt_install "${VTK_PACKAGES[@]}" >/dev/null
}
if [ "${SHADOWMAPS_SKIP_PARAVIEW:-0}" = 1 ]; then
  echo "SKIPPED: the ParaView plugin's build and tests (SHADOWMAPS_SKIP_PARAVIEW=1)" >&2
  exit 0
fi
install_missing_packages
removed="$(packages_paraview_removes)" || exit 1
mapfile -t VTK_PACKAGES < <(sed '/^$/d' <<< "$removed")
if [ "${#VTK_PACKAGES[@]}" -gt 0 ]; then
  trap swap_back EXIT
  echo "Installing ${PARAVIEW_PACKAGES[*]} (removes ${VTK_PACKAGES[*]} until the end)"
fi
apt_install "${PARAVIEW_PACKAGES[@]}" >/dev/null
link_paraview_python_modules
cmake -S "$ROOT/ParaView" -B "$PARAVIEW_BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build "$PARAVIEW_BUILD_DIR"
# lib/paraview-<major.minor>/plugins/ShadowMaps/ShadowMaps.so
PLUGIN="$(find "$PARAVIEW_BUILD_DIR/lib" -path '*/plugins/ShadowMaps/ShadowMaps.so' | head -1)"
[ -n "$PLUGIN" ] || { echo "The build made no ShadowMaps.so under $PARAVIEW_BUILD_DIR/lib"; exit 1; }
if [ "${#RUN[@]}" -gt 0 ]; then
  with_display "${RUN[@]//@PLUGIN@/$PLUGIN}"
  exit $?
fi
OUTPUT="$PARAVIEW_BUILD_DIR/Testing/Output"
with_display pvpython "$ROOT/Testing/ParaView/test_shadow_view.py" "$PLUGIN" "$OUTPUT"
# In parallel: the same scene on one rank, then split over three (oversubscribed).
with_display pvbatch "$ROOT/Testing/ParaView/test_parallel.py" "$PLUGIN" "$OUTPUT" serial
# A rank that missed a collective would hang the others: time out instead.
with_display timeout 600 mpiexec --allow-run-as-root --oversubscribe -np 3 \
  pvbatch "$ROOT/Testing/ParaView/test_parallel.py" "$PLUGIN" "$OUTPUT" parallel
# Client-server: three pvserver ranks render and composite for a pvpython client.
with_display bash "$ROOT/scripts/paraview_pvserver.sh" "$PLUGIN" "$OUTPUT"
if [ "${SHADOWMAPS_GUI_SCREENSHOT:-0}" = 1 ]; then
  bash "$ROOT/scripts/paraview_gui_screenshot.sh"
fi
