#include "ShadowMapTrapezoid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowmaps
{
namespace
{

constexpr double Infinity = std::numeric_limits<double>::infinity();
constexpr double Pi = 3.14159265358979323846;
// Beyond this ratio eta / lambda the trapezoid is treated as a rectangle: the
// chain's residual warp there is below 1e-5 of the map (0.02 texel at 2048), and
// the chain loses precision on nearer rectangles.
constexpr double RectangleRatio = 1e5;

glm::dvec2 Apply(const glm::dmat3& m, const glm::dvec2& p)
{
  const glm::dvec3 q = m * glm::dvec3(p, 1.0);
  return glm::dvec2(q) / q.z;
}

double Cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b)
{
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

glm::dmat3 Translation2D(const glm::dvec2& t)
{
  glm::dmat3 m(1.0);
  m[2] = glm::dvec3(t, 1.0);
  return m;
}

glm::dmat3 Scale2D(const glm::dvec2& s)
{
  glm::dmat3 m(1.0);
  m[0][0] = s.x;
  m[1][1] = s.y;
  return m;
}

// Light-space xy -> (lateral, axial) coordinates of the centre-line frame.
glm::dmat3 FrameRows(const glm::dvec2& lateral, const glm::dvec2& axial)
{
  return glm::transpose(glm::dmat3(glm::dvec3(lateral, 0.0), glm::dvec3(axial, 0.0), glm::dvec3(0.0, 0.0, 1.0)));
}

// The eight-matrix chain of the thesis (literature/000, "Trapéz shadow map-ek",
// steps 1-8), written for column vectors. a, b: top corners (left, right);
// c: a base corner; q: the vanishing point; axial: the centre-line direction.
// The last two steps put the top edge on Y = -1 and the base on Y = +1.
glm::dmat3 TrapezoidChain(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
  const glm::dvec2& q, const glm::dvec2& axial)
{
  // 1. T1: centre of the top edge to the origin.
  const glm::dmat3 t1 = Translation2D(-0.5 * (a + b));
  // 2. R: top edge along x, base toward +y.
  const glm::dmat3 r = FrameRows(glm::normalize(b - a), axial);
  // 3. T2: intersection of the side edges (q) to the origin.
  glm::dmat3 m = r * t1;
  const glm::dmat3 t2 = Translation2D(-Apply(m, q));
  m = t2 * m;
  // 4. H: shear so that the trapezoid is symmetric about the y axis.
  const glm::dvec2 topCentre = Apply(m, 0.5 * (a + b));
  glm::dmat3 h(1.0);
  h[1][0] = -topCentre.x / topCentre.y;
  m = h * m;
  // 5. S1: top corner b to (1, 1): sides at 45 degrees, top of unit half-length.
  const glm::dvec2 corner = Apply(m, b);
  m = Scale2D(1.0 / corner) * m;
  // 6. N: (x, y, w) -> (x, y + w, y), the trapezoid becomes a rectangle.
  const glm::dmat3 n(glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 1.0), glm::dvec3(0.0, 1.0, 0.0));
  m = n * m;
  // 7. T3: centre the rectangle vertically; 8. S2: stretch it to [-1, 1].
  const double yTop = Apply(m, a).y;
  const double yBase = Apply(m, c).y;
  const glm::dmat3 t3 = Translation2D(glm::dvec2(0.0, -0.5 * (yTop + yBase)));
  const glm::dmat3 s2 = Scale2D(glm::dvec2(1.0, 2.0 / (yBase - yTop)));
  return s2 * t3 * m;
}

// Affine map of the rectangle [tMin, tMax] x [sTop, sBase] of the centre-line
// frame onto [-1, 1]^2: the degenerate trapezoid (q at infinity).
glm::dmat3 RectangleMap(const glm::dvec2& lateral, const glm::dvec2& axial, double tMin, double tMax,
  double sTop, double sBase)
{
  const glm::dmat3 toSquare = Translation2D(glm::dvec2(-1.0)) *
    Scale2D(glm::dvec2(2.0 / (tMax - tMin), 2.0 / (sBase - sTop))) *
    Translation2D(-glm::dvec2(tMin, sTop));
  return toSquare * FrameRows(lateral, axial);
}

// Direction of the centre-line frame's axial axis. Fully warped (weight 1): the
// projected view axis. Unwarped (weight 0): the camera's up in the light's plane,
// which, unlike the view axis, does not reverse where the light crosses the view.
// Between, the frame turns from the view axis toward the nearest quarter turn of
// the up; quarterTurns returns the counter-clockwise turns of the square that bring
// the map back to the up's orientation (a square turned by quarter turns keeps its
// texel grid).
glm::dvec2 CentreLineFrame(const glm::dvec2& viewAxis, const glm::dvec2& up, double weight, int& quarterTurns)
{
  const double alpha = std::atan2(viewAxis.y, viewAxis.x);
  const double beta = glm::length(up) > 1e-9 * glm::length(viewAxis) ? std::atan2(up.y, up.x) : alpha;
  const QuarterTurns turns = NearestQuarterTurns(beta - alpha);
  const double angle = alpha + (1.0 - weight) * turns.Residual;
  quarterTurns = static_cast<int>(((-turns.Turns) % 4 + 4) % 4);
  return { std::cos(angle), std::sin(angle) };
}

// Warp weight at angle gamma between the view and light lines: 0 (the rectangle)
// below UniformBelowDegrees, 1 from fadeAngleDegrees on, a smoothstep between, so
// that the map does not move at all within a small cone around the view axis.
double TrapezoidWarpWeight(double gammaRadians, double fadeAngleDegrees)
{
  constexpr double UniformBelowDegrees = 2.0;
  const double full = glm::radians(std::min(std::max(fadeAngleDegrees, 1e-6), 90.0));
  const double uniform = std::min(glm::radians(UniformBelowDegrees), 0.5 * full);
  return SmoothStep(uniform, full, gammaRadians);
}

// Counter-clockwise quarter turns of NDC x, y (exact).
glm::dmat3 QuarterTurnMatrix(int turns)
{
  static const int cosines[4] = { 1, 0, -1, 0 };
  const int c = cosines[turns & 3];
  const int s = cosines[(turns + 3) & 3];
  glm::dmat3 m(1.0);
  m[0][0] = c;
  m[0][1] = s;
  m[1][0] = -s;
  m[1][1] = c;
  return m;
}

} // namespace

std::vector<glm::dvec2> ConvexHull2D(std::vector<glm::dvec2> points)
{
  std::sort(points.begin(), points.end(),
    [](const glm::dvec2& p, const glm::dvec2& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3)
  {
    return points;
  }
  std::vector<glm::dvec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) // lower chain
  {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) // upper chain
  {
    while (k >= lower && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

TrapezoidMap FitTrapezoid(const glm::dmat4& cameraViewProjection, const Aabb& sceneBounds,
  const glm::dvec3& lightDirection, double focusDistance, double focusFraction,
  double fadeAngleDegrees)
{
  TrapezoidFrame frame;
  frame.Casters = sceneBounds.IsEmpty() ? Aabb{ glm::dvec3(-1.0), glm::dvec3(1.0) } : sceneBounds;
  frame.LightDirection = SafeDirection(lightDirection);
  // B = frustum ∩ scene (survey §4.1).
  frame.Body = IntersectFrustumWithBox(cameraViewProjection, frame.Casters);
  const glm::dmat4 inverse = glm::inverse(cameraViewProjection);
  frame.NearCentre = ProjectPoint(inverse, glm::dvec3(0.0, 0.0, -1.0));
  const glm::dvec3 axis = ProjectPoint(inverse, glm::dvec3(0.0, 0.0, 0.0)) - frame.NearCentre;
  if (glm::length(axis) > 0.0)
  {
    frame.ViewAxis = glm::normalize(axis);
  }
  frame.CameraUp = ProjectPoint(inverse, glm::dvec3(0.0, 1.0, -1.0)) - frame.NearCentre;
  frame.Focus = frame.NearCentre + frame.ViewAxis * std::max(focusDistance, 0.0);
  return FitTrapezoidFrame(frame, focusFraction, fadeAngleDegrees);
}

namespace
{
// Step 1 and 3 (thesis): B (or, without one, the casters' box) in light space,
// its 2D convex hull, and how far B reaches from the light.
std::vector<glm::dvec2> HullInLightSpace(
  const TrapezoidFrame& frame, const glm::dmat4& lightView, double& bodyFar)
{
  std::vector<glm::dvec3> body = frame.Body;
  if (body.empty())
  {
    const auto corners = frame.Casters.Corners();
    body.assign(corners.begin(), corners.end());
  }
  std::vector<glm::dvec2> projected;
  bodyFar = 0.0;
  for (const auto& p : body)
  {
    const glm::dvec3 q = ProjectPoint(lightView, p);
    projected.emplace_back(q);
    bodyFar = std::max(bodyFar, -q.z);
  }
  return ConvexHull2D(projected);
}

// The hull's extent along the centre line (top sTop, base sBase) and across it
// (tMin, tMax), each at least minimumExtent.
struct HullExtent
{
  double Top = Infinity;
  double Base = -Infinity;
  double LateralMin = Infinity;
  double LateralMax = -Infinity;
  double Length() const { return this->Base - this->Top; }
};

HullExtent ExtentAlong(const std::vector<glm::dvec2>& hull, const glm::dvec2& axial,
  const glm::dvec2& lateral, double minimumExtent)
{
  HullExtent e;
  for (const auto& p : hull)
  {
    e.Top = std::min(e.Top, glm::dot(p, axial));
    e.Base = std::max(e.Base, glm::dot(p, axial));
    e.LateralMin = std::min(e.LateralMin, glm::dot(p, lateral));
    e.LateralMax = std::max(e.LateralMax, glm::dot(p, lateral));
  }
  if (e.Base - e.Top < minimumExtent)
  {
    e.Base = e.Top + minimumExtent;
  }
  if (e.LateralMax - e.LateralMin < minimumExtent)
  {
    e.LateralMin -= 0.5 * minimumExtent;
    e.LateralMax += 0.5 * minimumExtent;
  }
  return e;
}

// delta': the focus point's distance from the top edge along the centre line
// (delta from the near plane on the view axis, [MT04]), kept inside the
// trapezoid. Where the near-plane centre lies before the hull's top (the
// camera's axis passing beside B), the focus span, its distance from that
// centre, is laid off from the top instead: the focus itself can lie before the
// top, and delta measured to it would vanish, eta with it, warping B onto a sliver.
double FocusOffset(const glm::dvec2& focusInLight, const glm::dvec2& nearInLight,
  const glm::dvec2& axial, const HullExtent& e)
{
  const double focusSpan = glm::dot(focusInLight - nearInLight, axial);
  const double deltaRaw = std::max(glm::dot(focusInLight, axial) - e.Top,
    glm::dot(nearInLight, axial) < e.Top ? focusSpan : -Infinity);
  return std::min(std::max(deltaRaw, 1e-3 * e.Length()), e.Length());
}

// The unwarped rectangle around the hull.
void FitRectangle(const glm::dvec2& axial, const glm::dvec2& lateral, const HullExtent& e,
  double yUnwarped, TrapezoidMap& map)
{
  map.VanishingDistance = Infinity;
  map.FocusLine = 0.5 * (yUnwarped + 1.0);
  map.TrapezoidToSquare =
    RectangleMap(lateral, axial, e.LateralMin, e.LateralMax, e.Top, e.Base);
  map.Corners = { lateral * e.LateralMin + axial * e.Top, lateral * e.LateralMax + axial * e.Top,
    lateral * e.LateralMax + axial * e.Base, lateral * e.LateralMin + axial * e.Base };
}

// The trapezoid whose side edges are the two lines through q (eta before the top
// on the centre line) that enclose the hull.
void FitTrapezoidSides(const glm::dvec2& axial, const glm::dvec2& lateral, double tCentre,
  const HullExtent& e, double eta, double yTarget, TrapezoidMap& map)
{
  const double sQ = e.Top - eta;
  double kMin = Infinity, kMax = -Infinity;
  for (const auto& p : map.Hull)
  {
    const double k = (glm::dot(p, lateral) - tCentre) / (glm::dot(p, axial) - sQ);
    kMin = std::min(kMin, k);
    kMax = std::max(kMax, k);
  }
  const double minimumSlope = 1e-9 * (e.LateralMax - e.LateralMin) / (eta + e.Length());
  if (kMax - kMin < minimumSlope)
  {
    kMin -= 0.5 * minimumSlope;
    kMax += 0.5 * minimumSlope;
  }
  const auto onSide = [&](double k, double s) { return lateral * (tCentre + k * (s - sQ)) + axial * s; };
  map.Corners = { onSide(kMin, e.Top), onSide(kMax, e.Top), onSide(kMax, e.Base), onSide(kMin, e.Base) };
  const glm::dvec2 q = lateral * tCentre + axial * sQ;
  map.VanishingDistance = eta;
  map.FocusLine = 0.5 * (yTarget + 1.0);
  map.TrapezoidToSquare = TrapezoidChain(map.Corners[0], map.Corners[1], map.Corners[3], q, axial);
}

// Linear light-space depth: casters from the scene inside the trapezoid's
// bounding rectangle (ComputeNearAndFar), receivers up to B's far end.
void FitDepthRange(const Aabb& scene, double bodyFar, double diagonal, TrapezoidMap& map)
{
  glm::dvec2 lo(Infinity), hi(-Infinity);
  for (const auto& c : map.Corners)
  {
    lo = glm::min(lo, c);
    hi = glm::max(hi, c);
  }
  glm::dvec2 depth = ComputeNearAndFar(map.LightView, lo, hi, scene);
  if (!(depth.y > depth.x))
  {
    depth = { 0.0, bodyFar };
  }
  const double range = std::max(bodyFar - depth.x, diagonal * 1e-6);
  map.DepthNear = depth.x - range * 1e-3;
  map.DepthFar = bodyFar + range * 1e-3;
}
} // namespace

TrapezoidMap FitTrapezoidFrame(const TrapezoidFrame& frame, double focusFraction, double fadeAngleDegrees)
{
  const Aabb& scene = frame.Casters;
  const glm::dvec3& d = frame.LightDirection;
  const double diagonal = std::max(scene.Diagonal(), 1e-300);
  TrapezoidMap map;
  map.LightView = LightLookAt(scene.Center() - d * diagonal, d);
  double bodyFar = 0.0;
  map.Hull = HullInLightSpace(frame, map.LightView, bodyFar);

  // Step 2: the centre line, from the projected near-plane centre along the
  // projected view axis. Its length per unit of view axis is sin(light, view).
  const glm::dvec2 axisInLight = glm::dvec2(glm::dmat3(map.LightView) * frame.ViewAxis);
  const double sine = glm::length(axisInLight);
  const double gamma = frame.Gamma >= 0.0 ? frame.Gamma : std::asin(std::min(sine, 1.0));
  map.WarpWeight = TrapezoidWarpWeight(gamma, fadeAngleDegrees);
  const glm::dvec2 axial = CentreLineFrame(sine > 1e-12 ? axisInLight / sine : glm::dvec2(0.0, 1.0),
    glm::dvec2(glm::dmat3(map.LightView) * frame.CameraUp), map.WarpWeight, map.QuarterTurns);
  const glm::dvec2 lateral(axial.y, -axial.x);
  const glm::dvec2 nearInLight = glm::dvec2(ProjectPoint(map.LightView, frame.NearCentre));

  // Step 4: top and base perpendicular to the centre line, touching the hull.
  const HullExtent extent = ExtentAlong(map.Hull, axial, lateral, diagonal * 1e-9);
  const double lambda = extent.Length();
  const glm::dvec2 focusInLight = glm::dvec2(ProjectPoint(map.LightView, frame.Focus));
  const double delta = FocusOffset(focusInLight, nearInLight, axial, extent);
  map.FocusPoint = focusInLight + axial * (extent.Top + delta - glm::dot(focusInLight, axial));

  // Target line of the focus point, NDC Y (top -1, base +1): the paper's
  // 2 * fraction - 1 (0.6 for the 80% line), faded toward the unwarped value
  // 2 delta'/lambda - 1 as the light approaches the view axis.
  const double yUnwarped = 2.0 * delta / lambda - 1.0;
  const double yPaper = 2.0 * std::min(std::max(focusFraction, 0.0), 0.999) - 1.0;
  const double yTarget = yUnwarped + map.WarpWeight * (yPaper - yUnwarped);

  // Distance eta from the top edge to q: the 1D projective map y(s) = A + B/s
  // (s from q) with y(eta) = -1, y(eta + lambda) = 1, y(eta + delta') = yTarget
  // gives eta = lambda delta' (1 - y) / (lambda - 2 delta' + lambda y), the
  // [MT04] formula with xi = -y (top and base swapped).
  const double denominator = lambda * (yTarget - yUnwarped);
  const double eta = denominator > 0.0 ? delta * (1.0 - yTarget) * lambda / denominator : Infinity;
  if (!(eta < RectangleRatio * lambda))
  {
    FitRectangle(axial, lateral, extent, yUnwarped, map);
  }
  else
  {
    FitTrapezoidSides(axial, lateral, glm::dot(nearInLight, lateral), extent, eta, yTarget, map);
  }
  FitDepthRange(scene, bodyFar, diagonal, map);
  return map;
}

LightView FitSpotTrapezoid(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& sceneBounds, const glm::dvec3& position, const glm::dvec3& direction,
  double coneAngleDegrees, int resolution, double focusDistance, double focusFraction)
{
  const glm::dmat4 cameraViewProjection = cameraProjection * cameraView;
  const LightView cone =
    FitSpot(cameraViewProjection, sceneBounds, position, direction, coneAngleDegrees, resolution);
  const glm::dmat4 toLightSpace = cone.ViewProjection();
  const glm::dmat4 cameraToWorld = glm::inverse(cameraView);
  if (sceneBounds.IsEmpty() || !IsFinite(cameraViewProjection) || !IsFinite(toLightSpace) ||
    !IsFinite(cameraToWorld))
  {
    return cone;
  }

  // B = camera frustum ∩ scene ∩ the spot's frustum, and its view-depth range.
  const Aabb& scene = sceneBounds;
  const SpotSpace space = FocusInSpotSpace(cameraViewProjection, scene, cone);
  TrapezoidFrame frame;
  frame.Body = space.Body;
  if (frame.Body.empty())
  {
    return cone;
  }
  double zNear = Infinity, zFar = -Infinity;
  for (const auto& p : space.WorldBody)
  {
    const double depth = -(cameraView * glm::dvec4(p, 1.0)).z;
    zNear = std::min(zNear, depth);
    zFar = std::max(zFar, depth);
  }

  // The camera's axis over B's depth range, its focus point and its up, taken
  // into the spot's post-perspective space (a projective map keeps lines).
  const glm::dvec3 eye(cameraToWorld[3]);
  const glm::dvec3 view = glm::normalize(-glm::dvec3(cameraToWorld[2]));
  const glm::dvec3 up = glm::normalize(glm::dvec3(cameraToWorld[1]));
  const double delta = focusDistance > 0.0 ? focusDistance : 0.2 * (zFar - zNear);
  const double step = 1e-3 * std::max(zFar - zNear, scene.Diagonal() * 1e-6);
  const std::array<glm::dvec3, 4> worldAxis = { eye + view * zNear,
    eye + view * std::max(zFar, zNear + step), eye + view * (zNear + delta),
    eye + view * zNear + up * step };
  std::array<glm::dvec3, 4> axis;
  for (size_t i = 0; i < worldAxis.size(); ++i)
  {
    const glm::dvec4 q = toLightSpace * glm::dvec4(worldAxis[i], 1.0);
    if (!(q.w > 0.0))
    {
      return cone;
    }
    axis[i] = glm::dvec3(q) / q.w;
  }
  frame.Casters = Aabb{ glm::dvec3(-1.0), glm::dvec3(1.0) }; // the spot's frustum
  frame.LightDirection = glm::dvec3(0.0, 0.0, 1.0);
  frame.NearCentre = axis[0];
  frame.ViewAxis = axis[1] - axis[0];
  frame.Focus = axis[2];
  frame.CameraUp = axis[3] - axis[0];
  if (!(glm::length(frame.ViewAxis) > 0.0) || !IsFiniteVector(frame.ViewAxis) ||
    !IsFiniteVector(frame.CameraUp))
  {
    return cone;
  }
  frame.ViewAxis = glm::normalize(frame.ViewAxis);
  // In the world: zero exactly when the camera's axis passes through the light,
  // which is when the axis runs along the light in the spot's space.
  const glm::dvec3 toAxis = eye + view * (0.5 * (zNear + zFar)) - position;
  if (glm::length(toAxis) > 0.0)
  {
    frame.Gamma = std::acos(std::min(std::abs(glm::dot(glm::normalize(toAxis), view)), 1.0));
  }

  // Clip W = the spot's w times the trapezoid's W, and the trapezoid's W is a
  // plane over the map as for a directional light.
  return FromSpotSpace(TrapezoidLightView(FitTrapezoidFrame(frame, focusFraction), resolution), cone);
}

glm::dvec3 NdcToInverseW(const LightView& view)
{
  // Clip (X, Y, W) as a function of light-space (x, y, 1): rows X, Y, W and
  // columns x, y, 1 of the projection. Its inverse applied to (x_ndc, y_ndc, 1)
  // = (X, Y, W) / W gives (x, y, 1) / W, whose last component is 1 / W.
  const glm::dmat4& p = view.Projection;
  const glm::dmat3 xyw(glm::dvec3(p[0][0], p[0][1], p[0][3]), glm::dvec3(p[1][0], p[1][1], p[1][3]),
    glm::dvec3(p[3][0], p[3][1], p[3][3]));
  const double determinant = glm::determinant(xyw);
  if (!(std::abs(determinant) > 1e-300) || !std::isfinite(determinant))
  {
    return { 0.0, 0.0, 1.0 };
  }
  const glm::dmat3 inverse = glm::inverse(xyw);
  return { inverse[0][2], inverse[1][2], inverse[2][2] };
}

glm::dvec2 TrapezoidToNdc(const TrapezoidMap& map, const glm::dvec2& lightXY)
{
  return Apply(map.TrapezoidToSquare, lightXY);
}

glm::dvec4 DepthRow(const TrapezoidMap& map)
{
  const glm::dmat4& v = map.LightView;
  const glm::dvec4 lightZ(v[0][2], v[1][2], v[2][2], v[3][2]); // row 2: world -> light z
  const double range = map.DepthFar - map.DepthNear;
  return (-lightZ - glm::dvec4(0.0, 0.0, 0.0, map.DepthNear)) / range;
}

glm::dvec3 MapToTexture(const TrapezoidMap& map, const glm::dvec3& world)
{
  const glm::dvec3 light = ProjectPoint(map.LightView, world);
  const glm::dvec2 ndc =
    glm::dmat2(QuarterTurnMatrix(map.QuarterTurns)) * TrapezoidToNdc(map, glm::dvec2(light));
  const double depth = glm::dot(DepthRow(map), glm::dvec4(world, 1.0));
  return { 0.5 * ndc.x + 0.5, 0.5 * ndc.y + 0.5, depth };
}

LightView TrapezoidLightView(const TrapezoidMap& map, int resolution)
{
  const glm::dmat3 h = QuarterTurnMatrix(map.QuarterTurns) * map.TrapezoidToSquare;
  const double range = map.DepthFar - map.DepthNear;
  LightView view;
  view.View = map.LightView;
  // Columns act on light-space x, y, z, 1; rows give clip X, Y, Z, W.
  view.Projection = glm::dmat4(glm::dvec4(h[0][0], h[0][1], 0.0, h[0][2]),
    glm::dvec4(h[1][0], h[1][1], 0.0, h[1][2]), glm::dvec4(0.0, 0.0, -2.0 / range, 0.0),
    glm::dvec4(h[2][0], h[2][1], -(map.DepthFar + map.DepthNear) / range, h[2][2]));
  view.Perspective = true;
  view.LinearDepth = true;

  // The coarsest texel over the trapezoid, at its corners: the map is coarsest
  // at the base, and X, Y, W do not depend on light-space depth.
  const glm::dmat4 lightToWorld = glm::inverse(map.LightView);
  const glm::dvec3 u(lightToWorld[0]);
  const glm::dvec3 v(lightToWorld[1]);
  double extent = 0.0;
  for (const auto& corner : map.Corners)
  {
    extent = std::max(extent, glm::length(corner - map.Corners[0]));
  }
  const double depth = -0.5 * (map.DepthNear + map.DepthFar);
  double texel = 0.0;
  for (const auto& corner : map.Corners)
  {
    const glm::dvec3 p(lightToWorld * glm::dvec4(corner, depth, 1.0));
    texel = std::max(texel, TexelAcrossLight(view.ViewProjection(), p, u, v, extent * 1e-5, resolution));
  }
  view.TexelConstant = texel;
  return view;
}

glm::dvec3 TextureToInverseW(const LightView& view)
{
  if (!view.LinearDepth)
  {
    return glm::dvec3(0.0);
  }
  // x_ndc = 2 u - 1.
  const glm::dvec3 r = NdcToInverseW(view);
  return glm::dvec3(2.0 * r.x, 2.0 * r.y, r.z - r.x - r.y);
}

} // namespace shadowmaps
