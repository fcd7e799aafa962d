"""Steady frames of 2,025 boxes (one actor and mapper each) and a ground under a
sun at 960 x 540 with 64^2 maps (so that rasterisation adds little and the
per-actor work shows): argv[1] is none, vtk (VTK's vtkShadowMapPass), uniform
(vtkDepthShadowMapPass) or csm (vtkCascadedShadowMapPass), argv[2] the frames
timed after 3 untimed; with --moving the frames orbit the camera by one degree
each, rendered as a user's drag (the window's desired update rate 15). Prints the mean frame in ms and the rendering thread's CPU time
per frame (VTK's, the pass's and the driver's work on that thread; llvmpipe rasterises
on threads of its own). For where the time goes,
run it under perf and sum the samples under a function with perf_inclusive.py:

  mkfifo ctl ack; PERF_CONTROL=ctl,ack PYTHONPATH=build/lib/python3/dist-packages \\
    xvfb-run -a perf record --control=fifo:ctl,ack -D -1 -F 499 --call-graph dwarf,16384 \\
    -o uniform.data /usr/bin/python3 Measurement/many_actors.py uniform 60
  /usr/bin/python3 Measurement/perf_inclusive.py uniform.data vtkAbstractShadowMapPass::PrepareShadows
"""
import os
import sys
import time

import vtkshadowmaps
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)
from vtkmodules.vtkRenderingOpenGL2 import (vtkCameraPass, vtkRenderPassCollection,
                                            vtkSequencePass, vtkShadowMapBakerPass,
                                            vtkShadowMapPass)


def perf_command(control, command):
    """Has a perf record started with --control=fifo:CTL,ACK -D -1 sample only the
    timed frames: control is "CTL,ACK"."""
    if control:
        ctl, ack = control.split(",")
        with open(ctl, "w") as fifo:
            fifo.write(command + "\n")
        with open(ack) as fifo:
            fifo.read(5)


def add(renderer, source):
    mapper = vtkPolyDataMapper(); mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor(); actor.SetMapper(mapper); renderer.AddActor(actor)
    return actor


window = vtkRenderWindow(); window.SetSize(960, 540); window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
renderer = vtkRenderer(); window.AddRenderer(renderer)
ground = vtkPlaneSource(); ground.SetOrigin(-50, -50, 0); ground.SetPoint1(50, -50, 0)
ground.SetPoint2(-50, 50, 0)
add(renderer, ground)
cube = vtkCubeSource()
for i in range(45):
    for j in range(45):
        height = 0.5 + 3.0 * ((i * 7 + j * 13) % 10) / 10.0
        box = add(renderer, cube)
        box.SetScale(1.2, 1.2, height); box.SetPosition(-44 + 2 * i, -44 + 2 * j, height / 2)
renderer.AutomaticLightCreationOff()
sun = vtkLight(); sun.SetLightTypeToSceneLight(); sun.SetPositional(False)
sun.SetPosition(1, -1, 3); sun.SetFocalPoint(0, 0, 0); renderer.AddLight(sun)
camera = renderer.GetActiveCamera()
camera.SetPosition(-65, -70, 35); camera.SetFocalPoint(0, 0, 0); camera.SetViewUp(0, 0, 1)
renderer.ResetCameraClippingRange()

kind = sys.argv[1]
if kind in ("uniform", "csm"):
    shadows = (vtkshadowmaps.vtkDepthShadowMapPass() if kind == "uniform"
               else vtkshadowmaps.vtkCascadedShadowMapPass())
    shadows.SetResolution(64); renderer.SetPass(shadows)
elif kind == "vtk":
    baker = vtkShadowMapBakerPass(); baker.SetResolution(64)
    shadow = vtkShadowMapPass(); shadow.SetShadowMapBakerPass(baker)
    passes = vtkRenderPassCollection(); passes.AddItem(baker); passes.AddItem(shadow)
    sequence = vtkSequencePass(); sequence.SetPasses(passes)
    camera_pass = vtkCameraPass(); camera_pass.SetDelegatePass(sequence)
    renderer.SetPass(camera_pass)
for _ in range(3):
    window.Render()
arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
frames = int(arguments[1]) if len(arguments) > 1 else 40
moving = "--moving" in sys.argv
if moving:
    window.SetDesiredUpdateRate(15.0)
control = os.environ.get("PERF_CONTROL")  # perf record --control=fifo:CTL,ACK -D -1
perf_command(control, "enable")
start = time.perf_counter()
cpu_start = time.thread_time()
for _ in range(frames):
    if moving:
        camera.Azimuth(1.0); renderer.ResetCameraClippingRange()
    window.Render()
perf_command(control, "disable")
print(f"{kind}: {(time.perf_counter() - start) / frames * 1000:.1f} ms per "
      f"{'moving' if moving else 'steady'} frame, "
      f"{(time.thread_time() - cpu_start) / frames * 1000:.1f} ms of the rendering thread's CPU")
