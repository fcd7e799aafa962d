// Unit tests for the perspective shadow map math (Plugin/ShadowMapPerspective.{h,cxx}).
#include "ShadowMapMotion.h"
#include "ShadowMapPerspective.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace
{
using shadowmaps::Aabb;
using shadowmaps::testing::WarpTestGround;
using shadowmaps::PerspectiveMap;
using shadowmaps::PsmLightKind;

constexpr double ClipTolerance = 1e-9;

const glm::dvec3 Eye(0.0, -45.0, 5.0);
const glm::dvec3 Target(0.0, 0.0, 5.0); // looks along +y

glm::dmat4 CameraView()
{
  return glm::lookAt(Eye, Target, glm::dvec3(0.0, 0.0, 1.0));
}

glm::dmat4 CameraProjection(bool parallel = false)
{
  return parallel ? glm::ortho(-15.0, 15.0, -10.0, 10.0, 0.5, 80.0)
                  : glm::perspective(glm::radians(45.0), 1.5, 0.5, 80.0);
}

void ExpectBodyInsideMap(const PerspectiveMap& map, const glm::dmat4& camera)
{
  const glm::dmat4 vp = map.Light.ViewProjection();
  ASSERT_TRUE(shadowmaps::IsFinite(vp));
  const auto body = shadowmaps::IntersectFrustumWithBox(camera, WarpTestGround());
  ASSERT_FALSE(body.empty());
  for (const auto& p : body)
  {
    const glm::dvec4 clip = vp * glm::dvec4(p, 1.0);
    EXPECT_GT(clip.w, 0.0);
    EXPECT_LE(std::abs(clip.x / clip.w), 1.0 + ClipTolerance);
    EXPECT_LE(std::abs(clip.y / clip.w), 1.0 + ClipTolerance);
    EXPECT_LE(std::abs(clip.z / clip.w), 1.0 + ClipTolerance);
  }
}

double Depth01(const glm::dmat4& m, const glm::dvec4& p)
{
  const glm::dvec4 clip = m * p;
  return 0.5 * clip.z / clip.w + 0.5;
}

} // namespace

TEST(PerspectivePSM, InverseProjectionDepthFollowsTheThesisFormula)
{
  const double a = 0.25;
  const glm::dmat4 m = shadowmaps::InverseProjection({ -1.0, -1.0 }, { 1.0, 1.0 }, a);
  // Light-view space looks down -z: Z = -z.
  const auto depthAt = [&](double z) { return Depth01(m, glm::dvec4(0.0, 0.0, -z, 1.0)); };
  EXPECT_NEAR(depthAt(-a), 0.0, 1e-15);
  EXPECT_NEAR(depthAt(a), 1.0, 1e-15);
  EXPECT_NEAR(depthAt(-1e15), 0.5, 1e-12);
  EXPECT_NEAR(depthAt(1e15), 0.5, 1e-12);
  // Points at infinity (w = 0) on either side: exactly 1/2.
  EXPECT_NEAR(Depth01(m, glm::dvec4(0.0, 0.0, -1.0, 0.0)), 0.5, 1e-15);
  EXPECT_NEAR(Depth01(m, glm::dvec4(0.0, 0.0, 1.0, 0.0)), 0.5, 1e-15);
  for (double z : { -3.0, -0.5, 0.4, 7.0 })
  {
    EXPECT_NEAR(depthAt(z), 0.5 * (1.0 + a / z), 1e-15);
  }
}

TEST(PerspectivePSM, InverseLightKeepsDepthOrderThroughTheInfinityPlane)
{
  // Light behind the viewer, shining forward and down: a ray from a caster
  // behind the camera through the camera plane (the infinity plane of
  // post-perspective space) into the view frustum.
  const glm::dvec3 light = glm::normalize(glm::dvec3(0.1, 1.0, -0.35));
  const PerspectiveMap map =
    shadowmaps::FitPerspective(CameraView(), CameraProjection(), WarpTestGround(), light, 2048);
  ASSERT_EQ(map.Kind, PsmLightKind::Inverse);
  EXPECT_GT(map.InverseNear, 0.0);
  const glm::dmat4 vp = map.Light.ViewProjection();
  const glm::dvec3 receiver(0.5, -30.0, 0.0); // in the frustum, on the ground
  double previous = -1.0;
  int crossed = 0;
  // From far behind the camera toward the receiver, in the light's travel order.
  for (double t = 40.0; t >= 0.0; t -= 0.25)
  {
    const glm::dvec3 p = receiver - light * t;
    const glm::dvec4 clip = vp * glm::dvec4(p, 1.0);
    if (!(std::abs(clip.z) <= clip.w)) // outside the depth range (|Z| < a): skipped
    {
      continue;
    }
    crossed += (CameraView() * glm::dvec4(p, 1.0)).z > 0.0 ? 1 : 0; // behind the viewer
    const double depth = 0.5 * clip.z / clip.w + 0.5;
    EXPECT_GT(clip.w, 0.0) << t;
    EXPECT_GT(depth, previous) << t;
    previous = depth;
  }
  EXPECT_GT(crossed, 10); // the ray really came from behind the viewer
}

TEST(PerspectivePSM, BodyMapsInsideForLightsInFrontPerpendicularAndBehind)
{
  const glm::dmat4 camera = CameraProjection() * CameraView();
  struct Case
  {
    glm::dvec3 Light;
    PsmLightKind Kind;
  };
  const Case cases[] = {
    { { 0.2, -1.0, -0.5 }, PsmLightKind::Point },     // toward the viewer: light in front
    { { 0.0, 0.0, -1.0 }, PsmLightKind::Directional }, // straight down: perpendicular
    { { 0.3, 0.0, -1.0 }, PsmLightKind::Directional },
    { { 0.1, 1.0, -0.35 }, PsmLightKind::Inverse },    // from behind the viewer
    { { -0.5, 0.7, -0.6 }, PsmLightKind::Inverse },
  };
  for (const auto& c : cases)
  {
    for (double slideBack : { 0.0, 5.0 })
    {
      const PerspectiveMap map =
        shadowmaps::FitPerspective(CameraView(), CameraProjection(), WarpTestGround(), c.Light, 2048, slideBack);
      EXPECT_EQ(map.Kind, c.Kind);
      EXPECT_TRUE(map.Light.Perspective);
      EXPECT_GT(map.Light.TexelConstant, 0.0);
      ExpectBodyInsideMap(map, camera);
    }
  }
}

TEST(PerspectivePSM, SlideBackKeepsTheNearPlaneQuad)
{
  const glm::dmat4 real = CameraProjection() * CameraView();
  const glm::dmat4 slid = shadowmaps::SlideBackPostPerspective(CameraView(), CameraProjection(), 5.0);
  for (const auto& ndc : { glm::dvec3(-1, -1, -1), glm::dvec3(1, -1, -1), glm::dvec3(1, 1, -1), glm::dvec3(-1, 1, -1) })
  {
    const glm::dvec4 w = glm::inverse(real) * glm::dvec4(ndc, 1.0);
    const glm::dvec4 q = slid * (w / w.w);
    EXPECT_NEAR(q.x / q.w, ndc.x, 1e-12);
    EXPECT_NEAR(q.y / q.w, ndc.y, 1e-12);
    EXPECT_NEAR(q.z / q.w, -1.0, 1e-12);
  }
}

TEST(PerspectivePSM, NoNaNForLightAlongAgainstViewAndParallelCameras)
{
  const glm::dvec3 view = glm::normalize(Target - Eye);
  for (bool parallel : { false, true })
  {
    const glm::dmat4 camera = CameraProjection(parallel) * CameraView();
    for (const glm::dvec3& light : { view, -view, view + glm::dvec3(0.0, 0.0, -1e-9),
           -view + glm::dvec3(1e-7, 0.0, 0.0), glm::dvec3(0.0, 0.0, -1.0), glm::dvec3(1.0, 1.0, -1.0) })
    {
      const PerspectiveMap map =
        shadowmaps::FitPerspective(CameraView(), CameraProjection(parallel), WarpTestGround(), light, 1024);
      if (parallel)
      {
        EXPECT_EQ(map.Kind, PsmLightKind::Uniform);
      }
      EXPECT_TRUE(std::isfinite(map.Light.TexelConstant));
      ExpectBodyInsideMap(map, camera);
    }
  }
}

TEST(PerspectivePSM, KozlovBiasScalesWithWorldTexelSize)
{
  const glm::dvec3 light(0.2, -1.0, -0.5);
  const PerspectiveMap map =
    shadowmaps::FitPerspective(CameraView(), CameraProjection(), WarpTestGround(), light, 2048);
  // PSM texels grow with distance from the viewer.
  const glm::dvec4 towardLight(-glm::normalize(light), 0.0);
  const double nearTexel =
    shadowmaps::WorldTexelSize(map.Light, { 0.0, -40.0, 0.0 }, towardLight, 1e-4, 2048);
  const double farTexel =
    shadowmaps::WorldTexelSize(map.Light, { 0.0, 30.0, 0.0 }, towardLight, 1e-4, 2048);
  EXPECT_GT(nearTexel, 0.0);
  EXPECT_GT(farTexel, 2.0 * nearTexel);
  const glm::dvec3 p(1.0, 2.0, 3.0);
  const glm::dvec3 biased = shadowmaps::KozlovBiasedPoint(p, light, 0.01, 2.0, farTexel);
  EXPECT_NEAR(glm::length(biased - p), 0.01 + 2.0 * farTexel, 1e-12);
  EXPECT_LT(glm::dot(biased - p, light), 0.0); // moved toward the light
}

// ---------------------------------------------------------------------------
// Continuity. The camera looks a little down the ground; fixed points are the
// midpoints of B's vertex pairs. The light turns about the camera's side axis, in
// 0.1 degree steps through the view direction (and through its opposite).

namespace
{
constexpr int MotionResolution = 2048;

glm::dmat4 TiltedCameraView()
{
  return glm::lookAt(Eye, glm::dvec3(0.0, 0.0, 3.0), glm::dvec3(0.0, 0.0, 1.0));
}

std::vector<glm::dvec3> PointsBetweenBodyVertices()
{
  const auto body =
    shadowmaps::IntersectFrustumWithBox(CameraProjection() * TiltedCameraView(), WarpTestGround());
  std::vector<glm::dvec3> points;
  for (size_t i = 0; i < body.size(); ++i)
  {
    for (size_t j = i + 1; j < body.size(); ++j)
    {
      points.push_back(0.5 * (body[i] + body[j]));
    }
  }
  return points;
}

// The largest excess move over FitDirectional's per 0.1 degree step as the light
// turns from -degrees to +degrees about the camera's side axis, `sign` giving a
// light along (+1) or against (-1) the view; the pass's slide-back and weight.
double LargestExcessMove(double degrees, double sign)
{
  const glm::dmat4 view = TiltedCameraView();
  const glm::dvec3 forward = -glm::dvec3(glm::transpose(view)[2]);
  const glm::dvec3 up = glm::normalize(glm::cross(glm::cross(forward, glm::dvec3(0.0, 0.0, 1.0)), forward));
  const double slideBack = std::sqrt(0.5 * 80.0);
  shadowmaps::testing::ExcessMotion motion(PointsBetweenBodyVertices(), MotionResolution);
  const int steps = static_cast<int>(std::lround(degrees * 10.0));
  for (int step = -steps; step <= steps; ++step)
  {
    const double t = glm::radians(0.1 * step);
    const glm::dvec3 light = sign * (std::cos(t) * forward + std::sin(t) * up);
    const PerspectiveMap map = shadowmaps::FitPerspective(view, CameraProjection(), WarpTestGround(), light,
      MotionResolution, slideBack, shadowmaps::PerspectiveWarpWeight(forward, light));
    EXPECT_TRUE(shadowmaps::IsFinite(map.Light.ViewProjection()));
    motion.Step(map.Light,
      shadowmaps::FitDirectional(CameraProjection() * view, WarpTestGround(), light, MotionResolution));
  }
  return motion.Worst();
}
} // namespace

// The property: through the degenerate angle no point moves more than 2
// texels per step beyond the uniform map's own move. The map before the fade
// (21b0cfb) moved 29 texels per step here.
TEST(PerspectivePSM, MapMovesContinuouslyThroughTheViewAxis)
{
  for (double sign : { 1.0, -1.0 })
  {
    const double excess = LargestExcessMove(2.0, sign);
    std::printf("[ continuity ] PSM, light %s the view, +-2 deg: largest excess %.4f texels\n",
      sign > 0 ? "along  " : "against", excess);
    EXPECT_LT(excess, 2.0);
  }
}

// Through the fade band (2 to 20 degrees) and beyond, the map moves with the
// light but never pops: no step moves a point by 5% of the map beyond the uniform
// map's move. Before the fade and the continuous light camera (21b0cfb), one step
// moved a point by 2040 texels here.
TEST(PerspectivePSM, WarpFadesInWithoutPopping)
{
  for (double sign : { 1.0, -1.0 })
  {
    const double excess = LargestExcessMove(30.0, sign);
    std::printf("[ fade-in  ] PSM, light %s the view, +-30 deg: largest excess %.2f texels\n",
      sign > 0 ? "along  " : "against", excess);
    EXPECT_LT(excess, 0.05 * MotionResolution);
  }
}

// As the weight goes to 0 the map becomes FitDirectional's; at 0 it is that map.
TEST(PerspectivePSM, ConvergesToTheUniformMapAsTheWeightGoesToZero)
{
  const glm::dmat4 camera = CameraProjection() * TiltedCameraView();
  const std::vector<glm::dvec3> points = PointsBetweenBodyVertices();
  for (const glm::dvec3& towardLight : { glm::dvec3(0.1, 1.0, -0.2), glm::dvec3(0.05, -1.0, -0.1),
         glm::dvec3(0.3, -1.0, -0.4) })
  {
    const glm::dvec3 light = glm::normalize(towardLight);
    const shadowmaps::LightView uniform =
      shadowmaps::FitDirectional(camera, WarpTestGround(), light, MotionResolution);
    double previous = INFINITY;
    for (double weight : { 1e-2, 1e-4, 1e-6, 1e-8 })
    {
      const PerspectiveMap map = shadowmaps::FitPerspective(
        TiltedCameraView(), CameraProjection(), WarpTestGround(), light, MotionResolution, 6.0, weight);
      double farthest = 0.0;
      for (const auto& p : points)
      {
        farthest = std::max(farthest,
          glm::length(shadowmaps::testing::MapTexels(map.Light, p, MotionResolution) -
            shadowmaps::testing::MapTexels(uniform, p, MotionResolution)));
      }
      EXPECT_LT(farthest, previous) << "weight " << weight;
      previous = farthest;
    }
    EXPECT_LT(previous, 0.01) << "texels from the uniform map at weight 1e-8";
    const PerspectiveMap atZero = shadowmaps::FitPerspective(
      TiltedCameraView(), CameraProjection(), WarpTestGround(), light, MotionResolution, 6.0, 0.0);
    EXPECT_EQ(atZero.Kind, PsmLightKind::Uniform);
    EXPECT_EQ(atZero.Light.ViewProjection(), uniform.ViewProjection());
  }
}

// ---------------------------------------------------------------------------
// Spot lights (FitSpotPerspective). The spot swings, 16 units from a ground point
// 8 units ahead of the camera, through the camera's axis: behind the camera
// shining forward, or ahead of it shining back.

namespace
{
struct SpotSwing
{
  glm::dvec3 Eye{ 0.0, -9.5, 1.2 };
  glm::dvec3 View = glm::normalize(glm::dvec3(0.0, 9.5, -0.4));
  glm::dmat4 CameraView = glm::lookAt(Eye, Eye + View, glm::dvec3(0.0, 0.0, 1.0));
  glm::dmat4 Projection = glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.1, 40.0);
  Aabb Scene{ glm::dvec3(-10.0, -10.0, -0.1), glm::dvec3(10.0, 10.0, 2.5) };
  glm::dvec3 Centre = Eye + View * 8.0;

  std::vector<glm::dvec3> GroundPoints() const
  {
    const glm::dvec3 side = glm::normalize(glm::cross(View, glm::dvec3(0.0, 0.0, 1.0)));
    std::vector<glm::dvec3> points;
    for (double x : { -1.5, 0.0, 1.5 })
    {
      for (double y : { -3.0, 0.0, 3.0 })
      {
        points.push_back(glm::dvec3(Centre.x, Centre.y, 0.0) + side * x + glm::dvec3(0.0, y, 0.0));
      }
    }
    return points;
  }
};
} // namespace

TEST(PerspectivePSM, SpotWarpFadesInWithoutPopping)
{
  const SpotSwing swing;
  const glm::dvec3 side = glm::normalize(glm::cross(swing.View, glm::dvec3(0.0, 0.0, 1.0)));
  const glm::dvec3 up = glm::cross(side, swing.View);
  for (double facing : { 1.0, -1.0 })
  {
    for (const glm::dvec3& across : { up, side })
    {
      shadowmaps::testing::ExcessMotion motion(swing.GroundPoints(), MotionResolution);
      for (int step = -300; step <= 300; ++step)
      {
        const double t = glm::radians(0.1 * step);
        const glm::dvec3 ray = facing * (std::cos(t) * swing.View + std::sin(t) * across);
        const glm::dvec3 spot = swing.Centre - ray * 16.0;
        const PerspectiveMap map = shadowmaps::FitSpotPerspective(swing.CameraView, swing.Projection,
          swing.Scene, spot, ray, 40.0, MotionResolution, 2.0,
          shadowmaps::PerspectiveWarpWeight(swing.View, ray));
        ASSERT_TRUE(shadowmaps::IsFinite(map.Light.ViewProjection()));
        motion.Step(map.Light, shadowmaps::FitSpot(swing.Projection * swing.CameraView, swing.Scene,
                                 spot, ray, 40.0, MotionResolution));
      }
      std::printf("[ fade-in  ] spot PSM %s, turning %s, +-30 deg: largest excess %.2f texels\n",
        facing > 0 ? "behind the camera" : "facing it        ", across == up ? "up  " : "side",
        motion.Worst());
      EXPECT_LT(motion.Worst(), 0.05 * MotionResolution);
    }
  }
}

// The uniform map of a spot's PSM is the cone map cropped to B.
TEST(PerspectivePSM, SpotMapConvergesToTheCroppedConeMapAsTheWeightGoesToZero)
{
  const SpotSwing swing;
  const glm::dvec3 spot(5.0, -2.0, 7.0);
  const glm::dvec3 axis = glm::normalize(swing.Centre - spot);
  const glm::dmat4 camera = swing.Projection * swing.CameraView;
  const shadowmaps::LightView cone =
    shadowmaps::FitSpotToLitBody(camera, swing.Scene, spot, axis, 40.0, MotionResolution);
  const PerspectiveMap warped = shadowmaps::FitSpotPerspective(
    swing.CameraView, swing.Projection, swing.Scene, spot, axis, 40.0, MotionResolution, 2.0, 1.0);
  EXPECT_EQ(warped.Kind, PsmLightKind::Point);
  EXPECT_TRUE(warped.Light.TexelSizeFromGradient);
  double previous = INFINITY;
  for (double weight : { 1e-2, 1e-4, 1e-6 })
  {
    const PerspectiveMap map = shadowmaps::FitSpotPerspective(swing.CameraView, swing.Projection,
      swing.Scene, spot, axis, 40.0, MotionResolution, 2.0, weight);
    double farthest = 0.0;
    for (const auto& p : swing.GroundPoints())
    {
      farthest = std::max(farthest,
        glm::length(shadowmaps::testing::MapTexels(map.Light, p, MotionResolution) -
          shadowmaps::testing::MapTexels(cone, p, MotionResolution)));
    }
    std::printf("[ limit    ] spot PSM at weight %g: %.4f texels from the cone map\n", weight, farthest);
    EXPECT_LT(farthest, previous + 0.05) << "weight " << weight;
    previous = farthest;
  }
  // The cropped cone map keeps its filter margin inside the cone, the PSM does
  // not: up to that margin (4 texels) remains at the cone's edge.
  EXPECT_LT(previous, 4.0);
  const PerspectiveMap atZero = shadowmaps::FitSpotPerspective(
    swing.CameraView, swing.Projection, swing.Scene, spot, axis, 40.0, MotionResolution, 2.0, 0.0);
  EXPECT_EQ(atZero.Kind, PsmLightKind::Uniform);
  EXPECT_EQ(atZero.Light.ViewProjection(), cone.ViewProjection());
}
