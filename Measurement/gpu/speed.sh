#!/bin/bash
# On the GPU machine, from the repository root, with .gpu/bundle.tar.xz
# carried (make_bundle.sh): `vtkshadows speed ARGS` ROUNDS times, each run's
# log and CSVs under $OUT (the device tool brings at most 8 files back).
#
#   bash Measurement/gpu/speed.sh ROUNDS ARGS...
set -o pipefail
rounds=$1
shift
[ -n "${OUT:-}" ] || { echo "speed.sh: OUT (the device tool's output folder) is not set" >&2; exit 1; }
# Three files come back per round (the log, speed.csv, frames.csv), and the
# device tool brings back eight.
[ "$rounds" -ge 1 ] && [ "$rounds" -le 2 ] || { echo "speed.sh: ROUNDS must be 1 or 2" >&2; exit 1; }
mkdir -p /tmp/b && xz -dc .gpu/bundle.tar.xz | tar -C /tmp/b -xf - || exit 1
for i in $(seq "$rounds"); do
  /tmp/b/run_on_gpu.sh /tmp/b/bin/vtkshadows speed "$@" --out "$OUT/r$i" > "$OUT/r$i.log" 2>&1
  echo "round $i: rc $?, $(grep -m1 'GL renderer' "$OUT/r$i.log")"
  rm -f "$OUT/r$i/speed.md"
done
