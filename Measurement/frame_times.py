"""Frame times of a 51-actor scene (a ground and 50 boxes) with a sun and 4 point
lights, 480 x 270, in one process: no shadows, VTK's vtkShadowMapPass and this
module's warped and cascaded passes, moving (orbit 0.3 degrees a frame) and
steady; medians over 3 interleaved rounds of 8 frames. For this module's passes
it also prints the shader sources built and the map layers rendered per moving frame.

  PYTHONPATH=build/lib/python3/dist-packages \
    xvfb-run -a /usr/bin/python3 Measurement/frame_times.py
"""
import statistics, time
from vtkmodules.vtkRenderingCore import vtkLight
import vtkshadowmaps
from timing_scene import add_ground_and_boxes, add_sun, vtk_shadow_map_pass, window
r, w = window(480, 270)
add_ground_and_boxes(r, 20, 50)
add_sun(r)
for x, y in [(-10, -10), (10, -10), (-10, 10), (10, 10)]:
    l = vtkLight(); l.SetPositional(True); l.SetConeAngle(90); l.SetPosition(x, y, 6); l.SetFocalPoint(x, y, 0)
    l.SetIntensity(0.3); r.AddLight(l)
cam = r.GetActiveCamera(); cam.SetPosition(0, -40, 20); cam.SetFocalPoint(0, 0, 0); cam.SetViewUp(0, 0, 1)
makers = {"none": lambda: None, "vtk": vtk_shadow_map_pass, "warped": vtkshadowmaps.vtkWarpedShadowMapPass,
          "cascaded": vtkshadowmaps.vtkCascadedShadowMapPass}
passes = {k: f() for k, f in makers.items()}
times = {k: ([], []) for k in makers}
for round_ in range(3):
    for k, pss in passes.items():
        r.SetPass(pss); w.SetMultiSamples(0)
        r.ResetCameraClippingRange(); w.Render(); w.Render()
        for f in range(8):
            cam.Azimuth(0.3); r.ResetCameraClippingRange(); t = time.perf_counter(); w.Render(); times[k][0].append(time.perf_counter() - t)
        for f in range(8):
            t = time.perf_counter(); w.Render(); times[k][1].append(time.perf_counter() - t)
builds = {}
for k in ("warped", "cascaded"):
    pss = passes[k]
    if hasattr(pss, "GetNumberOfShaderBuilds"):
        # Props the camera culled since the pass switch build theirs when first cast.
        r.SetPass(pss); w.Render(); cam.Azimuth(0.3); r.ResetCameraClippingRange(); w.Render()
        before = pss.GetNumberOfShaderBuilds()
        cam.Azimuth(0.3); r.ResetCameraClippingRange(); w.Render()
        builds[k] = (pss.GetNumberOfShaderBuilds() - before, pss.GetNumberOfRenderedLayers(),
                     pss.GetNumberOfShadowMapLayers())
for k, (moving, steady) in times.items():
    line = f"{k:9s} moving {1000*statistics.median(moving):7.1f} ms  steady {1000*statistics.median(steady):7.1f} ms"
    if k in builds:
        line += f"  per moving frame: shader sources {builds[k][0]}, layers rendered {builds[k][1]} of {builds[k][2]}"
    print(line)
for pss in passes.values():
    if pss is not None:
        pss.ReleaseGraphicsResources(w)
