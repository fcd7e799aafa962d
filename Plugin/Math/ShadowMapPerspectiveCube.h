// Kozlov's cube map with a displaced centre (GPU Gems ch. 14, literature/001,
// "Using Cube Maps"): in the camera's post-perspective space nearly every light
// is a point light, and a cube map around it whose faces lie on the faces of
// the receivers' box that look away from it ("platforms") spreads its texels in
// proportion to screen area wherever the light is. Each face is a perspective
// map from the light's post-perspective position onto its platform, cropped to
// the receivers its platform holds (unit-cube clipping per face). A receiver is
// shaded by the face whose platform the ray from the light through it leaves
// the box by. Plain C++ and GLM, pure functions.
#ifndef ShadowMapPerspectiveCube_h
#define ShadowMapPerspectiveCube_h

#include "ShadowMapFocusing.h"

#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace shadowmaps
{
/// Faces of a post-perspective cube, in the order of FitCubeFaces' world
/// faces: +x, -x, +y, -y, +z, -z of post-perspective space.
constexpr int PerspectiveCubeFaces = 6;

/// The unit axis face `face` looks along.
glm::dvec3 PerspectiveCubeAxis(int face);

/// Distance along face `face`'s axis from `light` to the face's platform, the
/// side of `box` that face lies on: positive when the face looks away from the
/// light (the light is on the box's side of the platform's plane), which is
/// when the face is used.
double PlatformDistance(const Aabb& box, const glm::dvec3& light, int face);

/// The face that holds `point` (Kozlov's Example 14-1, the displaced-centre
/// lookup): the face whose platform the ray from `light` through the point
/// leaves `box` by, the largest (point - light) . axis / PlatformDistance over
/// the faces that look away from the light. -1 when no such face gives a
/// positive value (the point is the light itself).
int DisplacedCubeFace(const Aabb& box, const glm::dvec3& light, const glm::dvec3& point);

/// A light's post-perspective cube map.
struct PerspectiveCube
{
  /// World to map, one per face. Faces that look toward the light, or whose
  /// platform holds no receiver, are OutOfView.
  std::array<LightView, PerspectiveCubeFaces> Faces;
  /// Per face, 1 / PlatformDistance for a face that looks away from the light,
  /// 0 for one that does not. A face's clip w is the receiver's post-perspective
  /// w times its distance along the face's axis from the light, so clip w times
  /// this is largest for the face DisplacedCubeFace picks (the common w > 0
  /// cancels out): receivers pick their face from the faces' matrices.
  std::array<double, PerspectiveCubeFaces> Selection{};
  /// World to post-perspective space (the virtual camera's, with slide-back).
  glm::dmat4 PostPerspective{ 1.0 };
  /// The light in post-perspective space.
  glm::dvec3 LightPosition{ 0.0 };
  /// The receivers' box in post-perspective space: the platforms are its sides.
  Aabb Platforms;
  /// The light is behind the virtual camera: its faces use Kozlov's inverse
  /// projection (near -a, far +a), as its rays reach the receivers through
  /// infinity.
  bool Inverse = false;
  /// False when no cube can be built: a parallel projection (no warp), no
  /// receiver in view, a light that stays directional in post-perspective space
  /// (it lies in the camera's plane) or a non-finite fit. Faces are then unset.
  bool Valid = false;
};

/// Kozlov's cube map of the light at the homogeneous point `towardLight`
/// ((P, 1) for a point or spot light, (-d, 0) for a sun travelling along d)
/// for the receivers inside the world planes `receivers` (the camera's
/// frustum, the scene's box, and for a spot the half-space it lights; each
/// face's receivers are those planes and the face's pyramid). The virtual
/// camera slides back by slideBack, or further when casters of the receivers
/// would otherwise lie behind it (SlideBackHoldingCasters). Each face's window
/// gets a margin of marginTexels texels for filters that reach over its edge.
/// Faces are perspective maps (depth z / w; texel sizes from the map's
/// gradient). Their near plane lies at half their receivers' nearest distance,
/// as FitPerspective's (casters nearer the light are clamped onto it), but no
/// nearer a positional light than a hundredth of the scene's reach from it in
/// the world: receivers that near it are left unshadowed (a light among the
/// receivers, the apex of its faces, always has such).
PerspectiveCube FitPerspectiveCube(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const std::vector<Plane>& receivers, const Aabb& scene, const glm::dvec4& towardLight,
  int resolution, double slideBack, double marginTexels);

/// What KeptCubeServes compares kept cubes with: the frame's own cube and the
/// coarsest texel of each of its faces over the receivers it gives that face
/// (0 for a face given none). Made once per frame for every cube tried.
struct FreshCube
{
  PerspectiveCube Cube;
  std::array<double, PerspectiveCubeFaces> CoarsestTexels{};
  double Coarsest = 0.0;
};
FreshCube MeasureFreshCube(const PerspectiveCube& cube, const std::vector<Plane>& receivers,
  const Aabb& scene, const glm::dvec4& towardLight, int resolution);

/// Whether a cube fitted for an earlier camera, `kept` with its `selection`,
/// still serves the frame whose receivers lie inside the world planes
/// `receivers` as `fresh` (the frame's own cube) would: every receiver the
/// kept faces' selection gives to a face lies inside that face's map, at least
/// reachTexels from its sides (filters look beyond the receiver), before its
/// far plane, and not before its near plane where fresh's face has it beyond
/// its own, on a face that was rendered; no receiver lies where no kept face
/// looks (behind a light that was off the box's corner); and each kept face's
/// coarsest texel across the light over its receivers is at most
/// maximumTexelRatio times fresh's same face's over its own (or fresh's
/// coarsest, where fresh gives that face none). Checked at the vertices of
/// each face's receivers, as KeptViewServes. Kept faces keep their own
/// selection, so receivers and maps agree however the camera has moved since.
bool KeptCubeServes(const std::vector<LightView>& kept, const std::vector<double>& selection,
  const std::vector<Plane>& receivers, const FreshCube& fresh, const Aabb& scene,
  const glm::dvec4& towardLight, int resolution, double maximumTexelRatio, double reachTexels);

} // namespace shadowmaps

#endif
