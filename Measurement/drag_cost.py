"""Frames of a drag (the window's DesiredUpdateRate at 15, as VTK's interactor
styles set it) orbiting the camera by argv[1] degrees a frame: no shadows, VTK's
vtkShadowMapPass and the LiSPSM and TSM warped passes at 2048^2 with
InteractiveTexelRatio 1 (a fresh fit every frame), 1.5 (the default), 2 and 3.
A ground, a sphere and 50 boxes, 960 x 540; mean and median of 2 interleaved rounds
of 24 dragged frames, the map layers rendered per frame, and the largest ratio of
a kept view's texel to the fresh fit's allowed (the cost in sharpness).

  PYTHONPATH=build/lib/python3/dist-packages:Measurement \
    xvfb-run -a /usr/bin/python3 Measurement/drag_cost.py 0.3
"""
import statistics, sys
import vtkshadowmaps
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkCamera
from timing_scene import add, add_ground_and_boxes, add_sun, timed_render, vtk_shadow_map_pass, window

degrees = float(sys.argv[1])
r, w = window(960, 540)
add_ground_and_boxes(r, 60, 50)
s = vtkSphereSource(); s.SetCenter(0, 0, 3); s.SetRadius(2); s.SetThetaResolution(64); s.SetPhiResolution(64)
add(r, s)
add_sun(r)
cam = r.GetActiveCamera(); cam.SetPosition(0, -50, 8); cam.SetFocalPoint(0, 0, 0); cam.SetViewUp(0, 0, 1)
start = vtkCamera(); start.DeepCopy(cam)


def warped(mode, ratio):
    p = vtkshadowmaps.vtkWarpedShadowMapPass(); p.SetResolution(2048)
    getattr(p, "SetWarpModeTo" + mode)()
    p.SetInteractiveTexelRatio(ratio)
    return p


passes = {"none": None, "vtk": vtk_shadow_map_pass(2048)}
for mode in ("LiSPSM", "TSM"):
    for ratio in (1.0, 1.5, 2.0, 3.0):
        passes[f"{mode.lower()} {ratio:g}"] = warped(mode, ratio)
times = {k: [] for k in passes}; layers = {k: [] for k in passes}
for round_ in range(2):
    for k, q in passes.items():
        r.SetPass(q); cam.DeepCopy(start); r.ResetCameraClippingRange()
        w.SetDesiredUpdateRate(0.0001); w.Render(); w.Render()
        w.SetDesiredUpdateRate(15.0)
        for f in range(24):
            cam.Azimuth(degrees); r.ResetCameraClippingRange()
            times[k].append(timed_render(w))
            if q is not None and hasattr(q, "GetNumberOfRenderedLayers"):
                layers[k].append(q.GetNumberOfRenderedLayers())
        w.SetDesiredUpdateRate(0.0001)
r.SetPass(None)
for q in passes.values():
    if q is not None:
        q.ReleaseGraphicsResources(w)
vtk_mean = statistics.mean(times["vtk"])
print(f"orbit {degrees:g} degrees a frame; ms, and mean / VTK's mean")
for k in passes:
    per_frame = f"{statistics.mean(layers[k]):.2f}" if layers[k] else "-"
    print(f"{k:11s} mean {1000 * statistics.mean(times[k]):6.1f} median {1000 * statistics.median(times[k]):6.1f} "
          f"mean/vtk {statistics.mean(times[k]) / vtk_mean:5.2f} layers/frame {per_frame}")
