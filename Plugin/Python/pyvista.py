"""This module's shadows in a PyVista ``Plotter``, in one line.

    import pyvista as pv
    from vtkshadowmaps.pyvista import enable_shadows, disable_shadows

    plotter = pv.Plotter(lighting="none")
    plotter.add_light(pv.Light(light_type="scene light", position=(2, 3, 5)))
    ...
    shadows = enable_shadows(plotter)  # the automatic pass; or a technique:
    shadows = enable_shadows(plotter, "cascaded", number_of_cascades=3)
    plotter.enable_ssao()            # PyVista's own passes compose with it
    disable_shadows(plotter)         # the plain view again, GL memory released

It replaces ``plotter.enable_shadows()`` (VTK's vtkShadowMapPass) and keeps
PyVista's own chain of render passes: the shadow pass takes the place of the
vtkRenderStepsPass inside PyVista's camera pass (and draws the scene with a
steps pass of its own, which peels translucent geometry when the renderer
asks for depth peeling), so anti-aliasing (SSAA, FXAA), SSAO, eye-dome
lighting, depth of field and depth peeling all still apply to the shadowed
image. Tested with PyVista 0.44 and 0.49.
"""

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

from . import TECHNIQUES, make_pass  # noqa: F401 (TECHNIQUES: the names enable_shadows takes)
from . import vtkRenderingShadowMaps as _module


def _render_passes(plotter):
    renderer = getattr(plotter, "renderer", plotter)
    passes = getattr(renderer, "_render_passes", None)
    if passes is None or not hasattr(passes, "_pass_collection"):
        raise RuntimeError(
            "this PyVista keeps its render passes in a way vtkshadowmaps.pyvista does not "
            "know (tested with PyVista 0.44 and 0.49); use renderer.SetPass(make_pass(...)) "
            "instead, which replaces PyVista's own passes")
    return renderer, passes


def _items(collection):
    collection.InitTraversal()
    items = []
    item = collection.GetNextRenderPass()
    while item is not None:
        items.append(item)
        item = collection.GetNextRenderPass()
    return items


def _current_shadow_pass(passes):
    current = passes._shadow_map_pass
    return current if isinstance(current, _module.vtkAbstractShadowMapPass) else None


def enable_shadows(plotter, technique="auto", **settings):
    """Turns on this module's shadows in the plotter's active renderer (or in
    the renderer given as ``plotter``) and returns the pass (make_pass's:
    vtkAutomaticShadowMapPass by default). Replaces VTK's
    shadows (``plotter.enable_shadows()``) and an earlier call's pass. To go
    back to VTK's shadows, call disable_shadows first: PyVista's
    enable_shadows() sees a shadow pass in place and does nothing."""
    renderer, passes = _render_passes(plotter)
    disable_shadows(plotter)
    if passes._shadow_map_pass is not None:
        plotter.disable_shadows()  # VTK's vtkShadowMapPass
    shadow_pass = make_pass(technique, **settings)
    collection = passes._pass_collection
    steps = [item for item in _items(collection) if item.IsA("vtkRenderStepsPass")]
    if len(steps) != 1:
        raise RuntimeError(
            "PyVista's pass collection does not hold the one vtkRenderStepsPass expected")
    collection.RemoveItem(steps[0])
    collection.AddItem(shadow_pass)
    # PyVista keeps its chain of passes on the renderer while it has a shadow
    # pass, and releases that pass's GL objects when the renderer closes.
    passes._shadow_map_pass = shadow_pass
    passes._update_passes()
    return shadow_pass


def disable_shadows(plotter):
    """Turns this module's shadows off again: PyVista's chain as it was, and
    the pass's maps and programs released (no GL memory kept)."""
    renderer, passes = _render_passes(plotter)
    shadow_pass = _current_shadow_pass(passes)
    if shadow_pass is None:
        return
    collection = passes._pass_collection
    collection.RemoveItem(shadow_pass)
    collection.AddItem(vtkRenderStepsPass())  # as PyVista makes its chain
    render_window = renderer.GetRenderWindow()
    if render_window is not None:
        shadow_pass.ReleaseGraphicsResources(render_window)
    passes._shadow_map_pass = None
    passes._update_passes()
