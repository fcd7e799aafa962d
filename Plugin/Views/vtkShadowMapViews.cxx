#include "vtkShadowMapViews.h"

#include "ShadowMapCascades.h" // For TightDepthRange
#include "ShadowMapKeptViews.h"
#include "ShadowMapLight.h"

#include <array>
#include <optional>

using shadowmaps::LightView;
using shadowmaps::ShadowFrame;
using shadowmaps::ShadowLight;

namespace
{
// A view fitted again in an interactive frame is fitted to a camera whose eye
// is moved back by WidenedBackwardPerNearDepth times the nearest visible prop's
// depth and whose sides are turned out by WidenedTurnDegrees, both multiplied
// by the largest of WidenedShares whose fit serves. It then holds several
// frames of a drag (docs/notes/interactive-speed.md, "Wider refits").
constexpr double WidenedBackwardPerNearDepth = 0.1;
constexpr double WidenedTurnDegrees = 1.0;
constexpr std::array<double, 5> WidenedShares{ 4.0, 2.0, 1.0, 0.5, 0.25 };
// A widened view's texels may be coarser than the fresh fit's by this share of
// InteractiveTexelRatio's margin over 1; the rest is left for the camera's next
// moves, so that the view is not refitted at once (in the drags measured, the
// side room ended most kept views, not their texels).
constexpr double WidenedShareOfTexelMargin = 0.75;

// Whether `view` serves `frame` as `fresh`, the frame's own fit, would: over
// the visible scene of frame's camera, with texels at most `texelRatio` times
// fresh's.
bool ServesAsFreshFit(const ShadowFrame& frame, const ShadowLight& light, const LightView& view,
  const LightView& fresh, double texelRatio)
{
  shadowmaps::LightRays rays;
  rays.Positional = light.Kind != shadowmaps::LightKind::Directional;
  rays.Position = light.Position;
  rays.Direction = light.Direction;
  rays.ConeAngleDegrees = light.ConeAngle;
  // The filter's taps, and about a texel of normal offset.
  return shadowmaps::KeptViewServes(view, fresh, frame.CameraViewProjection(), frame.SceneBounds,
    rays, frame.Resolution, texelRatio, frame.FilterReachTexels + 1.0);
}

// The fit by `fit` of the widest of a few widened cameras that `accept` takes.
std::optional<LightView> FitForNearbyCameras(const ShadowFrame& frame,
  const std::function<LightView(const ShadowFrame&)>& fit,
  const std::function<bool(const LightView&)>& accept)
{
  for (const ShadowFrame& wider : vtkShadowMapViews::WidenedFrames(frame))
  {
    const LightView view = fit(wider);
    if (shadowmaps::IsFinite(view.ViewProjection()) && accept(view))
    {
      return view;
    }
  }
  return std::nullopt;
}
} // namespace

//------------------------------------------------------------------------------
std::vector<ShadowFrame> vtkShadowMapViews::WidenedFrames(const ShadowFrame& frame)
{
  std::vector<ShadowFrame> frames;
  const double nearest =
    shadowmaps::TightDepthRange(frame.CameraView, frame.CameraProjection, frame.PropBounds, 0.01).x;
  for (const double share : WidenedShares)
  {
    const shadowmaps::Camera widened =
      shadowmaps::WidenedCamera({ frame.CameraView, frame.CameraProjection },
        share * WidenedBackwardPerNearDepth * nearest, share * WidenedTurnDegrees);
    if (widened.Projection == frame.CameraProjection)
    {
      break; // a parallel projection, or no visible depth to widen by
    }
    frames.push_back(frame);
    frames.back().CameraView = widened.View;
    frames.back().CameraProjection = widened.Projection;
  }
  return frames;
}

//------------------------------------------------------------------------------
double vtkShadowMapViews::WidenedTexelRatio() const
{
  return 1.0 + WidenedShareOfTexelMargin * (this->InteractiveTexelRatio - 1.0);
}

//------------------------------------------------------------------------------
void vtkShadowMapViews::FitUniformViews(const ShadowFrame& frame, ShadowLight& light)
{
  light.Views.clear();
  if (shadowmaps::NeedsCubeFaces(light))
  {
    light.Layout = shadowmaps::ViewLayout::CubeFaces;
    const auto faces = shadowmaps::FitCubeFacesToView(
      frame.CameraViewProjection(), frame.SceneBounds, light.Position, frame.Resolution);
    light.Views.assign(faces.begin(), faces.end());
    return;
  }
  light.Layout = shadowmaps::ViewLayout::Single;
  if (light.Kind == shadowmaps::LightKind::Spot)
  {
    light.Views.push_back(shadowmaps::FitSpot(frame.CameraViewProjection(), frame.SceneBounds,
      light.Position, light.Direction, light.ConeAngle, frame.Resolution, true));
    return;
  }
  light.Views.push_back(shadowmaps::FitDirectional(
    frame.CameraViewProjection(), frame.SceneBounds, light.Direction, frame.Resolution, true));
}

//------------------------------------------------------------------------------
bool vtkShadowMapViews::MayKeepViews(const ShadowFrame& frame) const
{
  return (frame.Interactive || frame.StillKeepsViews) && this->InteractiveTexelRatio > 1.0;
}

//------------------------------------------------------------------------------
LightView vtkShadowMapViews::InteractiveView(const ShadowFrame& frame, const ShadowLight& light,
  const LightView& fresh, const LightView* last, const ViewFit& fit) const
{
  if (!this->MayKeepViews(frame))
  {
    return fresh;
  }
  const auto serves = [&](const LightView& view, double texelRatio) {
    return ServesAsFreshFit(frame, light, view, fresh, texelRatio);
  };
  if (last && serves(*last, this->InteractiveTexelRatio))
  {
    return *last;
  }
  if (!fit)
  {
    return fresh;
  }
  const double widenedRatio = this->WidenedTexelRatio();
  const auto accept = [&](const LightView& view) { return serves(view, widenedRatio); };
  return FitForNearbyCameras(frame, fit, accept).value_or(fresh);
}

//------------------------------------------------------------------------------
const char* vtkShadowMapViews::GetKindName(const shadowmaps::ShadowLight& light) const
{
  switch (light.Layout)
  {
    case shadowmaps::ViewLayout::CubeFaces:
      return "cube faces";
    case shadowmaps::ViewLayout::PerspectiveCube:
      return "psm-cube";
    case shadowmaps::ViewLayout::Cascades:
      return "cascades";
    case shadowmaps::ViewLayout::Tiles:
      return "tiles";
    default:
      return this->GetSingleMapKindName(light);
  }
}

//------------------------------------------------------------------------------
void vtkShadowMapViews::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InteractiveTexelRatio: " << this->InteractiveTexelRatio << "\n";
}
