#!/bin/sh
# A compiler launcher (CMAKE_CXX_COMPILER_LAUNCHER) for compiling against a VTK
# that was configured but not built (Testing/VTK97/CompileModule.cmake): the
# compile only checks the source (-fsyntax-only) and leaves an empty object, so
# that the build tool records it as done.
#   syntax_only.sh <compiler> <arguments...>
"$@" -fsyntax-only || exit $?
output=
previous=
for argument in "$@"; do
  [ "$previous" = -o ] && output="$argument"
  previous="$argument"
done
[ -z "$output" ] || : > "$output"
