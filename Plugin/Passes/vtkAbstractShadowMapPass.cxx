#include "vtkAbstractShadowMapPass.h"

#include "ShadowMapAnalysis.h"
#include "ShadowMapCasterShader.h"
#include "ShadowMapCascades.h"
#include "ShadowMapCasterReach.h"
#include "ShadowMapCasting.h"
#include "ShadowMapCombination.h"
#include "ShadowMapClosedSurfaces.h"
#include "ShadowMapGlm.h"
#include "ShadowMapLayerContent.h"
#include "ShadowMapLight.h"
#include "ShadowMapLinearDepthResolve.h"
#include "ShadowMapReceiverShader.h"
#include "ShadowMapStoreFromLightDepths.h"
#include "ShadowMapTextureArray.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkHardwareSelector.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
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
#include "vtkVolume.h"

#include <glm/gtc/matrix_transform.hpp>
#include "ShadowMapVTKCompat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <unordered_set>

vtkInformationKeyMacro(vtkAbstractShadowMapPass, CASTS_SHADOWS, Integer);
vtkInformationKeyMacro(vtkAbstractShadowMapPass, RECEIVES_SHADOWS, Integer);

using shadowmaps::Aabb;
using shadowmaps::ToGlm;
using shadowmaps::ToVtk;
using shadowmaps::LightKind;
using shadowmaps::LightView;
using shadowmaps::ShadowLight;

namespace
{

// An absent key means yes.
bool IsEnabled(vtkInformation* info, vtkInformationIntegerKey* key)
{
  return !info || !info->Has(key) || info->Get(key) != 0;
}

bool HasRenderPass(vtkInformation* info, vtkObjectBase* pass)
{
  vtkInformationObjectBaseVectorKey* key = vtkOpenGLRenderPass::RenderPasses();
  for (int i = 0; info->Has(key) && i < info->Length(key); ++i)
  {
    if (info->Get(key, i) == pass)
    {
      return true;
    }
  }
  return false;
}

bool FrustumMeetsBox(const std::array<shadowmaps::Plane, 6>& planes, const Aabb& box)
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

// Views out of view hold no shadows, whatever their precision. Depth maps that
// are 32-bit go to 16 bits only with twice the margin, so that a camera hovering
// at the threshold does not reallocate the maps, and move the shadows' contacts
// by the bias of the other format, every frame. Maps not allocated (new, or
// released after a GL failure) and value maps take the 16-bit rule.
bool SixteenBitDepthSuffices(const std::vector<ShadowLight>& lights, bool thirtyTwoBitNow)
{
  const double stepsPerTexel = thirtyTwoBitNow ? 32.0 : 16.0;
  return std::all_of(lights.begin(), lights.end(), [&](const ShadowLight& light) {
    return std::all_of(light.Views.begin(), light.Views.end(), [&](const LightView& view) {
      return view.OutOfView || shadowmaps::SixteenBitDepthSuffices(view, stepsPerTexel);
    });
  });
}

// The most samples GL offers per texel of a multisample buffer.
int MaximumSamples()
{
  GLint samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &samples);
  return std::max(1, static_cast<int>(samples));
}

// Window coordinates (pixels of a resolution^2 map, window depth) to world.
glm::dmat4 WindowToWorld(const LightView& view, int resolution)
{
  const double half = 0.5 * resolution;
  glm::dmat4 viewport(1.0);
  viewport[0][0] = viewport[1][1] = half;
  viewport[3][0] = viewport[3][1] = half;
  viewport[2][2] = 0.5;
  viewport[3][2] = 0.5;
  return glm::inverse(viewport * view.ViewProjection());
}

bool AnyLinearDepthView(const std::vector<ShadowLight>& lights)
{
  return std::any_of(lights.begin(), lights.end(), [](const ShadowLight& light) {
    return std::any_of(light.Views.begin(), light.Views.end(),
      [](const LightView& view) { return view.LinearDepth; });
  });
}

bool IsNonFinite(const LightView& view)
{
  return !shadowmaps::IsFinite(view.View) || !shadowmaps::IsFinite(view.Projection);
}

// The bits of a matrix, so that the signature follows the camera's values
// rather than its identity or MTime (image-processing passes hand their
// delegate a fresh copy of the camera every frame).
void AppendBits(double value, std::vector<vtkMTimeType>& signature)
{
  vtkMTimeType bits = 0;
  std::memcpy(&bits, &value, sizeof(double));
  signature.push_back(bits);
}

void AppendBoxBits(const Aabb& box, std::vector<vtkMTimeType>& signature)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    AppendBits(box.Min[axis], signature);
    AppendBits(box.Max[axis], signature);
  }
}

void AppendMatrixBits(const glm::dmat4& m, std::vector<vtkMTimeType>& signature)
{
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      AppendBits(m[c][r], signature);
    }
  }
}

// Modification time of everything a caster's depth depends on, including its
// mapper's input after bringing the pipeline up to date (composite inputs too).
vtkMTimeType CasterMTime(vtkProp* prop)
{
  vtkMTimeType time = prop->GetRedrawMTime();
  auto* actor = vtkActor::SafeDownCast(prop);
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  if (mapper && mapper->GetNumberOfInputPorts() > 0 && mapper->GetNumberOfInputConnections(0) > 0)
  {
    mapper->GetInputAlgorithm()->Update();
    if (vtkDataObject* input = mapper->GetInputDataObject(0, 0))
    {
      time = std::max(time, input->GetMTime());
    }
  }
  return time;
}

// A prop that renders into the maps, with its world bounds and the
// modification time of everything its depth depends on.
struct Caster
{
  vtkProp* Prop = nullptr;
  Aabb Bounds;
  vtkMTimeType MTime = 0;
};

// Volumes keep vtkProp's default HasOpaqueGeometry() but draw nothing into a
// depth map; as casters they would only re-render the maps on every transfer
// function edit.
bool DrawsIntoDepthMaps(vtkProp* prop)
{
  return prop->HasOpaqueGeometry() && !vtkVolume::SafeDownCast(prop);
}

// The part of `visible` (the focus body; empty when culling is off) whose
// receivers `view` shades: a cascade's slice of it.
std::vector<glm::dvec3> ShadedBody(const shadowmaps::ShadowFrame& frame, const LightView& view,
  const std::vector<glm::dvec3>& visible)
{
  const glm::dvec2 depths = view.ShadedDepths;
  if (visible.empty() || !std::isfinite(depths.y))
  {
    return visible;
  }
  const glm::dmat4 slice = shadowmaps::SubFrustumProjection(frame.CameraProjection, depths.x, depths.y);
  return shadowmaps::IntersectFrustumWithBox(slice * frame.CameraView, frame.SceneBounds);
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
  return filterReachTexels * std::max(texel, first) + (normalOffsetTexels + 1.0) * texel;
}

// The casters inside the view's frustum.
std::vector<const Caster*> CastersInView(const std::vector<Caster>& all, const LightView& view)
{
  std::vector<const Caster*> casters;
  if (view.OutOfView)
  {
    return casters;
  }
  const auto planes = shadowmaps::FrustumPlanes(view.ViewProjection());
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
  const shadowmaps::ShadowReach reach = shadowmaps::ReachOfBody(viewProjection, visible, margin);
  std::vector<const Caster*> casters;
  std::copy_if(inView.begin(), inView.end(), std::back_inserter(casters), [&](const Caster* c) {
    return shadowmaps::MayShadowInto(reach, viewProjection, c->Bounds);
  });
  return casters;
}

// What a layer's texels depend on of its view besides what ForgetLayersIfStale
// watches: its matrices, its light's depth (stored by light-depth maps) and,
// where the representation's post-processing follows it, its FilterScale (a
// cascade's blur follows the first cascade's texels, which may change while
// this one's matrices stay).
std::vector<vtkMTimeType> LayerViewBits(
  const ShadowLight& light, std::size_t index, bool postProcessingFollowsFilterScale)
{
  const LightView& view = light.Views[index];
  std::vector<vtkMTimeType> bits;
  if (postProcessingFollowsFilterScale)
  {
    AppendBits(shadowmaps::FilterScale(light, index), bits);
  }
  AppendMatrixBits(view.View, bits);
  AppendMatrixBits(view.Projection, bits);
  const shadowmaps::LightDepth& depth = light.Depth;
  for (double value : { depth.Plane.x, depth.Plane.y, depth.Plane.z, depth.Plane.w,
         depth.PerDistance, depth.Origin.x, depth.Origin.y, depth.Origin.z })
  {
    AppendBits(value, bits);
  }
  bits.push_back(view.OutOfView ? 1 : 0);
  bits.push_back(view.LinearDepth ? 1 : 0);
  return bits;
}

shadowmaps::CasterStamp StampOf(const Caster& caster)
{
  return { caster.Prop, caster.MTime };
}

std::vector<shadowmaps::CasterStamp> StampsOf(const std::vector<const Caster*>& casters)
{
  std::vector<shadowmaps::CasterStamp> stamps;
  stamps.reserve(casters.size());
  for (const Caster* caster : casters)
  {
    stamps.push_back(StampOf(*caster));
  }
  return stamps;
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

  // The maps and what renders them.
  shadowmaps::TextureArray Maps;
  shadowmaps::MapStorage Storage;
  vtkNew<vtkOpaquePass> OpaquePass;
  vtkNew<vtkCamera> LightCamera;
  vtkNew<vtkMatrix4x4> LightProjection;
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
  shadowmaps::LinearDepthResolve LinearDepths;
  // Light depths of value maps, while the processes' maps are combined.
  shadowmaps::StoreFromLightDepths LightDepths;
  shadowmaps::ClosedCasters ClosedCasters;

  // What the maps were last rendered for; empty when they must be re-rendered.
  std::vector<vtkMTimeType> Signature;
  bool MapsValid = false;
  // Per layer, what it was last rendered from; all of them are forgotten when
  // what every layer depends on changes (LayersKey).
  std::vector<shadowmaps::LayerContent> LayerContents;
  bool WarnedUncombined = false;
  bool WarnedUngatheredBounds = false;
  std::vector<vtkMTimeType> LayersKey;
  /// The lights and views the maps were rendered for (reused with the maps),
  /// and what else their fits depended on but the camera.
  std::vector<shadowmaps::ShadowLight> RenderedLights;
  vtkMTimeType RenderedPassTime = 0;
  int RenderedResolution = 0;
  Aabb RenderedSceneBounds;

  // The receivers' shader code and uniforms of the current maps.
  shadowmaps::ReceiverCode Code;
  shadowmaps::ReceiverUniforms Uniforms;
  // The casters' branch of the same shaders and its uniforms.
  shadowmaps::CasterCode CasterCode;
  shadowmaps::CasterUniforms CasterUniforms;
  shadowmaps::ProgramStamps CasterPrograms;
  // Programs the casters drew with since the scene last did.
  std::unordered_set<vtkShaderProgram*> CastSinceSceneDraw;
  // The shaders depend on these; GetShaderStageMTime() follows them.
  std::string ShaderKey;
  std::vector<vtkProp*> NonReceivers;
  vtkTimeStamp ShaderKeyTime;
  int MapUnit = -1;
  // Depth peeling's first-pass depths, while casting.
  int PeelUnit = -1;
  bool TextureUnitsReserved = false;
  bool ShaderCodeCompiles = true;
  // The props whose render passes this pass joined in this frame.
  std::vector<vtkProp*> Joined;

  bool Active = false;
  bool Casting = false;
  bool SceneCameraParallel = false;
  bool WarnedTooManyLights = false;
  bool WarnedNonFiniteViews = false;
  bool WarnedResolution = false;
  std::string LastGLError;
  std::string WarnedGLError;
};

//------------------------------------------------------------------------------
vtkAbstractShadowMapPass::vtkAbstractShadowMapPass(
  vtkShadowMapViews* defaultViews, vtkShadowMapRepresentation* defaultRepresentation)
  : Internal(new Internals)
{
  this->Internal->DefaultViews = defaultViews;
  this->Internal->DefaultRepresentation = defaultRepresentation;
  this->Internal->Views = defaultViews;
  this->Internal->Representation = defaultRepresentation;
  this->Internal->ShaderKeyTime.Modified();
}

//------------------------------------------------------------------------------
vtkAbstractShadowMapPass::~vtkAbstractShadowMapPass()
{
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
  return this->Internal->Maps.GetMemoryBytes();
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
  if (renderer && !this->DelegatePass)
  {
    r.FollowRendererTranslucency(renderer);
  }
  if (renderer && renderer->GetSelector())
  {
    // A hardware selection pass: ids, not light. The maps stay as they are.
    this->LeaveRenderPasses();
    delegate->Render(s);
    this->NumberOfRenderedProps = delegate->GetNumberOfRenderedProps();
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
    this->ReleaseTextureUnits(renderer);
  }
  this->LeaveRenderPasses();
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::JoinRenderPasses(vtkProp* const* props, int count)
{
  // As vtkOpenGLRenderPass::PreRender, but once per prop: casters join before
  // the scene's props, and a prop's set of passes must be the same in both
  // draws for its mapper to keep its shaders.
  Internals& r = *this->Internal;
  for (int i = 0; i < count; ++i)
  {
    vtkProp* prop = props[i];
    if (!prop->GetPropertyKeys())
    {
      vtkNew<vtkInformation> keys;
      prop->SetPropertyKeys(keys);
    }
    if (!HasRenderPass(prop->GetPropertyKeys(), this))
    {
      prop->GetPropertyKeys()->Append(vtkOpenGLRenderPass::RenderPasses(), this);
      r.Joined.push_back(prop);
    }
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::LeaveRenderPasses()
{
  Internals& r = *this->Internal;
  for (vtkProp* prop : r.Joined)
  {
    prop->GetPropertyKeys()->Remove(vtkOpenGLRenderPass::RenderPasses(), this);
  }
  r.Joined.clear();
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
  this->CollectNonReceivers(s);
  const bool ready = this->UpdateShadowMaps(renderer);
  // Lights whose views were not finite are gone by now.
  this->NumberOfShadowedLights = static_cast<int>(this->Internal->Lights.size());
  return ready;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::CollectLights(vtkOpenGLRenderer* renderer)
{
  auto& lights = this->Internal->Lights;
  lights.clear();
  int shaderIndex = 0;
  vtkCollectionSimpleIterator it;
  vtkLightCollection* collection = renderer->GetLights();
  collection->InitTraversal(it);
  int skipped = 0;
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (!light->GetSwitch())
    {
      continue; // switched-off lights get no index in the mappers' shaders
    }
    const int index = shaderIndex++;
    if (light->LightTypeIsHeadlight() || !IsEnabled(light->GetInformation(), CASTS_SHADOWS()))
    {
      continue;
    }
    if (static_cast<int>(lights.size()) == VTK_MAX_SHADOWED_LIGHTS)
    {
      ++skipped;
      continue;
    }
    ShadowLight shadowLight;
    shadowLight.Light = light;
    shadowLight.ShaderIndex = index;
    shadowLight.Position = ToGlm(light->GetTransformedPosition());
    shadowLight.Direction = ToGlm(light->GetTransformedFocalPoint()) - shadowLight.Position;
    shadowLight.ConeAngle = light->GetConeAngle();
    shadowLight.Attenuation = std::min(std::max(light->GetShadowAttenuation(), 0.0f), 1.0f);
    shadowLight.Kind = !light->GetPositional() ? LightKind::Directional
      : shadowLight.ConeAngle < 90.0           ? LightKind::Spot
                                               : LightKind::Point;
    lights.push_back(shadowLight);
  }
  if (skipped > 0 && !this->Internal->WarnedTooManyLights)
  {
    vtkWarningMacro(<< skipped << " light(s) beyond the first " << VTK_MAX_SHADOWED_LIGHTS
                    << " shadowed lights cast no shadows; they still light the scene.");
  }
  this->Internal->WarnedTooManyLights = skipped > 0;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::CollectCastersAndCamera(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  shadowmaps::ShadowFrame& frame = r.Frame;
  r.Casters.clear();
  frame.PropBounds.clear();
  frame.SceneBounds = Aabb();
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility())
    {
      continue;
    }
    const Aabb bounds = Aabb::FromBounds(prop->GetBounds());
    if (!bounds.IsUsable())
    {
      continue;
    }
    frame.SceneBounds.Add(bounds);
    frame.PropBounds.push_back(bounds);
    if (!prop->GetPropertyKeys())
    {
      // Render passes create the keys on first use, which modifies the prop;
      // create them now so that this first use does not re-render the maps.
      vtkNew<vtkInformation> keys;
      prop->SetPropertyKeys(keys);
    }
    if (IsEnabled(prop->GetPropertyKeys(), CASTS_SHADOWS()) && DrawsIntoDepthMaps(prop))
    {
      r.Casters.push_back({ prop, bounds, CasterMTime(prop) });
    }
  }

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
  vtkCamera* camera = renderer->GetActiveCamera();
  frame.CameraView = ToGlm(camera->GetViewTransformMatrix());
  frame.CameraProjection =
    ToGlm(camera->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1.0, 1.0));
  frame.FilterReachTexels = r.Representation->GetFilterReachTexels();
  frame.Interactive = this->InteractiveUpdateRate < VTK_DOUBLE_MAX &&
    renderer->GetRenderWindow()->GetDesiredUpdateRate() >= this->InteractiveUpdateRate;
}

//------------------------------------------------------------------------------
std::vector<vtkMTimeType> vtkAbstractShadowMapPass::MapSignature(vtkOpenGLRenderer* renderer)
{
  const Internals& r = *this->Internal;
  int size[2];
  int origin[2];
  renderer->GetTiledSizeAndOrigin(size, size + 1, origin, origin + 1);
  std::vector<vtkMTimeType> signature = { this->GetMTime(), renderer->GetLights()->GetMTime(),
    renderer->GetViewProps()->GetMTime(), static_cast<vtkMTimeType>(size[0]),
    static_cast<vtkMTimeType>(size[1]) };
  AppendMatrixBits(r.Frame.CameraView, signature);
  AppendMatrixBits(r.Frame.CameraProjection, signature);
  // The fits and the casters' reach follow every prop's bounds, receivers'
  // too (every process's, with an exchange: GatherPropBounds came first).
  for (const Aabb& box : r.Frame.PropBounds)
  {
    AppendBoxBits(box, signature);
  }
  AppendBoxBits(r.Frame.SceneBounds, signature);
  // A still render after interactive ones fits anew what they may have kept.
  signature.push_back(r.Frame.Interactive ? 1 : 0);
  for (const auto& light : r.Lights)
  {
    signature.push_back(reinterpret_cast<vtkMTimeType>(light.Light));
    signature.push_back(light.Light->GetMTime());
  }
  for (const auto& caster : r.Casters)
  {
    signature.push_back(reinterpret_cast<vtkMTimeType>(caster.Prop));
    signature.push_back(caster.MTime);
  }
  return signature;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::GatherPropBounds()
{
  Internals& r = *this->Internal;
  if (!this->Exchange)
  {
    return;
  }
  const bool given = this->UseSceneBounds && Aabb::FromBounds(this->SceneBounds).IsUsable();
  if (!shadowmaps::GatherPropBounds(this->Exchange, r.Frame, given) && !given &&
    !r.WarnedUngatheredBounds)
  {
    vtkWarningMacro(<< "The exchange gathers no prop bounds and no scene bounds are given "
                       "(SetSceneBounds): the processes' views may differ.");
    r.WarnedUngatheredBounds = true;
  }
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::UpdateShadowMaps(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  this->GatherPropBounds();
  if (this->Exchange)
  {
    // The processes must fit the same views: interactive only if every one's
    // window is (a plain MPI program raises one rank's update rate).
    r.Frame.Interactive = !this->Exchange->AnyOf(!r.Frame.Interactive);
  }
  std::vector<vtkMTimeType> signature = this->MapSignature(renderer);
  const bool stale = !(r.MapsValid && signature == r.Signature);
  // Every process asks every frame: another one's casters may have moved.
  if (!(this->Exchange ? this->Exchange->AnyOf(stale) : stale))
  {
    // CollectLights rebuilt the lights without views; the maps hold these.
    r.Lights = r.RenderedLights;
    return true;
  }
  r.Signature.clear();
  r.MapsValid = false;

  r.Frame.Resolution = this->UsableResolution();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  // Each failure still answers the other processes' question (CombineAcrossProcesses).
  if (!this->FitViews())
  {
    this->CombineAcrossProcesses(window, false);
    return false;
  }
  this->ChooseStorage();
  this->UpdateShaderKey(renderer);
  if (!r.ShaderCodeCompiles)
  {
    this->CombineAcrossProcesses(window, false);
    this->ReportGLFailure("the shadow shader code does not compile (see the shader error above; a "
                          "representation's GLSL?)");
    return false;
  }
  std::string error;
  if (!r.Maps.Reserve(r.Frame.Resolution, this->NumberOfShadowMapLayers, r.Storage.Format,
        r.Storage.Mipmaps, error))
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
  if (!this->NeedsSecondOutput())
  {
    r.Maps.ReleaseSecondOutput();
  }
  if (r.Storage.Samples <= 1)
  {
    r.Maps.ReleaseSamples();
  }
  r.Uniforms.Pack(r.Lights, r.Frame.CameraView);
  r.RenderedLights = r.Lights;
  r.RenderedPassTime = this->GetMTime();
  r.RenderedResolution = r.Frame.Resolution;
  r.RenderedSceneBounds = r.Frame.SceneBounds;
  r.Signature = std::move(signature);
  r.MapsValid = true;
  r.WarnedGLError.clear();
  ++this->NumberOfShadowMapUpdates;
  return true;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::NeedsSecondOutput() const
{
  // Peeled two-surface maps, value maps whose light depths are combined, and
  // linear-depth views of depth maps.
  const Internals& r = *this->Internal;
  if (r.Storage.SecondDepth == shadowmaps::SecondDepthMethod::Peeling ||
    this->MapCombination() == shadowmaps::Combination::NearestLightDepths)
  {
    return true;
  }
  return shadowmaps::IsDepth(r.Storage.Format) && AnyLinearDepthView(r.Lights);
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
    light.LastViews = this->LastViewsOf(light);
    r.Views->FitLight(r.Frame, light);
    light.LastViews.clear();
    light.Depth = light.Kind == LightKind::Directional
      ? shadowmaps::DirectionalLightDepth(light.Direction, r.Frame.SceneBounds)
      : shadowmaps::PositionalLightDepth(light.Position, r.Frame.SceneBounds);
  }
  this->DropLightsWithoutUsableViews();
  this->AssignLayers();
  return !r.Lights.empty();
}

//------------------------------------------------------------------------------
std::vector<LightView> vtkAbstractShadowMapPass::LastViewsOf(const ShadowLight& light)
{
  const Internals& r = *this->Internal;
  const Aabb& bounds = r.Frame.SceneBounds;
  const bool onlyTheCameraMoved = r.RenderedPassTime == this->GetMTime() &&
    r.RenderedResolution == r.Frame.Resolution && r.RenderedSceneBounds.Min == bounds.Min &&
    r.RenderedSceneBounds.Max == bounds.Max;
  if (!onlyTheCameraMoved)
  {
    return {};
  }
  for (const ShadowLight& rendered : r.RenderedLights)
  {
    if (rendered.Light == light.Light && rendered.Kind == light.Kind &&
      rendered.Position == light.Position && rendered.Direction == light.Direction &&
      rendered.ConeAngle == light.ConeAngle)
    {
      return rendered.Views;
    }
  }
  return {};
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
  r.Representation->GetMapStorage(r.Storage);
  this->ChooseSecondDepthMethod();
  const bool thirtyTwoBitNow =
    r.Maps.GetResolution() != 0 && r.Maps.GetFormat() == shadowmaps::TexelFormat::Depth;
  if (r.Storage.Format == shadowmaps::TexelFormat::Depth &&
    SixteenBitDepthSuffices(r.Lights, thirtyTwoBitNow))
  {
    r.Storage.Format = shadowmaps::TexelFormat::Depth16;
  }
  // Depth maps store the views' own depths; two-surface maps compare them.
  const bool oneValueMap = !shadowmaps::IsDepth(r.Storage.Format) &&
    r.Storage.SecondDepth == shadowmaps::SecondDepthMethod::None;
  r.Storage.LightDepth = r.Storage.LightDepth && oneValueMap;
  // Combined light-depth maps are rebuilt from each texel's nearest light
  // depth, not its samples.
  const bool combinesLightDepths = this->Exchange && r.Storage.LightDepth;
  r.Storage.Samples = oneValueMap && !r.Storage.MinimumBlending && !combinesLightDepths
    ? std::max(1, std::min(r.Storage.Samples, MaximumSamples()))
    : 1;
  r.Code.Definitions = std::string(r.Storage.LightDepth ? "#define VTK_SHADOW_LIGHT_DEPTH\n" : "") +
    r.Representation->GetReceiverDefinitions();
  r.Code.Lookup = r.Representation->GetReceiverLookupCode();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ChooseSecondDepthMethod()
{
  using shadowmaps::SecondDepthMethod;
  Internals& r = *this->Internal;
  shadowmaps::MapStorage& storage = r.Storage;
  if (storage.Format != shadowmaps::TexelFormat::TwoFloats)
  {
    storage.SecondDepth = SecondDepthMethod::None;
  }
  if (storage.SecondDepth == SecondDepthMethod::Auto)
  {
    std::vector<std::pair<vtkProp*, vtkMTimeType>> casters;
    for (const Caster& caster : r.Casters)
    {
      casters.emplace_back(caster.Prop, caster.MTime);
    }
    // Processes that combine their maps must make them the same way, and
    // peeling is right whatever each one's casters are.
    storage.SecondDepth = !this->Exchange && r.ClosedCasters.AllClosed(casters)
      ? SecondDepthMethod::FrontAndBackFaces
      : SecondDepthMethod::Peeling;
  }
  if (storage.SecondDepth != SecondDepthMethod::None)
  {
    storage.MinimumBlending = storage.SecondDepth == SecondDepthMethod::FrontAndBackFaces;
    storage.ClearValues[0] = storage.ClearValues[1] = 1.0f;
  }
  this->NumberOfCasterPassesPerLayer = storage.SecondDepth == SecondDepthMethod::Peeling ? 2 : 1;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::UpdateShaderKey(vtkOpenGLRenderer* renderer)
{
  // Before the casters draw: they build the shaders the scene then uses.
  Internals& r = *this->Internal;
  // Analysis settings are pass parameters: a change re-renders the maps.
  const bool recolours = this->AnalysisView != NO_ANALYSIS && this->AnalysisView != SHADOW_MAP;
  shadowmaps::AddAnalysisReceiverCode(
    recolours ? this->AnalysisView : 0, this->AnalysisLight, r.Lights, r.Code);
  r.Code.Rehash();
  r.CasterCode.SecondDepth = r.Storage.SecondDepth;
  // Two surfaces' depths need both faces of the casters.
  r.CasterCode.Faces =
    r.Storage.SecondDepth == shadowmaps::SecondDepthMethod::None ? this->CasterFaces : BOTH_FACES;
  const bool values = !shadowmaps::IsDepth(r.Storage.Format);
  r.CasterCode.StoreCode = values ? r.Storage.StoreCode : std::string();
  r.CasterCode.KeepsLightDepth =
    this->MapCombination() == shadowmaps::Combination::NearestLightDepths;
  r.CasterCode.StoreFunctions = values ? r.Storage.StoreFunctions : std::string();
  r.CasterCode.LightDepth = values && r.Storage.LightDepth;
  r.CasterCode.LinearDepth = AnyLinearDepthView(r.Lights);
  std::string key = shadowmaps::ReceiverShader::Key(r.Lights, this->NumberOfShadowMapLayers, r.Code) +
    '|' + r.CasterCode.Key();
  if (key != r.ShaderKey)
  {
    r.ShaderKey = std::move(key);
    r.ShaderKeyTime.Modified();
    r.ShaderCodeCompiles = this->ShaderCodeCompiles(renderer);
  }
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::ShaderCodeCompiles(vtkOpenGLRenderer* renderer)
{
  shadowmaps::ProbeShaders probe = shadowmaps::MakeProbeShaders(this->Internal->Lights);
  std::string geometryShader;
  this->PreReplaceShaderValues(probe.Vertex, geometryShader, probe.Fragment, nullptr, nullptr);
  this->InjectShadowCode(probe.Vertex, geometryShader, probe.Fragment, true);
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  return window->GetShaderCache()->ReadyShaderProgram(
           probe.Vertex.c_str(), probe.Fragment.c_str(), "") != nullptr;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ApplyCasterUniforms(const ShadowLight& light, const LightView& view)
{
  // 32-bit depth (linear-depth views are never 16-bit): one polygon-offset unit
  // is 2^-24 for depths in [0.5, 1).
  constexpr float DepthUnit = 1.0f / 16777216.0f;
  Internals& r = *this->Internal;
  const std::array<float, 3> windowToInverseW = shadowmaps::WindowToInverseW(view, r.Frame.Resolution);
  const shadowmaps::DepthOffset offset = this->GetRepresentation()->GetCasterDepthOffset();
  const auto slope = static_cast<float>(offset.SlopeScaled);
  const auto constant = static_cast<float>(offset.Constant);
  if (view.LinearDepth)
  {
    // A directional light's linear depth spans its casters and B: its
    // slope-scaled term is capped at what a 45 degree surface needs in a
    // uniform map as deep as it is wide (SlopeScaledBias texels' worth, 2 /
    // resolution at the default). A spot's stored depth is its post-perspective
    // depth, crowded toward 1: no such cap.
    const float cap = light.Kind == LightKind::Directional
      ? slope / static_cast<float>(std::max(r.Frame.Resolution, 1))
      : std::numeric_limits<float>::max();
    glPolygonOffset(0.0f, 0.0f);
    r.CasterUniforms.SetView(windowToInverseW, { { slope, constant * DepthUnit, cap } }, !view.Perspective);
  }
  else
  {
    glPolygonOffset(slope, constant);
    r.CasterUniforms.SetView(windowToInverseW, { { 0.0f, 0.0f, 0.0f } }, !view.Perspective);
  }
  if (r.CasterCode.LightDepth)
  {
    // Positions relative to the depth's origin, composed in double: no large
    // world coordinate is formed in float.
    const shadowmaps::LightDepth& depth = light.Depth;
    const glm::dmat4 windowToLight =
      glm::translate(glm::dmat4(1.0), -depth.Origin) * WindowToWorld(view, r.Frame.Resolution);
    r.CasterUniforms.SetLightDepth(
      glm::mat4(windowToLight), glm::vec4(depth.Plane), static_cast<float>(depth.PerDistance));
  }
  // Every program takes the view's uniforms on its first draw into it.
  r.CasterPrograms.Invalidate();
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
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  this->ForgetLayersIfStale();
  const shadowmaps::Combination combination = this->MapCombination();
  if (combination != shadowmaps::Combination::None)
  {
    // The layers hold the combination of every process's casters, not this
    // one's: all of them are rendered again and combined again.
    r.LayerContents.assign(r.LayerContents.size(), {});
  }
  const bool keepsLightDepths = combination == shadowmaps::Combination::NearestLightDepths;
  if (keepsLightDepths)
  {
    r.LightDepths.Reset(r.Maps, this->NumberOfShadowMapLayers);
  }
  int draws = 0;
  std::vector<shadowmaps::RenderedLayer> rendered;
  bool ok = true;
  {
    const shadowmaps::CasterGLState casterState(state,
      !shadowmaps::IsDepth(r.Storage.Format) && r.Storage.MinimumBlending);
    vtkSmartPointer<vtkCamera> userCamera = renderer->GetActiveCamera();
    r.SceneCameraParallel = userCamera->GetParallelProjection() != 0;
    renderer->SetActiveCamera(r.LightCamera);
    this->ReserveTextureUnits(renderer);
    r.Casting = true;
    std::vector<shadowmaps::CasterStamp> frameCasters;
    std::transform(r.Casters.begin(), r.Casters.end(), std::back_inserter(frameCasters), StampOf);
    const std::vector<shadowmaps::CasterStamp> current =
      shadowmaps::SortedByProp(std::move(frameCasters));
    const std::vector<glm::dvec3> visible = this->ShadowReachCulling
      ? shadowmaps::IntersectFrustumWithBox(
          r.Frame.CameraProjection * r.Frame.CameraView, r.Frame.SceneBounds)
      : std::vector<glm::dvec3>();
    // While the user drags, views stay put as the camera turns (kept by
    // vtkShadowMapViews::InteractiveView, or snapped to a grid): a layer
    // re-rendered then takes every caster in its view, so that casters the
    // camera brings into reach later in the drag are already drawn. Not where
    // InteractiveTexelRatio 1 asks drags to render as still frames do, where
    // every layer is combined anew each frame, or where coarse mip levels would
    // average the extra casters into what receivers see.
    const bool drawsAllInView = this->GetViews()->MayKeepViews(r.Frame) &&
      combination == shadowmaps::Combination::None && !r.Storage.Mipmaps;
    for (const ShadowLight& light : r.Lights)
    {
      for (size_t v = 0; v < light.Views.size() && ok; ++v)
      {
        const int layer = light.FirstLayer + static_cast<int>(v);
        const std::vector<glm::dvec3> shaded = ShadedBody(r.Frame, light.Views[v], visible);
        const std::vector<const Caster*> inView = CastersInView(r.Casters, light.Views[v]);
        const std::vector<const Caster*> needed = CastersReaching(inView, light.Views[v], shaded,
          ReachMargin(light, v, shaded, r.Frame.FilterReachTexels, this->NormalOffset));
        std::vector<vtkMTimeType> viewBits =
          LayerViewBits(light, v, r.Representation->GetPostProcessingFollowsFilterScale());
        if (r.LayerContents[layer].Holds(viewBits, StampsOf(needed), current))
        {
          continue;
        }
        const std::vector<const Caster*>& casters = drawsAllInView ? inView : needed;
        std::vector<shadowmaps::CasterStamp> stamps = StampsOf(casters);
        const bool linearDepths =
          light.Views[v].LinearDepth && shadowmaps::IsDepth(r.Storage.Format);
        const bool peeling = r.Storage.SecondDepth == shadowmaps::SecondDepthMethod::Peeling;
        const bool multisampled = r.Storage.Samples > 1;
        ok = multisampled
          ? r.Maps.BindSamples(state, r.Storage.Samples, r.LastGLError)
          : r.Maps.BindLayer(state, layer, r.LastGLError, linearDepths || peeling || keepsLightDepths);
        if (ok)
        {
          this->ApplyCasterUniforms(light, light.Views[v]);
          std::vector<vtkProp*> props;
          std::transform(casters.begin(), casters.end(), std::back_inserter(props),
            [](const Caster* caster) { return caster->Prop; });
          draws += this->RenderCastersIntoView(renderer, light.Views[v], props, linearDepths);
          ok = !multisampled || r.Maps.ResolveSamples(state, layer, r.LastGLError);
          ok = ok && (!linearDepths || r.LinearDepths.Render(window, r.Maps, layer, r.LastGLError));
          ok = ok && (!keepsLightDepths || r.LightDepths.Keep(state, r.Maps, layer, r.LastGLError));
          if (ok && peeling && !props.empty())
          {
            ok = this->PeelSecondSurface(renderer, layer, props, draws);
          }
          r.LayerContents[layer] =
            shadowmaps::LayerContent(std::move(viewBits), std::move(stamps));
          rendered.push_back({ layer, shadowmaps::FilterScale(light, v) });
        }
      }
    }
    r.Casting = false;
    renderer->SetActiveCamera(userCamera);
  }
  this->NumberOfRenderedLayers = static_cast<int>(rendered.size());
  if (!rendered.empty())
  {
    this->NumberOfCasterDraws = draws;
  }
  ok = this->CombineAcrossProcesses(window, ok);
  if (!ok)
  {
    r.LayerContents.clear();
    return false;
  }
  return rendered.empty() || this->PostProcessShadowMaps(renderer, rendered);
}

//------------------------------------------------------------------------------
shadowmaps::Combination vtkAbstractShadowMapPass::MapCombination() const
{
  return this->Exchange ? shadowmaps::CombinationOf(this->Internal->Storage)
                        : shadowmaps::Combination::None;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::CombineAcrossProcesses(vtkOpenGLRenderWindow* window, bool ok)
{
  Internals& r = *this->Internal;
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
      r.LastGLError = "another process could not render its shadow maps";
    }
    return false;
  }
  const shadowmaps::Combination how = this->MapCombination();
  if (how == shadowmaps::Combination::None)
  {
    if (!r.WarnedUncombined)
    {
      vtkWarningMacro(<< "Maps of values other than light depths are not combined across "
                         "processes; these maps hold each process's own casters.");
      r.WarnedUncombined = true;
    }
    return true;
  }
  return shadowmaps::CombineTexels(this->Exchange, window, how, r.Maps, r.Storage, r.LightDepths,
    this->NumberOfShadowMapLayers, r.Frame.Resolution, r.LastGLError);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ForgetLayersIfStale()
{
  Internals& r = *this->Internal;
  // What every layer depends on besides its view and casters: the parameters of
  // the pass and its strategies (the bias, the caster faces and store code among
  // them), the storage, and how a second depth is made (AUTO may change it when
  // some other layer's casters change).
  const std::vector<vtkMTimeType> key = { this->GetMTime(), r.Maps.GetAllocations(),
    static_cast<vtkMTimeType>(r.Frame.Resolution),
    static_cast<vtkMTimeType>(r.Storage.SecondDepth) };
  if (key != r.LayersKey)
  {
    r.LayersKey = key;
    r.LayerContents.clear();
  }
  r.LayerContents.resize(static_cast<size_t>(this->NumberOfShadowMapLayers));
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PostProcessShadowMaps(
  vtkOpenGLRenderer* renderer, const std::vector<shadowmaps::RenderedLayer>& rendered)
{
  Internals& r = *this->Internal;
  if (!r.Representation->PostProcessMaps(renderer, r.Maps, rendered))
  {
    r.LastGLError = "the shadow maps could not be post-processed";
    return false;
  }
  r.Maps.GenerateMipmaps();
  return true;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ClearLayer(vtkOpenGLRenderer* renderer, bool linearDepths)
{
  Internals& r = *this->Internal;
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow())->GetState();
  state->vtkglViewport(0, 0, r.Frame.Resolution, r.Frame.Resolution);
  state->vtkglClearDepth(1.0);
  GLbitfield buffers = GL_DEPTH_BUFFER_BIT;
  if (!shadowmaps::IsDepth(r.Storage.Format))
  {
    const float* clear = r.Storage.ClearValues;
    state->vtkglClearColor(clear[0], clear[1], clear[2], clear[3]);
    buffers |= GL_COLOR_BUFFER_BIT;
  }
  else if (linearDepths)
  {
    state->vtkglClearColor(1.0, 1.0, 1.0, 1.0);
    buffers |= GL_COLOR_BUFFER_BIT;
  }
  state->vtkglClear(buffers);
  if (this->MapCombination() == shadowmaps::Combination::NearestLightDepths)
  {
    // The casters' light depths: far where none draws.
    const float far[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
    glClearBufferfv(GL_COLOR, 1, far);
  }
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::RenderCastersIntoView(vtkOpenGLRenderer* renderer,
  const LightView& view, std::vector<vtkProp*>& casters, bool linearDepths)
{
  Internals& r = *this->Internal;
  this->ClearLayer(renderer, linearDepths);
  if (casters.empty())
  {
    return 0;
  }
  shadowmaps::SetCameraToView(r.LightCamera, r.LightProjection, view, r.SceneCameraParallel);
  this->JoinRenderPasses(casters.data(), static_cast<int>(casters.size()));
  return this->DrawCasters(renderer, casters);
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PeelSecondSurface(
  vtkOpenGLRenderer* renderer, int layer, std::vector<vtkProp*>& casters, int& draws)
{
  // The first pass left the nearest surface in both values and in the second
  // output; this one keeps, in y only, the nearest surface behind it.
  Internals& r = *this->Internal;
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow())->GetState();
  if (!r.Maps.BindLayer(state, layer, r.LastGLError, false))
  {
    return false;
  }
  vtkOpenGLState::ScopedglColorMask keepMask(state);
  vtkOpenGLState::ScopedglClearColor keepClearColor(state);
  vtkOpenGLState::ScopedglActiveTexture keepUnit(state);
  state->vtkglColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE);
  state->vtkglClearColor(1.0, 1.0, 1.0, 1.0);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // Through the state cache: the casters' own textures find their units by it.
  state->vtkglActiveTexture(GL_TEXTURE0 + r.PeelUnit);
  glBindTexture(GL_TEXTURE_2D, r.Maps.GetSecondOutput());
  r.CasterUniforms.SetPeeling(true, r.PeelUnit);
  r.CasterPrograms.Invalidate();
  draws += this->DrawCasters(renderer, casters);
  r.CasterUniforms.SetPeeling(false, r.PeelUnit);
  r.CasterPrograms.Invalidate();
  state->vtkglActiveTexture(GL_TEXTURE0 + r.PeelUnit);
  glBindTexture(GL_TEXTURE_2D, 0);
  return true;
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::DrawCasters(vtkOpenGLRenderer* renderer, std::vector<vtkProp*>& casters)
{
  Internals& r = *this->Internal;
  vtkRenderState casterState(renderer);
  casterState.SetPropArrayAndCount(casters.data(), static_cast<int>(casters.size()));
  casterState.SetFrameBuffer(nullptr);
  r.OpaquePass->Render(&casterState);
  return r.OpaquePass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::CollectNonReceivers(const vtkRenderState* s)
{
  Internals& r = *this->Internal;
  std::vector<vtkProp*> nonReceivers;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (!IsEnabled(prop->GetPropertyKeys(), RECEIVES_SHADOWS()))
    {
      nonReceivers.push_back(prop);
    }
  }
  if (nonReceivers != r.NonReceivers)
  {
    r.NonReceivers = std::move(nonReceivers);
    r.ShaderKeyTime.Modified();
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReserveTextureUnits(vtkOpenGLRenderer* renderer)
{
  // Casters and receivers share programs, so the receivers' samplers must point
  // at units of their own while the casters draw too (a sampler sharing a unit
  // with one of another type fails the draw), with no map bound: the maps are
  // being rendered.
  Internals& r = *this->Internal;
  if (r.TextureUnitsReserved)
  {
    return;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  // Work on our own unit: creating a texture binds it to the active unit, which
  // may hold another pass's texture (e.g. the tone-mapping pass's colour).
  r.MapUnit = window->GetTextureUnitManager()->Allocate();
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + r.MapUnit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  if (r.Storage.SecondDepth == shadowmaps::SecondDepthMethod::Peeling)
  {
    r.PeelUnit = window->GetTextureUnitManager()->Allocate();
    r.CasterUniforms.SetPeeling(false, r.PeelUnit);
  }
  r.Representation->ActivateReceiverResources(window);
  r.TextureUnitsReserved = true;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::BindShadowTextures(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  this->ReserveTextureUnits(renderer);
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  r.Maps.SetLinearFiltering(r.Representation->GetLinearFiltering());
  r.Maps.BindToUnit(window->GetState(), r.MapUnit);
  r.Uniforms.NewFrame();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReleaseTextureUnits(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  if (!r.TextureUnitsReserved)
  {
    return;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + r.MapUnit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  window->GetTextureUnitManager()->Free(r.MapUnit);
  r.MapUnit = -1;
  if (r.PeelUnit >= 0)
  {
    window->GetTextureUnitManager()->Free(r.PeelUnit);
    r.PeelUnit = -1;
  }
  r.Representation->DeactivateReceiverResources();
  r.TextureUnitsReserved = false;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReportGLFailure(const std::string& error)
{
  Internals& r = *this->Internal;
  r.Maps.Release();
  r.MapsValid = false;
  r.RenderedLights.clear();
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
  shadowmaps::CasterShader::MarkInjectionPoints(fragmentShader);
  shadowmaps::ReceiverShader::MarkInjectionPoints(fragmentShader);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  const Internals& r = *this->Internal;
  ++this->NumberOfShaderBuilds;
  // Shaders first built by a caster draw are the ones the scene then uses.
  const bool receives =
    (r.Active || r.Casting) && prop && IsEnabled(prop->GetPropertyKeys(), RECEIVES_SHADOWS());
  const shadowmaps::CasterBranch branch =
    this->InjectShadowCode(vertexShader, geometryShader, fragmentShader, receives);
  ++(branch == shadowmaps::CasterBranch::DepthOnly ? this->NumberOfDepthOnlyCasterShaders
                                                   : this->NumberOfOwnFragmentCasterShaders);
  return true;
}

//------------------------------------------------------------------------------
shadowmaps::CasterBranch vtkAbstractShadowMapPass::InjectShadowCode(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, bool receives)
{
  const Internals& r = *this->Internal;
  const shadowmaps::CasterBranch branch =
    shadowmaps::CasterShader::Inject(fragmentShader, r.CasterCode);
  for (std::string* stage : { &vertexShader, &geometryShader, &fragmentShader })
  {
    shadowmaps::CasterShader::RouteCameraParallel(*stage);
  }
  const int unpatched = shadowmaps::ReceiverShader::Inject(fragmentShader, r.Lights,
    this->NumberOfShadowMapLayers, r.Code, receives, branch == shadowmaps::CasterBranch::DepthOnly);
  if (unpatched > 0 && this->NumberOfUnpatchedReceiverLights == 0)
  {
    vtkWarningMacro(<< "This VTK's mapper lights " << unpatched
                    << " shadowed light(s) in shader code this pass does not know how to patch: "
                       "they cast no shadow on that prop (reported once).");
  }
  this->NumberOfUnpatchedReceiverLights += unpatched;
  return branch;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  Internals& r = *this->Internal;
  if (r.Casting)
  {
    if (r.CasterPrograms.FirstUse(program))
    {
      r.CastSinceSceneDraw.insert(program);
      r.CasterUniforms.ApplyCasting(program);
      if (shadowmaps::ReceiverUniforms::IsReceiver(program))
      {
        // Not sampled while casting, but a sampler must not share a unit with
        // one of another type.
        program->SetUniformi("vtkShadowMaps", r.MapUnit);
        r.Representation->SetReceiverUniforms(program);
      }
    }
  }
  else if (r.Active && r.Uniforms.FirstUseThisFrame(program))
  {
    r.CasterUniforms.ApplyReceiving(program);
    if (r.CastSinceSceneDraw.erase(program) > 0)
    {
      // The renderer sets a program's lighting uniforms again only when the
      // lights or the camera changed after it last did; the light cameras
      // changed after the scene's camera, and the casters' draws of this
      // program left the lights in their frames.
      program->SetUniformGroupUpdateTime(vtkShaderProgram::LightingGroup, 0);
    }
    if (shadowmaps::ReceiverUniforms::IsReceiver(program))
    {
      r.Uniforms.Apply(program, r.MapUnit, r.Frame.Resolution, this->NormalOffset);
      r.Representation->SetReceiverUniforms(program);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkAbstractShadowMapPass::GetShaderStageMTime()
{
  return this->Internal->ShaderKeyTime.GetMTime();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::RenderShadowMapView(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  if (this->AnalysisLight >= static_cast<int>(r.Lights.size()))
  {
    return;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  const bool twoSurfaces = r.Storage.SecondDepth != shadowmaps::SecondDepthMethod::None;
  if (!r.MapView.Render(window, r.Maps, r.MapUnit, r.Lights[this->AnalysisLight], twoSurfaces,
        r.Storage.WarpExponent))
  {
    this->ReportGLFailure("the shadow-map view shader did not compile");
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReleaseGraphicsResources(vtkWindow* window)
{
  Internals& r = *this->Internal;
  r.Maps.Release();
  r.MapsValid = false;
  r.RenderedLights.clear();
  r.Signature.clear();
  r.MapView.ReleaseGraphicsResources(window);
  r.LinearDepths.ReleaseGraphicsResources(window);
  r.LightDepths.ReleaseGraphicsResources(window);
  r.Representation->ReleaseGraphicsResources(window);
  if (r.DefaultRepresentation != r.Representation)
  {
    r.DefaultRepresentation->ReleaseGraphicsResources(window);
  }
  r.CasterPrograms.Clear();
  r.CastSinceSceneDraw.clear();
  r.OpaquePass->ReleaseGraphicsResources(window);
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
