"""Shadow-map render passes for VTK: ``renderer.SetPass(vtkshadowmaps.make_pass())`` (the
automatic pass: each light's views chosen from where it shines, in dual-depth maps), a
technique by name (``make_pass("cascaded")``), or a class
(``renderer.SetPass(vtkshadowmaps.vtkWarpedShadowMapPass())``)."""
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
