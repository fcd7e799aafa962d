#include "vtkWarpedShadowMapViews.h"

#include "ShadowMapCascades.h"
#include "ShadowMapLight.h"
#include "ShadowMapPerspective.h"
#include "ShadowMapPerspectiveCube.h"
#include "ShadowMapTrapezoid.h"
#include "ShadowMapWarping.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_access.hpp>

vtkStandardNewMacro(vtkWarpedShadowMapViews);

using shadowmaps::LightView;
using shadowmaps::Plane;
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

// The world planes around the receivers a light's shadows can fall on: the
// camera's frustum, the scene, and for a spot the half-space in front of it
// (and its cone's map where one map holds the cone).
std::vector<shadowmaps::Plane> ReceiversOfLight(const glm::dmat4& cameraViewProjection,
  const shadowmaps::Aabb& scene, const ShadowLight& light, int resolution)
{
  std::vector<shadowmaps::Plane> planes;
  for (const auto& set : { shadowmaps::FrustumPlanes(cameraViewProjection), shadowmaps::BoxPlanes(scene) })
  {
    planes.insert(planes.end(), set.begin(), set.end());
  }
  if (light.Kind == shadowmaps::LightKind::Spot)
  {
    const glm::dvec3 axis = shadowmaps::SafeDirection(light.Direction);
    planes.push_back({ axis, -glm::dot(axis, light.Position) });
    if (light.ConeAngle <= shadowmaps::WidestSingleMapCone)
    {
      const auto cone = shadowmaps::FrustumPlanes(shadowmaps::FitSpot(cameraViewProjection, scene,
        light.Position, light.Direction, light.ConeAngle, resolution)
                                                    .ViewProjection());
      planes.insert(planes.end(), cone.begin(), cone.end());
    }
  }
  return planes;
}
} // namespace

//------------------------------------------------------------------------------
vtkWarpedShadowMapViews::vtkWarpedShadowMapViews()
  : PseudoNearFraction(shadowmaps::WarpOptions().PseudoNearFraction)
{
}

//------------------------------------------------------------------------------
const char* vtkWarpedShadowMapViews::GetSingleMapKindName(const ShadowLight& light) const
{
  // Only warped views take their texel size from the map's gradient; a fit
  // that could not warp (a parallel camera, the light along the view) is the
  // focused uniform map.
  if (light.Views.empty() || !light.Views.front().TexelSizeFromGradient)
  {
    return "uniform";
  }
  switch (this->WarpMode)
  {
    case LISPSM:
      return "lispsm";
    case GMNPR:
      return "gmnpr";
    case PSM:
      return "psm";
    case TSM:
      return "tsm";
    default:
      return "uniform";
  }
}

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
  options.PseudoNearFraction = this->PseudoNearFraction;
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
bool vtkWarpedShadowMapViews::UsesPerspectiveCube(const ShadowLight& light) const
{
  if (this->WarpMode != PSM)
  {
    return false;
  }
  return shadowmaps::NeedsCubeFaces(light) ? this->PSMCubeMap != PSM_CUBE_NEVER
                                           : this->PSMCubeMap == PSM_CUBE_ALWAYS;
}

//------------------------------------------------------------------------------
bool vtkWarpedShadowMapViews::AssignPerspectiveCube(const ShadowFrame& frame, ShadowLight& light) const
{
  std::vector<Plane> receivers;
  const shadowmaps::PerspectiveCube cube = this->FitCubeFor(frame, light, receivers);
  if (!cube.Valid)
  {
    return false;
  }
  light.Layout = shadowmaps::ViewLayout::PerspectiveCube;
  const auto assign = [&light](const shadowmaps::PerspectiveCube& chosen) {
    light.Views.assign(chosen.Faces.begin(), chosen.Faces.end());
    light.FaceSelection.assign(chosen.Selection.begin(), chosen.Selection.end());
  };
  if (this->MayKeepViews(frame))
  {
    // A kept cube keeps its own selection: receivers pick its faces as they
    // were rendered, however the camera has moved.
    const shadowmaps::Aabb scene = shadowmaps::NonDegenerate(frame.SceneBounds);
    const shadowmaps::FreshCube fresh = shadowmaps::MeasureFreshCube(
      cube, receivers, scene, shadowmaps::TowardLight(light), frame.Resolution);
    const auto serves = [&](const std::vector<LightView>& faces,
                          const std::vector<double>& selection, double texelRatio) {
      return shadowmaps::KeptCubeServes(faces, selection, receivers, fresh, scene,
        shadowmaps::TowardLight(light), frame.Resolution, texelRatio,
        frame.FilterReachTexels + 1.0);
    };
    if (serves(light.LastViews, light.LastFaceSelection, this->InteractiveTexelRatio))
    {
      light.Views = light.LastViews;
      light.FaceSelection = light.LastFaceSelection;
      return true;
    }
    for (const ShadowFrame& wider : vtkShadowMapViews::WidenedFrames(frame))
    {
      std::vector<Plane> widerReceivers;
      const shadowmaps::PerspectiveCube widened = this->FitCubeFor(wider, light, widerReceivers);
      if (widened.Valid &&
        serves(std::vector<LightView>(widened.Faces.begin(), widened.Faces.end()),
          std::vector<double>(widened.Selection.begin(), widened.Selection.end()),
          this->WidenedTexelRatio()))
      {
        assign(widened);
        return true;
      }
    }
  }
  assign(cube);
  return true;
}

//------------------------------------------------------------------------------
shadowmaps::PerspectiveCube vtkWarpedShadowMapViews::FitCubeFor(
  const ShadowFrame& frame, const ShadowLight& light, std::vector<Plane>& receivers) const
{
  const glm::dmat4 projection =
    TightProjection(frame.CameraView, frame.CameraProjection, frame.PropBounds);
  const shadowmaps::Aabb scene = shadowmaps::NonDegenerate(frame.SceneBounds);
  receivers = ReceiversOfLight(projection * frame.CameraView, scene, light, frame.Resolution);
  return shadowmaps::FitPerspectiveCube(frame.CameraView, projection, receivers, scene,
    shadowmaps::TowardLight(light), frame.Resolution,
    PSMSlideBackFor(this->PSMSlideBack, projection), std::max(4.0, frame.FilterReachTexels + 1.0));
}

//------------------------------------------------------------------------------
void vtkWarpedShadowMapViews::FitLight(const ShadowFrame& frame, ShadowLight& light)
{
  const bool cube = this->UsesPerspectiveCube(light);
  const bool mayWarp = this->WarpMode != UNIFORM && !shadowmaps::NeedsCubeFaces(light);
  // Every warp but PSM stores linear depth (PSM's w depends on depth). A light
  // that gets the cube keeps its features in a frame that falls back to
  // another layout (no cube can be built: a parallel camera, the light in the
  // camera's plane), which still changes the receivers' layout and so their
  // shaders.
  light.PossibleFeatures = (cube ? shadowmaps::GradientTexels : 0) |
    (!mayWarp                ? 0
        : this->WarpMode == PSM ? shadowmaps::GradientTexels
                                : shadowmaps::GradientTexels | shadowmaps::LinearDepths);
  if (cube && frame.SceneBounds.IsUsable() && this->AssignPerspectiveCube(frame, light))
  {
    return;
  }
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
  os << indent << "PseudoNearFraction: " << this->PseudoNearFraction << "\n";
  os << indent << "PSMSlideBack: " << this->PSMSlideBack << "\n";
  os << indent << "PSMCubeMap: " << this->PSMCubeMap << "\n";
  os << indent << "TSMFocusDistance: " << this->TSMFocusDistance << "\n";
  os << indent << "TSMFocusFraction: " << this->TSMFocusFraction << "\n";
}
