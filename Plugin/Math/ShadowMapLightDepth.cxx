#include "ShadowMapLightDepth.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowmaps
{
namespace
{
// Depth a over [nearest, farthest] mapped to [0, 1], with a margin so that the
// scene's extreme points do not sit on the clamp, and a least range so that a
// flat scene seen along the light still divides by something finite.
glm::dvec2 Normalization(double nearest, double farthest, double scale)
{
  const double least = std::max(scale, 1e-30) * 1e-6;
  const double margin = std::max((farthest - nearest) * 1e-3, least);
  const double lower = nearest - margin;
  const double range = farthest + margin - lower;
  return { 1.0 / range, -lower / range };
}

double DistanceToBox(const glm::dvec3& p, const Aabb& box)
{
  const glm::dvec3 outside = glm::max(glm::max(box.Min - p, p - box.Max), glm::dvec3(0.0));
  return glm::length(outside);
}
} // namespace

LightDepth DirectionalLightDepth(const glm::dvec3& direction, const Aabb& scene)
{
  const glm::dvec3 d = SafeDirection(direction);
  double nearest = 0.0;
  double farthest = 0.0;
  if (!scene.IsEmpty())
  {
    nearest = std::numeric_limits<double>::max();
    farthest = -nearest;
    for (const glm::dvec3& corner : scene.Corners())
    {
      nearest = std::min(nearest, glm::dot(d, corner));
      farthest = std::max(farthest, glm::dot(d, corner));
    }
  }
  const double scale = scene.IsEmpty() ? 1.0 : scene.Diagonal();
  const glm::dvec3 origin = scene.IsEmpty() ? glm::dvec3(0.0) : scene.Center();
  const glm::dvec2 n = Normalization(nearest, farthest, scale);
  LightDepth depth;
  depth.Plane = glm::dvec4(d * n.x, n.y + n.x * glm::dot(d, origin));
  depth.Origin = origin;
  return depth;
}

LightDepth PositionalLightDepth(const glm::dvec3& position, const Aabb& scene)
{
  double nearest = 0.0;
  double farthest = 0.0;
  if (!scene.IsEmpty())
  {
    nearest = DistanceToBox(position, scene);
    for (const glm::dvec3& corner : scene.Corners())
    {
      farthest = std::max(farthest, glm::length(corner - position));
    }
  }
  const double scale = scene.IsEmpty() ? 1.0 : std::max(scene.Diagonal(), farthest);
  const glm::dvec2 n = Normalization(nearest, farthest, scale);
  LightDepth depth;
  depth.Plane = glm::dvec4(0.0, 0.0, 0.0, n.y);
  depth.PerDistance = n.x;
  depth.Origin = position;
  return depth;
}

double EvaluateLightDepth(const LightDepth& depth, const glm::dvec3& p)
{
  const glm::dvec3 relative = p - depth.Origin;
  return glm::dot(glm::dvec3(depth.Plane), relative) + depth.Plane.w +
    depth.PerDistance * glm::length(relative);
}

LightDepth TransformLightDepth(const LightDepth& depth, const glm::dmat4& rigid)
{
  // Relative positions rotate with the frame; lengths keep.
  LightDepth moved = depth;
  moved.Plane = glm::dvec4(glm::dmat3(rigid) * glm::dvec3(depth.Plane), depth.Plane.w);
  moved.Origin = glm::dvec3(rigid * glm::dvec4(depth.Origin, 1.0));
  return moved;
}
} // namespace shadowmaps
