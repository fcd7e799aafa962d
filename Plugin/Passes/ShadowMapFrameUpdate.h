// One renderer's frame of shadow maps, from the scene to maps the receivers
// can read: collect the shadowed lights, the casters and the camera; decide
// whether the maps must be rendered (FramePolicy); fit each light's views,
// choose the storage, update the shadow code, reserve the maps, draw the
// layers that changed (LayerDrawing), combine them across processes and
// post-process them. It keeps each renderer's maps and what the receivers'
// shaders and programs were made for. The pass hands it its parameters each
// frame and keeps the VTK side: parameters, the context and renderers'
// lifetimes, the props' render passes and the shader hooks, which read what
// this holds (Filament's ShadowMapManager beside FView). Warnings are
// collected, each once until its cause changes, for the pass to report.
// Not a VTK class.
#ifndef ShadowMapFrameUpdate_h
#define ShadowMapFrameUpdate_h

#include "ShadowMapCasting.h"         // For CasterGLState
#include "ShadowMapClosedSurfaces.h"  // For ClosedCasters
#include "ShadowMapFramePolicy.h"     // For FramePolicy
#include "ShadowMapLayerDrawing.h"    // For LayerDrawing
#include "ShadowMapLight.h"           // For ShadowFrame, ShadowLight
#include "ShadowMapPassShaders.h"     // For PassShaders
#include "ShadowMapProgramUniforms.h" // For ProgramUniforms
#include "ShadowMapReceiverTextures.h" // For ReceiverTextures
#include "ShadowMapRendererMaps.h"    // For MapsByRenderer
#include "ShadowMapSceneReading.h"   // For Caster
#include "ShadowMapStepTimes.h"       // For StepTimes

#include "vtkType.h"
#include "vtkWeakPointer.h"

#include <functional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

class vtkInformationDoubleKey;
class vtkInformationIntegerKey;
class vtkLight;
class vtkOpenGLRenderWindow;
class vtkOpenGLRenderer;
class vtkProp;
class vtkRenderState;
class vtkRenderer;
class vtkShadowMapExchange;
class vtkShadowMapRepresentation;
class vtkShadowMapViews;
class vtkWindow;

namespace shadowmaps
{
struct RenderedLayer;

/// The receiver code a prop's shaders get: none, receiving, or receiving and
/// dividing its own share out of the transmittance maps.
enum class ReceiverRole
{
  None,
  Receives,
  ReceivesWithOwnShare
};

/// What a prop's property keys (and its kind) make it as a receiver.
ReceiverRole ReceiverRoleOf(
  vtkProp* prop, vtkInformationIntegerKey* casts, vtkInformationIntegerKey* receives);

/// The pass's parameters, as one frame's update reads them.
struct FrameSettings
{
  /// The views each light gets: its own, or the pass's.
  std::function<vtkShadowMapViews*(vtkLight*)> ViewsOf;
  /// The representation of this update's maps, and the lights they shadow
  /// (empty: all): a pass whose lights use several representations has an
  /// update, a group of maps, for each.
  vtkShadowMapRepresentation* Representation = nullptr;
  std::function<bool(vtkLight*)> Shadows;
  /// The group's index: its names in the shaders (ShaderGroup).
  int Group = 0;
  /// Several groups' code shares the programs: the pass, not the update,
  /// tries it on a probe program before the mappers build it, and a frame
  /// without lights of the group empties its code (PassShaders::Clear).
  bool AmongGroups = false;
  vtkShadowMapExchange* Exchange = nullptr;
  /// The pass's modification time, its strategies' included: a change
  /// re-renders the maps. Asked at each step that reads it, as a strategy
  /// may change itself during the update.
  std::function<vtkMTimeType()> ParametersTime;
  /// The bounds the views are fitted to, when given (UseSceneBounds).
  bool UseSceneBounds = false;
  const double* SceneBounds = nullptr;
  bool SoftShadows = true;
  int Resolution = 2048;
  int CasterFaces = 2;
  double NormalOffset = 1.0;
  bool ShadowReachCulling = true;
  double InteractiveUpdateRate = 1.0;
  /// Still renders may keep views as interactive ones do (ShadowFrame::StillKeepsViews).
  bool AnimationKeepsViews = false;
  /// The share of Resolution maps drawn during a drag are drawn at.
  double InteractiveResolutionScale = 1.0;
  /// An analysis view that recolours the receivers (0: none).
  int RecolouringAnalysisView = 0;
  int AnalysisLight = 0;
  /// The most lights that cast shadows (VTK_MAX_SHADOWED_LIGHTS).
  int MaximumShadowedLights = 8;
  /// The property and light keys of the pass.
  vtkInformationIntegerKey* Casts = nullptr;
  vtkInformationIntegerKey* Receives = nullptr;
  vtkInformationDoubleKey* LightSize = nullptr;
  /// Has the props join the pass's render passes (the casters before they draw).
  std::function<void(vtkProp* const*, int)> JoinProps;
};

/// What the frames so far leave to be read: the pass's statistics.
struct FrameStatistics
{
  int ShadowedLights = 0;
  int Layers = 0;
  int NonFiniteViews = 0;
  int Updates = 0;
  /// Of the last frame that rendered layers.
  int CasterDraws = 0;
  int RenderedLayers = 0;
  /// Of the last map update.
  int CasterPassesPerLayer = 1;
  /// The width and height of the maps the last frame read.
  int Resolution = 0;
  /// Where the last frame's shadow work went.
  StepTimes Steps;
};

class FrameUpdate
{
public:
  FrameUpdate() = default;
  FrameUpdate(const FrameUpdate&) = delete;
  FrameUpdate& operator=(const FrameUpdate&) = delete;

  /// Makes `renderer`'s maps (and its camera's eye's) the current ones.
  void SelectRenderer(vtkOpenGLRenderer* renderer);

  /// The frame's shadows for the current renderer, in two steps, so that
  /// every group's texture units are reserved before any group's casters
  /// draw (they share programs). Prepare collects its lights, casters and
  /// camera and, where anything they depend on changed, makes ready to render
  /// its maps; false: no light to shadow, and nothing to render. Render then
  /// renders them, and whether the frame has shadows (false: a failure,
  /// warned). Every process of a parallel renderer makes the same collective
  /// calls in each step.
  bool Prepare(vtkOpenGLRenderer* renderer, const vtkRenderState* s, const FrameSettings& settings);
  bool Render(vtkOpenGLRenderer* renderer);
  /// Between Prepare and Render: the maps are not rendered, and Render
  /// fails with `error` (still answering the other processes).
  void Abandon(const std::string& error);

  /// Binds the maps for the receivers of the frame just prepared.
  void BindForReceivers(vtkOpenGLRenderer* renderer);

  /// The frame goes on without shadows: the current maps are released, and
  /// `error` is warned (once until another).
  void Fail(const std::string& error, vtkWindow* context);

  /// The warnings found since the last call.
  std::vector<std::string> TakeWarnings();

  const FrameStatistics& Statistics() const { return this->Counts; }
  void ClearFrameStatistics() { this->Counts.RenderedLayers = 0; }

  /// What the shader hooks and the analysis read of the current frame.
  const std::vector<ShadowLight>& Lights() const { return this->FrameLights; }
  RendererMaps& Maps() { return *this->Renderers.Current(); }
  const RendererMaps& Maps() const { return *this->Renderers.Current(); }
  const ShadowFrame& Frame() const { return this->CurrentFrame; }
  /// The current renderer's code (none before a renderer is selected).
  const PassShaders& Shaders() const;
  /// This group's share of the mappers' shaders.
  GroupCode ShaderCode() const { return { &this->Shaders(), &this->FrameLights, this->Counts.Layers }; }
  /// The analysis view's light among Lights(); -1 when another group's.
  int AnalysedLight() const { return this->AnalysisLight; }
  ProgramUniforms& Programs() { return this->Uniforms; }
  ReceiverTextures& Textures() { return this->Units; }
  /// Each shadowed light's share of the lights' intensity (volumes that receive).
  const std::vector<float>& LightShares() const { return this->Shares; }
  /// The casters' GL state while they draw into the maps, else nullptr.
  CasterGLState* CastingState() const { return this->Casting; }

  /// The renderers whose maps are kept.
  bool HoldsMapsOf(vtkRenderer* renderer) const { return this->Renderers.Holds(renderer); }
  bool HoldsNoMaps() const { return this->Renderers.Empty(); }
  std::size_t MemoryBytes() const { return this->Renderers.MemoryBytes(); }
  /// Releases `renderer`'s maps in `window`'s (current) context.
  void ReleaseMapsOf(vtkRenderer* renderer, vtkOpenGLRenderWindow* window);
  /// Releases every GL object held in `window`'s context.
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  void CollectLights(vtkOpenGLRenderer* renderer);
  /// Keeps the lights of this update's group (FrameSettings::Shadows), and
  /// of `clamped` (lights whose size was clamped) those.
  void KeepLightsOfGroup(std::vector<vtkLight*>& clamped);
  void SettleLightSizes(const std::vector<vtkLight*>& clamped);
  void CollectCastersAndCamera(vtkOpenGLRenderer* renderer);
  void RebuildShadersOfChangedReceivers(const vtkRenderState* s);
  /// Prepare's part once the scene is read: what must be rendered, in Pending.
  void PlanMaps(vtkOpenGLRenderer* renderer);
  /// After the layers were rendered: what the maps now hold.
  void FinishMaps(MapSignature signature);
  int UsableResolution();
  /// The maps' resolution when a drag must draw layers: `still` scaled by
  /// InteractiveResolutionScale, not below 64.
  int CoarseResolution(int still) const;
  /// Fits the views at `resolution`, chooses the storage and the shader code,
  /// and reserves the maps, keeping maps of resolution `spare` (0: none) for
  /// the next switch between a drag's and a still frame's resolutions. False
  /// with `error` on a failure to warn of, with none where no light has
  /// usable views.
  bool PrepareLayers(vtkOpenGLRenderer* renderer, int resolution, int spare, std::string& error);
  /// Which layers must be drawn, and with which casters (MapUpdates::Plan),
  /// in layer order.
  std::vector<LayerPlan> PlanLayers();
  bool FitViews();
  void DropLightsWithoutUsableViews();
  void AssignLayers();
  void ChooseStorage();
  /// The shadow code for the current maps' lights, layers and storage; a new
  /// key rebuilds the mappers' shaders, once the code is known to compile.
  void UpdateShaders();
  /// The transmittance maps as the storage asks (none without translucent casters).
  bool ReserveTransmittanceMaps(std::string& error);
  /// Draws the layers `plans` render, then combines and post-processes them.
  bool RenderMaps(vtkOpenGLRenderer* renderer, std::vector<LayerPlan> plans);
  void ReserveTextureUnits(vtkOpenGLRenderer* renderer);
  /// Whether receivers read the depth maps without comparison this frame
  /// (the soft shadows' blocker search).
  bool ReadsRawDepths() const;
  CastingSettings CastingSettingsOfUpdate() const;
  LayerRules LayerRulesOfUpdate() const;
  Combination MapCombination() const;
  /// On every process that updates its maps: FramePolicy::Combine (without
  /// an exchange, returns `ok`).
  bool CombineAcrossProcesses(vtkOpenGLRenderWindow* window, bool ok);
  bool PostProcess(vtkOpenGLRenderer* renderer, const std::vector<RenderedLayer>& rendered);
  void TakePolicyWarnings();
  /// `warning` once: again only after `last` held another.
  void WarnOnce(const std::string& warning, std::string& last);

  // The frame being rendered, and the settings it is rendered with.
  const FrameSettings* Settings = nullptr;
  ShadowFrame CurrentFrame;
  std::vector<ShadowLight> FrameLights;
  /// The analysis view's light among FrameLights; -1 when another group's.
  int AnalysisLight = -1;
  /// What Prepare left Render to do.
  struct PendingMaps
  {
    enum class Step
    {
      Nothing,
      RenderLayers,
      Fail
    };
    Step Next = Step::Nothing;
    std::vector<LayerPlan> Plans;
    MapSignature Signature;
    /// Fail: the failure to warn of (none where no light had usable views).
    std::string Error;
  };
  PendingMaps Pending;
  std::vector<Caster> Casters;
  bool SceneCameraParallel = false;
  /// Whether this process's casters (or, with an exchange, any process's)
  /// draw into the transmittance maps.
  bool TranslucentOnAnyProcess = false;
  std::vector<float> Shares;
  FrameStatistics Counts;

  // What renders the maps, and each renderer's (and eye's) maps.
  LayerDrawing Layers;
  ClosedCasters Closed;
  FramePolicy Policy;
  MapsByRenderer Renderers;
  /// The most samples per texel the context offers (GL_MAX_SAMPLES), asked
  /// once, and only by maps that may be multisampled.
  int MaximumSamples = 0;
  CasterGLState* Casting = nullptr;

  // What is set on the mappers' programs and which units they read.
  ProgramUniforms Uniforms;
  ReceiverTextures Units;
  /// Whether each prop received shadows (and held its own transmittance)
  /// when it last drew through the pass: what its shaders were built for.
  std::unordered_map<vtkProp*, std::pair<vtkWeakPointer<vtkProp>, ReceiverRole>> Receives;

  // Warnings, and what each last warned of.
  std::vector<std::string> Warnings;
  bool WarnedTooManyLights = false;
  std::string WarnedLightSizes;
  bool WarnedNonFiniteViews = false;
  bool WarnedResolution = false;
  std::string LastGLError;
  std::string WarnedGLError;
  std::string WarnedVolume;
};
} // namespace shadowmaps

#endif
