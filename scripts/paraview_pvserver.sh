#!/usr/bin/env bash
# Client-server test of the ShadowMaps plugin (run by scripts/paraview.sh under
# one X display): three pvserver ranks, each holding a piece of the scene,
# render and composite; a pvpython client connects and runs
# Testing/ParaView/test_parallel.py in its pvserver mode.
#   scripts/paraview_pvserver.sh PLUGIN OUTDIR
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PLUGIN="$1"
OUTPUT="$2"
# A port of this run's own, so that two runs neither collide nor stop each other's server.
PORT="${SHADOWMAPS_PVSERVER_PORT:-$((20000 + $$ % 20000))}"
mkdir -p "$OUTPUT"
LOG="$OUTPUT/pvserver.log"
: > "$LOG"

timeout -k 10 900 mpiexec --allow-run-as-root --oversubscribe -np 3 \
  pvserver --server-port="$PORT" > "$LOG" 2>&1 &
SERVER=$!
stop_server() {
  kill "$SERVER" 2>/dev/null || true
  pkill -f "pvserver --server-port=$PORT" 2>/dev/null || true
  wait "$SERVER" 2>/dev/null || true
}
trap stop_server EXIT

for _ in $(seq 1 60); do
  grep -q "Accepting connection" "$LOG" && break
  kill -0 "$SERVER" 2>/dev/null || { echo "pvserver exited:"; cat "$LOG"; exit 1; }
  sleep 1
done
grep -q "Accepting connection" "$LOG" || { echo "pvserver did not start:"; cat "$LOG"; exit 1; }
status=0
timeout -k 10 600 pvpython "$ROOT/Testing/ParaView/test_parallel.py" "$PLUGIN" "$OUTPUT" pvserver \
  "$PORT" || status=$?
if [ "$status" -ne 0 ]; then
  echo "The client failed ($status); the server said:"
  cat "$LOG"
fi
exit "$status"
