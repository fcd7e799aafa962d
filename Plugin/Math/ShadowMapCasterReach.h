// Which casters can shadow what the camera sees, per light view. A light ray is
// a line of constant x and y in a view's clip space (that is what makes it a
// shadow map), so a caster can only shadow the visible receivers if its
// footprint there meets the footprint of the focus body B (camera frustum ∩
// scene bounds) and some of it lies nearer the light than B's farthest point.
// The view's own frustum keeps casters of its rectangle; B's footprint is a
// convex polygon inside it, whose corners (a cascade's slice, a frustum seen
// at an angle) hold casters whose shadows fall outside the view.
#ifndef ShadowMapCasterReach_h
#define ShadowMapCasterReach_h

#include "ShadowMapFocusing.h" // For Aabb

#include <glm/glm.hpp>

#include <vector>

namespace shadowmaps
{
/// Where in a view's clip space shadows can be seen.
struct ShadowReach
{
  /// Every caster may matter (part of B lies behind the light, or B is empty).
  bool Everywhere = true;
  /// B's footprint: a convex polygon in clip x, y, counter-clockwise.
  std::vector<glm::dvec2> Footprint;
  /// B's farthest clip depth.
  double FarthestDepth = 0.0;
  /// How far beyond the footprint, in clip x and y, receivers still sample the
  /// map (filter taps, normal offset).
  double Margin = 0.0;
};

/// The reach of the focus body `body` (its vertices) in the view
/// `viewProjection`, widened by `margin` in clip x and y.
ShadowReach ReachOfBody(
  const glm::dmat4& viewProjection, const std::vector<glm::dvec3>& body, double margin);

/// False only if a caster within `bounds` can shadow nothing in `reach`.
bool MayShadowInto(const ShadowReach& reach, const glm::dmat4& viewProjection, const Aabb& bounds);

/// Convex hull of points in the plane, counter-clockwise, without repeated or
/// collinear points (Andrew's monotone chain).
std::vector<glm::dvec2> ConvexHull(std::vector<glm::dvec2> points);
} // namespace shadowmaps

#endif
