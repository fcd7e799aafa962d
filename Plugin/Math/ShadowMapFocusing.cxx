#include "ShadowMapFocusing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace shadowmaps
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

// Corner i of a cube has x from bit 0, y from bit 1, z from bit 2.
glm::dvec3 CubeCorner(int i, const glm::dvec3& lo, const glm::dvec3& hi)
{
  return { (i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z };
}

// The 12 edges of a cube as pairs of corner indices.
const std::array<std::array<int, 2>, 12>& CubeEdges()
{
  static const std::array<std::array<int, 2>, 12> edges = { { { 0, 1 }, { 2, 3 }, { 4, 5 },
    { 6, 7 }, { 0, 2 }, { 1, 3 }, { 4, 6 }, { 5, 7 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } } };
  return edges;
}

// The 6 faces of a cube as corner-index quads in winding order.
const std::array<std::array<int, 4>, 6>& CubeFaces()
{
  static const std::array<std::array<int, 4>, 6> faces = { { { 0, 2, 6, 4 }, { 1, 3, 7, 5 },
    { 0, 1, 5, 4 }, { 2, 3, 7, 6 }, { 0, 1, 3, 2 }, { 4, 5, 7, 6 } } };
  return faces;
}

bool InsideAll(const std::array<Plane, 6>& planes, const glm::dvec3& p, double tolerance)
{
  return std::all_of(planes.begin(), planes.end(),
    [&](const Plane& plane) { return plane.Distance(p) >= -tolerance; });
}

// Adds the crossings of segments a-b with each plane that lie inside all of `inside`.
void AddEdgeCrossings(const glm::dvec3& a, const glm::dvec3& b,
  const std::array<Plane, 6>& cutting, const std::array<Plane, 6>& inside, double tolerance,
  std::vector<glm::dvec3>& out)
{
  for (const Plane& plane : cutting)
  {
    const double da = plane.Distance(a);
    const double db = plane.Distance(b);
    if ((da < 0.0) == (db < 0.0) || da == db)
    {
      continue;
    }
    const glm::dvec3 p = a + (b - a) * (da / (da - db));
    if (InsideAll(inside, p, tolerance))
    {
      out.push_back(p);
    }
  }
}

// Sutherland-Hodgman: keeps the part of a polygon where coordinate `axis` of each
// vertex satisfies sign * (v[axis] - bound) >= 0.
std::vector<glm::dvec3> ClipPolygon(
  const std::vector<glm::dvec3>& polygon, int axis, double bound, double sign)
{
  std::vector<glm::dvec3> out;
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i)
  {
    const glm::dvec3& a = polygon[i];
    const glm::dvec3& b = polygon[(i + 1) % n];
    const double da = sign * (a[axis] - bound);
    const double db = sign * (b[axis] - bound);
    if (da >= 0.0)
    {
      out.push_back(a);
    }
    if ((da >= 0.0) != (db >= 0.0))
    {
      out.push_back(a + (b - a) * (da / (da - db)));
    }
  }
  return out;
}


const std::array<glm::dvec3, 6> CubeFaceDirections = { { { 1, 0, 0 }, { -1, 0, 0 },
  { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } } };

// Tangent of a cube face's half angle: slightly over 1 (90 degree faces) so that
// filter taps at face seams stay in the map.
double CubeFaceHalfWidth(int resolution)
{
  return 1.0 + 8.0 / std::max(resolution, 1);
}

// Body points if any, else the box corners.
std::vector<glm::dvec3> BodyOrScene(const glm::dmat4& cameraViewProjection, const Aabb& scene)
{
  std::vector<glm::dvec3> body;
  if (IsFinite(cameraViewProjection))
  {
    body = IntersectFrustumWithBox(cameraViewProjection, scene);
  }
  if (body.empty())
  {
    const auto corners = scene.Corners();
    body.assign(corners.begin(), corners.end());
  }
  return body;
}
} // namespace

double SmoothStep(double low, double high, double x)
{
  if (x <= low)
  {
    return 0.0;
  }
  if (x >= high)
  {
    return 1.0;
  }
  const double t = (x - low) / (high - low);
  return t * t * (3.0 - 2.0 * t);
}

double TexelAcrossLight(const glm::dmat4& viewProjection, const glm::dvec3& p, const glm::dvec3& u,
  const glm::dvec3& v, double step, int resolution)
{
  const glm::dvec2 du = (glm::dvec2(ProjectPoint(viewProjection, p + u * step)) -
                          glm::dvec2(ProjectPoint(viewProjection, p - u * step))) / (2.0 * step);
  const glm::dvec2 dv = (glm::dvec2(ProjectPoint(viewProjection, p + v * step)) -
                          glm::dvec2(ProjectPoint(viewProjection, p - v * step))) / (2.0 * step);
  // Smallest singular value of the 2x2 Jacobian with columns du and dv.
  const double trace = glm::dot(du, du) + glm::dot(dv, dv);
  const double determinant = std::abs(du.x * dv.y - du.y * dv.x);
  const double largest2 =
    0.5 * (trace + std::sqrt(std::max(trace * trace - 4.0 * determinant * determinant, 0.0)));
  const double sigma = largest2 > 0.0 ? determinant / std::sqrt(largest2) : 0.0;
  return sigma > 0.0 && std::isfinite(sigma) ? 2.0 / std::max(resolution, 1) / sigma : 0.0;
}

QuarterTurns NearestQuarterTurns(double angle)
{
  QuarterTurns result;
  result.Turns = std::lround(angle / (0.5 * glm::pi<double>()));
  result.Residual = angle - result.Turns * 0.5 * glm::pi<double>();
  return result;
}

Aabb NonDegenerate(const Aabb& box)
{
  Aabb result = box;
  const glm::dvec3 size = box.Max - box.Min;
  const double largest = std::max({ size.x, size.y, size.z });
  const double minimum = largest > 0.0 ? largest * 1e-3 : std::max(1.0, glm::length(box.Max) * 1e-3);
  for (int axis = 0; axis < 3; ++axis)
  {
    if (size[axis] < minimum)
    {
      result.Min[axis] -= 0.5 * minimum;
      result.Max[axis] += 0.5 * minimum;
    }
  }
  return result;
}

glm::dvec3 ProjectPoint(const glm::dmat4& m, const glm::dvec3& p)
{
  const glm::dvec4 q = m * glm::dvec4(p, 1.0);
  return glm::dvec3(q) / q.w;
}

glm::dvec3 SafeDirection(const glm::dvec3& direction)
{
  const double length = glm::length(direction);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return { 0.0, 0.0, -1.0 };
  }
  return direction / length;
}

bool Aabb::IsEmpty() const
{
  return !(this->Min.x <= this->Max.x && this->Min.y <= this->Max.y && this->Min.z <= this->Max.z);
}

void Aabb::Add(const glm::dvec3& p)
{
  if (this->IsEmpty())
  {
    this->Min = this->Max = p;
    return;
  }
  this->Min = glm::min(this->Min, p);
  this->Max = glm::max(this->Max, p);
}

void Aabb::Add(const Aabb& other)
{
  if (!other.IsEmpty())
  {
    this->Add(other.Min);
    this->Add(other.Max);
  }
}

glm::dvec3 Aabb::Center() const
{
  return 0.5 * (this->Min + this->Max);
}

bool Aabb::IsUsable() const
{
  return !this->IsEmpty() && std::isfinite(this->Diagonal());
}

double Aabb::Diagonal() const
{
  return this->IsEmpty() ? 0.0 : glm::length(this->Max - this->Min);
}

std::array<glm::dvec3, 8> Aabb::Corners() const
{
  std::array<glm::dvec3, 8> corners;
  for (int i = 0; i < 8; ++i)
  {
    corners[i] = CubeCorner(i, this->Min, this->Max);
  }
  return corners;
}

Aabb Aabb::FromBounds(const double bounds[6])
{
  Aabb box;
  if (bounds && bounds[0] <= bounds[1] && bounds[2] <= bounds[3] && bounds[4] <= bounds[5])
  {
    box.Min = { bounds[0], bounds[2], bounds[4] };
    box.Max = { bounds[1], bounds[3], bounds[5] };
  }
  return box;
}

std::array<glm::dvec3, 8> FrustumCorners(const glm::dmat4& viewProjection)
{
  const glm::dmat4 inverse = glm::inverse(viewProjection);
  std::array<glm::dvec3, 8> corners;
  for (int i = 0; i < 8; ++i)
  {
    corners[i] = ProjectPoint(inverse, CubeCorner(i, glm::dvec3(-1.0), glm::dvec3(1.0)));
  }
  return corners;
}

std::array<Plane, 6> FrustumPlanes(const glm::dmat4& viewProjection)
{
  const glm::dmat4 t = glm::transpose(viewProjection); // t[i] is row i
  std::array<Plane, 6> planes;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      const glm::dvec4 row = side == 0 ? t[3] + t[axis] : t[3] - t[axis];
      const double length = glm::length(glm::dvec3(row));
      planes[2 * axis + side] = { glm::dvec3(row) / length, row.w / length };
    }
  }
  return planes;
}

std::array<Plane, 6> BoxPlanes(const Aabb& box)
{
  std::array<Plane, 6> planes;
  for (int axis = 0; axis < 3; ++axis)
  {
    glm::dvec3 n(0.0);
    n[axis] = 1.0;
    planes[2 * axis] = { n, -box.Min[axis] };
    planes[2 * axis + 1] = { -n, box.Max[axis] };
  }
  return planes;
}

std::vector<glm::dvec3> ConvexPolytopeVertices(const std::vector<Plane>& planes, double scale)
{
  // Run for every cascade in every moving frame: what does not depend on the
  // innermost loop is computed once, in the same arithmetic as there.
  const size_t count = planes.size();
  const double tolerance = 1e-9 * std::max(scale, 1e-300);
  std::vector<double> lengths(count);
  std::vector<double> slack(count);
  for (size_t i = 0; i < count; ++i)
  {
    lengths[i] = glm::length(planes[i].Normal);
    slack[i] = -tolerance * lengths[i];
  }
  std::vector<glm::dvec3> vertices;
  for (size_t i = 0; i < count; ++i)
  {
    const Plane& a = planes[i];
    for (size_t j = i + 1; j < count; ++j)
    {
      const Plane& b = planes[j];
      const glm::dvec3 ab = glm::cross(a.Normal, b.Normal);
      for (size_t k = j + 1; k < count; ++k)
      {
        const Plane& c = planes[k];
        const glm::dvec3 bc = glm::cross(b.Normal, c.Normal);
        const double determinant = glm::dot(a.Normal, bc);
        const double norms = lengths[i] * lengths[j] * lengths[k];
        if (!(std::abs(determinant) > 1e-12 * norms))
        {
          continue; // two of the planes are (nearly) parallel
        }
        // Cramer's rule for n_a.x = -d_a, n_b.x = -d_b, n_c.x = -d_c.
        const glm::dvec3 x =
          (-a.Offset * bc - b.Offset * glm::cross(c.Normal, a.Normal) - c.Offset * ab) / determinant;
        if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z))
        {
          continue;
        }
        bool inside = true;
        for (size_t m = 0; m < count && inside; ++m)
        {
          inside = planes[m].Distance(x) >= slack[m];
        }
        if (inside)
        {
          vertices.push_back(x);
        }
      }
    }
  }
  return vertices;
}

std::vector<glm::dvec3> IntersectFrustumWithBox(const glm::dmat4& viewProjection, const Aabb& box)
{
  std::vector<glm::dvec3> points;
  if (box.IsEmpty())
  {
    return points;
  }
  const auto frustumCorners = FrustumCorners(viewProjection);
  const auto frustumPlanes = FrustumPlanes(viewProjection);
  const auto boxCorners = box.Corners();
  const auto boxPlanes = BoxPlanes(box);
  const double tolerance = 1e-9 * std::max(box.Diagonal(), 1e-300);

  for (const auto& p : frustumCorners)
  {
    if (InsideAll(boxPlanes, p, tolerance))
    {
      points.push_back(p);
    }
  }
  for (const auto& p : boxCorners)
  {
    if (InsideAll(frustumPlanes, p, tolerance))
    {
      points.push_back(p);
    }
  }
  // A crossing lies on an edge of one body, hence in that body; it is a vertex
  // of the intersection only if it is also inside the other body.
  for (const auto& edge : CubeEdges())
  {
    AddEdgeCrossings(
      frustumCorners[edge[0]], frustumCorners[edge[1]], boxPlanes, boxPlanes, tolerance, points);
    AddEdgeCrossings(
      boxCorners[edge[0]], boxCorners[edge[1]], frustumPlanes, frustumPlanes, tolerance, points);
  }
  points.erase(std::remove_if(points.begin(), points.end(),
                 [](const glm::dvec3& p) { return !std::isfinite(p.x + p.y + p.z); }),
    points.end());
  return points;
}

glm::dmat4 LightLookAt(const glm::dvec3& eye, const glm::dvec3& direction)
{
  const glm::dvec3 d = SafeDirection(direction);
  const glm::dvec3 up = std::abs(d.z) < 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(0.0, 1.0, 0.0);
  return glm::lookAt(eye, eye + d, up);
}

glm::dvec2 ComputeNearAndFar(
  const glm::dmat4& lightView, const glm::dvec2& xyMin, const glm::dvec2& xyMax, const Aabb& box)
{
  if (box.IsEmpty())
  {
    return { 0.0, 0.0 };
  }
  const auto corners = box.Corners();
  double zMin = Infinity;
  double zMax = -Infinity;
  for (const auto& face : CubeFaces())
  {
    std::vector<glm::dvec3> polygon;
    for (int index : face)
    {
      polygon.push_back(ProjectPoint(lightView, corners[index]));
    }
    polygon = ClipPolygon(polygon, 0, xyMin.x, 1.0);
    polygon = ClipPolygon(polygon, 0, xyMax.x, -1.0);
    polygon = ClipPolygon(polygon, 1, xyMin.y, 1.0);
    polygon = ClipPolygon(polygon, 1, xyMax.y, -1.0);
    for (const auto& p : polygon)
    {
      zMin = std::min(zMin, p.z);
      zMax = std::max(zMax, p.z);
    }
  }
  if (zMin > zMax)
  {
    return { 0.0, 0.0 };
  }
  return { -zMax, -zMin };
}

glm::dvec2 VisibleDepthRange(
  const glm::dmat4& cameraView, const glm::dmat4& cameraProjection, const std::vector<Aabb>& boxes)
{
  const glm::dmat4 viewProjection = cameraProjection * cameraView;
  const std::array<Plane, 6> frustum = FrustumPlanes(viewProjection);
  const auto depthOf = [&cameraView](const glm::dvec3& p) {
    return -(cameraView * glm::dvec4(p, 1.0)).z;
  };
  double nearest = Infinity, farthest = -Infinity;
  for (const Aabb& box : boxes)
  {
    if (box.IsEmpty())
    {
      continue;
    }
    // Most boxes of a large scene are wholly in view or out of it: their part
    // in view is all of them or nothing, and clipping them, the costly part,
    // is left to the boxes across the frustum whose depths could widen the
    // range (the clipped box's depths lie within its corners').
    const std::array<glm::dvec3, 8> corners = box.Corners();
    const double tolerance = 1e-9 * std::max(box.Diagonal(), 1e-300);
    glm::dvec2 span(Infinity, -Infinity);
    bool inside = true;
    bool outside = false;
    for (const Plane& plane : frustum)
    {
      int behind = 0;
      for (const glm::dvec3& corner : corners)
      {
        // As InsideAll: a distance that is not a number is not inside.
        behind += plane.Distance(corner) >= -tolerance ? 0 : 1;
      }
      inside = inside && behind == 0;
      outside = outside || behind == 8;
    }
    if (outside)
    {
      continue;
    }
    for (const glm::dvec3& corner : corners)
    {
      span = glm::dvec2(std::min(span.x, depthOf(corner)), std::max(span.y, depthOf(corner)));
    }
    if (!inside && span.x >= nearest && span.y <= farthest)
    {
      continue;
    }
    if (!inside)
    {
      span = glm::dvec2(Infinity, -Infinity);
      for (const auto& p : IntersectFrustumWithBox(viewProjection, box))
      {
        span = glm::dvec2(std::min(span.x, depthOf(p)), std::max(span.y, depthOf(p)));
      }
    }
    nearest = std::min(nearest, span.x);
    farthest = std::max(farthest, span.y);
  }
  if (!(farthest >= nearest) || !std::isfinite(farthest - nearest))
  {
    return { 0.0, 0.0 };
  }
  return { nearest, farthest };
}

LightView FitDirectional(const glm::dmat4& cameraViewProjection, const Aabb& sceneBounds,
  const glm::dvec3& lightDirection, int resolution, bool stable)
{
  const Aabb scene = sceneBounds.IsEmpty() ? Aabb{ glm::dvec3(-1.0), glm::dvec3(1.0) }
                                           : NonDegenerate(sceneBounds);
  const glm::dvec3 d = SafeDirection(lightDirection);
  const double diagonal = scene.Diagonal();
  LightView fit;
  fit.View = LightLookAt(scene.Center() - d * diagonal, d);

  glm::dvec2 lo(Infinity), hi(-Infinity);
  double bodyFar = 0.0;
  for (const auto& p : BodyOrScene(cameraViewProjection, scene))
  {
    const glm::dvec3 q = ProjectPoint(fit.View, p);
    lo = glm::min(lo, glm::dvec2(q));
    hi = glm::max(hi, glm::dvec2(q));
    bodyFar = std::max(bodyFar, -q.z);
  }
  // Keep a few texels of margin so that filter kernels at B's rim stay in the map.
  const double minimumExtent = diagonal * 1e-6;
  const glm::dvec2 extent = glm::max(hi - lo, glm::dvec2(minimumExtent));
  const glm::dvec2 margin = extent * (4.0 / std::max(resolution, 1));
  lo -= margin;
  hi = lo + extent + 2.0 * margin;
  if (stable)
  {
    SnapWindowOutward(lo, hi, 2.0 * diagonal);
    bodyFar = SnapUp(bodyFar, diagonal / 64.0);
  }

  glm::dvec2 depth = ComputeNearAndFar(fit.View, lo, hi, scene);
  if (!(depth.y > depth.x))
  {
    depth = { 0.0, bodyFar };
  }
  const double range = std::max(bodyFar - depth.x, diagonal * 1e-6);
  const double zNear = depth.x - range * 1e-3;
  const double zFar = bodyFar + range * 1e-3;
  fit.Projection = glm::ortho(lo.x, hi.x, lo.y, hi.y, zNear, zFar);
  fit.Perspective = false;
  fit.TexelConstant = std::max(hi.x - lo.x, hi.y - lo.y) / std::max(resolution, 1);
  return fit;
}

LightView FitSpot(const glm::dmat4& cameraViewProjection, const Aabb& sceneBounds,
  const glm::dvec3& position, const glm::dvec3& direction, double coneAngleDegrees,
  int resolution, bool stable)
{
  const Aabb scene = sceneBounds.IsEmpty() ? Aabb{ position - 1.0, position + 1.0 }
                                           : NonDegenerate(sceneBounds);
  return FitSpotToBody(BodyOrScene(cameraViewProjection, scene), scene, position, direction,
    coneAngleDegrees, resolution, stable);
}

void SnapWindowOutward(glm::dvec2& lo, glm::dvec2& hi, double span)
{
  const double width = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(width > 0.0) || !(span > 0.0) || !std::isfinite(width))
  {
    return;
  }
  const double level = std::max(4.0, std::floor(std::log2(span / width)) + 4.0);
  const double cell = span / std::exp2(std::min(level, 40.0));
  lo = glm::floor(lo / cell) * cell;
  hi = glm::ceil(hi / cell) * cell;
}

double SnapUp(double value, double cell)
{
  return cell > 0.0 && std::isfinite(value) ? std::ceil(value / cell) * cell : value;
}

void SnapCropOutward(glm::dvec2& lo, glm::dvec2& hi, double t)
{
  SnapWindowOutward(lo, hi, 2.0 * t);
  lo = glm::max(lo, glm::dvec2(-t));
  hi = glm::min(hi, glm::dvec2(t));
}

LightView FitSpotToBody(const std::vector<glm::dvec3>& body, const Aabb& sceneBounds,
  const glm::dvec3& position, const glm::dvec3& direction, double coneAngleDegrees, int resolution,
  bool stable)
{
  const Aabb scene = sceneBounds.IsEmpty() ? Aabb{ position - 1.0, position + 1.0 } : sceneBounds;
  LightView fit;
  fit.View = LightLookAt(position, direction);
  const double halfAngle = glm::radians(std::min(std::max(coneAngleDegrees, 0.5), 80.0));
  const double t = std::tan(halfAngle);

  // Crop the cone to B's projection when all of B is in front of the light.
  glm::dvec2 lo(Infinity), hi(-Infinity);
  double bodyFar = 0.0;
  bool cropValid = true;
  const double diagonal = scene.Diagonal();
  for (const auto& p : body)
  {
    const glm::dvec3 q = ProjectPoint(fit.View, p);
    bodyFar = std::max(bodyFar, -q.z);
    if (-q.z <= diagonal * 1e-6)
    {
      cropValid = false;
      continue;
    }
    const glm::dvec2 tangent = glm::dvec2(q) / -q.z;
    lo = glm::min(lo, tangent);
    hi = glm::max(hi, tangent);
  }
  lo = glm::max(lo, glm::dvec2(-t));
  hi = glm::min(hi, glm::dvec2(t));
  if (!cropValid || !(hi.x > lo.x) || !(hi.y > lo.y))
  {
    lo = glm::dvec2(-t);
    hi = glm::dvec2(t);
  }
  const glm::dvec2 margin = (hi - lo) * (4.0 / std::max(resolution, 1));
  lo = glm::max(lo - margin, glm::dvec2(-t));
  hi = glm::min(hi + margin, glm::dvec2(t));
  double zFar = std::max(bodyFar, diagonal * 1e-3) * 1.001;
  if (stable)
  {
    SnapCropOutward(lo, hi, t);
    zFar = std::exp2(std::ceil(std::log2(zFar) * 8.0) / 8.0);
  }

  // The near plane at the nearest scene point inside the (cropped) cone: depth
  // precision goes as the ratio of far to near, and the scene's bounding box
  // often reaches behind the light or beside its cone.
  const double minimumNear = zFar * 1e-3;
  std::vector<Plane> planes;
  const glm::dmat4 cone = glm::frustum(lo.x * minimumNear, hi.x * minimumNear, lo.y * minimumNear,
                            hi.y * minimumNear, minimumNear, zFar) *
    fit.View;
  for (const auto& set : { FrustumPlanes(cone), BoxPlanes(scene) })
  {
    planes.insert(planes.end(), set.begin(), set.end());
  }
  double nearest = Infinity;
  for (const auto& p : ConvexPolytopeVertices(planes, diagonal))
  {
    nearest = std::min(nearest, -ProjectPoint(fit.View, p).z);
  }
  const double zNear = std::isfinite(nearest) ? std::max(nearest * 0.999, minimumNear) : minimumNear;
  fit.Projection = glm::frustum(lo.x * zNear, hi.x * zNear, lo.y * zNear, hi.y * zNear, zNear, zFar);
  fit.Perspective = true;
  fit.TexelPerUnitDistance = std::max(hi.x - lo.x, hi.y - lo.y) / std::max(resolution, 1);
  return fit;
}

LightView FitSpotToLitBody(const glm::dmat4& cameraViewProjection, const Aabb& scene,
  const glm::dvec3& position, const glm::dvec3& direction, double coneAngleDegrees,
  int resolution, std::vector<glm::dvec3>* litBody, bool stable)
{
  const LightView cone =
    FitSpot(cameraViewProjection, scene, position, direction, coneAngleDegrees, resolution, stable);
  std::vector<glm::dvec3> body = SpotFocusBody(cameraViewProjection, scene, cone.ViewProjection());
  const LightView fit = body.empty()
    ? cone
    : FitSpotToBody(body, scene, position, direction, coneAngleDegrees, resolution, stable);
  if (litBody)
  {
    *litBody = std::move(body);
  }
  return fit;
}

TileGrid MakeTileGrid(int columns, int rows, int resolution, double marginTexels)
{
  TileGrid grid;
  grid.Columns = std::max(columns, 1);
  grid.Rows = std::max(rows, 1);
  const double texels = std::max(resolution, 1);
  const double margin = std::min(std::max(marginTexels, 0.0), 0.25 * texels);
  // A tile's core takes texels - 2 margin texels of its window.
  grid.WindowFraction =
    glm::dvec2(1.0 / grid.Columns, 1.0 / grid.Rows) * (texels / (texels - 2.0 * margin));
  return grid;
}

glm::dvec2 TileGrid::Center(int column, int row) const
{
  return { -1.0 + (2.0 * column + 1.0) / this->Columns, -1.0 + (2.0 * row + 1.0) / this->Rows };
}

std::vector<LightView> TileView(const LightView& whole, const TileGrid& grid)
{
  const glm::dvec2 fraction = grid.WindowFraction;
  // Window sizes (near-plane extents over near, or widths) of the whole map. A
  // warped map has no such window: its texel size comes from its gradient, and
  // the tiles' texels are the whole map's over the coarser window fraction.
  const glm::dvec2 window = whole.TexelSizeFromGradient
    ? glm::dvec2(1.0)
    : glm::dvec2(2.0 / whole.Projection[0][0], 2.0 / whole.Projection[1][1]);
  const double texelScale =
    std::max(window.x * fraction.x, window.y * fraction.y) / std::max(window.x, window.y);
  std::vector<LightView> tiles;
  for (int row = 0; row < grid.Rows; ++row)
  {
    for (int column = 0; column < grid.Columns; ++column)
    {
      const glm::dvec2 center = grid.Center(column, row);
      glm::dmat4 crop(1.0);
      crop[0][0] = 1.0 / fraction.x;
      crop[1][1] = 1.0 / fraction.y;
      crop[3][0] = -center.x / fraction.x;
      crop[3][1] = -center.y / fraction.y;
      LightView tile = whole;
      tile.Projection = crop * whole.Projection;
      tile.TexelConstant *= texelScale;
      tile.TexelPerUnitDistance *= texelScale;
      tiles.push_back(tile);
    }
  }
  return tiles;
}

std::array<LightView, 6> FitCubeFaces(const Aabb& sceneBounds, const glm::dvec3& position, int resolution)
{
  const Aabb scene = sceneBounds.IsEmpty() ? Aabb{ position - 1.0, position + 1.0 }
                                           : NonDegenerate(sceneBounds);
  double farthest = 0.0;
  for (const auto& p : scene.Corners())
  {
    farthest = std::max(farthest, glm::length(p - position));
  }
  // A face sees a point at depth = its largest |coordinate| relative to the light
  // (the face's axis dominates), so the nearest depth any face needs is the
  // largest per-axis gap to the box, not the Euclidean distance to it.
  const glm::dvec3 gap = glm::max(glm::max(scene.Min - position, position - scene.Max), 0.0);
  const double outside = std::max({ gap.x, gap.y, gap.z });
  const double zFar = std::max(farthest, scene.Diagonal() * 1e-3) * 1.001;
  const double zNear = std::max(outside * 0.999, zFar * 1e-3);
  const double t = CubeFaceHalfWidth(resolution);
  std::array<LightView, 6> faces;
  for (int i = 0; i < 6; ++i)
  {
    faces[i].View = LightLookAt(position, CubeFaceDirections[i]);
    faces[i].Projection = glm::frustum(-t * zNear, t * zNear, -t * zNear, t * zNear, zNear, zFar);
    faces[i].Perspective = true;
    faces[i].TexelPerUnitDistance = 2.0 * t / std::max(resolution, 1);
  }
  return faces;
}

std::array<LightView, 6> FitCubeFacesToView(const glm::dmat4& cameraViewProjection,
  const Aabb& sceneBounds, const glm::dvec3& position, int resolution)
{
  std::array<LightView, 6> faces = FitCubeFaces(sceneBounds, position, resolution);
  if (sceneBounds.IsEmpty() || !IsFinite(cameraViewProjection))
  {
    return faces;
  }
  const Aabb scene = NonDegenerate(sceneBounds);
  const double halfAngle = glm::degrees(std::atan(CubeFaceHalfWidth(resolution)));
  for (int i = 0; i < 6; ++i)
  {
    const std::vector<glm::dvec3> body =
      SpotFocusBody(cameraViewProjection, scene, faces[i].ViewProjection());
    if (body.empty())
    {
      faces[i].OutOfView = true;
    }
    else
    {
      faces[i] =
        FitSpotToBody(body, scene, position, CubeFaceDirections[i], halfAngle, resolution, true);
    }
  }
  return faces;
}

glm::dmat4 ClipToTexture()
{
  return glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)) * glm::scale(glm::dmat4(1.0), glm::dvec3(0.5));
}

std::vector<glm::dvec3> ProjectAheadOfTheLight(
  const std::vector<glm::dvec3>& points, const glm::dmat4& lightViewProjection)
{
  std::vector<glm::dvec3> projected;
  for (const auto& p : points)
  {
    const glm::dvec4 q = lightViewProjection * glm::dvec4(p, 1.0);
    if (!(q.w > 0.0))
    {
      return {};
    }
    projected.push_back(glm::dvec3(q) / q.w);
  }
  return projected;
}

std::vector<glm::dvec3> SpotFocusBody(
  const glm::dmat4& cameraViewProjection, const Aabb& scene, const glm::dmat4& lightViewProjection)
{
  std::vector<Plane> planes;
  for (const auto& set :
    { FrustumPlanes(cameraViewProjection), BoxPlanes(scene), FrustumPlanes(lightViewProjection) })
  {
    planes.insert(planes.end(), set.begin(), set.end());
  }
  return ConvexPolytopeVertices(planes, std::max(scene.Diagonal(), 1e-300));
}

bool IsFiniteVector(const glm::dvec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

glm::dvec2 ProjectionDepthRange(const glm::dmat4& projection)
{
  // View depth z maps to clip z = A z + B, clip w = c z + d (w row (0, 0, c, d)).
  const double a = projection[2][2];
  const double b = projection[3][2];
  const double c = projection[2][3];
  const double d = projection[3][3];
  // Near: A z + B = -(c z + d); far: A z + B = c z + d. Depth = -z.
  const double nearDenominator = a + c;
  const double farDenominator = a - c;
  if (nearDenominator == 0.0 || farDenominator == 0.0)
  {
    return { 0.0, 0.0 };
  }
  const glm::dvec2 range((b + d) / nearDenominator, (b - d) / farDenominator);
  if (!std::isfinite(range.x) || !std::isfinite(range.y))
  {
    return { 0.0, 0.0 };
  }
  return range;
}

bool SixteenBitDepthSuffices(const LightView& view, double stepsPerTexel)
{
  constexpr double Steps = 65535.0;
  const glm::dmat4& p = view.Projection;
  if (view.TexelSizeFromGradient || view.LinearDepth || !IsFinite(p) || p[0][3] != 0.0 ||
    p[1][3] != 0.0)
  {
    return false;
  }
  double step = 0.0;
  double texel = view.TexelConstant;
  if (!view.Perspective && p[2][3] == 0.0 && p[3][3] == 1.0 && p[2][2] != 0.0)
  {
    step = 2.0 / std::abs(p[2][2]) / Steps;
  }
  else if (view.Perspective && p[2][3] == -1.0 && p[3][3] == 0.0)
  {
    // Window depth (f / (f - n)) (1 - n / d) at distance d: steps grow as d^2.
    const glm::dvec2 planes = ProjectionDepthRange(p);
    const double n = planes.x;
    const double f = planes.y;
    if (!(n > 0.0 && f > n))
    {
      return false;
    }
    step = f * (f - n) / n / Steps;
    texel += view.TexelPerUnitDistance * f;
  }
  else
  {
    return false;
  }
  return std::isfinite(step) && texel > 0.0 && step * stepsPerTexel <= texel;
}

bool IsFinite(const glm::dmat4& m)
{
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      if (!std::isfinite(m[c][r]))
      {
        return false;
      }
    }
  }
  return true;
}

SpotSpace FocusInSpotSpace(
  const glm::dmat4& cameraViewProjection, const Aabb& scene, const LightView& cone)
{
  SpotSpace space;
  space.Cone = cone;
  space.WorldBody = SpotFocusBody(cameraViewProjection, scene, space.ToSpace());
  space.Body = ProjectAheadOfTheLight(space.WorldBody, space.ToSpace());
  return space;
}

LightView FromSpotSpace(LightView fit, const LightView& cone)
{
  fit.View = fit.View * cone.ViewProjection();
  fit.LinearDepth = true;
  fit.Perspective = true;
  fit.TexelSizeFromGradient = true;
  fit.TexelConstant = 0.0;
  fit.TexelPerUnitDistance = cone.TexelPerUnitDistance;
  return IsFinite(fit.ViewProjection()) ? fit : cone;
}

//------------------------------------------------------------------------------
glm::dvec4 TileOfWholeImage(const glm::dvec4& tileViewport, const glm::dvec4& rendererViewport)
{
  const glm::dvec2 lo(rendererViewport.x, rendererViewport.y);
  const glm::dvec2 size = glm::dvec2(rendererViewport.z, rendererViewport.w) - lo;
  const glm::dvec2 from = glm::clamp(glm::dvec2(tileViewport.x, tileViewport.y), lo, lo + size);
  const glm::dvec2 to = glm::clamp(glm::dvec2(tileViewport.z, tileViewport.w), lo, lo + size);
  if (!(size.x > 0.0 && size.y > 0.0 && to.x > from.x && to.y > from.y))
  {
    return { -1.0, -1.0, 1.0, 1.0 };
  }
  const glm::dvec2 ndcFrom = 2.0 * (from - lo) / size - 1.0;
  const glm::dvec2 ndcTo = 2.0 * (to - lo) / size - 1.0;
  return { ndcFrom.x, ndcFrom.y, ndcTo.x, ndcTo.y };
}

//------------------------------------------------------------------------------
glm::dmat4 WholeImageProjection(const glm::dmat4& tileProjection, const glm::dvec4& tile)
{
  // The tile's clip coordinates are the whole's about the tile's centre c,
  // scaled by its half size h: x' = (x - c.x w) / h.x. Back: x = h.x x' + c.x w.
  const glm::dvec2 center(0.5 * (tile.x + tile.z), 0.5 * (tile.y + tile.w));
  const glm::dvec2 half(0.5 * (tile.z - tile.x), 0.5 * (tile.w - tile.y));
  glm::dmat4 tileToWhole(1.0);
  tileToWhole[0][0] = half.x;
  tileToWhole[1][1] = half.y;
  tileToWhole[3][0] = center.x;
  tileToWhole[3][1] = center.y;
  return tileToWhole * tileProjection;
}

} // namespace shadowmaps
