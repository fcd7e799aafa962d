// The receivers' side of a shadow-map pass: the GLSL injected into the mappers'
// fragment shaders (ReceiverShader) and the uniforms it reads (ReceiverUniforms).
// The pass decides what to inject; these classes know how.
#ifndef ShadowMapReceiverShader_h
#define ShadowMapReceiverShader_h

#include "ShadowMapProgramStamps.h"

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

class vtkShaderProgram;

namespace shadowmaps
{
class ShaderGroup;
struct ShadowLight;

/// The C++ constants the receivers' GLSL shares, as #defines: the view layouts
/// (VTK_SHADOW_LAYOUT_*) and receiver features (VTK_SHADOW_FEATURE_*).
std::string ReceiverShaderConstants();

/// The arguments every per-light receiver function takes for light `index`
/// (vtkShadowFactor, vtkShadowAnalysisColor): position, normal, light index,
/// first layer, layout, view count and features, the last four as literals.
std::string ReceiverCallArguments(const ShadowLight& light, int index);

/// What the pass injects besides the shared receiver functions.
struct ReceiverCode
{
  /// Before the receiver functions: the representation's #defines.
  std::string Definitions;
  /// After them: the representation's lookup (defines vtkShadowLookup).
  std::string Lookup;
  /// After the lookup: the analysis view's functions (empty: none).
  std::string AnalysisFunctions;
  /// At the end of main(): the analysis view's statement (empty: none).
  std::string AnalysisStatement;
  /// Translucent casters tint the light: the shadow factors are colours
  /// (VTK_SHADOW_TRANSMITTANCE, which Definitions then holds).
  bool Transmittance = false;
  /// A hash of the four, for the shader key (Rehash after changing them).
  std::size_t Hash = 0;
  void Rehash();
};

class ReceiverShader
{
public:
  /// Before the mapper's own replacements: markers where the shadow code goes.
  static void MarkInjectionPoints(std::string& fragmentShader);

  /// Scales each of `group`'s lights' diffuse and specular (Phong) or
  /// radiance (PBR) terms by its shadow factor where the mapper generated
  /// them, and puts the group's shadow code before the markers (ClearMarkers
  /// removes them once every group's is in). `receives` false, or a shader
  /// without per-light code (unlit), injects nothing. `facetDerivatives`: the drawn position is
  /// the surface's until the lighting (not an impostor's), so its screen
  /// derivatives, taken where VTK keeps control flow uniform, give the facet
  /// (vtkShadowSetReceiverPlane); otherwise the shading normal stands in.
  /// Returns how many receiving lights the shader lights with (it names their
  /// lightColor) in code none of the patterns found: a VTK whose mapper
  /// changed its lighting code; those lights cast no shadow on the prop.
  /// `ownShare`: the maps hold what this prop lets through where it is
  /// translucent (HoldsItsOwnTransmittance), which its receivers divide out.
  static int Inject(std::string& fragmentShader, const std::vector<ShadowLight>& lights,
    int layers, const ReceiverCode& code, bool receives, bool facetDerivatives, bool ownShare,
    const ShaderGroup& group);

  /// Before the volume mapper's own replacements (its GPU ray caster's
  /// template): markers where InjectVolume puts its code.
  static void MarkVolumeInjectionPoints(std::string& fragmentShader);

  /// Darkens each sample the ray caster composites by the shadows of the
  /// opaque casters at the sample (taken at every fourth sample of a ray),
  /// light by light in proportion to each shadowed light's share of the
  /// lights' intensity (vtkShadowVolumeLightShares, set per draw): the
  /// sample's colour, lit or not, is what the volume shows of the light.
  /// `factors`: the call that darkens each sample, which the first group to
  /// inject makes and the next add their lights' shadowed shares to. Without
  /// `receives` or lights, or where the shader composites no sample (maximum
  /// intensity and other blend modes), injects nothing; returns whether it
  /// injected.
  static bool InjectVolume(std::string& fragmentShader, const std::vector<ShadowLight>& lights,
    int layers, const ReceiverCode& code, bool receives, const ShaderGroup& group,
    std::string& factors);

  /// What every group's receiver code uses once any group's is in (the
  /// impostors' drawn size), before the markers are cleared.
  static void DeclareShared(std::string& fragmentShader);

  /// Removes the surface's and the volume's markers, after the last group's code.
  static void ClearMarkers(std::string& fragmentShader);

  /// A key of everything Inject's result depends on but the shader it patches.
  static std::string Key(const std::vector<ShadowLight>& lights, int layers, const ReceiverCode& code);
};

/// A vertex and a fragment shader shaped like a lit mapper's, with the lines
/// the injections look for (markers, per-light colour sums) for `lights`: the
/// pass builds them with its injections and compiles them before any mapper
/// gets the code, since VTK 9.1's mapper crashes on a program that fails to build.
struct ProbeShaders
{
  std::string Vertex;
  std::string Fragment;
};
ProbeShaders MakeProbeShaders(const std::vector<ShadowLight>& lights);

/// The texture units the receivers' samplers read.
struct ReceiverTextureUnits
{
  /// The maps (vtkShadowMaps).
  int Maps = -1;
  /// The maps' depths without comparison (vtkShadowDepths), for the soft
  /// shadows of depth maps; -1 when nobody reads them.
  int RawDepths = -1;
  /// The transmittance maps (vtkShadowTransmittances); -1 without them.
  int Transmittances = -1;
};

/// The uniforms of the receiver functions for one map update: one struct per
/// view (vtkShadowViews) and per light (vtkShadowLights), named as the
/// group of the maps names them (ShaderGroup).
class ReceiverUniforms
{
public:
  /// Packs the lights' views for a camera with view matrix `cameraView`.
  void Pack(const std::vector<ShadowLight>& lights, const glm::dmat4& cameraView);

  /// Whether `program` is a receiver of the shadow code of the group whose
  /// names end with `suffix`.
  static bool IsReceiver(vtkShaderProgram* program, const std::string& suffix);

  /// Starts a frame: its texture units may differ from the last one's.
  void NewFrame() { this->Programs.Invalidate(); }

  /// True on a program's first use in this frame since the last Pack.
  bool FirstUseThisFrame(vtkShaderProgram* program) { return this->Programs.FirstUse(program); }

  /// Sets the packed uniforms, the maps' texture units and resolution and the
  /// receivers' normal offset (texels), named as the group whose names end
  /// with `suffix` (ShaderGroup) names them.
  void Apply(vtkShaderProgram* program, const ReceiverTextureUnits& units, int resolution,
    double normalOffset, const std::string& suffix);

  /// Points the samplers of the group whose names end with `suffix` at the
  /// units (each sampler type its own).
  static void ApplyTextureUnits(
    vtkShaderProgram* program, const ReceiverTextureUnits& units, const std::string& suffix);

private:
  struct View
  {
    glm::mat4 ViewToMap{ 1.0f };
    glm::vec2 TexelSize{ 0.0f };
    glm::vec3 DepthInverseW{ 0.0f };
    glm::vec3 Selection{ 0.0f, 1e38f, 1e38f };
    float FilterScale = 1.0f;
    glm::vec3 CropScale{ 1.0f };
    glm::vec3 CropOffset{ 0.0f };
  };
  struct Light
  {
    glm::vec3 PositionVC{ 0.0f };
    float Attenuation = 1.0f;
    glm::vec2 Fade{ 0.0f };
    float CoverageBand = -1.0f;
    glm::vec4 TileGrid{ 0.0f };
    glm::vec4 DepthPlane{ 0.0f };
    glm::vec3 DepthOrigin{ 0.0f };
    float DepthPerDistance = 0.0f;
    glm::vec4 TowardLightVC{ 0.0f };
    float Size = 0.0f;
    bool Sized = false;
  };
  static View PackView(const ShadowLight& light, std::size_t index, const glm::dmat4& viewToWorld);
  static Light PackLight(const ShadowLight& light, const glm::dmat4& cameraView);
  void NameMembers();

  std::vector<View> Views;
  std::vector<Light> Lights;
  std::string Suffix;
  glm::mat4 ViewToWorld{ 1.0f };
  /// "vtkShadowViews[i]." and "vtkShadowLights[i]." member names, made once.
  std::vector<std::vector<std::string>> ViewNames;
  std::vector<std::vector<std::string>> LightNames;
  ProgramStamps Programs;
};
} // namespace shadowmaps

#endif
