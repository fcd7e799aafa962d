#!/usr/bin/env bash
# Installs what is missing, builds, and renders the built-in default scene with
# shadows. Prints the path of the PNG. SHADOWMAPS_STACK=trixie or sid does it
# in that stack's root (scripts/stacks.sh).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
run_in_stack_if_asked "$0" "$@"
install_missing_packages
configure_and_build
with_display "$BUILD_DIR/bin/vtkshadows" render -o "$BUILD_DIR/vtkshadows-default.png"
