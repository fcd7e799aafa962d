#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (unit, image, Python, CLI),
# then the ParaView plugin's (scripts/paraview.sh).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
install_missing_packages
configure_and_build
(cd "$BUILD_DIR" && with_display ctest --output-on-failure --timeout 600)
bash "$ROOT/scripts/paraview.sh"
