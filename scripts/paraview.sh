#!/usr/bin/env bash
# The ParaView half of the tests (scripts/test.sh runs it after the VTK half):
# builds the ShadowMaps plugin (ParaView/) against ParaView's own VTK and runs
# its tests in pvpython and, on three MPI ranks, pvbatch and pvserver. Debian's
# python3-paraview, which pvpython, pvbatch and the plugin's wrapping need,
# conflicts with python3-vtk9 (and so with libvtk9-dev):
# this script swaps them in and, whatever happens, back out, leaving the
# packages the README's main command needs.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

PARAVIEW_BUILD_DIR="${PARAVIEW_BUILD_DIR:-$ROOT/build-paraview}"
# libprotobuf-dev: the headers of the server-manager messages (vtkSIShadowRoleProperty).
PARAVIEW_PACKAGES=(paraview paraview-dev python3-paraview openmpi-bin libprotobuf-dev)
VTK_PACKAGES=(libvtk9-dev python3-vtk9)
PLUGIN="$PARAVIEW_BUILD_DIR/lib/paraview-5.11/plugins/ShadowMaps/ShadowMaps.so"

apt_install() {
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@" ||
    { as_root apt-get update -qq &&
      as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@"; }
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
trap swap_back EXIT

echo "Installing ${PARAVIEW_PACKAGES[*]} (removes ${VTK_PACKAGES[*]} until the end)"
apt_install "${PARAVIEW_PACKAGES[@]}" >/dev/null
cmake -S "$ROOT/ParaView" -B "$PARAVIEW_BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build "$PARAVIEW_BUILD_DIR"
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
