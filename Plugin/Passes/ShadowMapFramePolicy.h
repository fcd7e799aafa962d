// What a pass renders each frame, and across processes (Filament's
// ShadowMapManager keeps this apart from the maps' math, as this keeps it
// apart from the pass that renders): on every process the frame starts with
// the processes' props and their agreement (all interactive? any translucent
// caster?); the maps' signature decides whether they must be rendered (here
// or on any process); each layer's request carries the frame's rules (reach
// culling's receivers, the drag rule, the filter's reach) to MapUpdates, which
// keeps what each layer holds; after rendering, the processes' maps are
// combined. The pass asks; this decides. Holds no GL object. Not a VTK class.
#ifndef ShadowMapFramePolicy_h
#define ShadowMapFramePolicy_h

#include "ShadowMapCombination.h" // For Combination
#include "ShadowMapUpdates.h"     // For LayerRequest, MapUpdates

#include "vtkShadowMapExchange.h" // For vtkWeakPointer<vtkShadowMapExchange>
#include "vtkType.h"                // For vtkMTimeType
#include "vtkWeakPointer.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkRenderer;

namespace shadowmaps
{
struct MapStorage;
struct RendererMaps;

/// What a frame's layers follow besides their views.
struct LayerRules
{
  /// Reach culling: casters are drawn into a layer only where their shadows
  /// can reach the receivers in view.
  bool ReachCulling = true;
  /// The views' strategy may keep views while the user drags
  /// (vtkShadowMapViews::MayKeepViews).
  bool ViewsMayBeKept = false;
  double NormalOffsetTexels = 1.0;
  /// The representation's blur follows the view's filter scale.
  bool PostProcessingFollowsFilterScale = false;
};

class FramePolicy
{
public:
  /// The exchange of a parallel renderer; null: one process.
  void SetExchange(vtkShadowMapExchange* exchange) { this->Exchange = exchange; }

  /// Starts a frame with shadowed lights, on every process alike: the fits see
  /// every process's props (frame.PropBounds, and the scene bounds unless
  /// `sceneBoundsGiven`); frame.Interactive holds only if it does on every
  /// process. Returns whether some caster, here or on any process, draws
  /// into the transmittance maps (all then make them).
  bool BeginFrame(ShadowFrame& frame, const std::vector<Caster>& casters, bool sceneBoundsGiven);

  /// The signature of everything `renderer`'s maps depend on for this frame
  /// (`passTime`: the pass's and its strategies' modification time).
  static MapSignature Signature(vtkRenderer* renderer, vtkMTimeType passTime,
    const ShadowFrame& frame, const std::vector<ShadowLight>& lights,
    const std::vector<Caster>& casters);

  /// Whether the maps must be rendered for `signature`: they do not hold it
  /// here, or on some other process (asked every frame: another process's
  /// casters may have moved).
  bool MustRender(const MapUpdates& updates, const MapSignature& signature) const;

  /// Whether `here` holds on this process or on any other (every process
  /// asks, in the same order): decisions every process must take alike, such
  /// as drawing a drag's layers coarser when any process draws one.
  bool AnyProcess(bool here) const;

  /// How the processes' maps of `storage` combine (None on one process).
  Combination CombinationFor(const MapStorage& storage) const;

  /// Whether the processes' layers of `storage` are combined (their maps, or
  /// their transmittance maps): a layer then holds every process's casters,
  /// and every layer is rendered and combined anew at each update (a kept
  /// one would be combined twice).
  bool CombinesLayers(const MapStorage& storage) const;

  /// Starts an update of the maps: the rules its layers follow.
  void BeginLayers(const ShadowFrame& frame, const MapStorage& storage, const LayerRules& rules);

  /// The request for one layer: view `view` of `light`.
  LayerRequest RequestFor(const ShadowLight& light, std::size_t view) const;

  /// After an update, on every process, whether or not it rendered (`ok`):
  /// false on all if any failed or their maps' shapes differ (resolution,
  /// layers, storage); else the processes' maps of `layers` layers combined,
  /// and their transmittance maps. False with `error` when they cannot be
  /// combined.
  bool Combine(vtkOpenGLRenderWindow* window, RendererMaps& maps, int layers, int resolution,
    bool ok, std::string& error);

  /// What the frame's decisions had to warn about, each once while its cause
  /// lasts; emptied by the call.
  std::vector<std::string> TakeWarnings();

private:
  void WarnOnce(bool cause, bool& warned, const std::string& warning);

  vtkWeakPointer<vtkShadowMapExchange> Exchange;
  // This update's rules, and the receivers' body in view (reach culling).
  LayerRules Rules;
  std::vector<glm::dvec3> Visible;
  bool DrawsAllInView = false;
  std::vector<std::string> Warnings;
  bool WarnedUngatheredBounds = false;
  bool WarnedUncombined = false;
  bool WarnedUnmultiplied = false;
};
} // namespace shadowmaps

#endif
