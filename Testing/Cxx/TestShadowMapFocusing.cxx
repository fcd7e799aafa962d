// Unit tests for the pure focusing math in Plugin/ShadowMapFocusing.{h,cxx}.
#include "ShadowMapFocusing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace
{
using shadowmaps::Aabb;
using shadowmaps::LightView;
using shadowmaps::Plane;

constexpr int Resolution = 2048;
// Clip-space slack for "inside [-1, 1]^3": far above rounding, far below a texel.
constexpr double ClipTolerance = 1e-9;

std::string ToString(const glm::dvec3& p)
{
  std::ostringstream out;
  out.precision(17);
  out << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return out.str();
}

Aabb MakeBox(const glm::dvec3& min, const glm::dvec3& max)
{
  Aabb box;
  box.Min = min;
  box.Max = max;
  return box;
}

glm::dvec3 TransformPoint(const glm::dmat4& m, const glm::dvec3& p)
{
  const glm::dvec4 q = m * glm::dvec4(p, 1.0);
  return glm::dvec3(q) / q.w;
}

// Distance in front of the eye of a view matrix (view space looks down -z).
double ViewDepth(const glm::dmat4& view, const glm::dvec3& p)
{
  return -TransformPoint(view, p).z;
}

// World z is up unless the camera looks (nearly) straight up or down.
glm::dmat4 CameraLookAt(const glm::dvec3& eye, const glm::dvec3& target)
{
  const bool vertical = std::abs(glm::normalize(target - eye).z) > 0.99;
  return glm::lookAt(eye, target, vertical ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0));
}

glm::dmat4 PerspectiveCamera(const glm::dvec3& eye,
  const glm::dvec3& target,
  double zNear,
  double zFar)
{
  return glm::perspective(glm::radians(60.0), 16.0 / 9.0, zNear, zFar) * CameraLookAt(eye, target);
}

glm::dmat4 ParallelCamera(const glm::dvec3& eye,
  const glm::dvec3& target,
  double halfHeight,
  double zNear,
  double zFar)
{
  const double halfWidth = halfHeight * 16.0 / 9.0;
  return glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, zNear, zFar) *
    CameraLookAt(eye, target);
}

// A large flat scene (400 x 400 x 10 at scale 1) seen by a walker standing in it.
struct GroundScene
{
  Aabb Scene;
  glm::dvec3 Eye;
  glm::dvec3 Target;
  double Near;
  double Far;

  explicit GroundScene(double scale = 1.0)
    : Scene(
        MakeBox(glm::dvec3(-200.0, -200.0, 0.0) * scale, glm::dvec3(200.0, 200.0, 10.0) * scale))
    , Eye(glm::dvec3(0.0, -180.0, 5.0) * scale)
    , Target(glm::dvec3(0.0, 0.0, 2.0) * scale)
    , Near(0.1 * scale)
    , Far(500.0 * scale)
  {
  }

  glm::dmat4 Camera() const
  {
    return PerspectiveCamera(this->Eye, this->Target, this->Near, this->Far);
  }
  glm::dvec3 ViewDirection() const { return glm::normalize(this->Target - this->Eye); }
};

// The same ground scene seen from high above at a slant.
glm::dmat4 AerialCamera(double scale = 1.0)
{
  return PerspectiveCamera(
    glm::dvec3(0.0, -250.0, 60.0) * scale, glm::dvec3(0.0), 1.0 * scale, 600.0 * scale);
}

bool InsidePlanes(const std::array<Plane, 6>& planes, const glm::dvec3& p, double tolerance)
{
  return std::all_of(planes.begin(),
    planes.end(),
    [&](const Plane& plane) { return plane.Distance(p) >= -tolerance; });
}

bool InsideBox(const Aabb& box, const glm::dvec3& p, double tolerance)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    if (p[axis] < box.Min[axis] - tolerance || p[axis] > box.Max[axis] + tolerance)
    {
      return false;
    }
  }
  return true;
}

Aabb BoundsOf(const std::vector<glm::dvec3>& points, const glm::dmat4& frame = glm::dmat4(1.0))
{
  Aabb bounds;
  for (const auto& p : points)
  {
    bounds.Add(TransformPoint(frame, p));
  }
  return bounds;
}

glm::dvec3 RandomPointInBox(std::mt19937& random, const Aabb& box)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  return box.Min + (box.Max - box.Min) * glm::dvec3(unit(random), unit(random), unit(random));
}

glm::dvec3 RandomDirection(std::mt19937& random)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  glm::dvec3 d;
  do
  {
    d = glm::dvec3(normal(random), normal(random), normal(random));
  } while (glm::length(d) < 1e-6);
  return glm::normalize(d);
}

// Parameter interval [enter, exit] of the ray origin + t * direction inside box;
// false when the ray's line misses the box.
bool RayBoxInterval(const glm::dvec3& origin,
  const glm::dvec3& direction,
  const Aabb& box,
  double& enter,
  double& exit)
{
  enter = -std::numeric_limits<double>::infinity();
  exit = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis)
  {
    if (direction[axis] == 0.0)
    {
      if (origin[axis] < box.Min[axis] || origin[axis] > box.Max[axis])
      {
        return false;
      }
      continue;
    }
    double t0 = (box.Min[axis] - origin[axis]) / direction[axis];
    double t1 = (box.Max[axis] - origin[axis]) / direction[axis];
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    enter = std::max(enter, t0);
    exit = std::min(exit, t1);
  }
  return enter <= exit;
}

// Points of a regular grid over the box, corners included.
std::vector<glm::dvec3> GridPoints(const Aabb& box, int nx, int ny, int nz)
{
  std::vector<glm::dvec3> points;
  for (int i = 0; i < nx; ++i)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int k = 0; k < nz; ++k)
      {
        const glm::dvec3 f(double(i) / (nx - 1), double(j) / (ny - 1), double(k) / (nz - 1));
        points.push_back(box.Min + (box.Max - box.Min) * f);
      }
    }
  }
  return points;
}

::testing::AssertionResult InsideClipVolume(const glm::dmat4& viewProjection,
  const glm::dvec3& p,
  double tolerance = ClipTolerance)
{
  const glm::dvec4 clip = viewProjection * glm::dvec4(p, 1.0);
  if (!(clip.w > 0.0))
  {
    return ::testing::AssertionFailure() << ToString(p) << " has clip w " << clip.w;
  }
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  if (!(std::abs(ndc.x) <= 1.0 + tolerance && std::abs(ndc.y) <= 1.0 + tolerance &&
        std::abs(ndc.z) <= 1.0 + tolerance))
  {
    return ::testing::AssertionFailure()
      << ToString(p) << " maps to NDC " << ToString(ndc) << ", outside [-1, 1]^3";
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult IsFiniteFit(const LightView& fit)
{
  if (!shadowmaps::IsFinite(fit.View))
  {
    return ::testing::AssertionFailure() << "view matrix is not finite";
  }
  if (!shadowmaps::IsFinite(fit.Projection))
  {
    return ::testing::AssertionFailure() << "projection matrix is not finite";
  }
  const double determinant = glm::determinant(fit.ViewProjection());
  if (!std::isfinite(determinant) || determinant == 0.0)
  {
    return ::testing::AssertionFailure() << "view-projection is singular: det " << determinant;
  }
  if (!std::isfinite(fit.TexelConstant) || !std::isfinite(fit.TexelPerUnitDistance))
  {
    return ::testing::AssertionFailure() << "texel sizes are not finite";
  }
  return ::testing::AssertionSuccess();
}

// Asserts the two properties a focused directional fit must have: the focus body
// B is inside the light's clip volume, and no scene point inside the map's x/y
// range that is nearer to the light than B's far end is cut by the near plane.
void CheckDirectionalFit(const glm::dmat4& camera,
  const Aabb& scene,
  const glm::dvec3& lightDirection)
{
  const LightView fit = shadowmaps::FitDirectional(camera, scene, lightDirection, Resolution);
  ASSERT_TRUE(IsFiniteFit(fit));
  EXPECT_FALSE(fit.Perspective);
  const glm::dmat4 viewProjection = fit.ViewProjection();

  const auto body = shadowmaps::IntersectFrustumWithBox(camera, scene);
  ASSERT_FALSE(body.empty());
  double bodyFar = -std::numeric_limits<double>::infinity();
  for (const auto& p : body)
  {
    EXPECT_TRUE(InsideClipVolume(viewProjection, p));
    bodyFar = std::max(bodyFar, ViewDepth(fit.View, p));
  }

  int casters = 0;
  for (const auto& p : GridPoints(scene, 41, 41, 6))
  {
    const glm::dvec3 ndc = TransformPoint(viewProjection, p);
    if (std::abs(ndc.x) > 1.0 || std::abs(ndc.y) > 1.0 || ViewDepth(fit.View, p) > bodyFar)
    {
      continue;
    }
    ++casters;
    EXPECT_GE(ndc.z, -1.0 - ClipTolerance)
      << "caster " << ToString(p) << " is cut by the near plane";
  }
  EXPECT_GT(casters, 0);
}

std::vector<glm::dvec3> TestLightDirections(const glm::dvec3& viewDirection)
{
  const glm::dvec3 right = glm::normalize(glm::cross(viewDirection, glm::dvec3(0.0, 0.0, 1.0)));
  return {
    { 0.0, 0.0, -1.0 },                          // overhead
    right,                                       // perpendicular to the view
    right + glm::dvec3(0.0, 0.0, -0.5),          // perpendicular, from above
    viewDirection + glm::dvec3(0.0, 0.0, -0.5),  // from behind the viewer
    -viewDirection + glm::dvec3(0.0, 0.0, -0.5), // facing the viewer
    viewDirection,                               // exactly along the view
    -viewDirection,                              // exactly against the view
  };
}

// ---------------------------------------------------------------------------
// Aabb

TEST(Aabb, DefaultConstructedIsEmpty)
{
  const Aabb box;
  EXPECT_TRUE(box.IsEmpty());
  EXPECT_EQ(box.Diagonal(), 0.0);
}

TEST(Aabb, AddPointsGrowsToTheirBounds)
{
  Aabb box;
  box.Add(glm::dvec3(1.0, 2.0, 3.0));
  EXPECT_FALSE(box.IsEmpty());
  EXPECT_EQ(box.Min, glm::dvec3(1.0, 2.0, 3.0));
  EXPECT_EQ(box.Max, glm::dvec3(1.0, 2.0, 3.0));
  EXPECT_EQ(box.Diagonal(), 0.0);

  box.Add(glm::dvec3(-1.0, 5.0, 0.0));
  EXPECT_EQ(box.Min, glm::dvec3(-1.0, 2.0, 0.0));
  EXPECT_EQ(box.Max, glm::dvec3(1.0, 5.0, 3.0));
  EXPECT_EQ(box.Center(), glm::dvec3(0.0, 3.5, 1.5));
  EXPECT_DOUBLE_EQ(box.Diagonal(), std::sqrt(4.0 + 9.0 + 9.0));
}

TEST(Aabb, AddBoxIgnoresEmptyBoxes)
{
  Aabb box = MakeBox(glm::dvec3(0.0), glm::dvec3(1.0));
  box.Add(Aabb{});
  EXPECT_EQ(box.Min, glm::dvec3(0.0));
  EXPECT_EQ(box.Max, glm::dvec3(1.0));

  box.Add(MakeBox(glm::dvec3(-2.0, 0.5, 0.5), glm::dvec3(0.5, 0.5, 4.0)));
  EXPECT_EQ(box.Min, glm::dvec3(-2.0, 0.0, 0.0));
  EXPECT_EQ(box.Max, glm::dvec3(1.0, 1.0, 4.0));

  Aabb empty;
  empty.Add(MakeBox(glm::dvec3(-1.0), glm::dvec3(2.0)));
  EXPECT_EQ(empty.Min, glm::dvec3(-1.0));
  EXPECT_EQ(empty.Max, glm::dvec3(2.0));
}

TEST(Aabb, CornersAreTheEightDistinctExtremes)
{
  const Aabb box = MakeBox(glm::dvec3(-1.0, 2.0, -3.0), glm::dvec3(4.0, 5.0, 6.0));
  const auto corners = box.Corners();
  for (size_t i = 0; i < corners.size(); ++i)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      EXPECT_TRUE(corners[i][axis] == box.Min[axis] || corners[i][axis] == box.Max[axis]);
    }
    for (size_t j = 0; j < i; ++j)
    {
      EXPECT_NE(corners[i], corners[j]);
    }
  }
}

TEST(Aabb, FromBoundsReadsVtkOrderAndRejectsInvalid)
{
  const double bounds[6] = { -1.0, 1.0, -2.0, 2.0, -3.0, 3.0 };
  const Aabb box = Aabb::FromBounds(bounds);
  EXPECT_EQ(box.Min, glm::dvec3(-1.0, -2.0, -3.0));
  EXPECT_EQ(box.Max, glm::dvec3(1.0, 2.0, 3.0));

  const double uninitialized[6] = {
    1.0, -1.0, 1.0, -1.0, 1.0, -1.0
  }; // vtkMath::UninitializeBounds
  EXPECT_TRUE(Aabb::FromBounds(uninitialized).IsEmpty());
  EXPECT_TRUE(Aabb::FromBounds(nullptr).IsEmpty());
}

// ---------------------------------------------------------------------------
// Frustum corners and planes

std::vector<glm::dmat4> TestCameras()
{
  return {
    PerspectiveCamera(glm::dvec3(3.0, -4.0, 2.0), glm::dvec3(0.0, 1.0, 0.5), 0.5, 30.0),
    PerspectiveCamera(glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(0.0, 0.0, -1.0), 1.0, 20.0),
    ParallelCamera(glm::dvec3(-10.0, 2.0, 7.0), glm::dvec3(0.0), 4.0, 1.0, 40.0),
    GroundScene().Camera(),
  };
}

TEST(Frustum, CornersLieOnTheirThreePlanesAndInsideTheOthers)
{
  for (const auto& camera : TestCameras())
  {
    const auto corners = shadowmaps::FrustumCorners(camera);
    const auto planes = shadowmaps::FrustumPlanes(camera);
    for (const auto& plane : planes)
    {
      EXPECT_NEAR(glm::length(plane.Normal), 1.0, 1e-12);
    }
    for (int i = 0; i < 8; ++i)
    {
      const double scale = std::max(1.0, glm::length(corners[i]));
      for (int axis = 0; axis < 3; ++axis)
      {
        // Bit `axis` of the corner index picks the +1 (plane 2*axis+1) or -1 face.
        const int onSide = (i >> axis) & 1;
        EXPECT_NEAR(planes[2 * axis + onSide].Distance(corners[i]), 0.0, 1e-9 * scale)
          << "corner " << i << " axis " << axis;
        EXPECT_GT(planes[2 * axis + 1 - onSide].Distance(corners[i]), 1e-6 * scale)
          << "corner " << i << " axis " << axis;
      }
    }
  }
}

TEST(Frustum, PointsInsideAreOnThePositiveSideOfAllPlanes)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> inside(-0.999, 0.999);
  for (const auto& camera : TestCameras())
  {
    const auto planes = shadowmaps::FrustumPlanes(camera);
    const glm::dmat4 inverse = glm::inverse(camera);
    for (int n = 0; n < 200; ++n)
    {
      const glm::dvec3 ndc(inside(random), inside(random), inside(random));
      const glm::dvec3 p = TransformPoint(inverse, ndc);
      for (const auto& plane : planes)
      {
        EXPECT_GT(plane.Distance(p), 0.0) << ToString(ndc);
      }
    }
    // A small step out of the centre of each face: exactly that plane reports
    // the point outside.
    for (int face = 0; face < 6; ++face)
    {
      glm::dvec3 ndc(0.0);
      ndc[face / 2] = face % 2 == 0 ? -1.0 : 1.0;
      const glm::dvec3 center = TransformPoint(inverse, ndc);
      double step = std::numeric_limits<double>::infinity();
      for (int other = 0; other < 6; ++other)
      {
        step = other == face ? step : std::min(step, 0.1 * planes[other].Distance(center));
      }
      const glm::dvec3 p = center - step * planes[face].Normal;
      for (int other = 0; other < 6; ++other)
      {
        if (other == face)
        {
          EXPECT_LT(planes[other].Distance(p), 0.0) << "face " << face;
        }
        else
        {
          EXPECT_GT(planes[other].Distance(p), 0.0) << "face " << face << " other " << other;
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------
// IntersectFrustumWithBox

// True when every expected point has a match in actual within tolerance.
::testing::AssertionResult ContainsAll(const std::vector<glm::dvec3>& actual,
  const std::vector<glm::dvec3>& expected,
  double tolerance)
{
  for (const auto& e : expected)
  {
    const bool found = std::any_of(actual.begin(),
      actual.end(),
      [&](const glm::dvec3& a) { return glm::length(a - e) <= tolerance; });
    if (!found)
    {
      return ::testing::AssertionFailure() << "missing " << ToString(e);
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(IntersectFrustumWithBox, BoxInsideFrustumGivesTheBoxCorners)
{
  const glm::dmat4 camera =
    PerspectiveCamera(glm::dvec3(0.0), glm::dvec3(0.0, 0.0, -1.0), 0.1, 100.0);
  const Aabb box = MakeBox(glm::dvec3(-1.0, -1.0, -20.0), glm::dvec3(1.0, 1.0, -10.0));
  const auto body = shadowmaps::IntersectFrustumWithBox(camera, box);
  const auto corners = box.Corners();
  EXPECT_EQ(body.size(), 8u);
  EXPECT_TRUE(ContainsAll(body, { corners.begin(), corners.end() }, 1e-12));
}

TEST(IntersectFrustumWithBox, FrustumInsideBoxGivesTheFrustumCorners)
{
  for (const auto& camera : TestCameras())
  {
    const auto corners = shadowmaps::FrustumCorners(camera);
    Aabb box = BoundsOf({ corners.begin(), corners.end() });
    box.Min -= 5.0;
    box.Max += 5.0;
    const auto body = shadowmaps::IntersectFrustumWithBox(camera, box);
    EXPECT_EQ(body.size(), 8u);
    EXPECT_TRUE(ContainsAll(body, { corners.begin(), corners.end() }, 1e-9 * box.Diagonal()));
  }
}

TEST(IntersectFrustumWithBox, DisjointBodiesGiveNothing)
{
  const glm::dmat4 camera =
    PerspectiveCamera(glm::dvec3(0.0), glm::dvec3(0.0, 0.0, -1.0), 1.0, 20.0);
  const std::vector<Aabb> outside = {
    MakeBox(glm::dvec3(-1.0, -1.0, 5.0), glm::dvec3(1.0, 1.0, 10.0)),    // behind the eye
    MakeBox(glm::dvec3(-1.0, -1.0, -40.0), glm::dvec3(1.0, 1.0, -30.0)), // beyond far
    MakeBox(glm::dvec3(50.0, -1.0, -15.0), glm::dvec3(60.0, 1.0, -5.0)), // off to the side
    MakeBox(glm::dvec3(-5.0, -5.0, -0.5), glm::dvec3(5.0, 5.0, -0.2)),   // between eye and near
  };
  for (const auto& box : outside)
  {
    EXPECT_TRUE(shadowmaps::IntersectFrustumWithBox(camera, box).empty())
      << "box " << ToString(box.Min) << " - " << ToString(box.Max);
  }
  EXPECT_TRUE(shadowmaps::IntersectFrustumWithBox(camera, Aabb{}).empty());
}

TEST(IntersectFrustumWithBox, PartialOverlapIsTheIntersectionHull)
{
  struct Case
  {
    glm::dmat4 Camera;
    Aabb Box;
  };
  const GroundScene ground;
  const std::vector<Case> cases = {
    { PerspectiveCamera(glm::dvec3(0.0), glm::dvec3(0.0, 0.0, -1.0), 1.0, 20.0),
      MakeBox(glm::dvec3(0.0, 0.0, -30.0), glm::dvec3(10.0, 10.0, -5.0)) },
    { PerspectiveCamera(glm::dvec3(-15.0, 3.0, 4.0), glm::dvec3(0.0), 1.0, 15.0),
      MakeBox(glm::dvec3(-5.0), glm::dvec3(5.0)) },
    { ParallelCamera(glm::dvec3(-10.0, 2.0, 7.0), glm::dvec3(0.0), 3.0, 1.0, 14.0),
      MakeBox(glm::dvec3(-4.0, -4.0, -1.0), glm::dvec3(6.0, 4.0, 1.0)) },
    { ground.Camera(), ground.Scene },
    { AerialCamera(), ground.Scene },
  };
  // Frames in which the hull's bounds are compared with the samples: world and
  // two rotated "light" frames.
  const std::vector<glm::dmat4> frames = { glm::dmat4(1.0),
    shadowmaps::LightLookAt(glm::dvec3(0.0), glm::dvec3(1.0, 2.0, -3.0)),
    shadowmaps::LightLookAt(glm::dvec3(0.0), glm::dvec3(-0.3, 0.1, -1.0)) };

  std::mt19937 random(11);
  for (size_t c = 0; c < cases.size(); ++c)
  {
    SCOPED_TRACE("case " + std::to_string(c));
    const auto& camera = cases[c].Camera;
    const auto& box = cases[c].Box;
    const double tolerance = 1e-9 * box.Diagonal();
    const auto planes = shadowmaps::FrustumPlanes(camera);

    const auto body = shadowmaps::IntersectFrustumWithBox(camera, box);
    ASSERT_GE(body.size(), 4u);
    for (const auto& p : body)
    {
      EXPECT_TRUE(InsideBox(box, p, tolerance)) << ToString(p);
      EXPECT_TRUE(InsidePlanes(planes, p, tolerance)) << ToString(p);
    }

    std::vector<Aabb> hullBounds;
    for (const auto& frame : frames)
    {
      hullBounds.push_back(BoundsOf(body, frame));
    }
    int samplesInBoth = 0;
    for (int n = 0; n < 20000; ++n)
    {
      const glm::dvec3 p = RandomPointInBox(random, box);
      if (!InsidePlanes(planes, p, 0.0))
      {
        continue;
      }
      ++samplesInBoth;
      for (size_t f = 0; f < frames.size(); ++f)
      {
        EXPECT_TRUE(InsideBox(hullBounds[f], TransformPoint(frames[f], p), tolerance))
          << ToString(p) << " frame " << f;
      }
    }
    EXPECT_GT(samplesInBoth, 50);
  }
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

// ---------------------------------------------------------------------------
// FitCubeFaces, CubeFaceIndex

TEST(CubeFaceIndex, PicksTheDominantAxis)
{
  EXPECT_EQ(shadowmaps::CubeFaceIndex({ 1.0, 0.2, -0.3 }), 0);
  EXPECT_EQ(shadowmaps::CubeFaceIndex({ -1.0, 0.2, -0.3 }), 1);
  EXPECT_EQ(shadowmaps::CubeFaceIndex({ 0.1, 2.0, -0.3 }), 2);
  EXPECT_EQ(shadowmaps::CubeFaceIndex({ 0.1, -2.0, -0.3 }), 3);
  EXPECT_EQ(shadowmaps::CubeFaceIndex({ 0.1, 0.2, 0.3 }), 4);
  EXPECT_EQ(shadowmaps::CubeFaceIndex({ 0.1, 0.2, -0.3 }), 5);
}

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
      EXPECT_TRUE(InsideClipVolume(faces[shadowmaps::CubeFaceIndex(d)].ViewProjection(), p))
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
      const int index = shadowmaps::CubeFaceIndex(d);
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
  EXPECT_LT(focusedArea, 0.75 * wholeArea);
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

// ---------------------------------------------------------------------------
// Degenerate inputs

struct DegenerateCase
{
  std::string Name;
  glm::dmat4 Camera;
  Aabb Scene;
  glm::dvec3 LightDirection;
};

std::vector<DegenerateCase> DegenerateCases()
{
  const GroundScene ground;
  const glm::dvec3 view = ground.ViewDirection();
  const glm::dvec3 slanted(0.3, 0.2, -1.0);
  std::vector<DegenerateCase> cases = {
    { "empty scene", ground.Camera(), Aabb{}, slanted },
    { "flat scene",
      ground.Camera(),
      MakeBox(glm::dvec3(-200.0, -200.0, 0.0), glm::dvec3(200.0, 200.0, 0.0)),
      slanted },
    { "flat scene, overhead light",
      ground.Camera(),
      MakeBox(glm::dvec3(-200.0, -200.0, 0.0), glm::dvec3(200.0, 200.0, 0.0)),
      glm::dvec3(0.0, 0.0, -1.0) },
    { "point scene",
      ground.Camera(),
      MakeBox(glm::dvec3(0.0, 0.0, 2.0), glm::dvec3(0.0, 0.0, 2.0)),
      slanted },
    { "point scene at origin",
      ground.Camera(),
      MakeBox(glm::dvec3(0.0), glm::dvec3(0.0)),
      slanted },
    { "light along the view", ground.Camera(), ground.Scene, view },
    { "light against the view", ground.Camera(), ground.Scene, -view },
    { "zero light direction", ground.Camera(), ground.Scene, glm::dvec3(0.0) },
    { "parallel camera",
      ParallelCamera(ground.Eye, ground.Target, 20.0, 0.1, 500.0),
      ground.Scene,
      slanted },
    { "zero camera matrix", glm::dmat4(0.0), ground.Scene, slanted },
  };
  for (const double scale : { 1e-4, 1e5 })
  {
    const GroundScene scaled(scale);
    cases.push_back({ "scale " + std::to_string(scale), scaled.Camera(), scaled.Scene, slanted });
    cases.push_back({ "scale " + std::to_string(scale) + ", light along the view",
      scaled.Camera(),
      scaled.Scene,
      scaled.ViewDirection() });
  }
  return cases;
}

TEST(Degenerate, FitDirectionalStaysFinite)
{
  for (const auto& c : DegenerateCases())
  {
    SCOPED_TRACE(c.Name);
    const LightView fit =
      shadowmaps::FitDirectional(c.Camera, c.Scene, c.LightDirection, Resolution);
    EXPECT_TRUE(IsFiniteFit(fit));
    if (c.Scene.IsEmpty())
    {
      continue;
    }
    // Whatever the degeneracy, the part of the scene the camera sees is covered
    // (the whole scene when that part is empty).
    auto covered = shadowmaps::IntersectFrustumWithBox(c.Camera, c.Scene);
    if (covered.empty())
    {
      const auto corners = c.Scene.Corners();
      covered.assign(corners.begin(), corners.end());
    }
    for (const auto& p : covered)
    {
      EXPECT_TRUE(InsideClipVolume(fit.ViewProjection(), p));
    }
  }
}

TEST(Degenerate, FitSpotStaysFinite)
{
  for (const auto& c : DegenerateCases())
  {
    SCOPED_TRACE(c.Name);
    const glm::dvec3 center = c.Scene.IsEmpty() ? glm::dvec3(0.0) : c.Scene.Center();
    const double size = std::max(c.Scene.Diagonal(), 1.0);
    const glm::dvec3 position = center - glm::normalize(glm::dvec3(0.3, 0.2, -1.0)) * size;
    EXPECT_TRUE(IsFiniteFit(
      shadowmaps::FitSpot(c.Camera, c.Scene, position, c.LightDirection, 30.0, Resolution)));
    // A light exactly at the scene's centre, and cone angles out of range.
    EXPECT_TRUE(IsFiniteFit(
      shadowmaps::FitSpot(c.Camera, c.Scene, center, c.LightDirection, 0.0, Resolution)));
    EXPECT_TRUE(IsFiniteFit(
      shadowmaps::FitSpot(c.Camera, c.Scene, center, c.LightDirection, 120.0, Resolution)));
  }
}

TEST(Degenerate, FitCubeFacesStaysFinite)
{
  for (const auto& c : DegenerateCases())
  {
    SCOPED_TRACE(c.Name);
    const glm::dvec3 center = c.Scene.IsEmpty() ? glm::dvec3(0.0) : c.Scene.Center();
    for (const auto& position :
      { center, center + glm::dvec3(3.0, -2.0, 1.0) * std::max(c.Scene.Diagonal(), 1.0) })
    {
      for (const auto& face : shadowmaps::FitCubeFaces(c.Scene, position, Resolution))
      {
        EXPECT_TRUE(IsFiniteFit(face));
      }
      for (const auto& face :
        shadowmaps::FitCubeFacesToView(c.Camera, c.Scene, position, Resolution))
      {
        EXPECT_TRUE(IsFiniteFit(face)) << "focused on the view";
      }
    }
  }
  // Without a usable camera every face keeps the whole-scene fit and is drawn.
  const GroundScene ground;
  const glm::dmat4 broken(std::numeric_limits<double>::quiet_NaN());
  for (const auto& face :
    shadowmaps::FitCubeFacesToView(broken, ground.Scene, glm::dvec3(0.0, 0.0, 5.0), Resolution))
  {
    EXPECT_TRUE(IsFiniteFit(face));
    EXPECT_FALSE(face.OutOfView);
  }
}

TEST(Degenerate, ZeroResolutionStaysFinite)
{
  const GroundScene ground;
  EXPECT_TRUE(IsFiniteFit(
    shadowmaps::FitDirectional(ground.Camera(), ground.Scene, glm::dvec3(0.0, 0.0, -1.0), 0)));
  EXPECT_TRUE(IsFiniteFit(shadowmaps::FitSpot(ground.Camera(),
    ground.Scene,
    glm::dvec3(0.0, 0.0, 100.0),
    glm::dvec3(0.0, 0.0, -1.0),
    30.0,
    0)));
  for (const auto& face : shadowmaps::FitCubeFaces(ground.Scene, glm::dvec3(0.0, 0.0, 5.0), 0))
  {
    EXPECT_TRUE(IsFiniteFit(face));
  }
}

// ---------------------------------------------------------------------------
// SixteenBitDepthSuffices

// World distance along the view axis that one 16-bit step of window depth spans
// at distance d, measured on the projection itself.
double SixteenBitStepAt(const glm::dmat4& projection, double d)
{
  const auto window = [&](double distance) {
    const glm::dvec4 clip = projection * glm::dvec4(0.0, 0.0, -distance, 1.0);
    return 0.5 * clip.z / clip.w + 0.5;
  };
  const double h = 1e-6 * d;
  const double slope = std::abs(window(d + h) - window(d - h)) / (2.0 * h);
  return 1.0 / 65535.0 / slope;
}

LightView OrthographicView(double halfWidth, double nearPlane, double farPlane, int resolution)
{
  LightView view;
  view.Projection = glm::ortho(-halfWidth, halfWidth, -halfWidth, halfWidth, nearPlane, farPlane);
  view.TexelConstant = 2.0 * halfWidth / resolution;
  return view;
}

LightView PerspectiveView(double fovyDegrees, double nearPlane, double farPlane, int resolution)
{
  LightView view;
  view.Perspective = true;
  view.Projection = glm::perspective(glm::radians(fovyDegrees), 1.0, nearPlane, farPlane);
  view.TexelPerUnitDistance = 2.0 * std::tan(glm::radians(fovyDegrees) / 2.0) / resolution;
  return view;
}

TEST(SixteenBitDepthSuffices, WhenTheStepIsAtMostASixteenthOfATexel)
{
  // Orthographic: the step is the same everywhere.
  for (double depthRange : { 1.0, 30.0, 39.0, 41.0, 100.0, 1e4 })
  {
    SCOPED_TRACE("orthographic, depth range " + std::to_string(depthRange));
    const LightView view = OrthographicView(10.0, 5.0, 5.0 + depthRange, 2048);
    const double step = SixteenBitStepAt(view.Projection, 5.0 + 0.5 * depthRange);
    EXPECT_NEAR(step, depthRange / 65535.0, 1e-6 * step);
    EXPECT_EQ(shadowmaps::SixteenBitDepthSuffices(view), 16.0 * step <= view.TexelConstant);
    EXPECT_EQ(shadowmaps::SixteenBitDepthSuffices(view, 32.0), 32.0 * step <= view.TexelConstant);
  }
  // Perspective: steps grow as the distance squared, texels linearly; the far
  // plane decides.
  for (double farPlane : { 1.5, 3.0, 3.2, 3.4, 3.6, 10.0, 1000.0 })
  {
    SCOPED_TRACE("perspective, far plane " + std::to_string(farPlane));
    const LightView view = PerspectiveView(60.0, 1.0, farPlane, 2048);
    const double step = SixteenBitStepAt(view.Projection, farPlane);
    const double texel = view.TexelPerUnitDistance * farPlane;
    EXPECT_EQ(shadowmaps::SixteenBitDepthSuffices(view), 16.0 * step <= texel);
    EXPECT_EQ(shadowmaps::SixteenBitDepthSuffices(view, 32.0), 32.0 * step <= texel);
  }
  EXPECT_TRUE(shadowmaps::SixteenBitDepthSuffices(OrthographicView(10.0, 5.0, 35.0, 2048)));
  EXPECT_FALSE(shadowmaps::SixteenBitDepthSuffices(OrthographicView(10.0, 5.0, 105.0, 2048)));
  EXPECT_TRUE(shadowmaps::SixteenBitDepthSuffices(PerspectiveView(60.0, 1.0, 3.0, 2048)));
  EXPECT_FALSE(shadowmaps::SixteenBitDepthSuffices(PerspectiveView(60.0, 1.0, 10.0, 2048)));
  // The stricter rule that 32-bit maps must pass to go to 16 bits.
  EXPECT_FALSE(shadowmaps::SixteenBitDepthSuffices(OrthographicView(10.0, 5.0, 35.0, 2048), 32.0));
  EXPECT_TRUE(shadowmaps::SixteenBitDepthSuffices(OrthographicView(10.0, 5.0, 20.0, 2048), 32.0));
}

TEST(SixteenBitDepthSuffices, NotForWarpedLinearOrDegenerateViews)
{
  LightView warped = OrthographicView(10.0, 5.0, 6.0, 2048);
  warped.TexelSizeFromGradient = true;
  EXPECT_FALSE(shadowmaps::SixteenBitDepthSuffices(warped));
  LightView linear = OrthographicView(10.0, 5.0, 6.0, 2048);
  linear.LinearDepth = true;
  EXPECT_FALSE(shadowmaps::SixteenBitDepthSuffices(linear));

  LightView notANumber = OrthographicView(10.0, 5.0, 6.0, 2048);
  notANumber.Projection[2][2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(shadowmaps::SixteenBitDepthSuffices(notANumber));
  LightView noTexel = OrthographicView(10.0, 5.0, 6.0, 2048);
  noTexel.TexelConstant = 0.0;
  EXPECT_FALSE(shadowmaps::SixteenBitDepthSuffices(noTexel)) << "no texel size";
  LightView inverted = PerspectiveView(60.0, 1.0, 4.0, 2048);
  inverted.Projection = glm::perspective(glm::radians(60.0), 1.0, 4.0, 1.0);
  EXPECT_FALSE(shadowmaps::SixteenBitDepthSuffices(inverted)) << "far before near";
  LightView mislabelled = OrthographicView(10.0, 5.0, 6.0, 2048);
  mislabelled.Perspective = true;
  EXPECT_FALSE(shadowmaps::SixteenBitDepthSuffices(mislabelled)) << "no perspective projection";
}

// ---------------------------------------------------------------------------
// ClipToTexture, IsFinite

TEST(ClipToTexture, MapsClipCubeToUnitCube)
{
  const glm::dmat4 m = shadowmaps::ClipToTexture();
  EXPECT_EQ(m * glm::dvec4(-1.0, -1.0, -1.0, 1.0), glm::dvec4(0.0, 0.0, 0.0, 1.0));
  EXPECT_EQ(m * glm::dvec4(1.0, 1.0, 1.0, 1.0), glm::dvec4(1.0, 1.0, 1.0, 1.0));
  EXPECT_EQ(m * glm::dvec4(0.0, 0.0, 0.0, 1.0), glm::dvec4(0.5, 0.5, 0.5, 1.0));
  EXPECT_EQ(m * glm::dvec4(-1.0, 1.0, 0.5, 1.0), glm::dvec4(0.0, 1.0, 0.75, 1.0));
}

TEST(IsFinite, DetectsNanAndInfinity)
{
  EXPECT_TRUE(shadowmaps::IsFinite(glm::dmat4(1.0)));
  glm::dmat4 m(1.0);
  m[2][3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(shadowmaps::IsFinite(m));
  m[2][3] = -std::numeric_limits<double>::infinity();
  EXPECT_FALSE(shadowmaps::IsFinite(m));
}

} // namespace

TEST(ConvexPolytope, BoxCutByAPlaneHasItsVertices)
{
  const Aabb box{ glm::dvec3(0.0), glm::dvec3(1.0) };
  const auto boxPlanes = shadowmaps::BoxPlanes(box);
  std::vector<Plane> planes(boxPlanes.begin(), boxPlanes.end());
  EXPECT_EQ(shadowmaps::ConvexPolytopeVertices(planes, 1.0).size(), 8u);
  // Keep x + y + z <= 1: the corner tetrahedron, vertices (0,0,0) and the unit axes.
  planes.push_back({ glm::normalize(glm::dvec3(-1.0)), 1.0 / std::sqrt(3.0) });
  const auto vertices = shadowmaps::ConvexPolytopeVertices(planes, 1.0);
  ASSERT_FALSE(vertices.empty());
  for (const auto& v : vertices)
  {
    EXPECT_LE(v.x + v.y + v.z, 1.0 + 1e-9);
    EXPECT_GE(std::min({ v.x, v.y, v.z }), -1e-9);
  }
  for (const glm::dvec3& corner : { glm::dvec3(0.0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1) })
  {
    EXPECT_TRUE(std::any_of(vertices.begin(), vertices.end(),
      [&](const glm::dvec3& v) { return glm::length(v - corner) < 1e-9; }))
      << corner.x << " " << corner.y << " " << corner.z;
  }
  // Planes with no common point give nothing.
  planes.push_back({ glm::dvec3(1.0, 0.0, 0.0), -2.0 });
  EXPECT_TRUE(shadowmaps::ConvexPolytopeVertices(planes, 1.0).empty());
}

// The spot's near plane sits at the nearest scene point inside its cone, not at
// the scene box's nearest corner (which may be behind the light or beside the cone).
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
TEST(TileView, TilesPartitionTheMapAndKeepItsCoordinates)
{
  const Aabb scene{ glm::dvec3(-10.0, -10.0, 0.0), glm::dvec3(10.0, 10.0, 2.5) };
  const glm::dmat4 camera = glm::perspective(glm::radians(30.0), 1.0, 0.1, 40.0) *
    glm::lookAt(glm::dvec3(0, -9.5, 1.2), glm::dvec3(0, 0, 0.8), glm::dvec3(0, 0, 1));
  const LightView whole = shadowmaps::FitSpot(
    camera, scene, glm::dvec3(5.0, -2.0, 7.0), glm::dvec3(-0.3, 0.2, -1.0), 30.0, 512);
  constexpr int Columns = 3;
  constexpr int Rows = 2;
  constexpr double Margin = 2.0;
  const shadowmaps::TileGrid grid = shadowmaps::MakeTileGrid(Columns, Rows, 512, Margin);
  const auto tiles = shadowmaps::TileView(whole, grid);
  ASSERT_EQ(tiles.size(), static_cast<size_t>(Columns * Rows));
  const double inset = Margin / 512.0;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> ndc(-0.999, 0.999);
  for (int n = 0; n < 2000; ++n)
  {
    // A point of the whole map's frustum, from its NDC.
    const glm::dvec4 h = glm::inverse(whole.ViewProjection()) * glm::dvec4(ndc(random), ndc(random), ndc(random), 1.0);
    const glm::dvec3 p = glm::dvec3(h) / h.w;
    const glm::dvec4 w = whole.ViewProjection() * glm::dvec4(p, 1.0);
    int inCores = 0;
    for (size_t t = 0; t < tiles.size(); ++t)
    {
      const glm::dvec4 q = tiles[t].ViewProjection() * glm::dvec4(p, 1.0);
      const glm::dvec3 texture = glm::dvec3(q) / q.w * 0.5 + 0.5;
      EXPECT_NEAR(texture.z, (w.z / w.w) * 0.5 + 0.5, 1e-9);
      const bool inCore = texture.x >= inset && texture.x <= 1.0 - inset && texture.y >= inset &&
        texture.y <= 1.0 - inset;
      inCores += inCore;
      if (inCore)
      {
        // Tile (column, row) holds the whole map's window [column / Columns, ...),
        // which is where the receivers look for it, from the first tile.
        const glm::dvec2 u = glm::dvec2(w) / w.w * 0.5 + 0.5;
        EXPECT_EQ(static_cast<int>(t), static_cast<int>(u.y * Rows) * Columns + static_cast<int>(u.x * Columns));
        EXPECT_EQ(static_cast<int>(t), grid.TileOf(glm::dvec2(w) / w.w));
        const glm::dvec4 first =
          shadowmaps::ClipToTexture() * tiles[0].ViewProjection() * glm::dvec4(p, 1.0);
        EXPECT_EQ(static_cast<int>(t), grid.TileFromFirstTile(glm::dvec2(first) / first.w));
      }
    }
    EXPECT_EQ(inCores, 1) << "point " << n;
  }
  for (const LightView& tile : tiles)
  {
    EXPECT_TRUE(tile.Perspective);
    EXPECT_LT(tile.TexelPerUnitDistance, whole.TexelPerUnitDistance * 0.55);
    EXPECT_GT(tile.TexelPerUnitDistance, whole.TexelPerUnitDistance / 3.0);
  }
}

TEST(TileView, CountsAndMarginClamp)
{
  LightView whole;
  whole.Projection = glm::ortho(-4.0, 4.0, -2.0, 2.0, 1.0, 10.0);
  whole.TexelConstant = 8.0 / 256.0;
  const shadowmaps::TileGrid single = shadowmaps::MakeTileGrid(0, -3, 256, -5.0);
  EXPECT_EQ(single.Columns, 1);
  EXPECT_EQ(single.Rows, 1);
  EXPECT_EQ(single.WindowFraction, glm::dvec2(1.0));
  const auto one = shadowmaps::TileView(whole, single);
  ASSERT_EQ(one.size(), 1u);
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      EXPECT_NEAR(one[0].Projection[c][r], whole.Projection[c][r], 1e-12) << "a single tile without margin is the map";
    }
  }
  // The margin is clamped to a quarter of the tile: its core is then half its window.
  const shadowmaps::TileGrid clamped = shadowmaps::MakeTileGrid(2, 2, 256, 1000.0);
  EXPECT_DOUBLE_EQ(clamped.WindowFraction.x, 1.0);
  EXPECT_EQ(shadowmaps::TileView(whole, clamped).size(), 4u);
  // 2 x 2 tiles without margin: texels half the size.
  const auto halves = shadowmaps::TileView(whole, shadowmaps::MakeTileGrid(2, 2, 256, 0.0));
  EXPECT_DOUBLE_EQ(halves[3].TexelConstant, whole.TexelConstant / 2.0);

  // A warped map's projection has no window (here turned half a turn, so its
  // x and y scales are negative): tiles scale its per-distance texel by the
  // coarser window fraction.
  LightView warped = whole;
  warped.Projection = glm::rotate(glm::dmat4(1.0), glm::pi<double>(), glm::dvec3(0, 0, 1)) *
    glm::frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
  warped.Perspective = true;
  warped.TexelSizeFromGradient = true;
  warped.TexelConstant = 0.0;
  warped.TexelPerUnitDistance = 2.0 / 256.0;
  for (const auto& tile : shadowmaps::TileView(warped, shadowmaps::MakeTileGrid(3, 2, 256, 0.0)))
  {
    EXPECT_DOUBLE_EQ(tile.TexelPerUnitDistance, warped.TexelPerUnitDistance / 2.0);
    EXPECT_EQ(tile.TexelConstant, 0.0);
  }
}

TEST(TileView, PointsOutsideTheMapGetTheNearestTile)
{
  const shadowmaps::TileGrid grid = shadowmaps::MakeTileGrid(3, 2, 256, 2.0);
  EXPECT_EQ(grid.TileOf({ -5.0, -5.0 }), 0);
  EXPECT_EQ(grid.TileOf({ 5.0, -5.0 }), 2);
  EXPECT_EQ(grid.TileOf({ -5.0, 5.0 }), 3);
  EXPECT_EQ(grid.TileOf({ 5.0, 5.0 }), 5);
  EXPECT_EQ(grid.TileOf({ 0.0, 0.5 }), 4);
}
