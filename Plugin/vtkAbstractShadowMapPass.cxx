#include "vtkAbstractShadowMapPass.h"

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
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapCasterPass.h"
#include "vtkShadowMapInternals.h"
#include "vtkShadowMapsDepthLookupFS.h"
#include "vtkShadowMapsReceiverFS.h"
#include "vtkShadowMapsViewFS.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTextureUnitManager.h"
#include "vtkVolume.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

vtkInformationKeyMacro(vtkAbstractShadowMapPass, CASTS_SHADOWS, Integer);
vtkInformationKeyMacro(vtkAbstractShadowMapPass, RECEIVES_SHADOWS, Integer);

using shadowmaps::Aabb;
using shadowmaps::LightKind;
using shadowmaps::LightView;
using shadowmaps::ShadowLight;

namespace
{
// Cones wider than this (half angle, degrees) are rendered as six cube faces:
// one perspective map that wide wastes most of its texels at the rim.
constexpr double WidestSingleMapCone = 60.0;
constexpr int NoiseSize = 32;

glm::dmat4 ToGlm(vtkMatrix4x4* m)
{
  glm::dmat4 result;
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      result[column][row] = m->GetElement(row, column);
    }
  }
  return result;
}

void ToVtk(const glm::dmat4& m, vtkMatrix4x4* result)
{
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      result->SetElement(row, column, m[column][row]);
    }
  }
}

// An absent key means yes.
bool IsEnabled(vtkInformation* info, vtkInformationIntegerKey* key)
{
  return !info || !info->Has(key) || info->Get(key) != 0;
}

glm::dvec3 ToGlm(const double v[3])
{
  return { v[0], v[1], v[2] };
}

// Polydata draws are patched where the mapper applies light i's colour: Phong's
// diffuse and specular sums and PBR's radiance (vtkOpenGLPolyDataMapper 9.1).
int InjectShadowFactor(std::string& fragmentShader, int shaderIndex, int lightIndex)
{
  const std::string color = "lightColor" + std::to_string(shaderIndex);
  const std::string factor = "vtkShadowFactor" + std::to_string(lightIndex);
  const std::pair<std::string, std::string> patterns[] = {
    { "diffuse += (df * " + color + ");", "diffuse += (df * " + color + " * " + factor + ");" },
    { "specular += (sf * " + color + ");", "specular += (sf * " + color + " * " + factor + ");" },
    { "radiance = " + color + ";", "radiance = " + color + " * " + factor + ";" },
    { "radiance = " + color + " * attenuation;",
      "radiance = " + color + " * " + factor + " * attenuation;" },
  };
  int replaced = 0;
  for (const auto& pattern : patterns)
  {
    for (size_t at = fragmentShader.find(pattern.first); at != std::string::npos;
         at = fragmentShader.find(pattern.first, at + pattern.second.size()))
    {
      fragmentShader.replace(at, pattern.first.size(), pattern.second);
      ++replaced;
    }
  }
  return replaced;
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

// 1 / W as a plane over texture coordinates (u, v, 1) for receivers of
// linear-depth views; zero for the others.
glm::vec3 TextureToInverseW(const LightView& view)
{
  if (!view.LinearDepth)
  {
    return glm::vec3(0.0f);
  }
  // x_ndc = 2 u - 1.
  const glm::dvec3 r = shadowmaps::NdcToInverseW(view);
  return glm::vec3(2.0 * r.x, 2.0 * r.y, r.z - r.x - r.y);
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
  const glm::vec3 t = TextureToInverseW(view);
  const float scale = 1.0f / static_cast<float>(std::max(resolution, 1));
  return { { t.x * scale, t.y * scale, t.z } };
}

// Per-texel rotations (cos, sin) of the Poisson disc.
vtkSmartPointer<vtkTextureObject> CreateRotationNoise(vtkOpenGLRenderWindow* window)
{
  std::mt19937 generator(20261122);
  std::uniform_real_distribution<float> angle(0.0f, 6.2831853f);
  std::vector<float> rotations(NoiseSize * NoiseSize * 2);
  for (size_t i = 0; i < rotations.size(); i += 2)
  {
    const float a = angle(generator);
    rotations[i] = std::cos(a);
    rotations[i + 1] = std::sin(a);
  }
  auto noise = vtkSmartPointer<vtkTextureObject>::New();
  noise->SetContext(window);
  noise->SetWrapS(vtkTextureObject::Repeat);
  noise->SetWrapT(vtkTextureObject::Repeat);
  noise->SetMinificationFilter(vtkTextureObject::Nearest);
  noise->SetMagnificationFilter(vtkTextureObject::Nearest);
  noise->Create2DFromRaw(NoiseSize, NoiseSize, 2, VTK_FLOAT, rotations.data());
  return noise;
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

// Volumes keep vtkProp's default HasOpaqueGeometry() but draw nothing into a
// depth map; as casters they would only re-render the maps on every transfer
// function edit.
bool DrawsIntoDepthMaps(vtkProp* prop)
{
  return prop->HasOpaqueGeometry() && !vtkVolume::SafeDownCast(prop);
}
} // namespace

struct vtkAbstractShadowMapPass::Resources
{
  shadowmaps::TextureArray Maps;
  shadowmaps::MapStorage Storage;
  std::string LookupCode; // GetReceiverLookupCode() of the current maps
  size_t LookupCodeHash = 0;
  vtkNew<vtkShadowMapCasterPass> CasterPass;
  vtkNew<vtkOpaquePass> OpaquePass;
  vtkNew<vtkCamera> LightCamera;
  vtkNew<vtkMatrix4x4> LightProjection;
  vtkNew<vtkRenderStepsPass> DefaultDelegate;
  vtkSmartPointer<vtkTextureObject> Noise;
  std::unique_ptr<vtkOpenGLQuadHelper> MapViewQuad;

  // What the maps were last rendered for; empty when they must be re-rendered.
  std::vector<vtkMTimeType> Signature;
  bool MapsValid = false;
  /// The lights and views the maps were rendered for (reused with the maps).
  std::vector<shadowmaps::ShadowLight> RenderedLights;

  // Receiver shaders depend on these; GetShaderStageMTime() follows them.
  std::string ShaderKey;
  std::vector<vtkProp*> NonReceivers;
  vtkTimeStamp ShaderKeyTime;

  // Uniform values of the current maps.
  std::vector<float> ViewToMap;
  std::vector<float> TexelSizes;
  /// Per view: 1 / W as a plane over texture (u, v, 1) for linear-depth views, else 0.
  std::vector<float> DepthInverseW;
  std::vector<float> Cascades;
  std::vector<float> TileGrids;
  std::vector<float> CascadeLights;
  std::vector<float> LightPositions;
  std::vector<float> Attenuations;
  glm::mat4 ViewToWorld{ 1.0f };
  int MapUnit = -1;

  bool Active = false;
  bool WarnedTooManyLights = false;
  bool WarnedNonFiniteViews = false;
  bool WarnedResolution = false;
  std::string LastGLError;
  std::string WarnedGLError;
};

//------------------------------------------------------------------------------
vtkAbstractShadowMapPass::vtkAbstractShadowMapPass()
  : Internal(new Internals)
  , Resource(new Resources)
{
  this->Resource->ShaderKeyTime.Modified();
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
size_t vtkAbstractShadowMapPass::GetShadowMapMemory() const
{
  return this->Resource->Maps.GetMemoryBytes();
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfDepthOnlyCasterShaders() const
{
  return this->Resource->CasterPass->GetNumberOfDepthOnlyShaders();
}

//------------------------------------------------------------------------------
int vtkAbstractShadowMapPass::GetNumberOfOwnFragmentCasterShaders() const
{
  return this->Resource->CasterPass->GetNumberOfOwnFragmentShaders();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  auto* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkRenderPass* delegate =
    this->DelegatePass ? this->DelegatePass : this->Resource->DefaultDelegate.Get();

  Resources& r = *this->Resource;
  r.Active = renderer && this->PrepareShadows(s, renderer);
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
bool vtkAbstractShadowMapPass::PrepareShadows(const vtkRenderState*, vtkOpenGLRenderer* renderer)
{
  renderer->UpdateLightsGeometryToFollowCamera();
  this->CollectLights(renderer);
  this->NumberOfShadowedLights = static_cast<int>(this->Internal->Lights.size());
  if (this->Internal->Lights.empty())
  {
    this->NumberOfShadowMapLayers = 0;
    return false;
  }
  this->CollectPropsAndBounds(renderer);
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
    if (!light->GetPositional())
    {
      shadowLight.Kind = LightKind::Directional;
    }
    else if (shadowLight.ConeAngle < 90.0)
    {
      shadowLight.Kind = LightKind::Spot;
      shadowLight.Cube = shadowLight.ConeAngle > WidestSingleMapCone;
    }
    else
    {
      shadowLight.Kind = LightKind::Point;
      shadowLight.Cube = true;
    }
    lights.push_back(shadowLight);
  }
  if (skipped > 0 && !this->Resource->WarnedTooManyLights)
  {
    vtkWarningMacro(<< skipped << " light(s) beyond the first " << VTK_MAX_SHADOWED_LIGHTS
                    << " shadowed lights cast no shadows; they still light the scene.");
  }
  this->Resource->WarnedTooManyLights = skipped > 0;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::CollectPropsAndBounds(vtkOpenGLRenderer* renderer)
{
  Internals& in = *this->Internal;
  in.Casters.clear();
  in.PropBounds.clear();
  in.SceneBounds = Aabb();
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
    in.SceneBounds.Add(bounds);
    in.PropBounds.push_back(bounds);
    if (!prop->GetPropertyKeys())
    {
      // Render passes create the keys on first use, which modifies the prop;
      // create them now so that this first use does not re-render the maps.
      vtkNew<vtkInformation> keys;
      prop->SetPropertyKeys(keys);
    }
    if (IsEnabled(prop->GetPropertyKeys(), CASTS_SHADOWS()) && DrawsIntoDepthMaps(prop))
    {
      in.Casters.push_back({ prop, bounds });
    }
  }

  vtkCamera* camera = renderer->GetActiveCamera();
  in.CameraView = ToGlm(camera->GetViewTransformMatrix());
  in.CameraProjection =
    ToGlm(camera->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1.0, 1.0));
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::UpdateShadowMaps(vtkOpenGLRenderer* renderer)
{
  Internals& in = *this->Internal;
  Resources& r = *this->Resource;

  int size[2];
  int origin[2];
  renderer->GetTiledSizeAndOrigin(size, size + 1, origin, origin + 1);
  std::vector<vtkMTimeType> signature = { this->GetMTime(), renderer->GetLights()->GetMTime(),
    renderer->GetViewProps()->GetMTime(), static_cast<vtkMTimeType>(size[0]),
    static_cast<vtkMTimeType>(size[1]) };
  AppendMatrixBits(in.CameraView, signature);
  AppendMatrixBits(in.CameraProjection, signature);
  for (const auto& light : in.Lights)
  {
    signature.push_back(reinterpret_cast<vtkMTimeType>(light.Light));
    signature.push_back(light.Light->GetMTime());
  }
  for (const auto& caster : in.Casters)
  {
    signature.push_back(reinterpret_cast<vtkMTimeType>(caster.Prop));
    signature.push_back(CasterMTime(caster.Prop));
  }
  if (r.MapsValid && signature == r.Signature)
  {
    // CollectLights rebuilt the lights without views; the maps hold these.
    in.Lights = r.RenderedLights;
    return true;
  }
  r.Signature.clear();
  r.MapsValid = false;

  GLint maximumSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maximumSize);
  in.Resolution = std::min(this->Resolution, std::max(static_cast<int>(maximumSize), 64));
  if (in.Resolution != this->Resolution && !r.WarnedResolution)
  {
    vtkWarningMacro(<< "Resolution " << this->Resolution << " exceeds the GL maximum texture size; using "
                    << in.Resolution << ".");
    r.WarnedResolution = true;
  }

  for (int i = 0; i < static_cast<int>(in.Lights.size()); ++i)
  {
    this->ComputeLightViews(in, i);
  }
  this->DropLightsWithNonFiniteViews();
  if (in.Lights.empty())
  {
    this->NumberOfShadowMapLayers = 0;
    return false;
  }
  int layers = 0;
  for (ShadowLight& light : in.Lights)
  {
    light.FirstLayer = layers;
    layers += static_cast<int>(light.Views.size());
  }
  this->NumberOfShadowMapLayers = layers;

  this->GetMapStorage(r.Storage);
  const bool thirtyTwoBitNow =
    r.Maps.GetResolution() != 0 && r.Maps.GetFormat() == shadowmaps::TexelFormat::Depth;
  if (r.Storage.Format == shadowmaps::TexelFormat::Depth &&
    SixteenBitDepthSuffices(in.Lights, thirtyTwoBitNow))
  {
    r.Storage.Format = shadowmaps::TexelFormat::Depth16;
  }
  r.LookupCode = this->GetReceiverLookupCode();
  r.LookupCodeHash = std::hash<std::string>{}(r.LookupCode);
  std::string error;
  if (!r.Maps.Reserve(in.Resolution, layers, r.Storage.Format, r.Storage.Mipmaps, error) ||
    !this->RenderShadowMaps(renderer))
  {
    this->ReportGLFailure(error.empty() ? r.LastGLError : error);
    return false;
  }
  this->StoreReceiverUniforms();
  r.RenderedLights = in.Lights;
  r.Signature = std::move(signature);
  r.MapsValid = true;
  r.WarnedGLError.clear();
  ++this->NumberOfShadowMapUpdates;
  return true;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ApplyDepthBias(const ShadowLight& light, const LightView& view)
{
  // 32-bit depth (linear-depth views are never 16-bit): one polygon-offset unit
  // is 2^-24 for depths in [0.5, 1).
  constexpr float DepthUnit = 1.0f / 16777216.0f;
  const auto slope = static_cast<float>(this->SlopeScaledBias);
  const auto constant = static_cast<float>(this->ConstantBias);
  if (view.LinearDepth)
  {
    // A directional light's linear depth spans its casters and B: its
    // slope-scaled term is capped at what a 45 degree surface needs in a
    // uniform map as deep as it is wide (SlopeScaledBias texels' worth, 2 /
    // resolution at the default). A spot's stored depth is its post-perspective
    // depth, crowded toward 1: no such cap.
    const float cap = light.Kind == LightKind::Directional
      ? slope / static_cast<float>(std::max(this->Internal->Resolution, 1))
      : std::numeric_limits<float>::max();
    glPolygonOffset(0.0f, 0.0f);
    this->Resource->CasterPass->SetLinearDepthBias({ { slope, constant * DepthUnit, cap } });
  }
  else
  {
    glPolygonOffset(slope, constant);
    this->Resource->CasterPass->SetLinearDepthBias({ { 0.0f, 0.0f, 0.0f } });
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::DropLightsWithNonFiniteViews()
{
  std::vector<ShadowLight>& lights = this->Internal->Lights;
  const std::size_t before = lights.size();
  this->NumberOfNonFiniteViews = 0;
  lights.erase(std::remove_if(lights.begin(), lights.end(),
                 [this](const ShadowLight& light) {
                   const auto nonFinite = std::count_if(light.Views.begin(), light.Views.end(), IsNonFinite);
                   this->NumberOfNonFiniteViews += static_cast<int>(nonFinite);
                   return nonFinite > 0;
                 }),
    lights.end());
  if (lights.size() == before)
  {
    this->Resource->WarnedNonFiniteViews = false;
    return;
  }
  if (!this->Resource->WarnedNonFiniteViews)
  {
    vtkWarningMacro(<< this->NumberOfNonFiniteViews
                    << " light view(s) came out with non-finite matrices; their lights cast no "
                       "shadows until the views are finite again.");
    this->Resource->WarnedNonFiniteViews = true;
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::FitLightViewsUniform(Internals& in, int lightIndex)
{
  ShadowLight& light = in.Lights[lightIndex];
  light.Views.clear();
  if (light.Cube)
  {
    const auto faces = shadowmaps::FitCubeFacesToView(
      in.CameraViewProjection(), in.SceneBounds, light.Position, in.Resolution);
    light.Views.assign(faces.begin(), faces.end());
  }
  else if (light.Kind == LightKind::Spot)
  {
    light.Views.push_back(shadowmaps::FitSpot(in.CameraViewProjection(), in.SceneBounds,
      light.Position, light.Direction, light.ConeAngle, in.Resolution));
  }
  else
  {
    light.Views.push_back(shadowmaps::FitDirectional(
      in.CameraViewProjection(), in.SceneBounds, light.Direction, in.Resolution));
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::GetMapStorage(shadowmaps::MapStorage& storage) const
{
  storage = shadowmaps::MapStorage();
}

//------------------------------------------------------------------------------
std::string vtkAbstractShadowMapPass::GetReceiverLookupCode() const
{
  return vtkShadowMapsDepthLookupFS;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PostProcessShadowMaps(vtkOpenGLRenderer*, shadowmaps::TextureArray&)
{
  return true;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::RenderShadowMaps(vtkOpenGLRenderer* renderer)
{
  Internals& in = *this->Internal;
  Resources& r = *this->Resource;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();

  state->PushFramebufferBindings();
  vtkOpenGLState::ScopedglViewport savedViewport(state);
  vtkOpenGLState::ScopedglEnableDisable savedScissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedOffset(state, GL_POLYGON_OFFSET_FILL);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglEnable(GL_POLYGON_OFFSET_FILL);
  // Casters nearer the light than a view's near plane are clamped onto it rather
  // than clipped ("pancaking"): they still occlude all that lies behind them, so
  // a fit may put its near plane where depth precision is needed.
  const GLboolean depthClampWasOn = glIsEnabled(GL_DEPTH_CLAMP);
  glEnable(GL_DEPTH_CLAMP);
  const bool minimumBlending =
    r.Storage.Format == shadowmaps::TexelFormat::TwoFloats && r.Storage.MinimumBlending;
  if (minimumBlending)
  {
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendEquation(GL_MIN);
  }

  vtkSmartPointer<vtkCamera> userCamera = renderer->GetActiveCamera();
  renderer->SetActiveCamera(r.LightCamera);
  r.CasterPass->SetCasterFaces(this->CasterFaces);
  r.CasterPass->SetStoreCode(
    r.Storage.Format == shadowmaps::TexelFormat::TwoFloats ? r.Storage.StoreCode : std::string());
  r.CasterPass->SetLinearDepth(std::any_of(in.Lights.begin(), in.Lights.end(), [](const ShadowLight& l) {
    return std::any_of(l.Views.begin(), l.Views.end(), [](const LightView& v) { return v.LinearDepth; });
  }));
  this->NumberOfCasterDraws = 0;

  bool ok = true;
  for (ShadowLight& light : in.Lights)
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
  glPolygonOffset(0.0f, 0.0f);
  if (!depthClampWasOn)
  {
    glDisable(GL_DEPTH_CLAMP);
  }
  if (minimumBlending)
  {
    state->vtkglBlendEquation(GL_FUNC_ADD);
  }
  state->PopFramebufferBindings();
  if (ok)
  {
    r.Maps.GenerateMipmaps();
    ok = this->PostProcessShadowMaps(renderer, r.Maps);
    if (!ok)
    {
      r.LastGLError = "the shadow maps could not be post-processed";
    }
  }
  return ok;
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ClearLayer(vtkOpenGLRenderer* renderer)
{
  Resources& r = *this->Resource;
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow())->GetState();
  state->vtkglViewport(0, 0, this->Internal->Resolution, this->Internal->Resolution);
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
  Internals& in = *this->Internal;
  Resources& r = *this->Resource;
  this->ClearLayer(renderer);
  if (view.OutOfView)
  {
    return;
  }

  SetCameraToView(r.LightCamera, r.LightProjection, view);
  r.CasterPass->SetWindowToInverseW(WindowToInverseW(view, in.Resolution));

  const auto planes = shadowmaps::FrustumPlanes(view.ViewProjection());
  std::vector<vtkProp*> visible;
  for (const auto& caster : in.Casters)
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
void vtkAbstractShadowMapPass::StoreReceiverUniforms()
{
  Internals& in = *this->Internal;
  Resources& r = *this->Resource;
  r.ViewToMap.clear();
  r.TexelSizes.clear();
  r.DepthInverseW.clear();
  r.Cascades.clear();
  r.TileGrids.clear();
  r.CascadeLights.clear();
  r.LightPositions.clear();
  const glm::dmat4 viewToWorld = glm::inverse(in.CameraView);
  r.Attenuations.clear();
  const glm::dmat4 toTexture = shadowmaps::ClipToTexture();
  for (const ShadowLight& light : in.Lights)
  {
    for (const LightView& view : light.Views)
    {
      const glm::dmat4 viewToMapD = toTexture * view.ViewProjection() * viewToWorld;
      const glm::vec3 inverseW = TextureToInverseW(view);
      r.DepthInverseW.insert(r.DepthInverseW.end(), glm::value_ptr(inverseW), glm::value_ptr(inverseW) + 3);
      const size_t cascade = static_cast<size_t>(&view - light.Views.data());
      // Cascades of one light share their texel formula's kind (constant for
      // directional, per unit distance for spot), so the sum compares them.
      const double firstTexel =
        light.Views.front().TexelConstant + light.Views.front().TexelPerUnitDistance;
      const double texel = view.TexelConstant + view.TexelPerUnitDistance;
      const glm::vec4 depths = light.Cascaded && cascade < light.CascadeDepths.size()
        ? glm::vec4(glm::vec3(light.CascadeDepths[cascade]),
            firstTexel > 0.0 && texel > 0.0 ? firstTexel / texel : 1.0)
        : glm::vec4(0.0f, 1e38f, 1e38f, 1.0f);
      r.Cascades.insert(r.Cascades.end(), glm::value_ptr(depths), glm::value_ptr(depths) + 4);
      const glm::mat4 viewToMap(viewToMapD);
      r.ViewToMap.insert(r.ViewToMap.end(), glm::value_ptr(viewToMap), glm::value_ptr(viewToMap) + 16);
      // A negative constant tells the receiver to use the map's local gradient.
      r.TexelSizes.push_back(
        view.TexelSizeFromGradient ? -1.0f : static_cast<float>(view.TexelConstant));
      r.TexelSizes.push_back(static_cast<float>(view.TexelPerUnitDistance));
    }
    const glm::dvec3 positionVC(in.CameraView * glm::dvec4(light.Position, 1.0));
    r.LightPositions.push_back(static_cast<float>(positionVC.x));
    r.LightPositions.push_back(static_cast<float>(positionVC.y));
    r.LightPositions.push_back(static_cast<float>(positionVC.z));
    r.Attenuations.push_back(light.Attenuation);
    r.CascadeLights.push_back(static_cast<float>(light.Fade.x));
    r.CascadeLights.push_back(static_cast<float>(light.Fade.y));
    r.CascadeLights.push_back(static_cast<float>(light.CoverageBlendFraction));
    const shadowmaps::TileGrid& tiles = light.Tiles;
    const float grid[4] = { static_cast<float>(tiles.Columns), static_cast<float>(tiles.Rows),
      static_cast<float>(tiles.WindowFraction.x), static_cast<float>(tiles.WindowFraction.y) };
    r.TileGrids.insert(r.TileGrids.end(), grid, grid + 4);
  }
  r.ViewToWorld = glm::mat4(viewToWorld);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::UpdateReceiverShaderKey(const vtkRenderState* s)
{
  Resources& r = *this->Resource;
  std::ostringstream key;
  key << this->Filter << ' ' << this->KernelSize << ' ' << this->PoissonSamples << ' '
      << this->NumberOfShadowMapLayers << ' ' << r.LookupCodeHash
      << ' ' << this->AnalysisView << ' ' << this->AnalysisLight << ';';
  for (const ShadowLight& light : this->Internal->Lights)
  {
    key << light.ShaderIndex << ':' << light.FirstLayer << ':' << light.ViewKind() << ':'
        << light.Views.size() << ':' << light.ReceiverFeatures() << ' ';
  }
  std::vector<vtkProp*> nonReceivers;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (!IsEnabled(prop->GetPropertyKeys(), RECEIVES_SHADOWS()))
    {
      nonReceivers.push_back(prop);
    }
  }
  if (key.str() != r.ShaderKey || nonReceivers != r.NonReceivers)
  {
    r.ShaderKey = key.str();
    r.NonReceivers = std::move(nonReceivers);
    r.ShaderKeyTime.Modified();
  }
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::BindShadowTextures(vtkOpenGLRenderer* renderer)
{
  Resources& r = *this->Resource;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  // Work on our own unit: creating a texture binds it to the active unit, which
  // may hold another pass's texture (e.g. the tone-mapping pass's colour).
  r.MapUnit = window->GetTextureUnitManager()->Allocate();
  glActiveTexture(GL_TEXTURE0 + r.MapUnit);
  if (!r.Noise)
  {
    r.Noise = CreateRotationNoise(window);
  }
  r.Noise->Activate();
  r.Maps.SetLinearFiltering(this->Filter != HARD);
  r.Maps.BindToUnit(r.MapUnit);
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::UnbindShadowTextures(vtkOpenGLRenderer* renderer)
{
  Resources& r = *this->Resource;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  if (r.MapUnit >= 0)
  {
    glActiveTexture(GL_TEXTURE0 + r.MapUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    window->GetTextureUnitManager()->Free(r.MapUnit);
    r.MapUnit = -1;
  }
  r.Noise->Deactivate();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReportGLFailure(const std::string& error)
{
  Resources& r = *this->Resource;
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
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Dec", "//VTK::Light::Dec\n//VTK::ShadowMaps::Dec", false);
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Impl", "//VTK::ShadowMaps::Impl\n//VTK::Light::Impl", false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::PostReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  // The receiver's position is taken in the fragment shader, not the vertex
  // shader, because impostor mappers compute their true surface per fragment.
  std::ostringstream impl;
  if (this->Resource->Active && prop && IsEnabled(prop->GetPropertyKeys(), RECEIVES_SHADOWS()))
  {
    const auto& lights = this->Internal->Lights;
    for (int k = 0; k < static_cast<int>(lights.size()); ++k)
    {
      if (InjectShadowFactor(fragmentShader, lights[k].ShaderIndex, k) > 0)
      {
        impl << "  float vtkShadowFactor" << k << " = vtkShadowFactor(vertexVC.xyz, "
             << "vtkShadowNormalVC, " << k << ", " << lights[k].FirstLayer << ", "
             << lights[k].ViewKind() << ", " << lights[k].Views.size() << ", "
             << lights[k].ReceiverFeatures() << ");\n";
      }
    }
  }
  if (impl.tellp() <= 0)
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::ShadowMaps::Dec", "");
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::ShadowMaps::Impl", "");
    return true;
  }
  const std::string analysis = this->AnalysisCode();
  if (!analysis.empty())
  {
    // After everything that sets the colour: main() is the last function.
    const size_t end = fragmentShader.rfind('}');
    if (end != std::string::npos)
    {
      fragmentShader.insert(end, analysis);
    }
  }
  std::ostringstream dec;
  if (!analysis.empty())
  {
    dec << "#define VTK_SHADOW_ANALYSIS " << this->AnalysisView << "\n";
  }
  dec << "#define VTK_SHADOW_FILTER " << this->Filter << "\n"
      << "#define VTK_SHADOW_KERNEL " << this->KernelSize << "\n"
      << "#define VTK_SHADOW_POISSON_SAMPLES " << this->PoissonSamples << "\n"
      << "#define VTK_SHADOW_MAX_VIEWS " << std::max(this->NumberOfShadowMapLayers, 1) << "\n"
      << "#define VTK_SHADOW_MAX_LIGHTS " << this->Internal->Lights.size() << "\n"
      << vtkShadowMapsReceiverFS << this->Resource->LookupCode;
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::ShadowMaps::Dec", dec.str());
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::ShadowMaps::Impl",
    "  vec3 vtkShadowNormalVC = normalize(normalVCVSOutput);\n" +
      impl.str());
  return true;
}

//------------------------------------------------------------------------------
std::string vtkAbstractShadowMapPass::AnalysisCode() const
{
  const auto& lights = this->Internal->Lights;
  if (this->AnalysisView == NO_ANALYSIS || this->AnalysisView == SHADOW_MAP ||
    this->AnalysisLight >= static_cast<int>(lights.size()))
  {
    return std::string();
  }
  const ShadowLight& light = lights[this->AnalysisLight];
  std::ostringstream code;
  code << "  gl_FragData[0] = vtkShadowAnalysisColor(vertexVC.xyz, vtkShadowNormalVC, "
       << this->AnalysisLight << ", " << light.FirstLayer << ", " << light.ViewKind() << ", "
       << light.Views.size() << ", " << light.ReceiverFeatures() << ");\n";
  return code.str();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::RenderShadowMapView(vtkOpenGLRenderer* renderer)
{
  Resources& r = *this->Resource;
  const auto& lights = this->Internal->Lights;
  if (this->AnalysisLight >= static_cast<int>(lights.size()))
  {
    return;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  if (!r.MapViewQuad)
  {
    r.MapViewQuad.reset(new vtkOpenGLQuadHelper(window, nullptr, vtkShadowMapsViewFS, ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(r.MapViewQuad->Program);
  }
  vtkShaderProgram* program = r.MapViewQuad->Program;
  if (!program || !program->GetCompiled())
  {
    this->ReportGLFailure("the shadow-map view shader did not compile");
    return;
  }
  const ShadowLight& light = lights[this->AnalysisLight];
  program->SetUniformi("vtkShadowMaps", r.MapUnit);
  program->SetUniformi("vtkShadowFirstView", light.FirstLayer);
  program->SetUniformi("vtkShadowViewCount", static_cast<int>(light.Views.size()));
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  r.Maps.SetDepthComparison(false);
  r.MapViewQuad->Render();
  r.Maps.SetDepthComparison(true);
}

//------------------------------------------------------------------------------
bool vtkAbstractShadowMapPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  Resources& r = *this->Resource;
  if (!r.Active || !program->IsUniformUsed("vtkShadowViewToMap"))
  {
    return true;
  }
  const int views = static_cast<int>(r.TexelSizes.size() / 2);
  const int lights = static_cast<int>(r.Attenuations.size());
  program->SetUniformi("vtkShadowMaps", r.MapUnit);
  program->SetUniformi("vtkShadowNoise", r.Noise->GetTextureUnit());
  program->SetUniformMatrix4x4("vtkShadowViewToWorld", glm::value_ptr(r.ViewToWorld));
  program->SetUniformMatrix4x4v("vtkShadowViewToMap", views, r.ViewToMap.data());
  program->SetUniform2fv(
    "vtkShadowTexelSize", views, reinterpret_cast<const float(*)[2]>(r.TexelSizes.data()));
  program->SetUniform3fv(
    "vtkShadowDepthInverseW", views, reinterpret_cast<const float(*)[3]>(r.DepthInverseW.data()));
  program->SetUniform4fv("vtkShadowCascade", views, reinterpret_cast<const float(*)[4]>(r.Cascades.data()));
  program->SetUniform4fv(
    "vtkShadowTileGrid", lights, reinterpret_cast<const float(*)[4]>(r.TileGrids.data()));
  program->SetUniform3fv(
    "vtkShadowCascadeLight", lights, reinterpret_cast<const float(*)[3]>(r.CascadeLights.data()));
  program->SetUniform3fv(
    "vtkShadowLightPositionVC", lights, reinterpret_cast<const float(*)[3]>(r.LightPositions.data()));
  program->SetUniform1fv("vtkShadowAttenuation", lights, r.Attenuations.data());
  program->SetUniformf("vtkShadowMapResolution", static_cast<float>(this->Internal->Resolution));
  program->SetUniformf("vtkShadowNormalOffset", static_cast<float>(this->NormalOffset));
  program->SetUniformf("vtkShadowFilterRadius", static_cast<float>(this->FilterRadius));
  return true;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkAbstractShadowMapPass::GetShaderStageMTime()
{
  return this->Resource->ShaderKeyTime.GetMTime();
}

//------------------------------------------------------------------------------
void vtkAbstractShadowMapPass::ReleaseGraphicsResources(vtkWindow* window)
{
  Resources& r = *this->Resource;
  r.Maps.Release();
  r.MapsValid = false;
  r.Signature.clear();
  if (r.Noise)
  {
    r.Noise->ReleaseGraphicsResources(window);
    r.Noise = nullptr;
  }
  if (r.MapViewQuad)
  {
    r.MapViewQuad->ReleaseGraphicsResources(window);
    r.MapViewQuad.reset();
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
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "CasterFaces: " << this->CasterFaces << "\n";
  os << indent << "Filter: " << this->Filter << "\n";
  os << indent << "KernelSize: " << this->KernelSize << "\n";
  os << indent << "FilterRadius: " << this->FilterRadius << "\n";
  os << indent << "PoissonSamples: " << this->PoissonSamples << "\n";
  os << indent << "ConstantBias: " << this->ConstantBias << "\n";
  os << indent << "SlopeScaledBias: " << this->SlopeScaledBias << "\n";
  os << indent << "NormalOffset: " << this->NormalOffset << "\n";
  os << indent << "AnalysisView: " << this->AnalysisView << "\n";
  os << indent << "AnalysisLight: " << this->AnalysisLight << "\n";
  os << indent << "NumberOfShadowedLights: " << this->NumberOfShadowedLights << "\n";
  os << indent << "NumberOfShadowMapLayers: " << this->NumberOfShadowMapLayers << "\n";
  os << indent << "NumberOfShadowMapUpdates: " << this->NumberOfShadowMapUpdates << "\n";
}
