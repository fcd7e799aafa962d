// Unit tests for cascaded shadow maps in Plugin/ShadowMapCascades.{h,cxx}: the practical
// split scheme (survey 003 §4.3.1), split sanitizing, sub-frustum projections, the
// focused and stable (texel-snapped, 003 / Microsoft 004) cascade fits, near/far from
// the clipped scene box (004's ComputeNearAndFar) and the CPU model of the shader's
// cascade selection and blending.
#include "ShadowMapCascades.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace
{
using shadowmaps::Aabb;
using shadowmaps::LightView;

constexpr double Pi = 3.14159265358979323846;
constexpr int Resolution = 2048;

// The split formula written out independently of the implementation.
double Split(double n, double f, int i, int m, double lambda)
{
  const double t = double(i) / double(m);
  return lambda * n * std::pow(f / n, t) + (1.0 - lambda) * (n + (f - n) * t);
}

// Camera at eye looking at target with world up +z.
glm::dmat4 LookAt(const glm::dvec3& eye, const glm::dvec3& target)
{
  return glm::lookAt(eye, target, glm::dvec3(0.0, 0.0, 1.0));
}

glm::dmat4 CameraProjection()
{
  return glm::perspective(glm::radians(60.0), 16.0 / 9.0, 1.0, 100.0);
}

// A large ground slab: the receivers of an outdoor scene.
Aabb Ground()
{
  return { glm::dvec3(-200.0, -200.0, -1.0), glm::dvec3(200.0, 200.0, 0.0) };
}

glm::dvec3 Ndc(const LightView& fit, const glm::dvec3& p)
{
  const glm::dvec4 c = fit.ViewProjection() * glm::dvec4(p, 1.0);
  return glm::dvec3(c) / c.w;
}

// Texel coordinate u * resolution (and v * resolution) of a world point.
glm::dvec2 TexelCoordinate(const LightView& fit, const glm::dvec3& p)
{
  const glm::dvec3 ndc = Ndc(fit, p);
  return (glm::dvec2(ndc) * 0.5 + 0.5) * double(Resolution);
}

bool AllFinite(const LightView& fit)
{
  return shadowmaps::IsFinite(fit.View) && shadowmaps::IsFinite(fit.Projection) &&
    std::isfinite(fit.TexelConstant) && std::isfinite(glm::determinant(fit.ViewProjection())) &&
    glm::determinant(fit.ViewProjection()) != 0.0;
}

// Expects every corner of the sub-frustum inside the map's x/y square.
void ExpectContainsSubFrustum(const LightView& fit, const glm::dmat4& cameraView, const glm::dmat4& sub)
{
  for (const auto& corner : shadowmaps::FrustumCorners(sub * cameraView))
  {
    const glm::dvec3 ndc = Ndc(fit, corner);
    EXPECT_LE(std::abs(ndc.x), 1.0);
    EXPECT_LE(std::abs(ndc.y), 1.0);
  }
}

// ---------------------------------------------------------------------------
// Splits.

TEST(ShadowMapCascades, PracticalSplitsFollowTheFormula)
{
  for (double lambda : { 0.0, 0.5, 1.0 })
  {
    for (int m : { 1, 2, 4, 7 })
    {
      const std::vector<double> splits = shadowmaps::PracticalSplits(1.0, 100.0, m, lambda);
      ASSERT_EQ(splits.size(), size_t(m + 1));
      EXPECT_EQ(splits.front(), 1.0);
      EXPECT_EQ(splits.back(), 100.0);
      for (int i = 0; i <= m; ++i)
      {
        EXPECT_NEAR(splits[i], Split(1.0, 100.0, i, m, lambda), 1e-12 * splits[i]) << lambda << " " << i;
        if (i > 0)
        {
          EXPECT_GT(splits[i], splits[i - 1]);
        }
      }
    }
  }
  // Literal values: uniform, logarithmic, and their average.
  const std::vector<double> uniform = shadowmaps::PracticalSplits(1.0, 100.0, 4, 0.0);
  const std::vector<double> logarithmic = shadowmaps::PracticalSplits(1.0, 100.0, 4, 1.0);
  const std::vector<double> practical = shadowmaps::PracticalSplits(1.0, 100.0, 4, 0.5);
  const double expectedUniform[] = { 1.0, 25.75, 50.5, 75.25, 100.0 };
  const double expectedLog[] = { 1.0, 3.16227766, 10.0, 31.6227766, 100.0 };
  for (int i = 0; i < 5; ++i)
  {
    EXPECT_NEAR(uniform[i], expectedUniform[i], 1e-12);
    EXPECT_NEAR(logarithmic[i], expectedLog[i], 1e-8);
    EXPECT_NEAR(practical[i], 0.5 * (expectedUniform[i] + expectedLog[i]), 1e-8);
  }
  EXPECT_NEAR(practical[2], 30.25, 1e-12);
}

TEST(ShadowMapCascades, PracticalSplitsNeverReturnNaN)
{
  const double nan = std::nan("");
  const double inf = HUGE_VAL;
  const struct
  {
    double n, f;
    int m;
    double lambda;
  } cases[] = { { 0.0, 100.0, 4, 1.0 }, { -5.0, 100.0, 4, 0.5 }, { 10.0, 10.0, 3, 1.0 },
    { 10.0, 1.0, 3, 0.7 }, { nan, 100.0, 2, 1.0 }, { 1.0, inf, 2, 1.0 }, { 1.0, 100.0, 0, nan },
    { 1.0, 100.0, -3, 5.0 }, { 0.0, 0.0, 4, 1.0 } };
  for (const auto& c : cases)
  {
    const std::vector<double> splits = shadowmaps::PracticalSplits(c.n, c.f, c.m, c.lambda);
    ASSERT_GE(splits.size(), 2u);
    for (size_t i = 0; i < splits.size(); ++i)
    {
      EXPECT_TRUE(std::isfinite(splits[i])) << c.n << " " << c.f;
      if (i > 0)
      {
        EXPECT_GE(splits[i], splits[i - 1]);
      }
    }
    EXPECT_GT(splits.back(), splits.front());
  }
}

TEST(ShadowMapCascades, SanitizeSplitsRepairsBadInputAndSaysSo)
{
  std::string problem;
  const std::vector<double> splits =
    shadowmaps::SanitizeSplits({ 40.0, -3.0, 10.0, 250.0, 40.0, 5.0, 100.0, std::nan("") }, 1.0, 100.0, &problem);
  const std::vector<double> expected = { 1.0, 5.0, 10.0, 40.0, 100.0 };
  EXPECT_EQ(splits, expected);
  EXPECT_FALSE(problem.empty());
  EXPECT_NE(problem.find("-3"), std::string::npos) << problem;
  EXPECT_NE(problem.find("250"), std::string::npos) << problem;
  EXPECT_NE(problem.find("sorted"), std::string::npos) << problem;
  EXPECT_NE(problem.find("duplicate"), std::string::npos) << problem;

  // Each defect alone is reported.
  for (const std::vector<double>& bad : std::vector<std::vector<double>>{
         { 20.0, 10.0 }, { 10.0, 10.0 }, { -1.0, 10.0 }, { 10.0, 150.0 }, { 1.0, 10.0 } })
  {
    problem.clear();
    const std::vector<double> result = shadowmaps::SanitizeSplits(bad, 1.0, 100.0, &problem);
    EXPECT_FALSE(problem.empty());
    EXPECT_EQ(result.front(), 1.0);
    EXPECT_EQ(result.back(), 100.0);
    EXPECT_TRUE(std::adjacent_find(result.begin(), result.end(), std::greater_equal<double>()) == result.end());
  }

  // Valid input: unchanged, no problem (a stale message is cleared).
  problem = "stale";
  const std::vector<double> valid = shadowmaps::SanitizeSplits({ 3.0, 12.5, 47.0 }, 1.0, 100.0, &problem);
  EXPECT_EQ(valid, (std::vector<double>{ 1.0, 3.0, 12.5, 47.0, 100.0 }));
  EXPECT_TRUE(problem.empty()) << problem;
  EXPECT_EQ(shadowmaps::SanitizeSplits({}, 1.0, 100.0, &problem), (std::vector<double>{ 1.0, 100.0 }));
  EXPECT_TRUE(problem.empty());
  EXPECT_EQ(shadowmaps::SanitizeSplits({ 3.0 }, 1.0, 100.0, nullptr).size(), 3u);

  // A bad depth range still gives an increasing list, and a message.
  const std::vector<double> degenerate = shadowmaps::SanitizeSplits({ 3.0 }, 5.0, 5.0, &problem);
  ASSERT_EQ(degenerate.size(), 2u);
  EXPECT_GT(degenerate[1], degenerate[0]);
  EXPECT_FALSE(problem.empty());
}

// ---------------------------------------------------------------------------
// Sub-frustum projection.

TEST(ShadowMapCascades, SubFrustumProjectionMovesOnlyTheDepthPlanes)
{
  const glm::dmat4 projections[] = { CameraProjection(),
    glm::frustum(-0.3, 0.7, -0.2, 0.5, 1.0, 100.0), // off-axis
    glm::ortho(-10.0, 14.0, -6.0, 7.0, 0.5, 80.0),
    glm::ortho(-10.0, 14.0, -6.0, 7.0, -20.0, 80.0) };
  for (const glm::dmat4& p : projections)
  {
    const glm::dvec2 full = shadowmaps::ProjectionDepthRange(p);
    const double n = std::max(full.x, 0.0) + 3.0;
    const double f = 0.5 * full.y;
    const glm::dmat4 sub = shadowmaps::SubFrustumProjection(p, n, f);
    const glm::dvec2 range = shadowmaps::ProjectionDepthRange(sub);
    EXPECT_NEAR(range.x, n, 1e-9 * f);
    EXPECT_NEAR(range.y, f, 1e-9 * f);
    // Same side planes: every point has the same clip x, y, w.
    for (const glm::dvec3& q : { glm::dvec3(1.0, 2.0, -5.0), glm::dvec3(-3.0, 0.5, -30.0) })
    {
      const glm::dvec4 a = p * glm::dvec4(q, 1.0);
      const glm::dvec4 b = sub * glm::dvec4(q, 1.0);
      EXPECT_EQ(a.x, b.x);
      EXPECT_EQ(a.y, b.y);
      EXPECT_EQ(a.w, b.w);
    }
    // The near and far planes land on clip z = -1 and +1.
    for (const auto& corner : shadowmaps::FrustumCorners(sub))
    {
      EXPECT_TRUE(std::abs(-corner.z - n) < 1e-9 * f || std::abs(-corner.z - f) < 1e-9 * f) << corner.z;
    }
  }
  // Degenerate ranges stay finite and invertible.
  for (const glm::dvec2& nf : { glm::dvec2(5.0, 5.0), glm::dvec2(0.0, 10.0), glm::dvec2(-4.0, 10.0),
         glm::dvec2(10.0, 2.0), glm::dvec2(std::nan(""), 3.0) })
  {
    for (const glm::dmat4& p : projections)
    {
      const glm::dmat4 sub = shadowmaps::SubFrustumProjection(p, nf.x, nf.y);
      EXPECT_TRUE(shadowmaps::IsFinite(sub));
      EXPECT_TRUE(shadowmaps::IsFinite(glm::inverse(sub)));
      EXPECT_NE(glm::determinant(sub), 0.0);
    }
  }
}

TEST(ShadowMapCascades, BoundingSphereContainsTheSubFrustumAndIsMinimalOnTheAxis)
{
  const glm::dmat4 sub = shadowmaps::SubFrustumProjection(CameraProjection(), 10.0, 31.6);
  const shadowmaps::BoundingSphere sphere = shadowmaps::CascadeBoundingSphere(sub);
  EXPECT_NEAR(sphere.Center.x, 0.0, 1e-12);
  EXPECT_NEAR(sphere.Center.y, 0.0, 1e-12);
  double largest = 0.0;
  for (const auto& corner : shadowmaps::FrustumCorners(sub))
  {
    largest = std::max(largest, glm::length(corner - sphere.Center));
  }
  EXPECT_NEAR(largest, sphere.Radius, 1e-12 * sphere.Radius);
  // Moving the centre along the axis either way only makes it larger.
  for (double dz : { -1e-3, 1e-3 })
  {
    double moved = 0.0;
    for (const auto& corner : shadowmaps::FrustumCorners(sub))
    {
      moved = std::max(moved, glm::length(corner - sphere.Center - glm::dvec3(0.0, 0.0, dz)));
    }
    EXPECT_GT(moved, sphere.Radius);
  }
}

// ---------------------------------------------------------------------------
// Stable fitting.

TEST(ShadowMapCascades, StableFitKeepsItsTexelGridWhenTheCameraMoves)
{
  const glm::dvec3 light = glm::normalize(glm::dvec3(0.4, -0.3, -1.0));
  const std::vector<double> splits = shadowmaps::PracticalSplits(1.0, 100.0, 4, 0.5);
  const glm::dvec3 eye(3.0, -7.0, 2.0);
  const glm::dvec3 target(40.0, 20.0, 0.0);
  const std::vector<glm::dvec3> world = { { 0.0, 0.0, 0.0 }, { 12.3, -4.5, 0.0 }, { 33.0, 17.0, -0.5 },
    { -8.0, 25.0, 3.0 } };

  for (int cascade = 0; cascade < 4; ++cascade)
  {
    const glm::dmat4 sub =
      shadowmaps::SubFrustumProjection(CameraProjection(), splits[cascade], splits[cascade + 1]);
    const LightView reference = shadowmaps::FitCascadeStable(LookAt(eye, target), sub, Ground(), light, Resolution);
    ASSERT_TRUE(AllFinite(reference));
    const double texel = reference.TexelConstant;
    EXPECT_EQ(texel, 2.0 / reference.Projection[0][0] / Resolution);

    // Sub-texel moves, moves of several texels, and small turns.
    std::vector<glm::dmat4> views;
    for (const glm::dvec3& move : { glm::dvec3(0.3, 0.0, 0.0), glm::dvec3(0.0, 0.17, 0.05),
           glm::dvec3(-0.41, 0.23, 0.0), glm::dvec3(3.7, -5.2, 0.0), glm::dvec3(11.0, 4.0, 1.0) })
    {
      views.push_back(LookAt(eye + move * texel, target + move * texel));
    }
    for (double degrees : { 0.01, -0.3, 2.0 })
    {
      const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::dvec3(0.0, 0.0, 1.0));
      views.push_back(LookAt(eye, eye + glm::dvec3(turn * glm::dvec4(target - eye, 0.0))));
    }
    for (const glm::dmat4& view : views)
    {
      const LightView fit = shadowmaps::FitCascadeStable(view, sub, Ground(), light, Resolution);
      ASSERT_TRUE(AllFinite(fit));
      // Same orientation, same size, bitwise.
      EXPECT_EQ(fit.View, reference.View);
      EXPECT_EQ(fit.Projection[0][0], reference.Projection[0][0]);
      EXPECT_EQ(fit.Projection[1][1], reference.Projection[1][1]);
      EXPECT_EQ(fit.TexelConstant, reference.TexelConstant);
      // The grid moved by whole texels only.
      glm::dvec2 shift(0.0);
      for (size_t i = 0; i < world.size(); ++i)
      {
        const glm::dvec2 d = TexelCoordinate(fit, world[i]) - TexelCoordinate(reference, world[i]);
        EXPECT_NEAR(d.x, std::round(d.x), 1e-6) << cascade;
        EXPECT_NEAR(d.y, std::round(d.y), 1e-6) << cascade;
        if (i == 0)
        {
          shift = d;
        }
        // All points shift by the same whole number of texels.
        EXPECT_NEAR(d.x, shift.x, 1e-6);
        EXPECT_NEAR(d.y, shift.y, 1e-6);
      }
      ExpectContainsSubFrustum(fit, view, sub);
    }
  }
}

// A camera sliding sideways keeps each cascade's whole map (its matrices,
// bitwise) until the sphere has moved a thirty-second of the map: the centre moves
// in steps of that many texels, and the far plane in eighths of the half-width.
// With one-texel steps an orbiting camera re-rendered every cascade in nearly
// every frame.
TEST(ShadowMapCascades, StableFitMovesInStepsOfAThirtySecondOfTheMap)
{
  const glm::dvec3 light = glm::normalize(glm::dvec3(0.4, -0.3, -1.0));
  const std::vector<double> splits = shadowmaps::PracticalSplits(1.0, 100.0, 4, 0.5);
  const glm::dvec3 eye(3.0, -7.0, 2.0);
  const glm::dvec3 target(40.0, 20.0, 0.0);
  const glm::dvec3 side = glm::normalize(glm::cross(target - eye, glm::dvec3(0.0, 0.0, 1.0)));
  // Scenes deeper than the spheres (the far plane is the sphere's) and not.
  for (const Aabb& scene : { Ground(), Aabb{ glm::dvec3(-200.0), glm::dvec3(200.0) } })
  {
    for (int cascade = 0; cascade < 4; ++cascade)
    {
      const glm::dmat4 sub =
        shadowmaps::SubFrustumProjection(CameraProjection(), splits[cascade], splits[cascade + 1]);
      const double texel =
        shadowmaps::FitCascadeStable(LookAt(eye, target), sub, scene, light, Resolution).TexelConstant;
      // 256 moves of half a texel: 128 texels, two steps of 64 texels at 2048².
      std::vector<glm::dmat4> distinct;
      for (int move = 0; move <= 256; ++move)
      {
        const glm::dvec3 offset = side * (0.5 * move * texel);
        const LightView fit =
          shadowmaps::FitCascadeStable(LookAt(eye + offset, target + offset), sub, scene, light, Resolution);
        ASSERT_EQ(fit.TexelConstant, texel);
        if (distinct.empty() || fit.Projection != distinct.back())
        {
          distinct.push_back(fit.Projection);
        }
      }
      // Each axis crosses at most two steps, the far plane at most two eighths;
      // with one-texel steps there were 257 maps.
      EXPECT_GE(distinct.size(), 2u) << "128 texels cross a 64-texel step";
      EXPECT_LE(distinct.size(), 7u) << "cascade " << cascade;
    }
  }
}

TEST(ShadowMapCascades, StableFitContainsItsSubFrustumForAnyCamera)
{
  const std::vector<double> splits = shadowmaps::PracticalSplits(0.5, 300.0, 4, 0.75);
  const glm::dmat4 projections[] = { glm::perspective(glm::radians(45.0), 1.0, 0.5, 300.0),
    glm::perspective(glm::radians(90.0), 2.5, 0.5, 300.0), glm::frustum(-0.1, 0.5, -0.3, 0.2, 0.5, 300.0) };
  for (const glm::dmat4& projection : projections)
  {
    for (int cascade = 0; cascade < 4; ++cascade)
    {
      const glm::dmat4 sub =
        shadowmaps::SubFrustumProjection(projection, splits[cascade], splits[cascade + 1]);
      for (double heading = 0.0; heading < 360.0; heading += 37.0)
      {
        const glm::dvec3 eye(5.0, -3.0, 4.0);
        const glm::dvec3 forward(std::cos(glm::radians(heading)), std::sin(glm::radians(heading)), -0.2);
        const glm::dmat4 view = LookAt(eye, eye + forward);
        const LightView fit = shadowmaps::FitCascadeStable(view, sub, Ground(), { 0.3, 0.1, -1.0 }, 1024);
        ASSERT_TRUE(AllFinite(fit));
        ExpectContainsSubFrustum(fit, view, sub);
      }
    }
  }
}

TEST(ShadowMapCascades, StableFitKeepsCastersBetweenTheSubFrustumAndTheLight)
{
  // Camera 2 units above the ground looking along +x; the light comes from +x, high.
  const glm::dmat4 view = LookAt({ 0.0, 0.0, 2.0 }, { 1.0, 0.0, 2.0 });
  // Logarithmic splits: cascade 0 spans depths 1 to 3.16.
  const std::vector<double> splits = shadowmaps::PracticalSplits(1.0, 100.0, 4, 1.0);
  const glm::dmat4 sub = shadowmaps::SubFrustumProjection(CameraProjection(), splits[0], splits[1]);
  const glm::dvec3 light = glm::normalize(glm::dvec3(-1.0, 0.0, -1.0));
  // A tall pole well beyond the cascade's far split but on the light rays through it.
  const Aabb pole{ glm::dvec3(20.0, -0.5, 0.0), glm::dvec3(21.0, 0.5, 30.0) };
  Aabb scene = Ground();
  scene.Add(pole);
  ASSERT_GT(pole.Min.x, splits[1] + 1.0);

  for (const LightView& fit : { shadowmaps::FitCascadeStable(view, sub, scene, light, Resolution),
         shadowmaps::FitCascadeTight(view, sub, scene, light, Resolution) })
  {
    ASSERT_TRUE(AllFinite(fit));
    // The pole is outside the sub-frustum.
    const auto planes = shadowmaps::FrustumPlanes(sub * view);
    for (const auto& corner : pole.Corners())
    {
      EXPECT_TRUE(std::any_of(planes.begin(), planes.end(),
        [&](const shadowmaps::Plane& p) { return p.Distance(corner) < 0.0; }));
    }
    // Every sample of the pole that falls inside the map's square is inside its depth range.
    int inside = 0;
    for (double x = 20.0; x <= 21.0; x += 0.25)
    {
      for (double y = -0.5; y <= 0.5; y += 0.25)
      {
        for (double z = 0.0; z <= 30.0; z += 0.5)
        {
          const glm::dvec3 ndc = Ndc(fit, { x, y, z });
          if (std::abs(ndc.x) <= 1.0 && std::abs(ndc.y) <= 1.0)
          {
            ++inside;
            EXPECT_GE(ndc.z, -1.0) << x << " " << y << " " << z;
            EXPECT_LE(ndc.z, 1.0) << x << " " << y << " " << z;
          }
        }
      }
    }
    EXPECT_GT(inside, 10);
  }
  // The test bites: some of the pole inside the stable map is farther toward the light
  // than the sub-frustum's bounding sphere reaches, so a depth range taken from the
  // sphere (or the sub-frustum) alone would miss it.
  const LightView stable = shadowmaps::FitCascadeStable(view, sub, scene, light, Resolution);
  const shadowmaps::BoundingSphere sphere = shadowmaps::CascadeBoundingSphere(sub);
  const glm::dvec3 centre(glm::inverse(view) * glm::dvec4(sphere.Center, 1.0));
  int towardLight = 0;
  for (double z = 0.0; z <= 30.0; z += 0.5)
  {
    const glm::dvec3 p(20.5, 0.0, z);
    const glm::dvec3 ndc = Ndc(stable, p);
    if (std::abs(ndc.x) <= 1.0 && std::abs(ndc.y) <= 1.0 && glm::dot(centre - p, light) > 1.5 * sphere.Radius)
    {
      ++towardLight;
    }
  }
  EXPECT_GT(towardLight, 0);
}

// ---------------------------------------------------------------------------
// Degenerate input.

TEST(ShadowMapCascades, DegenerateInputGivesFiniteMatrices)
{
  const glm::dmat4 view = LookAt({ 0.0, 0.0, 2.0 }, { 1.0, 0.0, 2.0 });
  const glm::dmat4 perspective = CameraProjection();
  const glm::dmat4 parallel = glm::ortho(-20.0, 20.0, -10.0, 10.0, 0.1, 100.0);
  const struct
  {
    const char* name;
    glm::dmat4 sub;
    Aabb scene;
    glm::dvec3 light;
    glm::dmat4 view;
  } cases[] = {
    { "empty scene", shadowmaps::SubFrustumProjection(perspective, 1.0, 10.0), Aabb{}, { 0.0, 0.3, -1.0 }, view },
    { "zero light", shadowmaps::SubFrustumProjection(perspective, 1.0, 10.0), Ground(), glm::dvec3(0.0), view },
    { "light along view", shadowmaps::SubFrustumProjection(perspective, 1.0, 10.0), Ground(), { 1.0, 0.0, 0.0 }, view },
    { "light against view", shadowmaps::SubFrustumProjection(perspective, 1.0, 10.0), Ground(), { -1.0, 0.0, 0.0 }, view },
    { "light straight down", shadowmaps::SubFrustumProjection(perspective, 1.0, 10.0), Ground(), { 0.0, 0.0, -1.0 }, view },
    { "parallel camera", shadowmaps::SubFrustumProjection(parallel, 0.1, 30.0), Ground(), { 0.2, 0.3, -1.0 }, view },
    { "parallel camera, near < 0", shadowmaps::SubFrustumProjection(parallel, -5.0, 30.0), Ground(), { 0.2, 0.3, -1.0 }, view },
    { "zNear == zFar", shadowmaps::SubFrustumProjection(perspective, 7.0, 7.0), Ground(), { 0.2, 0.3, -1.0 }, view },
    { "zNear == zFar == 0", shadowmaps::SubFrustumProjection(perspective, 0.0, 0.0), Ground(), { 0.2, 0.3, -1.0 }, view },
    { "point scene", shadowmaps::SubFrustumProjection(perspective, 1.0, 10.0), Aabb{ glm::dvec3(3.0), glm::dvec3(3.0) }, { 0.2, 0.3, -1.0 }, view },
    { "singular projection", glm::dmat4(0.0), Ground(), { 0.2, 0.3, -1.0 }, view },
    { "NaN camera view", shadowmaps::SubFrustumProjection(perspective, 1.0, 10.0), Ground(), { 0.2, 0.3, -1.0 }, glm::dmat4(std::nan("")) },
    { "scene behind camera", shadowmaps::SubFrustumProjection(perspective, 1.0, 10.0), Aabb{ glm::dvec3(-50.0), glm::dvec3(-40.0) }, { 0.2, 0.3, -1.0 }, view },
  };
  for (const auto& c : cases)
  {
    EXPECT_TRUE(shadowmaps::IsFinite(c.sub) || std::string(c.name) == "singular projection") << c.name;
    for (int resolution : { 1, 16, 2048 })
    {
      const LightView stable = shadowmaps::FitCascadeStable(c.view, c.sub, c.scene, c.light, resolution);
      EXPECT_TRUE(AllFinite(stable)) << c.name << " " << resolution;
      EXPECT_GT(stable.TexelConstant, 0.0) << c.name;
    }
    if (shadowmaps::IsFinite(c.view))
    {
      const LightView tight = shadowmaps::FitCascadeTight(c.view, c.sub, c.scene, c.light, Resolution);
      EXPECT_TRUE(shadowmaps::IsFinite(tight.ViewProjection())) << c.name;
    }
  }
}

// ---------------------------------------------------------------------------
// The depth range each cascade's map covers (the shader's selection and blend
// are tested through the shader: ShadowReceiverSelection, ShadowCascades).

TEST(ShadowMapCascades, CascadeMapsCoverThePreviousBlendBand)
{
  const std::vector<double> splits = { 1.0, 4.0, 10.0, 40.0, 100.0 };
  EXPECT_EQ(shadowmaps::BlendBandStart(splits, 1, 0.25), 8.5);
  // The range a cascade must cover includes the previous cascade's blend band.
  EXPECT_EQ(shadowmaps::CascadeDepthRange(splits, 0, 0.25), glm::dvec2(1.0, 4.0));
  EXPECT_EQ(shadowmaps::CascadeDepthRange(splits, 2, 0.25), glm::dvec2(8.5, 40.0));
  EXPECT_EQ(shadowmaps::CascadeDepthRange(splits, 2, 0.0), glm::dvec2(10.0, 40.0));
  EXPECT_EQ(shadowmaps::CascadeDepthRange(splits, 4, 0.25), glm::dvec2(0.0, 0.0));
}

} // namespace

TEST(ShadowMapCascades, QuantizedDepthRangeRoundsOutToTheGrid)
{
  const double step = std::exp2(0.25);
  const glm::dvec2 range(3.0, 37.0);
  const glm::dvec2 q = shadowmaps::QuantizedDepthRange(range, 4);
  EXPECT_LE(q.x, range.x);
  EXPECT_GT(q.x * step, range.x);
  EXPECT_GE(q.y, range.y);
  EXPECT_LT(q.y, range.y * step);
  for (double level : { q.x, q.y })
  {
    const double k = 4.0 * std::log2(level);
    EXPECT_NEAR(k, std::round(k), 1e-9) << level << " is on the grid";
  }
  // Every range inside one cell gives the same result: small moves change nothing.
  EXPECT_EQ(shadowmaps::QuantizedDepthRange({ 3.05, 36.2 }, 4), q);
  // Ranges already on levels stay.
  EXPECT_EQ(shadowmaps::QuantizedDepthRange({ 4.0, 32.0 }, 4), glm::dvec2(4.0, 32.0));
  // Near <= 0 (parallel cameras) keeps its near; bad input comes back unchanged.
  EXPECT_EQ(shadowmaps::QuantizedDepthRange({ -2.0, 5.0 }, 4).x, -2.0);
  EXPECT_EQ(shadowmaps::QuantizedDepthRange({ 5.0, 2.0 }, 4), glm::dvec2(5.0, 2.0));
  EXPECT_EQ(shadowmaps::QuantizedDepthRange({ 1.0, 2.0 }, 0), glm::dvec2(1.0, 2.0));
  const double nan = std::nan("");
  EXPECT_TRUE(std::isnan(shadowmaps::QuantizedDepthRange({ nan, 2.0 }, 4).x));
}
