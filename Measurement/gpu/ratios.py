"""Steady and moving frames over VTK's pass's, per scene, map size and
technique, over several `vtkshadows speed` runs (their speed.csv files): the
median and the range of the runs, for machines whose frame times vary from run
to run (the GPU machine of docs/notes/many-actors.md, "On a GPU").

  /usr/bin/python3 Measurement/gpu/ratios.py RUN1/speed.csv RUN2/speed.csv ...
"""
import collections
import csv
import statistics
import sys

ratios = collections.defaultdict(lambda: ([], []))
for path in sys.argv[1:]:
    rows = list(csv.DictReader(open(path)))
    vtk = {(r["scene"], r["setup"], r["resolution"]): r for r in rows if r["technique"] == "vtk"}
    for r in rows:
        reference = vtk.get((r["scene"], r["setup"], r["resolution"]))
        if reference is None:
            continue
        steady, moving = ratios[(r["scene"], r["setup"], r["resolution"], r["technique"])]
        steady.append(float(r["steady_s"]) / float(reference["steady_s"]))
        moving.append(float(r["moving_s"]) / float(reference["moving_s"]))


def summary(values):
    return f"{statistics.median(values):.2f} ({min(values):.2f}–{max(values):.2f})"


print("| scene | light | map | technique | runs | steady / VTK's pass | moving / VTK's pass |")
print("|---|---|---:|---|---:|---:|---:|")
for (scene, setup, resolution, technique), (steady, moving) in ratios.items():
    print(f"| {scene} | {setup} | {resolution}² | {technique} | {len(steady)} | {summary(steady)} "
          f"| {summary(moving)} |")
