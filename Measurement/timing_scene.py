"""The scene and the timed frame of the Python timing scripts (frame_times.py,
cascade_cost.py, moving_cost.py): an off-screen window, a ground, rows of boxes,
a sun, and one frame timed to the GL's completion."""
import time
import vtkmodules.vtkRenderingOpenGL2  # noqa
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


def add_sun(renderer):
    sun = vtkLight(); sun.SetPositional(False); sun.SetPosition(0.3, 0.4, 1); sun.SetFocalPoint(0, 0, 0)
    renderer.AddLight(sun)


def timed_render(w):
    """Seconds of one frame, the GL finished."""
    t = time.perf_counter(); w.Render(); w.WaitForCompletion()
    return time.perf_counter() - t
