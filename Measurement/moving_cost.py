"""Moving (orbit 0.3 degrees a frame) and steady frames of no shadows and the warped
and cascaded passes on a ground, a sphere and N boxes (N the argument), 960 x 540,
medians of 3 interleaved rounds of 6 frames. Works with any build of the module
(PYTHONPATH), e.g. to compare commits.

  PYTHONPATH=build/lib/python3/dist-packages \
    xvfb-run -a /usr/bin/python3 Measurement/moving_cost.py 50
"""
import statistics, time, sys
import vtkmodules.vtkRenderingOpenGL2  # noqa
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource, vtkCubeSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow
import vtkshadowmaps
r = vtkRenderer(); w = vtkRenderWindow(); w.SetOffScreenRendering(1); w.SetSize(960, 540); w.AddRenderer(r)
def add(src):
    m = vtkPolyDataMapper(); m.SetInputConnection(src.GetOutputPort()); a = vtkActor(); a.SetMapper(m); r.AddActor(a)
p = vtkPlaneSource(); p.SetOrigin(-60,-60,0); p.SetPoint1(60,-60,0); p.SetPoint2(-60,60,0); add(p)
s = vtkSphereSource(); s.SetCenter(0,0,3); s.SetRadius(2); s.SetThetaResolution(64); s.SetPhiResolution(64); add(s)
for i in range(int(sys.argv[1])):
    c = vtkCubeSource(); c.SetCenter(-18 + (i % 10) * 4, -18 + (i // 10) * 4, 1); c.SetZLength(2); add(c)
r.AutomaticLightCreationOff()
sun = vtkLight(); sun.SetPositional(False); sun.SetPosition(0.3, 0.4, 1); sun.SetFocalPoint(0, 0, 0); r.AddLight(sun)
cam = r.GetActiveCamera(); cam.SetPosition(0, -50, 8); cam.SetFocalPoint(0, 0, 0); cam.SetViewUp(0, 0, 1)
from vtkmodules.vtkRenderingCore import vtkCamera
init = vtkCamera(); init.DeepCopy(cam)
makers = {"none": lambda: None, "warped": vtkshadowmaps.vtkWarpedShadowMapPass, "cascaded": vtkshadowmaps.vtkCascadedShadowMapPass}
passes = {k: f() for k, f in makers.items()}
mv = {k: [] for k in passes}; st = {k: [] for k in passes}
for rnd in range(3):
    for k, q in passes.items():
        r.SetPass(q); cam.DeepCopy(init); r.ResetCameraClippingRange(); w.Render(); w.Render()
        for f in range(6):
            t = time.perf_counter(); w.Render(); w.WaitForCompletion(); st[k].append(time.perf_counter() - t)
        for f in range(6):
            cam.Azimuth(0.3); r.ResetCameraClippingRange(); t = time.perf_counter(); w.Render(); w.WaitForCompletion(); mv[k].append(time.perf_counter() - t)
for k in passes:
    print(f"{sys.argv[1]:>3s} boxes {k:9s} moving {1000*statistics.median(mv[k]):6.1f} steady {1000*statistics.median(st[k]):6.1f}")
