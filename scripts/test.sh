#!/usr/bin/env bash
# Installs what is missing, builds and runs every test on each stack the module
# supports (scripts/stacks.sh), then prints the matrix: stack, VTK, ParaView,
# PyVista, tests passed and failed. Any failure of the project's on any stack
# fails the run; a stack whose root Debian's archive cannot serve is reported
# loudly as unavailable.
#   SHADOWMAPS_STACK=host|trixie|sid scripts/test.sh   one stack only
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
set +e
if [ -n "${SHADOWMAPS_STACK:-}" ]; then
  stacks=("$SHADOWMAPS_STACK")
else
  stacks=(host trixie sid)
fi
mkdir -p "$MATRIX_DIR"
rm -f "$MATRIX_DIR"/*.row
status=0
for stack in "${stacks[@]}"; do
  echo "=== Stack $stack"
  start=$(date +%s)
  if [ "$stack" = host ]; then
    SHADOWMAPS_STACK=host BUILD_DIR="$BUILD_DIR" bash "$ROOT/scripts/test_stack.sh" || status=1
  else
    ensure_stack "$stack"
    case $? in
      0) in_stack "$stack" bash scripts/test_stack.sh || status=1 ;;
      "$STACK_UNAVAILABLE")
        stack_unavailable "$stack"
        printf '%s\t-\t-\t-\t0\t0\t%s\n' "$stack" \
          "UNAVAILABLE: Debian's archive could not serve the root" > "$MATRIX_DIR/$stack.row" ;;
      *) status=1 ;; # no row: the matrix counts the stack as failed
    esac
  fi
  echo "=== Stack $stack took $(( $(date +%s) - start )) s"
done
print_matrix "${stacks[@]}" || status=1
exit "$status"
