#!/bin/bash
# On the GPU machine, from the repository root, with .gpu/bundle.tar.xz
# (make_bundle.sh, the "after" build) and .gpu/before/ (the module library of
# the build to compare with, copied there from its build's lib/) carried:
# `vtkshadows speed ARGS` with each build's module in turn, ROUNDS times
# alternating (before, after, before, ...). Everything
# comes back as $OUT/ab.tar.gz (the device tool brings back eight files):
# before1/, after1/, ... each with its log, speed.csv and frames.csv.
#
#   bash Measurement/gpu/ab.sh ROUNDS ARGS...
set -o pipefail
rounds=$1
shift
[ -n "${OUT:-}" ] || { echo "ab.sh: OUT (the device tool's output folder) is not set" >&2; exit 1; }
[ "$rounds" -ge 1 ] && [ "$rounds" -le 8 ] || { echo "ab.sh: ROUNDS must be 1 to 8" >&2; exit 1; }
[ -d .gpu/before ] || { echo "ab.sh: .gpu/before/ (the before build's module) is missing" >&2; exit 1; }
mkdir -p /tmp/b && xz -dc .gpu/bundle.tar.xz | tar -C /tmp/b -xf - || exit 1
mkdir -p /tmp/after && for library in .gpu/before/*; do
  cp "/tmp/b/lib/$(basename "$library")" /tmp/after/ || exit 1
done
results=$(mktemp -d)
for i in $(seq "$rounds"); do
  for build in before after; do
    source=.gpu/before
    [ "$build" = after ] && source=/tmp/after
    cp "$source"/* /tmp/b/lib/
    /tmp/b/run_on_gpu.sh /tmp/b/bin/vtkshadows speed "$@" --out "$results/$build$i" \
      > "$results/$build$i.log" 2>&1
    echo "$build $i: rc $?, $(grep -m1 'GL renderer' "$results/$build$i.log")"
    rm -f "$results/$build$i/speed.md"
  done
done
tar -C "$results" -czf "$OUT/ab.tar.gz" .
