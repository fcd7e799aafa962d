// How a frame's maps store their texels: the representation's wish
// (MapStorage, vtkShadowMapRepresentation::GetMapStorage) completed with what
// this frame's views, casters and processes allow, and what that storage needs
// of the maps besides their layers. Decides only; the pass allocates. Not a
// VTK class.
#ifndef ShadowMapStorageChoice_h
#define ShadowMapStorageChoice_h

#include "ShadowMapCombination.h"  // For Combination
#include "ShadowMapLight.h"        // For ShadowLight
#include "ShadowMapSceneReading.h" // For Caster

#include <vector>

namespace shadowmaps
{
class ClosedCasters;
struct MapStorage;

/// What besides the views and casters the choice depends on.
struct StorageLimits
{
  /// The processes combine their maps (vtkShadowMapExchange): they must all
  /// make them the same way, and light depths are combined, not samples.
  bool CombinesAcrossProcesses = false;
  /// The maps now hold 32-bit depths (a hysteresis for the 16-bit rule).
  bool ThirtyTwoBitDepthNow = false;
  /// The most samples the GL offers per texel.
  int MaximumSamples = 1;
};

/// Completes `storage`, as the representation asked for it: the way a second
/// depth is made (AUTO: front and back faces where every caster is closed,
/// else peeling), 16-bit depth where every view in view is precise enough,
/// the light depth only for maps of one value, and the samples.
void CompleteStorage(MapStorage& storage, const std::vector<ShadowLight>& lights,
  const std::vector<Caster>& casters, ClosedCasters& closedCasters, const StorageLimits& limits);

/// Caster passes per layer: 2 for peeled two-surface maps, else 1.
int CasterPassesPerLayer(const MapStorage& storage);

bool AnyLinearDepthView(const std::vector<ShadowLight>& lights);

/// Whether the maps need their second output: peeled two-surface maps, value
/// maps whose light depths are combined, and linear-depth views of depth maps.
bool NeedsSecondOutput(
  const MapStorage& storage, Combination combination, const std::vector<ShadowLight>& lights);
} // namespace shadowmaps

#endif
