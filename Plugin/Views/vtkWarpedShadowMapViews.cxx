#include "vtkWarpedShadowMapViews.h"

#include "ShadowMapCascades.h"
#include "ShadowMapLight.h"
#include "ShadowMapPerspective.h"
#include "ShadowMapTrapezoid.h"
#include "ShadowMapWarping.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_access.hpp>

vtkStandardNewMacro(vtkWarpedShadowMapViews);

using shadowmaps::LightView;
using shadowmaps::ShadowFrame;
using shadowmaps::ShadowLight;

namespace
{
// Distance along the view axis from the camera's near plane to the farthest
// point of the focus body B (0 when B is empty).
double FocusBodyDepth(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const shadowmaps::Aabb& scene)
{
  const glm::dmat4 inverse = glm::inverse(cameraProjection);
  const glm::dvec4 nearCentre = inverse * glm::dvec4(0.0, 0.0, -1.0, 1.0);
  const double nearDistance = -nearCentre.z / nearCentre.w;
  double farthest = nearDistance;
  for (const auto& p : shadowmaps::IntersectFrustumWithBox(cameraProjection * cameraView, scene))
  {
    farthest = std::max(farthest, -(cameraView * glm::dvec4(p, 1.0)).z);
  }
  return std::isfinite(farthest - nearDistance) ? farthest - nearDistance : 0.0;
}
glm::dvec3 ViewDirection(const glm::dmat4& cameraView)
{
  return -glm::dvec3(glm::row(cameraView, 2));
}

// PSMSlideBack, or when negative the geometric mean of the (tight) near and far.
double PSMSlideBackFor(double setting, const glm::dmat4& projection)
{
  if (setting >= 0.0)
  {
    return setting;
  }
  const glm::dvec2 planes = shadowmaps::ProjectionDepthRange(projection);
  return std::sqrt(std::max(planes.x * planes.y, 0.0));
}

// The camera's projection with its near and far planes moved to the nearest and
// farthest visible prop. PSM spends its map in proportion to 1 / depth from the
// near plane (Stamminger and Drettakis push the near plane as far as the scene
// allows); a camera standing inside the scene's bounds would otherwise give the
// empty space in front of it nearly the whole map.
glm::dmat4 TightProjection(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const std::vector<shadowmaps::Aabb>& props)
{
  const glm::dvec2 range = shadowmaps::TightDepthRange(cameraView, cameraProjection, props, 0.01);
  if (!(range.y > range.x) || range == shadowmaps::ProjectionDepthRange(cameraProjection))
  {
    return cameraProjection;
  }
  return shadowmaps::SubFrustumProjection(cameraProjection, range.x, range.y);
}
} // namespace

//------------------------------------------------------------------------------
shadowmaps::DirectionalWarp vtkWarpedShadowMapViews::LightSpaceWarpOf(int warpMode)
{
  return warpMode == GMNPR ? shadowmaps::DirectionalWarp::GMNPR : shadowmaps::DirectionalWarp::LiSPSM;
}

//------------------------------------------------------------------------------
shadowmaps::WarpOptions vtkWarpedShadowMapViews::LightSpaceWarpOptions() const
{
  shadowmaps::WarpOptions options;
  options.FreeParameterN = this->LiSPSMFreeParameter;
  options.LloydFalloff = this->LloydFalloff;
  return options;
}

//------------------------------------------------------------------------------
LightView vtkWarpedShadowMapViews::FitDirectionalLight(
  const ShadowFrame& frame, const ShadowLight& light) const
{
  // Every warp measures the view's depths on the frustum focused on what is
  // visible: PSM spends its map as 1 / depth from the near plane, TSM measures
  // its focus distance from it, and LiSPSM's n_opt = z_n + sqrt(z_f z_n) (and
  // GMNPR's lambda) take its z_n. A camera's own near plane can be a hair in
  // front of it, and the warp then spends the map on empty air.
  const glm::dmat4 projection =
    TightProjection(frame.CameraView, frame.CameraProjection, frame.PropBounds);
  if (this->WarpMode == PSM)
  {
    const double weight =
      shadowmaps::PerspectiveWarpWeight(ViewDirection(frame.CameraView), light.Direction);
    return shadowmaps::FitPerspective(frame.CameraView, projection, frame.SceneBounds,
      light.Direction, frame.Resolution, PSMSlideBackFor(this->PSMSlideBack, projection), weight)
      .Light;
  }
  if (this->WarpMode == TSM)
  {
    const double delta = this->TSMFocusDistance > 0.0
      ? this->TSMFocusDistance
      : 0.2 * FocusBodyDepth(frame.CameraView, projection, frame.SceneBounds);
    const shadowmaps::TrapezoidMap map = shadowmaps::FitTrapezoid(projection * frame.CameraView,
      frame.SceneBounds, light.Direction, delta, this->TSMFocusFraction);
    return shadowmaps::TrapezoidLightView(map, frame.Resolution);
  }
  LightView view = shadowmaps::FitDirectionalWarped(frame.CameraView, projection,
    frame.SceneBounds, light.Direction, frame.Resolution, LightSpaceWarpOf(this->WarpMode),
    this->LightSpaceWarpOptions());
  return view;
}

//------------------------------------------------------------------------------
LightView vtkWarpedShadowMapViews::FitSpotLight(
  const ShadowFrame& frame, const ShadowLight& light) const
{
  if (this->WarpMode == PSM)
  {
    const glm::dmat4 projection =
      TightProjection(frame.CameraView, frame.CameraProjection, frame.PropBounds);
    const double weight =
      shadowmaps::PerspectiveWarpWeight(ViewDirection(frame.CameraView), light.Direction);
    return shadowmaps::FitSpotPerspective(frame.CameraView, projection, frame.SceneBounds,
      light.Position, light.Direction, light.ConeAngle, frame.Resolution,
      PSMSlideBackFor(this->PSMSlideBack, projection), weight)
      .Light;
  }
  if (this->WarpMode == TSM)
  {
    return shadowmaps::FitSpotTrapezoid(frame.CameraView, frame.CameraProjection,
      frame.SceneBounds, light.Position, light.Direction, light.ConeAngle, frame.Resolution,
      this->TSMFocusDistance, this->TSMFocusFraction);
  }
  return shadowmaps::FitSpotWarped(frame.CameraView, frame.CameraProjection, frame.SceneBounds,
    light.Position, light.Direction, light.ConeAngle, frame.Resolution,
    LightSpaceWarpOf(this->WarpMode), this->LightSpaceWarpOptions());
}

//------------------------------------------------------------------------------
LightView vtkWarpedShadowMapViews::FitWarpedView(const ShadowFrame& frame, const ShadowLight& light) const
{
  if (light.Kind == shadowmaps::LightKind::Spot)
  {
    return this->FitSpotLight(frame, light);
  }
  LightView view = this->FitDirectionalLight(frame, light);
  // A warped map's TexelConstant bounds the coarsest texel over B; as a normal
  // offset near the viewer it would be many texels too large.
  view.TexelSizeFromGradient = view.Perspective;
  return view;
}

//------------------------------------------------------------------------------
void vtkWarpedShadowMapViews::FitLight(const ShadowFrame& frame, ShadowLight& light)
{
  const bool mayWarp = this->WarpMode != UNIFORM && !shadowmaps::NeedsCubeFaces(light);
  // Every warp but PSM stores linear depth (PSM's w depends on depth).
  light.PossibleFeatures = !mayWarp ? 0
    : this->WarpMode == PSM        ? shadowmaps::GradientTexels
                                   : shadowmaps::GradientTexels | shadowmaps::LinearDepths;
  if (!mayWarp)
  {
    vtkShadowMapViews::FitUniformViews(frame, light);
    return;
  }
  LightView view = this->FitWarpedView(frame, light);
  if (!shadowmaps::IsFinite(view.ViewProjection()))
  {
    vtkShadowMapViews::FitUniformViews(frame, light);
    return;
  }
  const LightView* last = light.LastViews.size() == 1 ? &light.LastViews.front() : nullptr;
  view = this->InteractiveView(frame, light, view, last,
    [&](const ShadowFrame& wider) { return this->FitWarpedView(wider, light); });
  light.Layout = shadowmaps::ViewLayout::Single;
  light.Views = { view };
}

//------------------------------------------------------------------------------
void vtkWarpedShadowMapViews::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "WarpMode: " << this->WarpMode << "\n";
  os << indent << "LiSPSMFreeParameter: " << this->LiSPSMFreeParameter << "\n";
  os << indent << "LloydFalloff: " << this->LloydFalloff << "\n";
  os << indent << "PSMSlideBack: " << this->PSMSlideBack << "\n";
  os << indent << "TSMFocusDistance: " << this->TSMFocusDistance << "\n";
  os << indent << "TSMFocusFraction: " << this->TSMFocusFraction << "\n";
}
