#include "ShadowMapFrameUpdate.h"

#include "ShadowMapAnalysis.h"
#include "ShadowMapCasterShader.h"
#include "ShadowMapLightDepth.h"
#include "ShadowMapPropParts.h"
#include "ShadowMapPropRoles.h"
#include "ShadowMapStorageChoice.h"
#include "ShadowMapTextureArray.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderState.h"
#include "vtkShadowMapRepresentation.h"
#include "vtkShadowMapViews.h"
#include "vtkVolume.h"

#include "ShadowMapVTKCompat.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

namespace shadowmaps
{
namespace
{
std::vector<vtkVolume*> CastingVolumes(const std::vector<Caster>& casters)
{
  std::vector<vtkVolume*> volumes;
  for (const Caster& caster : casters)
  {
    if (auto* volume = vtkVolume::SafeDownCast(caster.Prop))
    {
      volumes.push_back(volume);
    }
  }
  return volumes;
}

// The most samples GL offers per texel of a multisample buffer.
int MaximumSamplesOfTheGL()
{
  GLint samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &samples);
  return std::max(1, static_cast<int>(samples));
}

bool IsNonFinite(const LightView& view)
{
  return !IsFinite(view.View) || !IsFinite(view.Projection);
}

vtkOpenGLRenderWindow* WindowOf(vtkOpenGLRenderer* renderer)
{
  return static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
}

bool AnyRenders(const std::vector<LayerPlan>& plans)
{
  return std::any_of(
    plans.begin(), plans.end(), [](const LayerPlan& plan) { return plan.Render; });
}
} // namespace

//------------------------------------------------------------------------------
ReceiverRole ReceiverRoleOf(
  vtkProp* prop, vtkInformationIntegerKey* casts, vtkInformationIntegerKey* receives)
{
  if (!TakesPart(prop, receives))
  {
    return ReceiverRole::None;
  }
  return HoldsItsOwnTransmittance(prop, casts) ? ReceiverRole::ReceivesWithOwnShare
                                                : ReceiverRole::Receives;
}

//------------------------------------------------------------------------------
void FrameUpdate::SelectRenderer(vtkOpenGLRenderer* renderer)
{
  this->Renderers.Select(renderer);
}

//------------------------------------------------------------------------------
const PassShaders& FrameUpdate::Shaders() const
{
  static const PassShaders none;
  const RendererMaps* maps = this->Renderers.Current();
  return maps ? maps->Code : none;
}

//------------------------------------------------------------------------------
bool FrameUpdate::Prepare(
  vtkOpenGLRenderer* renderer, const vtkRenderState* s, const FrameSettings& settings)
{
  this->Settings = &settings;
  this->Counts.Steps.Clear();
  this->Pending = PendingMaps();
  this->Uniforms.SetGroup(settings.Group);
  {
    const StepTimes::Scope reading(this->Counts.Steps, FrameStep::Reading);
    renderer->UpdateLightsGeometryToFollowCamera();
    this->CollectLights(renderer);
    this->Counts.ShadowedLights = static_cast<int>(this->FrameLights.size());
    if (this->FrameLights.empty())
    {
      this->Counts.Layers = 0;
      if (settings.AmongGroups)
      {
        this->Maps().Code.Clear();
      }
      return false;
    }
    this->CollectCastersAndCamera(renderer);
  }
  {
    const StepTimes::Scope shaders(this->Counts.Steps, FrameStep::Shaders);
    this->RebuildShadersOfChangedReceivers(s);
  }
  this->PlanMaps(renderer);
  // Before any group's casters draw: they share the receivers' programs.
  this->ReserveTextureUnits(renderer);
  return true;
}

//------------------------------------------------------------------------------
void FrameUpdate::Abandon(const std::string& error)
{
  this->Pending.Next = PendingMaps::Step::Fail;
  this->Pending.Error = error;
}

//------------------------------------------------------------------------------
bool FrameUpdate::Render(vtkOpenGLRenderer* renderer)
{
  PendingMaps pending = std::move(this->Pending);
  this->Pending = PendingMaps();
  bool ready = true;
  if (pending.Next == PendingMaps::Step::Fail)
  {
    // Each failure still answers the other processes' question.
    this->CombineAcrossProcesses(WindowOf(renderer), false);
    if (!pending.Error.empty())
    {
      this->Fail(pending.Error, renderer->GetRenderWindow());
    }
    ready = false;
  }
  else if (pending.Next == PendingMaps::Step::RenderLayers)
  {
    ready = this->RenderMaps(renderer, std::move(pending.Plans));
    if (ready)
    {
      this->FinishMaps(std::move(pending.Signature));
    }
    else
    {
      this->Fail(this->LastGLError, renderer->GetRenderWindow());
    }
  }
  // Lights whose views were not finite are gone by now.
  this->Counts.ShadowedLights = static_cast<int>(this->FrameLights.size());
  return ready;
}

//------------------------------------------------------------------------------
void FrameUpdate::CollectLights(vtkOpenGLRenderer* renderer)
{
  const FrameSettings& settings = *this->Settings;
  int skipped = 0;
  std::vector<vtkLight*> clamped;
  this->FrameLights = CollectShadowedLights(renderer, settings.Casts, settings.LightSize,
    settings.MaximumShadowedLights, skipped, clamped);
  if (skipped > 0 && !this->WarnedTooManyLights)
  {
    std::ostringstream warning;
    warning << skipped << " light(s) beyond the first " << settings.MaximumShadowedLights
            << " shadowed lights cast no shadows; they still light the scene.";
    this->Warnings.push_back(warning.str());
  }
  this->WarnedTooManyLights = skipped > 0;
  this->Shares = IntensityShares(renderer, this->FrameLights);
  this->KeepLightsOfGroup(clamped);
  this->SettleLightSizes(clamped);
}

//------------------------------------------------------------------------------
void FrameUpdate::KeepLightsOfGroup(std::vector<vtkLight*>& clamped)
{
  const FrameSettings& settings = *this->Settings;
  if (settings.Shadows)
  {
    clamped.erase(std::remove_if(clamped.begin(), clamped.end(),
                    [&settings](vtkLight* light) { return !settings.Shadows(light); }),
      clamped.end());
  }
  this->AnalysisLight = -1;
  std::vector<ShadowLight> kept;
  std::vector<float> keptShares;
  for (std::size_t i = 0; i < this->FrameLights.size(); ++i)
  {
    if (settings.Shadows && !settings.Shadows(this->FrameLights[i].Light))
    {
      continue;
    }
    if (static_cast<int>(i) == settings.AnalysisLight)
    {
      this->AnalysisLight = static_cast<int>(kept.size());
    }
    kept.push_back(std::move(this->FrameLights[i]));
    if (i < this->Shares.size())
    {
      keptShares.push_back(this->Shares[i]);
    }
  }
  this->FrameLights = std::move(kept);
  this->Shares = std::move(keptShares);
}

//------------------------------------------------------------------------------
void FrameUpdate::SettleLightSizes(const std::vector<vtkLight*>& clamped)
{
  const FrameSettings& settings = *this->Settings;
  vtkShadowMapRepresentation* representation = settings.Representation;
  std::ostringstream warning;
  if (!clamped.empty())
  {
    const double stored = StoredLightSize(clamped.front(), settings.LightSize);
    warning << clamped.size()
            << " light(s) have a LIGHT_SIZE (or OSPRay radius) that is not finite, negative, or a "
               "sun wider than "
            << WidestSun << " degrees: the first's " << stored << " is taken as "
            << LightSizeOf(clamped.front(), settings.LightSize) << ". ";
  }
  // Asked of the representation only with a sized light: its storage and soft
  // code are strings built on each call.
  bool soft = settings.SoftShadows &&
    std::any_of(this->FrameLights.begin(), this->FrameLights.end(),
      [](const ShadowLight& light) { return light.Size > 0.0; });
  if (soft)
  {
    // Depth textures' soft shadows read their depths through a sampler object.
    MapStorage storage;
    representation->GetMapStorage(storage);
    if (IsDepth(storage.Format) && !SamplerObjectsAvailable())
    {
      warning << "This OpenGL has no sampler objects (3.3): lights with a LIGHT_SIZE cast hard "
                 "shadows from depth maps.";
      soft = false;
    }
    else if (!representation->GetSupportsSizedLights())
    {
      warning << representation->GetClassName()
              << " draws hard shadows of lights with a LIGHT_SIZE in its present settings: soft "
                 "shadows come from depth maps, dual-depth maps and mipmapped VSM, EVSM4 and MSM "
                 "moments.";
      soft = false;
    }
  }
  if (!soft)
  {
    for (ShadowLight& light : this->FrameLights)
    {
      light.Size = 0.0; // hard shadows
    }
  }
  this->WarnOnce(warning.str(), this->WarnedLightSizes);
}

//------------------------------------------------------------------------------
void FrameUpdate::CollectCastersAndCamera(vtkOpenGLRenderer* renderer)
{
  const FrameSettings& settings = *this->Settings;
  ShadowFrame& frame = this->CurrentFrame;
  const SceneCamera camera = ReadSceneCamera(renderer, frame);
  this->SceneCameraParallel = camera.Parallel;
  this->Uniforms.SetDrawnRadius(camera.DrawnRadius);
  const std::string unmarchedVolume =
    CollectProps(renderer, camera.Sizing, settings.Casts, this->Maps().Props, frame, this->Casters);
  this->Maps().Volumes.KeepOnly(CastingVolumes(this->Casters));
  // A volume that cannot be marched casts nothing; the others still do.
  this->WarnOnce(unmarchedVolume.empty() ? std::string()
                                         : "A volume casts no shadow: " + unmarchedVolume + ".",
    this->WarnedVolume);

  const Aabb given = Aabb::FromBounds(settings.SceneBounds);
  if (settings.UseSceneBounds && given.IsUsable())
  {
    // The same on every process of a parallel renderer, whatever piece it
    // holds; with an exchange, GatherPropBounds gives the fits every
    // process's props.
    frame.SceneBounds = given;
    if (!settings.Exchange)
    {
      frame.PropBounds.assign(1, given);
    }
  }
  frame.FilterReachTexels = settings.Representation->GetFilterReachTexels();
  frame.Interactive = IsInteractiveRender(renderer, settings.InteractiveUpdateRate);
}

//------------------------------------------------------------------------------
void FrameUpdate::RebuildShadersOfChangedReceivers(const vtkRenderState* s)
{
  // A prop's shaders hold its receiving code or not: only a prop whose
  // RECEIVES_SHADOWS (or HoldsItsOwnTransmittance) changed since it last drew
  // here builds them again. Props entering or leaving the view, receivers or
  // not, change no shader.
  const FrameSettings& settings = *this->Settings;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    const ReceiverRole receives = ReceiverRoleOf(prop, settings.Casts, settings.Receives);
    auto known = this->Receives.find(prop);
    if (known == this->Receives.end() || known->second.first != prop)
    {
      this->Receives[prop] = { prop, receives };
      continue;
    }
    if (known->second.second != receives)
    {
      known->second.second = receives;
      RebuildShaders(prop);
    }
  }
  // Forget deleted props.
  for (auto it = this->Receives.begin(); it != this->Receives.end();)
  {
    it = it->second.first ? std::next(it) : this->Receives.erase(it);
  }
}

//------------------------------------------------------------------------------
void FrameUpdate::PlanMaps(vtkOpenGLRenderer* renderer)
{
  const FrameSettings& settings = *this->Settings;
  RendererMaps& maps = this->Maps();
  this->Policy.SetExchange(settings.Exchange);
  const bool boundsGiven =
    settings.UseSceneBounds && Aabb::FromBounds(settings.SceneBounds).IsUsable();
  this->TranslucentOnAnyProcess =
    this->Policy.BeginFrame(this->CurrentFrame, this->Casters, boundsGiven);
  this->CurrentFrame.StillKeepsViews = !this->CurrentFrame.Interactive && settings.AnimationKeepsViews;
  this->TakePolicyWarnings();
  MapSignature signature = FramePolicy::Signature(
    renderer, settings.ParametersTime(), this->CurrentFrame, this->FrameLights, this->Casters);
  if (!this->Policy.MustRender(maps.Updates, signature))
  {
    // CollectLights rebuilt the lights without views; the maps hold these,
    // lit by the mapper as the lights collected now are (switching another
    // light moves a light's place among the renderer's).
    const bool moved = maps.Updates.TakeShaderIndices(this->FrameLights);
    this->FrameLights = maps.Updates.GetRenderedLights();
    this->Counts.Layers = maps.Layers;
    this->CurrentFrame.Resolution = maps.Maps.GetResolution();
    this->Counts.Resolution = this->CurrentFrame.Resolution;
    if (maps.Code.Empty() || moved)
    {
      // A group without lights in an earlier frame emptied the code.
      this->UpdateShaders();
    }
    return;
  }

  // A drag draws whatever layers it must draw coarser (CoarseResolution); the
  // still frame's maps serve it while no layer needs drawing here or on any
  // other process. Every process asks that question whenever a drag may be
  // coarser, whatever its own maps hold (one may have lost them), so that
  // they all make the same collective calls.
  const int still = this->UsableResolution();
  const int coarse = this->CoarseResolution(still);
  const int drag = this->CurrentFrame.Interactive ? coarse : still;
  int resolution = drag < still && maps.Maps.GetResolution() != still ? drag : still;
  // Maps of the other resolution are kept for the next switch.
  const auto spareFor = [still, coarse](int used) {
    return coarse == still ? 0 : used == still ? coarse : still;
  };
  std::string error;
  bool ok = this->PrepareLayers(renderer, resolution, spareFor(resolution), error);
  std::vector<LayerPlan> plans = ok ? this->PlanLayers() : std::vector<LayerPlan>();
  if (drag < still &&
    this->Policy.AnyProcess(resolution == drag || !ok || AnyRenders(plans)) && resolution != drag)
  {
    resolution = drag;
    ok = ok && this->PrepareLayers(renderer, resolution, spareFor(resolution), error);
    plans = ok ? this->PlanLayers() : std::vector<LayerPlan>();
  }
  this->Pending.Next = ok ? PendingMaps::Step::RenderLayers : PendingMaps::Step::Fail;
  this->Pending.Plans = std::move(plans);
  this->Pending.Signature = std::move(signature);
  this->Pending.Error = std::move(error);
}

//------------------------------------------------------------------------------
void FrameUpdate::FinishMaps(MapSignature signature)
{
  const FrameSettings& settings = *this->Settings;
  RendererMaps& maps = this->Maps();
  if (!NeedsSecondOutput(maps.Storage, this->MapCombination(), this->FrameLights))
  {
    maps.Maps.ReleaseSecondOutput();
  }
  if (maps.Storage.Samples <= 1)
  {
    maps.Maps.ReleaseSamples();
  }
  maps.Uniforms.Pack(this->FrameLights, this->CurrentFrame.CameraView);
  maps.Updates.Finish(this->FrameLights, std::move(signature), settings.ParametersTime(),
    this->CurrentFrame.Resolution, this->CurrentFrame.SceneBounds);
  maps.Layers = this->Counts.Layers;
  this->Counts.Resolution = this->CurrentFrame.Resolution;
  this->WarnedGLError.clear();
  ++this->Counts.Updates;
}

//------------------------------------------------------------------------------
bool FrameUpdate::ReserveTransmittanceMaps(std::string& error)
{
  RendererMaps& maps = this->Maps();
  if (!maps.Storage.Transmittance)
  {
    maps.Transmittances.Release();
    return true;
  }
  return maps.Transmittances.Reserve(this->CurrentFrame.Resolution, this->Counts.Layers, error);
}

//------------------------------------------------------------------------------
int FrameUpdate::UsableResolution()
{
  const int wanted = this->Settings->Resolution;
  GLint maximumSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maximumSize);
  const int usable = std::min(wanted, std::max(static_cast<int>(maximumSize), 64));
  if (usable != wanted && !this->WarnedResolution)
  {
    std::ostringstream warning;
    warning << "Resolution " << wanted << " exceeds the GL maximum texture size; using " << usable
            << ".";
    this->Warnings.push_back(warning.str());
    this->WarnedResolution = true;
  }
  return usable;
}

//------------------------------------------------------------------------------
int FrameUpdate::CoarseResolution(int still) const
{
  const int coarse =
    static_cast<int>(std::lround(still * this->Settings->InteractiveResolutionScale));
  return std::min(still, std::max(coarse, 64));
}

//------------------------------------------------------------------------------
bool FrameUpdate::PrepareLayers(
  vtkOpenGLRenderer* renderer, int resolution, int spare, std::string& error)
{
  this->CurrentFrame.Resolution = resolution;
  StepTimes& steps = this->Counts.Steps;
  {
    const StepTimes::Scope fitting(steps, FrameStep::Fitting);
    if (!this->FitViews())
    {
      return false; // no light with usable views: no failure to warn of
    }
  }
  {
    const StepTimes::Scope storage(steps, FrameStep::Storage);
    this->ChooseStorage();
  }
  {
    const StepTimes::Scope shaders(steps, FrameStep::Shaders);
    this->UpdateShaders();
  }
  const StepTimes::Scope storage(steps, FrameStep::Storage);
  RendererMaps& maps = this->Maps();
  maps.SwitchMaps(resolution, spare);
  return maps.Maps.Reserve(resolution, this->Counts.Layers, maps.Storage.Format,
           maps.Storage.Mipmaps, error) &&
    this->ReserveTransmittanceMaps(error);
}

//------------------------------------------------------------------------------
bool FrameUpdate::FitViews()
{
  const FrameSettings& settings = *this->Settings;
  const ShadowFrame& frame = this->CurrentFrame;
  for (ShadowLight& light : this->FrameLights)
  {
    const ShadowLight* kept = this->Maps().Updates.KeptLight(
      light, settings.ParametersTime(), frame.Resolution, frame.SceneBounds);
    light.LastViews = kept ? kept->Views : std::vector<LightView>{};
    light.LastFaceSelection = kept ? kept->FaceSelection : std::vector<double>{};
    settings.ViewsOf(light.Light)->FitLight(frame, light);
    light.LastViews.clear();
    light.LastFaceSelection.clear();
    light.Depth = light.Kind == LightKind::Directional
      ? DirectionalLightDepth(light.Direction, frame.SceneBounds)
      : PositionalLightDepth(light.Position, frame.SceneBounds);
  }
  this->DropLightsWithoutUsableViews();
  this->AssignLayers();
  return !this->FrameLights.empty();
}

//------------------------------------------------------------------------------
void FrameUpdate::DropLightsWithoutUsableViews()
{
  std::vector<ShadowLight>& lights = this->FrameLights;
  const std::size_t before = lights.size();
  int nonFiniteViews = 0;
  int withoutViews = 0;
  std::string strategies;
  lights.erase(std::remove_if(lights.begin(), lights.end(),
                 [&](const ShadowLight& light) {
                   const auto nonFinite =
                     std::count_if(light.Views.begin(), light.Views.end(), IsNonFinite);
                   nonFiniteViews += static_cast<int>(nonFinite);
                   withoutViews += light.Views.empty() ? 1 : 0;
                   const bool dropped = nonFinite > 0 || light.Views.empty();
                   const std::string name = this->Settings->ViewsOf(light.Light)->GetClassName();
                   if (dropped && strategies.find(name) == std::string::npos)
                   {
                     strategies += (strategies.empty() ? "" : ", ") + name;
                   }
                   return dropped;
                 }),
    lights.end());
  this->Counts.NonFiniteViews = nonFiniteViews;
  if (lights.size() == before)
  {
    this->WarnedNonFiniteViews = false;
    return;
  }
  if (!this->WarnedNonFiniteViews)
  {
    // A views strategy of the user's may leave a light without views.
    std::ostringstream warning;
    warning << nonFiniteViews << " light view(s) came out with non-finite matrices and "
            << withoutViews << " light(s) got no view from " << strategies << "; these lights cast no shadows until their views are usable again.";
    this->Warnings.push_back(warning.str());
    this->WarnedNonFiniteViews = true;
  }
}

//------------------------------------------------------------------------------
void FrameUpdate::AssignLayers()
{
  int layers = 0;
  for (ShadowLight& light : this->FrameLights)
  {
    light.FirstLayer = layers;
    layers += static_cast<int>(light.Views.size());
  }
  this->Counts.Layers = layers;
}

//------------------------------------------------------------------------------
void FrameUpdate::ChooseStorage()
{
  RendererMaps& maps = this->Maps();
  this->Settings->Representation->GetMapStorage(maps.Storage);
  StorageLimits limits;
  limits.CombinesAcrossProcesses = this->Settings->Exchange != nullptr;
  limits.ThirtyTwoBitDepthNow =
    maps.Maps.GetResolution() != 0 && maps.Maps.GetFormat() == TexelFormat::Depth;
  if (maps.Storage.Samples > 1 && this->MaximumSamples <= 0)
  {
    this->MaximumSamples = MaximumSamplesOfTheGL();
  }
  limits.MaximumSamples = std::max(this->MaximumSamples, 1);
  CompleteStorage(maps.Storage, this->FrameLights, this->Casters, this->Closed, limits);
  maps.Storage.Transmittance = this->TranslucentOnAnyProcess;
  this->Counts.CasterPassesPerLayer =
    CasterPassesPerLayer(maps.Storage) + (maps.Storage.Transmittance ? 1 : 0);
}

//------------------------------------------------------------------------------
void FrameUpdate::UpdateShaders()
{
  // Before the casters draw: they build the shaders the scene then uses.
  const FrameSettings& settings = *this->Settings;
  ShaderChoices choices;
  choices.CasterFaces = settings.CasterFaces;
  // Another group's light is analysed: no analysis code here.
  choices.AnalysisView = this->AnalysisLight >= 0 ? settings.RecolouringAnalysisView : 0;
  choices.AnalysisLight = std::max(this->AnalysisLight, 0);
  static_assert(ChosenViewsAnalysis == vtkAbstractShadowMapPass::CHOSEN_VIEWS, "one value");
  if (choices.AnalysisView == ChosenViewsAnalysis &&
    this->AnalysisLight < static_cast<int>(this->FrameLights.size()))
  {
    const ShadowLight& analysed = this->FrameLights[this->AnalysisLight];
    choices.AnalysisViewsKind = settings.ViewsOf(analysed.Light)->GetKindName(analysed);
  }
  choices.KeepsLightDepths = this->MapCombination() == Combination::NearestLightDepths;
  RendererMaps& maps = this->Maps();
  // MapGroups tries it on a probe program before any caster draws.
  maps.Code.Update(
    maps.Storage, settings.Representation, this->FrameLights, this->Counts.Layers, choices);
}

//------------------------------------------------------------------------------
CastingSettings FrameUpdate::CastingSettingsOfUpdate() const
{
  const RendererMaps& maps = this->Maps();
  const DepthOffset offset = this->Settings->Representation->GetCasterDepthOffset();
  CastingSettings casting;
  casting.Resolution = this->CurrentFrame.Resolution;
  casting.Depth16 = maps.Storage.Format == TexelFormat::Depth16;
  const CasterCode& code = maps.Code.GetCasterCode();
  casting.LightDepth = code.LightDepth || code.Transmittance;
  casting.SlopeScaledOffset = offset.SlopeScaled;
  casting.ConstantOffset = offset.Constant;
  casting.SceneCameraParallel = this->SceneCameraParallel;
  casting.StoreUniforms = maps.Storage.StoreUniforms;
  return casting;
}

//------------------------------------------------------------------------------
std::vector<LayerPlan> FrameUpdate::PlanLayers()
{
  const FrameSettings& settings = *this->Settings;
  RendererMaps& maps = this->Maps();
  const ShadowFrame& frame = this->CurrentFrame;
  // What every layer depends on besides its view and casters: the parameters
  // of the pass and its strategies (the bias, the caster faces and store code
  // among them), the storage, and how a second depth is made (AUTO may change
  // it when some other layer's casters change). Layers that hold every
  // process's casters combined are all rendered and combined again.
  maps.Updates.BeginUpdate({ settings.ParametersTime(), maps.Maps.GetAllocations(),
                             maps.Transmittances.GetAllocations(),
                             static_cast<vtkMTimeType>(frame.Resolution),
                             static_cast<vtkMTimeType>(maps.Storage.SecondDepth) },
    this->Counts.Layers, this->Policy.CombinesLayers(maps.Storage), this->Casters);
  this->Policy.BeginLayers(frame, maps.Storage, this->LayerRulesOfUpdate());
  std::vector<LayerPlan> plans;
  plans.reserve(static_cast<std::size_t>(this->Counts.Layers));
  for (const ShadowLight& light : this->FrameLights)
  {
    for (std::size_t v = 0; v < light.Views.size(); ++v)
    {
      plans.push_back(maps.Updates.Plan(frame, this->Casters, this->Policy.RequestFor(light, v)));
    }
  }
  return plans;
}

//------------------------------------------------------------------------------
bool FrameUpdate::RenderMaps(vtkOpenGLRenderer* renderer, std::vector<LayerPlan> plans)
{
  const FrameSettings& settings = *this->Settings;
  RendererMaps& maps = this->Maps();
  const ShadowFrame& frame = this->CurrentFrame;
  vtkOpenGLRenderWindow* window = WindowOf(renderer);
  const bool keepsLightDepths = this->MapCombination() == Combination::NearestLightDepths;
  if (keepsLightDepths)
  {
    maps.LightDepths.Reset(maps.Maps, this->Counts.Layers);
  }
  std::vector<RenderedLayer> rendered;
  bool ok = true;
  {
    const StepTimes::Scope drawing(this->Counts.Steps, FrameStep::Drawing);
    CasterGLState casterState(
      window->GetState(), !IsDepth(maps.Storage.Format) && maps.Storage.MinimumBlending);
    this->ReserveTextureUnits(renderer);
    this->Casting = &casterState;
    LayerDrawing::Update update;
    update.Renderer = renderer;
    update.Maps = &maps;
    update.Frame = &frame;
    update.Programs = &this->Uniforms;
    update.Casting = this->CastingSettingsOfUpdate();
    update.KeepsLightDepths = keepsLightDepths;
    update.PeelUnit = this->Units.GetPeelUnit();
    update.JoinCasters = settings.JoinProps;
    this->Layers.BeginUpdate(update);
    for (const ShadowLight& light : this->FrameLights)
    {
      for (std::size_t v = 0; v < light.Views.size() && ok; ++v)
      {
        const int layer = light.FirstLayer + static_cast<int>(v);
        LayerPlan& plan = plans[static_cast<std::size_t>(layer)];
        bool bound = false;
        ok = !plan.Render ||
          this->Layers.Draw(light, v, layer, plan.Casters, bound, this->LastGLError);
        if (bound)
        {
          maps.Updates.Rendered(layer, std::move(plan));
          rendered.push_back({ layer, FilterScale(light, v) });
        }
      }
    }
    this->Casting = nullptr;
    this->Layers.EndUpdate();
  }
  for (std::string& warning : this->Layers.TakeWarnings())
  {
    this->Warnings.push_back(std::move(warning));
  }
  this->Counts.RenderedLayers = static_cast<int>(rendered.size());
  if (!rendered.empty())
  {
    this->Counts.CasterDraws = this->Layers.GetDraws();
  }
  const StepTimes::Scope finishing(this->Counts.Steps, FrameStep::Finishing);
  ok = this->CombineAcrossProcesses(window, ok);
  if (!ok)
  {
    maps.Updates.Invalidate();
    return false;
  }
  return rendered.empty() || this->PostProcess(renderer, rendered);
}

//------------------------------------------------------------------------------
LayerRules FrameUpdate::LayerRulesOfUpdate() const
{
  const FrameSettings& settings = *this->Settings;
  LayerRules rules;
  rules.ReachCulling = settings.ShadowReachCulling;
  // Per frame: a layer of a light whose views are never kept that draws
  // every caster in its view draws no other pixel.
  rules.ViewsMayBeKept = std::any_of(this->FrameLights.begin(), this->FrameLights.end(),
    [this, &settings](const ShadowLight& light) {
      return settings.ViewsOf(light.Light)->MayKeepViews(this->CurrentFrame);
    });
  rules.NormalOffsetTexels = settings.NormalOffset;
  rules.PostProcessingFollowsFilterScale =
    settings.Representation->GetPostProcessingFollowsFilterScale();
  return rules;
}

//------------------------------------------------------------------------------
Combination FrameUpdate::MapCombination() const
{
  return this->Policy.CombinationFor(this->Maps().Storage);
}

//------------------------------------------------------------------------------
bool FrameUpdate::CombineAcrossProcesses(vtkOpenGLRenderWindow* window, bool ok)
{
  const bool combined = this->Policy.Combine(window, this->Maps(), this->Counts.Layers,
    this->CurrentFrame.Resolution, ok, this->LastGLError);
  this->TakePolicyWarnings();
  return combined;
}

//------------------------------------------------------------------------------
void FrameUpdate::TakePolicyWarnings()
{
  for (std::string& warning : this->Policy.TakeWarnings())
  {
    this->Warnings.push_back(std::move(warning));
  }
}

//------------------------------------------------------------------------------
bool FrameUpdate::PostProcess(
  vtkOpenGLRenderer* renderer, const std::vector<RenderedLayer>& rendered)
{
  if (!this->Settings->Representation->PostProcessMaps(renderer, this->Maps().Maps, rendered))
  {
    this->LastGLError = "the shadow maps could not be post-processed";
    return false;
  }
  this->Maps().Maps.GenerateMipmaps();
  return true;
}

//------------------------------------------------------------------------------
void FrameUpdate::ReserveTextureUnits(vtkOpenGLRenderer* renderer)
{
  // Before the casters draw: they share the receivers' programs.
  const MapStorage& storage = this->Maps().Storage;
  if (this->Units.Reserve(
        WindowOf(renderer), storage, this->ReadsRawDepths(), this->Settings->Representation) &&
    storage.SecondDepth == SecondDepthMethod::Peeling)
  {
    this->Uniforms.SetPeeling(false, this->Units.GetPeelUnit());
  }
}

//------------------------------------------------------------------------------
void FrameUpdate::BindForReceivers(vtkOpenGLRenderer* renderer)
{
  this->ReserveTextureUnits(renderer);
  this->Units.Bind(WindowOf(renderer), this->Maps(), this->Settings->Representation);
  this->Maps().Uniforms.NewFrame();
}

//------------------------------------------------------------------------------
bool FrameUpdate::ReadsRawDepths() const
{
  return IsDepth(this->Maps().Storage.Format) &&
    std::any_of(this->FrameLights.begin(), this->FrameLights.end(),
      [](const ShadowLight& light) { return light.Size > 0.0; });
}

//------------------------------------------------------------------------------
void FrameUpdate::Fail(const std::string& error, vtkWindow* context)
{
  this->Maps().ReleaseGraphicsResources(context);
  this->Counts.Layers = 0;
  this->Counts.Resolution = 0;
  if (error != this->WarnedGLError)
  {
    this->Warnings.push_back("Rendering without shadows: " + error);
    this->WarnedGLError = error;
  }
}

//------------------------------------------------------------------------------
void FrameUpdate::WarnOnce(const std::string& warning, std::string& last)
{
  if (!warning.empty() && warning != last)
  {
    this->Warnings.push_back(warning);
  }
  last = warning;
}

//------------------------------------------------------------------------------
std::vector<std::string> FrameUpdate::TakeWarnings()
{
  std::vector<std::string> taken;
  taken.swap(this->Warnings);
  return taken;
}

//------------------------------------------------------------------------------
void FrameUpdate::ReleaseMapsOf(vtkRenderer* renderer, vtkOpenGLRenderWindow* window)
{
  this->Renderers.Release(
    renderer, window, [this](const RendererMaps* maps) { this->Uniforms.Forget(maps); });
}

//------------------------------------------------------------------------------
void FrameUpdate::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Renderers.ReleaseAll(window);
  this->Uniforms.Clear();
  this->MaximumSamples = 0;
  this->Layers.ReleaseGraphicsResources(window);
}
} // namespace shadowmaps
