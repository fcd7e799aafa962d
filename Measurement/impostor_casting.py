"""What points drawn as spheres cost the maps: 50,000 points of 8 pixels in a ball over
a ground, 960 x 540, under a point light (six perspective cube faces) and a sun, every
layer rendered again each frame (the light's intensity toggles); the mean of 8 frames
after a first, with no pass and with each pass given on the command line, interleaved
in one process, as milliseconds and as ratios to no pass.

  PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
    Measurement/impostor_casting.py vtkDepthShadowMapPass vtkCascadedShadowMapPass
"""
import sys
import time

import vtkshadowmaps
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkPointSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401


def scene(light_kind, pass_name):
    window = vtkRenderWindow(); window.SetSize(960, 540); window.SetOffScreenRendering(1)
    renderer = vtkRenderer(); window.AddRenderer(renderer)
    for source in (vtkPlaneSource(), vtkPointSource()):
        mapper = vtkPolyDataMapper(); mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor(); actor.SetMapper(mapper); renderer.AddActor(actor)
        if isinstance(source, vtkPlaneSource):
            source.SetOrigin(-20, -20, 0); source.SetPoint1(20, -20, 0); source.SetPoint2(-20, 20, 0)
        else:
            source.SetNumberOfPoints(50000); source.SetRadius(5); source.SetCenter(0, 4, 6)
            actor.GetProperty().SetRenderPointsAsSpheres(True); actor.GetProperty().SetPointSize(8)
    renderer.AutomaticLightCreationOff()
    light = vtkLight(); light.SetLightTypeToSceneLight()
    if light_kind == "point":
        light.SetPositional(True); light.SetConeAngle(120); light.SetPosition(1, 0, 16)
    else:
        light.SetPositional(False); light.SetPosition(3, -2, 10)
    light.SetFocalPoint(0, 4, 0); renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -24, 12); camera.SetFocalPoint(0, 6, 0); camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    if pass_name != "none":
        renderer.SetPass(getattr(vtkshadowmaps, pass_name)())
    window.Render()
    return window, light


def mean_frame_ms(window, light, frames=8):
    start = time.perf_counter()
    for i in range(frames):
        light.SetIntensity(1.0 - 0.01 * (i % 2))
        window.Render()
    return 1000.0 * (time.perf_counter() - start) / frames


for light_kind in ("point", "sun"):
    scenes = {name: scene(light_kind, name) for name in ["none"] + sys.argv[1:]}
    times = {name: [] for name in scenes}
    for _ in range(2):
        for name, (window, light) in scenes.items():
            times[name].append(mean_frame_ms(window, light))
    none = min(times["none"])
    for name, measured in times.items():
        best = min(measured)
        print(f"{light_kind}: {name}: {best:.0f} ms, {best / none:.2f} x no pass")
