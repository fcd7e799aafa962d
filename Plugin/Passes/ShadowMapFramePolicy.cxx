#include "ShadowMapFramePolicy.h"

#include "ShadowMapFocusing.h" // For IntersectFrustumWithBox
#include "ShadowMapRendererMaps.h"
#include "vtkShadowMapExchange.h"

#include "vtkLightCollection.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"

namespace shadowmaps
{
//------------------------------------------------------------------------------
bool FramePolicy::BeginFrame(
  ShadowFrame& frame, const std::vector<Caster>& casters, bool sceneBoundsGiven)
{
  const bool translucent = AnyTranslucent(casters);
  if (!this->Exchange)
  {
    return translucent;
  }
  // Said once for good: ParaView turns the given bounds on and off.
  if (!GatherPropBounds(this->Exchange, frame, sceneBoundsGiven) && !sceneBoundsGiven &&
    !this->WarnedUngatheredBounds)
  {
    this->Warnings.emplace_back("The exchange gathers no prop bounds and no scene bounds are "
                                "given (SetSceneBounds): the processes' views may differ.");
    this->WarnedUngatheredBounds = true;
  }
  // The processes must fit the same views: interactive only if every one's
  // window is (a plain MPI program raises one rank's update rate); and all
  // make transmittance maps if any has a translucent caster.
  const FrameAgreement agreed = AgreeOnFrame(this->Exchange, frame.Interactive, translucent);
  frame.Interactive = agreed.AllInteractive;
  return agreed.AnyTranslucent;
}

//------------------------------------------------------------------------------
MapSignature FramePolicy::Signature(vtkRenderer* renderer, vtkMTimeType passTime,
  const ShadowFrame& frame, const std::vector<ShadowLight>& lights,
  const std::vector<Caster>& casters)
{
  MapInputs inputs;
  int origin[2];
  renderer->GetTiledSizeAndOrigin(&inputs.ViewportWidth, &inputs.ViewportHeight, origin, origin + 1);
  inputs.PassTime = passTime;
  inputs.LightsTime = renderer->GetLights()->GetMTime();
  inputs.PropsTime = renderer->GetViewProps()->GetMTime();
  return MapUpdates::Signature(inputs, frame, lights, casters);
}

//------------------------------------------------------------------------------
bool FramePolicy::MustRender(const MapUpdates& updates, const MapSignature& signature) const
{
  return this->AnyProcess(!updates.Current(signature));
}

//------------------------------------------------------------------------------
bool FramePolicy::AnyProcess(bool here) const
{
  return this->Exchange ? this->Exchange->AnyOf(here) : here;
}

//------------------------------------------------------------------------------
Combination FramePolicy::CombinationFor(const MapStorage& storage) const
{
  return this->Exchange ? CombinationOf(storage) : Combination::None;
}

//------------------------------------------------------------------------------
bool FramePolicy::CombinesLayers(const MapStorage& storage) const
{
  return this->Exchange && (CombinationOf(storage) != Combination::None || storage.Transmittance);
}

//------------------------------------------------------------------------------
void FramePolicy::BeginLayers(
  const ShadowFrame& frame, const MapStorage& storage, const LayerRules& rules)
{
  this->Rules = rules;
  this->Visible = rules.ReachCulling
    ? IntersectFrustumWithBox(frame.CameraProjection * frame.CameraView, frame.SceneBounds)
    : std::vector<glm::dvec3>();
  // While the user drags, views stay put as the camera turns (kept by
  // vtkShadowMapViews::InteractiveView, or snapped to a grid): a layer
  // re-rendered then takes every caster in its view, so that casters the
  // camera brings into reach later in the drag are already drawn. Not where
  // InteractiveTexelRatio 1 asks drags to render as still frames do, where
  // every layer is combined anew each frame, or where coarse mip levels would
  // average the extra casters into what receivers see.
  this->DrawsAllInView = rules.ViewsMayBeKept && !this->CombinesLayers(storage) && !storage.Mipmaps;
}

//------------------------------------------------------------------------------
LayerRequest FramePolicy::RequestFor(const ShadowLight& light, std::size_t view) const
{
  LayerRequest request;
  request.Layer = light.FirstLayer + static_cast<int>(view);
  request.Light = &light;
  request.View = view;
  request.Visible = &this->Visible;
  request.NormalOffsetTexels = this->Rules.NormalOffsetTexels;
  request.PostProcessingFollowsFilterScale = this->Rules.PostProcessingFollowsFilterScale;
  request.DrawsAllInView = this->DrawsAllInView;
  return request;
}

//------------------------------------------------------------------------------
bool FramePolicy::Combine(vtkOpenGLRenderWindow* window, RendererMaps& maps, int layers,
  int resolution, bool ok, std::string& error)
{
  if (!this->Exchange)
  {
    return ok;
  }
  // Every process that is updating its maps calls the same collectives in the
  // same order, whatever failed where: first whether any failed, then (all
  // having chosen the same storage) the maps' shape, then their texels.
  if (this->Exchange->AnyOf(!ok))
  {
    if (ok)
    {
      error = "another process could not render its shadow maps";
    }
    return false;
  }
  const Combination how = this->CombinationFor(maps.Storage);
  if (!AgreeOnShape(this->Exchange, resolution, layers, how, maps.Storage.Transmittance))
  {
    error = "the processes' shadow maps differ in size or kind";
    return false;
  }
  this->WarnOnce(how == Combination::None, this->WarnedUncombined,
    "Maps of values other than light depths are not combined across processes; these maps "
    "hold each process's own casters.");
  bool combined = how == Combination::None ||
    CombineTexels(this->Exchange, window, how, maps.Maps, maps.Storage, maps.LightDepths, layers,
      resolution, error);
  if (maps.Storage.Transmittance)
  {
    // Agreed by every process (BeginFrame): all make these calls.
    bool multiplied = false;
    combined = CombineTransmittances(this->Exchange, window, maps.Transmittances, layers,
                 resolution, multiplied, error) &&
      combined;
    this->WarnOnce(!multiplied, this->WarnedUnmultiplied,
      "The exchange multiplies no transmittance maps (ProductOf): each process's translucent "
      "casters and volumes shade its own receivers only.");
  }
  return combined;
}

//------------------------------------------------------------------------------
std::vector<std::string> FramePolicy::TakeWarnings()
{
  std::vector<std::string> warnings;
  warnings.swap(this->Warnings);
  return warnings;
}

//------------------------------------------------------------------------------
void FramePolicy::WarnOnce(bool cause, bool& warned, const std::string& warning)
{
  if (cause && !warned)
  {
    this->Warnings.push_back(warning);
  }
  warned = cause;
}
} // namespace shadowmaps
