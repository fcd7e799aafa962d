// Which casters can shadow what a map shades. Receivers look a map up at their
// own position's clip x, y (moved by their normal offset, widened by the
// filter's taps), and a caster darkens a lookup only where it was drawn: so a
// caster whose footprint in the view's clip space misses the footprint of the
// receivers the map shades cannot shadow them. Those receivers lie in the focus
// body B (camera frustum ∩ scene bounds, or a cascade's slice of it), grown in
// the world by how far receivers sample beyond where they are. The view's own
// frustum keeps casters of its rectangle; B's footprint is a convex polygon
// inside it whose corners (a stable cascade's square around its slice, a
// frustum seen at an angle) hold casters whose shadows fall outside the view.
// Depth is not tested: two-surface maps keep what lies beyond a receiver too.
#ifndef ShadowMapCasterReach_h
#define ShadowMapCasterReach_h

#include "ShadowMapFocusing.h" // For Aabb

#include <glm/glm.hpp>

#include <vector>

namespace shadowmaps
{
/// Where in a view's clip space receivers sample it.
struct ShadowReach
{
  /// Every caster may matter: part of B lies behind the light or projects to
  /// no usable polygon, or B is empty.
  bool Everywhere = true;
  /// B's footprint: a convex polygon in clip x, y, counter-clockwise.
  std::vector<glm::dvec2> Footprint;
};

/// The reach of the focus body `body` (its vertices), each vertex grown by
/// `margin` world units along every axis, in the view `viewProjection`.
ShadowReach ReachOfBody(
  const glm::dmat4& viewProjection, const std::vector<glm::dvec3>& body, double margin);

/// False only if a caster within `bounds` can shadow nothing in `reach`.
bool MayShadowInto(const ShadowReach& reach, const glm::dmat4& viewProjection, const Aabb& bounds);
} // namespace shadowmaps

#endif
