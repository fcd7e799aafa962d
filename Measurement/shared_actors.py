"""Still frames of N boxes and a ground shown in two renderers of one window
(left: a shadow pass; right: none), the actors shared by both renderers or the
right one holding copies: the frame time and the shader sources built over the
timed frames. VTK's mapper keeps one program per primitive and rebuilds it
whenever the render passes on its prop change, which they did between the two
renderers' draws of a shared actor every frame until the pass kept its place
on such props (issue 63).

  PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
    Measurement/shared_actors.py [N (300)] [FRAMES (10)]

Prints one line per arrangement: the mean still frame in ms, the rendering
thread's CPU time per frame (llvmpipe rasterises on threads of its own), and the shader
sources the left renderer's mappers built over the timed frames (the pass's
NumberOfShaderBuilds; the right renderer's rebuilds, which the pass does not
see, were as many).
"""
import sys
import time

import vtkshadowmaps
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)

COUNT = int(sys.argv[1]) if len(sys.argv) > 1 else 300
FRAMES = int(sys.argv[2]) if len(sys.argv) > 2 else 10


def actor_of(source):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def scene(shared):
    window = vtkRenderWindow()
    window.SetSize(960, 480)
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    left, right = vtkRenderer(), vtkRenderer()
    left.SetViewport(0.0, 0.0, 0.5, 1.0)
    right.SetViewport(0.5, 0.0, 1.0, 1.0)
    for renderer in (left, right):
        window.AddRenderer(renderer)
        renderer.AutomaticLightCreationOff()
        sun = vtkLight()
        sun.SetLightTypeToSceneLight()
        sun.SetPositional(False)
        sun.SetPosition(1, -1, 3)
        sun.SetFocalPoint(0, 0, 0)
        renderer.AddLight(sun)
    ground = vtkPlaneSource()
    ground.SetOrigin(-30, -30, 0)
    ground.SetPoint1(30, -30, 0)
    ground.SetPoint2(-30, 30, 0)
    cube = vtkCubeSource()
    side = int(COUNT ** 0.5 + 0.999)
    placements = [(None, None)] + [(i % side, i // side) for i in range(COUNT)]
    for i, j in placements:
        for renderer in (left, right):
            if renderer is right and shared:
                continue
            actor = actor_of(ground if i is None else cube)
            if i is not None:
                actor.SetScale(1.2, 1.2, 1.0 + (i * 7 + j * 13) % 5)
                actor.SetPosition(-28 + 56.0 * i / side, -28 + 56.0 * j / side, 0.5)
            renderer.AddActor(actor)
            if shared:
                right.AddActor(actor)
    for renderer in (left, right):
        renderer.ResetCamera()
    left.SetPass(vtkshadowmaps.vtkCascadedShadowMapPass())
    return window, left.GetPass()


for shared in (True, False):
    window, shadow_pass = scene(shared)
    for _ in range(3):
        window.Render()
    builds = shadow_pass.GetNumberOfShaderBuilds()
    start, cpu = time.perf_counter(), time.thread_time()
    for _ in range(FRAMES):
        window.Render()
    elapsed = (time.perf_counter() - start) / FRAMES * 1000.0
    cpu = (time.thread_time() - cpu) / FRAMES * 1000.0
    print(f"{'shared' if shared else 'copies'}: {COUNT} boxes, still frame {elapsed:.0f} ms "
          f"({cpu:.0f} ms of the rendering thread's CPU), "
          f"{shadow_pass.GetNumberOfShaderBuilds() - builds} shader sources built through the pass "
          f"in {FRAMES} frames")
