#!/usr/bin/env bash
# Takes docs/images/paraview-gui.png, ParaView's GUI with a Render View (Shadows)
# (ParaView/gui_scene.py), under its own Xvfb. Needs the plugin built
# (scripts/paraview.sh) and python3-paraview installed, which removes
# python3-vtk9: run it between the two, as scripts/paraview.sh does with
# SHADOWMAPS_GUI_SCREENSHOT=1.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
install_missing_packages imagemagick # import and convert
PARAVIEW_BUILD_DIR="${PARAVIEW_BUILD_DIR:-$ROOT/build-paraview}"
export SHADOWMAPS_PLUGIN="$PARAVIEW_BUILD_DIR/lib/paraview-5.11/plugins/ShadowMaps/ShadowMaps.so"
DISPLAY_NUMBER=:97
Xvfb "$DISPLAY_NUMBER" -screen 0 1280x800x24 -noreset &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null || true' EXIT
sleep 2
DISPLAY="$DISPLAY_NUMBER" paraview --dr --script="$ROOT/ParaView/gui_scene.py" &
paraview=$!
sleep "${SHADOWMAPS_GUI_WAIT:-40}"
# The window, without the bare screen around it.
DISPLAY="$DISPLAY_NUMBER" import -window root png:- | convert - -trim +repage "$ROOT/docs/images/paraview-gui.png"
kill "$paraview" 2>/dev/null || true
echo "$ROOT/docs/images/paraview-gui.png"
