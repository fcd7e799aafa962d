"""Samples of the python3 thread (or of the thread named by a third argument,
vtkshadows for the program's) under a function in a perf.data recorded with
--call-graph dwarf, and under which of its callees they fell:

  /usr/bin/python3 Measurement/perf_inclusive.py uniform.data vtkOpenGLPolyDataMapper::UpdateShaders
  /usr/bin/python3 Measurement/perf_inclusive.py speed.data shadowmaps::MapUpdates::Plan vtkshadows
"""
import collections
import subprocess
import sys

data, function = sys.argv[1], sys.argv[2]
thread = sys.argv[3] if len(sys.argv) > 3 else "python3"
script = subprocess.run(["perf", "script", "-i", data, "--comm", thread, "-F", "ip,sym"],
                        capture_output=True, text=True, check=True).stdout
callees = collections.Counter()
total = under = 0
for sample in script.split("\n\n"):
    frames = [line.strip().split(" ", 1)[-1] for line in sample.strip().splitlines() if line.strip()]
    if not frames:
        continue
    total += 1
    for depth, frame in enumerate(frames):  # the leaf first
        if frame.startswith(function):
            under += 1
            callees[frames[depth - 1][:80] if depth else "(itself)"] += 1
            break
print(f"{under} of {total} samples under {function}")
for callee, count in callees.most_common(12):
    print(f"  {count:5d}  {callee}")
