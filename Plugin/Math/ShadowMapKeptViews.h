// Keeping a light's last view while the camera moves. A warped view or a cascade
// follows the camera, so most moving frames would re-render its map; in interactive frames
// (vtkAbstractShadowMapPass::InteractiveUpdateRate) the views strategy may keep
// the view it last gave while that view still serves the frame as the fresh
// fit would, and when it must fit again it fits a slightly wider camera so
// that the new view lasts a few frames. Still frames always fit anew.
// Plain C++17 and GLM (double precision), no VTK state; every function is pure.
#ifndef ShadowMapKeptViews_h
#define ShadowMapKeptViews_h

#include "ShadowMapFocusing.h" // For Aabb, LightView

#include <glm/glm.hpp>

namespace shadowmaps
{
/// Where the light comes from and where it shines: texels are measured across
/// its rays, and only what it lights needs a map.
struct LightRays
{
  bool Positional = false;
  /// Positional lights.
  glm::dvec3 Position{ 0.0 };
  /// The direction the light travels (a spot's axis).
  glm::dvec3 Direction{ 0.0, 0.0, -1.0 };
  /// Spots: the cone's half angle; the square frustum around it bounds what
  /// the light shines on. 90 or more: no bound.
  double ConeAngleDegrees = 90.0;
};

/// True when `kept` serves the frame `cameraViewProjection` as `fresh` (the
/// frame's own fit) would:
/// - it holds every point of the visible, lit scene that `fresh` holds (the
///   vertices of the camera frustum ∩ `scene` ∩ a spot's cone frustum ∩
///   fresh's frustum) inside its map, about as far from its sides as fresh
///   holds them (up to the receivers' `reachTexels` and at least 3 texels,
///   less half a texel: receivers look a map up beyond where they are; checked
///   at the vertices), and before its far plane;
/// - its near plane keeps every caster that `fresh` keeps on the light rays
///   through those points (fresh's frustum ∩ `scene` ∩ a spot's cone frustum
///   ∩ the rays through their footprint in kept's map);
/// - its texels across the light are at most `maximumTexelRatio` times
///   fresh's at each of those points (for warped maps a bound at the body's
///   vertices, where the texels are largest and smallest, not a proof).
/// False when fresh holds nothing of the visible scene (there is nothing to
/// compare by) and for non-finite input.
bool KeptViewServes(const LightView& kept, const LightView& fresh,
  const glm::dmat4& cameraViewProjection, const Aabb& scene, const LightRays& rays, int resolution,
  double maximumTexelRatio, double reachTexels = 3.0);

/// A camera as its view and projection matrices.
struct Camera
{
  glm::dmat4 View{ 1.0 };
  glm::dmat4 Projection{ 1.0 };
};
/// A perspective camera widened so that what it sees holds what nearby cameras
/// see: the eye moved `backward` along the view axis and every side of the
/// frustum turned `degrees` outward, the near and far planes kept where they
/// were in the world. It holds the frusta of cameras turned by up to `degrees`
/// and moved sideways by up to `backward` times the tangent of its sides'
/// half angles (KeptViewServes decides exactly whether a view still serves).
/// The turn is capped at 30 degrees and no side turns past 86 degrees from the
/// axis. Parallel, stereo and sheared projections and a non-positive
/// `backward` or `degrees` come back unchanged.
Camera WidenedCamera(const Camera& camera, double backward, double degrees);
} // namespace shadowmaps

#endif
