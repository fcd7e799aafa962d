"""Whether VTK's own vtkShadowMapPass follows a time series: a contour of a
61^3 wavelet under a spot light, its value changed from 140 to 230 with the
pass set, against a fresh VTK pass's frame of the value-230 contour. VTK's baker
renders its map again only when a light or a prop is modified, not when a
prop's data change, so without the actor marked modified it keeps the first
value's shadow.

  xvfb-run -a /usr/bin/python3 Measurement/vtk_pass_time_series.py

Prints, for the data changed alone and for the data changed with the actor
marked modified, how many pixels differ by more than 30 (of 255, in any
channel) from the fresh pass's frame.
"""
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
from vtkmodules.vtkRenderingOpenGL2 import (vtkCameraPass, vtkRenderPassCollection,
                                            vtkSequencePass, vtkShadowMapPass)

FIRST_VALUE = 140.0
LAST_VALUE = 230.0


def vtk_shadow_pass():
    shadows = vtkShadowMapPass()
    passes = vtkRenderPassCollection()
    passes.AddItem(shadows.GetShadowMapBakerPass())
    passes.AddItem(shadows)
    sequence = vtkSequencePass()
    sequence.SetPasses(passes)
    camera_pass = vtkCameraPass()
    camera_pass.SetDelegatePass(sequence)
    return camera_pass


def scene(value):
    """A window showing the contour at `value` over a ground under a spot, with
    VTK's pass; returns the window, the contour filter and its actor."""
    renderer = vtkRenderer()
    window = vtkRenderWindow()
    window.SetSize(320, 240)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-30, 30, -30, 30, -30, 30)
    contour = vtkFlyingEdges3D()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, value)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(contour.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    ground = vtkPlaneSource()
    ground.SetOrigin(-60, -60, -36)
    ground.SetPoint1(60, -60, -36)
    ground.SetPoint2(-60, 60, -36)
    ground.SetResolution(50, 50)
    ground_mapper = vtkPolyDataMapper()
    ground_mapper.SetInputConnection(ground.GetOutputPort())
    ground_actor = vtkActor()
    ground_actor.SetMapper(ground_mapper)
    renderer.AddActor(ground_actor)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetConeAngle(60)
    light.SetPosition(0, 0, 150)
    light.SetFocalPoint(0, 0, 0)
    renderer.AddLight(light)
    renderer.SetPass(vtk_shadow_pass())
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -150, 120)
    camera.SetFocalPoint(0, 0, -20)
    renderer.ResetCameraClippingRange()
    return window, contour, actor


def frame(window):
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float)


def differing_pixels(touch_actor):
    window, contour, actor = scene(FIRST_VALUE)
    window.Render()
    contour.SetValue(0, LAST_VALUE)
    if touch_actor:
        actor.Modified()
    changed = frame(window)
    fresh_window, _, _ = scene(LAST_VALUE)
    fresh = frame(fresh_window)
    return int((numpy.abs(changed - fresh).max(axis=1) > 30).sum()), changed.shape[0]


for touch, label in ((False, "data changed alone"), (True, "data changed, actor modified")):
    differing, pixels = differing_pixels(touch)
    print(f"{label}: {differing} of {pixels} pixels differ from a fresh VTK pass's frame")
