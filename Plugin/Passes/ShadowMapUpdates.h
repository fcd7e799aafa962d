// The frame-to-frame policy of one renderer's maps (the rest of the pass only
// renders what it decides): whether the maps still show what a frame needs,
// which views to keep while only the camera moves, and, per layer, whether it
// must be rendered again and with which casters (those whose shadows can reach
// the view's receivers; every caster in view during a drag). Holds no GL
// object and no VTK state. Not a VTK class.
#ifndef ShadowMapUpdates_h
#define ShadowMapUpdates_h

#include "ShadowMapLayerContent.h"
#include "ShadowMapLight.h"
#include "ShadowMapSceneReading.h" // For Caster

#include "vtkType.h"

#include <vector>

class vtkProp;

namespace shadowmaps
{
/// What, besides the frame, decides whether maps must be rendered again.
struct MapInputs
{
  /// The pass's and its strategies' modification time.
  vtkMTimeType PassTime = 0;
  /// The renderer's lights' and props' collections' modification times.
  vtkMTimeType LightsTime = 0;
  vtkMTimeType PropsTime = 0;
  int ViewportWidth = 0;
  int ViewportHeight = 0;
};

/// How one layer's casters are chosen.
struct LayerRequest
{
  int Layer = 0;
  const ShadowLight* Light = nullptr;
  std::size_t View = 0;
  /// The focus body the receivers lie in (empty: no reach culling).
  const std::vector<glm::dvec3>* Visible = nullptr;
  double NormalOffsetTexels = 1.0;
  /// The representation's blur follows the view's filter scale.
  bool PostProcessingFollowsFilterScale = false;
  /// While the user drags: draw every caster in view (see MapUpdates::Plan).
  bool DrawsAllInView = false;
};

/// A layer to render: the casters to draw, and what the layer will then hold.
struct LayerPlan
{
  bool Render = false;
  std::vector<vtkProp*> Casters;
  std::vector<vtkMTimeType> ViewBits;
  std::vector<CasterStamp> Drawn;
  bool DrawnInDrag = false;
  bool DrawsEveryCasterInView = false;
};

/// What the maps of a frame depend on: the camera's projection, and the bits
/// of everything else. The projection is compared within a ten-millionth: a
/// capture of a renderer that fills part of the window
/// (vtkWindowToImageFilter) derives it by another path, which differs by
/// about 5e-9.
struct MapSignature
{
  std::vector<vtkMTimeType> Words;
  glm::dmat4 CameraProjection{ 0.0 };

  /// Whether `other` is this signature, its projection within a ten-millionth.
  bool Matches(const MapSignature& other) const;
  bool Empty() const { return this->Words.empty(); }
};

class MapUpdates
{
public:
  /// The signature of everything the maps of `frame` depend on.
  static MapSignature Signature(const MapInputs& inputs, const ShadowFrame& frame,
    const std::vector<ShadowLight>& lights, const std::vector<Caster>& casters);

  /// Whether the maps were rendered for `signature` and are still there.
  bool Current(const MapSignature& signature) const;

  /// The maps are gone (released, or a GL failure): everything is rendered anew.
  void Invalidate();

  /// `light` as it was last rendered, where only the camera moved since (its
  /// views are ShadowLight::LastViews), else null.
  const ShadowLight* KeptLight(
    const ShadowLight& light, vtkMTimeType passTime, int resolution, const Aabb& sceneBounds) const;

  /// The views of KeptLight, else none.
  std::vector<LightView> KeptViews(
    const ShadowLight& light, vtkMTimeType passTime, int resolution, const Aabb& sceneBounds) const;

  /// Starts rendering `layers` layers of `casters`: forgets every layer when
  /// `layersKey` (what all of them depend on) changed, or when the layers hold
  /// a combination of several processes' casters (`combined`).
  void BeginUpdate(const std::vector<vtkMTimeType>& layersKey, int layers, bool combined,
    const std::vector<Caster>& casters);

  /// Whether the request's layer must be rendered, and with which casters.
  LayerPlan Plan(const ShadowFrame& frame, const std::vector<Caster>& casters,
    const LayerRequest& request) const;

  /// The layer now holds what `plan` drew.
  void Rendered(int layer, LayerPlan plan);

  /// The update finished: the maps show `lights` for `signature`.
  void Finish(const std::vector<ShadowLight>& lights, MapSignature signature,
    vtkMTimeType passTime, int resolution, const Aabb& sceneBounds);

  /// The lights and views the maps were last rendered for.
  const std::vector<ShadowLight>& GetRenderedLights() const { return this->RenderedLights; }

  /// Gives each rendered light the shader index (its place among the
  /// renderer's lights) of the light of `collected` it is: switching another
  /// light moves it. Whether any moved.
  bool TakeShaderIndices(const std::vector<ShadowLight>& collected);

private:
  MapSignature RenderedSignature; // empty: to be rendered
  std::vector<LayerContent> Layers;
  std::vector<bool> LayersDrawnInDrag;
  std::vector<vtkMTimeType> LayersKey;
  std::vector<CasterStamp> CurrentCasters; // SortedByProp, this update's
  // Moves on whenever a caster, its version or its bounds change.
  std::vector<vtkMTimeType> CastersKey;
  unsigned long long CastersGeneration = 0;
  std::vector<ShadowLight> RenderedLights;
  vtkMTimeType RenderedPassTime = 0;
  int RenderedResolution = 0;
  Aabb RenderedSceneBounds;
};
} // namespace shadowmaps

#endif
