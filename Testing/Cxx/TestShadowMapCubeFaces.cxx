// Unit tests: The cube faces of point lights and wide spots (Plugin/Math/ShadowMapFocusing).
#include "FocusingTestHelpers.h"

using namespace focusingtest;

namespace
{
// ---------------------------------------------------------------------------
// FitCubeFaces

TEST(FitCubeFaces, FacesLookAlongTheirAxes)
{
  const glm::dvec3 position(1.0, 2.0, 3.0);
  const auto faces =
    shadowmaps::FitCubeFaces(MakeBox(glm::dvec3(-5.0), glm::dvec3(5.0)), position, Resolution);
  const glm::dvec3 axes[6] = {
    { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 }
  };
  for (int i = 0; i < 6; ++i)
  {
    ASSERT_TRUE(IsFiniteFit(faces[i]));
    EXPECT_TRUE(faces[i].Perspective);
    const glm::dvec3 ahead = TransformPoint(faces[i].View, position + axes[i]);
    EXPECT_NEAR(ahead.x, 0.0, 1e-12);
    EXPECT_NEAR(ahead.y, 0.0, 1e-12);
    EXPECT_NEAR(ahead.z, -1.0, 1e-12);
  }
}

TEST(FitCubeFaces, SceneSeenInTheDirectionsFaceIsInsideItsClipVolume)
{
  const Aabb scene = MakeBox(glm::dvec3(-10.0, -10.0, 0.0), glm::dvec3(10.0, 10.0, 5.0));
  const std::vector<glm::dvec3> positions = {
    { 1.0, 2.0, 2.5 },     // inside
    { 0.0, 0.0, 20.0 },    // above, outside along one axis
    { 30.0, -25.0, 15.0 }, // outside off a corner
    { -14.0, 3.0, 8.0 },   // outside off an edge
  };
  std::mt19937 random(5);
  for (const auto& position : positions)
  {
    SCOPED_TRACE("light at " + ToString(position));
    const auto faces = shadowmaps::FitCubeFaces(scene, position, Resolution);
    for (const auto& face : faces)
    {
      ASSERT_TRUE(IsFiniteFit(face));
    }
    int tested = 0;
    for (int n = 0; n < 20000; ++n)
    {
      const glm::dvec3 d = RandomDirection(random);
      double enter = 0.0;
      double exit = 0.0;
      if (!RayBoxInterval(position, d, scene, enter, exit))
      {
        continue;
      }
      // Distances very close to a light inside the scene fall before the near
      // plane by design (near is a small fraction of far).
      enter = std::max(enter, 0.05 * scene.Diagonal());
      if (exit < enter)
      {
        continue;
      }
      std::uniform_real_distribution<double> distance(enter, exit);
      const double r = n % 10 == 0 ? enter : distance(random);
      const glm::dvec3 p = position + d * r;
      ++tested;
      EXPECT_TRUE(InsideClipVolume(faces[DominantAxisFace(d)].ViewProjection(), p))
        << "direction " << ToString(d) << " r " << r;
    }
    EXPECT_GT(tested, 100);
  }
}

// Window of a perspective fit in tangent units (near-plane extent over near).
glm::dvec2 TangentWindow(const LightView& fit)
{
  return { 2.0 / fit.Projection[0][0], 2.0 / fit.Projection[1][1] };
}

TEST(FitCubeFacesToView, ReceiversInViewAndTheirCastersAreInsideTheirFace)
{
  const GroundScene ground;
  const glm::dmat4 camera = ground.Camera();
  std::mt19937 random(11);
  for (const auto& position : { glm::dvec3(0.0, -150.0, 8.0), glm::dvec3(20.0, 40.0, 30.0) })
  {
    SCOPED_TRACE("light at " + ToString(position));
    const auto faces = shadowmaps::FitCubeFacesToView(camera, ground.Scene, position, Resolution);
    for (const auto& face : faces)
    {
      ASSERT_TRUE(IsFiniteFit(face));
    }
    int tested = 0;
    for (int n = 0; n < 200000 && tested < 5000; ++n)
    {
      const glm::dvec3 receiver = RandomPointInBox(random, ground.Scene);
      const glm::dvec3 d = receiver - position;
      // Points very close to the light fall before the near plane by design.
      if (!InsideClipVolume(camera, receiver, 0.0) || glm::length(d) < 1.0)
      {
        continue;
      }
      ++tested;
      const int index = DominantAxisFace(d);
      EXPECT_FALSE(faces[index].OutOfView) << "face " << index;
      const glm::dmat4 face = faces[index].ViewProjection();
      EXPECT_TRUE(InsideClipVolume(face, receiver));
      const glm::dvec3 caster = position + 0.5 * d;
      if (InsideBox(ground.Scene, caster, 0.0))
      {
        EXPECT_TRUE(InsideClipVolume(face, caster)) << "caster halfway to the light";
      }
    }
    EXPECT_EQ(tested, 5000);
  }
}

TEST(FitCubeFacesToView, FacesShrinkToThePartInView)
{
  // A lamp 20 units above flat ground, 15 units ahead of a walker with a narrow
  // view: the walker sees the ground from about 26 units ahead, so only the far
  // part of the ground below the lamp, and nothing behind its own back.
  const GroundScene ground;
  const Aabb flat = MakeBox(ground.Scene.Min, glm::dvec3(ground.Scene.Max.x, ground.Scene.Max.y, 0.5));
  const glm::dmat4 camera = glm::perspective(glm::radians(20.0), 16.0 / 9.0, 0.1, 500.0) *
    CameraLookAt(ground.Eye, ground.Target);
  const glm::dvec3 position(0.0, -165.0, 20.0);
  const auto whole = shadowmaps::FitCubeFaces(flat, position, Resolution);
  const auto focused = shadowmaps::FitCubeFacesToView(camera, flat, position, Resolution);
  double wholeArea = 0.0;
  double focusedArea = 0.0;
  for (int i = 0; i < 6; ++i)
  {
    const glm::dvec2 w = TangentWindow(whole[i]);
    const glm::dvec2 f = TangentWindow(focused[i]);
    EXPECT_LE(f.x, w.x * (1.0 + 1e-9)) << "face " << i;
    EXPECT_LE(f.y, w.y * (1.0 + 1e-9)) << "face " << i;
    wholeArea += w.x * w.y;
    focusedArea += f.x * f.y;
  }
  // It looks along +y: only the faces looking down (-z) and ahead (+y) see
  // into its view.
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(focused[i].OutOfView, i != 2 && i != 5) << "face " << i;
  }
  const glm::dvec2 down = TangentWindow(focused[5]);
  const glm::dvec2 wholeDown = TangentWindow(whole[5]);
  EXPECT_LT(down.x * down.y, 0.5 * wholeDown.x * wholeDown.y);
  // Stable crops grow by up to an eighth per axis.
  EXPECT_LT(focusedArea, 0.8 * wholeArea);
}

TEST(FitCubeFacesToView, FacesOutOfViewAreMarkedAndKeepTheWholeSceneFit)
{
  // Looking away from the scene: no face holds a receiver in view.
  const GroundScene ground;
  const glm::dmat4 away = PerspectiveCamera(
    glm::dvec3(0.0, -300.0, 5.0), glm::dvec3(0.0, -400.0, 5.0), 0.1, 50.0);
  const glm::dvec3 position(0.0, -150.0, 8.0);
  const auto whole = shadowmaps::FitCubeFaces(ground.Scene, position, Resolution);
  const auto focused = shadowmaps::FitCubeFacesToView(away, ground.Scene, position, Resolution);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(focused[i].ViewProjection(), whole[i].ViewProjection()) << "face " << i;
    EXPECT_TRUE(focused[i].OutOfView) << "face " << i;
    EXPECT_FALSE(whole[i].OutOfView) << "face " << i;
  }
}
} // namespace

// A stable crop contains the crop asked for, loses at most an eighth of its
// width, and does not move while the crop moves within a grid cell.
TEST(FitCubeFaces, StableCropsSnapOutwardToAGrid)
{
  const double t = 1.0;
  for (const double width : { 1.5, 0.4, 0.05, 0.003 })
  {
    glm::dvec2 lo(-0.3, -0.2);
    glm::dvec2 hi = lo + width;
    glm::dvec2 snappedLo = lo, snappedHi = hi;
    shadowmaps::SnapCropOutward(snappedLo, snappedHi, t);
    EXPECT_LE(snappedLo.x, lo.x);
    EXPECT_LE(snappedLo.y, lo.y);
    EXPECT_GE(snappedHi.x, std::min(hi.x, t));
    EXPECT_GE(snappedHi.y, std::min(hi.y, t));
    const double kept = std::min(width, 2.0 * t);
    EXPECT_LE(snappedHi.x - snappedLo.x, kept * 1.125 + 1e-12) << width;

    // A shift far below a grid cell, where the edges are off the grid lines.
    const double shift = 1e-7 * width;
    glm::dvec2 movedLo = lo + shift, movedHi = hi + shift;
    if (std::min(snappedHi.x - hi.x, snappedHi.y - hi.y) > shift)
    {
      shadowmaps::SnapCropOutward(movedLo, movedHi, t);
      EXPECT_EQ(movedLo, snappedLo) << width;
      EXPECT_EQ(movedHi, snappedHi) << width;
    }
  }
}
