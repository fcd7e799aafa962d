#include "ShadowMapStorageChoice.h"

#include "ShadowMapClosedSurfaces.h"
#include "ShadowMapFocusing.h"
#include "ShadowMapTextureArray.h"
#include "vtkShadowMapRepresentation.h"

#include <algorithm>
#include <utility>

namespace shadowmaps
{
namespace
{
// Views out of view hold no shadows, whatever their precision. Depth maps that
// are 32-bit go to 16 bits only with twice the margin, so that a camera hovering
// at the threshold does not reallocate the maps, and move the shadows' contacts
// by the bias of the other format, every frame. Maps not allocated (new, or
// released after a GL failure) and value maps take the 16-bit rule.
bool EveryViewFitsSixteenBits(const std::vector<ShadowLight>& lights, bool thirtyTwoBitNow)
{
  const double stepsPerTexel = thirtyTwoBitNow ? 32.0 : 16.0;
  return std::all_of(lights.begin(), lights.end(), [&](const ShadowLight& light) {
    return std::all_of(light.Views.begin(), light.Views.end(), [&](const LightView& view) {
      return view.OutOfView || SixteenBitDepthSuffices(view, stepsPerTexel);
    });
  });
}

void ChooseSecondDepthMethod(MapStorage& storage, const std::vector<Caster>& casters,
  ClosedCasters& closedCasters, bool combinesAcrossProcesses)
{
  if (storage.Format != TexelFormat::TwoFloats)
  {
    storage.SecondDepth = SecondDepthMethod::None;
  }
  if (storage.SecondDepth == SecondDepthMethod::Auto)
  {
    std::vector<std::pair<vtkProp*, vtkMTimeType>> versions;
    versions.reserve(casters.size());
    for (const Caster& caster : casters)
    {
      if (caster.Opaque)
      {
        versions.emplace_back(caster.Prop, caster.Version);
      }
    }
    // Processes that combine their maps must make them the same way, and
    // peeling is right whatever each one's casters are.
    storage.SecondDepth = !combinesAcrossProcesses && closedCasters.AllClosed(versions)
      ? SecondDepthMethod::FrontAndBackFaces
      : SecondDepthMethod::Peeling;
  }
  if (storage.SecondDepth != SecondDepthMethod::None)
  {
    storage.MinimumBlending = storage.SecondDepth == SecondDepthMethod::FrontAndBackFaces;
    storage.ClearValues[0] = storage.ClearValues[1] = 1.0f;
  }
}
} // namespace

//------------------------------------------------------------------------------
void CompleteStorage(MapStorage& storage, const std::vector<ShadowLight>& lights,
  const std::vector<Caster>& casters, ClosedCasters& closedCasters, const StorageLimits& limits)
{
  ChooseSecondDepthMethod(storage, casters, closedCasters, limits.CombinesAcrossProcesses);
  if (storage.Format == TexelFormat::Depth &&
    EveryViewFitsSixteenBits(lights, limits.ThirtyTwoBitDepthNow))
  {
    storage.Format = TexelFormat::Depth16;
  }
  // Depth maps store the views' own depths; two-surface maps compare them.
  const bool oneValueMap =
    !IsDepth(storage.Format) && storage.SecondDepth == SecondDepthMethod::None;
  storage.LightDepth = storage.LightDepth && oneValueMap;
  // Combined light-depth maps are rebuilt from each texel's nearest light
  // depth, not its samples.
  const bool combinesLightDepths = limits.CombinesAcrossProcesses && storage.LightDepth;
  storage.Samples = oneValueMap && !storage.MinimumBlending && !combinesLightDepths
    ? std::max(1, std::min(storage.Samples, limits.MaximumSamples))
    : 1;
}

//------------------------------------------------------------------------------
int CasterPassesPerLayer(const MapStorage& storage)
{
  return storage.SecondDepth == SecondDepthMethod::Peeling ? 2 : 1;
}

//------------------------------------------------------------------------------
bool AnyLinearDepthView(const std::vector<ShadowLight>& lights)
{
  return std::any_of(lights.begin(), lights.end(), [](const ShadowLight& light) {
    return std::any_of(light.Views.begin(), light.Views.end(),
      [](const LightView& view) { return view.LinearDepth; });
  });
}

//------------------------------------------------------------------------------
bool NeedsSecondOutput(
  const MapStorage& storage, Combination combination, const std::vector<ShadowLight>& lights)
{
  if (storage.SecondDepth == SecondDepthMethod::Peeling ||
    combination == Combination::NearestLightDepths)
  {
    return true;
  }
  return IsDepth(storage.Format) && AnyLinearDepthView(lights);
}
} // namespace shadowmaps
