// Unit tests: Boxes, frusta and their intersection, the convex polytopes of the focus body (Plugin/Math/ShadowMapFocusing).
#include "FocusingTestHelpers.h"

using namespace focusingtest;

namespace
{
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
} // namespace
