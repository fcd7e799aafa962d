#include "ShadowMapPerspective.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowmaps
{
namespace
{

constexpr double Infinity = std::numeric_limits<double>::infinity();

glm::dvec3 ToPoint(const glm::dmat4& m, const glm::dvec3& p)
{
  const glm::dvec4 q = m * glm::dvec4(p, 1.0);
  return glm::dvec3(q) / q.w;
}

bool IsParallelProjection(const glm::dmat4& projection)
{
  return projection[2][3] == 0.0;
}

// Light-camera view in post-perspective space (an affine look-at).
glm::dmat4 LookFrom(const glm::dvec3& eye, const glm::dvec3& axis)
{
  return LightLookAt(eye, axis);
}

// Unit vector from eye along the mean of the unit directions to the points.
glm::dvec3 MeanDirection(const glm::dvec3& eye, const std::vector<glm::dvec3>& points)
{
  glm::dvec3 sum(0.0);
  for (const auto& p : points)
  {
    const double length = glm::length(p - eye);
    if (length > 0.0)
    {
      sum += (p - eye) / length;
    }
  }
  return glm::length(sum) > 0.0 ? glm::normalize(sum) : glm::dvec3(0.0, 0.0, -1.0);
}

// Tangent window and depth range of points seen by a perspective light camera.
struct LightWindow
{
  glm::dvec2 Lo{ Infinity }, Hi{ -Infinity };
  double Near = Infinity, Far = 0.0;
  bool Valid = false;
  double Area() const { return (this->Hi.x - this->Lo.x) * (this->Hi.y - this->Lo.y); }
};

LightWindow FitWindow(const glm::dmat4& view, const std::vector<glm::dvec3>& points)
{
  LightWindow window;
  window.Valid = true;
  for (const auto& p : points)
  {
    const glm::dvec3 q = ToPoint(view, p);
    const double depth = -q.z;
    // At most ~89.9 degrees off the axis: the window stays finite.
    if (!(depth > 1e-3 * glm::length(q)))
    {
      window.Valid = false;
      return window;
    }
    window.Near = std::min(window.Near, depth);
    window.Far = std::max(window.Far, depth);
    window.Lo = glm::min(window.Lo, glm::dvec2(q) / depth);
    window.Hi = glm::max(window.Hi, glm::dvec2(q) / depth);
  }
  return window;
}

} // namespace

glm::dmat4 SlideBackPostPerspective(
  const glm::dmat4& cameraView, const glm::dmat4& cameraProjection, double slideBack)
{
  const glm::dmat4& p = cameraProjection;
  if (!(slideBack > 0.0) || IsParallelProjection(p))
  {
    return p * cameraView;
  }
  // Frustum parameters of an OpenGL perspective matrix.
  const double n = p[3][2] / (p[2][2] - 1.0);
  const double f = p[3][2] / (p[2][2] + 1.0);
  const double width = 2.0 * n / p[0][0], height = 2.0 * n / p[1][1];
  const double l = 0.5 * width * (p[2][0] - 1.0), b = 0.5 * height * (p[2][1] - 1.0);
  // Same near-plane quad, seen from slideBack further back (Kozlov Fig. 14-6).
  const glm::dmat4 back = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -slideBack));
  const glm::dmat4 virtualProjection =
    glm::frustum(l, l + width, b, b + height, n + slideBack, f + slideBack);
  return virtualProjection * back * cameraView;
}

glm::dmat4 InverseProjection(const glm::dvec2& lo, const glm::dvec2& hi, double a)
{
  // x_ndc = (2 x/Z - (hi + lo)) / (hi - lo), z_ndc = a / Z, w = Z = -z.
  glm::dmat4 m(0.0);
  m[0][0] = 2.0 / (hi.x - lo.x);
  m[1][1] = 2.0 / (hi.y - lo.y);
  m[2][0] = (hi.x + lo.x) / (hi.x - lo.x);
  m[2][1] = (hi.y + lo.y) / (hi.y - lo.y);
  m[2][3] = -1.0;
  m[3][2] = a;
  return m;
}

PerspectiveMap FitPerspective(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& sceneBounds, const glm::dvec3& lightDirection, int resolution, double slideBack)
{
  const Aabb scene = sceneBounds.IsEmpty() ? Aabb{ glm::dvec3(-1.0), glm::dvec3(1.0) } : sceneBounds;
  const double lightLength = glm::length(lightDirection);
  const glm::dvec3 d = lightLength > 0.0 && std::isfinite(lightLength) ? lightDirection / lightLength
                                                                          : glm::dvec3(0.0, 0.0, -1.0);
  const glm::dmat4 camera = cameraProjection * cameraView;
  PerspectiveMap map;
  if (IsParallelProjection(cameraProjection))
  {
    // Post-perspective space of a parallel projection is affine: no warp.
    map.Light = FitDirectional(camera, scene, d, resolution);
    map.PostPerspective = camera;
    map.LightPosition = d;
    return map;
  }
  map.PostPerspective = SlideBackPostPerspective(cameraView, cameraProjection, slideBack);
  const glm::dmat4& post = map.PostPerspective;

  // Unit-cube clipping (Kozlov §14.1.3): the receivers B in post-perspective space.
  std::vector<glm::dvec3> body = IntersectFrustumWithBox(camera, scene);
  if (body.empty())
  {
    const auto corners = scene.Corners();
    for (const auto& c : corners)
    {
      if ((camera * glm::dvec4(c, 1.0)).w > 0.0)
      {
        body.push_back(c);
      }
    }
  }
  std::vector<glm::dvec3> points;
  glm::dvec3 lo(Infinity), hi(-Infinity);
  for (const auto& p : body)
  {
    const glm::dvec4 q = post * glm::dvec4(p, 1.0);
    if (q.w > 0.0)
    {
      points.push_back(glm::dvec3(q) / q.w);
      lo = glm::min(lo, points.back());
      hi = glm::max(hi, points.back());
    }
  }
  if (points.empty())
  {
    map.Light = FitDirectional(camera, scene, d, resolution);
    return map;
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-9);

  // The light's point at infinity (toward the light, -d) in post-perspective
  // space: w > 0 in front of the viewer, w < 0 behind it, w = 0 perpendicular.
  const glm::dvec4 light = post * glm::dvec4(-d, 0.0);
  const double lightXYZ = glm::length(glm::dvec3(light));
  const bool directional = !(std::abs(light.w) * 1e6 * radius > lightXYZ);

  if (directional)
  {
    // Still directional: an orthographic light camera fitted to B.
    const glm::dvec3 travel = -glm::dvec3(light) / lightXYZ;
    map.Kind = PsmLightKind::Directional;
    map.LightPosition = travel;
    const glm::dmat4 view = LookFrom(centre - travel * (4.0 * radius), travel);
    glm::dvec3 vlo(Infinity), vhi(-Infinity);
    for (const auto& p : points)
    {
      vlo = glm::min(vlo, ToPoint(view, p));
      vhi = glm::max(vhi, ToPoint(view, p));
    }
    const glm::dvec2 extent = glm::max(glm::dvec2(vhi - vlo), glm::dvec2(radius * 1e-9));
    // Casters up to the light camera's position; receivers to B's far end.
    map.Light.Projection = glm::ortho(vlo.x, vlo.x + extent.x, vlo.y, vlo.y + extent.y,
      1e-3 * radius, -vlo.z + 1e-3 * radius);
    map.Light.View = view * post;
  }
  else
  {
    const glm::dvec3 eye = glm::dvec3(light) / light.w;
    const bool inverse = light.w < 0.0;
    map.Kind = inverse ? PsmLightKind::Inverse : PsmLightKind::Point;
    map.LightPosition = eye;
    // The light camera looks from the light toward B in both cases; for the
    // inverse light, B lies at Z > 0 while casters behind the viewer come
    // through infinity (Z < 0), hence near = -a, far = +a. The light sits on
    // the plane z = (f + n) / (f - n) beyond the far face, so looking down -z
    // always sees all of B; the axis toward B's centre or the mean direction to
    // its points usually gives a smaller window (Kozlov: minimal cone), and the
    // smallest valid window is kept.
    const std::vector<glm::dvec3> axes = { centre - eye, MeanDirection(eye, points),
      glm::dvec3(0.0, 0.0, -1.0) };
    LightWindow best;
    glm::dmat4 view(1.0);
    for (const auto& axis : axes)
    {
      const glm::dmat4 candidate = LookFrom(eye, axis);
      const LightWindow window = FitWindow(candidate, points);
      if (window.Valid && (!best.Valid || window.Area() < best.Area()))
      {
        best = window;
        view = candidate;
      }
    }
    if (!best.Valid)
    {
      map.Kind = PsmLightKind::Uniform;
      map.Light = FitDirectional(camera, scene, d, resolution);
      return map;
    }
    glm::dvec2 tlo = best.Lo, thi = best.Hi;
    const double zMin = best.Near, zMax = best.Far;
    const glm::dvec2 size = glm::max(thi - tlo, glm::dvec2(1e-12));
    const glm::dvec2 margin = size * (4.0 / std::max(resolution, 1));
    tlo -= margin;
    thi = tlo + size + 2.0 * margin;
    if (inverse)
    {
      map.InverseNear = 0.999 * zMin;
      map.Light.Projection = InverseProjection(tlo, thi, map.InverseNear);
    }
    else
    {
      // Casters lie between the light and B: near toward the light.
      const double zNear = 1e-3 * zMin;
      const double zFar = zMax * 1.001;
      map.Light.Projection =
        glm::frustum(tlo.x * zNear, thi.x * zNear, tlo.y * zNear, thi.y * zNear, zNear, zFar);
    }
    map.Light.View = view * post;
  }
  map.Light.Perspective = true;
  double texel = 0.0;
  for (const auto& p : body)
  {
    texel = std::max(texel, WorldTexelSize(map.Light, p, resolution));
  }
  map.Light.TexelConstant = texel;
  return map;
}

double WorldTexelSize(const LightView& light, const glm::dvec3& world, int resolution)
{
  const glm::dmat4 m = light.ViewProjection();
  const glm::dmat4 inverse = glm::inverse(m);
  const glm::dvec4 clip = m * glm::dvec4(world, 1.0);
  const double step = 2.0 / std::max(resolution, 1);
  // Shift by one texel in NDC x and y at the same NDC depth; scaling by w keeps
  // the homogeneous point on the same side.
  const glm::dvec4 shifted = clip + glm::dvec4(step * clip.w, step * clip.w, 0.0, 0.0);
  const glm::dvec4 back = inverse * shifted;
  return glm::length(glm::dvec3(back) / back.w - world);
}

glm::dvec3 KozlovBiasedPoint(const glm::dvec3& world, const glm::dvec3& lightDirection, double a,
  double b, double texelSize)
{
  const double length = glm::length(lightDirection);
  const glm::dvec3 towardLight = length > 0.0 ? -lightDirection / length : glm::dvec3(0.0);
  return world + towardLight * (a + b * texelSize);
}

} // namespace shadowmaps
