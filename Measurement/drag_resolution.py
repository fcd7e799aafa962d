"""What drawing dual-depth maps costs while the camera moves, and what drawing them
coarser in a drag (InteractiveResolutionScale) saves: a ground, 20 boxes and a
sphere of 100 x 100 points under a spot light, 960 x 540, off screen.

1. Peeled dual-depth maps drawn anew (the pass Modified()) against steady frames, at
   2048^2 and 1024^2, with the props lit and unlit (llvmpipe runs the mappers'
   lighting code under the casters' branch; a GPU skips it).
2. A still frame, then a drag of 12 interactive frames (desired update rate 15, the
   camera turning 10 degrees a frame), twice, with the automatic pass at
   InteractiveResolutionScale 1 and 0.5: each frame's time, the maps' resolution, the
   layers drawn and the maps' memory.

  PYTHONPATH=build/lib/python3/dist-packages \\
    xvfb-run -a /usr/bin/python3 Measurement/drag_resolution.py
"""
import statistics
import vtkshadowmaps
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkLight
from timing_scene import add, add_ground_and_boxes, timed_render, window


def scene():
    r, w = window(960, 540)
    add_ground_and_boxes(r, 60, 20)
    s = vtkSphereSource(); s.SetCenter(0, 0, 3); s.SetRadius(2)
    s.SetThetaResolution(100); s.SetPhiResolution(100)
    add(r, s)
    spot = vtkLight(); spot.SetPositional(True); spot.SetPosition(10, -10, 25)
    spot.SetFocalPoint(0, 0, 0); spot.SetConeAngle(40); r.AddLight(spot)
    cam = r.GetActiveCamera(); cam.SetPosition(0, -50, 8); cam.SetFocalPoint(0, 0, 0); cam.SetViewUp(0, 0, 1)
    return r, w


def redraw_cost(resolution, lit):
    r, w = scene()
    actors = r.GetActors(); actors.InitTraversal()
    for _ in range(actors.GetNumberOfItems()):
        actors.GetNextActor().GetProperty().SetLighting(lit)
    p = vtkshadowmaps.vtkDualDepthShadowMapPass(); p.SetResolution(resolution)
    p.GetRepresentation().SetLayerMethodToDepthPeeling()
    r.SetPass(p); w.Render(); w.Render()
    steady, redrawn = [], []
    for _ in range(5):
        steady.append(timed_render(w))
        p.Modified()
        redrawn.append(timed_render(w))
    r.SetPass(None); p.ReleaseGraphicsResources(w)
    s, d = statistics.median(steady), statistics.median(redrawn)
    print(f"peeled dual depth {resolution}^2, {'lit' if lit else 'unlit'}: steady {1000 * s:.1f} ms, "
          f"redrawn {1000 * d:.1f} ms (+{1000 * (d - s):.1f})")


def drag(scale):
    r, w = scene()
    p = vtkshadowmaps.vtkAutomaticShadowMapPass(); p.SetInteractiveResolutionScale(scale)
    r.SetPass(p)
    cam = r.GetActiveCamera()
    print(f"InteractiveResolutionScale {scale}:")
    for _ in range(2):
        w.SetDesiredUpdateRate(0.0001)
        t = timed_render(w)
        print(f"  still  {1000 * t:6.1f} ms, maps {p.GetShadowMapResolution()}^2, "
              f"layers drawn {p.GetNumberOfRenderedLayers()}")
        w.SetDesiredUpdateRate(15)
        line = []
        for _ in range(12):
            cam.Azimuth(10)
            t = timed_render(w)
            line.append(f"{1000 * t:.0f}{'*' if p.GetNumberOfRenderedLayers() else ''}")
        print(f"  drag   {' '.join(line)} ms (* drew layers), maps {p.GetShadowMapResolution()}^2, "
              f"{p.GetShadowMapMemory() >> 20} MiB")
    r.SetPass(None); p.ReleaseGraphicsResources(w)


for resolution in (2048, 1024):
    for lit in (True, False):
        redraw_cost(resolution, lit)
for scale in (1.0, 0.5):
    drag(scale)
