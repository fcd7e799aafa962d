// Unit tests of Kozlov's post-perspective cube map (Plugin/Math/ShadowMapPerspectiveCube).
#include "FocusingTestHelpers.h"
#include "ShadowMapKeptViews.h"
#include "ShadowMapMotion.h"
#include "ShadowMapPerspectiveCube.h"

using namespace focusingtest;
using shadowmaps::PerspectiveCube;
using shadowmaps::testing::WarpTestGround;

namespace
{
const Aabb UnitCube = MakeBox(glm::dvec3(-1.0), glm::dvec3(1.0));

std::vector<int> FacesAwayFrom(const Aabb& box, const glm::dvec3& light)
{
  std::vector<int> faces;
  for (int face = 0; face < shadowmaps::PerspectiveCubeFaces; ++face)
  {
    if (shadowmaps::PlatformDistance(box, light, face) > 0.0)
    {
      faces.push_back(face);
    }
  }
  return faces;
}

TEST(PerspectiveCubeFaces, ThreeToFiveFacesOutsideTheCubeAndSixInside)
{
  EXPECT_EQ(FacesAwayFrom(UnitCube, { 0.2, -0.3, 0.5 }), (std::vector<int>{ 0, 1, 2, 3, 4, 5 }));
  // Beyond one side (a sun facing the camera lies beyond the far plane, +z).
  EXPECT_EQ(FacesAwayFrom(UnitCube, { 0.1, 0.2, 3.0 }), (std::vector<int>{ 0, 1, 2, 3, 5 }));
  // Off an edge and off a corner.
  EXPECT_EQ(FacesAwayFrom(UnitCube, { 3.0, -2.0, 0.0 }), (std::vector<int>{ 1, 2, 4, 5 }));
  EXPECT_EQ(FacesAwayFrom(UnitCube, { 3.0, 3.0, -3.0 }), (std::vector<int>{ 1, 3, 4 }));
}

// The face of the box through which the ray from `light` through `point`
// leaves it, by marching the ray: Kozlov's definition of the lookup.
int ExitFace(const Aabb& box, const glm::dvec3& light, const glm::dvec3& point)
{
  const glm::dvec3 d = point - light;
  double exit = std::numeric_limits<double>::infinity();
  int face = -1;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (d[axis] == 0.0)
    {
      continue;
    }
    const bool positive = d[axis] > 0.0;
    const double t = ((positive ? box.Max[axis] : box.Min[axis]) - light[axis]) / d[axis];
    if (t < exit)
    {
      exit = t;
      face = 2 * axis + (positive ? 0 : 1);
    }
  }
  return face;
}

TEST(PerspectiveCubeFaces, DisplacedCentreLookupFindsTheFaceTheRayLeavesBy)
{
  std::mt19937 random(11);
  const Aabb lights = MakeBox(glm::dvec3(-4.0), glm::dvec3(4.0));
  int tested = 0;
  for (int n = 0; n < 20000; ++n)
  {
    const glm::dvec3 light = RandomPointInBox(random, lights);
    const glm::dvec3 point = RandomPointInBox(random, UnitCube);
    const int face = shadowmaps::DisplacedCubeFace(UnitCube, light, point);
    ASSERT_EQ(face, ExitFace(UnitCube, light, point)) << ToString(light) << " " << ToString(point);
    EXPECT_GT(shadowmaps::PlatformDistance(UnitCube, light, face), 0.0);
    ++tested;
  }
  EXPECT_EQ(tested, 20000);
}

// A camera over the ground looking along +y, as TestShadowMapPerspective's.
const glm::dvec3 Eye(0.0, -45.0, 5.0);

glm::dmat4 CameraView()
{
  return glm::lookAt(Eye, glm::dvec3(0.0, 0.0, 5.0), glm::dvec3(0.0, 0.0, 1.0));
}

glm::dmat4 CameraProjection()
{
  return glm::perspective(glm::radians(45.0), 1.5, 0.5, 80.0);
}

std::vector<Plane> Receivers(const glm::dmat4& camera)
{
  std::vector<Plane> planes;
  for (const auto& set : { shadowmaps::FrustumPlanes(camera), shadowmaps::BoxPlanes(WarpTestGround()) })
  {
    planes.insert(planes.end(), set.begin(), set.end());
  }
  return planes;
}

PerspectiveCube Fit(const glm::dvec4& towardLight)
{
  return shadowmaps::FitPerspectiveCube(CameraView(), CameraProjection(),
    Receivers(CameraProjection() * CameraView()), WarpTestGround(), towardLight, Resolution, 0.0, 4.0);
}

// The face receivers pick: the largest clip w times the face's selection.
int SelectedFace(const PerspectiveCube& cube, const glm::dvec3& p)
{
  int best = -1;
  double largest = 0.0;
  for (int face = 0; face < shadowmaps::PerspectiveCubeFaces; ++face)
  {
    const double reach =
      (cube.Faces[face].ViewProjection() * glm::dvec4(p, 1.0)).w * cube.Selection[face];
    if (reach > largest)
    {
      largest = reach;
      best = face;
    }
  }
  return best;
}

// Receivers: points of the ground box inside the camera frustum.
std::vector<glm::dvec3> VisibleReceivers(std::mt19937& random, int count)
{
  const glm::dmat4 camera = CameraProjection() * CameraView();
  const auto frustum = shadowmaps::FrustumPlanes(camera);
  std::vector<glm::dvec3> points;
  while (static_cast<int>(points.size()) < count)
  {
    const glm::dvec3 p = RandomPointInBox(random, WarpTestGround());
    if (InsidePlanes(frustum, p, 0.0))
    {
      points.push_back(p);
    }
  }
  return points;
}

struct LightCase
{
  const char* Name;
  glm::dvec4 TowardLight;
  bool Inverse;
};

const LightCase Lights[] = {
  { "point light ahead, at street level", { 2.0, -30.0, 2.0, 1.0 }, false },
  { "point light over the far street", { -5.0, 20.0, 8.0, 1.0 }, false },
  { "point light behind the viewer", { 3.0, -60.0, 9.0, 1.0 }, true },
  { "sun facing the camera", { 0.1, 0.8, 0.3, 0.0 }, false },
  { "sun behind the viewer", { -0.2, -0.7, 0.5, 0.0 }, true },
};

TEST(PerspectiveCubeFit, EveryVisibleReceiverIsInsideTheMapOfTheFaceItPicks)
{
  std::mt19937 random(3);
  const std::vector<glm::dvec3> receivers = VisibleReceivers(random, 4000);
  for (const LightCase& light : Lights)
  {
    SCOPED_TRACE(light.Name);
    const PerspectiveCube cube = Fit(light.TowardLight);
    ASSERT_TRUE(cube.Valid);
    EXPECT_EQ(cube.Inverse, light.Inverse);
    std::array<int, 6> picked{};
    int clamped = 0;
    for (const glm::dvec3& p : receivers)
    {
      const int face = SelectedFace(cube, p);
      ASSERT_GE(face, 0) << ToString(p);
      // The receivers' rule is Kozlov's lookup in post-perspective space.
      const glm::dvec3 post = shadowmaps::ProjectPoint(cube.PostPerspective, p);
      ASSERT_EQ(face, shadowmaps::DisplacedCubeFace(cube.Platforms, cube.LightPosition, post));
      const LightView& view = cube.Faces[face];
      ASSERT_FALSE(view.OutOfView);
      const glm::dvec4 clip = view.ViewProjection() * glm::dvec4(p, 1.0);
      ASSERT_GT(clip.w, 0.0);
      const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
      EXPECT_LE(std::abs(ndc.x), 1.0 + ClipTolerance) << ToString(p);
      EXPECT_LE(std::abs(ndc.y), 1.0 + ClipTolerance) << ToString(p);
      EXPECT_LE(ndc.z, 1.0 + ClipTolerance) << ToString(p);
      // Receivers within a hundredth of the scene's reach of a light among
      // them lie before the near plane (unshadowed): few of the random ones.
      clamped += ndc.z < -1.0 - ClipTolerance ? 1 : 0;
      ++picked[face];
    }
    EXPECT_LE(clamped, static_cast<int>(receivers.size()) / 1000);
    int used = 0;
    for (int face = 0; face < 6; ++face)
    {
      used += picked[face] > 0 ? 1 : 0;
      // A face no receiver picks needs no casters.
      if (picked[face] > 40)
      {
        EXPECT_FALSE(cube.Faces[face].OutOfView);
      }
    }
    EXPECT_GE(used, 2);
  }
}

TEST(PerspectiveCubeFit, CastersBetweenTheLightAndAReceiverLieNearerInTheSameTexel)
{
  std::mt19937 random(8);
  const std::vector<glm::dvec3> receivers = VisibleReceivers(random, 1500);
  for (const LightCase& light : Lights)
  {
    SCOPED_TRACE(light.Name);
    const PerspectiveCube cube = Fit(light.TowardLight);
    ASSERT_TRUE(cube.Valid);
    int tested = 0;
    for (const glm::dvec3& p : receivers)
    {
      const glm::dvec3 toward = light.TowardLight.w != 0.0
        ? glm::dvec3(light.TowardLight) - p
        : glm::normalize(glm::dvec3(light.TowardLight)) * 10.0;
      const glm::dvec3 caster = p + 0.4 * toward;
      if (!InsideBox(WarpTestGround(), caster, 0.0))
      {
        continue; // only casters in the scene are held by the slide-back
      }
      const LightView& view = cube.Faces[SelectedFace(cube, p)];
      const glm::dvec4 r = view.ViewProjection() * glm::dvec4(p, 1.0);
      const glm::dvec4 c = view.ViewProjection() * glm::dvec4(caster, 1.0);
      ASSERT_GT(c.w, 0.0) << ToString(caster);
      const glm::dvec3 rn = glm::dvec3(r) / r.w;
      const glm::dvec3 cn = glm::dvec3(c) / c.w;
      EXPECT_NEAR(cn.x, rn.x, 1e-7);
      EXPECT_NEAR(cn.y, rn.y, 1e-7);
      // Casters nearer the light than the near plane are clamped onto it.
      EXPECT_LT(std::max(cn.z, -1.0), rn.z) << ToString(p);
      ++tested;
    }
    EXPECT_GT(tested, 100);
  }
}

TEST(PerspectiveCubeFit, NoCubeForAParallelCameraOrNoReceiver)
{
  const glm::dmat4 parallel = glm::ortho(-15.0, 15.0, -10.0, 10.0, 0.5, 80.0);
  EXPECT_FALSE(shadowmaps::FitPerspectiveCube(CameraView(), parallel,
    Receivers(parallel * CameraView()), WarpTestGround(), { 0.0, 0.0, 5.0, 1.0 }, Resolution, 0.0, 4.0)
                 .Valid);
  // Looking away from the scene: nothing to shade.
  const glm::dmat4 away = glm::lookAt(glm::dvec3(0.0, -60.0, 5.0), glm::dvec3(0.0, -100.0, 5.0),
    glm::dvec3(0.0, 0.0, 1.0));
  EXPECT_FALSE(shadowmaps::FitPerspectiveCube(away, CameraProjection(),
    Receivers(CameraProjection() * away), WarpTestGround(), { 0.0, 0.0, 5.0, 1.0 }, Resolution, 0.0, 4.0)
                 .Valid);
}

TEST(PerspectiveCubeFit, FiniteFacesForLightsOnTheViewAxisAndInTheCameraPlane)
{
  const std::vector<glm::dvec4> lights = {
    { 0.0, 1.0, 0.0, 0.0 },   // sun along the view
    { 0.0, -1.0, 0.0, 0.0 },  // sun against it
    { 0.0, 10.0, 5.0, 1.0 },  // point light on the view axis
    { 20.0, -45.0, 5.0, 1.0 }, // point light in the camera's plane
    { 0.0, -45.0, 5.0, 1.0 },  // point light at the eye
  };
  for (const glm::dvec4& light : lights)
  {
    SCOPED_TRACE(ToString(glm::dvec3(light)) + " w " + std::to_string(light.w));
    const PerspectiveCube cube = Fit(light);
    // The casters' slide-back moves even a light at the eye or in its plane
    // off the virtual camera's plane: every one gets a cube.
    ASSERT_TRUE(cube.Valid);
    for (const LightView& face : cube.Faces)
    {
      EXPECT_TRUE(shadowmaps::IsFinite(face.ViewProjection()));
    }
  }
}
} // namespace

namespace
{
glm::dmat4 MovedCameraView(double sideways, double turnDegrees)
{
  const glm::dvec3 eye = Eye + glm::dvec3(sideways, 0.0, 0.0);
  const double turn = glm::radians(turnDegrees);
  const glm::dvec3 forward(std::sin(turn), std::cos(turn), 0.0);
  return glm::lookAt(eye, eye + forward * 45.0, glm::dvec3(0.0, 0.0, 1.0));
}

// As a drag sees the ground: the far plane beyond it (a turned camera's far
// plane would cut it elsewhere) and the automatic slide-back, sqrt(near far).
glm::dmat4 DragProjection()
{
  return glm::perspective(glm::radians(45.0), 1.5, 0.5, 200.0);
}
const double DragSlideBack = 10.0;

PerspectiveCube FitFor(const glm::dmat4& view, const glm::dmat4& projection, const glm::dvec4& towardLight)
{
  return shadowmaps::FitPerspectiveCube(view, projection, Receivers(projection * view),
    WarpTestGround(), towardLight, Resolution, DragSlideBack, 4.0);
}

bool Serves(const PerspectiveCube& kept, const glm::dmat4& view, const glm::dvec4& towardLight,
  double texelRatio)
{
  const std::vector<LightView> faces(kept.Faces.begin(), kept.Faces.end());
  const std::vector<double> selection(kept.Selection.begin(), kept.Selection.end());
  const std::vector<Plane> receivers = Receivers(DragProjection() * view);
  const shadowmaps::FreshCube fresh = shadowmaps::MeasureFreshCube(
    FitFor(view, DragProjection(), towardLight), receivers, WarpTestGround(), towardLight, Resolution);
  return shadowmaps::KeptCubeServes(
    faces, selection, receivers, fresh, WarpTestGround(), towardLight, Resolution, texelRatio, 3.0);
}
} // namespace

TEST(PerspectiveCubeKept, ACubeServesItsOwnFrameAndNotAFarMove)
{
  for (const LightCase& light : Lights)
  {
    SCOPED_TRACE(light.Name);
    const PerspectiveCube cube = FitFor(CameraView(), DragProjection(), light.TowardLight);
    ASSERT_TRUE(cube.Valid);
    EXPECT_TRUE(Serves(cube, CameraView(), light.TowardLight, 1.0 + 1e-9));
    // Turned 40 degrees, the camera sees receivers the cube's crops never held.
    EXPECT_FALSE(Serves(cube, MovedCameraView(0.0, 40.0), light.TowardLight, 1.5));
  }
}

TEST(PerspectiveCubeKept, ACubeFittedToAWidenedCameraServesSmallMoves)
{
  // Fitted as a drag fits it (the camera moved back and its sides turned out
  // by a degree), it holds a camera moved a little sideways and turned half a
  // degree.
  for (const LightCase& light : Lights)
  {
    SCOPED_TRACE(light.Name);
    const shadowmaps::Camera widened =
      shadowmaps::WidenedCamera({ CameraView(), DragProjection() }, 0.5, 1.0);
    const PerspectiveCube cube = FitFor(widened.View, widened.Projection, light.TowardLight);
    ASSERT_TRUE(cube.Valid);
    EXPECT_TRUE(Serves(cube, MovedCameraView(0.1, 0.5), light.TowardLight, 2.0));
  }
}

namespace
{
std::vector<Plane> BoxAround(const glm::dvec3& centre, double half)
{
  const auto planes = shadowmaps::BoxPlanes(MakeBox(centre - half, centre + half));
  return { planes.begin(), planes.end() };
}

bool KeptServes(const PerspectiveCube& kept, const std::vector<Plane>& receivers,
  const glm::dvec4& towardLight, double texelRatio)
{
  const PerspectiveCube fresh = shadowmaps::FitPerspectiveCube(CameraView(), DragProjection(),
    receivers, WarpTestGround(), towardLight, Resolution, DragSlideBack, 4.0);
  EXPECT_TRUE(fresh.Valid);
  const std::vector<LightView> faces(kept.Faces.begin(), kept.Faces.end());
  const std::vector<double> selection(kept.Selection.begin(), kept.Selection.end());
  return shadowmaps::KeptCubeServes(faces, selection, receivers,
    shadowmaps::MeasureFreshCube(fresh, receivers, WarpTestGround(), towardLight, Resolution),
    WarpTestGround(), towardLight, Resolution, texelRatio, 3.0);
}

// A light above the street ahead, outside the receivers: its cube uses the
// faces that look away from it, down over the street.
const glm::dvec4 LampAbove(0.0, -20.0, 30.0, 1.0);
} // namespace

TEST(PerspectiveCubeKept, ReceiversNoKeptFaceLooksAtDoNotServe)
{
  // A light off a corner of the receivers' box in post-perspective space (to
  // the side, above and beyond the far end): three faces look away from it.
  const glm::dvec4 corner(300.0, 200.0, 200.0, 1.0);
  const PerspectiveCube kept = FitFor(CameraView(), DragProjection(), corner);
  ASSERT_TRUE(kept.Valid);
  int used = 0;
  for (const double selection : kept.Selection)
  {
    used += selection > 0.0 ? 1 : 0;
  }
  EXPECT_EQ(used, 3);
  // Behind the lamp from the box the faces were fitted to (in post-perspective
  // space, beyond the lamp away from the box's centre): no face picks it (the
  // receivers would be drawn unshadowed).
  // (Not so far beyond that it lies behind the camera.)
  glm::dvec3 behind(0.0);
  for (double t = 0.5; t > 1e-4; t *= 0.5)
  {
    const glm::dvec3 post =
      kept.LightPosition + t * (kept.LightPosition - kept.Platforms.Center());
    behind = shadowmaps::ProjectPoint(glm::inverse(kept.PostPerspective), post);
    if ((kept.PostPerspective * glm::dvec4(behind, 1.0)).w > 0.0)
    {
      break;
    }
  }
  ASSERT_GT((kept.PostPerspective * glm::dvec4(behind, 1.0)).w, 0.0) << ToString(behind);
  EXPECT_LT(SelectedFace(kept, behind), 0) << ToString(behind);
  EXPECT_FALSE(KeptServes(kept, BoxAround(behind, 0.2), corner, 1e9));
  // On the street in view, the faces hold it.
  const glm::dvec3 street(0.0, -20.0, 0.5);
  EXPECT_GE(SelectedFace(kept, street), 0);
  EXPECT_TRUE(KeptServes(kept, BoxAround(street, 0.5), corner, 1e9));
}

TEST(PerspectiveCubeKept, ReceiversBeforeAKeptFacesNearPlaneDoNotServe)
{
  // Fitted to the street, the faces' near planes lie far below the lamp: a
  // receiver just under it would be drawn unshadowed, where a fresh cube
  // shades it.
  const PerspectiveCube kept = FitFor(CameraView(), DragProjection(), LampAbove);
  ASSERT_TRUE(kept.Valid);
  EXPECT_FALSE(KeptServes(kept, BoxAround({ 0.0, -20.0, 28.0 }, 0.2), LampAbove, 1e9));
}

TEST(PerspectiveCubeKept, ACubeOfAWiderCameraServesOnlyWithinItsTexelRatio)
{
  // Fitted to a 100 degree camera at the same place, the faces hold the 45
  // degree camera's receivers with coarser texels.
  const glm::dmat4 wide = glm::perspective(glm::radians(100.0), 1.5, 0.5, 200.0);
  for (const LightCase& light : Lights)
  {
    SCOPED_TRACE(light.Name);
    const PerspectiveCube kept = FitFor(CameraView(), wide, light.TowardLight);
    ASSERT_TRUE(kept.Valid);
    const std::vector<Plane> receivers = Receivers(DragProjection() * CameraView());
    EXPECT_TRUE(KeptServes(kept, receivers, light.TowardLight, 1e9));
    EXPECT_FALSE(KeptServes(kept, receivers, light.TowardLight, 1.5));
  }
}
