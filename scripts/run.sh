#!/usr/bin/env bash
# Installs what is missing, builds, and renders the built-in default scene with
# shadows. Prints the path of the PNG.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
install_missing_packages
configure_and_build
with_display "$BUILD_DIR/bin/vtkshadows" render -o "$BUILD_DIR/vtkshadows-default.png"
