"""Shadow-map render passes for VTK: ``renderer.SetPass(vtkshadowmaps.vtkWarpedShadowMapPass())``."""
# The base classes live in VTK's own modules; load them before ours.
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from .vtkRenderingShadowMaps import *  # noqa: F401,F403
