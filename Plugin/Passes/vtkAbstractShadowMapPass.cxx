#include "vtkAbstractShadowMapPass.h"

#include "ShadowMapAnalysis.h"
#include "ShadowMapCasting.h"
#include "ShadowMapFrameUpdate.h"
#include "ShadowMapGroups.h"
#include "ShadowMapPerLight.h"
#include "ShadowMapImpostors.h"
#include "ShadowMapPropJoining.h"
#include "ShadowMapPropRoles.h"
#include "ShadowMapRendererUse.h"
#include "ShadowMapSceneReading.h"

#include "vtkCommand.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLight.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapExchange.h"
#include "vtkShadowMapRepresentation.h"
#include "vtkShadowMapViews.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkWeakPointer.h"

#include "ShadowMapVTKCompat.h"

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

vtkInformationKeyMacro(vtkAbstractShadowMapPass, CASTS_SHADOWS, Integer);
vtkInformationKeyMacro(vtkAbstractShadowMapPass, RECEIVES_SHADOWS, Integer);
vtkInformationKeyMacro(vtkAbstractShadowMapPass, LIGHT_SIZE, Double);

//------------------------------------------------------------------------------
double vtkAbstractShadowMapPass::GetLightSize(vtkLight* light, bool* clamped)
{
  return shadowmaps::LightSizeOf(light, LIGHT_SIZE(), clamped);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::GetTransmittance(
  const double color[3], double opacity, double transmitted[3])
{
  // Clamped as the casters' shader clamps; a NaN opacity counts as opaque.
  const double a = opacity >= 0.0 ? std::min(opacity, 1.0) : (opacity < 0.0 ? 0.0 : 1.0);
  for (int c = 0; c < 3; ++c)
  {
    const double channel = color[c] >= 0.0 ? std::min(color[c], 1.0) : 0.0;
    transmitted[c] = (1.0 - a) * ((1.0 - a) + a * channel);
  }
}

struct vtkAbstractShadowMapPass::Internals
{
  // The strategies: the preset's own, or the user's.
  vtkSmartPointer<vtkShadowMapViews> DefaultViews;
  vtkSmartPointer<vtkShadowMapRepresentation> DefaultRepresentation;
  vtkSmartPointer<vtkShadowMapViews> Views;
  vtkSmartPointer<vtkShadowMapRepresentation> Representation;
  // The lights with views or a representation of their own.
  shadowmaps::PerLight<vtkShadowMapViews> LightViews;
  shadowmaps::PerLight<vtkShadowMapRepresentation> LightRepresentations;

  // Forgets the lights deleted since: whether it forgot any (the pass is
  // then modified, so that no new light at a deleted one's address keeps
  // what the deleted one's strategies fitted).
  bool ForgetDeletedLights()
  {
    const bool views = this->LightViews.ForgetDeleted();
    return this->LightRepresentations.ForgetDeleted() || views;
  }

  // The settings of a renderer's frame, and what renders its maps, a group
  // per representation in use (which reads them until it is destroyed).
  shadowmaps::FrameSettings Settings;
  shadowmaps::MapGroups Groups;

  // What draws the scene.
  vtkNew<vtkRenderStepsPass> DefaultDelegate;
  vtkNew<vtkDualDepthPeelingPass> DepthPeeling;
  vtkSmartPointer<vtkRenderPass> BlendedTranslucency;

  // The default delegate draws translucent geometry as the renderer does
  // without a pass: depth-peeled when the renderer asks for it
  // (UseDepthPeeling, with its peel count and occlusion ratio), else blended
  // in one draw.
  void FollowRendererTranslucency(vtkRenderer* renderer)
  {
    if (!this->BlendedTranslucency)
    {
      this->BlendedTranslucency = this->DefaultDelegate->GetTranslucentPass();
      this->DepthPeeling->SetTranslucentPass(this->BlendedTranslucency);
    }
    vtkRenderPass* wanted = this->BlendedTranslucency;
    if (renderer->GetUseDepthPeeling())
    {
      this->DepthPeeling->SetMaximumNumberOfPeels(renderer->GetMaximumNumberOfPeels());
      this->DepthPeeling->SetOcclusionRatio(renderer->GetOcclusionRatio());
      wanted = this->DepthPeeling;
    }
    if (this->DefaultDelegate->GetTranslucentPass() != wanted)
    {
      this->DefaultDelegate->SetTranslucentPass(wanted);
    }
  }
  shadowmaps::MapView MapView;

  // The props whose render passes the pass joined, in this frame or past it.
  shadowmaps::PropJoining Joining;

  explicit Internals(vtkAbstractShadowMapPass* pass)
    : Joining(pass)
  {
  }

  // The window whose context holds the pass's GL objects, while it holds any,
  // and the renderers that draw through the pass: what a renderer stops
  // drawing with (the pass replaced or taken off) is released at once.
  vtkWeakPointer<vtkRenderWindow> Context;
  unsigned long ContextDeleteObserver = 0;
  bool HoldsGraphicsResources = false;
  std::unique_ptr<shadowmaps::RendererUse> Use;

  // Whether the frame being drawn has shadows.
  bool Active = false;
};

//------------------------------------------------------------------------------
vtkAbstractShadowMapPass::vtkAbstractShadowMapPass(
  vtkShadowMapViews* defaultViews, vtkShadowMapRepresentation* defaultRepresentation)
  : Internal(new Internals(this))
{
  this->Internal->DefaultViews = defaultViews;
  this->Internal->DefaultRepresentation = defaultRepresentation;
  this->Internal->Views = defaultViews;
  this->Internal->Representation = defaultRepresentation;
  this->Internal->Use = std::make_unique<shadowmaps::RendererUse>(
    [this](vtkRenderer* renderer) { this->ReleaseMapsOf(renderer); });
  shadowmaps::FrameSettings& settings = this->Internal->Settings;
  settings.MaximumShadowedLights = VTK_MAX_SHADOWED_LIGHTS;
  settings.Casts = CASTS_SHADOWS();
  settings.Receives = RECEIVES_SHADOWS();
  settings.LightSize = LIGHT_SIZE();
  settings.ParametersTime = [this]() { return this->GetMTime(); };
  settings.ViewsOf = [this](vtkLight* light) { return this->GetLightViews(light); };
  settings.JoinProps = [this](vtkProp* const* props, int count) {
    this->JoinRenderPasses(props, count);
  };
  // The scene draws into one colour buffer; the volume ray caster, drawing at a
  // coarser image sample distance, draws into as many as the last pass on the
  // volume says.
  this->SetActiveDrawBuffers(1);
}

//------------------------------------------------------------------------------
vtkAbstractShadowMapPass::~vtkAbstractShadowMapPass()
{
  this->ForgetContext();
  this->SetDelegatePass(nullptr);
  this->SetExchange(nullptr);
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(vtkAbstractShadowMapPass, Exchange, vtkShadowMapExchange);

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::SetDelegatePass(vtkRenderPass* delegate)
{
  if (this->DelegatePass == delegate)
  {
    return;
  }
  if (this->DelegatePass)
  {
    this->DelegatePass->UnRegister(this);
  }
  this->DelegatePass = delegate;
  if (delegate)
  {
    delegate->Register(this);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::SetViews(vtkShadowMapViews* views)
{
  vtkShadowMapViews* chosen = views ? views : this->Internal->DefaultViews.Get();
  if (chosen != this->Internal->Views)
  {
    this->Internal->Views = chosen;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkShadowMapViews* vtkAbstractShadowMapPass::GetViews()
{
  return this->Internal->Views;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::SetLightViews(vtkLight* light, vtkShadowMapViews* views)
{
  if (!light)
  {
    vtkWarningMacro(<< "SetLightViews: no light given; nothing changes.");
    return;
  }
  Internals& r = *this->Internal;
  const bool forgot = r.ForgetDeletedLights();
  if (r.LightViews.Set(light, views) || forgot)
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkShadowMapViews* vtkAbstractShadowMapPass::GetLightViews(vtkLight* light)
{
  vtkShadowMapViews* own = this->Internal->LightViews.Get(light);
  return own ? own : this->Internal->Views.Get();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::SetLightRepresentation(
  vtkLight* light, vtkShadowMapRepresentation* representation)
{
  if (!light)
  {
    vtkWarningMacro(<< "SetLightRepresentation: no light given; nothing changes.");
    return;
  }
  Internals& r = *this->Internal;
  const bool forgot = r.ForgetDeletedLights();
  if (r.LightRepresentations.Set(light, representation) || forgot)
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkShadowMapRepresentation* vtkAbstractShadowMapPass::GetLightRepresentation(vtkLight* light)
{
  vtkShadowMapRepresentation* own = this->Internal->LightRepresentations.Get(light);
  return own ? own : this->Internal->Representation.Get();
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfRepresentationsInUse()
{
  return this->Internal->Groups.Count();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::SetSceneBounds(
  double xMin, double xMax, double yMin, double yMax, double zMin, double zMax)
{
  const double bounds[6] = { xMin, xMax, yMin, yMax, zMin, zMax };
  this->SetSceneBounds(bounds);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::SetSceneBounds(const double bounds[6])
{
  for (int i = 0; i < 6; ++i)
  {
    if (!vtkShadowMapsIsFiniteParameter(this, "SceneBounds", bounds[i]))
    {
      return;
    }
  }
  if (!std::equal(bounds, bounds + 6, this->SceneBounds))
  {
    std::copy(bounds, bounds + 6, this->SceneBounds);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::SetInteractiveTexelRatio(double ratio)
{
  this->GetViews()->SetInteractiveTexelRatio(ratio);
}

//------------------------------------------------------------------------------
double vtkAbstractShadowMapPass::GetInteractiveTexelRatio()
{
  return this->GetViews()->GetInteractiveTexelRatio();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::SetRepresentation(vtkShadowMapRepresentation* representation)
{
  vtkShadowMapRepresentation* chosen =
    representation ? representation : this->Internal->DefaultRepresentation.Get();
  if (chosen != this->Internal->Representation)
  {
    this->Internal->Representation = chosen;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkShadowMapRepresentation* vtkAbstractShadowMapPass::GetRepresentation()
{
  return this->Internal->Representation;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkAbstractShadowMapPass::GetMTime()
{
  const Internals& r = *this->Internal;
  const vtkMTimeType time = std::max(
    { this->Superclass::GetMTime(), r.Views->GetMTime(), r.Representation->GetMTime() });
  return r.LightRepresentations.LatestMTime(r.LightViews.LatestMTime(time));
}

//------------------------------------------------------------------------------
size_t vtkAbstractShadowMapPass::GetShadowMapMemory() const
{
  return this->Internal->Groups.MemoryBytes();
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfShadowedLights() const
{
  return this->Internal->Groups.Statistics().ShadowedLights;
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfShadowMapLayers() const
{
  return this->Internal->Groups.Statistics().Layers;
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfNonFiniteViews() const
{
  return this->Internal->Groups.Statistics().NonFiniteViews;
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfShadowMapUpdates() const
{
  return this->Internal->Groups.Statistics().Updates;
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfCasterDraws() const
{
  return this->Internal->Groups.Statistics().CasterDraws;
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetShadowMapResolution() const
{
  return this->Internal->Groups.Statistics().Resolution;
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfRenderedLayers() const
{
  return this->Internal->Groups.Statistics().RenderedLayers;
}

//------------------------------------------------------------------------------
double vtkAbstractShadowMapPass::GetFrameStepMilliseconds(int step) const
{
  static_assert(NUMBER_OF_FRAME_STEPS == static_cast<int>(shadowmaps::FrameStep::Count),
    "one FrameStepType per shadowmaps::FrameStep");
  if (step < 0 || step >= NUMBER_OF_FRAME_STEPS)
  {
    return 0.0;
  }
  return this->Internal->Groups.Statistics().Steps.Get(static_cast<shadowmaps::FrameStep>(step));
}

//------------------------------------------------------------------------------
const char* vtkAbstractShadowMapPass::GetFrameStepName(int step)
{
  static const char* const names[NUMBER_OF_FRAME_STEPS] = { "reading", "fitting", "storage",
    "shaders", "drawing", "finishing" };
  return step >= 0 && step < NUMBER_OF_FRAME_STEPS ? names[step] : "";
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfCasterPassesPerLayer() const
{
  return this->Internal->Groups.Statistics().CasterPassesPerLayer;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  auto* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkRenderPass* delegate =
    this->DelegatePass ? this->DelegatePass : this->Internal->DefaultDelegate.Get();

  Internals& r = *this->Internal;
  r.Groups.ClearFrameStatistics();
  r.Active = false;
  if (renderer)
  {
    this->UseContextOf(renderer);
    this->SelectRendererMaps(renderer);
    // Kept past the last frame for the props another renderer drew meanwhile.
    this->ReleaseTextureUnits(renderer);
  }
  if (renderer && !this->DelegatePass)
  {
    r.FollowRendererTranslucency(renderer);
  }
  if (renderer && renderer->GetSelector())
  {
    this->RenderForSelection(renderer);
    return;
  }
  r.Active = renderer && this->PrepareShadows(renderer, s);
  if (r.Active)
  {
    this->JoinRenderPasses(s->GetPropArray(), s->GetPropArrayCount());
    r.Groups.BindForReceivers(renderer);
  }
  else
  {
    // Casters that joined before a failure would draw the scene through their
    // casters' branch.
    this->LeaveRenderPasses();
  }
  delegate->Render(s);
  this->NumberOfRenderedProps = delegate->GetNumberOfRenderedProps();
  if (r.Active && this->AnalysisView == SHADOW_MAP)
  {
    this->RenderShadowMapView(renderer);
  }
  if (renderer)
  {
    this->EndFrame(renderer);
  }
  r.Active = false;
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::RenderForSelection(vtkOpenGLRenderer* renderer)
{
  // Picking draws ids, not light, and the maps stay as they are. Without a
  // pass the renderer hands its props (or the ones picked from) to its
  // selector, which gives each its id before drawing it; a delegate's opaque
  // pass would draw them with none, and nothing could be picked.
  this->LeaveRenderPasses();
  this->UpdateCamera(renderer);
  this->UpdateLightGeometry(renderer);
  this->UpdateLights(renderer);
  this->UpdateGeometry(renderer);
  this->NumberOfRenderedProps = renderer->GetNumberOfPropsRendered();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::UseContextOf(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  vtkRenderWindow* window = renderer->GetRenderWindow();
  if (r.Context != window)
  {
    // Moved to another window: what the old context holds is freed there.
    this->ForgetContext();
    window->MakeCurrent();
    r.Context = window;
    // Freed while the window can still make its context current: after its
    // DeleteEvent it is being destroyed.
    r.ContextDeleteObserver =
      window->AddObserver(vtkCommand::DeleteEvent, this, &vtkAbstractShadowMapPass::ForgetContext);
  }
  r.HoldsGraphicsResources = true;
  r.Use->Drawn(renderer);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::SelectRendererMaps(vtkOpenGLRenderer* renderer)
{
  this->Internal->Groups.SelectRenderer(renderer);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReleaseMapsOf(vtkRenderer* renderer)
{
  Internals& r = *this->Internal;
  // Its code no longer counts, whatever maps it holds.
  r.Groups.ForgetCodeOf(renderer);
  if (!r.Context || !r.Groups.HoldsMapsOf(renderer))
  {
    return; // released with the context it was moved from, or never drawn
  }
  // At the end of the renderer's frame its context is current; a renderer
  // being deleted has left its window.
  const bool switches = renderer->GetRenderWindow() != r.Context;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(r.Context.GetPointer());
  if (switches)
  {
    window->PushContext();
  }
  r.Groups.ReleaseMapsOf(renderer, window);
  if (r.Groups.HoldsNoMaps())
  {
    // No renderer draws through the pass any more: it holds nothing.
    this->ReleaseGraphicsResources(window);
  }
  if (switches)
  {
    window->PopContext();
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ForgetContext()
{
  Internals& r = *this->Internal;
  if (!r.Context)
  {
    return;
  }
  // As VTK's own GL objects free themselves: in their context, made current
  // for the time it takes. A window finalized since released what its
  // renderers' passes held (HoldsGraphicsResources is then false).
  if (r.HoldsGraphicsResources)
  {
    auto* window = static_cast<vtkOpenGLRenderWindow*>(r.Context.GetPointer());
    window->PushContext();
    this->ReleaseGraphicsResources(window);
    window->PopContext();
  }
  r.HoldsGraphicsResources = false;
  r.Context->RemoveObserver(r.ContextDeleteObserver);
  r.Context = nullptr;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::JoinRenderPasses(vtkProp* const* props, int count)
{
  // A prop that neither casts nor receives (an annotation, by default) draws
  // as without the pass.
  this->Internal->Joining.Join(props, count, [](vtkProp* prop) {
    return shadowmaps::TakesPart(prop, CASTS_SHADOWS()) ||
      shadowmaps::TakesPart(prop, RECEIVES_SHADOWS());
  });
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::LeaveRenderPasses()
{
  this->Internal->Joining.LeaveAll();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::EndFrame(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  r.Joining.EndFrame(renderer);
  r.Groups.EndFrame();
  if (!r.Joining.KeepsAny())
  {
    this->ReleaseTextureUnits(renderer);
  }
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PrepareShadows(vtkOpenGLRenderer* renderer, const vtkRenderState* s)
{
  Internals& r = *this->Internal;
  shadowmaps::FrameSettings& settings = r.Settings;
  if (r.ForgetDeletedLights())
  {
    this->Modified();
  }
  this->ChooseForFrame(renderer);
  settings.Representation = r.Representation;
  settings.Exchange = this->Exchange;
  settings.UseSceneBounds = this->UseSceneBounds;
  settings.SceneBounds = this->SceneBounds;
  settings.SoftShadows = this->SoftShadows;
  settings.Resolution = this->GetLayerResolution();
  settings.CasterFaces = this->CasterFaces;
  settings.NormalOffset = this->NormalOffset;
  settings.ShadowReachCulling = this->ShadowReachCulling;
  settings.InteractiveUpdateRate = this->InteractiveUpdateRate;
  settings.AnimationKeepsViews = this->AnimationKeepsViews;
  settings.InteractiveResolutionScale = this->InteractiveResolutionScale;
  // Analysis settings are pass parameters: a change re-renders the maps.
  const bool recolours = this->AnalysisView != NO_ANALYSIS && this->AnalysisView != SHADOW_MAP;
  settings.RecolouringAnalysisView = recolours ? this->AnalysisView : 0;
  settings.AnalysisLight = this->AnalysisLight;
  std::vector<vtkShadowMapRepresentation*> assigned{ r.Representation };
  r.LightRepresentations.ForEachValue(
    [&assigned](vtkShadowMapRepresentation* own) { assigned.push_back(own); });
  const bool ready = r.Groups.Prepare(
    renderer, s, settings,
    [this](vtkLight* light) { return this->GetLightRepresentation(light); }, assigned);
  this->WarnAboutUpdate();
  return ready;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ChooseForFrame(vtkOpenGLRenderer*) {}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetLayerResolution()
{
  return this->Resolution;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::WarnAboutUpdate()
{
  for (const std::string& warning : this->Internal->Groups.TakeWarnings())
  {
    vtkWarningMacro(<< warning);
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReleaseTextureUnits(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  r.Groups.ReleaseTextureUnits(window);
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PreReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  // Markers for PostReplaceShaderValues, which knows whether the mapper
  // generated per-light code to patch and how it shapes its fragments.
  shadowmaps::PassShaders::MarkInjectionPoints(fragmentShader);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  using shadowmaps::ReceiverRole;
  const std::vector<shadowmaps::GroupCode> code = this->Internal->Groups.ShaderCode();
  this->Internal->Groups.ShadersBuilt(mapper, prop);
  ++this->NumberOfShaderBuilds;
  // Shaders first built by a caster draw are the ones the scene then uses; a
  // renderer drawing a prop the pass keeps joined (PropJoining) builds them
  // as the pass's renderer would.
  const ReceiverRole role = prop
    ? shadowmaps::ReceiverRoleOf(prop, CASTS_SHADOWS(), RECEIVES_SHADOWS())
    : ReceiverRole::None;
  if (vtkVolume::SafeDownCast(prop))
  {
    shadowmaps::PassShaders::InjectVolume(fragmentShader, code, role != ReceiverRole::None);
    return true;
  }
  int unpatched = 0;
  const shadowmaps::CasterBranch branch = shadowmaps::PassShaders::Inject(vertexShader,
    geometryShader, fragmentShader, code, role != ReceiverRole::None, unpatched,
    role == ReceiverRole::ReceivesWithOwnShare);
  ++(branch == shadowmaps::CasterBranch::DepthOnly ? this->NumberOfDepthOnlyCasterShaders
                                                   : this->NumberOfOwnFragmentCasterShaders);
  if (unpatched > 0 && this->NumberOfUnpatchedReceiverLights == 0)
  {
    vtkWarningMacro(<< "This VTK's mapper lights " << unpatched
                    << " shadowed light(s) in shader code this pass does not know how to patch: "
                       "they cast no shadow on that prop (reported once).");
  }
  this->NumberOfUnpatchedReceiverLights += unpatched;
  return true;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  Internals& r = *this->Internal;
  r.Groups.SetProgramUniforms(program, prop, r.Active, this->NormalOffset);
  return true;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkAbstractShadowMapPass::GetShaderStageMTime()
{
  return this->Internal->Groups.ShaderKeyTime();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::RenderShadowMapView(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  int light = 0;
  shadowmaps::FrameUpdate* update = r.Groups.AnalysedGroup(light);
  if (!update)
  {
    return;
  }
  shadowmaps::RendererMaps& maps = update->Maps();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  const bool twoSurfaces = maps.Storage.SecondDepth != shadowmaps::SecondDepthMethod::None;
  if (!r.MapView.Render(window, maps.Maps, update->Textures().Units().Maps,
        update->Lights()[light], twoSurfaces, maps.Storage.WarpExponent))
  {
    r.Groups.Fail("the shadow-map view shader did not compile", window);
    this->WarnAboutUpdate();
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReleaseGraphicsResources(vtkWindow* window)
{
  Internals& r = *this->Internal;
  r.Joining.LeaveAll();
  if (window == r.Context)
  {
    // The units kept past the last frame are that window's.
    r.Groups.ReleaseTextureUnits(static_cast<vtkOpenGLRenderWindow*>(window));
  }
  r.HoldsGraphicsResources = false;
  r.Groups.ReleaseGraphicsResources(window);
  r.MapView.ReleaseGraphicsResources(window);
  r.Representation->ReleaseGraphicsResources(window);
  if (r.DefaultRepresentation != r.Representation)
  {
    r.DefaultRepresentation->ReleaseGraphicsResources(window);
  }
  r.LightRepresentations.ForEachValue(
    [window](vtkShadowMapRepresentation* own) { own->ReleaseGraphicsResources(window); });
  r.DefaultDelegate->ReleaseGraphicsResources(window);
  r.DepthPeeling->ReleaseGraphicsResources(window);
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "Exchange: " << this->Exchange << "\n";
  os << indent << "UseSceneBounds: " << this->UseSceneBounds << "\n";
  os << indent << "SoftShadows: " << this->SoftShadows << "\n";
  os << indent << "SceneBounds: " << this->SceneBounds[0] << " " << this->SceneBounds[1] << " "
     << this->SceneBounds[2] << " " << this->SceneBounds[3] << " " << this->SceneBounds[4] << " "
     << this->SceneBounds[5] << "\n";
  os << indent << "Views:\n";
  this->Internal->Views->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Lights with views of their own: " << this->Internal->LightViews.Size() << "\n";
  os << indent << "Lights with a representation of their own: "
     << this->Internal->LightRepresentations.Size() << "\n";
  os << indent << "NumberOfRepresentationsInUse: " << this->Internal->Groups.Count() << "\n";
  os << indent << "Representation:\n";
  this->Internal->Representation->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "CasterFaces: " << this->CasterFaces << "\n";
  os << indent << "NormalOffset: " << this->NormalOffset << "\n";
  os << indent << "ShadowReachCulling: " << this->ShadowReachCulling << "\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "AnimationKeepsViews: " << this->AnimationKeepsViews << "\n";
  os << indent << "InteractiveResolutionScale: " << this->InteractiveResolutionScale << "\n";
  os << indent << "AnalysisView: " << this->AnalysisView << "\n";
  os << indent << "AnalysisLight: " << this->AnalysisLight << "\n";
  os << indent << "NumberOfShadowedLights: " << this->GetNumberOfShadowedLights() << "\n";
  os << indent << "NumberOfShadowMapLayers: " << this->GetNumberOfShadowMapLayers() << "\n";
  os << indent << "ShadowMapResolution: " << this->GetShadowMapResolution() << "\n";
  os << indent << "NumberOfNonFiniteViews: " << this->GetNumberOfNonFiniteViews() << "\n";
  os << indent << "NumberOfShadowMapUpdates: " << this->GetNumberOfShadowMapUpdates() << "\n";
  os << indent << "NumberOfCasterDraws: " << this->GetNumberOfCasterDraws() << "\n";
  os << indent << "NumberOfRenderedLayers: " << this->GetNumberOfRenderedLayers() << "\n";
  for (int step = 0; step < NUMBER_OF_FRAME_STEPS; ++step)
  {
    os << indent << "FrameStepMilliseconds(" << GetFrameStepName(step)
       << "): " << this->GetFrameStepMilliseconds(step) << "\n";
  }
  os << indent << "NumberOfShaderBuilds: " << this->NumberOfShaderBuilds << "\n";
  os << indent << "NumberOfUnpatchedReceiverLights: " << this->NumberOfUnpatchedReceiverLights << "\n";
  os << indent << "NumberOfCasterPassesPerLayer: " << this->GetNumberOfCasterPassesPerLayer() << "\n";
}
