#include "ShadowMapPerspective.h"

#include "ShadowMapWarping.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace shadowmaps
{
namespace
{

constexpr double Infinity = std::numeric_limits<double>::infinity();
// cos 60 degrees: see SlideBackKeepingTheLightAway.
constexpr double WidestLightConeCosine = 0.5;

// Near plane distance of a projection (0 if undefined).
double NearDistance(const glm::dmat4& projection)
{
  return ProjectionDepthRange(projection).x;
}

// The light camera is fitted in post-perspective space scaled by a^(1 - weight),
// a = the camera's near-plane half size (x, y) and half depth range (z). As the
// weight goes to 0 the virtual camera slides back to infinity and
// post-perspective space tends to the camera's view space divided by a:
// stretched thousands of times more across than in depth, where a light a few
// degrees off the view looks almost perpendicular to it and the map swings
// fast. Scaled by a it tends to view space itself, whose cones and
// perpendiculars are the world's; at weight 1 it is post-perspective space.
glm::dmat4 FittingScale(const glm::dmat4& cameraProjection, double weight)
{
  const glm::dvec2 planes = ProjectionDepthRange(cameraProjection);
  const double near = planes.x;
  const double far = planes.y;
  const glm::dvec3 a(near / cameraProjection[0][0], near / cameraProjection[1][1], 0.5 * (far - near));
  return glm::scale(glm::dmat4(1.0), glm::pow(a, glm::dvec3(1.0 - weight)));
}

bool IsParallelProjection(const glm::dmat4& projection)
{
  return projection[2][3] == 0.0;
}

// View matrix of a light camera at `origin` whose camera x, y and -z axes are
// right, up and forward: camera coordinates are the coefficients of
// (p - origin) in that basis.
glm::dmat4 FrameView(
  const glm::dvec3& origin, const glm::dvec3& right, const glm::dvec3& up, const glm::dvec3& forward)
{
  return glm::inverse(glm::dmat4(
    glm::dvec4(right, 0.0), glm::dvec4(up, 0.0), glm::dvec4(-forward, 0.0), glm::dvec4(origin, 1.0)));
}

// The image of direction v at world point p under the projective map m.
glm::dvec3 PushForward(const glm::dmat4& m, const glm::dvec3& p, const glm::dvec3& v)
{
  const glm::dvec4 q = m * glm::dvec4(p, 1.0);
  const glm::dvec4 dq = m * glm::dvec4(v, 0.0);
  return (glm::dvec3(dq) - glm::dvec3(q) / q.w * dq.w) / q.w;
}

// Axis of the narrowest cone from eye that holds every point (Kozlov's minimal
// cone around B). The narrowest cone is unique, so its axis moves continuously
// with the points; it is among the cones whose rim passes through two or three
// of them: the candidate whose widest point is nearest wins. The zero vector when
// a point is at the eye or the cone would be (nearly) a half-space.
glm::dvec3 NarrowestConeAxis(const glm::dvec3& eye, const std::vector<glm::dvec3>& points)
{
  std::vector<glm::dvec3> u;
  for (const auto& p : points)
  {
    const double length = glm::length(p - eye);
    if (!(length > 0.0))
    {
      return glm::dvec3(0.0);
    }
    u.push_back((p - eye) / length);
  }
  double bestCosine = -1.0;
  glm::dvec3 best(0.0);
  auto consider = [&](glm::dvec3 axis) {
    const double length = glm::length(axis);
    if (!(length > 1e-12))
    {
      return;
    }
    axis /= length;
    double cosine = 1.0;
    for (const auto& v : u)
    {
      cosine = std::min(cosine, glm::dot(axis, v));
    }
    if (cosine > bestCosine)
    {
      bestCosine = cosine;
      best = axis;
    }
  };
  const size_t n = u.size();
  for (size_t i = 0; i < n; ++i)
  {
    for (size_t j = i + 1; j < n; ++j)
    {
      consider(u[i] + u[j]);
      for (size_t k = j + 1; k < n; ++k)
      {
        const glm::dvec3 normal = glm::cross(u[j] - u[i], u[k] - u[i]);
        consider(glm::dot(normal, u[i]) >= 0.0 ? normal : -normal);
      }
    }
  }
  if (n == 1)
  {
    best = u.front();
    bestCosine = 1.0;
  }
  return bestCosine > 1e-3 ? best : glm::dvec3(0.0);
}

} // namespace

bool StaysDirectional(const glm::dvec4& light, double radius)
{
  return !(std::abs(light.w) * 1e6 * radius > glm::length(glm::dvec3(light)));
}

namespace
{

// Cosine of the half-angle of the narrowest cone from the light's position in
// post-perspective space `post` that holds the body's points; 1 for a light that
// stays directional there, -1 when no cone narrower than a half-space holds them.
double LightConeCosine(
  const glm::dmat4& post, const std::vector<glm::dvec3>& body, const glm::dvec4& towardLight)
{
  const glm::dvec4 light = post * towardLight;
  std::vector<glm::dvec3> points;
  glm::dvec3 lo(Infinity), hi(-Infinity);
  for (const auto& p : body)
  {
    points.push_back(ProjectPoint(post, p));
    lo = glm::min(lo, points.back());
    hi = glm::max(hi, points.back());
  }
  if (StaysDirectional(light, 0.5 * glm::length(hi - lo)))
  {
    return 1.0;
  }
  const glm::dvec3 eye = glm::dvec3(light) / light.w;
  const glm::dvec3 axis = NarrowestConeAxis(eye, points);
  if (glm::length(axis) == 0.0)
  {
    return -1.0;
  }
  double cosine = 1.0;
  for (const auto& p : points)
  {
    cosine = std::min(cosine, glm::dot(axis, glm::normalize(p - eye)));
  }
  return cosine;
}

// The smallest slide-back from `start` on at which the light sees B within a
// cone of half-angle acos(minimumCosine) in post-perspective space. Near B the
// light's position makes the map change fastest as the light turns, and at B's
// silhouette the map would need a half-space. `start` when no slide-back up to
// 2^40 near distances reaches it (a spot light sees B as widely from any
// slide-back as from its own position).
double SlideBackKeepingTheLightAway(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const std::vector<glm::dvec3>& body, const glm::dvec4& towardLight, double start,
  double minimumCosine, double weight)
{
  const glm::dmat4 scale = FittingScale(cameraProjection, weight);
  auto cosineAt = [&](double slideBack) {
    return LightConeCosine(
      scale * SlideBackPostPerspective(cameraView, cameraProjection, slideBack), body, towardLight);
  };
  if (cosineAt(start) >= minimumCosine)
  {
    return start;
  }
  double lo = start, hi = std::max(start, NearDistance(cameraProjection));
  for (int i = 0; i < 40 && cosineAt(hi) < minimumCosine; ++i)
  {
    lo = hi;
    hi *= 2.0;
  }
  if (cosineAt(hi) < minimumCosine)
  {
    return start;
  }
  for (int i = 0; i < 50; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (cosineAt(mid) >= minimumCosine ? hi : lo) = mid;
  }
  return hi;
}

// Forward axis of the light camera at eye. Looking down -z, its image plane is
// parallel to the screen and PSM's texels follow the screen's; from a light
// beside the unit cube, -z sees B nearly edge-on, so the axis turns toward the
// narrowest cone's as B's widest angle from -z grows from 26 to 90 degrees (a
// wide blend: the light's post-perspective position moves fast as it turns).
// The blend is scaled by the warp's weight, so that at weight 0 the axis is the
// light's direction and the map the uniform one. Both axes see all of B in
// front, and so does any blend of them. Zero when none does.
glm::dvec3 LightCameraForward(
  const glm::dvec3& eye, const std::vector<glm::dvec3>& points, double weight)
{
  const glm::dvec3 cone = NarrowestConeAxis(eye, points);
  if (glm::length(cone) == 0.0)
  {
    return cone;
  }
  const glm::dvec3 down(0.0, 0.0, -1.0);
  double cosine = 1.0;
  for (const auto& p : points)
  {
    cosine = std::min(cosine, glm::dot(down, glm::normalize(p - eye)));
  }
  const double t = weight * glm::smoothstep(0.0, 0.9, cosine);
  return glm::normalize(glm::mix(cone, down, t));
}

// The image, on the plane one unit in front of a light camera at the origin of
// q looking along forward, of direction v at the point q.
glm::dvec3 ImageDirection(const glm::dvec3& v, const glm::dvec3& q, const glm::dvec3& forward)
{
  const double depth = glm::dot(q, forward);
  return (v * depth - q * glm::dot(v, forward)) / (depth * depth);
}

// The part of v perpendicular to the unit vector axis.
glm::dvec3 Perpendicular(const glm::dvec3& v, const glm::dvec3& axis)
{
  return v - glm::dot(v, axis) * axis;
}

// View of a light camera at eye looking along the unit vector forward, its image
// turned so that `up` (perpendicular to forward) points up and `right` to the
// right: orthonormal axes, so the window fits B without shear.
glm::dmat4 TurnedView(const glm::dvec3& eye, const glm::dvec3& forward, const glm::dvec3& right,
  const glm::dvec3& up)
{
  const glm::dvec3 y = glm::normalize(up);
  glm::dvec3 x = glm::cross(forward, y);
  if (glm::dot(x, right) < 0.0)
  {
    x = -x;
  }
  return FrameView(eye, x, y, forward);
}


// Tangent window and depth range of points seen by a perspective light camera.
struct LightWindow
{
  glm::dvec2 Lo{ Infinity }, Hi{ -Infinity };
  double Near = Infinity, Far = 0.0;
  bool Valid = false;
};

LightWindow FitWindow(const glm::dmat4& view, const std::vector<glm::dvec3>& points)
{
  LightWindow window;
  window.Valid = true;
  for (const auto& p : points)
  {
    const glm::dvec3 q = ProjectPoint(view, p);
    const double depth = -q.z;
    // The camera's axis (NarrowestConeAxis) keeps every point well in front.
    if (!(depth > 0.0) || !IsFiniteVector(q))
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

// Vertices of B = camera frustum ∩ scene; when they do not meet, the scene's
// corners in front of the camera.
std::vector<glm::dvec3> PerspectiveBody(const glm::dmat4& camera, const Aabb& scene)
{
  std::vector<glm::dvec3> body = IntersectFrustumWithBox(camera, scene);
  if (body.empty())
  {
    for (const auto& c : scene.Corners())
    {
      if ((camera * glm::dvec4(c, 1.0)).w > 0.0)
      {
        body.push_back(c);
      }
    }
  }
  return body;
}

// Mid-depth of B along the camera's axis (the near plane when B is empty).
double TypicalDepth(
  const glm::dmat4& cameraView, const glm::dmat4& cameraProjection, const std::vector<glm::dvec3>& body)
{
  double nearest = Infinity, farthest = 0.0;
  for (const auto& p : body)
  {
    const double depth = -(cameraView * glm::dvec4(p, 1.0)).z;
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  return body.empty() ? NearDistance(cameraProjection) : 0.5 * (nearest + farthest);
}

// The fitting space of a PSM (post-perspective space, FittingScale) with B's
// points in it and the uniform map's axes carried into it.
struct PerspectiveSpace
{
  glm::dmat4 Transform{ 1.0 };
  std::vector<glm::dvec3> Points;
  glm::dvec3 Centre{ 0.0 };
  double Radius = 0.0;
  /// Where the axes are carried: the camera's axis at B's typical depth (off the
  /// axis, the image of a step in depth is mostly sideways), and that point here.
  glm::dvec3 AxisPoint{ 0.0 };
  glm::dvec3 AxisPointImage{ 0.0 };
  glm::dvec3 Right{ 0.0 }, Up{ 0.0 };
  /// A point light's uniform map: its axis carried into this space at the
  /// light (zero for a directional light, whose narrowest cone tends to it).
  glm::dvec3 Forward{ 0.0 };
};

// What a PSM needs of its light: the homogeneous point toward it ((-d, 0) for a
// directional light, (P, 1) for a spot at P) and its uniform map, whose view's
// axes orient the PSM's and whose matrices it returns when it cannot warp.
struct PerspectiveLight
{
  glm::dvec4 TowardLight{ 0.0, 0.0, 1.0, 0.0 };
  LightView Uniform;
  bool Positional = false;
};

// The light camera's view for an orthographic (Directional) or perspective fit:
// the uniform map's axes, as seen by that camera, orient its image, so the map
// turns continuously with the light and does not flip where the light passes
// from in front of the viewer to behind; as the weight goes to 0 they become the
// uniform map's own axes.
LightView FitDirectionalInSpace(const PerspectiveSpace& space, const glm::dvec3& travel, int resolution)
{
  const glm::dmat4 view = TurnedView(space.Centre - travel * (4.0 * space.Radius), travel,
    Perpendicular(space.Right, travel), Perpendicular(space.Up, travel));
  glm::dvec3 lo(Infinity), hi(-Infinity);
  for (const auto& p : space.Points)
  {
    lo = glm::min(lo, ProjectPoint(view, p));
    hi = glm::max(hi, ProjectPoint(view, p));
  }
  const glm::dvec2 extent = glm::max(glm::dvec2(hi - lo), glm::dvec2(space.Radius * 1e-9));
  const glm::dvec2 margin = extent * (4.0 / std::max(resolution, 1));
  const glm::dvec2 start = glm::dvec2(lo) - margin;
  const glm::dvec2 end = start + extent + 2.0 * margin;
  // Casters up to the light camera's position; receivers to B's far end.
  const double depth = std::max(-lo.z, 4.0 * space.Radius);
  LightView fit;
  fit.Projection = glm::ortho(start.x, end.x, start.y, end.y, 1e-3 * depth, depth * (1.0 + 1e-3));
  fit.View = view * space.Transform;
  return fit;
}

// The light camera at eye looks toward B (LightCameraForward); for the inverse
// light, B lies at Z > 0 while casters behind the viewer come through infinity
// (Z < 0), hence near = -a, far = +a. False when no view holds B in front.
bool FitPointInSpace(const PerspectiveSpace& space, const glm::dvec3& eye, bool inverse,
  double weight, int resolution, LightView& fit, double& inverseNear)
{
  glm::dvec3 forward = LightCameraForward(eye, space.Points, weight);
  if (glm::length(space.Forward) > 0.0 && glm::length(forward) > 0.0)
  {
    // Toward the uniform map's own axis as the weight goes to 0.
    forward = glm::normalize(glm::mix(space.Forward, forward, weight));
  }
  const glm::dvec3 toAxisPoint = space.AxisPointImage - eye;
  if (!(glm::dot(toAxisPoint, forward) > 0.0))
  {
    return false;
  }
  const glm::dmat4 view = TurnedView(eye, forward, ImageDirection(space.Right, toAxisPoint, forward),
    ImageDirection(space.Up, toAxisPoint, forward));
  const LightWindow window = FitWindow(view, space.Points);
  if (!window.Valid)
  {
    return false;
  }
  const glm::dvec2 size = glm::max(window.Hi - window.Lo, glm::dvec2(1e-12));
  const glm::dvec2 margin = size * (4.0 / std::max(resolution, 1));
  const glm::dvec2 lo = window.Lo - margin;
  const glm::dvec2 hi = lo + size + 2.0 * margin;
  if (inverse)
  {
    inverseNear = 0.999 * window.Near;
    fit.Projection = InverseProjection(lo, hi, inverseNear);
  }
  else
  {
    // Casters lie between the light and B, but the near plane stays close to B:
    // the pass renders casters with depth clamping, so those nearer the light
    // land on the near plane and still occlude everything behind it, while depth
    // keeps its precision where the receivers are. A near plane toward the light
    // (a thousandth of B's distance) left float depth too coarse to tell a
    // receiver from the surface it lies on: a spot ahead of a street-level
    // camera had acne over most of the street.
    const double zNear = 0.5 * window.Near;
    fit.Projection =
      glm::frustum(lo.x * zNear, hi.x * zNear, lo.y * zNear, hi.y * zNear, zNear, window.Far * 1.001);
  }
  fit.View = view * space.Transform;
  return true;
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
  const glm::dvec2 planes = ProjectionDepthRange(p);
  const double n = planes.x;
  const double f = planes.y;
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

namespace
{
// For a point light, the point on its uniform map's axis at B's mean distance
// along it: in front of the light camera, where the axes are carried.
glm::dvec3 AxisPointOfLight(const PerspectiveLight& light, const std::vector<glm::dvec3>& body)
{
  const glm::dvec3 position(light.TowardLight);
  const glm::dvec3 axis = -glm::dvec3(glm::row(light.Uniform.View, 2));
  double distance = 0.0;
  for (const auto& p : body)
  {
    distance += glm::dot(p - position, axis) / double(body.size());
  }
  return position + axis * distance;
}

// Where a ray from p (inside the box) along v leaves the box, going at most
// limit times v; p when v is zero.
glm::dvec3 ExitFromBox(const Aabb& box, const glm::dvec3& p, const glm::dvec3& v, double limit)
{
  if (v == glm::dvec3(0.0))
  {
    return p;
  }
  double t = limit;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (v[axis] > 0.0)
    {
      t = std::min(t, (box.Max[axis] - p[axis]) / v[axis]);
    }
    else if (v[axis] < 0.0)
    {
      t = std::min(t, (box.Min[axis] - p[axis]) / v[axis]);
    }
  }
  return p + v * std::max(t, 0.0);
}

} // namespace

double SlideBackHoldingCasters(const glm::dmat4& cameraView, const std::vector<glm::dvec3>& body,
  const Aabb& scene, const glm::dvec4& towardLight)
{
  const bool positional = towardLight.w != 0.0;
  double nearest = Infinity;
  for (const auto& p : body)
  {
    // Up to the light's position, or out of the scene toward a directional light.
    const glm::dvec3 toward =
      positional ? glm::dvec3(towardLight) / towardLight.w - p : glm::dvec3(towardLight);
    const glm::dvec3 end = ExitFromBox(scene, p, toward, positional ? 1.0 : Infinity);
    for (const glm::dvec3& q : { p, end })
    {
      nearest = std::min(nearest, -(cameraView * glm::dvec4(q, 1.0)).z);
    }
  }
  const double margin = 1e-3 * scene.Diagonal();
  return std::isfinite(nearest) && nearest < margin ? margin - nearest : 0.0;
}

namespace
{
// The PSM of either light kind for receivers `body` (see FitPerspective).
// B's points in the space; its centre and radius there. False when a point lies
// on or behind the space's w = 0 plane.
bool AddBodyToSpace(const std::vector<glm::dvec3>& body, PerspectiveSpace& space)
{
  glm::dvec3 lo(Infinity), hi(-Infinity);
  for (const auto& p : body)
  {
    const glm::dvec4 q = space.Transform * glm::dvec4(p, 1.0);
    if (!(q.w > 0.0))
    {
      return false;
    }
    space.Points.push_back(glm::dvec3(q) / q.w);
    lo = glm::min(lo, space.Points.back());
    hi = glm::max(hi, space.Points.back());
  }
  space.Centre = 0.5 * (lo + hi);
  space.Radius = std::max(0.5 * glm::length(hi - lo), 1e-9);
  return true;
}

// A positional light's own axis, taken into the space at the light and turned
// toward B (seen from the light's image `eye`).
glm::dvec3 LightAxisInSpace(
  const PerspectiveSpace& space, const PerspectiveLight& light, const glm::dvec3& eye)
{
  const glm::dvec3 axis = -glm::dvec3(glm::row(light.Uniform.View, 2));
  glm::dvec3 forward = PushForward(space.Transform, glm::dvec3(light.TowardLight), axis);
  forward = glm::dot(forward, space.Centre - eye) < 0.0 ? -forward : forward;
  return glm::length(forward) > 0.0 ? glm::normalize(forward) : forward;
}

PerspectiveMap FitPerspectiveToBody(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const std::vector<glm::dvec3>& body, const Aabb& scene, const PerspectiveLight& light,
  int resolution, double slideBack, double weight)
{
  PerspectiveMap map;
  map.PostPerspective = cameraProjection * cameraView;
  map.LightPosition = glm::dvec3(light.TowardLight);
  map.Light = light.Uniform;
  if (body.empty())
  {
    return map;
  }
  // A point at view depth z lies off its uniform-map place by about
  // (z - near)(far - z) / ((far - near)(z + slide-back)): the warp's pull goes as
  // 1 / (z + slide-back) at B's typical depth z. A weight w multiplies that pull
  // by sliding the virtual camera back to (z + slideBack) / w - z, so that the
  // map moves about evenly as the weight grows.
  const double typicalDepth = TypicalDepth(cameraView, cameraProjection, body);
  const double slide = std::max((typicalDepth + std::max(slideBack, 0.0)) / weight - typicalDepth,
    SlideBackHoldingCasters(cameraView, body, scene, light.TowardLight));
  // A point light inside the view's reach sees B within its cone in the world,
  // but unscaled post-perspective space can open that cone to nearly a
  // half-space: its fit is made in the fully rescaled space.
  const double scaleWeight = light.Positional ? 0.0 : weight;
  map.PostPerspective = SlideBackPostPerspective(cameraView, cameraProjection,
    SlideBackKeepingTheLightAway(cameraView, cameraProjection, body, light.TowardLight, slide,
      WidestLightConeCosine, scaleWeight));

  PerspectiveSpace space;
  space.Transform = FittingScale(cameraProjection, scaleWeight) * map.PostPerspective;
  if (!AddBodyToSpace(body, space))
  {
    return map;
  }
  space.AxisPoint = light.Positional
    ? AxisPointOfLight(light, body)
    : glm::dvec3(glm::inverse(cameraView) * glm::dvec4(0.0, 0.0, -typicalDepth, 1.0));
  space.AxisPointImage = ProjectPoint(space.Transform, space.AxisPoint);
  const glm::dmat4& frame = light.Uniform.View;
  space.Right = PushForward(space.Transform, space.AxisPoint, glm::dvec3(glm::row(frame, 0)));
  space.Up = PushForward(space.Transform, space.AxisPoint, glm::dvec3(glm::row(frame, 1)));

  // The light in post-perspective space: w > 0 in front of the viewer, w < 0
  // behind it, w = 0 on the camera's plane (perpendicular, for a sun).
  const glm::dvec4 post = space.Transform * light.TowardLight;
  LightView fit;
  if (StaysDirectional(post, space.Radius))
  {
    map.Kind = PsmLightKind::Directional;
    map.LightPosition = -glm::normalize(glm::dvec3(post));
    fit = FitDirectionalInSpace(space, map.LightPosition, resolution);
  }
  else
  {
    const bool inverse = post.w < 0.0;
    const glm::dvec3 eye = glm::dvec3(post) / post.w;
    if (light.Positional)
    {
      space.Forward = LightAxisInSpace(space, light, eye);
    }
    if (!FitPointInSpace(space, eye, inverse, weight, resolution, fit, map.InverseNear))
    {
      return map;
    }
    map.Kind = inverse ? PsmLightKind::Inverse : PsmLightKind::Point;
    map.LightPosition = eye;
  }
  fit.Perspective = true;
  const double step = std::max(scene.Diagonal(), 1e-300) * 1e-5;
  for (const auto& p : body)
  {
    fit.TexelConstant =
      std::max(fit.TexelConstant, WorldTexelSize(fit, p, light.TowardLight, step, resolution));
  }
  map.Light = fit;
  return map;
}

double ClampedWeight(double warpWeight)
{
  return std::isnan(warpWeight) ? 1.0 : std::min(warpWeight, 1.0);
}
} // namespace

PerspectiveMap FitPerspective(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& sceneBounds, const glm::dvec3& lightDirection, int resolution, double slideBack,
  double warpWeight)
{
  const Aabb scene = sceneBounds.IsEmpty() ? Aabb{ glm::dvec3(-1.0), glm::dvec3(1.0) } : sceneBounds;
  const glm::dvec3 d = SafeDirection(lightDirection);
  const glm::dmat4 camera = cameraProjection * cameraView;
  PerspectiveLight light;
  light.TowardLight = glm::dvec4(-d, 0.0);
  light.Uniform = FitDirectional(camera, scene, d, resolution);
  const double weight = ClampedWeight(warpWeight);
  // Post-perspective space of a parallel projection is affine: no warp.
  if (IsParallelProjection(cameraProjection) || !(weight > 0.0))
  {
    PerspectiveMap map;
    map.PostPerspective = camera;
    map.LightPosition = d;
    map.Light = light.Uniform;
    return map;
  }
  // Unit-cube clipping (Kozlov §14.1.3): the receivers B in post-perspective space.
  PerspectiveMap map = FitPerspectiveToBody(cameraView, cameraProjection,
    PerspectiveBody(camera, scene), scene, light, resolution, slideBack, weight);
  if (map.Kind == PsmLightKind::Uniform)
  {
    map.LightPosition = d;
  }
  return map;
}

PerspectiveMap FitSpotPerspective(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& scene, const glm::dvec3& position, const glm::dvec3& direction,
  double coneAngleDegrees, int resolution, double slideBack, double warpWeight)
{
  const glm::dmat4 camera = cameraProjection * cameraView;
  PerspectiveLight light;
  light.TowardLight = glm::dvec4(position, 1.0);
  light.Positional = true;
  // B = camera frustum ∩ scene ∩ the spot's frustum; the uniform map is the cone
  // map cropped to B, which the PSM becomes as its weight goes to 0.
  std::vector<glm::dvec3> body;
  light.Uniform =
    FitSpotToLitBody(camera, scene, position, direction, coneAngleDegrees, resolution, &body);
  const double weight = ClampedWeight(warpWeight);
  if (IsParallelProjection(cameraProjection) || !(weight > 0.0) || !IsFiniteVector(position))
  {
    PerspectiveMap map;
    map.PostPerspective = camera;
    map.LightPosition = position;
    map.Light = light.Uniform;
    return map;
  }
  PerspectiveMap map = FitPerspectiveToBody(
    cameraView, cameraProjection, body, scene, light, resolution, slideBack, weight);
  // Texels vary too much across a warped map for the cone's per-distance formula.
  map.Light.TexelSizeFromGradient = map.Kind != PsmLightKind::Uniform;
  return map;
}

double PerspectiveWarpWeight(const glm::dvec3& viewDirection, const glm::dvec3& lightDirection)
{
  WarpOptions band;
  band.UniformBelowDegrees = 2.0;
  band.FullWarpAboveDegrees = 20.0;
  return WarpFade(ViewLightAngle(viewDirection, lightDirection), band);
}

double WorldTexelSize(const LightView& map, const glm::dvec3& world,
  const glm::dvec4& towardLight, double step, int resolution)
{
  const glm::dvec3 ray = towardLight.w != 0.0
    ? world - glm::dvec3(towardLight) / towardLight.w
    : -glm::dvec3(towardLight);
  const glm::dmat4 frame = LightLookAt(glm::dvec3(0.0), ray);
  return TexelAcrossLight(map.ViewProjection(), world, glm::dvec3(glm::row(frame, 0)),
    glm::dvec3(glm::row(frame, 1)), step, resolution);
}

glm::dvec3 KozlovBiasedPoint(const glm::dvec3& world, const glm::dvec3& lightDirection, double a,
  double b, double texelSize)
{
  const double length = glm::length(lightDirection);
  const glm::dvec3 towardLight = length > 0.0 ? -lightDirection / length : glm::dvec3(0.0);
  return world + towardLight * (a + b * texelSize);
}

} // namespace shadowmaps
