#include "ShadowMapCasterReach.h"

#include "ShadowMapTrapezoid.h" // For ConvexHull2D

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowmaps
{
namespace
{
double Cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b)
{
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The map position of p, false where it is not in front of the view or not finite.
bool ProjectInFront(const glm::dmat4& m, const glm::dvec3& p, glm::dvec2& xy)
{
  const glm::dvec4 clip = m * glm::dvec4(p, 1.0);
  xy = glm::dvec2(clip) / clip.w;
  return clip.w > 0.0 && std::isfinite(xy.x) && std::isfinite(xy.y);
}

// Clip x, y of points through a projection; false if any lies behind it or so
// close to its plane that the division is not finite.
bool ProjectAll(const glm::dmat4& m, const glm::dvec3* points, size_t count, std::vector<glm::dvec2>& out)
{
  out.clear();
  for (size_t i = 0; i < count; ++i)
  {
    glm::dvec2 xy;
    if (!ProjectInFront(m, points[i], xy))
    {
      return false;
    }
    out.push_back(xy);
  }
  return true;
}

// Separating axis test of an axis-aligned rectangle against a convex polygon.
bool RectangleMeetsPolygon(
  const glm::dvec2& lo, const glm::dvec2& hi, const std::vector<glm::dvec2>& polygon)
{
  glm::dvec2 polygonLo(std::numeric_limits<double>::max());
  glm::dvec2 polygonHi(std::numeric_limits<double>::lowest());
  for (const auto& p : polygon)
  {
    polygonLo = glm::min(polygonLo, p);
    polygonHi = glm::max(polygonHi, p);
  }
  if (hi.x < polygonLo.x || lo.x > polygonHi.x || hi.y < polygonLo.y || lo.y > polygonHi.y)
  {
    return false;
  }
  const glm::dvec2 corners[4] = { lo, { hi.x, lo.y }, hi, { lo.x, hi.y } };
  for (size_t i = 0; i < polygon.size(); ++i)
  {
    const glm::dvec2& a = polygon[i];
    const glm::dvec2& b = polygon[(i + 1) % polygon.size()];
    // The polygon lies left of each of its edges: the rectangle is outside if
    // all of its corners lie right of one.
    const bool allRight = std::all_of(
      std::begin(corners), std::end(corners), [&](const glm::dvec2& c) { return Cross(a, b, c) < 0.0; });
    if (allRight)
    {
      return false;
    }
  }
  return true;
}
} // namespace

//------------------------------------------------------------------------------
ShadowReach ReachOfBody(
  const glm::dmat4& viewProjection, const std::vector<glm::dvec3>& body, double margin)
{
  ShadowReach reach;
  if (!std::isfinite(margin))
  {
    return reach;
  }
  // The grown body is convex too: its vertices are among these.
  std::vector<glm::dvec3> grown;
  for (const auto& p : body)
  {
    for (int corner = 0; corner < 8; ++corner)
    {
      grown.push_back(p +
        margin * glm::dvec3(corner & 1 ? 1.0 : -1.0, corner & 2 ? 1.0 : -1.0, corner & 4 ? 1.0 : -1.0));
    }
  }
  std::vector<glm::dvec2> footprint;
  if (grown.empty() || !ProjectAll(viewProjection, grown.data(), grown.size(), footprint))
  {
    return reach;
  }
  reach.Footprint = ConvexHull2D(footprint);
  // A degenerate footprint (B seen edge-on) bounds nothing reliably.
  reach.Everywhere = reach.Footprint.size() < 3;
  return reach;
}

//------------------------------------------------------------------------------
bool MayShadowInto(const ShadowReach& reach, const glm::dmat4& viewProjection, const Aabb& bounds)
{
  if (reach.Everywhere)
  {
    return true;
  }
  // Called for every caster and layer: no allocation.
  glm::dvec2 lo(std::numeric_limits<double>::max());
  glm::dvec2 hi(std::numeric_limits<double>::lowest());
  for (const glm::dvec3& corner : bounds.Corners())
  {
    glm::dvec2 xy;
    if (!ProjectInFront(viewProjection, corner, xy))
    {
      return true;
    }
    lo = glm::min(lo, xy);
    hi = glm::max(hi, xy);
  }
  return RectangleMeetsPolygon(lo, hi, reach.Footprint);
}
} // namespace shadowmaps
