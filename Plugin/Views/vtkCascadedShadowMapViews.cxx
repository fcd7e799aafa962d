#include "vtkCascadedShadowMapViews.h"

#include "ShadowMapCascades.h"
#include "ShadowMapLight.h"
#include "ShadowMapWarping.h"
#include "vtkObjectFactory.h"
#include "vtkWarpedShadowMapViews.h"

#include <algorithm>
#include <limits>
#include <cmath>

vtkStandardNewMacro(vtkCascadedShadowMapViews);

namespace
{
constexpr int MaximumCascades = 8;

// Stable cascades round the visible depth range out to levels 2^(1/4) apart.
constexpr int StableRangeStepsPerOctave = 4;

// A depth range {near, far} made usable: far beyond near, both finite.
glm::dvec2 UsableRange(glm::dvec2 range)
{
  if (!(range.y > range.x) || !std::isfinite(range.y - range.x))
  {
    range = { std::max(range.x, 0.0), std::max(range.x, 0.0) + 1.0 };
  }
  return range;
}

// The depths of what the camera sees (its near and far planes tightened to the
// visible props), and the range cascades split: the same, or for stable
// cascades widened to the nearest levels of a fixed grid, so that the splits
// do not follow every small change of the visible depth. The levels may lie
// outside the planes: interactors reset the clipping range every frame, and
// splits kept inside it moved with every camera move (re-rendering every
// cascade).
struct DepthRanges
{
  glm::dvec2 Visible;
  glm::dvec2 Split;
};
DepthRanges SplitRange(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const std::vector<shadowmaps::Aabb>& props, bool stable)
{
  const glm::dvec2 visible =
    UsableRange(shadowmaps::TightDepthRange(cameraView, cameraProjection, props));
  return { visible,
    stable ? UsableRange(shadowmaps::QuantizedDepthRange(visible, StableRangeStepsPerOctave))
           : visible };
}

// One cascade's view of a directional light.
shadowmaps::LightView FitCascade(const glm::dmat4& cameraView, const glm::dmat4& subProjection,
  const shadowmaps::Aabb& scene, int resolution, const glm::dvec3& lightDirection, int fitMode,
  int cascadeWarp)
{
  if (fitMode == vtkCascadedShadowMapViews::STABLE)
  {
    return shadowmaps::FitCascadeStable(cameraView, subProjection, scene, lightDirection, resolution);
  }
  if (cascadeWarp != vtkCascadedShadowMapViews::NO_WARP)
  {
    shadowmaps::LightView view = shadowmaps::FitDirectionalWarped(
      cameraView, subProjection, scene, lightDirection, resolution, vtkWarpedShadowMapViews::LightSpaceWarpOf(cascadeWarp));
    view.TexelSizeFromGradient = view.Perspective;
    return view;
  }
  return shadowmaps::FitCascadeTight(cameraView, subProjection, scene, lightDirection, resolution);
}
} // namespace

//------------------------------------------------------------------------------
void vtkCascadedShadowMapViews::SetNumberOfCascades(int count)
{
  const int clamped = std::min(std::max(count, 1), MaximumCascades);
  if (clamped != count)
  {
    vtkWarningMacro(<< "NumberOfCascades " << count << " is outside [1, " << MaximumCascades
                    << "]; using " << clamped << ".");
  }
  if (clamped != this->NumberOfCascades)
  {
    this->NumberOfCascades = clamped;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapViews::SetSplitLambda(double lambda)
{
  if (!vtkShadowMapsIsFiniteParameter(this, "SplitLambda", lambda, this->SplitLambda))
  {
    return;
  }
  const double clamped = std::min(std::max(lambda, 0.0), 1.0);
  if (clamped != lambda)
  {
    vtkWarningMacro(<< "SplitLambda " << lambda << " is outside [0, 1]; using " << clamped << ".");
  }
  if (clamped != this->SplitLambda)
  {
    this->SplitLambda = clamped;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapViews::AddSplitDistance(double distance)
{
  if (!vtkShadowMapsIsFiniteParameter(this, "SplitDistance", distance))
  {
    return;
  }
  this->SplitDistances.push_back(distance);
  this->SplitProblemReported = false;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapViews::RemoveAllSplitDistances()
{
  if (!this->SplitDistances.empty())
  {
    this->SplitDistances.clear();
    this->SplitProblemReported = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
double vtkCascadedShadowMapViews::GetSplit(int i) const
{
  return i >= 0 && i < static_cast<int>(this->LastSplits.size()) ? this->LastSplits[i] : 0.0;
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapViews::SetMaximumShadowDistance(double distance)
{
  if (!vtkShadowMapsIsFiniteParameter(
        this, "MaximumShadowDistance", distance, this->MaximumShadowDistance))
  {
    return;
  }
  const double clamped = distance > 0.0 ? distance : 0.0;
  if (clamped != distance)
  {
    vtkWarningMacro(<< "MaximumShadowDistance " << distance
                    << " is not a positive distance; using the visible depth (0).");
  }
  if (clamped != this->MaximumShadowDistance)
  {
    this->MaximumShadowDistance = clamped;
    this->SplitProblemReported = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::vector<double> vtkCascadedShadowMapViews::ComputeSplits(
  const shadowmaps::ShadowFrame& in, double fade[2])
{
  const DepthRanges ranges =
    SplitRange(in.CameraView, in.CameraProjection, in.PropBounds, this->FitMode == STABLE);
  glm::dvec2 range = ranges.Split;
  std::string problem;
  fade[0] = fade[1] = 0.0;
  // Decided on what is visible: the rounded range must not make shadows fade
  // (or stop) in view, nor switch a fade on and off as it steps.
  const double maximum = this->MaximumShadowDistance;
  if (maximum > 0.0)
  {
    if (maximum <= ranges.Visible.x)
    {
      problem = "MaximumShadowDistance is not beyond the nearest visible depth; shadows end there.";
      range.y = range.x * (1.0 + 1e-6) + 1e-9;
    }
    else if (maximum < ranges.Visible.y)
    {
      range.y = maximum;
      if (this->FadeFraction > 0.0)
      {
        fade[0] = range.y * (1.0 - this->FadeFraction);
        fade[1] = range.y;
      }
    }
    else
    {
      range.y = std::min(range.y, maximum);
    }
  }

  std::vector<double> splits;
  if (this->SplitDistances.empty())
  {
    splits = shadowmaps::PracticalSplits(range.x, range.y, this->NumberOfCascades, this->SplitLambda);
  }
  else
  {
    std::string splitProblem;
    splits = shadowmaps::SanitizeSplits(this->SplitDistances, range.x, range.y, &splitProblem);
    if (!splitProblem.empty())
    {
      problem += (problem.empty() ? "" : " ") + splitProblem;
    }
    if (static_cast<int>(splits.size()) > MaximumCascades + 1)
    {
      splits.erase(splits.begin() + MaximumCascades, splits.end() - 1);
      problem += " More than " + std::to_string(MaximumCascades) + " cascades; the last ones are merged.";
    }
  }
  // Once per setting: the repaired values depend on the visible depth, which
  // changes from frame to frame.
  if (!problem.empty() && !this->SplitProblemReported)
  {
    vtkWarningMacro(<< problem);
    this->SplitProblemReported = true;
  }
  return splits;
}

//------------------------------------------------------------------------------
bool vtkCascadedShadowMapViews::MayWarp() const
{
  return this->FitMode == TIGHT && this->CascadeWarp != NO_WARP;
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapViews::FitLight(
  const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light)
{
  if (shadowmaps::NeedsCubeFaces(light))
  {
    light.PossibleFeatures = 0;
    vtkShadowMapViews::FitUniformViews(frame, light);
    return;
  }
  // Warped maps store linear depth (FitWarpedFrame, FitSpotWarped). A spot's
  // tiles crop one map, warped or not; unwarped cascades share the light's
  // rotation and differ by their orthographic boxes.
  light.PossibleFeatures =
    this->MayWarp() ? shadowmaps::GradientTexels | shadowmaps::LinearDepths : 0;
  if (light.Kind == shadowmaps::LightKind::Spot || !this->MayWarp())
  {
    light.PossibleFeatures |= shadowmaps::CroppedViews;
  }
  double fade[2];
  const std::vector<double> splits = this->ComputeSplits(frame, fade);
  this->LastSplits = splits;
  light.Fade = glm::dvec2(fade[0], fade[1]);
  if (light.Kind == shadowmaps::LightKind::Spot)
  {
    this->TileSpotLight(frame, light);
    return;
  }
  this->FitCascades(frame, splits, light);
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapViews::FitCascades(const shadowmaps::ShadowFrame& frame,
  const std::vector<double>& splits, shadowmaps::ShadowLight& light) const
{
  light.Layout = shadowmaps::ViewLayout::Cascades;
  light.Views.clear();
  light.CascadeDepths.clear();
  const int cascades = static_cast<int>(splits.size()) - 1;
  const ViewFit fit = [&](const shadowmaps::ShadowFrame& in) {
    return FitCascade(in.CameraView, in.CameraProjection, in.SceneBounds, in.Resolution,
      light.Direction, this->FitMode, this->CascadeWarp);
  };
  for (int c = 0; c < cascades; ++c)
  {
    const glm::dvec2 depths = shadowmaps::CascadeDepthRange(splits, c, this->BlendFraction);
    shadowmaps::ShadowFrame sub = frame;
    sub.CameraProjection =
      shadowmaps::SubFrustumProjection(frame.CameraProjection, depths.x, depths.y);
    // A stable cascade's texel size must depend on its depth range alone: it
    // is not fitted to a widened camera.
    const bool hasLastViews = static_cast<int>(light.LastViews.size()) == cascades;
    light.Views.push_back(this->InteractiveView(sub, light, fit(sub),
      hasLastViews ? &light.LastViews[c] : nullptr, this->FitMode == STABLE ? ViewFit() : fit));
    const bool blends = this->BlendFraction > 0.0 && c + 1 < cascades;
    light.CascadeDepths.emplace_back(splits[c], splits[c + 1],
      blends ? shadowmaps::BlendBandStart(splits, c, this->BlendFraction) : shadowmaps::NoBlendBand);
    if (this->Selection == BY_DEPTH)
    {
      // From where the previous cascade starts blending into this one; the last
      // one also shades whatever lies beyond its split (unfaded).
      const double first = c > 0 && light.CascadeDepths[c - 1].z < shadowmaps::NoBlendBand
        ? light.CascadeDepths[c - 1].z
        : splits[c];
      const double last =
        c + 1 < cascades ? splits[c + 1] : std::numeric_limits<double>::infinity();
      light.Views.back().ShadedDepths = glm::dvec2(first, last);
    }
  }
  light.CoverageBlendFraction = this->Selection == BY_COVERAGE ? this->BlendFraction : -1.0;
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapViews::TileSpotLight(
  const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light) const
{
  // The cascades' layers hold one map of the cone cropped to the lit part of
  // the view, at sqrt(cascades) times the resolution: a spot's texels are
  // spread by the distance to the light, not to the camera, and one such map
  // misclassified fewer pixels than depth cascades in every benchmark scene.
  const int rows = std::max(static_cast<int>(std::sqrt(this->NumberOfCascades)), 1);
  const int columns = std::max(this->NumberOfCascades / rows, 1);
  const shadowmaps::LightView whole = this->FitSpotMap(frame, light);
  light.Layout = shadowmaps::ViewLayout::Tiles;
  light.Tiles = shadowmaps::MakeTileGrid(columns, rows, frame.Resolution, frame.FilterReachTexels);
  light.Views = shadowmaps::TileView(whole, light.Tiles);
}

//------------------------------------------------------------------------------
shadowmaps::LightView vtkCascadedShadowMapViews::FitSpotMap(
  const shadowmaps::ShadowFrame& in, const shadowmaps::ShadowLight& light) const
{
  if (this->MayWarp())
  {
    const shadowmaps::LightView warped = shadowmaps::FitSpotWarped(in.CameraView,
      in.CameraProjection, in.SceneBounds, light.Position, light.Direction, light.ConeAngle,
      in.Resolution, vtkWarpedShadowMapViews::LightSpaceWarpOf(this->CascadeWarp));
    // Where it cannot warp (parallel camera, empty body), FitSpotWarped gives the
    // cone cropped to B; the lit part of B below is tighter.
    if (warped.TexelSizeFromGradient)
    {
      return warped;
    }
  }
  // Stable cascades' tiles grow outward to a grid, as a uniform spot map does.
  return shadowmaps::FitSpotToLitBody(in.CameraViewProjection(), in.SceneBounds, light.Position,
    light.Direction, light.ConeAngle, in.Resolution, nullptr, this->FitMode == STABLE);
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapViews::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfCascades: " << this->NumberOfCascades << "\n";
  os << indent << "SplitLambda: " << this->SplitLambda << "\n";
  os << indent << "SplitDistances:";
  for (double d : this->SplitDistances)
  {
    os << " " << d;
  }
  os << "\n";
  os << indent << "MaximumShadowDistance: " << this->MaximumShadowDistance << "\n";
  os << indent << "FadeFraction: " << this->FadeFraction << "\n";
  os << indent << "BlendFraction: " << this->BlendFraction << "\n";
  os << indent << "FitMode: " << this->FitMode << "\n";
  os << indent << "CascadeWarp: " << this->CascadeWarp << "\n";
  os << indent << "Selection: " << this->Selection << "\n";
}
