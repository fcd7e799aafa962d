"""The scene and the timed frame of the Python timing scripts (frame_times.py,
cascade_cost.py, moving_cost.py, rerender_cost.py, drag_cost.py, reach_culling.py): an off-screen
window, a ground, rows of boxes, a sun, VTK's shadow pass, and one frame timed to
the GL's completion."""
import time
from vtkmodules.vtkRenderingOpenGL2 import (vtkCameraPass, vtkRenderPassCollection, vtkSequencePass,
                                            vtkShadowMapPass)
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow


def window(width, height):
    """An off-screen window with one renderer and automatic lights off."""
    r = vtkRenderer(); w = vtkRenderWindow(); w.SetOffScreenRendering(1); w.SetSize(width, height)
    w.AddRenderer(r); r.AutomaticLightCreationOff()
    return r, w


def add(renderer, source):
    m = vtkPolyDataMapper(); m.SetInputConnection(source.GetOutputPort())
    a = vtkActor(); a.SetMapper(m); renderer.AddActor(a)


def add_ground_and_boxes(renderer, half_size, boxes):
    """A square ground of half_size at z = 0 and `boxes` 1 x 1 x 2 boxes, ten to a row, 4 apart."""
    p = vtkPlaneSource(); p.SetOrigin(-half_size, -half_size, 0)
    p.SetPoint1(half_size, -half_size, 0); p.SetPoint2(-half_size, half_size, 0); add(renderer, p)
    for i in range(boxes):
        c = vtkCubeSource(); c.SetCenter(-18 + (i % 10) * 4, -18 + (i // 10) * 4, 1); c.SetZLength(2)
        add(renderer, c)


def add_sun(renderer, toward=(0.3, 0.4, 1)):
    """A directional scene light shining from `toward` to the origin."""
    sun = vtkLight(); sun.SetPositional(False); sun.SetPosition(*toward); sun.SetFocalPoint(0, 0, 0)
    renderer.AddLight(sun)


def timed_render(w):
    """Seconds of one frame, the GL finished."""
    t = time.perf_counter(); w.Render(); w.WaitForCompletion()
    return time.perf_counter() - t


def vtk_shadow_map_pass(resolution=None):
    """VTK's vtkShadowMapPass as its documentation assembles it: the baker, then the
    shadow pass, in a sequence under a camera pass."""
    shadows = vtkShadowMapPass()
    if resolution is not None:
        shadows.GetShadowMapBakerPass().SetResolution(resolution)
    passes = vtkRenderPassCollection()
    passes.AddItem(shadows.GetShadowMapBakerPass()); passes.AddItem(shadows)
    sequence = vtkSequencePass(); sequence.SetPasses(passes)
    camera = vtkCameraPass(); camera.SetDelegatePass(sequence)
    return camera
