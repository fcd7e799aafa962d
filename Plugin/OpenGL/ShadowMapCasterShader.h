// The casters' side of a shadow-map pass: the branch put into every mapper
// shader the pass builds, which draws the prop into a shadow map when the
// uniform vtkShadowCasting is set (Shaders/vtkShadowMapsCasterFS.glsl says why
// casters and receivers share one program), and the uniforms of that branch.
//
// Most shaders get the branch at the top of main(): depth only, none of the
// mapper's colouring. Shaders that shape their own fragments (sphere and stick
// impostors write gl_FragDepth, point Gaussians discard) get it where the
// lighting would start, so their silhouettes stay right.
//
// With storage code (value maps) the branch writes what it says; with linear
// depth it makes the depth Z (linear light-space depth) instead of Z / W, W
// taken from the window position (SetView's windowToInverseW), and writes it as
// colour for ShadowMapLinearDepthResolve to copy into the depth map.
#ifndef ShadowMapCasterShader_h
#define ShadowMapCasterShader_h

#include "ShadowMapImpostors.h"     // For Impostors
#include "ShadowMapShaderGroup.h"   // For ShaderGroup
#include "ShadowMapTextureArray.h" // For SecondDepthMethod

#include <array>
#include <string>

#include <glm/glm.hpp>

class vtkShaderProgram;

namespace shadowmaps
{

/// What the casters' branch does; a change rebuilds the shaders.
struct CasterCode
{
  /// vtkAbstractShadowMapPass::CasterFacesType: 0 front, 1 back, 2 both.
  int Faces = 2;
  /// GLSL storing the texel's values (reads `float vtkShadowCasterDepth`,
  /// writes gl_FragData[0]); empty: depth only.
  std::string StoreCode;
  /// GLSL functions StoreCode calls.
  std::string StoreFunctions;
  /// vtkShadowCasterDepth is the light depth (MapStorage::LightDepth), from
  /// the window position through CasterUniforms::SetLightDepth's uniforms.
  bool LightDepth = false;
  /// With StoreCode: the light depth is also written to the second output
  /// (gl_FragData[1]), for the processes' maps to be combined by it
  /// (shadowmaps::StoreFromLightDepths).
  bool KeepsLightDepth = false;
  bool LinearDepth = false;
  /// Not None (nor Auto): the branch stores the two nearest surfaces' depths
  /// this way instead of StoreCode, and draws both faces. FrontAndBackFaces
  /// writes x for front faces, y for back faces, for minimum blending.
  /// Peeling writes its depth to both values and to the second output; with
  /// CasterUniforms::SetPeeling it discards what is not behind that output's
  /// first pass (the nearest surface), for the second pass to keep y.
  SecondDepthMethod SecondDepth = SecondDepthMethod::None;
  /// Some caster is translucent: every shader also gets the branch that
  /// draws it into the transmittance maps (vtkShadowCasting 2), after the
  /// mapper's colour code, and the depth branch takes vtkShadowCasting 1 only.
  bool Transmittance = false;

  std::string Key() const;
};

/// Where a shader's casters' branch went.
enum class CasterBranch
{
  DepthOnly,
  AfterOwnFragments
};

class CasterShader
{
public:
  /// Before the mapper's own replacements: the markers where the branch may go.
  /// Call before the receivers' markers (both precede //VTK::Light::Impl).
  static void MarkInjectionPoints(std::string& fragmentShader);

  /// Puts `group`'s branch before one of the markers (ClearMarkers removes
  /// them once every group's is in). `mapperShader`: the fragment shader
  /// before any group's code, whose own fragment shaping says where the
  /// branch goes. `sized`: the impostors ImpostorShader::Size sized, whose
  /// depth the branch computes.
  static CasterBranch Inject(std::string& fragmentShader, const std::string& mapperShader,
    const CasterCode& code, Impostors sized, const ShaderGroup& group);

  /// Before the groups' Inject: what every group's branch uses, once (the
  /// branches' selector vtkShadowCasting, the impostors' depth functions).
  static void DeclareShared(
    std::string& fragmentShader, const std::string& mapperShader, Impostors sized);

  /// Removes the markers, after the last group's Inject.
  static void ClearMarkers(std::string& fragmentShader);

  /// The GLSL expression (a vec3) of what the drawn surface lets through
  /// (vtkAbstractShadowMapPass::GetTransmittance's model), valid after the
  /// mapper's colour code of `mapperCode`; empty where that code has no
  /// colour and opacity. Needs the declarations of CasterCode::Transmittance.
  static std::string TransmittedLight(const std::string& mapperCode);

  /// Whether the camera is parallel is part of the state VTK's mappers rebuild
  /// their shaders on, so the light camera keeps the scene camera's flag; a
  /// shader stage that reads the uniform cameraParallel (impostors cast their
  /// rays by it) reads the light view's own while casting instead.
  static void RouteCameraParallel(std::string& shader);

};

/// The uniforms of the casters' branch for the view being rendered.
class CasterUniforms
{
public:
  /// `windowToInverseW`: the row r with 1 / W = dot(r, (gl_FragCoord.xy, 1));
  /// `linearDepthBias`: slope-scaled factor, constant, cap of the slope-scaled
  /// term (depth units) for linear-depth views; (0, 0, 1) and zeros otherwise;
  /// `parallel`: whether the view's projection is parallel.
  void SetView(const std::array<float, 3>& windowToInverseW,
    const std::array<float, 3>& linearDepthBias, bool parallel);

  /// The light depth (CasterCode::LightDepth) of the view being rendered:
  /// window coordinates (pixels, window depth) to world positions relative to
  /// the light's LightDepth::Origin, and its Plane and PerDistance.
  void SetLightDepth(const glm::mat4& windowToLight, const glm::vec4& plane, float perDistance);

  /// Peeling (CasterCode::SecondDepth): whether this is the second pass, and
  /// the texture unit of the first pass's depths (kept by every program, in
  /// both paths: samplers of two types must not share a unit).
  void SetPeeling(bool secondPass, int peelUnit);

  /// Impostors' sizes (ImpostorShader::Size) in the view being rendered.
  ImpostorUniforms& Impostors() { return this->ImpostorSizes; }

  /// Whether the next draws go into the transmittance maps (translucent
  /// casters) instead of the maps.
  void SetTransmitting(bool transmitting) { this->Transmitting = transmitting; }

  /// The group whose branch and uniforms these are (ShaderGroup).
  void SetGroup(int index);

  /// Selects the branch and sets the view's uniforms.
  void ApplyCasting(vtkShaderProgram* program) const;

  /// Selects the scene's path.
  void ApplyReceiving(vtkShaderProgram* program) const;

  /// Points the group's peeling sampler at its unit (SetPeeling).
  void ApplyPeelUnit(vtkShaderProgram* program) const;

private:
  bool SecondPass = false;
  bool Transmitting = false;
  int PeelUnit = 0;
  std::array<float, 3> WindowToInverseW{ { 0.0f, 0.0f, 1.0f } };
  std::array<float, 3> LinearDepthBias{ { 0.0f, 0.0f, 0.0f } };
  glm::mat4 WindowToLight{ 1.0f };
  glm::vec4 LightDepthPlane{ 0.0f };
  float LightDepthPerDistance = 0.0f;
  bool Parallel = false;
  ImpostorUniforms ImpostorSizes;
  ShaderGroup Group;
  /// The group's names of the uniforms set by name, made once.
  struct Names
  {
    std::string PeelDepths, PeelSecondPass, WindowToLight, LightDepthPlane,
      LightDepthPerDistance, WindowToInverseW, LinearDepthBias;
  };
  static Names NamesOf(const ShaderGroup& group);
  Names GroupNames = NamesOf(ShaderGroup());
};
} // namespace shadowmaps

#endif
