// The light depth filterable maps store (Plugin/Math/ShadowMapLightDepth).
#include "FocusingTestHelpers.h"
#include "ShadowMapLightDepth.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace shadowmaps;
using focusingtest::MakeBox;

namespace
{

/// Least and greatest light depth over the box's corners.
glm::dvec2 RangeOverCorners(const LightDepth& depth, const Aabb& box)
{
  glm::dvec2 range(1e300, -1e300);
  for (const glm::dvec3& corner : box.Corners())
  {
    const double d = EvaluateLightDepth(depth, corner);
    range = glm::dvec2(std::min(range.x, d), std::max(range.y, d));
  }
  return range;
}
} // namespace

// Along a directional light: the scene spans [0, 1] but for a small margin,
// and depth grows along the light, by the same amount for the same step
// anywhere (linear in light space).
TEST(ShadowMapLightDepth, DirectionalSpansTheSceneLinearly)
{
  const Aabb scene = MakeBox({ -10, -5, 0 }, { 30, 5, 8 });
  const glm::dvec3 direction = glm::normalize(glm::dvec3(-0.4, 0.3, -1.0));
  const LightDepth depth = DirectionalLightDepth(direction, scene);
  const glm::dvec2 range = RangeOverCorners(depth, scene);
  EXPECT_GT(range.x, 0.0);
  EXPECT_LT(range.x, 0.01);
  EXPECT_LT(range.y, 1.0);
  EXPECT_GT(range.y, 0.99);
  const double step = EvaluateLightDepth(depth, glm::dvec3(1, 2, 3) + direction) -
    EvaluateLightDepth(depth, { 1, 2, 3 });
  const double stepElsewhere = EvaluateLightDepth(depth, glm::dvec3(20, -4, 7) + direction) -
    EvaluateLightDepth(depth, { 20, -4, 7 });
  EXPECT_GT(step, 0.0);
  EXPECT_NEAR(step, stepElsewhere, 1e-12);
  // Across the light, nothing changes.
  const glm::dvec3 across = glm::normalize(glm::cross(direction, glm::dvec3(0, 0, 1)));
  EXPECT_NEAR(EvaluateLightDepth(depth, glm::dvec3(1, 2, 3) + 5.0 * across),
    EvaluateLightDepth(depth, { 1, 2, 3 }), 1e-12);
}

// From a positional light: the distance, 0 near the light (inside the scene),
// the farthest corner just under 1.
TEST(ShadowMapLightDepth, PositionalIsTheDistance)
{
  const Aabb scene = MakeBox({ -10, -10, 0 }, { 10, 10, 10 });
  const glm::dvec3 light(1, 2, 6);
  const LightDepth depth = PositionalLightDepth(light, scene);
  EXPECT_NEAR(EvaluateLightDepth(depth, light), 0.0, 0.01);
  EXPECT_GT(RangeOverCorners(depth, scene).y, 0.99);
  EXPECT_LT(RangeOverCorners(depth, scene).y, 1.0);
  // Equal distances, equal depths.
  EXPECT_NEAR(EvaluateLightDepth(depth, light + glm::dvec3(3, 0, 0)),
    EvaluateLightDepth(depth, light + glm::dvec3(0, 0, -3)), 1e-12);
  // A light outside: its nearest point of the scene is near 0.
  const LightDepth outside = PositionalLightDepth({ 0, 0, 30 }, scene);
  EXPECT_NEAR(EvaluateLightDepth(outside, { 0, 0, 10 }), 0.0, 0.01);
}

// The same function in a camera's frame: a rigid transform moves points and
// the function alike.
TEST(ShadowMapLightDepth, TransformFollowsARigidFrame)
{
  const Aabb scene = MakeBox({ -3, -3, 0 }, { 3, 3, 2 });
  const glm::dmat4 view = glm::lookAt(glm::dvec3(4, -9, 5), glm::dvec3(0, 0, 0.5), glm::dvec3(0, 0, 1));
  for (const LightDepth& depth : { DirectionalLightDepth({ 0.2, 0.1, -1.0 }, scene),
         PositionalLightDepth({ 1, 1, 4 }, scene) })
  {
    const LightDepth moved = TransformLightDepth(depth, view);
    for (const glm::dvec3& p : { glm::dvec3(0, 0, 0), glm::dvec3(2, -1, 1.5), glm::dvec3(-3, 3, 0) })
    {
      EXPECT_NEAR(EvaluateLightDepth(moved, glm::dvec3(view * glm::dvec4(p, 1.0))),
        EvaluateLightDepth(depth, p), 1e-12);
    }
  }
}

// Degenerate scenes give finite functions: empty, a flat scene seen along the
// light (no depth range), a huge and a tiny one.
TEST(ShadowMapLightDepth, DegenerateScenesStayFinite)
{
  const auto finite = [](const LightDepth& d) {
    return std::isfinite(d.Plane.x) && std::isfinite(d.Plane.y) && std::isfinite(d.Plane.z) &&
      std::isfinite(d.Plane.w) && std::isfinite(d.PerDistance);
  };
  EXPECT_TRUE(finite(DirectionalLightDepth({ 0, 0, -1 }, Aabb())));
  EXPECT_TRUE(finite(PositionalLightDepth({ 0, 0, 1 }, Aabb())));
  const Aabb flat = MakeBox({ -1, -1, 0 }, { 1, 1, 0 });
  const LightDepth along = DirectionalLightDepth({ 0, 0, -1 }, flat);
  EXPECT_TRUE(finite(along));
  EXPECT_NEAR(EvaluateLightDepth(along, { 0, 0, 0 }), 0.5, 1e-9);
  EXPECT_TRUE(finite(DirectionalLightDepth({ 0, 0, -1 }, MakeBox({ -1e6, -1e6, -1e6 }, { 1e6, 1e6, 1e6 }))));
  EXPECT_TRUE(finite(PositionalLightDepth({ 0, 0, 0 }, MakeBox({ -1e-6, -1e-6, 0 }, { 1e-6, 1e-6, 1e-6 }))));
  // The light on a flat scene's only point.
  EXPECT_TRUE(finite(PositionalLightDepth({ 0, 0, 0 }, MakeBox({ 0, 0, 0 }, { 0, 0, 0 }))));
}
