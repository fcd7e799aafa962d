// Unit tests: The focused fits of Plugin/Math/ShadowMapFocusing: near and far from the scene, the light frame, the directional and spot fits.
#include "FocusingTestHelpers.h"

using namespace focusingtest;

namespace
{
// ---------------------------------------------------------------------------
// VisibleDepthRange

// The range by definition: every box clipped to the frustum.
glm::dvec2 ClippedDepthRange(
  const glm::dmat4& view, const glm::dmat4& projection, const std::vector<Aabb>& boxes)
{
  double nearest = std::numeric_limits<double>::infinity();
  double farthest = -nearest;
  for (const Aabb& box : boxes)
  {
    for (const glm::dvec3& p : shadowmaps::IntersectFrustumWithBox(projection * view, box))
    {
      const double depth = -(view * glm::dvec4(p, 1.0)).z;
      nearest = std::min(nearest, depth);
      farthest = std::max(farthest, depth);
    }
  }
  return farthest >= nearest ? glm::dvec2(nearest, farthest) : glm::dvec2(0.0);
}

// Which boxes it clips is a shortcut (those wholly in view or out of it are
// not, nor those that cannot widen the range): the range is the clipped one's.
TEST(VisibleDepthRange, IsTheRangeOfTheBoxesClippedToTheFrustum)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> position(-60.0, 60.0);
  std::uniform_real_distribution<double> size(0.1, 12.0);
  const glm::dmat4 view =
    glm::lookAt(glm::dvec3(-40.0, -50.0, 25.0), glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 1.0));
  const glm::dmat4 projections[] = { glm::perspective(0.6, 16.0 / 9.0, 2.0, 150.0),
    glm::ortho(-30.0, 30.0, -20.0, 20.0, 5.0, 120.0) };
  for (const glm::dmat4& projection : projections)
  {
    for (int scene = 0; scene < 20; ++scene)
    {
      std::vector<Aabb> boxes;
      for (int i = 0; i < 200; ++i)
      {
        const glm::dvec3 corner(position(random), position(random), position(random) * 0.3);
        boxes.push_back(
          MakeBox(corner, corner + glm::dvec3(size(random), size(random), size(random))));
      }
      const glm::dvec2 expected = ClippedDepthRange(view, projection, boxes);
      const glm::dvec2 range = shadowmaps::VisibleDepthRange(view, projection, boxes);
      ASSERT_GT(expected.y, expected.x);
      EXPECT_NEAR(range.x, expected.x, 1e-9 * expected.y) << "scene " << scene;
      EXPECT_NEAR(range.y, expected.y, 1e-9 * expected.y) << "scene " << scene;
    }
  }
  // Nothing in view: no range.
  const std::vector<Aabb> behind{ MakeBox(glm::dvec3(-60.0, -80.0, 30.0), glm::dvec3(-55.0, -75.0, 35.0)) };
  EXPECT_EQ(shadowmaps::VisibleDepthRange(view, projections[0], behind), glm::dvec2(0.0));
}

// ---------------------------------------------------------------------------
// ComputeNearAndFar

TEST(ComputeNearAndFar, AxisAlignedLightOverABox)
{
  // Light at height 100 looking straight down: depth = 100 - z.
  const glm::dmat4 view =
    glm::lookAt(glm::dvec3(0.0, 0.0, 100.0), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  const Aabb box = MakeBox(glm::dvec3(-10.0, -10.0, 0.0), glm::dvec3(10.0, 10.0, 5.0));

  const glm::dvec2 whole =
    shadowmaps::ComputeNearAndFar(view, glm::dvec2(-20.0), glm::dvec2(20.0), box);
  EXPECT_NEAR(whole.x, 95.0, 1e-12);
  EXPECT_NEAR(whole.y, 100.0, 1e-12);

  // A slab covering part of the box sees the same depths.
  const glm::dvec2 part =
    shadowmaps::ComputeNearAndFar(view, glm::dvec2(-3.0, 8.0), glm::dvec2(2.0, 30.0), box);
  EXPECT_NEAR(part.x, 95.0, 1e-12);
  EXPECT_NEAR(part.y, 100.0, 1e-12);
}

TEST(ComputeNearAndFar, SidePlanesCutTheBox)
{
  // Light travelling along (1, 0, -1)/sqrt2 from (-10, 0, 10). In light space
  // x = (px + pz)/sqrt2, y = py, depth = (px - pz + 20)/sqrt2, so the cube
  // [-1, 1]^3 is a diamond in (x, depth) with vertices at x = +-sqrt2 (depth
  // 20/sqrt2) and x = 0 (depths 18/sqrt2 and 22/sqrt2).
  const glm::dvec3 eye(-10.0, 0.0, 10.0);
  const glm::dvec3 direction = glm::normalize(glm::dvec3(1.0, 0.0, -1.0));
  const glm::dmat4 view = glm::lookAt(eye, eye + direction, glm::dvec3(0.0, 1.0, 0.0));
  const Aabb cube = MakeBox(glm::dvec3(-1.0), glm::dvec3(1.0));
  const double s = std::sqrt(2.0);

  const glm::dvec2 whole =
    shadowmaps::ComputeNearAndFar(view, glm::dvec2(-5.0), glm::dvec2(5.0), cube);
  EXPECT_NEAR(whole.x, 18.0 / s, 1e-12);
  EXPECT_NEAR(whole.y, 22.0 / s, 1e-12);

  // x in [sqrt2/2, sqrt2]: the diamond's edges give depths 19/sqrt2 .. 21/sqrt2.
  const glm::dvec2 right =
    shadowmaps::ComputeNearAndFar(view, glm::dvec2(s / 2.0, -5.0), glm::dvec2(5.0, 5.0), cube);
  EXPECT_NEAR(right.x, 19.0 / s, 1e-12);
  EXPECT_NEAR(right.y, 21.0 / s, 1e-12);

  // x in [-sqrt2, -3 sqrt2/4], also cut in y (which does not change depth).
  const glm::dvec2 left =
    shadowmaps::ComputeNearAndFar(view, glm::dvec2(-5.0, -0.5), glm::dvec2(-0.75 * s, 0.25), cube);
  EXPECT_NEAR(left.x, 19.5 / s, 1e-12);
  EXPECT_NEAR(left.y, 20.5 / s, 1e-12);
}

TEST(ComputeNearAndFar, SlabMissingTheBoxGivesZero)
{
  const glm::dmat4 view =
    glm::lookAt(glm::dvec3(0.0, 0.0, 100.0), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  const Aabb box = MakeBox(glm::dvec3(-10.0, -10.0, 0.0), glm::dvec3(10.0, 10.0, 5.0));
  EXPECT_EQ(shadowmaps::ComputeNearAndFar(view, glm::dvec2(11.0, -5.0), glm::dvec2(20.0, 5.0), box),
    glm::dvec2(0.0));
  EXPECT_EQ(
    shadowmaps::ComputeNearAndFar(view, glm::dvec2(-5.0, -30.0), glm::dvec2(5.0, -10.5), box),
    glm::dvec2(0.0));
  EXPECT_EQ(shadowmaps::ComputeNearAndFar(view, glm::dvec2(-5.0), glm::dvec2(5.0), Aabb{}),
    glm::dvec2(0.0));
}
// ---------------------------------------------------------------------------
// LightLookAt, FitDirectional

TEST(LightLookAt, LooksAlongTheDirectionForAnyDirection)
{
  const glm::dvec3 eye(1.0, -2.0, 3.0);
  for (const glm::dvec3 d : { glm::dvec3(0.0, 0.0, -1.0),
         glm::dvec3(0.0, 0.0, 1.0),
         glm::dvec3(1.0, 0.0, 0.0),
         glm::dvec3(0.3, -0.2, -0.9),
         glm::dvec3(0.0, 0.1, 5.0) })
  {
    const glm::dmat4 view = shadowmaps::LightLookAt(eye, d);
    ASSERT_TRUE(shadowmaps::IsFinite(view));
    const glm::dvec3 ahead = TransformPoint(view, eye + 2.0 * glm::normalize(d));
    EXPECT_NEAR(ahead.x, 0.0, 1e-12);
    EXPECT_NEAR(ahead.y, 0.0, 1e-12);
    EXPECT_NEAR(ahead.z, -2.0, 1e-12);
  }
}

TEST(FitDirectional, GroundSceneBodyInsideAndCastersNotCut)
{
  const GroundScene ground;
  for (const auto& camera : { ground.Camera(), AerialCamera() })
  {
    for (const auto& direction : TestLightDirections(ground.ViewDirection()))
    {
      SCOPED_TRACE("light direction " + ToString(direction));
      CheckDirectionalFit(camera, ground.Scene, direction);
    }
  }
}

TEST(FitDirectional, FocusesOnTheBody)
{
  // The ortho x/y range hugs B: B's light-space extent fills the map up to the
  // few-texel margin.
  const GroundScene ground;
  for (const auto& direction : TestLightDirections(ground.ViewDirection()))
  {
    SCOPED_TRACE("light direction " + ToString(direction));
    const LightView fit =
      shadowmaps::FitDirectional(ground.Camera(), ground.Scene, direction, Resolution);
    Aabb ndcBounds;
    for (const auto& p : shadowmaps::IntersectFrustumWithBox(ground.Camera(), ground.Scene))
    {
      ndcBounds.Add(TransformPoint(fit.ViewProjection(), p));
    }
    EXPECT_LT(ndcBounds.Min.x, -0.98);
    EXPECT_GT(ndcBounds.Max.x, 0.98);
    EXPECT_LT(ndcBounds.Min.y, -0.98);
    EXPECT_GT(ndcBounds.Max.y, 0.98);
    // One texel is the map's width over the resolution.
    const double width = 2.0 / fit.Projection[0][0];
    EXPECT_NEAR(
      fit.TexelConstant * Resolution, std::max(width, 2.0 / fit.Projection[1][1]), 1e-9 * width);
  }
}

// A stable fit holds what the loose one holds (CheckDirectionalFit), is at most
// an eighth wider per axis, and stays the same matrix while the camera turns a
// little, so that the pass keeps its map.
TEST(FitDirectional, StableFitsStayPutForSmallCameraMoves)
{
  const GroundScene ground;
  const glm::dvec3 aside = glm::normalize(glm::dvec3(1.0, 0.4, -0.6));
  for (const auto& direction : TestLightDirections(ground.ViewDirection()))
  {
    SCOPED_TRACE("light direction " + ToString(direction));
    const LightView loose =
      shadowmaps::FitDirectional(ground.Camera(), ground.Scene, direction, Resolution);
    const LightView stable =
      shadowmaps::FitDirectional(ground.Camera(), ground.Scene, direction, Resolution, true);
    EXPECT_LE(2.0 / stable.Projection[0][0], 1.125 * 2.0 / loose.Projection[0][0] + 1e-9);
    EXPECT_GE(2.0 / stable.Projection[0][0], 2.0 / loose.Projection[0][0] - 1e-9);
    int unchanged = 0;
    for (int step = 1; step <= 10; ++step)
    {
      const glm::dvec3 target = ground.Target + aside * (0.002 * step);
      const glm::dmat4 camera =
        PerspectiveCamera(ground.Eye, target, ground.Near, ground.Far);
      const LightView moved =
        shadowmaps::FitDirectional(camera, ground.Scene, direction, Resolution, true);
      unchanged += moved.Projection == stable.Projection && moved.View == stable.View ? 1 : 0;
    }
    EXPECT_GE(unchanged, 5) << "most small moves keep the map";
    CheckDirectionalFit(ground.Camera(), ground.Scene, direction, true);
  }
}

TEST(FitDirectional, CameraLookingAwayFallsBackToTheScene)
{
  const GroundScene ground;
  // Looking up into the sky from above the scene: B is empty.
  const glm::dmat4 camera =
    PerspectiveCamera(glm::dvec3(0.0, 0.0, 50.0), glm::dvec3(0.0, 1.0, 100.0), 0.1, 100.0);
  ASSERT_TRUE(shadowmaps::IntersectFrustumWithBox(camera, ground.Scene).empty());
  const LightView fit =
    shadowmaps::FitDirectional(camera, ground.Scene, glm::dvec3(0.2, 0.1, -1.0), Resolution);
  ASSERT_TRUE(IsFiniteFit(fit));
  for (const auto& p : ground.Scene.Corners())
  {
    EXPECT_TRUE(InsideClipVolume(fit.ViewProjection(), p));
  }
}

TEST(FitDirectional, SceneScalesFrom1em4To1e5)
{
  for (const double scale : { 1e-4, 1e5 })
  {
    SCOPED_TRACE("scale " + std::to_string(scale));
    const GroundScene ground(scale);
    for (const auto& camera : { ground.Camera(), AerialCamera(scale) })
    {
      for (const auto& direction : TestLightDirections(ground.ViewDirection()))
      {
        SCOPED_TRACE("light direction " + ToString(direction));
        CheckDirectionalFit(camera, ground.Scene, direction);
      }
    }
  }
}

TEST(FitDirectional, ParallelProjectionCamera)
{
  const GroundScene ground;
  const glm::dmat4 camera =
    ParallelCamera(glm::dvec3(-100.0, -150.0, 80.0), glm::dvec3(0.0), 60.0, 1.0, 400.0);
  for (const auto& direction :
    TestLightDirections(glm::normalize(-glm::dvec3(-100.0, -150.0, 80.0))))
  {
    SCOPED_TRACE("light direction " + ToString(direction));
    CheckDirectionalFit(camera, ground.Scene, direction);
  }
}
// ---------------------------------------------------------------------------
// FitSpot

TEST(FitSpot, BodyInsideTheConeIsInsideTheClipVolume)
{
  const GroundScene ground;
  struct Spot
  {
    glm::dvec3 Position;
    glm::dvec3 Direction;
    double HalfAngle;
  };
  const std::vector<Spot> spots = {
    { { 50.0, -50.0, 80.0 }, { -50.0, 50.0, -80.0 }, 40.0 },
    { { 0.0, -150.0, 30.0 }, { 0.0, 1.0, -0.4 }, 25.0 },
    { { 0.0, -100.0, 200.0 }, { 0.0, 0.0, -1.0 }, 70.0 },
    { { 0.0, 100.0, 20.0 }, { 0.0, -1.0, -0.2 }, 10.0 }, // facing the viewer
  };
  for (const auto& camera : { ground.Camera(), AerialCamera() })
  {
    const auto body = shadowmaps::IntersectFrustumWithBox(camera, ground.Scene);
    ASSERT_FALSE(body.empty());
    for (const auto& spot : spots)
    {
      SCOPED_TRACE("spot at " + ToString(spot.Position));
      const LightView fit = shadowmaps::FitSpot(
        camera, ground.Scene, spot.Position, spot.Direction, spot.HalfAngle, Resolution);
      ASSERT_TRUE(IsFiniteFit(fit));
      EXPECT_TRUE(fit.Perspective);
      const glm::dvec3 axis = glm::normalize(spot.Direction);
      const double cosHalfAngle = std::cos(glm::radians(spot.HalfAngle));
      int inCone = 0;
      for (const auto& p : body)
      {
        const glm::dvec3 toPoint = glm::normalize(p - spot.Position);
        if (glm::dot(toPoint, axis) < cosHalfAngle)
        {
          continue;
        }
        ++inCone;
        EXPECT_TRUE(InsideClipVolume(fit.ViewProjection(), p));
      }
      // Scene points inside the cone that are part of B by sampling as well.
      std::mt19937 random(3);
      const auto planes = shadowmaps::FrustumPlanes(camera);
      for (int n = 0; n < 5000; ++n)
      {
        const glm::dvec3 p = RandomPointInBox(random, ground.Scene);
        if (!InsidePlanes(planes, p, 0.0) ||
          glm::dot(glm::normalize(p - spot.Position), axis) < cosHalfAngle)
        {
          continue;
        }
        ++inCone;
        EXPECT_TRUE(InsideClipVolume(fit.ViewProjection(), p));
      }
      EXPECT_GT(inCone, 0);
    }
  }
}

TEST(FitSpot, NearPlaneAtTheNearestScenePointInTheCone)
{
  const Aabb scene{ glm::dvec3(-10.0, -10.0, 0.0), glm::dvec3(10.0, 10.0, 2.5) };
  const glm::dvec3 position(5.0, -2.0, 7.0);
  const glm::dmat4 camera = glm::perspective(glm::radians(30.0), 1.0, 0.1, 40.0) *
    glm::lookAt(glm::dvec3(0, -9.5, 1.2), glm::dvec3(0, 0, 0.8), glm::dvec3(0, 0, 1));
  for (const glm::dvec3& direction : { glm::dvec3(0.0, 0.0, -1.0), glm::normalize(-position) })
  {
    const LightView fit = shadowmaps::FitSpot(camera, scene, position, direction, 30.0, 1024);
    const glm::dvec4 nearCentre = glm::inverse(fit.Projection) * glm::dvec4(0.0, 0.0, -1.0, 1.0);
    const double zNear = -nearCentre.z / nearCentre.w;
    // Brute force: the nearest of many scene points inside the map's frustum.
    const glm::dmat4 clip = fit.ViewProjection();
    double nearest = 1e300;
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j)
        for (int k = 0; k <= 10; ++k)
        {
          const glm::dvec3 p(-10.0 + 0.5 * i, -10.0 + 0.5 * j, 0.25 * k);
          const glm::dvec4 q = clip * glm::dvec4(p, 1.0);
          if (q.w > 0.0 && std::abs(q.x) <= q.w && std::abs(q.y) <= q.w)
          {
            nearest = std::min(nearest, -(fit.View * glm::dvec4(p, 1.0)).z);
          }
        }
    EXPECT_LE(zNear, nearest);
    EXPECT_GT(zNear, 0.9 * nearest) << "near plane far in front of the scene";
  }
}

// Tiles of one map: every point of the map lies in the core of exactly one
// tile, at the place the whole map's coordinates predict, with the same depth;
// texel sizes scale with the tile's share of the window.
// ---------------------------------------------------------------------------
// TileOfWholeImage, WholeImageProjection

TEST(WholeImageProjection, TilesOfARendererGiveBackTheWholeProjection)
{
  // A renderer on the right half of the window; the window renders its
  // top-right quarter (a 2 x 2 tiling): the renderer's upper half.
  const glm::dvec4 tile =
    shadowmaps::TileOfWholeImage(glm::dvec4(0.5, 0.5, 1.0, 1.0), glm::dvec4(0.5, 0.0, 1.0, 1.0));
  EXPECT_EQ(tile, glm::dvec4(-1.0, 0.0, 1.0, 1.0));
  EXPECT_EQ(shadowmaps::TileOfWholeImage(glm::dvec4(0.0, 0.0, 1.0, 1.0), glm::dvec4(0.5, 0.0, 1.0, 1.0)),
    glm::dvec4(-1.0, -1.0, 1.0, 1.0));
  // A tile the renderer does not reach: the whole.
  EXPECT_EQ(shadowmaps::TileOfWholeImage(glm::dvec4(0.0, 0.0, 0.5, 0.5), glm::dvec4(0.5, 0.0, 1.0, 1.0)),
    glm::dvec4(-1.0, -1.0, 1.0, 1.0));

  // The tile's projection, as a camera narrowed onto that part would have it.
  const glm::dmat4 whole = glm::perspective(glm::radians(40.0), 1.5, 0.5, 80.0);
  const glm::dmat4 tileProjection = glm::frustum(-0.5 * std::tan(glm::radians(20.0)) * 1.5,
    0.5 * std::tan(glm::radians(20.0)) * 1.5, 0.0, 0.5 * std::tan(glm::radians(20.0)), 0.5, 80.0);
  const glm::dmat4 back = shadowmaps::WholeImageProjection(tileProjection, tile);
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      EXPECT_NEAR(back[c][r], whole[c][r], 1e-12) << c << ", " << r;
    }
  }
}

} // namespace
