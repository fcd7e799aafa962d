// Perspective shadow maps (Stamminger & Drettakis 2002) for directional
// and spot lights, with Kozlov's fixes (GPU Gems ch. 14, literature/001): the inverse
// light projection for lights behind the viewer, the virtual near-plane
// slide-back and unit-cube clipping (focus on B in post-perspective space).
// Plain C++ and GLM, pure functions.
#ifndef ShadowMapPerspective_h
#define ShadowMapPerspective_h

#include "ShadowMapFocusing.h"

#include <vector>

#include <glm/glm.hpp>

namespace shadowmaps
{

/// How the directional light looks in the camera's post-perspective space.
enum class PsmLightKind
{
  Uniform,     ///< parallel-projection camera: no warp, FitDirectional
  Directional, ///< light perpendicular to the view: stays directional (ortho light camera)
  Point,       ///< light in front of the viewer: point light beyond the far plane
  Inverse      ///< light behind the viewer: Kozlov's inverse projection (near -a, far +a)
};

struct PerspectiveMap
{
  /// View = light-camera view * fitting scale * camera post-perspective
  /// transform; ViewProjection() maps world points of B into [-1, 1]^2 with w > 0.
  LightView Light;
  PsmLightKind Kind = PsmLightKind::Uniform;
  /// Camera post-perspective transform (with slide-back) the map was built in.
  glm::dmat4 PostPerspective{ 1.0 };
  /// Light position in post-perspective space (Point / Inverse), or the
  /// direction light travels (Directional).
  glm::dvec3 LightPosition{ 0.0 };
  /// Kozlov's a for the inverse projection (0 otherwise).
  double InverseNear = 0.0;
};

/// Virtual slide-back (Kozlov Fig. 14-6): the camera moved back by slideBack
/// along its axis with near' = near + slideBack, so that the near-plane quads of
/// the real and virtual cameras lie on the same plane. Returns the virtual
/// camera's projection * view. cameraProjection must be a perspective frustum
/// (OpenGL convention); slideBack <= 0 returns projection * view.
glm::dmat4 SlideBackPostPerspective(
  const glm::dmat4& cameraView, const glm::dmat4& cameraProjection, double slideBack);

/// Kozlov's inverse light projection in light-view space (looking down -z,
/// Z = -z_view): the usual projection with near = -a, far = +a. NDC x, y from
/// the tangent window [lo, hi]; NDC z = a / Z, i.e. depth in [0, 1]
/// Z_psm = 1/2 (1 + a/Z) (thesis literature/000; Kozlov §14.1.2).
glm::dmat4 InverseProjection(const glm::dvec2& lo, const glm::dvec2& hi, double a);

/// The PSM for a directional light travelling along lightDirection.
/// B = camera frustum ∩ scene is focused in post-perspective space (unit-cube
/// clipping). The light camera looks from the light's post-perspective position
/// along the axis of the narrowest cone around B, turned toward -z (image plane
/// parallel to the screen) where that cone is narrow; its image is turned so
/// that the uniform map's (FitDirectional's) axes, carried into post-perspective
/// space on the camera's axis, keep their directions in the map. Nothing in the
/// fit switches between discrete choices, so the map moves continuously as the
/// light turns, including where the light passes from in front of the viewer to
/// behind. The slide-back is raised where needed to keep B within 60 degrees of
/// the light's axis (near B's silhouette the map would swing fastest).
/// warpWeight in [0, 1] (PerspectiveWarpWeight) scales the warp's pull: the
/// virtual camera slides back to (z + slideBack) / warpWeight - z, z = B's mid
/// depth, and the fit's space is rescaled toward view space, so that as the
/// weight goes to 0 the map converges to FitDirectional's, which it returns at 0.
/// Parallel-projection cameras, and fits with no light camera that holds B in
/// front, return the uniform map too (Kind Uniform).
PerspectiveMap FitPerspective(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& scene, const glm::dvec3& lightDirection, int resolution, double slideBack = 0.0,
  double warpWeight = 1.0);

/// The PSM of a spot light at `position` (Stamminger and Drettakis treat point
/// lights the same way): the light is the point (position, 1), a point light in
/// front of the viewer or an inverse one behind it in post-perspective space.
/// B = camera frustum ∩ scene ∩ the spot's frustum (FitSpot's cone map). As for
/// FitPerspective, with the cone map cropped to B (FitSpotToBody) in the uniform
/// map's place: its axes orient the light camera's image, its axis is where the
/// light camera's axis goes as the weight falls, and the PSM converges to it as
/// warpWeight goes to 0. That map is returned at weight 0, for
/// parallel-projection cameras, and when no light camera holds B in front; the
/// cone map when B is empty. The fit is made in fully rescaled post-perspective
/// space (a spot's 40 degree cone can open to nearly a half-space in NDC).
PerspectiveMap FitSpotPerspective(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& scene, const glm::dvec3& position, const glm::dvec3& direction,
  double coneAngleDegrees, int resolution, double slideBack = 0.0, double warpWeight = 1.0);

/// FitPerspective's warpWeight for a camera looking along viewDirection: 0 below 2
/// degrees between the view and light lines, 1 above 20, a smoothstep between
/// (WarpFade's shape over a wider band than the light-space warps': PSM's warp is
/// the strongest, and over 2 to 12 degrees its map moves by more than 5% of its
/// width per 0.1 degree of the light's turn).
double PerspectiveWarpWeight(const glm::dvec3& viewDirection, const glm::dvec3& lightDirection);

/// True when the homogeneous light point `light` (a light in post-perspective
/// space) is so far from a body of this radius, relative to its size, that the
/// light is treated as directional there.
bool StaysDirectional(const glm::dvec4& light, double radius);

/// The slide-back that puts every caster able to shadow the receivers `body`
/// in front of the virtual camera (SlideBackPostPerspective). Those casters lie
/// on the segments from B toward the light (the homogeneous point
/// `towardLight`), inside the scene; the GPU clips whatever has w <= 0 in
/// post-perspective space, so a caster behind the viewer (a light behind the
/// viewer, a building over a street-level camera's shoulder) would vanish from
/// the map and its shadow with it. Stamminger and Drettakis, and Kozlov (001,
/// the virtual slide-back), move the virtual camera back until such casters
/// are in front of it. 0 when they already are.
double SlideBackHoldingCasters(const glm::dmat4& cameraView, const std::vector<glm::dvec3>& body,
  const Aabb& scene, const glm::dvec4& towardLight);

/// Kozlov's world-space texel size L_texel at a world point: the edge of the
/// map's coarsest texel there, across the light's ray through the point
/// (TexelAcrossLight, central differences of `step`). `towardLight` is the
/// direction toward a sun (w = 0) or a light's position (w = 1).
double WorldTexelSize(const LightView& map, const glm::dvec3& world,
  const glm::dvec4& towardLight, double step, int resolution);

/// Kozlov's world-space bias: P_biased = P + L (a + b L_texel), L the unit
/// vector toward the light (minus the direction it travels). The biased point
/// is then transformed with the map's matrix as usual.
glm::dvec3 KozlovBiasedPoint(const glm::dvec3& world, const glm::dvec3& lightDirection, double a,
  double b, double texelSize);

} // namespace shadowmaps

#endif
