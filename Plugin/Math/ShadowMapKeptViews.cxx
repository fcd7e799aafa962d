#include "ShadowMapKeptViews.h"

#include "ShadowMapPerspective.h" // For WorldTexelSize

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowmaps
{
namespace
{
// Relative slack of the clip-space comparisons: a view compared with itself
// holds its own boundary.
constexpr double ClipTolerance = 1e-6;
// Receivers look a map up beyond where they are (filter taps, normal offset):
// a kept view keeps the room the fresh fit leaves at its sides, up to the
// receivers' reach and at least this many texels (the warped fits leave 4, TSM
// none), less half a texel (a trapezoid's sides pass a hair from the body's
// corners, differently in each).
constexpr double SideRoomTexels = 3.0;
constexpr double SideRoomSlackTexels = 0.5;

template <class... PlaneSets>
std::vector<Plane> Joined(const PlaneSets&... sets)
{
  std::vector<Plane> planes;
  (planes.insert(planes.end(), sets.begin(), sets.end()), ...);
  return planes;
}

// The world plane where clip `row` equals `value` times clip w, facing where it
// is larger (sign 1) or smaller (sign -1).
Plane ClipPlane(const glm::dmat4& viewProjection, int row, double value, double sign)
{
  const glm::dmat4 t = glm::transpose(viewProjection); // t[i] is row i
  const glm::dvec4 plane = sign * (t[row] - value * t[3]);
  const double length = glm::length(glm::dvec3(plane));
  return { glm::dvec3(plane) / length, plane.w / length };
}

// How far inside its map's sides `p` lies, in NDC units; -infinity behind the map.
double SideRoom(const glm::dmat4& viewProjection, const glm::dvec3& p)
{
  const glm::dvec4 c = viewProjection * glm::dvec4(p, 1.0);
  return c.w > 0.0 ? 1.0 - std::max(std::abs(c.x), std::abs(c.y)) / c.w
                   : -std::numeric_limits<double>::infinity();
}

bool BeforeFar(const glm::dmat4& viewProjection, const glm::dvec3& p)
{
  const glm::dvec4 c = viewProjection * glm::dvec4(p, 1.0);
  return c.w > 0.0 && c.z <= c.w + ClipTolerance * c.w;
}

// Stricter than the casters need (they are drawn with depth clamping), which
// only costs a refit; linear-depth views store what the casters compute.
bool BeyondNear(const glm::dmat4& viewProjection, const glm::dvec3& p)
{
  const glm::dvec4 c = viewProjection * glm::dvec4(p, 1.0);
  return c.w > 0.0 && c.z >= -c.w - ClipTolerance * c.w;
}

bool AllFinite(std::initializer_list<const glm::dmat4*> matrices)
{
  return std::all_of(matrices.begin(), matrices.end(), [](const glm::dmat4* m) { return IsFinite(*m); });
}

// The rectangle of the points' map coordinates, as the four planes of the
// light rays through its sides.
std::array<Plane, 4> FootprintPlanes(const glm::dmat4& viewProjection, const std::vector<glm::dvec3>& points)
{
  glm::dvec2 lo(1.0);
  glm::dvec2 hi(-1.0);
  for (const auto& p : points)
  {
    const glm::dvec3 ndc = ProjectPoint(viewProjection, p);
    lo = glm::min(lo, glm::dvec2(ndc));
    hi = glm::max(hi, glm::dvec2(ndc));
  }
  return { ClipPlane(viewProjection, 0, lo.x, 1.0), ClipPlane(viewProjection, 0, hi.x, -1.0),
    ClipPlane(viewProjection, 1, lo.y, 1.0), ClipPlane(viewProjection, 1, hi.y, -1.0) };
}

// The side planes of a spot's square cone frustum; none for other lights.
std::vector<Plane> LitPlanes(const LightRays& rays)
{
  if (!rays.Positional || !(rays.ConeAngleDegrees < 90.0))
  {
    return {};
  }
  const glm::dmat4 cone =
    glm::perspective(glm::radians(2.0 * rays.ConeAngleDegrees), 1.0, 1.0, 2.0) *
    LightLookAt(rays.Position, SafeDirection(rays.Direction));
  const auto planes = FrustumPlanes(cone);
  return { planes.begin(), planes.begin() + 4 };
}

double TexelRatio(const LightView& kept, const LightView& fresh, const glm::dvec3& p,
  const LightRays& rays, double step, int resolution)
{
  const glm::dvec4 towardLight =
    rays.Positional ? glm::dvec4(rays.Position, 1.0) : glm::dvec4(-rays.Direction, 0.0);
  const double keptTexel = WorldTexelSize(kept, p, towardLight, step, resolution);
  const double freshTexel = WorldTexelSize(fresh, p, towardLight, step, resolution);
  if (!(keptTexel > 0.0))
  {
    return std::numeric_limits<double>::infinity();
  }
  return freshTexel > 0.0 ? keptTexel / freshTexel : 1.0;
}
} // namespace

//------------------------------------------------------------------------------
bool KeptViewServes(const LightView& kept, const LightView& fresh,
  const glm::dmat4& cameraViewProjection, const Aabb& scene, const LightRays& rays, int resolution,
  double maximumTexelRatio, double reachTexels)
{
  const glm::dmat4 keptClip = kept.ViewProjection();
  const glm::dmat4 freshClip = fresh.ViewProjection();
  const double scale = scene.Diagonal();
  if (!AllFinite({ &keptClip, &freshClip, &cameraViewProjection }) || !(scale > 0.0) ||
    !std::isfinite(scale))
  {
    return false;
  }
  const auto camera = FrustumPlanes(cameraViewProjection);
  const auto held = FrustumPlanes(freshClip);
  const auto box = BoxPlanes(scene);
  const std::vector<Plane> lit = LitPlanes(rays);
  const std::vector<glm::dvec3> body = ConvexPolytopeVertices(Joined(camera, held, box, lit), scale);
  // Nothing to compare by (or planes that meet nowhere): the fresh fit.
  if (body.empty())
  {
    return false;
  }
  const double texel = 2.0 / std::max(resolution, 1); // in NDC units
  for (const auto& p : body)
  {
    const double needed = std::max(
      std::min(SideRoom(freshClip, p), std::max(SideRoomTexels, reachTexels) * texel) -
        SideRoomSlackTexels * texel,
      -ClipTolerance);
    if (!(SideRoom(keptClip, p) >= needed) || !BeforeFar(keptClip, p))
    {
      return false;
    }
  }
  const auto footprint = FootprintPlanes(keptClip, body);
  for (const auto& p : ConvexPolytopeVertices(Joined(held, box, lit, footprint), scale))
  {
    if (!BeyondNear(keptClip, p))
    {
      return false;
    }
  }
  const double step = scale * 1e-5;
  return std::all_of(body.begin(), body.end(), [&](const glm::dvec3& p) {
    return TexelRatio(kept, fresh, p, rays, step, resolution) <= maximumTexelRatio;
  });
}

//------------------------------------------------------------------------------
Camera WidenedCamera(const Camera& camera, double backward, double degrees)
{
  // A glm::frustum-style matrix (VTK's cameras make them too, up to a scale);
  // stereo and sheared projections are left alone.
  const double w = -camera.Projection[2][3];
  const glm::dmat4 p = camera.Projection / (w > 0.0 ? w : 1.0);
  const bool frustum = w > 0.0 && p[3][3] == 0.0 && p[3][0] == 0.0 && p[3][1] == 0.0 &&
    p[0][0] > 0.0 && p[1][1] > 0.0 && IsFinite(p);
  if (!frustum || !(backward > 0.0) || !(degrees > 0.0) || !std::isfinite(backward))
  {
    return camera;
  }
  // The sides' slopes (x / depth at depth 1).
  const double left = (p[2][0] - 1.0) / p[0][0];
  const double right = (p[2][0] + 1.0) / p[0][0];
  const double bottom = (p[2][1] - 1.0) / p[1][1];
  const double top = (p[2][1] + 1.0) / p[1][1];
  const double turn = glm::radians(std::min(degrees, 30.0));
  const auto outward = [turn](double slope, double sign) {
    const double angle = std::atan(slope);
    const double turned = angle + sign * turn;
    return std::tan(sign > 0.0 ? std::max(angle, std::min(1.5, turned))
                               : std::min(angle, std::max(-1.5, turned)));
  };
  const glm::dvec2 planes = ProjectionDepthRange(p);
  const double zNear = planes.x + backward;
  const double zFar = planes.y + backward;
  Camera widened;
  widened.View = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -backward)) * camera.View;
  widened.Projection = glm::frustum(outward(left, -1.0) * zNear, outward(right, 1.0) * zNear,
    outward(bottom, -1.0) * zNear, outward(top, 1.0) * zNear, zNear, zFar);
  return widened;
}
} // namespace shadowmaps
