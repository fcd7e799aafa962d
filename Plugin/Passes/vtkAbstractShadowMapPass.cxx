#include "vtkAbstractShadowMapPass.h"

#include "ShadowMapAnalysis.h"
#include "ShadowMapCasterShader.h"
#include "ShadowMapCascades.h"
#include "ShadowMapCasterReach.h"
#include "ShadowMapPropRecords.h"
#include "ShadowMapCasting.h"
#include "ShadowMapCombination.h"
#include "ShadowMapFramePolicy.h"
#include "ShadowMapClosedSurfaces.h"
#include "ShadowMapGlm.h"
#include "ShadowMapLayerContent.h"
#include "ShadowMapLayerDrawing.h"
#include "ShadowMapLight.h"
#include "ShadowMapLinearDepthResolve.h"
#include "ShadowMapPropJoining.h"
#include "ShadowMapPropParts.h"
#include "ShadowMapReceiverShader.h"
#include "ShadowMapReceiverTextures.h"
#include "ShadowMapPassShaders.h"
#include "ShadowMapProgramUniforms.h"
#include "ShadowMapRendererMaps.h"
#include "ShadowMapRendererUse.h"
#include "ShadowMapSceneReading.h"
#include "ShadowMapStorageChoice.h"
#include "ShadowMapStoreFromLightDepths.h"
#include "ShadowMapTextureArray.h"
#include "ShadowMapUpdates.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkVolume.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkShadowMapExchange.h"
#include "vtkShadowMapRepresentation.h"
#include "vtkShadowMapViews.h"
#include "vtkSmartPointer.h"
#include "vtkTextureUnitManager.h"
#include "vtkShaderProgram.h"
#include "vtkWeakPointer.h"

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include "ShadowMapVTKCompat.h"

#include <algorithm>
#include <sstream>
#include <array>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <unordered_map>
#include <unordered_set>

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

using shadowmaps::Aabb;
using shadowmaps::Caster;
using shadowmaps::ToGlm;
using shadowmaps::ToVtk;
using shadowmaps::LightKind;
using shadowmaps::LightView;
using shadowmaps::ShadowLight;

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
int MaximumSamples()
{
  GLint samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &samples);
  return std::max(1, static_cast<int>(samples));
}

bool IsNonFinite(const LightView& view)
{
  return !shadowmaps::IsFinite(view.View) || !shadowmaps::IsFinite(view.Projection);
}
} // namespace

struct vtkAbstractShadowMapPass::Internals
{
  // The strategies: the preset's own, or the user's.
  vtkSmartPointer<vtkShadowMapViews> DefaultViews;
  vtkSmartPointer<vtkShadowMapRepresentation> DefaultRepresentation;
  vtkSmartPointer<vtkShadowMapViews> Views;
  vtkSmartPointer<vtkShadowMapRepresentation> Representation;

  // The frame being rendered.
  shadowmaps::ShadowFrame Frame;
  std::vector<shadowmaps::ShadowLight> Lights;
  std::vector<Caster> Casters;

  // What draws the casters into the maps' layers.
  shadowmaps::LayerDrawing Layers;
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
  shadowmaps::ClosedCasters ClosedCasters;
  // What each frame renders, and across processes.
  shadowmaps::FramePolicy Policy;

  // The maps of each renderer (and eye) that draws through the pass; Maps()
  // are the ones of the frame being rendered.
  shadowmaps::MapsByRenderer Renderers;
  shadowmaps::RendererMaps& Maps() { return *this->Renderers.Current(); }
  const shadowmaps::RendererMaps& Maps() const { return *this->Renderers.Current(); }
  // The maps whose lights, layers and storage the shader code was made for.
  const shadowmaps::RendererMaps* CodeFor = nullptr;

  // The shadow code in the mappers' shaders, the same for every renderer's
  // maps, and what the pass sets on their programs.
  shadowmaps::PassShaders Shaders;
  shadowmaps::ProgramUniforms Programs;
  // Whether each prop received shadows (and held its own transmittance) when
  // it last drew through the pass: what its shaders were built for.
  std::unordered_map<vtkProp*, std::pair<vtkWeakPointer<vtkProp>, vtkAbstractShadowMapPass::ReceiverRole>>
    Receives;
  // The units the receivers' samplers read, from the casters' draws to the
  // end of the frame.
  shadowmaps::ReceiverTextures Textures;
  bool ShaderCodeCompiles = true;
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

  bool Active = false;
  bool Casting = false;
  // The GL state of the casters' draws, while they draw.
  shadowmaps::CasterGLState* CastingState = nullptr;
  bool SceneCameraParallel = false;
  // The most samples per texel the context offers (GL_MAX_SAMPLES), asked
  // once, and only by maps that may be multisampled.
  int MaximumSamples = 0;
  bool WarnedTooManyLights = false;
  /// The last warning about light sizes, so that a frame repeats none.
  std::string WarnedLightSizes;
  bool WarnedNonFiniteViews = false;
  bool WarnedResolution = false;
  std::string LastGLError;
  std::string WarnedGLError;
  /// What kept a volume from casting, once warned: its data, or the GL.
  std::string WarnedVolume;
  /// Whether this process's casters (or, with an exchange, any process's)
  /// draw into the transmittance maps.
  bool TranslucentOnAnyProcess = false;
  /// Each shadowed light's share of the lights' intensity, for the volumes
  /// that receive (ReceiverShader::InjectVolume).
  std::vector<float> LightShares;
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
  return std::max({ this->Superclass::GetMTime(), this->Internal->Views->GetMTime(),
    this->Internal->Representation->GetMTime() });
}

//------------------------------------------------------------------------------
size_t vtkAbstractShadowMapPass::GetShadowMapMemory() const
{
  return this->Internal->Renderers.MemoryBytes();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  auto* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkRenderPass* delegate =
    this->DelegatePass ? this->DelegatePass : this->Internal->DefaultDelegate.Get();

  Internals& r = *this->Internal;
  this->NumberOfRenderedLayers = 0;
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
    this->BindShadowTextures(renderer);
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
  this->Internal->Renderers.Select(renderer);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReleaseMapsOf(vtkRenderer* renderer)
{
  Internals& r = *this->Internal;
  if (!r.Context || !r.Renderers.Holds(renderer))
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
  r.Renderers.Release(renderer, window, [&r](const shadowmaps::RendererMaps* maps) {
    r.CodeFor = r.CodeFor == maps ? nullptr : r.CodeFor;
    r.Programs.Forget(maps);
  });
  if (r.Renderers.Empty())
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
  r.Programs.EndFrame();
  if (!r.Joining.KeepsAny())
  {
    this->ReleaseTextureUnits(renderer);
  }
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PrepareShadows(vtkOpenGLRenderer* renderer, const vtkRenderState* s)
{
  renderer->UpdateLightsGeometryToFollowCamera();
  this->CollectLights(renderer);
  this->NumberOfShadowedLights = static_cast<int>(this->Internal->Lights.size());
  if (this->Internal->Lights.empty())
  {
    this->NumberOfShadowMapLayers = 0;
    return false;
  }
  this->CollectCastersAndCamera(renderer);
  this->RebuildShadersOfChangedReceivers(s);
  const bool ready = this->UpdateShadowMaps(renderer);
  // Lights whose views were not finite are gone by now.
  this->NumberOfShadowedLights = static_cast<int>(this->Internal->Lights.size());
  return ready;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::CollectLights(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  int skipped = 0;
  std::vector<vtkLight*> clamped;
  r.Lights = shadowmaps::CollectShadowedLights(
    renderer, CASTS_SHADOWS(), LIGHT_SIZE(), VTK_MAX_SHADOWED_LIGHTS, skipped, clamped);
  if (skipped > 0 && !r.WarnedTooManyLights)
  {
    vtkWarningMacro(<< skipped << " light(s) beyond the first " << VTK_MAX_SHADOWED_LIGHTS
                    << " shadowed lights cast no shadows; they still light the scene.");
  }
  r.WarnedTooManyLights = skipped > 0;
  this->WarnAboutLightSizes(clamped);
  r.LightShares = shadowmaps::IntensityShares(renderer, r.Lights);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::WarnAboutLightSizes(const std::vector<vtkLight*>& clamped)
{
  Internals& r = *this->Internal;
  std::ostringstream warning;
  if (!clamped.empty())
  {
    const double stored = shadowmaps::StoredLightSize(clamped.front(), LIGHT_SIZE());
    warning << clamped.size()
            << " light(s) have a LIGHT_SIZE (or OSPRay radius) that is not finite, negative, or a "
               "sun wider than "
            << shadowmaps::WidestSun << " degrees: the first's " << stored << " is taken as "
            << shadowmaps::LightSizeOf(clamped.front(), LIGHT_SIZE()) << ". ";
  }
  // Asked of the representation only with a sized light: its storage and soft
  // code are strings built on each call.
  bool soft = this->SoftShadows &&
    std::any_of(r.Lights.begin(), r.Lights.end(),
      [](const shadowmaps::ShadowLight& light) { return light.Size > 0.0; });
  if (soft)
  {
    // Depth textures' soft shadows read their depths through a sampler object.
    shadowmaps::MapStorage storage;
    r.Representation->GetMapStorage(storage);
    if (shadowmaps::IsDepth(storage.Format) && !shadowmaps::SamplerObjectsAvailable())
    {
      warning << "This OpenGL has no sampler objects (3.3): lights with a LIGHT_SIZE cast hard "
                 "shadows from depth maps.";
      soft = false;
    }
    else if (!r.Representation->GetSupportsSizedLights())
    {
      warning << r.Representation->GetClassName()
              << " draws hard shadows of lights with a LIGHT_SIZE in its present settings: soft "
                 "shadows come from depth maps, dual-depth maps and mipmapped VSM, EVSM4 and MSM "
                 "moments.";
      soft = false;
    }
  }
  if (!soft)
  {
    for (shadowmaps::ShadowLight& light : r.Lights)
    {
      light.Size = 0.0; // hard shadows
    }
  }
  if (!warning.str().empty() && warning.str() != r.WarnedLightSizes)
  {
    vtkWarningMacro(<< warning.str());
  }
  r.WarnedLightSizes = warning.str();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::CollectCastersAndCamera(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  shadowmaps::ShadowFrame& frame = r.Frame;
  const shadowmaps::SceneCamera camera = shadowmaps::ReadSceneCamera(renderer, frame);
  r.SceneCameraParallel = camera.Parallel;
  r.Programs.SetDrawnRadius(camera.DrawnRadius);
  const std::string unmarchedVolume = shadowmaps::CollectProps(
    renderer, camera.Sizing, CASTS_SHADOWS(), r.Maps().Props, frame, r.Casters);
  r.Maps().Volumes.KeepOnly(CastingVolumes(r.Casters));
  this->WarnAboutVolume(unmarchedVolume);

  const Aabb given = Aabb::FromBounds(this->SceneBounds);
  if (this->UseSceneBounds && given.IsUsable())
  {
    // The same on every process of a parallel renderer, whatever piece it
    // holds; with an exchange, GatherPropBounds gives the fits every
    // process's props.
    frame.SceneBounds = given;
    if (!this->Exchange)
    {
      frame.PropBounds.assign(1, given);
    }
  }
  frame.FilterReachTexels = r.Representation->GetFilterReachTexels();
  frame.Interactive = this->InteractiveUpdateRate < VTK_DOUBLE_MAX &&
    renderer->GetRenderWindow()->GetDesiredUpdateRate() >= this->InteractiveUpdateRate;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::UpdateShadowMaps(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  shadowmaps::RendererMaps& maps = r.Maps();
  r.Policy.SetExchange(this->Exchange);
  const bool boundsGiven = this->UseSceneBounds && Aabb::FromBounds(this->SceneBounds).IsUsable();
  r.TranslucentOnAnyProcess = r.Policy.BeginFrame(r.Frame, r.Casters, boundsGiven);
  this->WarnAboutPolicy();
  std::vector<vtkMTimeType> signature = shadowmaps::FramePolicy::Signature(
    renderer, this->GetMTime(), r.Frame, r.Lights, r.Casters);
  if (!r.Policy.MustRender(maps.Updates, signature))
  {
    // CollectLights rebuilt the lights without views; the maps hold these.
    r.Lights = maps.Updates.GetRenderedLights();
    this->NumberOfShadowMapLayers = maps.Layers;
    if (r.CodeFor != &maps)
    {
      // The shaders follow the lights, layers and storage of the renderer
      // they draw for: another renderer's may differ.
      this->UpdateShaders(renderer);
    }
    return true;
  }

  r.Frame.Resolution = this->UsableResolution();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  // Each failure still answers the other processes' question (CombineAcrossProcesses).
  if (!this->FitViews())
  {
    this->CombineAcrossProcesses(window, false);
    return false;
  }
  this->ChooseStorage();
  this->UpdateShaders(renderer);
  if (!r.ShaderCodeCompiles)
  {
    this->CombineAcrossProcesses(window, false);
    this->ReportGLFailure("the shadow shader code does not compile (see the shader error above; a "
                          "representation's GLSL?)");
    return false;
  }
  std::string error;
  if (!maps.Maps.Reserve(r.Frame.Resolution, this->NumberOfShadowMapLayers, maps.Storage.Format,
        maps.Storage.Mipmaps, error) ||
    !this->ReserveTransmittanceMaps(error))
  {
    this->CombineAcrossProcesses(window, false);
    this->ReportGLFailure(error);
    return false;
  }
  if (!this->RenderShadowMaps(renderer))
  {
    this->ReportGLFailure(r.LastGLError);
    return false;
  }
  if (!shadowmaps::NeedsSecondOutput(maps.Storage, this->MapCombination(), r.Lights))
  {
    maps.Maps.ReleaseSecondOutput();
  }
  if (maps.Storage.Samples <= 1)
  {
    maps.Maps.ReleaseSamples();
  }
  maps.Uniforms.Pack(r.Lights, r.Frame.CameraView);
  maps.Updates.Finish(
    r.Lights, std::move(signature), this->GetMTime(), r.Frame.Resolution, r.Frame.SceneBounds);
  maps.Layers = this->NumberOfShadowMapLayers;
  r.WarnedGLError.clear();
  ++this->NumberOfShadowMapUpdates;
  return true;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::ReserveTransmittanceMaps(std::string& error)
{
  Internals& r = *this->Internal;
  shadowmaps::RendererMaps& maps = r.Maps();
  if (!maps.Storage.Transmittance)
  {
    maps.Transmittances.Release();
    return true;
  }
  return maps.Transmittances.Reserve(r.Frame.Resolution, this->NumberOfShadowMapLayers, error);
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::UsableResolution()
{
  Internals& r = *this->Internal;
  GLint maximumSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maximumSize);
  const int usable = std::min(this->Resolution, std::max(static_cast<int>(maximumSize), 64));
  if (usable != this->Resolution && !r.WarnedResolution)
  {
    vtkWarningMacro(<< "Resolution " << this->Resolution
                    << " exceeds the GL maximum texture size; using " << usable << ".");
    r.WarnedResolution = true;
  }
  return usable;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::FitViews()
{
  Internals& r = *this->Internal;
  for (ShadowLight& light : r.Lights)
  {
    const ShadowLight* kept = r.Maps().Updates.KeptLight(
      light, this->GetMTime(), r.Frame.Resolution, r.Frame.SceneBounds);
    light.LastViews = kept ? kept->Views : std::vector<shadowmaps::LightView>{};
    light.LastFaceSelection = kept ? kept->FaceSelection : std::vector<double>{};
    r.Views->FitLight(r.Frame, light);
    light.LastViews.clear();
    light.LastFaceSelection.clear();
    light.Depth = light.Kind == LightKind::Directional
      ? shadowmaps::DirectionalLightDepth(light.Direction, r.Frame.SceneBounds)
      : shadowmaps::PositionalLightDepth(light.Position, r.Frame.SceneBounds);
  }
  this->DropLightsWithoutUsableViews();
  this->AssignLayers();
  return !r.Lights.empty();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::AssignLayers()
{
  int layers = 0;
  for (ShadowLight& light : this->Internal->Lights)
  {
    light.FirstLayer = layers;
    layers += static_cast<int>(light.Views.size());
  }
  this->NumberOfShadowMapLayers = layers;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ChooseStorage()
{
  Internals& r = *this->Internal;
  shadowmaps::RendererMaps& maps = r.Maps();
  r.Representation->GetMapStorage(maps.Storage);
  shadowmaps::StorageLimits limits;
  limits.CombinesAcrossProcesses = this->Exchange != nullptr;
  limits.ThirtyTwoBitDepthNow =
    maps.Maps.GetResolution() != 0 && maps.Maps.GetFormat() == shadowmaps::TexelFormat::Depth;
  if (maps.Storage.Samples > 1 && r.MaximumSamples <= 0)
  {
    r.MaximumSamples = MaximumSamples();
  }
  limits.MaximumSamples = std::max(r.MaximumSamples, 1);
  shadowmaps::CompleteStorage(maps.Storage, r.Lights, r.Casters, r.ClosedCasters, limits);
  maps.Storage.Transmittance = r.TranslucentOnAnyProcess;
  this->NumberOfCasterPassesPerLayer =
    shadowmaps::CasterPassesPerLayer(maps.Storage) + (maps.Storage.Transmittance ? 1 : 0);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::UpdateShaders(vtkOpenGLRenderer* renderer)
{
  // Before the casters draw: they build the shaders the scene then uses.
  Internals& r = *this->Internal;
  shadowmaps::ShaderChoices choices;
  choices.CasterFaces = this->CasterFaces;
  // Analysis settings are pass parameters: a change re-renders the maps.
  const bool recolours = this->AnalysisView != NO_ANALYSIS && this->AnalysisView != SHADOW_MAP;
  choices.AnalysisView = recolours ? this->AnalysisView : 0;
  choices.AnalysisLight = this->AnalysisLight;
  choices.KeepsLightDepths =
    this->MapCombination() == shadowmaps::Combination::NearestLightDepths;
  r.CodeFor = &r.Maps();
  if (r.Shaders.Update(r.Maps().Storage, r.Representation, r.Lights,
        this->NumberOfShadowMapLayers, choices))
  {
    auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
    r.ShaderCodeCompiles = r.Shaders.Compiles(window, r.Lights, this->NumberOfShadowMapLayers);
  }
}

//------------------------------------------------------------------------------
shadowmaps::CastingSettings vtkAbstractShadowMapPass::CastingSettingsOfUpdate()
{
  Internals& r = *this->Internal;
  const shadowmaps::DepthOffset offset = r.Representation->GetCasterDepthOffset();
  shadowmaps::CastingSettings settings;
  settings.Resolution = r.Frame.Resolution;
  settings.Depth16 = r.Maps().Storage.Format == shadowmaps::TexelFormat::Depth16;
  const shadowmaps::CasterCode& code = r.Shaders.GetCasterCode();
  settings.LightDepth = code.LightDepth || code.Transmittance;
  settings.SlopeScaledOffset = offset.SlopeScaled;
  settings.ConstantOffset = offset.Constant;
  settings.SceneCameraParallel = r.SceneCameraParallel;
  settings.StoreUniforms = r.Maps().Storage.StoreUniforms;
  return settings;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::DropLightsWithoutUsableViews()
{
  std::vector<ShadowLight>& lights = this->Internal->Lights;
  const std::size_t before = lights.size();
  this->NumberOfNonFiniteViews = 0;
  int withoutViews = 0;
  lights.erase(std::remove_if(lights.begin(), lights.end(),
                 [this, &withoutViews](const ShadowLight& light) {
                   const auto nonFinite = std::count_if(light.Views.begin(), light.Views.end(), IsNonFinite);
                   this->NumberOfNonFiniteViews += static_cast<int>(nonFinite);
                   withoutViews += light.Views.empty() ? 1 : 0;
                   return nonFinite > 0 || light.Views.empty();
                 }),
    lights.end());
  if (lights.size() == before)
  {
    this->Internal->WarnedNonFiniteViews = false;
    return;
  }
  if (!this->Internal->WarnedNonFiniteViews)
  {
    // A views strategy of the user's may leave a light without views.
    vtkWarningMacro(<< this->NumberOfNonFiniteViews
                    << " light view(s) came out with non-finite matrices and " << withoutViews
                    << " light(s) got no view from " << this->Internal->Views->GetClassName()
                    << "; these lights cast no shadows until their views are usable again.");
    this->Internal->WarnedNonFiniteViews = true;
  }
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::RenderShadowMaps(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  shadowmaps::RendererMaps& maps = r.Maps();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  const bool keepsLightDepths =
    this->MapCombination() == shadowmaps::Combination::NearestLightDepths;
  // What every layer depends on besides its view and casters: the parameters
  // of the pass and its strategies (the bias, the caster faces and store code
  // among them), the storage, and how a second depth is made (AUTO may change
  // it when some other layer's casters change). Layers that hold every
  // process's casters combined are all rendered and combined again.
  maps.Updates.BeginUpdate({ this->GetMTime(), maps.Maps.GetAllocations(),
                             maps.Transmittances.GetAllocations(),
                             static_cast<vtkMTimeType>(r.Frame.Resolution),
                             static_cast<vtkMTimeType>(maps.Storage.SecondDepth) },
    this->NumberOfShadowMapLayers, r.Policy.CombinesLayers(maps.Storage), r.Casters);
  if (keepsLightDepths)
  {
    maps.LightDepths.Reset(maps.Maps, this->NumberOfShadowMapLayers);
  }
  std::vector<shadowmaps::RenderedLayer> rendered;
  bool ok = true;
  {
    shadowmaps::CasterGLState casterState(window->GetState(),
      !shadowmaps::IsDepth(maps.Storage.Format) && maps.Storage.MinimumBlending);
    this->ReserveTextureUnits(renderer);
    r.Casting = true;
    r.CastingState = &casterState;
    shadowmaps::LayerDrawing::Update update;
    update.Renderer = renderer;
    update.Maps = &maps;
    update.Frame = &r.Frame;
    update.Programs = &r.Programs;
    update.Casting = this->CastingSettingsOfUpdate();
    update.KeepsLightDepths = keepsLightDepths;
    update.PeelUnit = r.Textures.GetPeelUnit();
    update.JoinCasters = [this](vtkProp* const* props, int count) {
      this->JoinRenderPasses(props, count);
    };
    r.Layers.BeginUpdate(update);
    r.Policy.BeginLayers(r.Frame, maps.Storage, this->LayerRulesOfUpdate());
    for (const ShadowLight& light : r.Lights)
    {
      for (size_t v = 0; v < light.Views.size() && ok; ++v)
      {
        const int layer = light.FirstLayer + static_cast<int>(v);
        shadowmaps::LayerPlan plan =
          maps.Updates.Plan(r.Frame, r.Casters, r.Policy.RequestFor(light, v));
        bool bound = false;
        ok = !plan.Render || r.Layers.Draw(light, v, layer, plan.Casters, bound, r.LastGLError);
        if (bound)
        {
          maps.Updates.Rendered(layer, std::move(plan));
          rendered.push_back({ layer, shadowmaps::FilterScale(light, v) });
        }
      }
    }
    r.Casting = false;
    r.CastingState = nullptr;
    r.Layers.EndUpdate();
  }
  for (const std::string& warning : r.Layers.TakeWarnings())
  {
    vtkWarningMacro(<< warning);
  }
  this->NumberOfRenderedLayers = static_cast<int>(rendered.size());
  if (!rendered.empty())
  {
    this->NumberOfCasterDraws = r.Layers.GetDraws();
  }
  ok = this->CombineAcrossProcesses(window, ok);
  if (!ok)
  {
    maps.Updates.Invalidate();
    return false;
  }
  return rendered.empty() || this->PostProcessShadowMaps(renderer, rendered);
}

//------------------------------------------------------------------------------
shadowmaps::LayerRules vtkAbstractShadowMapPass::LayerRulesOfUpdate()
{
  Internals& r = *this->Internal;
  shadowmaps::LayerRules rules;
  rules.ReachCulling = this->ShadowReachCulling;
  rules.ViewsMayBeKept = this->GetViews()->MayKeepViews(r.Frame);
  rules.NormalOffsetTexels = this->NormalOffset;
  rules.PostProcessingFollowsFilterScale = r.Representation->GetPostProcessingFollowsFilterScale();
  return rules;
}

//------------------------------------------------------------------------------
shadowmaps::Combination vtkAbstractShadowMapPass::MapCombination() const
{
  return this->Internal->Policy.CombinationFor(this->Internal->Maps().Storage);
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::CombineAcrossProcesses(vtkOpenGLRenderWindow* window, bool ok)
{
  Internals& r = *this->Internal;
  const bool combined = r.Policy.Combine(
    window, r.Maps(), this->NumberOfShadowMapLayers, r.Frame.Resolution, ok, r.LastGLError);
  this->WarnAboutPolicy();
  return combined;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::WarnAboutPolicy()
{
  for (const std::string& warning : this->Internal->Policy.TakeWarnings())
  {
    vtkWarningMacro(<< warning);
  }
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PostProcessShadowMaps(
  vtkOpenGLRenderer* renderer, const std::vector<shadowmaps::RenderedLayer>& rendered)
{
  Internals& r = *this->Internal;
  if (!r.Representation->PostProcessMaps(renderer, r.Maps().Maps, rendered))
  {
    r.LastGLError = "the shadow maps could not be post-processed";
    return false;
  }
  r.Maps().Maps.GenerateMipmaps();
  return true;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::WarnAboutVolume(const std::string& why)
{
  // A volume that cannot be marched casts nothing; the others still do.
  // Warned again once the scene has had none such.
  Internals& r = *this->Internal;
  if (!why.empty() && why != r.WarnedVolume)
  {
    vtkWarningMacro(<< "A volume casts no shadow: " << why << ".");
  }
  r.WarnedVolume = why;
}

//------------------------------------------------------------------------------
vtkAbstractShadowMapPass::ReceiverRole vtkAbstractShadowMapPass::ReceiverRoleOf(vtkProp* prop) const
{
  if (!shadowmaps::TakesPart(prop, RECEIVES_SHADOWS()))
  {
    return ReceiverRole::None;
  }
  return shadowmaps::HoldsItsOwnTransmittance(prop, CASTS_SHADOWS())
    ? ReceiverRole::ReceivesWithOwnShare
    : ReceiverRole::Receives;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::RebuildShadersOfChangedReceivers(const vtkRenderState* s)
{
  // A prop's shaders hold its receiving code or not: only a prop whose
  // RECEIVES_SHADOWS (or HoldsItsOwnTransmittance) changed since it last drew
  // here builds them again. Props
  // entering or leaving the view, receivers or not, change no shader.
  Internals& r = *this->Internal;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    const ReceiverRole receives = this->ReceiverRoleOf(prop);
    auto known = r.Receives.find(prop);
    if (known == r.Receives.end() || known->second.first != prop)
    {
      r.Receives[prop] = { prop, receives };
      continue;
    }
    if (known->second.second != receives)
    {
      known->second.second = receives;
      shadowmaps::RebuildShaders(prop);
    }
  }
  // Forget deleted props.
  for (auto it = r.Receives.begin(); it != r.Receives.end();)
  {
    it = it->second.first ? std::next(it) : r.Receives.erase(it);
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReserveTextureUnits(vtkOpenGLRenderer* renderer)
{
  // Before the casters draw: they share the receivers' programs.
  Internals& r = *this->Internal;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  const shadowmaps::MapStorage& storage = r.Maps().Storage;
  if (r.Textures.Reserve(window, storage, this->ReadsRawDepths(), r.Representation) &&
    storage.SecondDepth == shadowmaps::SecondDepthMethod::Peeling)
  {
    r.Programs.SetPeeling(false, r.Textures.GetPeelUnit());
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::BindShadowTextures(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  this->ReserveTextureUnits(renderer);
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  r.Textures.Bind(window, r.Maps(), r.Representation);
  r.Maps().Uniforms.NewFrame();
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::ReadsRawDepths() const
{
  const Internals& r = *this->Internal;
  return shadowmaps::IsDepth(r.Maps().Storage.Format) &&
    std::any_of(r.Lights.begin(), r.Lights.end(),
      [](const shadowmaps::ShadowLight& light) { return light.Size > 0.0; });
}

//------------------------------------------------------------------------------
shadowmaps::ReceiverTextureUnits vtkAbstractShadowMapPass::ReceiverUnits() const
{
  return this->Internal->Textures.Units();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReleaseTextureUnits(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  r.Textures.Release(window, r.Representation);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReportGLFailure(const std::string& error)
{
  Internals& r = *this->Internal;
  r.Maps().ReleaseGraphicsResources(r.Context);
  this->NumberOfShadowMapLayers = 0;
  if (error != r.WarnedGLError)
  {
    vtkWarningMacro(<< "Rendering without shadows: " << error);
    r.WarnedGLError = error;
  }
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
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  const Internals& r = *this->Internal;
  ++this->NumberOfShaderBuilds;
  // Shaders first built by a caster draw are the ones the scene then uses; a
  // renderer drawing a prop the pass keeps joined (PropJoining) builds them
  // as the pass's renderer would.
  const ReceiverRole role = prop ? this->ReceiverRoleOf(prop) : ReceiverRole::None;
  if (vtkVolume::SafeDownCast(prop))
  {
    r.Shaders.InjectVolume(
      fragmentShader, r.Lights, this->NumberOfShadowMapLayers, role != ReceiverRole::None);
    return true;
  }
  int unpatched = 0;
  const shadowmaps::CasterBranch branch = r.Shaders.Inject(vertexShader, geometryShader,
    fragmentShader, r.Lights, this->NumberOfShadowMapLayers, role != ReceiverRole::None,
    unpatched, role == ReceiverRole::ReceivesWithOwnShare);
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
  if (r.Casting)
  {
    r.CastingState->UseProgramPointSize(shadowmaps::ImpostorShader::IsSized(program));
    r.Programs.Casting(program, this->ReceiverUnits(), r.Representation);
  }
  else if (r.Active)
  {
    r.Programs.Receiving(
      program, r.Maps(), this->ReceiverUnits(), r.Frame.Resolution, this->NormalOffset,
      r.Representation);
    if (vtkVolume::SafeDownCast(prop) && !r.LightShares.empty())
    {
      program->SetUniform1fv("vtkShadowVolumeLightShares", static_cast<int>(r.LightShares.size()),
        r.LightShares.data());
    }
  }
  else
  {
    r.Programs.DrawnWithoutThePass(program, this->ReceiverUnits(), r.Representation);
  }
  return true;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkAbstractShadowMapPass::GetShaderStageMTime()
{
  return this->Internal->Shaders.GetKeyTime();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::RenderShadowMapView(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  shadowmaps::RendererMaps& maps = r.Maps();
  if (this->AnalysisLight >= static_cast<int>(r.Lights.size()))
  {
    return;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  const bool twoSurfaces = maps.Storage.SecondDepth != shadowmaps::SecondDepthMethod::None;
  if (!r.MapView.Render(window, maps.Maps, r.Textures.Units().Maps, r.Lights[this->AnalysisLight], twoSurfaces,
        maps.Storage.WarpExponent))
  {
    this->ReportGLFailure("the shadow-map view shader did not compile");
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
    r.Textures.Release(static_cast<vtkOpenGLRenderWindow*>(window), r.Representation);
  }
  r.HoldsGraphicsResources = false;
  r.Renderers.ReleaseAll(window);
  r.CodeFor = nullptr;
  r.MapView.ReleaseGraphicsResources(window);
  r.Representation->ReleaseGraphicsResources(window);
  if (r.DefaultRepresentation != r.Representation)
  {
    r.DefaultRepresentation->ReleaseGraphicsResources(window);
  }
  r.Programs.Clear();
  r.MaximumSamples = 0;
  r.Layers.ReleaseGraphicsResources(window);
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
  os << indent << "Representation:\n";
  this->Internal->Representation->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "CasterFaces: " << this->CasterFaces << "\n";
  os << indent << "NormalOffset: " << this->NormalOffset << "\n";
  os << indent << "ShadowReachCulling: " << this->ShadowReachCulling << "\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "AnalysisView: " << this->AnalysisView << "\n";
  os << indent << "AnalysisLight: " << this->AnalysisLight << "\n";
  os << indent << "NumberOfShadowedLights: " << this->NumberOfShadowedLights << "\n";
  os << indent << "NumberOfShadowMapLayers: " << this->NumberOfShadowMapLayers << "\n";
  os << indent << "NumberOfNonFiniteViews: " << this->NumberOfNonFiniteViews << "\n";
  os << indent << "NumberOfShadowMapUpdates: " << this->NumberOfShadowMapUpdates << "\n";
  os << indent << "NumberOfCasterDraws: " << this->NumberOfCasterDraws << "\n";
  os << indent << "NumberOfRenderedLayers: " << this->NumberOfRenderedLayers << "\n";
  os << indent << "NumberOfShaderBuilds: " << this->NumberOfShaderBuilds << "\n";
  os << indent << "NumberOfUnpatchedReceiverLights: " << this->NumberOfUnpatchedReceiverLights << "\n";
  os << indent << "NumberOfCasterPassesPerLayer: " << this->NumberOfCasterPassesPerLayer << "\n";
}
