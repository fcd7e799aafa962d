#include "vtkWarpedShadowMapPass.h"

#include "ShadowMapWarping.h"
#include "vtkObjectFactory.h"
#include "vtkShadowMapInternals.h"

vtkStandardNewMacro(vtkWarpedShadowMapPass);

void vtkWarpedShadowMapPass::ComputeLightViews(Internals& internals, int lightIndex)
{
  shadowmaps::ShadowLight& light = internals.Lights[lightIndex];
  if (this->WarpMode == UNIFORM || light.Kind != shadowmaps::LightKind::Directional)
  {
    this->FitLightViewsUniform(internals, lightIndex);
    return;
  }
  shadowmaps::WarpOptions options;
  options.FreeParameterN = this->LiSPSMFreeParameter;
  options.LloydFalloff = this->LloydFalloff;
  const auto warp = this->WarpMode == GMNPR ? shadowmaps::DirectionalWarp::GMNPR
                                            : shadowmaps::DirectionalWarp::LiSPSM;
  shadowmaps::LightView view = shadowmaps::FitDirectionalWarped(internals.CameraView,
    internals.CameraProjection, internals.SceneBounds, light.Direction, internals.Resolution, warp,
    options);
  // The warped map's TexelConstant bounds the coarsest texel over B; as a normal
  // offset near the viewer it would be many texels too large.
  view.TexelSizeFromGradient = view.Perspective;
  light.Views = { view };
}

void vtkWarpedShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "WarpMode: " << this->WarpMode << "\n";
  os << indent << "LiSPSMFreeParameter: " << this->LiSPSMFreeParameter << "\n";
  os << indent << "LloydFalloff: " << this->LloydFalloff << "\n";
}
