#include "ShadowMapReceiverShader.h"

#include "ShadowMapCasterShader.h"
#include "ShadowMapCrop.h"
#include "ShadowMapImpostors.h"
#include "ShadowMapLight.h"
#include "ShadowMapShaderGroup.h"
#include "ShadowMapTrapezoid.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsReceiverFS.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

namespace shadowmaps
{
namespace
{
// Polydata draws are patched where the mapper applies light i's colour: Phong's
// diffuse and specular sums and PBR's radiance (vtkOpenGLPolyDataMapper 9.1).
int InjectShadowFactor(std::string& fragmentShader, int shaderIndex, const std::string& factor)
{
  const std::string color = "lightColor" + std::to_string(shaderIndex);
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

// A translucent receiver's own transmittance, for the maps' product to hold
// it once (vtkShadowOwnTransmittance); nothing for an opaque receiver's.
std::string OwnTransmittance(const std::string& fragmentShader, const ReceiverCode& code)
{
  const std::string transmitted =
    code.Transmittance ? CasterShader::TransmittedLight(fragmentShader) : std::string();
  return transmitted.empty() ? std::string()
                             : "  vtkShadowOwnTransmittance = " + transmitted + ";\n";
}

// Whether the shader uses `name` as a whole word (lightColor1, not
// lightColor12) outside a uniform's declaration: VTK declares every light's
// colour for props it then draws unlit (lighting off, lines without normals).
bool UsesWord(const std::string& shader, const std::string& name)
{
  for (size_t at = shader.find(name); at != std::string::npos; at = shader.find(name, at + 1))
  {
    const size_t end = at + name.size();
    const bool whole = end == shader.size() ||
      !(std::isalnum(static_cast<unsigned char>(shader[end])) || shader[end] == '_');
    const size_t line = shader.find_last_of('\n', at);
    const size_t first = shader.find_first_not_of(" \t", line == std::string::npos ? 0 : line + 1);
    if (whole && shader.compare(first, 8, "uniform ") != 0)
    {
      return true;
    }
  }
  return false;
}

const char* const UniformFlowMarker = "//VTK::ShadowMaps::UniformFlow";

// The volume ray caster's template (raycasterfs.glsl, VTK 9.1 to 9.6): where
// its declarations end, where each ray starts, and the lines that composite a
// sample (premultiplying its colour by its opacity; the independent
// components' path composites its own sum).
const char* const VolumeDecMarker = "//VTK::ShadowMaps::VolumeDec";
const char* const VolumeRayMarker = "//VTK::ShadowMaps::VolumeRay";
const char* const VolumeFactorCall = "vtkShadowVolumeFactor(g_dataPos)";
const std::pair<const char*, const char*> VolumeSamplePatterns[] = {
  { "g_srcColor.rgb *= g_srcColor.a;",
    "g_srcColor.rgb *= vtkShadowVolumeFactor(g_dataPos) * g_srcColor.a;" },
  { "g_fragColor = (1.0f - g_fragColor.a) * tmp + g_fragColor;",
    "tmp.rgb *= vtkShadowVolumeFactor(g_dataPos);\n"
    "      g_fragColor = (1.0f - g_fragColor.a) * tmp + g_fragColor;" },
};

// The volumes' receiver function: what reaches a sample of the lights, as a
// factor of its colour. The maps' transmittance holds the volume's own
// absorption at one depth per texel: a sample takes the opaque casters'
// shadows only. A sample has no surface: it faces each light (its normal
// offset moves it toward the light, and a dual-depth map compares it with a
// plane across the light's rays). Shadows change over the maps' texels while
// samples step by half voxels: a ray takes the shadow at every
// VTK_SHADOW_VOLUME_REUSE-th sample it composites and keeps it for the others.
std::string VolumeFactorFunction(const std::vector<ShadowLight>& lights)
{
  std::ostringstream function;
  function << "mat4 vtkShadowVolumeTextureToVC = mat4(1.0);\n"
              "const int VTK_SHADOW_VOLUME_REUSE = 4;\n"
              "int vtkShadowVolumeSamples = 0;\n"
              "vec3 vtkShadowVolumeKept = vec3(1.0);\n"
              "uniform float vtkShadowVolumeLightShares[VTK_SHADOW_MAX_LIGHTS];\n"
              "vec3 vtkShadowTowardLight(vec3 positionVC, int light)\n{\n"
              "  vec3 relative = positionVC - vtkShadowLights[light].DepthOrigin;\n"
              "  vec3 deeper = vtkShadowLights[light].DepthPlane.xyz +\n"
              "    vtkShadowLights[light].DepthPerDistance * relative / max(length(relative), 1e-30);\n"
              "  return length(deeper) > 0.0 ? -normalize(deeper) : vec3(0.0, 0.0, 1.0);\n}\n"
              "vec3 vtkShadowVolumeFactor(vec3 texturePosition)\n{\n"
              "  if (vtkShadowReceiving == 0 ||\n"
              "    vtkShadowVolumeSamples++ % VTK_SHADOW_VOLUME_REUSE != 0)\n  {\n"
              "    return vtkShadowVolumeKept;\n  }\n"
              "  vec4 position = vtkShadowVolumeTextureToVC * vec4(texturePosition, 1.0);\n"
              "  vec3 vtkShadowPositionVC = position.xyz / position.w;\n"
              "  vec3 vtkShadowNormalVC;\n"
              "#ifdef VTK_SHADOW_TRANSMITTANCE\n"
              "  vtkShadowTransmittanceReceived = false;\n"
              "#endif\n"
              "  vec3 factor = vec3(1.0);\n";
  for (int k = 0; k < static_cast<int>(lights.size()); ++k)
  {
    function << "  vtkShadowNormalVC = vtkShadowTowardLight(vtkShadowPositionVC, " << k << ");\n"
             << "#ifdef VTK_SHADOW_RECEIVER_PLANE\n"
                "  vtkShadowPlaneNormalVC = vtkShadowNormalVC;\n"
                "#endif\n"
             << "  factor -= vtkShadowVolumeLightShares[" << k
             << "] * (1.0 - vec3(vtkShadowFactor(" << ReceiverCallArguments(lights[k], k)
             << ")));\n";
  }
  function << "  vtkShadowVolumeKept = factor;\n  return factor;\n}\n";
  return function.str();
}

void ClearVolumeMarkers(std::string& fragmentShader)
{
  vtkShaderProgram::Substitute(fragmentShader, VolumeDecMarker, "");
  vtkShaderProgram::Substitute(fragmentShader, VolumeRayMarker, "");
}

// Puts `text` before `marker`, which stays for the next group's code.
void PutBeforeMarker(std::string& shader, const std::string& marker, const std::string& text)
{
  vtkShaderProgram::Substitute(shader, marker, text + marker);
}

void ClearSurfaceMarkers(std::string& fragmentShader)
{
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::ShadowMaps::Dec", "");
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::ShadowMaps::Impl", "");
  vtkShaderProgram::Substitute(fragmentShader, UniformFlowMarker, "");
}

// The receiver functions and what they need around them.
std::string Declarations(const std::vector<ShadowLight>& lights, int layers, const ReceiverCode& code)
{
  std::ostringstream dec;
  dec << ReceiverShaderConstants() << code.Definitions
      << "#define VTK_SHADOW_MAX_VIEWS " << std::max(layers, 1) << "\n"
      << "#define VTK_SHADOW_MAX_LIGHTS " << lights.size() << "\n"
      << "uniform int vtkShadowReceiving;\n"
      << vtkShadowMapsReceiverFS << code.Lookup << code.AnalysisFunctions;
  return dec.str();
}

glm::vec3 ToFloat(const glm::dvec3& v)
{
  return glm::vec3(v);
}
} // namespace

//------------------------------------------------------------------------------
std::string ReceiverShaderConstants()
{
  const std::pair<const char*, int> constants[] = {
    { "VTK_SHADOW_LAYOUT_SINGLE", static_cast<int>(ViewLayout::Single) },
    { "VTK_SHADOW_LAYOUT_CUBE_FACES", static_cast<int>(ViewLayout::CubeFaces) },
    { "VTK_SHADOW_LAYOUT_CASCADES", static_cast<int>(ViewLayout::Cascades) },
    { "VTK_SHADOW_LAYOUT_TILES", static_cast<int>(ViewLayout::Tiles) },
    { "VTK_SHADOW_LAYOUT_PERSPECTIVE_CUBE", static_cast<int>(ViewLayout::PerspectiveCube) },
    { "VTK_SHADOW_FEATURE_GRADIENT_TEXELS", GradientTexels },
    { "VTK_SHADOW_FEATURE_DISTANT_TEXELS", DistantTexels },
    { "VTK_SHADOW_FEATURE_LINEAR_DEPTHS", LinearDepths },
    { "VTK_SHADOW_FEATURE_CROPPED_VIEWS", CroppedViews },
    { "VTK_SHADOW_FEATURE_CASCADE_BLENDS", CascadeBlends },
    { "VTK_SHADOW_FEATURE_SIZED_LIGHT", SizedLight },
  };
  std::ostringstream defines;
  for (const auto& constant : constants)
  {
    defines << "#define " << constant.first << " " << constant.second << "\n";
  }
  return defines.str();
}

//------------------------------------------------------------------------------
std::string ReceiverCallArguments(const ShadowLight& light, int index)
{
  std::ostringstream arguments;
  arguments << "vtkShadowPositionVC, vtkShadowNormalVC, " << index << ", " << light.FirstLayer << ", "
            << static_cast<int>(light.Layout) << ", " << light.Views.size() << ", "
            << ReceiverFeatures(light);
  return arguments.str();
}

//------------------------------------------------------------------------------
void ReceiverShader::MarkInjectionPoints(std::string& fragmentShader)
{
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Dec", "//VTK::Light::Dec\n//VTK::ShadowMaps::Dec", false);
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Impl", "//VTK::ShadowMaps::Impl\n//VTK::Light::Impl", false);
  // After the mapper's own uniform-flow code, which may replace VTK's marker.
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::UniformFlow::Impl",
    std::string("//VTK::UniformFlow::Impl\n") + UniformFlowMarker, false);
}

//------------------------------------------------------------------------------
int ReceiverShader::Inject(std::string& fragmentShader, const std::vector<ShadowLight>& lights,
  int layers, const ReceiverCode& code, bool receives, bool facetDerivatives, bool ownShare,
  const ShaderGroup& group)
{
  // The receiver's position is taken in the fragment shader, not the vertex
  // shader, because impostor mappers compute their true surface per fragment.
  std::ostringstream declared;
  std::ostringstream impl;
  int unpatched = 0;
  for (int k = 0; receives && k < static_cast<int>(lights.size()); ++k)
  {
    const std::string factor = group.Rename("vtkShadowFactor" + std::to_string(k));
    if (InjectShadowFactor(fragmentShader, lights[k].ShaderIndex, factor) > 0)
    {
      declared << (code.Transmittance ? "  vec3" : "  float") << " vtkShadowFactor" << k
               << (code.Transmittance ? " = vec3(1.0);\n" : " = 1.0;\n");
      impl << "    vtkShadowFactor" << k << " = vtkShadowFactor("
           << ReceiverCallArguments(lights[k], k) << ");\n";
    }
    else if (UsesWord(fragmentShader, "lightColor" + std::to_string(lights[k].ShaderIndex)))
    {
      ++unpatched; // the mapper lights with it, in code this module does not know
    }
  }
  if (impl.tellp() <= 0)
  {
    return unpatched;
  }
  if (!code.AnalysisStatement.empty())
  {
    // After everything that sets the colour: main() is the last function.
    const size_t end = fragmentShader.rfind('}');
    if (end != std::string::npos)
    {
      fragmentShader.insert(end,
        group.Rename("  if (vtkShadowReceiving != 0)\n  {\n  " + code.AnalysisStatement + "  }\n"));
    }
  }
  PutBeforeMarker(
    fragmentShader, "//VTK::ShadowMaps::Dec", group.Rename(Declarations(lights, layers, code)));
  PutBeforeMarker(fragmentShader, UniformFlowMarker,
    facetDerivatives ? group.Rename("#ifdef VTK_SHADOW_POSITION_DERIVATIVES\n"
                                    "  vtkShadowPositionDx = dFdx(vertexVC.xyz);\n"
                                    "  vtkShadowPositionDy = dFdy(vertexVC.xyz);\n"
                                    "#endif\n")
                     : std::string());
  const std::string position = ImpostorShader::ReceiverPositionVC(fragmentShader);
  // Another renderer that draws the prop without the pass draws it with this
  // program too (PropJoining), unshadowed: vtkShadowReceiving 0.
  PutBeforeMarker(fragmentShader, "//VTK::ShadowMaps::Impl",
    group.Rename("  vec3 vtkShadowNormalVC = normalize(normalVCVSOutput);\n"
                 "  vec3 vtkShadowPositionVC = " + position + ";\n" + declared.str() +
      "  if (vtkShadowReceiving != 0)\n  {\n"
      "#ifdef VTK_SHADOW_RECEIVER_PLANE\n"
      "    vtkShadowSetReceiverPlane(vtkShadowNormalVC);\n"
      "#endif\n" +
      (ownShare ? OwnTransmittance(fragmentShader, code) : std::string()) + impl.str() + "  }\n"));
  return unpatched;
}

//------------------------------------------------------------------------------
void ReceiverShader::DeclareShared(std::string& fragmentShader)
{
  PutBeforeMarker(
    fragmentShader, "//VTK::ShadowMaps::Dec", ImpostorShader::ReceiverDeclarations(fragmentShader));
}

//------------------------------------------------------------------------------
void ReceiverShader::ClearMarkers(std::string& fragmentShader)
{
  ClearSurfaceMarkers(fragmentShader);
  ClearVolumeMarkers(fragmentShader);
}

//------------------------------------------------------------------------------
void ReceiverShader::MarkVolumeInjectionPoints(std::string& fragmentShader)
{
  if (fragmentShader.find("//VTK::CustomUniforms::Dec") == std::string::npos ||
    fragmentShader.find("//VTK::Shading::Init") == std::string::npos)
  {
    return;
  }
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::CustomUniforms::Dec",
    std::string(VolumeDecMarker) + "\n//VTK::CustomUniforms::Dec", false);
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Shading::Init",
    std::string("//VTK::Shading::Init\n") + VolumeRayMarker, false);
}

//------------------------------------------------------------------------------
bool ReceiverShader::InjectVolume(std::string& fragmentShader,
  const std::vector<ShadowLight>& lights, int layers, const ReceiverCode& code, bool receives,
  const ShaderGroup& group, std::string& factors)
{
  const bool marked = fragmentShader.find(VolumeDecMarker) != std::string::npos &&
    fragmentShader.find(VolumeRayMarker) != std::string::npos;
  if (!receives || !marked || lights.empty())
  {
    return false;
  }
  const std::string factor = group.Rename(VolumeFactorCall);
  if (factors.empty())
  {
    for (const auto& pattern : VolumeSamplePatterns)
    {
      if (fragmentShader.find(pattern.first) != std::string::npos)
      {
        vtkShaderProgram::Substitute(
          fragmentShader, pattern.first, group.Rename(pattern.second), true);
        factors = factor;
      }
    }
  }
  else
  {
    // Each group's factor is one less its lights' shadowed shares: the sum of
    // the groups' factors, less one for each but the first, is the lights'.
    vtkShaderProgram::Substitute(
      fragmentShader, factors, "(" + factors + " + " + factor + " - 1.0)", true);
  }
  if (factors.empty())
  {
    return false;
  }
  ReceiverCode volumeCode = code;
  volumeCode.AnalysisFunctions.clear();
  PutBeforeMarker(fragmentShader, VolumeDecMarker,
    group.Rename(Declarations(lights, layers, volumeCode) + VolumeFactorFunction(lights)));
  // The sample's texture coordinates to the camera's view coordinates, once a ray.
  PutBeforeMarker(fragmentShader, VolumeRayMarker,
    group.Rename(
      "  vtkShadowVolumeTextureToVC = inverse(vtkShadowViewToWorld) * in_volumeMatrix[0] *\n"
      "    inverse(ip_inverseTextureDataAdjusted);\n"
      "  vtkShadowVolumeSamples = 0;\n"));
  return true;
}

//------------------------------------------------------------------------------
ProbeShaders MakeProbeShaders(const std::vector<ShadowLight>& lights)
{
  ProbeShaders probe;
  probe.Vertex = R"(//VTK::System::Dec
in vec4 vertexMC;
out vec4 vertexVCVSOutput;
out vec3 normalVCVSOutput;
void main()
{
  vertexVCVSOutput = vertexMC;
  normalVCVSOutput = vec3(0.0, 0.0, 1.0);
  gl_Position = vertexMC;
}
)";;
  std::string declarations = "uniform int cameraParallel;\n";
  std::string lighting;
  for (const ShadowLight& light : lights)
  {
    const std::string color = "lightColor" + std::to_string(light.ShaderIndex);
    declarations += "uniform vec3 " + color + ";\n";
    lighting += "  diffuse += (df * " + color + ");\n";
  }
  probe.Fragment = "//VTK::System::Dec\n//VTK::Output::Dec\nin vec4 vertexVCVSOutput;\n"
                   "in vec3 normalVCVSOutput;\n" +
    declarations +
    "//VTK::Light::Dec\nvoid main()\n{\n  vec4 vertexVC = vertexVCVSOutput;\n"
    "  //VTK::UniformFlow::Impl\n"
    "  vec3 diffuse = vec3(0.0);\n  float df = float(cameraParallel);\n"
    "  //VTK::Light::Impl\n" +
    lighting + "  gl_FragData[0] = vec4(diffuse, 1.0);\n}\n";
  return probe;
}

//------------------------------------------------------------------------------
void ReceiverCode::Rehash()
{
  this->Hash =
    std::hash<std::string>{}(this->Definitions + '\n' + this->Lookup + '\n' +
      this->AnalysisFunctions + '\n' + this->AnalysisStatement);
}

//------------------------------------------------------------------------------
std::string ReceiverShader::Key(
  const std::vector<ShadowLight>& lights, int layers, const ReceiverCode& code)
{
  std::ostringstream key;
  key << layers << ' ' << code.Hash << ';';
  for (const ShadowLight& light : lights)
  {
    key << light.ShaderIndex << ':' << light.FirstLayer << ':' << static_cast<int>(light.Layout)
        << ':' << light.Views.size() << ':' << ReceiverFeatures(light) << ' ';
  }
  return key.str();
}

//------------------------------------------------------------------------------
ReceiverUniforms::View ReceiverUniforms::PackView(
  const ShadowLight& light, std::size_t index, const glm::dmat4& viewToWorld)
{
  const LightView& view = light.Views[index];
  View packed;
  packed.ViewToMap = glm::mat4(ClipToTexture() * view.ViewProjection() * viewToWorld);
  // A negative constant tells the receiver to use the map's local gradient.
  packed.TexelSize = glm::vec2(
    view.TexelSizeFromGradient ? -1.0f : static_cast<float>(view.TexelConstant),
    static_cast<float>(view.TexelPerUnitDistance));
  packed.DepthInverseW = ToFloat(TextureToInverseW(view));
  if (light.Layout == ViewLayout::Cascades && index < light.CascadeDepths.size())
  {
    packed.Selection = ToFloat(light.CascadeDepths[index]);
  }
  if (light.Layout == ViewLayout::PerspectiveCube && index < light.FaceSelection.size())
  {
    packed.Selection = glm::vec3(static_cast<float>(light.FaceSelection[index]), 0.0f, 0.0f);
  }
  packed.FilterScale = static_cast<float>(FilterScale(light, index));
  if ((ReceiverFeatures(light) & CroppedViews) != 0)
  {
    const MapCrop crop = CropBetween(ClipToTexture() * light.Views.front().ViewProjection(),
      ClipToTexture() * view.ViewProjection());
    if (IsFiniteVector(crop.Scale) && IsFiniteVector(crop.Offset))
    {
      packed.CropScale = ToFloat(crop.Scale);
      packed.CropOffset = ToFloat(crop.Offset);
    }
  }
  return packed;
}

//------------------------------------------------------------------------------
ReceiverUniforms::Light ReceiverUniforms::PackLight(
  const ShadowLight& light, const glm::dmat4& cameraView)
{
  Light packed;
  packed.PositionVC = ToFloat(glm::dvec3(cameraView * glm::dvec4(light.Position, 1.0)));
  packed.Attenuation = light.Attenuation;
  packed.Fade = glm::vec2(light.Fade);
  packed.CoverageBand = static_cast<float>(light.CoverageBlendFraction);
  packed.TileGrid = glm::vec4(static_cast<float>(light.Tiles.Columns),
    static_cast<float>(light.Tiles.Rows), static_cast<float>(light.Tiles.WindowFraction.x),
    static_cast<float>(light.Tiles.WindowFraction.y));
  const LightDepth depthVC = TransformLightDepth(light.Depth, cameraView);
  packed.DepthPlane = glm::vec4(depthVC.Plane);
  packed.DepthOrigin = glm::vec3(depthVC.Origin);
  packed.DepthPerDistance = static_cast<float>(depthVC.PerDistance);
  const bool sun = light.Kind == LightKind::Directional;
  packed.TowardLightVC = glm::vec4(cameraView * TowardLight(light));
  if (sun)
  {
    packed.TowardLightVC = glm::vec4(glm::normalize(glm::vec3(packed.TowardLightVC)), 0.0f);
  }
  packed.Sized = light.Size > 0.0; // the SizedLight feature's condition
  packed.Size = static_cast<float>(sun ? std::tan(glm::radians(0.5 * light.Size)) : light.Size);
  return packed;
}

//------------------------------------------------------------------------------
void ReceiverUniforms::Pack(const std::vector<ShadowLight>& lights, const glm::dmat4& cameraView)
{
  const glm::dmat4 viewToWorld = glm::inverse(cameraView);
  this->Views.clear();
  this->Lights.clear();
  for (const ShadowLight& light : lights)
  {
    for (std::size_t v = 0; v < light.Views.size(); ++v)
    {
      this->Views.push_back(PackView(light, v, viewToWorld));
    }
    this->Lights.push_back(PackLight(light, cameraView));
  }
  this->ViewToWorld = glm::mat4(viewToWorld);
  this->NameMembers();
  this->Programs.Clear();
}

//------------------------------------------------------------------------------
void ReceiverUniforms::NameMembers()
{
  const auto name = [this](const char* array, std::size_t i,
                      std::initializer_list<const char*> members) {
    std::vector<std::string> names;
    for (const char* member : members)
    {
      names.push_back(array + this->Suffix + "[" + std::to_string(i) + "]." + member);
    }
    return names;
  };
  for (std::size_t i = this->ViewNames.size(); i < this->Views.size(); ++i)
  {
    this->ViewNames.push_back(name(
      "vtkShadowViews", i, { "ViewToMap", "TexelSize", "DepthInverseW", "Selection", "FilterScale",
                              "CropScale", "CropOffset" }));
  }
  for (std::size_t i = this->LightNames.size(); i < this->Lights.size(); ++i)
  {
    this->LightNames.push_back(name(
      "vtkShadowLights", i, { "PositionVC", "Attenuation", "Fade", "CoverageBand", "TileGrid",
                              "DepthPlane", "DepthOrigin", "DepthPerDistance", "TowardLightVC",
                              "Size" }));
  }
}

//------------------------------------------------------------------------------
bool ReceiverUniforms::IsReceiver(vtkShaderProgram* program, const std::string& suffix)
{
  return program->IsUniformUsed(("vtkShadowViews" + suffix + "[0].ViewToMap").c_str());
}

//------------------------------------------------------------------------------
void ReceiverUniforms::ApplyTextureUnits(
  vtkShaderProgram* program, const ReceiverTextureUnits& units, const std::string& suffix)
{
  if (units.Maps >= 0)
  {
    program->SetUniformi(("vtkShadowMaps" + suffix).c_str(), units.Maps);
  }
  if (units.RawDepths >= 0)
  {
    program->SetUniformi(("vtkShadowDepths" + suffix).c_str(), units.RawDepths);
  }
  if (units.Transmittances >= 0)
  {
    program->SetUniformi(("vtkShadowTransmittances" + suffix).c_str(), units.Transmittances);
  }
}

//------------------------------------------------------------------------------
void ReceiverUniforms::Apply(vtkShaderProgram* program, const ReceiverTextureUnits& units,
  int resolution, double normalOffset, const std::string& suffix)
{
  if (suffix != this->Suffix)
  {
    // The maps' group took another place among the pass's groups.
    this->Suffix = suffix;
    this->ViewNames.clear();
    this->LightNames.clear();
    this->NameMembers();
  }
  for (std::size_t i = 0; i < this->Views.size(); ++i)
  {
    View& view = this->Views[i];
    const std::vector<std::string>& names = this->ViewNames[i];
    program->SetUniformMatrix4x4(names[0].c_str(), glm::value_ptr(view.ViewToMap));
    program->SetUniform2f(names[1].c_str(), glm::value_ptr(view.TexelSize));
    program->SetUniform3f(names[2].c_str(), glm::value_ptr(view.DepthInverseW));
    program->SetUniform3f(names[3].c_str(), glm::value_ptr(view.Selection));
    program->SetUniformf(names[4].c_str(), view.FilterScale);
    program->SetUniform3f(names[5].c_str(), glm::value_ptr(view.CropScale));
    program->SetUniform3f(names[6].c_str(), glm::value_ptr(view.CropOffset));
  }
  for (std::size_t i = 0; i < this->Lights.size(); ++i)
  {
    const Light& light = this->Lights[i];
    const std::vector<std::string>& names = this->LightNames[i];
    program->SetUniform3f(names[0].c_str(), glm::value_ptr(light.PositionVC));
    program->SetUniformf(names[1].c_str(), light.Attenuation);
    program->SetUniform2f(names[2].c_str(), glm::value_ptr(light.Fade));
    program->SetUniformf(names[3].c_str(), light.CoverageBand);
    program->SetUniform4f(names[4].c_str(), glm::value_ptr(light.TileGrid));
    program->SetUniform4f(names[5].c_str(), glm::value_ptr(light.DepthPlane));
    program->SetUniform3f(names[6].c_str(), glm::value_ptr(light.DepthOrigin));
    program->SetUniformf(names[7].c_str(), light.DepthPerDistance);
    if (light.Sized)
    {
      program->SetUniform4f(names[8].c_str(), glm::value_ptr(light.TowardLightVC));
      program->SetUniformf(names[9].c_str(), light.Size);
    }
  }
  ApplyTextureUnits(program, units, suffix);
  program->SetUniformi(("vtkShadowReceiving" + suffix).c_str(), 1);
  program->SetUniformMatrix4x4(
    ("vtkShadowViewToWorld" + suffix).c_str(), glm::value_ptr(this->ViewToWorld));
  program->SetUniformf(("vtkShadowMapResolution" + suffix).c_str(), static_cast<float>(resolution));
  program->SetUniformf(("vtkShadowNormalOffset" + suffix).c_str(), static_cast<float>(normalOffset));
}
} // namespace shadowmaps
