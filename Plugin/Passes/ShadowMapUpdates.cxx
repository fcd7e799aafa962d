#include "ShadowMapUpdates.h"

#include "ShadowMapCascades.h"
#include "ShadowMapCasterReach.h"
#include "ShadowMapFocusing.h"

#include "vtkLight.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>

namespace shadowmaps
{
namespace
{
// The bits of a value, so that signatures follow values rather than identities
// or modification times (image-processing passes hand their delegate a fresh
// copy of the camera every frame).
void AppendBits(double value, std::vector<vtkMTimeType>& bits)
{
  vtkMTimeType word = 0;
  std::memcpy(&word, &value, sizeof(double));
  bits.push_back(word);
}

void AppendBoxBits(const Aabb& box, std::vector<vtkMTimeType>& bits)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    AppendBits(box.Min[axis], bits);
    AppendBits(box.Max[axis], bits);
  }
}

void AppendMatrixBits(const glm::dmat4& m, std::vector<vtkMTimeType>& bits)
{
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      AppendBits(m[c][r], bits);
    }
  }
}

bool FrustumMeetsBox(const std::vector<Plane>& planes, const Aabb& box)
{
  for (const auto& plane : planes)
  {
    const glm::dvec3 farthest(plane.Normal.x >= 0.0 ? box.Max.x : box.Min.x,
      plane.Normal.y >= 0.0 ? box.Max.y : box.Min.y, plane.Normal.z >= 0.0 ? box.Max.z : box.Min.z);
    if (plane.Distance(farthest) < 0.0)
    {
      return false;
    }
  }
  return true;
}

// The part of `visible` (the focus body; empty when culling is off) whose
// receivers `view` shades: a cascade's slice of it.
std::vector<glm::dvec3> ShadedBody(
  const ShadowFrame& frame, const LightView& view, const std::vector<glm::dvec3>& visible)
{
  const glm::dvec2 depths = view.ShadedDepths;
  if (visible.empty() || !std::isfinite(depths.y))
  {
    return visible;
  }
  const glm::dmat4 slice = SubFrustumProjection(frame.CameraProjection, depths.x, depths.y);
  return IntersectFrustumWithBox(slice * frame.CameraView, frame.SceneBounds);
}

// The world-space size of the coarsest texel of `view` over `body` (the one the
// receivers' normal offset is scaled by); infinite when it varies beyond a
// formula (warped maps), which turns the culling off.
double CoarsestTexel(const ShadowLight& light, const LightView& view, const std::vector<glm::dvec3>& body)
{
  if (view.TexelSizeFromGradient)
  {
    return std::numeric_limits<double>::infinity();
  }
  double farthest = 0.0;
  for (const auto& p : body)
  {
    farthest = std::max(farthest, glm::length(p - light.Position));
  }
  return view.TexelConstant + view.TexelPerUnitDistance * farthest;
}

// How far beyond where they are the receivers of view `index` of `light` look
// its map up, in world units: the filter's taps (sized by the light's first
// view in cascades, whose kernels keep their world size), the normal offset,
// and a texel for rounding.
double ReachMargin(const ShadowLight& light, size_t index, const std::vector<glm::dvec3>& body,
  double filterReachTexels, double normalOffsetTexels)
{
  const double texel = CoarsestTexel(light, light.Views[index], body);
  const double first = CoarsestTexel(light, light.Views.front(), body);
  if (light.Size > 0.0)
  {
    // A sized light's soft kernels have a world size of their own, as wide as
    // the largest penumbra: every caster in the view may reach a receiver.
    return std::numeric_limits<double>::infinity();
  }
  return filterReachTexels * std::max(texel, first) + (normalOffsetTexels + 1.0) * texel;
}

// The casters inside the view's frustum, or nearer the light than its near
// plane: casters draw with depth clamping (CasterGLState), which keeps those
// on the near plane, where they still shadow everything behind them.
std::vector<const Caster*> CastersInView(const std::vector<Caster>& all, const LightView& view)
{
  std::vector<const Caster*> casters;
  if (view.OutOfView)
  {
    return casters;
  }
  const std::array<Plane, 6> frustum = FrustumPlanes(view.ViewProjection());
  constexpr std::size_t Near = 4; // FrustumPlanes: -x, +x, -y, +y, near, far
  std::vector<Plane> planes;
  for (std::size_t i = 0; i < frustum.size(); ++i)
  {
    if (i != Near)
    {
      planes.push_back(frustum[i]);
    }
  }
  for (const auto& caster : all)
  {
    if (FrustumMeetsBox(planes, caster.Bounds))
    {
      casters.push_back(&caster);
    }
  }
  return casters;
}

// Those of `inView` whose shadows may reach `visible`, the focus body (empty:
// no culling by it), looked up up to `margin` beyond it.
std::vector<const Caster*> CastersReaching(const std::vector<const Caster*>& inView,
  const LightView& view, const std::vector<glm::dvec3>& visible, double margin)
{
  const glm::dmat4 viewProjection = view.ViewProjection();
  const ShadowReach reach = ReachOfBody(viewProjection, visible, margin);
  std::vector<const Caster*> casters;
  std::copy_if(inView.begin(), inView.end(), std::back_inserter(casters),
    [&](const Caster* c) { return MayShadowInto(reach, viewProjection, c->Bounds); });
  return casters;
}

// What a layer's texels depend on of its view besides the layers' key: its
// matrices, its light's depth (stored by light-depth maps) and, where the
// representation's post-processing follows it, its FilterScale (a cascade's
// blur follows the first cascade's texels, which may change while this one's
// matrices stay).
std::vector<vtkMTimeType> LayerViewBits(
  const ShadowLight& light, std::size_t index, bool postProcessingFollowsFilterScale)
{
  const LightView& view = light.Views[index];
  std::vector<vtkMTimeType> bits;
  if (postProcessingFollowsFilterScale)
  {
    AppendBits(FilterScale(light, index), bits);
  }
  AppendMatrixBits(view.View, bits);
  AppendMatrixBits(view.Projection, bits);
  const LightDepth& depth = light.Depth;
  for (double value : { depth.Plane.x, depth.Plane.y, depth.Plane.z, depth.Plane.w,
         depth.PerDistance, depth.Origin.x, depth.Origin.y, depth.Origin.z })
  {
    AppendBits(value, bits);
  }
  bits.push_back(view.OutOfView ? 1 : 0);
  bits.push_back(view.LinearDepth ? 1 : 0);
  return bits;
}

std::vector<CasterStamp> StampsOf(const std::vector<const Caster*>& casters)
{
  std::vector<CasterStamp> stamps;
  stamps.reserve(casters.size());
  for (const Caster* caster : casters)
  {
    stamps.push_back({ caster->Prop, caster->Version });
  }
  return stamps;
}
} // namespace

//------------------------------------------------------------------------------
MapSignature MapUpdates::Signature(const MapInputs& inputs, const ShadowFrame& frame,
  const std::vector<ShadowLight>& lights, const std::vector<Caster>& casters)
{
  MapSignature whole;
  whole.CameraProjection = frame.CameraProjection;
  std::vector<vtkMTimeType>& signature = whole.Words;
  signature = { inputs.PassTime, inputs.LightsTime, inputs.PropsTime,
    static_cast<vtkMTimeType>(inputs.ViewportWidth), static_cast<vtkMTimeType>(inputs.ViewportHeight) };
  AppendMatrixBits(frame.CameraView, signature);
  // The fits and the casters' reach follow every prop's bounds, receivers'
  // too (every process's, with an exchange).
  for (const Aabb& box : frame.PropBounds)
  {
    AppendBoxBits(box, signature);
  }
  AppendBoxBits(frame.SceneBounds, signature);
  // A still render after interactive ones fits anew what they may have kept.
  signature.push_back(frame.Interactive ? 1 : 0);
  for (const auto& light : lights)
  {
    signature.push_back(reinterpret_cast<vtkMTimeType>(light.Light));
    signature.push_back(light.Light->GetMTime());
    // A light's MTime does not follow its information (LIGHT_SIZE).
    AppendBits(light.Size, signature);
  }
  for (const auto& caster : casters)
  {
    signature.push_back(reinterpret_cast<vtkMTimeType>(caster.Prop));
    signature.push_back(caster.Version);
  }
  return whole;
}

//------------------------------------------------------------------------------
bool MapSignature::Matches(const MapSignature& other) const
{
  // Each entry within a ten-millionth of itself, far below anything a zoom
  // changes (a 4096-texel map would move by a 2,000th of a texel); relative
  // only, since a parallel camera's entries scale with the inverse of its
  // size. The view's translation is in world units, whose scale this does not
  // know: it is compared bit for bit, with the rest (Words).
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      const double a = this->CameraProjection[c][r];
      const double b = other.CameraProjection[c][r];
      if (!(std::abs(a - b) <= 1e-7 * std::max(std::abs(a), std::abs(b))))
      {
        return false;
      }
    }
  }
  return this->Words == other.Words;
}

//------------------------------------------------------------------------------
bool MapUpdates::TakeShaderIndices(const std::vector<ShadowLight>& collected)
{
  bool moved = false;
  for (ShadowLight& light : this->RenderedLights)
  {
    auto same = std::find_if(collected.begin(), collected.end(),
      [&light](const ShadowLight& other) { return other.Light == light.Light; });
    if (same != collected.end() && same->ShaderIndex != light.ShaderIndex)
    {
      light.ShaderIndex = same->ShaderIndex;
      moved = true;
    }
  }
  return moved;
}

//------------------------------------------------------------------------------
bool MapUpdates::Current(const MapSignature& signature) const
{
  return !this->RenderedSignature.Empty() && signature.Matches(this->RenderedSignature);
}

//------------------------------------------------------------------------------
void MapUpdates::Invalidate()
{
  this->RenderedSignature = MapSignature();
  this->Layers.clear();
  this->LayersDrawnInDrag.clear();
  this->RenderedLights.clear();
}

//------------------------------------------------------------------------------
const ShadowLight* MapUpdates::KeptLight(
  const ShadowLight& light, vtkMTimeType passTime, int resolution, const Aabb& sceneBounds) const
{
  const bool onlyTheCameraMoved = this->RenderedPassTime == passTime &&
    this->RenderedResolution == resolution && this->RenderedSceneBounds.Min == sceneBounds.Min &&
    this->RenderedSceneBounds.Max == sceneBounds.Max;
  if (!onlyTheCameraMoved)
  {
    return nullptr;
  }
  for (const ShadowLight& rendered : this->RenderedLights)
  {
    if (rendered.Light == light.Light && rendered.Kind == light.Kind &&
      rendered.Position == light.Position && rendered.Direction == light.Direction &&
      rendered.ConeAngle == light.ConeAngle)
    {
      return &rendered;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
std::vector<LightView> MapUpdates::KeptViews(
  const ShadowLight& light, vtkMTimeType passTime, int resolution, const Aabb& sceneBounds) const
{
  const ShadowLight* kept = this->KeptLight(light, passTime, resolution, sceneBounds);
  return kept ? kept->Views : std::vector<LightView>{};
}

//------------------------------------------------------------------------------
void MapUpdates::BeginUpdate(const std::vector<vtkMTimeType>& layersKey, int layers, bool combined,
  const std::vector<Caster>& casters)
{
  this->RenderedSignature = MapSignature();
  if (layersKey != this->LayersKey || combined)
  {
    this->LayersKey = layersKey;
    this->Layers.clear();
    this->LayersDrawnInDrag.clear();
  }
  this->Layers.resize(static_cast<size_t>(std::max(layers, 0)));
  this->LayersDrawnInDrag.resize(this->Layers.size(), false);
  std::vector<CasterStamp> stamps;
  stamps.reserve(casters.size());
  for (const Caster& caster : casters)
  {
    stamps.push_back({ caster.Prop, caster.Version });
  }
  this->CurrentCasters = SortedByProp(std::move(stamps));
  // Which casters a view holds follows their bounds too, and only an actor's
  // bounds are known to follow its version (PropRecords).
  std::vector<vtkMTimeType> castersKey;
  castersKey.reserve(8 * casters.size());
  for (const Caster& caster : casters)
  {
    castersKey.push_back(static_cast<vtkMTimeType>(reinterpret_cast<std::uintptr_t>(caster.Prop)));
    castersKey.push_back(caster.Version);
    AppendBoxBits(caster.Bounds, castersKey);
  }
  if (castersKey != this->CastersKey)
  {
    this->CastersKey = std::move(castersKey);
    ++this->CastersGeneration;
  }
}

//------------------------------------------------------------------------------
LayerPlan MapUpdates::Plan(
  const ShadowFrame& frame, const std::vector<Caster>& casters, const LayerRequest& request) const
{
  const ShadowLight& light = *request.Light;
  const LightView& view = light.Views[request.View];
  LayerPlan plan;
  plan.ViewBits = LayerViewBits(light, request.View, request.PostProcessingFollowsFilterScale);
  plan.DrawnInDrag = frame.Interactive;
  // Levels of detail drawn during a drag (vtkLODActor's, ParaView's) are
  // chosen by time, which no caster version records: a still frame does not
  // keep a layer drawn in a drag.
  const bool dragged = this->LayersDrawnInDrag[request.Layer] && !frame.Interactive;
  const LayerContent& content = this->Layers[request.Layer];
  // A drag's kept views: no caster to sort out.
  if (!dragged && content.HoldsEveryCasterInView(plan.ViewBits, this->CastersGeneration))
  {
    return plan;
  }
  const std::vector<glm::dvec3> shaded = ShadedBody(frame, view, *request.Visible);
  const std::vector<const Caster*> inView = CastersInView(casters, view);
  const std::vector<const Caster*> needed = CastersReaching(inView, view, shaded,
    ReachMargin(light, request.View, shaded, frame.FilterReachTexels, request.NormalOffsetTexels));
  if (!dragged &&
    content.Holds(plan.ViewBits, StampsOf(needed), this->CurrentCasters, this->CastersGeneration))
  {
    return plan;
  }
  // While the user drags, views stay put as the camera turns (kept, or
  // snapped to a grid): a layer rendered then takes every caster in its view,
  // so that casters the camera brings into reach later in the drag are
  // already drawn.
  const std::vector<const Caster*>& drawn = request.DrawsAllInView ? inView : needed;
  plan.DrawsEveryCasterInView = request.DrawsAllInView;
  plan.Render = true;
  plan.Drawn = StampsOf(drawn);
  std::transform(drawn.begin(), drawn.end(), std::back_inserter(plan.Casters),
    [](const Caster* caster) { return caster->Prop; });
  return plan;
}

//------------------------------------------------------------------------------
void MapUpdates::Rendered(int layer, LayerPlan plan)
{
  this->LayersDrawnInDrag[layer] = plan.DrawnInDrag;
  this->Layers[layer] = LayerContent(std::move(plan.ViewBits), std::move(plan.Drawn),
    this->CastersGeneration, plan.DrawsEveryCasterInView);
}

//------------------------------------------------------------------------------
void MapUpdates::Finish(const std::vector<ShadowLight>& lights, MapSignature signature,
  vtkMTimeType passTime, int resolution, const Aabb& sceneBounds)
{
  this->RenderedLights = lights;
  this->RenderedSignature = std::move(signature);
  this->RenderedPassTime = passTime;
  this->RenderedResolution = resolution;
  this->RenderedSceneBounds = sceneBounds;
}
} // namespace shadowmaps
