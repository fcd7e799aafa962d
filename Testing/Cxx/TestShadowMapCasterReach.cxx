// Which casters can shadow what a view shades (Plugin/Math/ShadowMapCasterReach).
#include "FocusingTestHelpers.h"
#include "ShadowMapCasterReach.h"
#include "ShadowMapTrapezoid.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace shadowmaps;
using focusingtest::MakeBox;

namespace
{

std::vector<glm::dvec3> Corners(const Aabb& box)
{
  const auto corners = box.Corners();
  return std::vector<glm::dvec3>(corners.begin(), corners.end());
}
} // namespace

TEST(ShadowMapCasterReach, HullDropsInnerAndRepeatedPoints)
{
  const std::vector<glm::dvec2> hull =
    ConvexHull2D({ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0.5, 0.5 }, { 1, 1 }, { 0.5, 0 } });
  ASSERT_EQ(hull.size(), 4u);
  double area = 0.0;
  for (size_t i = 0; i < hull.size(); ++i)
  {
    const glm::dvec2& a = hull[i];
    const glm::dvec2& b = hull[(i + 1) % hull.size()];
    area += a.x * b.y - a.y * b.x;
  }
  EXPECT_DOUBLE_EQ(area / 2.0, 1.0) << "counter-clockwise, the unit square";
}

// In an orthographic view along -z (clip z grows away from the light), the
// receivers fill the unit cube around the origin.
TEST(ShadowMapCasterReach, CastersMustMeetTheFootprint)
{
  const glm::dmat4 view = glm::ortho(-5.0, 5.0, -5.0, 5.0, -10.0, 10.0);
  const ShadowReach reach = ReachOfBody(view, Corners(MakeBox({ -1, -1, -1 }, { 1, 1, 1 })), 0.0);
  ASSERT_FALSE(reach.Everywhere);
  EXPECT_TRUE(MayShadowInto(reach, view, MakeBox({ -0.5, -0.5, 2 }, { 0.5, 0.5, 3 })))
    << "above the receivers, nearer the light (the view looks down -z)";
  EXPECT_FALSE(MayShadowInto(reach, view, MakeBox({ 2, 2, 2 }, { 3, 3, 3 }))) << "beside them";
  EXPECT_TRUE(MayShadowInto(reach, view, MakeBox({ -0.5, -0.5, -4 }, { 0.5, 0.5, -3 })))
    << "behind them: kept, a two-surface map holds what lies beyond a receiver";
  // A footprint that is a diamond: its rectangle's corners hold no shadow.
  const ShadowReach diamond = ReachOfBody(
    view, { { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } }, 0.0);
  EXPECT_FALSE(MayShadowInto(diamond, view, MakeBox({ 0.7, 0.7, 1 }, { 0.9, 0.9, 2 })));
  EXPECT_TRUE(MayShadowInto(diamond, view, MakeBox({ 0.2, 0.2, 1 }, { 0.4, 0.4, 2 })));
  // The margin (how far receivers sample beyond themselves, in world units)
  // keeps a caster just beside them.
  const ShadowReach widened = ReachOfBody(view, Corners(MakeBox({ -1, -1, -1 }, { 1, 1, 1 })), 0.3);
  EXPECT_TRUE(MayShadowInto(widened, view, MakeBox({ 1.2, 0, 2 }, { 1.4, 0.5, 3 })));
  EXPECT_FALSE(MayShadowInto(reach, view, MakeBox({ 1.2, 0, 2 }, { 1.4, 0.5, 3 })));
}

// Where the focus body or a caster reaches behind a perspective light, the
// footprints mean nothing: every caster is kept.
TEST(ShadowMapCasterReach, BehindAPerspectiveLightEverythingIsKept)
{
  const glm::dmat4 view = glm::perspective(1.0, 1.0, 0.1, 100.0);
  const ShadowReach behind = ReachOfBody(view, Corners(MakeBox({ -1, -1, -5 }, { 1, 1, 5 })), 0.0);
  EXPECT_TRUE(behind.Everywhere);
  EXPECT_TRUE(MayShadowInto(behind, view, MakeBox({ 50, 50, -60 }, { 51, 51, -59 })));
  const ShadowReach ahead = ReachOfBody(view, Corners(MakeBox({ -1, -1, -6 }, { 1, 1, -4 })), 0.0);
  ASSERT_FALSE(ahead.Everywhere);
  EXPECT_TRUE(MayShadowInto(ahead, view, MakeBox({ -1, -1, -1 }, { 1, 1, 1 }))) << "reaches behind";
  EXPECT_FALSE(MayShadowInto(ahead, view, MakeBox({ 5, 5, -3 }, { 6, 6, -2 })));
  EXPECT_TRUE(ReachOfBody(view, {}, 0.0).Everywhere) << "no body: no culling";
  const glm::dvec3 onTheLightsPlane(1.0, 0.0, -1e-320);
  EXPECT_TRUE(ReachOfBody(view, { onTheLightsPlane, { 1, 1, -5 }, { -1, 1, -5 } }, 0.0).Everywhere)
    << "a point the division cannot place";
}
