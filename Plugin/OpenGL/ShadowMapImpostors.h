// VTK's impostors in the maps: points drawn as spheres and lines drawn as tubes
// are sized by their mappers in the scene camera's pixels, with a depth
// computed for that camera. While casting,
// the code put here sizes them as the scene camera shows them, in world units,
// and gives the casters' branch their depth towards the light; the receivers
// shade the round ones at their surface rather than at their centre.
//
// Points as spheres: Shaders/vtkShadowMapsSpriteVS.glsl and SpriteFS.glsl (the
// GL caps a point's size: 255 texels on llvmpipe). Tubes:
// vtkShadowMapsTubeGS.glsl and TubeFS.glsl. Flat wide lines keep their width in
// map texels (a screen-space decoration, drawn by the GL's own wide lines
// where it has them).
#ifndef ShadowMapImpostors_h
#define ShadowMapImpostors_h

#include <string>

#include <glm/glm.hpp>

class vtkShaderProgram;

namespace shadowmaps
{

/// What a mapper's shaders draw, as far as the maps are concerned.
enum class Impostors
{
  None,
  /// Points drawn as spheres.
  Spheres,
  /// Lines drawn as tubes.
  Tubes
};

class ImpostorShader
{
public:
  /// While casting, sizes the impostors the shaders draw to what the scene
  /// camera shows; returns what was sized (None: nothing to size, or a
  /// geometry shader template this does not know).
  static Impostors Size(
    std::string& vertexShader, std::string& geometryShader, const std::string& fragmentShader);

  /// The casters' branch's depth for `sized`, and the fragment shader code it
  /// calls; empty for impostors drawn at their own depth.
  static std::string CasterDepth(Impostors sized);
  static std::string CasterDeclarations(Impostors sized);
  /// Where the texel's ray leaves the impostor, once CasterDepth ran (dual
  /// depth maps' second surface); empty as CasterDepth is.
  static std::string CasterBackDepth(Impostors sized);

  /// Lets the fragments of the whole square a point drawn as a sphere covers
  /// through while casting (VTK's code keeps its inscribed circle only);
  /// nothing to do for tubes. False where VTK's cut was not found.
  static bool LiftOwnCutWhileCasting(std::string& fragmentShader, Impostors sized);

  /// The receivers' position (view coordinates) in a fragment shader: at the
  /// surface of spheres and tubes, else the interpolated vertexVC.
  static std::string ReceiverPositionVC(const std::string& fragmentShader);
  /// The uniforms ReceiverPositionVC uses (ImpostorUniforms::ApplyReceiving).
  static std::string ReceiverDeclarations(const std::string& fragmentShader);

  /// Whether a program takes ImpostorUniforms (its casters' draws also need
  /// GL_PROGRAM_POINT_SIZE).
  static bool IsSized(vtkShaderProgram* program);
};

/// The uniforms of Shaders/vtkShadowMapsImpostorSizes.glsl for a light view.
class ImpostorUniforms
{
public:
  /// The view's world to clip transform, the light (xyz towards it with w 0,
  /// or its position with w 1), the scene camera's eye depth row
  /// (dot(xyz, p) + w), and the light camera's P00 over the scene camera's,
  /// whether the scene camera is parallel, the map's size in texels and the
  /// largest point size the GL draws. The scene camera's P00 is the whole
  /// image's in a tile of a larger one: VTK sizes impostors by the whole
  /// image's width in pixels. The inverse is made in double.
  void Set(const glm::dmat4& worldToClip, const glm::vec4& light, const glm::vec4& sceneDepth,
    const glm::vec4& scale);

  /// The casters' depth offset in the view (slope-scaled factor, constant in
  /// depth units), which impostors writing their depth add themselves.
  void SetDepthOffset(const glm::vec2& offset) { this->DepthOffset = offset; }

  void Apply(vtkShaderProgram* program) const;

  /// The frame's drawn impostor radius over VTK's ZCalcR times the eye depth:
  /// the tile scale, 1 outside tiled captures.
  void SetDrawnRadius(float overZCalcR) { this->DrawnRadius = overZCalcR; }
  void ApplyReceiving(vtkShaderProgram* program) const;

private:
  glm::mat4 WorldToClip{ 1.0f };
  glm::mat4 ClipToWorld{ 1.0f };
  glm::vec4 Light{ 0.0f };
  glm::vec4 SceneDepth{ 0.0f };
  glm::vec4 Scale{ 0.0f };
  glm::vec2 DepthOffset{ 0.0f };
  float DrawnRadius = 1.0f;
};
} // namespace shadowmaps

#endif
