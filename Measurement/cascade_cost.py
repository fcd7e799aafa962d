"""Steady frames of cascaded maps by cascade count (and with blend, fade and coverage
selection varied) against no shadows and the uniform map, and of the dual-depth map
(second depth, uniform views or four cascades: "dual", "dual-csm4"): a ground and 50 boxes,
960 x 540, 1024^2 maps, medians of 3 interleaved rounds of 6 frames.

  PYTHONPATH=build/lib/python3/dist-packages \
    xvfb-run -a /usr/bin/python3 Measurement/cascade_cost.py

With --cpu, the frames are timed in this process's CPU time over 8 rounds; with
LP_NUM_THREADS=0 llvmpipe then rasterises in this thread, and the ratios vary
less from run to run than wall-clock ones on a shared machine. With
--variants=none,csm4,csm1 (say) only those are timed: to alternate builds of
the module within minutes, run each build's copy of build/lib in turn through
LD_LIBRARY_PATH and PYTHONPATH.
"""
import statistics
import sys
import time
import vtkshadowmaps
from timing_scene import add_ground_and_boxes, add_sun, timed_render, window

cpu = "--cpu" in sys.argv
def cpu_render(w):
    t = time.process_time(); w.Render(); w.WaitForCompletion()
    return time.process_time() - t
frame_time = cpu_render if cpu else timed_render
rounds = 8 if cpu else 3
r, w = window(960, 540)
add_ground_and_boxes(r, 60, 50)
add_sun(r)
cam = r.GetActiveCamera(); cam.SetPosition(0, -50, 8); cam.SetFocalPoint(0, 0, 0); cam.SetViewUp(0, 0, 1)
def csm(n=4, blend=None, fade=None, sel=None):
    q = vtkshadowmaps.vtkCascadedShadowMapPass(); q.SetResolution(1024); q.SetNumberOfCascades(n)
    v = q.GetViews()
    if blend is not None: v.SetBlendFraction(blend)
    if fade is not None: v.SetFadeFraction(fade)
    if sel is not None: v.SetSelection(sel)
    return q
def uni():
    q = vtkshadowmaps.vtkWarpedShadowMapPass(); q.SetResolution(1024); return q
def dual(cascaded=False):
    q = vtkshadowmaps.vtkDualDepthShadowMapPass(); q.SetResolution(1024)
    if cascaded: q.SetViews(vtkshadowmaps.vtkCascadedShadowMapViews())
    return q
variants = {"none": lambda: None, "uniform": uni, "csm4": csm, "csm4-noblend": lambda: csm(4, 0.0),
            "csm4-noblend-nofade": lambda: csm(4, 0.0, 0.0), "csm1": lambda: csm(1), "csm2": lambda: csm(2),
            "csm4-coverage": lambda: csm(4, sel=1), "dual": dual, "dual-csm4": lambda: dual(True)}
chosen = next((a.split("=", 1)[1].split(",") for a in sys.argv if a.startswith("--variants=")), None)
if chosen is not None:
    unknown = [k for k in chosen if k not in variants]
    if unknown:
        sys.exit(f"unknown variants {unknown}; known: {','.join(variants)}")
    variants = {k: variants[k] for k in chosen}
passes = {k: f() for k, f in variants.items()}
st = {k: [] for k in passes}
for rnd in range(rounds):
    for k, q in passes.items():
        r.SetPass(q); r.ResetCameraClippingRange(); w.Render(); w.Render()
        for f in range(6):
            st[k].append(frame_time(w))
base = statistics.median(st["none"]) if "none" in st else float("nan")
for k in passes:
    print(f"{k:22s} steady {1000*statistics.median(st[k]):6.1f} ms  x none {statistics.median(st[k])/base:.2f}")
