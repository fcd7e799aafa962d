"""Caster draws into the maps and frame times with and without ShadowReachCulling,
on a ground, a sphere and N boxes (N the argument), 960 x 540, for the uniform,
warped (LiSPSM) and cascaded passes under a sun, a spot and a point light;
moving frames orbit 0.3 degrees a frame, medians of 3 interleaved rounds of 6
frames. Draws are the pass's NumberOfCasterDraws of the last moving frame
that rendered layers; layers are the mean NumberOfRenderedLayers of the moving
frames (culling must not make them re-render more often).

  PYTHONPATH=build/lib/python3/dist-packages \
    xvfb-run -a /usr/bin/python3 Measurement/reach_culling.py 200
"""
import statistics, sys
import vtkshadowmaps
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkCamera, vtkLight
from timing_scene import add, add_ground_and_boxes, add_sun, timed_render, window


def set_light(renderer, kind):
    renderer.RemoveAllLights()
    if kind == "sun":
        add_sun(renderer)
        return
    light = vtkLight(); light.SetPositional(True); light.SetPosition(5, -10, 25); light.SetFocalPoint(0, 0, 0)
    light.SetConeAngle(50 if kind == "spot" else 180)
    renderer.AddLight(light)


r, w = window(960, 540)
add_ground_and_boxes(r, 60, int(sys.argv[1]))
s = vtkSphereSource(); s.SetCenter(0, 0, 3); s.SetRadius(2); s.SetThetaResolution(64); s.SetPhiResolution(64)
add(r, s)
cam = r.GetActiveCamera(); cam.SetPosition(0, -50, 8); cam.SetFocalPoint(0, 0, 0); cam.SetViewUp(0, 0, 1)
init = vtkCamera(); init.DeepCopy(cam)


def make(name, culling):
    p = {"uniform": vtkshadowmaps.vtkDepthShadowMapPass, "lispsm": vtkshadowmaps.vtkWarpedShadowMapPass,
         "cascaded": vtkshadowmaps.vtkCascadedShadowMapPass}[name]()
    if name == "lispsm":
        p.SetWarpModeToLiSPSM()
    p.SetShadowReachCulling(culling)
    return p


print("| light | pass | draws, culled | draws, not culled | layers per moving frame, culled | not culled "
      "| moving ms, culled | not culled |")
print("|---|---|---:|---:|---:|---:|---:|---:|")
for light in ("sun", "spot", "point"):
    set_light(r, light)
    for name in ("uniform", "lispsm", "cascaded"):
        passes = {c: make(name, c) for c in (True, False)}
        mv = {c: [] for c in passes}; draws = {}; layers = {c: [] for c in passes}
        for rnd in range(3):
            for c, q in passes.items():
                r.SetPass(q); cam.DeepCopy(init); r.ResetCameraClippingRange(); w.Render(); w.Render()
                for f in range(6):
                    cam.Azimuth(0.3); r.ResetCameraClippingRange(); mv[c].append(timed_render(w))
                    layers[c].append(q.GetNumberOfRenderedLayers())
                draws[c] = q.GetNumberOfCasterDraws()
        print(f"| {light} | {name} | {draws[True]} | {draws[False]} | "
              f"{statistics.mean(layers[True]):.2f} | {statistics.mean(layers[False]):.2f} | "
              f"{1000*statistics.median(mv[True]):.1f} | {1000*statistics.median(mv[False]):.1f} |")
