// What the unit tests of the focusing math share: cameras, a ground scene,
// random points and the containment checks of a fit.
#ifndef FocusingTestHelpers_h
#define FocusingTestHelpers_h

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

namespace focusingtest
{
using shadowmaps::Aabb;
using shadowmaps::LightView;
using shadowmaps::Plane;

constexpr int Resolution = 2048;
// Clip-space slack for "inside [-1, 1]^3": far above rounding, far below a texel.
constexpr double ClipTolerance = 1e-9;

inline std::string ToString(const glm::dvec3& p)
{
  std::ostringstream out;
  out.precision(17);
  out << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return out.str();
}

inline Aabb MakeBox(const glm::dvec3& min, const glm::dvec3& max)
{
  Aabb box;
  box.Min = min;
  box.Max = max;
  return box;
}

inline glm::dvec3 TransformPoint(const glm::dmat4& m, const glm::dvec3& p)
{
  const glm::dvec4 q = m * glm::dvec4(p, 1.0);
  return glm::dvec3(q) / q.w;
}

// Distance in front of the eye of a view matrix (view space looks down -z).
inline double ViewDepth(const glm::dmat4& view, const glm::dvec3& p)
{
  return -TransformPoint(view, p).z;
}

// World z is up unless the camera looks (nearly) straight up or down.
inline glm::dmat4 CameraLookAt(const glm::dvec3& eye, const glm::dvec3& target)
{
  const bool vertical = std::abs(glm::normalize(target - eye).z) > 0.99;
  return glm::lookAt(eye, target, vertical ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0));
}

inline glm::dmat4 PerspectiveCamera(const glm::dvec3& eye,
  const glm::dvec3& target,
  double zNear,
  double zFar)
{
  return glm::perspective(glm::radians(60.0), 16.0 / 9.0, zNear, zFar) * CameraLookAt(eye, target);
}

inline glm::dmat4 ParallelCamera(const glm::dvec3& eye,
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
inline glm::dmat4 AerialCamera(double scale = 1.0)
{
  return PerspectiveCamera(
    glm::dvec3(0.0, -250.0, 60.0) * scale, glm::dvec3(0.0), 1.0 * scale, 600.0 * scale);
}

inline bool InsidePlanes(const std::array<Plane, 6>& planes, const glm::dvec3& p, double tolerance)
{
  return std::all_of(planes.begin(),
    planes.end(),
    [&](const Plane& plane) { return plane.Distance(p) >= -tolerance; });
}

inline bool InsideBox(const Aabb& box, const glm::dvec3& p, double tolerance)
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

inline Aabb BoundsOf(const std::vector<glm::dvec3>& points, const glm::dmat4& frame = glm::dmat4(1.0))
{
  Aabb bounds;
  for (const auto& p : points)
  {
    bounds.Add(TransformPoint(frame, p));
  }
  return bounds;
}

inline glm::dvec3 RandomPointInBox(std::mt19937& random, const Aabb& box)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  return box.Min + (box.Max - box.Min) * glm::dvec3(unit(random), unit(random), unit(random));
}

inline glm::dvec3 RandomDirection(std::mt19937& random)
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
inline bool RayBoxInterval(const glm::dvec3& origin,
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
inline std::vector<glm::dvec3> GridPoints(const Aabb& box, int nx, int ny, int nz)
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

inline ::testing::AssertionResult InsideClipVolume(const glm::dmat4& viewProjection,
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

inline ::testing::AssertionResult IsFiniteFit(const LightView& fit)
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
inline void CheckDirectionalFit(const glm::dmat4& camera,
  const Aabb& scene,
  const glm::dvec3& lightDirection,
  bool stable = false)
{
  const LightView fit = shadowmaps::FitDirectional(camera, scene, lightDirection, Resolution, stable);
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

inline std::vector<glm::dvec3> TestLightDirections(const glm::dvec3& viewDirection)
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

// The cube face (order of FitCubeFaces: +x, -x, +y, -y, +z, -z) that sees
// direction d: its dominant axis.
inline int DominantAxisFace(const glm::dvec3& d)
{
  const glm::dvec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z)
  {
    return d.x >= 0.0 ? 0 : 1;
  }
  if (a.y >= a.z)
  {
    return d.y >= 0.0 ? 2 : 3;
  }
  return d.z >= 0.0 ? 4 : 5;
}

// Index (row * Columns + column) of the tile whose core holds a point of the
// whole map's NDC; points outside the map get the nearest tile.
inline int TileOf(const shadowmaps::TileGrid& grid, const glm::dvec2& wholeNdc)
{
  const glm::dvec2 cells = glm::floor((wholeNdc * 0.5 + 0.5) * glm::dvec2(grid.Columns, grid.Rows));
  const int column = static_cast<int>(std::min(std::max(cells.x, 0.0), grid.Columns - 1.0));
  const int row = static_cast<int>(std::min(std::max(cells.y, 0.0), grid.Rows - 1.0));
  return row * grid.Columns + column;
}

// TileOf a point given by its texture coordinates in the first tile.
inline int TileFromFirstTile(const shadowmaps::TileGrid& grid, const glm::dvec2& firstTileTexture)
{
  const glm::dvec2 ndc = 2.0 * firstTileTexture - 1.0;
  return TileOf(grid, ndc * grid.WindowFraction + grid.Center(0, 0));
}
} // namespace focusingtest

#endif
