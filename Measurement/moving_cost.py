"""Moving (orbit 0.3 degrees a frame) and steady frames of no shadows and the warped
and cascaded passes on a ground, a sphere and N boxes (N the argument), 960 x 540,
medians of 3 interleaved rounds of 6 frames. Works with any build of the module
(PYTHONPATH), e.g. to compare commits.

  PYTHONPATH=build/lib/python3/dist-packages \
    xvfb-run -a /usr/bin/python3 Measurement/moving_cost.py 50
"""
import statistics, sys
import vtkshadowmaps
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkCamera
from timing_scene import add, add_ground_and_boxes, add_sun, timed_render, window
r, w = window(960, 540)
add_ground_and_boxes(r, 60, int(sys.argv[1]))
s = vtkSphereSource(); s.SetCenter(0, 0, 3); s.SetRadius(2); s.SetThetaResolution(64); s.SetPhiResolution(64)
add(r, s)
add_sun(r)
cam = r.GetActiveCamera(); cam.SetPosition(0, -50, 8); cam.SetFocalPoint(0, 0, 0); cam.SetViewUp(0, 0, 1)
init = vtkCamera(); init.DeepCopy(cam)
makers = {"none": lambda: None, "warped": vtkshadowmaps.vtkWarpedShadowMapPass, "cascaded": vtkshadowmaps.vtkCascadedShadowMapPass}
passes = {k: f() for k, f in makers.items()}
mv = {k: [] for k in passes}; st = {k: [] for k in passes}
for rnd in range(3):
    for k, q in passes.items():
        r.SetPass(q); cam.DeepCopy(init); r.ResetCameraClippingRange(); w.Render(); w.Render()
        for f in range(6):
            st[k].append(timed_render(w))
        for f in range(6):
            cam.Azimuth(0.3); r.ResetCameraClippingRange(); mv[k].append(timed_render(w))
for k in passes:
    print(f"{sys.argv[1]:>3s} boxes {k:9s} moving {1000*statistics.median(mv[k]):6.1f} steady {1000*statistics.median(st[k]):6.1f}")
