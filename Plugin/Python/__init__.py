"""Shadow-map render passes for VTK, one line to turn shadows on::

    renderer.SetPass(vtkshadowmaps.make_pass())

``make_pass(technique, **settings)`` makes a pass by name, its settings given as
snake_case names of its setters (``make_pass("cascaded", number_of_cascades=3)``):

- ``auto`` (the default): vtkAutomaticShadowMapPass gives each light the views its
  situation measured best for, on dual-depth maps; ``cost_budget`` lets it spend
  more maps, ``SetLightViews(light, views)`` pins a light's views and
  ``SetLightRepresentation(light, representation)`` its representation.
- ``uniform``, ``psm``, ``lispsm``, ``tsm``, ``gmnpr``: vtkWarpedShadowMapPass in that
  warp mode (one map per sun or spot, warped to give the viewer's near field more
  texels; ``psm_cube_map`` for Kozlov's cube).
- ``cascaded``: vtkCascadedShadowMapPass, a sun's maps split along the view
  (``number_of_cascades``, ``split_lambda``, ``maximum_shadow_distance``).
- ``depth``: vtkDepthShadowMapPass, depth maps in any views (``SetViews``).
- ``dual-depth``: vtkDualDepthShadowMapPass, two surfaces a texel, no bias to tune.
- ``variance``: vtkVarianceShadowMapPass, filterable moments (``SetMomentsToEVSM4()``,
  ``blur_radius``, ``light_bleeding_reduction``).

Every pass takes ``resolution``, a filter (``SetFilterToPoisson()``, ...),
``soft_shadows`` (lights with a LIGHT_SIZE), ``animation_keeps_views`` (scripted
camera paths keep views as drags do) and the CASTS_SHADOWS and RECEIVES_SHADOWS
property keys. ``vtkshadowmaps.pyvista.enable_shadows(plotter)`` puts a pass in
PyVista's chain. The guide (docs/GUIDE.md in the sources) has every setting."""
# The base classes live in VTK's own modules; load them before ours.
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from .vtkRenderingShadowMaps import *  # noqa: F401,F403
from .vtkRenderingShadowMaps import (vtkAutomaticShadowMapPass, vtkCascadedShadowMapPass,
                                     vtkDepthShadowMapPass,
                                     vtkDualDepthShadowMapPass, vtkVarianceShadowMapPass,
                                     vtkWarpedShadowMapPass)

# A technique's name -> (the pass's class, its warp mode or None).
TECHNIQUES = {
    "auto": (vtkAutomaticShadowMapPass, None),
    "uniform": (vtkWarpedShadowMapPass, "Uniform"),
    "psm": (vtkWarpedShadowMapPass, "PSM"),
    "lispsm": (vtkWarpedShadowMapPass, "LiSPSM"),
    "tsm": (vtkWarpedShadowMapPass, "TSM"),
    "gmnpr": (vtkWarpedShadowMapPass, "GMNPR"),
    "cascaded": (vtkCascadedShadowMapPass, None),
    "depth": (vtkDepthShadowMapPass, None),
    "dual-depth": (vtkDualDepthShadowMapPass, None),
    "variance": (vtkVarianceShadowMapPass, None),
}


def _setter(shadow_pass, name):
    """The setter a snake_case setting names, its words matched without case:
    ``resolution`` is SetResolution, ``psm_cube_map`` SetPSMCubeMap."""
    wanted = "set" + name.replace("_", "").lower()
    for attribute in dir(shadow_pass):
        if attribute.startswith("Set") and attribute.lower() == wanted:
            return getattr(shadow_pass, attribute)
    setter = "Set" + "".join(word[:1].upper() + word[1:] for word in name.split("_"))
    raise ValueError(f"{type(shadow_pass).__name__} has no {setter} (from {name!r})")


def make_pass(technique="auto", **settings):
    """The shadow pass of a technique (a key of TECHNIQUES; by default "auto",
    vtkAutomaticShadowMapPass), its settings given as snake_case names of its
    setters: ``resolution=2048`` calls ``SetResolution(2048)``, ``psm_cube_map=1``
    ``SetPSMCubeMap(1)``."""
    if technique not in TECHNIQUES:
        raise ValueError(
            f"unknown shadow technique {technique!r}; one of {', '.join(TECHNIQUES)}")
    pass_class, warp_mode = TECHNIQUES[technique]
    shadow_pass = pass_class()
    if warp_mode is not None:
        getattr(shadow_pass, "SetWarpModeTo" + warp_mode)()
    for name, value in settings.items():
        _setter(shadow_pass, name)(value)
    return shadow_pass
