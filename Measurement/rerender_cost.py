"""What re-rendering the maps costs VTK's vtkShadowMapPass and this project's passes:
a ground and a sphere of N x N points (argv[2]), 960 x 540, maps of argv[1] texels,
steady frames against frames after a change that re-renders the maps. argv[3] 'light':
the sun's Modified() (VTK's baker re-renders when a light's time changes; this
project's passes compare the light's values and keep their maps); 'pass': the pass's
Modified() (this project's passes re-render; VTK's camera pass has nothing to redo).
Medians of 3 interleaved rounds of 5 frames.

  PYTHONPATH=build/lib/python3/dist-packages \
    xvfb-run -a /usr/bin/python3 Measurement/rerender_cost.py 1024 500 light
"""
import statistics, sys
import vtkshadowmaps
from vtkmodules.vtkFiltersSources import vtkSphereSource
from timing_scene import add, add_ground_and_boxes, add_sun, timed_render, vtk_shadow_map_pass, window

resolution, points, change = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
r, w = window(960, 540)
add_ground_and_boxes(r, 60, 0)
s = vtkSphereSource(); s.SetCenter(0, 0, 3); s.SetRadius(2)
s.SetThetaResolution(points); s.SetPhiResolution(points)
add(r, s)
add_sun(r)
cam = r.GetActiveCamera(); cam.SetPosition(0, -50, 8); cam.SetFocalPoint(0, 0, 0); cam.SetViewUp(0, 0, 1)


def ours(mode):
    p = vtkshadowmaps.vtkWarpedShadowMapPass(); p.SetResolution(resolution)
    getattr(p, "SetWarpModeTo" + mode)()
    return p


passes = {"none": None, "vtk": vtk_shadow_map_pass(resolution), "uniform": ours("Uniform"), "lispsm": ours("LiSPSM")}
changed = {k: [] for k in passes}; steady = {k: [] for k in passes}
for round in range(3):
    for k, q in passes.items():
        r.SetPass(q); w.Render(); w.Render()
        for f in range(5):
            steady[k].append(timed_render(w))
        for f in range(5):
            if q is not None:
                (r.GetLights().GetItemAsObject(0) if change == "light" else q).Modified()
            changed[k].append(timed_render(w))
r.SetPass(None)
for q in passes.values():
    if q is not None:
        q.ReleaseGraphicsResources(w)
for k in passes:
    print(f"{k:8s} steady {1000 * statistics.median(steady[k]):6.1f} ms, after a {change} change "
          f"{1000 * statistics.median(changed[k]):6.1f} ms")
