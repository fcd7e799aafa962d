// Unit tests of ShadowMapKeptViews: when a light's last view still serves a
// frame, and the widened camera a view is fitted to in interactive frames.
#include "FocusingTestHelpers.h"
#include "ShadowMapKeptViews.h"
#include "ShadowMapWarping.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace
{
using focusingtest::MakeBox;
using focusingtest::Resolution;
using shadowmaps::Aabb;
using shadowmaps::Camera;
using shadowmaps::DirectionalWarp;
using shadowmaps::LightRays;
using shadowmaps::LightView;

// A street-level camera on a 200 x 200 ground with 10-unit tall casters,
// looking along +y, turned by `degrees` about the vertical through the origin
// (an orbit about the scene's centre) from (0, -60, 3). Its near plane is where
// the ground enters the view, as the warped views' tight projection puts it.
constexpr double NearestVisible = 11.0;
Camera OrbitingCamera(double degrees)
{
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::dvec3(0.0, 0.0, 1.0));
  const glm::dvec3 eye = glm::dvec3(turn * glm::dvec4(0.0, -60.0, 3.0, 1.0));
  const glm::dvec3 target = glm::dvec3(turn * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  Camera camera;
  camera.View = glm::lookAt(eye, target, glm::dvec3(0.0, 0.0, 1.0));
  camera.Projection = glm::perspective(glm::radians(30.0), 16.0 / 9.0, NearestVisible, 300.0);
  return camera;
}

const Aabb Scene = MakeBox(glm::dvec3(-100.0, -100.0, 0.0), glm::dvec3(100.0, 100.0, 10.0));
const glm::dvec3 Sun = glm::normalize(glm::dvec3(0.6, 0.3, -1.0));

LightRays SunRays()
{
  LightRays rays;
  rays.Direction = Sun;
  return rays;
}

LightView LiSPSMFit(const Camera& camera)
{
  return shadowmaps::FitDirectionalWarped(
    camera.View, camera.Projection, Scene, Sun, Resolution, DirectionalWarp::LiSPSM);
}

bool Serves(const LightView& kept, const Camera& camera, double ratio = 1.5)
{
  return shadowmaps::KeptViewServes(kept, LiSPSMFit(camera), camera.Projection * camera.View,
    Scene, SunRays(), Resolution, ratio);
}

// A spot above the scene, aimed at its centre, and its LiSPSM fit of any cone.
LightRays SpotRays(double coneAngleDegrees)
{
  LightRays rays;
  rays.Positional = true;
  rays.Position = glm::dvec3(-20.0, -40.0, 30.0);
  rays.Direction = glm::dvec3(0.0, 0.0, 0.0) - rays.Position;
  rays.ConeAngleDegrees = coneAngleDegrees;
  return rays;
}

LightView SpotFit(const Camera& camera, double coneAngleDegrees)
{
  const LightRays rays = SpotRays(coneAngleDegrees);
  return shadowmaps::FitSpotWarped(camera.View, camera.Projection, Scene, rays.Position,
    rays.Direction, coneAngleDegrees, Resolution, DirectionalWarp::LiSPSM);
}

// `view` with its clip z remapped so that [lo, hi] of the old range becomes [-1, 1].
LightView WithDepthRange(LightView view, double lo, double hi)
{
  const glm::dmat4 remap = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -(lo + hi) / (hi - lo))) *
    glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 1.0, 2.0 / (hi - lo)));
  view.Projection = remap * view.Projection;
  return view;
}
} // namespace

TEST(ShadowMapKeptViews, AFitServesItsOwnFrame)
{
  const Camera camera = OrbitingCamera(0.0);
  const LightView fit = LiSPSMFit(camera);
  ASSERT_TRUE(fit.Perspective);
  EXPECT_TRUE(Serves(fit, camera));
}

TEST(ShadowMapKeptViews, AFitDoesNotServeACameraTurnedAway)
{
  EXPECT_FALSE(Serves(LiSPSMFit(OrbitingCamera(0.0)), OrbitingCamera(20.0)));
  EXPECT_FALSE(Serves(LiSPSMFit(OrbitingCamera(0.0)), OrbitingCamera(1.0)))
    << "a tight fit holds no moved frustum";
}

TEST(ShadowMapKeptViews, ANearPlaneThatCutsCastersDoesNotServe)
{
  const Camera camera = OrbitingCamera(0.0);
  const LightView fit = LiSPSMFit(camera);
  // The casters over what the camera sees reach a clip depth of about -0.54
  // (the fit's near plane covers a wider rectangle), its receivers -0.29.
  EXPECT_FALSE(Serves(WithDepthRange(fit, -0.45, 1.0), camera));
  EXPECT_TRUE(Serves(WithDepthRange(fit, -0.6, 1.0), camera));
  EXPECT_TRUE(Serves(WithDepthRange(fit, -1.2, 1.0), camera)) << "a deeper range holds more";
  // The fit's receivers reach a clip depth of about 0.3.
  EXPECT_FALSE(Serves(WithDepthRange(fit, -1.0, 0.2), camera)) << "a far plane that cuts receivers";
}

TEST(ShadowMapKeptViews, CoarserTexelsServeUpToTheRatio)
{
  const Camera camera = OrbitingCamera(0.0);
  LightView coarser = LiSPSMFit(camera);
  coarser.Projection = glm::scale(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 1.0)) * coarser.Projection;
  EXPECT_FALSE(Serves(coarser, camera, 1.5));
  EXPECT_FALSE(Serves(coarser, camera, 1.99));
  EXPECT_TRUE(Serves(coarser, camera, 2.01));
}

TEST(ShadowMapKeptViews, AFitToTheWidenedCameraServesAFewFramesOfAnOrbit)
{
  const Camera camera = OrbitingCamera(0.0);
  const LightView widened = LiSPSMFit(shadowmaps::WidenedCamera(camera, 0.1 * NearestVisible, 1.0));
  int served = 0;
  for (int frame = 1; frame <= 20 && Serves(widened, OrbitingCamera(0.3 * frame)); ++frame)
  {
    ++served;
  }
  EXPECT_GE(served, 3) << "frames of 0.3 degrees";
  EXPECT_LT(served, 20);
  EXPECT_TRUE(Serves(widened, camera));
}

TEST(ShadowMapKeptViews, TheWidenedCameraHoldsTurnedAndMovedCameras)
{
  const Camera camera = OrbitingCamera(0.0);
  const double backward = 1.0;
  const double degrees = 2.0;
  const Camera widened = shadowmaps::WidenedCamera(camera, backward, degrees);
  // Between the sides; the near and far planes stay where they were.
  const auto holds = [&](const Camera& other) {
    const glm::dmat4 clip = widened.Projection * widened.View;
    for (const glm::dvec3& corner : shadowmaps::FrustumCorners(other.Projection * other.View))
    {
      const glm::dvec4 c = clip * glm::dvec4(corner, 1.0);
      if (!(c.w > 0.0 && std::abs(c.x) <= c.w * (1.0 + 1e-9) && std::abs(c.y) <= c.w * (1.0 + 1e-9)))
      {
        return false;
      }
    }
    return true;
  };
  EXPECT_TRUE(holds(camera));
  // The narrower half angle is 15 degrees: sideways moves up to tan(15) * backward.
  const double sideways = 0.9 * std::tan(glm::radians(15.0)) * backward;
  for (const glm::dvec3 axis : { glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0) })
  {
    // Along the camera's own right and up.
    Camera moved = camera;
    moved.View = glm::translate(glm::dmat4(1.0), -sideways * axis) * camera.View;
    EXPECT_TRUE(holds(moved)) << "moved along " << axis.x << " " << axis.y;
    moved.View = glm::translate(glm::dmat4(1.0), -10.0 * sideways * axis) * camera.View;
    EXPECT_FALSE(holds(moved)) << "moved ten times as far along " << axis.x << " " << axis.y;
  }
  for (const glm::dvec3 axis : { glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0) })
  {
    Camera turned = camera;
    turned.View = glm::rotate(glm::dmat4(1.0), glm::radians(0.9 * degrees), axis) * camera.View;
    EXPECT_TRUE(holds(turned)) << "turned about " << axis.x << " " << axis.y;
    turned.View = glm::rotate(glm::dmat4(1.0), glm::radians(3.0 * degrees), axis) * camera.View;
    EXPECT_FALSE(holds(turned)) << "turned three times as far about " << axis.x << " " << axis.y;
  }
}

TEST(ShadowMapKeptViews, ParallelCamerasAndNoSlackAreNotWidened)
{
  Camera parallel = OrbitingCamera(0.0);
  parallel.Projection = glm::ortho(-10.0, 10.0, -5.0, 5.0, 0.5, 300.0);
  const Camera same = shadowmaps::WidenedCamera(parallel, 1.0, 2.0);
  EXPECT_EQ(same.View, parallel.View);
  EXPECT_EQ(same.Projection, parallel.Projection);
  const Camera perspective = OrbitingCamera(0.0);
  EXPECT_EQ(shadowmaps::WidenedCamera(perspective, 0.0, 2.0).Projection, perspective.Projection);
  EXPECT_EQ(shadowmaps::WidenedCamera(perspective, 1.0, 0.0).Projection, perspective.Projection);
}

TEST(ShadowMapKeptViews, ASpotFitServesItsOwnFrameAndNotANarrowerCone)
{
  const Camera camera = OrbitingCamera(0.0);
  const LightView fresh = SpotFit(camera, 40.0);
  ASSERT_TRUE(fresh.Perspective);
  const glm::dmat4 clip = camera.Projection * camera.View;
  const LightRays rays = SpotRays(40.0);
  EXPECT_TRUE(shadowmaps::KeptViewServes(fresh, fresh, clip, Scene, rays, Resolution, 1.5));
  // A view of a narrower cone misses part of what the light shines on.
  EXPECT_FALSE(
    shadowmaps::KeptViewServes(SpotFit(camera, 20.0), fresh, clip, Scene, rays, Resolution, 1.5));
}

// What a spot does not light needs no map: a view of the lit part serves the
// fit of a light whose frustum reaches beyond its cone.
TEST(ShadowMapKeptViews, ASpotViewNeedNotHoldWhatTheConeLeavesDark)
{
  const Camera camera = OrbitingCamera(0.0);
  const glm::dmat4 clip = camera.Projection * camera.View;
  const LightView lit = SpotFit(camera, 20.0);
  const LightView wider = SpotFit(camera, 40.0);
  EXPECT_TRUE(shadowmaps::KeptViewServes(lit, wider, clip, Scene, SpotRays(20.0), Resolution, 4.0))
    << "the 40 degree fit beyond a 20 degree cone holds only dark points";
  EXPECT_FALSE(shadowmaps::KeptViewServes(lit, wider, clip, Scene, SpotRays(90.0), Resolution, 4.0))
    << "unbounded, the same points must be held";
}

TEST(ShadowMapKeptViews, NonFiniteInputDoesNotServe)
{
  const Camera camera = OrbitingCamera(0.0);
  const LightView fit = LiSPSMFit(camera);
  glm::dmat4 broken = camera.Projection * camera.View;
  broken[0][0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(shadowmaps::KeptViewServes(fit, fit, broken, Scene, SunRays(), Resolution, 1.5));
  // A camera that sees none of the scene leaves nothing to compare by.
  const Camera away = { glm::lookAt(glm::dvec3(0.0, -200.0, 3.0), glm::dvec3(0.0, -300.0, 3.0),
                          glm::dvec3(0.0, 0.0, 1.0)),
    camera.Projection };
  EXPECT_FALSE(shadowmaps::KeptViewServes(
    fit, LiSPSMFit(away), away.Projection * away.View, Scene, SunRays(), Resolution, 1.5));
}

TEST(ShadowMapKeptViews, AViewMustKeepTheRoomAtItsSidesThatTheFitLeaves)
{
  const Camera camera = OrbitingCamera(0.0);
  const LightView fit = LiSPSMFit(camera);
  // The fit leaves about 4 texels at its sides, of which a kept view keeps 3:
  // pushed out by half a texel it still does, by 2 not.
  for (const double texels : { 0.5, 2.0 })
  {
    LightView squeezed = fit;
    const double scale = 1.0 + 2.0 * texels / Resolution;
    squeezed.Projection = glm::scale(glm::dmat4(1.0), glm::dvec3(scale, scale, 1.0)) * fit.Projection;
    EXPECT_EQ(Serves(squeezed, camera), texels < 1.0) << texels << " texels";
  }
  // Receivers that reach 6 texels need all the room the fit leaves.
  LightView squeezed = fit;
  const double scale = 1.0 + 2.0 * 0.75 / Resolution;
  squeezed.Projection = glm::scale(glm::dmat4(1.0), glm::dvec3(scale, scale, 1.0)) * fit.Projection;
  const glm::dmat4 clip = camera.Projection * camera.View;
  EXPECT_TRUE(shadowmaps::KeptViewServes(squeezed, fit, clip, Scene, SunRays(), Resolution, 1.5, 3.0));
  EXPECT_FALSE(shadowmaps::KeptViewServes(squeezed, fit, clip, Scene, SunRays(), Resolution, 1.5, 6.0));
}

TEST(ShadowMapKeptViews, StereoAndShearedProjectionsAreNotWidened)
{
  Camera sheared = OrbitingCamera(0.0);
  sheared.Projection[3][0] = 0.1;
  EXPECT_EQ(shadowmaps::WidenedCamera(sheared, 1.0, 2.0).Projection, sheared.Projection);
  // A projection scaled as a whole is the same frustum.
  Camera scaled = OrbitingCamera(0.0);
  scaled.Projection *= 2.0;
  const Camera widened = shadowmaps::WidenedCamera(scaled, 1.0, 2.0);
  const Camera reference = shadowmaps::WidenedCamera(OrbitingCamera(0.0), 1.0, 2.0);
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      EXPECT_NEAR(widened.Projection[c][r], reference.Projection[c][r], 1e-9) << c << " " << r;
    }
  }
}
