#include "vtkAbstractShadowMapPass.h"

#include "ShadowMapAnalysis.h"
#include "ShadowMapGlm.h"
#include "ShadowMapLight.h"
#include "ShadowMapReceiverShader.h"
#include "ShadowMapTextureArray.h"
#include "ShadowMapTrapezoid.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShadowMapCasterPass.h"
#include "vtkShadowMapRepresentation.h"
#include "vtkShadowMapViews.h"
#include "vtkSmartPointer.h"
#include "vtkTextureUnitManager.h"
#include "vtkVolume.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/gtc/type_ptr.hpp>

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

bool IsRigid(const glm::dmat4& m)
{
  const glm::dmat3 rotation(m);
  const glm::dmat3 error = glm::transpose(rotation) * rotation - glm::dmat3(1.0);
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    largest = std::max({ largest, std::abs(error[c].x), std::abs(error[c].y), std::abs(error[c].z) });
  }
  return largest < 1e-9 && m[0][3] == 0.0 && m[1][3] == 0.0 && m[2][3] == 0.0 && m[3][3] == 1.0;
}

bool IsNonFinite(const LightView& view)
{
  return !shadowmaps::IsFinite(view.View) || !shadowmaps::IsFinite(view.Projection);
}

// Points the VTK camera at a light view. A rigid view becomes the camera's frame
// and the projection is explicit, so VTK's tiled aspect ratio cannot distort the
// map. A non-rigid view (PSM: the light camera times the viewer's post-
// perspective transform) cannot be a camera frame; the camera then sits at the
// origin looking down -z and the whole transform is its projection.
void SetCameraToView(vtkCamera* camera, vtkMatrix4x4* projection, const LightView& view)
{
  const bool rigid = IsRigid(view.View);
  const glm::dmat4 frame = rigid ? glm::inverse(view.View) : glm::dmat4(1.0);
  const glm::dvec3 eye(frame[3]);
  const glm::dvec3 forward(-frame[2]);
  const glm::dvec3 up(frame[1]);
  camera->SetPosition(eye.x, eye.y, eye.z);
  camera->SetFocalPoint(eye.x + forward.x, eye.y + forward.y, eye.z + forward.z);
  camera->SetViewUp(up.x, up.y, up.z);
  camera->SetParallelProjection(!view.Perspective);
  ToVtk(rigid ? view.Projection : view.ViewProjection(), projection);
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->UseExplicitProjectionTransformMatrixOn();
  camera->Modified();
}

// 1 / W as a plane over window coordinates (gl_FragCoord.xy) of a map of
// `resolution` texels, for casters of linear-depth views; (0, 0, 1) for the others.
std::array<float, 3> WindowToInverseW(const LightView& view, int resolution)
{
  if (!view.LinearDepth)
  {
    return { { 0.0f, 0.0f, 1.0f } };
  }
  // u = x_window / resolution.
  const glm::vec3 t(shadowmaps::TextureToInverseW(view));
  const float scale = 1.0f / static_cast<float>(std::max(resolution, 1));
  return { { t.x * scale, t.y * scale, t.z } };
}

// The bits of a matrix, so that the signature follows the camera's values
// rather than its identity or MTime (image-processing passes hand their
// delegate a fresh copy of the camera every frame).
void AppendMatrixBits(const glm::dmat4& m, std::vector<vtkMTimeType>& signature)
{
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      vtkMTimeType bits = 0;
      std::memcpy(&bits, &m[c][r], sizeof(double));
      signature.push_back(bits);
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

// The GL state casters render with, set for the lifetime of the object and
// restored after: the maps' framebuffer bindings, depth test (or, for value
// maps kept by minimum blending, GL_MIN blending instead), polygon offset, and
// depth clamping: casters nearer the light than a view's near plane are clamped
// onto it rather than clipped ("pancaking"), so they still occlude all that lies
// behind them, and a fit may put its near plane where depth precision is needed.
class CasterGLState
{
public:
  CasterGLState(vtkOpenGLState* state, const shadowmaps::MapStorage& storage)
    : State(state)
    , Viewport(state)
    , Scissor(state, GL_SCISSOR_TEST)
    , Blend(state, GL_BLEND)
    , DepthTest(state, GL_DEPTH_TEST)
    , Offset(state, GL_POLYGON_OFFSET_FILL)
    , DepthClampWasOn(glIsEnabled(GL_DEPTH_CLAMP))
    , MinimumBlending(storage.Format == shadowmaps::TexelFormat::TwoFloats && storage.MinimumBlending)
  {
    state->PushFramebufferBindings();
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LEQUAL);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglEnable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_DEPTH_CLAMP);
    if (this->MinimumBlending)
    {
      state->vtkglDisable(GL_DEPTH_TEST);
      state->vtkglEnable(GL_BLEND);
      state->vtkglBlendEquation(GL_MIN);
    }
  }
  ~CasterGLState()
  {
    glPolygonOffset(0.0f, 0.0f);
    if (!this->DepthClampWasOn)
    {
      glDisable(GL_DEPTH_CLAMP);
    }
    if (this->MinimumBlending)
    {
      this->State->vtkglBlendEquation(GL_FUNC_ADD);
    }
    this->State->PopFramebufferBindings();
  }
  CasterGLState(const CasterGLState&) = delete;
  CasterGLState& operator=(const CasterGLState&) = delete;

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable Offset;
  GLboolean DepthClampWasOn;
  bool MinimumBlending;
};

// A prop that renders into the maps, with its world bounds.
struct Caster
{
  vtkProp* Prop = nullptr;
  Aabb Bounds;
};

// Volumes keep vtkProp's default HasOpaqueGeometry() but draw nothing into a
// depth map; as casters they would only re-render the maps on every transfer
// function edit.
bool DrawsIntoDepthMaps(vtkProp* prop)
{
  return prop->HasOpaqueGeometry() && !vtkVolume::SafeDownCast(prop);
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
  vtkNew<vtkShadowMapCasterPass> CasterPass;
  vtkNew<vtkOpaquePass> OpaquePass;
  vtkNew<vtkCamera> LightCamera;
  vtkNew<vtkMatrix4x4> LightProjection;
  vtkNew<vtkRenderStepsPass> DefaultDelegate;
  shadowmaps::MapView MapView;

  // What the maps were last rendered for; empty when they must be re-rendered.
  std::vector<vtkMTimeType> Signature;
  bool MapsValid = false;
  /// The lights and views the maps were rendered for (reused with the maps).
  std::vector<shadowmaps::ShadowLight> RenderedLights;

  // The receivers' shader code and uniforms of the current maps.
  shadowmaps::ReceiverCode Code;
  shadowmaps::ReceiverUniforms Uniforms;
  // Receiver shaders depend on these; GetShaderStageMTime() follows them.
  std::string ShaderKey;
  std::vector<vtkProp*> NonReceivers;
  vtkTimeStamp ShaderKeyTime;
  int MapUnit = -1;

  bool Active = false;
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
}

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
int vtkAbstractShadowMapPass::GetNumberOfDepthOnlyCasterShaders() const
{
  return this->Internal->CasterPass->GetNumberOfDepthOnlyShaders();
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfOwnFragmentCasterShaders() const
{
  return this->Internal->CasterPass->GetNumberOfOwnFragmentShaders();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  auto* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkRenderPass* delegate =
    this->DelegatePass ? this->DelegatePass : this->Internal->DefaultDelegate.Get();

  Internals& r = *this->Internal;
  r.Active = renderer && this->PrepareShadows(renderer);
  if (r.Active)
  {
    this->UpdateReceiverShaderKey(s);
    this->PreRender(s);
    this->BindShadowTextures(renderer);
  }
  delegate->Render(s);
  this->NumberOfRenderedProps = delegate->GetNumberOfRenderedProps();
  if (r.Active)
  {
    if (this->AnalysisView == SHADOW_MAP)
    {
      this->RenderShadowMapView(renderer);
    }
    this->UnbindShadowTextures(renderer);
    this->PostRender(s);
  }
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PrepareShadows(vtkOpenGLRenderer* renderer)
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
    if (bounds.IsEmpty() || !std::isfinite(bounds.Diagonal()))
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
      r.Casters.push_back({ prop, bounds });
    }
  }

  vtkCamera* camera = renderer->GetActiveCamera();
  frame.CameraView = ToGlm(camera->GetViewTransformMatrix());
  frame.CameraProjection =
    ToGlm(camera->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1.0, 1.0));
  frame.FilterReachTexels = r.Representation->GetFilterReachTexels();
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
  for (const auto& light : r.Lights)
  {
    signature.push_back(reinterpret_cast<vtkMTimeType>(light.Light));
    signature.push_back(light.Light->GetMTime());
  }
  for (const auto& caster : r.Casters)
  {
    signature.push_back(reinterpret_cast<vtkMTimeType>(caster.Prop));
    signature.push_back(CasterMTime(caster.Prop));
  }
  return signature;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::UpdateShadowMaps(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  std::vector<vtkMTimeType> signature = this->MapSignature(renderer);
  if (r.MapsValid && signature == r.Signature)
  {
    // CollectLights rebuilt the lights without views; the maps hold these.
    r.Lights = r.RenderedLights;
    return true;
  }
  r.Signature.clear();
  r.MapsValid = false;

  r.Frame.Resolution = this->UsableResolution();
  if (!this->FitViews())
  {
    return false;
  }
  this->ChooseStorage();
  std::string error;
  if (!r.Maps.Reserve(r.Frame.Resolution, this->NumberOfShadowMapLayers, r.Storage.Format,
        r.Storage.Mipmaps, error) ||
    !this->RenderShadowMaps(renderer))
  {
    this->ReportGLFailure(error.empty() ? r.LastGLError : error);
    return false;
  }
  r.Uniforms.Pack(r.Lights, r.Frame.CameraView);
  // Analysis settings are pass parameters: a change re-renders the maps.
  const bool recolours = this->AnalysisView != NO_ANALYSIS && this->AnalysisView != SHADOW_MAP;
  shadowmaps::AddAnalysisReceiverCode(
    recolours ? this->AnalysisView : 0, this->AnalysisLight, r.Lights, r.Code);
  r.Code.Rehash();
  r.RenderedLights = r.Lights;
  r.Signature = std::move(signature);
  r.MapsValid = true;
  r.WarnedGLError.clear();
  ++this->NumberOfShadowMapUpdates;
  return true;
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
    r.Views->FitLight(r.Frame, light);
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
  r.Representation->GetMapStorage(r.Storage);
  const bool thirtyTwoBitNow =
    r.Maps.GetResolution() != 0 && r.Maps.GetFormat() == shadowmaps::TexelFormat::Depth;
  if (r.Storage.Format == shadowmaps::TexelFormat::Depth &&
    SixteenBitDepthSuffices(r.Lights, thirtyTwoBitNow))
  {
    r.Storage.Format = shadowmaps::TexelFormat::Depth16;
  }
  r.Code.Definitions = r.Representation->GetReceiverDefinitions();
  r.Code.Lookup = r.Representation->GetReceiverLookupCode();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ApplyDepthBias(const ShadowLight& light, const LightView& view)
{
  // 32-bit depth (linear-depth views are never 16-bit): one polygon-offset unit
  // is 2^-24 for depths in [0.5, 1).
  constexpr float DepthUnit = 1.0f / 16777216.0f;
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
      ? slope / static_cast<float>(std::max(this->Internal->Frame.Resolution, 1))
      : std::numeric_limits<float>::max();
    glPolygonOffset(0.0f, 0.0f);
    this->Internal->CasterPass->SetLinearDepthBias({ { slope, constant * DepthUnit, cap } });
  }
  else
  {
    glPolygonOffset(slope, constant);
    this->Internal->CasterPass->SetLinearDepthBias({ { 0.0f, 0.0f, 0.0f } });
  }
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
  bool ok = true;
  {
    const CasterGLState casterState(state, r.Storage);
    vtkSmartPointer<vtkCamera> userCamera = renderer->GetActiveCamera();
    renderer->SetActiveCamera(r.LightCamera);
    this->PrepareCasterShaders();
    for (ShadowLight& light : r.Lights)
    {
      for (size_t v = 0; v < light.Views.size() && ok; ++v)
      {
        ok = r.Maps.BindLayer(state, light.FirstLayer + static_cast<int>(v), r.LastGLError);
        if (ok)
        {
          this->ApplyDepthBias(light, light.Views[v]);
          this->RenderCastersIntoView(renderer, light.Views[v]);
        }
      }
    }
    renderer->SetActiveCamera(userCamera);
  }
  return ok && this->PostProcessShadowMaps(renderer);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::PrepareCasterShaders()
{
  Internals& r = *this->Internal;
  r.CasterPass->SetCasterFaces(this->CasterFaces);
  r.CasterPass->SetStoreCode(
    r.Storage.Format == shadowmaps::TexelFormat::TwoFloats ? r.Storage.StoreCode : std::string());
  r.CasterPass->SetLinearDepth(std::any_of(r.Lights.begin(), r.Lights.end(), [](const ShadowLight& l) {
    return std::any_of(l.Views.begin(), l.Views.end(), [](const LightView& v) { return v.LinearDepth; });
  }));
  this->NumberOfCasterDraws = 0;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PostProcessShadowMaps(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  r.Maps.GenerateMipmaps();
  if (!r.Representation->PostProcessMaps(renderer, r.Maps))
  {
    r.LastGLError = "the shadow maps could not be post-processed";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ClearLayer(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow())->GetState();
  state->vtkglViewport(0, 0, r.Frame.Resolution, r.Frame.Resolution);
  state->vtkglClearDepth(1.0);
  GLbitfield buffers = GL_DEPTH_BUFFER_BIT;
  if (r.Storage.Format == shadowmaps::TexelFormat::TwoFloats)
  {
    state->vtkglClearColor(r.Storage.ClearValues[0], r.Storage.ClearValues[1], 0.0, 0.0);
    buffers |= GL_COLOR_BUFFER_BIT;
  }
  state->vtkglClear(buffers);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::RenderCastersIntoView(
  vtkOpenGLRenderer* renderer, const LightView& view)
{
  Internals& r = *this->Internal;
  this->ClearLayer(renderer);
  if (view.OutOfView)
  {
    return;
  }

  SetCameraToView(r.LightCamera, r.LightProjection, view);
  r.CasterPass->SetWindowToInverseW(WindowToInverseW(view, r.Frame.Resolution));

  const auto planes = shadowmaps::FrustumPlanes(view.ViewProjection());
  std::vector<vtkProp*> visible;
  for (const auto& caster : r.Casters)
  {
    if (FrustumMeetsBox(planes, caster.Bounds))
    {
      visible.push_back(caster.Prop);
    }
  }
  if (visible.empty())
  {
    return;
  }
  vtkRenderState casterState(renderer);
  casterState.SetPropArrayAndCount(visible.data(), static_cast<int>(visible.size()));
  casterState.SetFrameBuffer(nullptr);
  r.CasterPass->AttachToProps(&casterState);
  r.OpaquePass->Render(&casterState);
  r.CasterPass->DetachFromProps(&casterState);
  this->NumberOfCasterDraws += r.OpaquePass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::UpdateReceiverShaderKey(const vtkRenderState* s)
{
  Internals& r = *this->Internal;
  std::string key = shadowmaps::ReceiverShader::Key(r.Lights, this->NumberOfShadowMapLayers, r.Code);
  std::vector<vtkProp*> nonReceivers;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (!IsEnabled(prop->GetPropertyKeys(), RECEIVES_SHADOWS()))
    {
      nonReceivers.push_back(prop);
    }
  }
  if (key != r.ShaderKey || nonReceivers != r.NonReceivers)
  {
    r.ShaderKey = std::move(key);
    r.NonReceivers = std::move(nonReceivers);
    r.ShaderKeyTime.Modified();
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::BindShadowTextures(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  // Work on our own unit: creating a texture binds it to the active unit, which
  // may hold another pass's texture (e.g. the tone-mapping pass's colour).
  r.MapUnit = window->GetTextureUnitManager()->Allocate();
  glActiveTexture(GL_TEXTURE0 + r.MapUnit);
  r.Representation->ActivateReceiverResources(window);
  r.Maps.SetLinearFiltering(r.Representation->GetLinearFiltering());
  r.Maps.BindToUnit(r.MapUnit);
  r.Uniforms.NewFrame();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::UnbindShadowTextures(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  if (r.MapUnit >= 0)
  {
    glActiveTexture(GL_TEXTURE0 + r.MapUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    window->GetTextureUnitManager()->Free(r.MapUnit);
    r.MapUnit = -1;
  }
  this->GetRepresentation()->DeactivateReceiverResources();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReportGLFailure(const std::string& error)
{
  Internals& r = *this->Internal;
  r.Maps.Release();
  r.MapsValid = false;
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
  // generated per-light code to patch.
  shadowmaps::ReceiverShader::MarkInjectionPoints(fragmentShader);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PostReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  const Internals& r = *this->Internal;
  ++this->NumberOfReceiverShaderBuilds;
  const bool receives =
    r.Active && prop && IsEnabled(prop->GetPropertyKeys(), RECEIVES_SHADOWS());
  shadowmaps::ReceiverShader::Inject(
    fragmentShader, r.Lights, this->NumberOfShadowMapLayers, r.Code, receives);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  Internals& r = *this->Internal;
  if (r.Active && r.Uniforms.FirstUseThisFrame(program) &&
    shadowmaps::ReceiverUniforms::IsReceiver(program))
  {
    r.Uniforms.Apply(program, r.MapUnit, r.Frame.Resolution, this->NormalOffset);
    r.Representation->SetReceiverUniforms(program);
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
  if (!r.MapView.Render(window, r.Maps, r.MapUnit, r.Lights[this->AnalysisLight]))
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
  r.Signature.clear();
  r.MapView.ReleaseGraphicsResources(window);
  r.Representation->ReleaseGraphicsResources(window);
  if (r.DefaultRepresentation != r.Representation)
  {
    r.DefaultRepresentation->ReleaseGraphicsResources(window);
  }
  r.CasterPass->ReleaseGraphicsResources(window);
  r.OpaquePass->ReleaseGraphicsResources(window);
  r.DefaultDelegate->ReleaseGraphicsResources(window);
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
  os << indent << "Views:\n";
  this->Internal->Views->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Representation:\n";
  this->Internal->Representation->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "CasterFaces: " << this->CasterFaces << "\n";
  os << indent << "NormalOffset: " << this->NormalOffset << "\n";
  os << indent << "AnalysisView: " << this->AnalysisView << "\n";
  os << indent << "AnalysisLight: " << this->AnalysisLight << "\n";
  os << indent << "NumberOfShadowedLights: " << this->NumberOfShadowedLights << "\n";
  os << indent << "NumberOfShadowMapLayers: " << this->NumberOfShadowMapLayers << "\n";
  os << indent << "NumberOfNonFiniteViews: " << this->NumberOfNonFiniteViews << "\n";
  os << indent << "NumberOfShadowMapUpdates: " << this->NumberOfShadowMapUpdates << "\n";
  os << indent << "NumberOfCasterDraws: " << this->NumberOfCasterDraws << "\n";
  os << indent << "NumberOfReceiverShaderBuilds: " << this->NumberOfReceiverShaderBuilds << "\n";
}
