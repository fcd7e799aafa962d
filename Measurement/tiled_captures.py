"""Captures twice the window's size against one window of that size: a ground and
42 spheres under a sun, 400 x 300 captured at 800 x 600. For vtkWindowToImageFilter
with SetScale(2) and for vtkRenderLargeImage (magnification 2), with no pass and each
of the module's passes given on the command line, prints the pixels whose luminance
differs from the 800 x 600 window's by more than 60 of 255, per quarter (tile) at the
tile's best shift of up to 2 pixels, and the map updates the capture made.

  PYTHONPATH=build/lib/python3/dist-packages \
    xvfb-run -a /usr/bin/python3 Measurement/tiled_captures.py none \
    vtkDepthShadowMapPass vtkCascadedShadowMapPass
"""
import sys
import numpy as np
import vtkshadowmaps
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersHybrid import vtkRenderLargeImage
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)


def scene(width, height, pass_name):
    window = vtkRenderWindow(); window.SetSize(width, height); window.SetOffScreenRendering(1)
    renderer = vtkRenderer(); window.AddRenderer(renderer)

    def add(source):
        mapper = vtkPolyDataMapper(); mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor(); actor.SetMapper(mapper); renderer.AddActor(actor)

    ground = vtkPlaneSource(); ground.SetOrigin(-20, -20, 0); ground.SetPoint1(20, -20, 0)
    ground.SetPoint2(-20, 20, 0)
    add(ground)
    for i in range(-3, 4):
        for j in range(6):
            s = vtkSphereSource(); s.SetCenter(3 * i, 3 * j, 1.2); s.SetRadius(0.8)
            s.SetThetaResolution(24); s.SetPhiResolution(24)
            add(s)
    renderer.AutomaticLightCreationOff()
    sun = vtkLight(); sun.SetLightTypeToSceneLight(); sun.SetPositional(False)
    sun.SetPosition(3, -2, 10); sun.SetFocalPoint(0, 0, 0); renderer.AddLight(sun)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -14, 6); camera.SetFocalPoint(0, 6, 0); camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    shadow_pass = None
    if pass_name != "none":
        shadow_pass = getattr(vtkshadowmaps, pass_name)(); renderer.SetPass(shadow_pass)
    window.Render()
    return window, renderer, shadow_pass


def luminance(image):
    w, h, _ = image.GetDimensions()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return rgb.astype(float).mean(axis=2)


def differing_per_quarter(tiled, whole):
    counts = []
    for rows in (slice(0, 300), slice(300, 600)):
        for cols in (slice(0, 400), slice(400, 800)):
            counts.append(min(
                int((np.abs(np.roll(tiled, (dy, dx), (0, 1))[rows, cols][5:-5, 5:-5] -
                            whole[rows, cols][5:-5, 5:-5]) > 60).sum())
                for dx in range(-2, 3) for dy in range(-2, 3)))
    return counts


def updates(shadow_pass):
    return shadow_pass.GetNumberOfShadowMapUpdates() if shadow_pass else 0


for name in sys.argv[1:]:
    window, _, _ = scene(800, 600, name)
    grab = vtkWindowToImageFilter(); grab.SetInput(window); grab.ReadFrontBufferOff(); grab.Update()
    whole = luminance(grab.GetOutput())

    window, _, shadow_pass = scene(400, 300, name)
    before = updates(shadow_pass)
    grab = vtkWindowToImageFilter(); grab.SetInput(window); grab.ReadFrontBufferOff()
    grab.SetScale(2); grab.Update()
    print(f"{name}: vtkWindowToImageFilter x2: differing per quarter "
          f"{differing_per_quarter(luminance(grab.GetOutput()), whole)}, "
          f"map updates {updates(shadow_pass) - before}")

    window, renderer, shadow_pass = scene(400, 300, name)
    before = updates(shadow_pass)
    large = vtkRenderLargeImage(); large.SetInput(renderer); large.SetMagnification(2); large.Update()
    print(f"{name}: vtkRenderLargeImage x2: differing per quarter "
          f"{differing_per_quarter(luminance(large.GetOutput()), whole)}, "
          f"map updates {updates(shadow_pass) - before}")
