// Unit tests for the trapezoidal shadow map math (Plugin/ShadowMapTrapezoid.{h,cxx}).
#include "ShadowMapTrapezoid.h"
#include "ShadowMapMotion.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace
{
using shadowmaps::Aabb;
using shadowmaps::testing::WarpTestGround;
using shadowmaps::TrapezoidMap;

constexpr double Tolerance = 1e-9;

glm::dmat4 Camera(const glm::dvec3& eye, const glm::dvec3& target, bool parallel = false)
{
  const glm::dvec3 d = glm::normalize(target - eye);
  const glm::dvec3 up = std::abs(d.z) > 0.99 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
  const glm::dmat4 view = glm::lookAt(eye, target, up);
  const glm::dmat4 projection = parallel ? glm::ortho(-15.0, 15.0, -10.0, 10.0, 0.5, 80.0)
                                         : glm::perspective(glm::radians(45.0), 1.5, 0.5, 80.0);
  return projection * view;
}

// Horizontal camera looking along +y; the sun straight down is perpendicular to it.
glm::dmat4 HorizontalCamera()
{
  return Camera({ 0.0, -45.0, 5.0 }, { 0.0, 0.0, 5.0 });
}

glm::dvec3 LightSpace(const TrapezoidMap& map, const glm::dvec3& world)
{
  const glm::dvec4 q = map.LightView * glm::dvec4(world, 1.0);
  return glm::dvec3(q) / q.w;
}

void ExpectInsideUnitCube(const glm::dvec3& t)
{
  EXPECT_GE(t.x, -Tolerance);
  EXPECT_LE(t.x, 1.0 + Tolerance);
  EXPECT_GE(t.y, -Tolerance);
  EXPECT_LE(t.y, 1.0 + Tolerance);
  EXPECT_GE(t.z, -Tolerance);
  EXPECT_LE(t.z, 1.0 + Tolerance);
}

bool IsFinite(const TrapezoidMap& map)
{
  for (int c = 0; c < 3; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      if (!std::isfinite(map.TrapezoidToSquare[c][r]))
      {
        return false;
      }
    }
  }
  for (const auto& c : map.Corners)
  {
    if (!std::isfinite(c.x) || !std::isfinite(c.y))
    {
      return false;
    }
  }
  return std::isfinite(map.DepthNear) && std::isfinite(map.DepthFar) &&
    shadowmaps::IsFinite(map.LightView);
}

struct Setup
{
  glm::dmat4 Camera;
  glm::dvec3 Light;
};

std::vector<Setup> Sweep()
{
  std::vector<Setup> setups;
  const glm::dvec3 eye(0.0, -45.0, 5.0);
  const std::vector<glm::dvec3> targets = { { 0.0, 0.0, 5.0 }, { 10.0, 0.0, 0.0 }, { 0.0, -44.0, 0.0 },
    { -20.0, 10.0, 2.0 } };
  for (bool parallel : { false, true })
  {
    for (const auto& target : targets)
    {
      const glm::dmat4 camera = Camera(eye, target, parallel);
      const glm::dvec3 view = glm::normalize(target - eye);
      std::vector<glm::dvec3> lights = { view, -view, { 0.0, 0.0, -1.0 }, { 1.0, 1.0, -1.0 },
        { -1.0, 0.3, -0.2 }, view + glm::dvec3(1e-9, 0.0, 0.0), -view + glm::dvec3(0.0, 0.0, 1e-7),
        glm::normalize(view) * 10.0 + glm::dvec3(0.5, 0.0, 0.5) };
      for (const auto& light : lights)
      {
        setups.push_back({ camera, light });
      }
    }
  }
  return setups;
}

} // namespace

TEST(TrapezoidTSM, ConvexHullDropsInteriorAndCollinearPoints)
{
  const auto hull = shadowmaps::ConvexHull2D(
    { { 0, 0 }, { 2, 0 }, { 1, 0 }, { 2, 2 }, { 0, 2 }, { 1, 1 }, { 0.5, 1.5 }, { 2, 2 } });
  ASSERT_EQ(hull.size(), 4u);
  double area = 0.0;
  for (size_t i = 0; i < hull.size(); ++i)
  {
    const auto& p = hull[i];
    const auto& q = hull[(i + 1) % hull.size()];
    area += p.x * q.y - p.y * q.x;
  }
  EXPECT_DOUBLE_EQ(0.5 * area, 4.0); // counter-clockwise, the full square
}

TEST(TrapezoidTSM, CornersMapToUnitSquareCorners)
{
  const glm::dvec2 expected[4] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
  for (const auto& setup : Sweep())
  {
    const TrapezoidMap map = shadowmaps::FitTrapezoid(setup.Camera, WarpTestGround(), setup.Light, 10.0);
    for (int i = 0; i < 4; ++i)
    {
      const glm::dvec2 ndc = shadowmaps::TrapezoidToNdc(map, map.Corners[i]);
      EXPECT_NEAR(ndc.x, expected[i].x, Tolerance) << "corner " << i;
      EXPECT_NEAR(ndc.y, expected[i].y, Tolerance) << "corner " << i;
    }
  }
}

TEST(TrapezoidTSM, FocusPointMapsToThe80PercentLine)
{
  const glm::dmat4 camera = HorizontalCamera();
  const double delta = 10.0;
  const TrapezoidMap map = shadowmaps::FitTrapezoid(camera, WarpTestGround(), { 0.0, 0.0, -1.0 }, delta);
  EXPECT_DOUBLE_EQ(map.WarpWeight, 1.0);
  EXPECT_TRUE(std::isfinite(map.VanishingDistance));
  EXPECT_GT(map.VanishingDistance, 0.0);
  EXPECT_NEAR(map.FocusLine, 0.8, 1e-12);
  const glm::dvec2 ndc = shadowmaps::TrapezoidToNdc(map, map.FocusPoint);
  EXPECT_NEAR(0.5 * ndc.y + 0.5, 0.8, Tolerance);
  // The same from the world point delta past the near plane centre (eye at
  // y = -45, near 0.5): the focus was not clamped.
  const glm::dvec3 focusWorld(0.0, -45.0 + 0.5 + delta, 5.0);
  EXPECT_NEAR(shadowmaps::MapToTexture(map, focusWorld).y, 0.8, Tolerance);
  // Without warping that point would sit at delta'/lambda of the map: the warp
  // gave the focus region much more than its share.
  const double lambda = glm::length(map.Corners[3] - map.Corners[0]); // symmetric here
  EXPECT_LT(delta / lambda, 0.3);
  // A non-perpendicular light in front of the fade angle keeps the 80% rule.
  const TrapezoidMap oblique = shadowmaps::FitTrapezoid(camera, WarpTestGround(), { 0.3, 0.6, -1.0 }, delta);
  EXPECT_DOUBLE_EQ(oblique.WarpWeight, 1.0);
  EXPECT_NEAR(0.5 * shadowmaps::TrapezoidToNdc(oblique, oblique.FocusPoint).y + 0.5, 0.8, Tolerance);
}

// A camera's axis beside B (its near-plane centre before the hull's top, as a
// parallel camera's can be beside a spot's cone): the focus span is laid off
// from the hull's top, the trapezoid keeps a real vanishing distance, and the
// focus point still maps to the 80% line.
TEST(TrapezoidTSM, NearPlaneCentreBeforeTheHullLaysTheFocusOffFromTheTop)
{
  shadowmaps::TrapezoidFrame frame;
  const shadowmaps::Aabb body{ glm::dvec3(-5.0, 20.0, 0.0), glm::dvec3(5.0, 40.0, 2.0) };
  const auto corners = body.Corners();
  frame.Body.assign(corners.begin(), corners.end());
  frame.Casters = body;
  frame.LightDirection = glm::dvec3(0.0, 0.0, -1.0);
  frame.ViewAxis = glm::dvec3(0.0, 1.0, 0.0);
  frame.CameraUp = glm::dvec3(0.0, 0.0, 1.0);
  frame.NearCentre = glm::dvec3(0.0, 0.0, 1.0); // 20 units before the hull's top
  frame.Focus = frame.NearCentre + frame.ViewAxis * 4.0;
  const TrapezoidMap map = shadowmaps::FitTrapezoidFrame(frame);
  ASSERT_TRUE(IsFinite(map));
  EXPECT_DOUBLE_EQ(map.WarpWeight, 1.0);
  // Measured from the hull's top, the focus (4 units past the near-plane
  // centre, 16 before the top) gave delta 1e-3 of the hull's depth and eta with it.
  const double lambda = 20.0;
  EXPECT_GT(map.VanishingDistance, 0.05 * lambda);
  EXPECT_NEAR(0.5 * shadowmaps::TrapezoidToNdc(map, map.FocusPoint).y + 0.5, map.FocusLine, Tolerance);
  const glm::dvec2 topCentre = 0.5 * (map.Corners[0] + map.Corners[1]);
  const glm::dvec2 baseCentre = 0.5 * (map.Corners[2] + map.Corners[3]);
  const glm::dvec2 axial = glm::normalize(baseCentre - topCentre);
  EXPECT_NEAR(glm::dot(map.FocusPoint - topCentre, axial), 4.0, 1e-9);
}

TEST(TrapezoidTSM, EveryHullAndBodyPointMapsInsideTheSquare)
{
  for (const auto& setup : Sweep())
  {
    const TrapezoidMap map = shadowmaps::FitTrapezoid(setup.Camera, WarpTestGround(), setup.Light, 10.0);
    ASSERT_TRUE(IsFinite(map));
    for (const auto& p : map.Hull)
    {
      const glm::dvec2 ndc = shadowmaps::TrapezoidToNdc(map, p);
      EXPECT_LE(std::abs(ndc.x), 1.0 + Tolerance);
      EXPECT_LE(std::abs(ndc.y), 1.0 + Tolerance);
    }
    for (const auto& p : shadowmaps::IntersectFrustumWithBox(setup.Camera, WarpTestGround()))
    {
      ExpectInsideUnitCube(shadowmaps::MapToTexture(map, p));
    }
  }
}

TEST(TrapezoidTSM, DepthIsLinearInLightSpaceZ)
{
  const TrapezoidMap map = shadowmaps::FitTrapezoid(HorizontalCamera(), WarpTestGround(), { 0.2, 0.5, -1.0 }, 10.0);
  ASSERT_TRUE(std::isfinite(map.VanishingDistance)); // a real trapezoid
  const glm::dvec3 a(3.0, -20.0, 1.0), b(-7.0, 5.0, 9.0);
  const double za = LightSpace(map, a).z, zb = LightSpace(map, b).z;
  const double da = shadowmaps::MapToTexture(map, a).z, db = shadowmaps::MapToTexture(map, b).z;
  for (double t : { -0.5, 0.1, 0.37, 0.9, 1.5 })
  {
    const glm::dvec3 p = a + t * (b - a);
    const double z = LightSpace(map, p).z;
    const double expected = da + (db - da) * (z - za) / (zb - za);
    EXPECT_NEAR(shadowmaps::MapToTexture(map, p).z, expected, 1e-12);
    // and equal to the documented formula
    EXPECT_NEAR(shadowmaps::MapToTexture(map, p).z, (-z - map.DepthNear) / (map.DepthFar - map.DepthNear), 1e-12);
  }
}

TEST(TrapezoidTSM, LightViewMatrixMatchesTheMapping)
{
  const TrapezoidMap map = shadowmaps::FitTrapezoid(HorizontalCamera(), WarpTestGround(), { 0.2, 0.5, -1.0 }, 10.0);
  const shadowmaps::LightView view = shadowmaps::TrapezoidLightView(map, 2048);
  EXPECT_TRUE(view.Perspective);
  EXPECT_GT(view.TexelConstant, 0.0);
  const glm::dmat4 vp = view.ViewProjection();
  for (const auto& p : shadowmaps::IntersectFrustumWithBox(HorizontalCamera(), WarpTestGround()))
  {
    const glm::dvec4 clip = vp * glm::dvec4(p, 1.0);
    const glm::dvec3 t = shadowmaps::MapToTexture(map, p);
    EXPECT_GE(clip.w, 1.0 - Tolerance);
    EXPECT_NEAR(0.5 * clip.x / clip.w + 0.5, t.x, Tolerance);
    EXPECT_NEAR(0.5 * clip.y / clip.w + 0.5, t.y, Tolerance);
    EXPECT_NEAR(0.5 * clip.z + 0.5, t.z, Tolerance); // linear depth before the divide
    EXPECT_LE(std::abs(clip.z), clip.w);             // never depth-clipped
  }
}

TEST(TrapezoidTSM, CasterRecoversLinearDepthFromTheNdcPosition)
{
  const TrapezoidMap map = shadowmaps::FitTrapezoid(HorizontalCamera(), WarpTestGround(), { 0.2, 0.5, -1.0 }, 10.0);
  const shadowmaps::LightView view = shadowmaps::TrapezoidLightView(map, 2048);
  EXPECT_TRUE(view.LinearDepth);
  const glm::dvec3 inverseW = shadowmaps::NdcToInverseW(view);
  const glm::dmat4 vp = view.ViewProjection();
  for (const auto& p : shadowmaps::IntersectFrustumWithBox(HorizontalCamera(), WarpTestGround()))
  {
    // What a caster's fragment shader sees: NDC x, y and the window depth Z / W.
    const glm::dvec4 clip = vp * glm::dvec4(p, 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    const double w = 1.0 / glm::dot(inverseW, glm::dvec3(ndc.x, ndc.y, 1.0));
    EXPECT_NEAR(w, clip.w, 1e-9 * clip.w);
    EXPECT_NEAR(0.5 * ndc.z * w + 0.5, shadowmaps::MapToTexture(map, p).z, 1e-9);
  }
  // W = 1 (an orthographic map) gives the identity.
  shadowmaps::LightView ortho;
  ortho.Projection = glm::ortho(-2.0, 3.0, -1.0, 4.0, 0.5, 9.0);
  const glm::dvec3 identity = shadowmaps::NdcToInverseW(ortho);
  EXPECT_NEAR(identity.x, 0.0, 1e-15);
  EXPECT_NEAR(identity.y, 0.0, 1e-15);
  EXPECT_NEAR(identity.z, 1.0, 1e-15);
}

TEST(TrapezoidTSM, LightAlongTheViewGivesTheUniformFocusedMap)
{
  const glm::dvec3 eye(0.0, -45.0, 30.0), target(0.0, 0.0, 0.0);
  const glm::dmat4 camera = Camera(eye, target);
  const glm::dvec3 view = glm::normalize(target - eye);
  for (const glm::dvec3& light : { view, -view })
  {
    const TrapezoidMap map = shadowmaps::FitTrapezoid(camera, WarpTestGround(), light, 10.0);
    ASSERT_TRUE(IsFinite(map));
    EXPECT_EQ(map.WarpWeight, 0.0);
    EXPECT_TRUE(std::isinf(map.VanishingDistance));
    // Affine: W is 1 everywhere.
    for (const auto& c : map.Corners)
    {
      EXPECT_NEAR((map.TrapezoidToSquare * glm::dvec3(c, 1.0)).z, 1.0, 1e-15);
    }
    // Same extent as the focused uniform fit (which adds 4 texels each side).
    const shadowmaps::LightView uniform = shadowmaps::FitDirectional(camera, WarpTestGround(), light, 2048);
    const double width = glm::length(map.Corners[1] - map.Corners[0]);
    const double height = glm::length(map.Corners[3] - map.Corners[0]);
    const double uniformWidth = 2.0 / uniform.Projection[0][0];
    const double uniformHeight = 2.0 / uniform.Projection[1][1];
    EXPECT_NEAR(std::max(width, height) * (1.0 + 8.0 / 2048), std::max(uniformWidth, uniformHeight), 1e-9 * uniformWidth);
    EXPECT_NEAR(std::min(width, height) * (1.0 + 8.0 / 2048), std::min(uniformWidth, uniformHeight), 1e-9 * uniformWidth);
  }
}

TEST(TrapezoidTSM, WarpFadesContinuouslyTowardTheViewAxis)
{
  // Tilt the light away from the view axis in a fixed plane: the map of a
  // fixed point and the warp strength W_base / W_top move continuously to the
  // uniform limit.
  const glm::dvec3 eye(0.0, -45.0, 30.0), target(0.0, 0.0, 0.0);
  const glm::dmat4 camera = Camera(eye, target);
  const glm::dvec3 view = glm::normalize(target - eye);
  const glm::dvec3 side(1.0, 0.0, 0.0);
  const glm::dvec3 probe(2.0, -10.0, 1.0);
  double previousRatio = 1e300;
  glm::dvec3 previous(0.0);
  for (double degrees : { 20.0, 10.0, 5.0, 1.0, 1e-2, 1e-4, 1e-6, 1e-8 })
  {
    const double angle = glm::radians(degrees);
    const glm::dvec3 light = std::cos(angle) * view + std::sin(angle) * side;
    const TrapezoidMap map = shadowmaps::FitTrapezoid(camera, WarpTestGround(), light, 10.0);
    ASSERT_TRUE(IsFinite(map));
    const double wTop = (map.TrapezoidToSquare * glm::dvec3(map.Corners[0], 1.0)).z;
    const double wBase = (map.TrapezoidToSquare * glm::dvec3(map.Corners[3], 1.0)).z;
    const double ratio = wBase / wTop;
    EXPECT_LE(ratio, previousRatio + 1e-12) << degrees;
    previousRatio = ratio;
    const glm::dvec3 t = shadowmaps::MapToTexture(map, probe);
    if (degrees <= 1e-4)
    {
      EXPECT_LT(glm::length(glm::dvec2(t - previous)), 1e-3) << degrees;
    }
    previous = t;
  }
  EXPECT_NEAR(previousRatio, 1.0, 1e-6);
}

TEST(TrapezoidTSM, NoNaNOverCameraLightSweep)
{
  int count = 0;
  for (const auto& setup : Sweep())
  {
    for (double delta : { 0.0, 1.0, 10.0, 1e4 })
    {
      const TrapezoidMap map = shadowmaps::FitTrapezoid(setup.Camera, WarpTestGround(), setup.Light, delta);
      ASSERT_TRUE(IsFinite(map));
      const shadowmaps::LightView view = shadowmaps::TrapezoidLightView(map, 1024);
      ASSERT_TRUE(shadowmaps::IsFinite(view.ViewProjection()));
      ASSERT_TRUE(std::isfinite(view.TexelConstant));
      ++count;
    }
  }
  EXPECT_EQ(count, 256);
}

// Issue property: a light turning in 0.1 degree steps through the view axis (and
// through the axis opposite it) moves the map coordinates of fixed world points by
// less than 2 texels per step beyond what the focused uniform map's own moves are.
// The light turns in planes through the view axis at several azimuths about it:
// the centre line reverses at the axis, which used to flip the map over.
TEST(TrapezoidTSM, MapMovesContinuouslyThroughTheViewAxis)
{
  constexpr int resolution = 2048;
  const glm::dvec3 eye(0.0, -45.0, 5.0), target(0.0, 0.0, 3.0);
  const glm::dmat4 camera = Camera(eye, target);
  const glm::dvec3 view = glm::normalize(target - eye);
  const glm::dvec3 right = glm::normalize(glm::cross(view, glm::dvec3(0.0, 0.0, 1.0)));
  const glm::dvec3 up = glm::cross(right, view);
  const auto body = shadowmaps::IntersectFrustumWithBox(camera, WarpTestGround());
  ASSERT_FALSE(body.empty());
  std::vector<glm::dvec3> points(body.begin(), body.end());
  for (size_t i = 0; i + 1 < body.size(); ++i)
  {
    points.push_back(0.5 * (body[i] + body[i + 1]));
  }
  for (double sign : { 1.0, -1.0 })
  {
    for (double azimuth : { 0.0, 30.0, 90.0 })
    {
      const double a = glm::radians(azimuth);
      const glm::dvec3 across = std::cos(a) * up + std::sin(a) * right;
      shadowmaps::testing::ExcessMotion motion(points, resolution);
      for (int step = -20; step <= 20; ++step)
      {
        const double t = glm::radians(0.1 * step);
        const glm::dvec3 light = sign * (std::cos(t) * view + std::sin(t) * across);
        const auto map = shadowmaps::TrapezoidLightView(
          shadowmaps::FitTrapezoid(camera, WarpTestGround(), light, 10.0), resolution);
        ASSERT_TRUE(shadowmaps::IsFinite(map.ViewProjection()));
        motion.Step(map, shadowmaps::FitDirectional(camera, WarpTestGround(), light, resolution));
      }
      std::printf("[ continuity ] TSM light %s, azimuth %4.0f: largest excess %.4f texels\n",
        sign > 0 ? "along the view  " : "against the view", azimuth, motion.Worst());
      EXPECT_LT(motion.Worst(), 2.0) << "light sign " << sign << ", azimuth " << azimuth;
    }
  }
}
