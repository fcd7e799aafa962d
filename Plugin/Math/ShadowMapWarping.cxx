#include "ShadowMapWarping.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowmaps
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double Infinity = std::numeric_limits<double>::infinity();

// The focused uniform map, used wherever a warp is not possible.
LightView Uniform(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection, const Aabb& scene,
  const glm::dvec3& lightDirection, int resolution)
{
  return FitDirectional(cameraProjection * cameraView, scene, lightDirection, resolution);
}

// Maps the box [lo, hi] onto [-1, 1]^3 (scale and translate, no flip).
glm::dmat4 BoxToClip(const glm::dvec3& lo, const glm::dvec3& hi)
{
  const glm::dvec3 scale = 2.0 / (hi - lo);
  glm::dmat4 m(1.0);
  for (int axis = 0; axis < 3; ++axis)
  {
    m[axis][axis] = scale[axis];
    m[3][axis] = -1.0 - lo[axis] * scale[axis];
  }
  return m;
}

// Half angle of the camera frustum in the plane of the view direction and the
// camera-space direction `inPlane` (x, y): tan(phi) is the frustum's support along it
// at unit depth, so that P_f - P_n of 002 Eq. 9 is exactly B's warp-axis extent.
double HalfAngleAlong(const glm::dmat4& cameraProjection, const glm::dvec2& inPlane)
{
  const glm::dmat4 inverse = glm::inverse(cameraProjection);
  double tangent = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    const glm::dvec3 ndc((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, -1.0);
    const glm::dvec3 q = ProjectPoint(inverse, ndc);
    if (-q.z > 0.0)
    {
      tangent = std::max(tangent, std::abs(glm::dot(inPlane, glm::dvec2(q)) / -q.z));
    }
  }
  return std::atan(tangent);
}

// The world-measured terms of a warp frame: B's view-depth range, and the
// camera's half angle in the plane of the view direction and the light (whose
// direction at B is lightDirection).
void SetCameraTerms(WarpFrame& frame, const glm::dmat4& cameraView,
  const glm::dmat4& cameraProjection, const std::vector<glm::dvec3>& worldBody,
  const glm::dvec3& lightDirection)
{
  frame.ZNear = Infinity;
  frame.ZFar = 0.0;
  for (const auto& p : worldBody)
  {
    const double depth = -ProjectPoint(cameraView, p).z;
    frame.ZNear = std::min(frame.ZNear, depth);
    frame.ZFar = std::max(frame.ZFar, depth);
  }
  const glm::dmat4 cameraToWorld = glm::inverse(cameraView);
  const glm::dvec3 view = glm::normalize(-glm::dvec3(cameraToWorld[2]));
  const glm::dvec3 up = glm::normalize(glm::dvec3(cameraToWorld[1]));
  const glm::dvec3 projected = view - glm::dot(view, lightDirection) * lightDirection;
  const glm::dvec3 upAcross = up - glm::dot(up, lightDirection) * lightDirection;
  const glm::dvec3 warpAxis = glm::length(projected) > 1e-12 ? glm::normalize(projected) : upAcross;
  const glm::dvec3 axisInCamera = glm::dmat3(cameraView) * warpAxis;
  const glm::dvec2 inPlane = glm::length(glm::dvec2(axisInCamera)) > 1e-12
    ? glm::normalize(glm::dvec2(axisInCamera))
    : glm::dvec2(0.0, 1.0);
  frame.Phi = HalfAngleAlong(cameraProjection, inPlane);
}

} // namespace

double ViewLightAngle(const glm::dvec3& viewDirection, const glm::dvec3& lightDirection)
{
  const double lengths = glm::length(viewDirection) * glm::length(lightDirection);
  if (!(lengths > 0.0) || !std::isfinite(lengths))
  {
    return 0.0;
  }
  // atan2 of |cross| and |dot| is accurate near 0 and pi/2, and folds theta to [0, pi/2].
  const double sine = glm::length(glm::cross(viewDirection, lightDirection));
  const double cosine = std::abs(glm::dot(viewDirection, lightDirection));
  return std::atan2(sine, cosine);
}

double LiSPSMFreeParameter(double zNear, double zFar, double gammaRadians, double phiRadians, bool lloyd)
{
  // 003 / 000: n_opt = z_n + sqrt(z_f z_n); original LiSPSM falloff n_opt / sin(gamma).
  const double nOpt = zNear + std::sqrt(zFar * zNear);
  const double sine = std::abs(std::sin(gammaRadians));
  if (!(sine > 0.0))
  {
    return Infinity;
  }
  double n = nOpt / sine;
  const double phiSine = std::abs(std::sin(phiRadians));
  if (lloyd && sine < phiSine)
  {
    n *= phiSine / sine; // faster than 1/sin below phi, continuous at phi (our choice).
  }
  return n;
}

double PseudoNear(double zNear, double zFar, double fraction)
{
  const double clamped = std::isfinite(fraction) ? std::min(std::max(fraction, 0.0), 1.0) : 0.0;
  return std::max(zNear, clamped * zFar);
}

double GMNPRLambda(double theta, double phi, double n, double f)
{
  theta = std::min(std::abs(theta), 0.5 * Pi);
  if (theta >= phi)
  {
    // 002 Eq. 8, first branch (lambda_1 of Eq. 4).
    const double ratio = std::tan(phi) / std::tan(theta);
    return (n + std::sqrt(f * n) - n * ratio) / (f - n + (f + n) * ratio);
  }
  // 002 Eq. 7 / Eq. 8 second branch: lambda_2* = sqrt(f n) / (2 f) / tan(theta pi / (4 phi)).
  const double t = std::tan(theta * Pi / (4.0 * phi));
  return t > 0.0 ? std::sqrt(f * n) / (2.0 * f) / t : Infinity;
}

double WarpDepthOfFrustum(double theta, double phi, double n, double f)
{
  theta = std::min(std::abs(theta), 0.5 * Pi);
  if (theta >= phi)
  {
    return (f - n + (f + n) * std::tan(phi) / std::tan(theta)) * std::sin(theta);
  }
  return 2.0 * f * std::tan(phi) * std::cos(theta);
}

double LiSPSMLambda(double theta, double phi, double n, double f)
{
  // 002 Eq. 9: P_n = (n + sqrt(f n)) / sin(theta) over the frustum's warp depth.
  const double nearDistance = LiSPSMFreeParameter(n, f, theta, phi, false);
  return LambdaFromWarpNear(nearDistance, WarpDepthOfFrustum(theta, phi, n, f));
}

double GMNPRAliasing(double lambda, double theta, double phi, double n, double f, double z)
{
  theta = std::min(std::abs(theta), 0.5 * Pi);
  const double tanPhi = std::tan(phi);
  double psi = 0.0;
  double varphi = 0.0;
  if (theta >= phi)
  {
    // 002 Eq. 2, theta in [phi, pi/2].
    const double ratio = tanPhi / std::tan(theta);
    const double span = f - n + (f + n) * ratio;
    psi = 1.0 / tanPhi / (span * lambda * (lambda + 1.0));
    varphi = span * lambda + n * ratio - n;
  }
  else
  {
    // 002 Eq. 2, theta in [0, phi].
    const double ratio = std::tan(theta) / tanPhi;
    psi = 1.0 / tanPhi / (2.0 * f * lambda * (lambda + 1.0) * ratio);
    varphi = f * (2.0 * lambda + 1.0) / ratio - f;
  }
  return psi * (z + varphi) * (z + varphi) / z;
}

double WarpNearFromLambda(double lambda, double warpDepth)
{
  return lambda * warpDepth;
}

double LambdaFromWarpNear(double warpNear, double warpDepth)
{
  return warpDepth > 0.0 ? warpNear / warpDepth : Infinity;
}

double WarpFade(double gammaRadians, const WarpOptions& options)
{
  const double low = glm::radians(std::min(std::max(options.UniformBelowDegrees, 0.0), 89.0));
  const double high =
    glm::radians(std::min(std::max(options.FullWarpAboveDegrees, glm::degrees(low)), 90.0));
  return SmoothStep(low, high, std::min(std::abs(gammaRadians), 0.5 * Pi));
}

namespace
{
// A warped fit stores depth linear in light space, as TSM does (thesis 000:
// multiply z back by w): the projection's depth row becomes the light-space
// depth from `nearDepth` to `farDepth` mapped to [-1, 1], independent of the
// warp's w, which is at least 1 over B and its casters (the warp's apex lies
// behind B's near side) and does not depend on depth. Rasterized depth is then
// that depth over w, inside the clip volume and ordered along every light ray,
// and casters and receivers recover the linear depth from the map position.
// Stored as rasterized, the warp's own depth crowds the far part of B into a
// sliver of the range, where a slope-scaled offset taken on it (the warp makes
// a large caster's window-space slope steep) pushed casters behind receivers.
void StoreLinearDepth(LightView& fit, double nearDepth, double farDepth)
{
  const double range = std::max(farDepth - nearDepth, std::abs(farDepth) * 1e-9 + 1e-300);
  const double lower = nearDepth - 1e-3 * range;
  const double upper = farDepth + 1e-3 * range;
  // Light-view z is minus the depth: z_clip = (2 (-z) - (lower + upper)) / (upper - lower).
  fit.Projection[0][2] = 0.0;
  fit.Projection[1][2] = 0.0;
  fit.Projection[2][2] = -2.0 / (upper - lower);
  fit.Projection[3][2] = -(lower + upper) / (upper - lower);
  fit.LinearDepth = true;
}
} // namespace

namespace
{
// Light space of a warp (000, 003): -z along the light, y = the view direction
// projected perpendicular to the light (the warp axis). Where that projection
// vanishes (gamma = 0) the warp is faded out and the axis only names a frame.
struct WarpLightSpace
{
  glm::dmat4 View{ 1.0 };
  glm::dvec3 WarpAxis{ 0.0 };
  glm::dvec3 Right{ 0.0 };
  /// The camera's up, perpendicular to the light.
  glm::dvec3 UpAcross{ 0.0 };
  double Diagonal = 0.0;
};

WarpLightSpace MakeWarpLightSpace(const WarpFrame& frame)
{
  const glm::dvec3& d = frame.LightDirection;
  WarpLightSpace space;
  space.UpAcross = frame.CameraUp - glm::dot(frame.CameraUp, d) * d;
  const glm::dvec3 projected = frame.ViewDirection - glm::dot(frame.ViewDirection, d) * d;
  space.WarpAxis = glm::length(projected) > 1e-12 ? glm::normalize(projected)
    : glm::length(space.UpAcross) > 1e-12          ? glm::normalize(space.UpAcross)
                                                   : glm::dvec3(LightLookAt(glm::dvec3(0.0), d)[0]);
  space.Diagonal = frame.Casters.Diagonal();
  const glm::dvec3 lightEye = frame.Casters.Center() - d * space.Diagonal;
  space.View = glm::lookAt(lightEye, lightEye + d, space.WarpAxis);
  space.Right = glm::cross(d, space.WarpAxis);
  return space;
}

// B's footprint in light space and its depth range from the nearest caster over
// that footprint to B's far end.
struct LightSpaceBody
{
  glm::dvec2 Lo{ Infinity };
  glm::dvec2 Hi{ -Infinity };
  double CasterNear = Infinity;
  double BodyFar = -Infinity;
};

LightSpaceBody BodyInLightSpace(const WarpFrame& frame, const WarpLightSpace& space)
{
  LightSpaceBody b;
  double bodyNear = Infinity;
  for (const auto& p : frame.Body)
  {
    const glm::dvec3 q = ProjectPoint(space.View, p);
    b.Lo = glm::min(b.Lo, glm::dvec2(q));
    b.Hi = glm::max(b.Hi, glm::dvec2(q));
    bodyNear = std::min(bodyNear, -q.z);
    b.BodyFar = std::max(b.BodyFar, -q.z);
  }
  const double minimumExtent = space.Diagonal * 1e-6;
  b.Hi = glm::max(b.Hi, b.Lo + minimumExtent);
  // Casters between B and the light: nearest scene point over B's footprint.
  const glm::dvec2 depthRange = ComputeNearAndFar(space.View, b.Lo, b.Hi, frame.Casters);
  b.CasterNear = depthRange.y > depthRange.x ? std::min(depthRange.x, bodyNear) : bodyNear;
  b.BodyFar = std::max(b.BodyFar, b.CasterNear + minimumExtent);
  return b;
}

// The warp's near distance n in this frame's units (B's extent along the warp
// axis is warpDepth): n keeps its ratio to that extent from the world, where
// LiSPSM and GMNPR choose it (002's lambda = P_n / (P_f - P_n)). Infinite: no warp.
double WarpNearInFrame(
  const WarpFrame& frame, DirectionalWarp warp, const WarpOptions& options, double warpDepth)
{
  const double worldWarpDepth = frame.WarpDepthInWorld > 0.0 ? frame.WarpDepthInWorld : warpDepth;
  double warpNear = Infinity;
  if (options.FreeParameterN > 0.0)
  {
    warpNear = options.FreeParameterN;
  }
  else if (frame.ZNear > 0.0 && frame.ZFar > frame.ZNear)
  {
    const double zNear = PseudoNear(frame.ZNear, frame.ZFar, options.PseudoNearFraction);
    if (warp == DirectionalWarp::LiSPSM)
    {
      warpNear = LiSPSMFreeParameter(zNear, frame.ZFar, frame.Gamma, frame.Phi, options.LloydFalloff);
    }
    else if (frame.Phi > 0.0)
    {
      // 002: lambda = P_n / (P_f - P_n), P_f - P_n = B's extent along the warp axis.
      warpNear = WarpNearFromLambda(
        GMNPRLambda(frame.Gamma, frame.Phi, zNear, frame.ZFar), worldWarpDepth);
    }
  }
  return warpNear * (worldWarpDepth > 0.0 ? warpDepth / worldWarpDepth : 1.0);
}

// The warp P with apex n behind B's near side along y, written so that it is the
// identity at strength k = 0: with y' = y - y_near,
//   (x, y', z) -> (x, y', z) / (1 + y' / n)  =  (n x, n y', n z) / (n + y'),
// i.e. the division by the distance to the apex of a perspective frustum along y;
// y' / (1 + y'/n) = n - n^2 / (n + y') is its hyperbolic depth. In homogeneous form
// only the w row changes: w = 1 + (k / (P_f - P_n)) y'.
glm::dmat4 WarpAlongY(const glm::dvec3& apexFoot, double strength, double warpDepth)
{
  glm::dmat4 warpMatrix(1.0);
  warpMatrix[1][3] = warpDepth > 0.0 ? strength / warpDepth : 0.0;
  return warpMatrix * glm::translate(glm::dmat4(1.0), -apexFoot);
}

// The map's in-plane orientation rho (map up = (-sin rho, cos rho) in light x/y):
// with the warp, the multiple of 90 degrees nearest the camera's up (projected
// perpendicular to the light), which keeps the map axes on the warp axis (a quarter
// turn maps the texel grid onto itself); without it (fade 0), the camera's up itself,
// which is continuous where the warp axis reverses (gamma = 0 or pi). The fade blends
// the two. Known limit: inside the fade band a light crossing the diagonal azimuth
// (warp axis at 45 degrees to the camera's up) turns the map by 90 * min(fade, 1 - fade).
glm::dmat4 MapTurn(const WarpLightSpace& space, double fade)
{
  const glm::dvec2 upInLight(
    glm::dot(space.UpAcross, space.Right), glm::dot(space.UpAcross, space.WarpAxis));
  const double upAngle =
    glm::length(upInLight) > 1e-9 ? std::atan2(-upInLight.x, upInLight.y) : 0.0;
  const double rho = upAngle - fade * NearestQuarterTurns(upAngle).Residual;
  glm::dmat4 turn(1.0);
  turn[0][0] = std::cos(rho);
  turn[1][0] = std::sin(rho);
  turn[0][1] = -std::sin(rho);
  turn[1][1] = std::cos(rho);
  return turn;
}

// Final orthographic fit: x, y over B, depth over B's footprint from the nearest
// caster to B's far end (light-space box; w > 0 on it, so its corners bound the
// image). False when the result is not finite.
bool FitMapBox(const WarpFrame& frame, const WarpLightSpace& space, const LightSpaceBody& b,
  const glm::dmat4& toMap, bool warped, int texels, LightView& fit)
{
  glm::dvec3 mapLo(Infinity), mapHi(-Infinity);
  for (const auto& p : frame.Body)
  {
    const glm::dvec3 m = ProjectPoint(toMap * space.View, p);
    mapLo = glm::min(mapLo, m);
    mapHi = glm::max(mapHi, m);
  }
  for (int i = 0; i < 8; ++i)
  {
    const glm::dvec3 q((i & 1) ? b.Hi.x : b.Lo.x, (i & 2) ? b.Hi.y : b.Lo.y,
      (i & 4) ? -b.CasterNear : -b.BodyFar);
    const glm::dvec3 m = ProjectPoint(toMap, q);
    mapLo.z = std::min(mapLo.z, m.z);
    mapHi.z = std::max(mapHi.z, m.z);
  }
  const glm::dvec3 extent = glm::max(mapHi - mapLo, 1e-9 * (glm::abs(mapHi) + glm::abs(mapLo)) + 1e-300);
  const glm::dvec3 margin(extent.x * 4.0 / texels, extent.y * 4.0 / texels, extent.z * 1e-3);
  fit = LightView();
  fit.View = space.View;
  fit.Projection = BoxToClip(mapLo - margin, mapLo + extent + margin) * toMap;
  fit.Perspective = warped;
  if (warped)
  {
    StoreLinearDepth(fit, b.CasterNear, b.BodyFar);
  }
  return IsFinite(fit.Projection) && IsFiniteVector(mapLo) && IsFiniteVector(mapHi);
}

// Conservative texel: the largest world-space texel edge over B's vertices (the
// far end of the warp is the coarsest part): (2 / resolution) / sigma_min of the
// Jacobian of clip x/y with respect to the light-perpendicular world directions.
// Without one, B's light-space extent over the texels.
double ConservativeTexel(const WarpFrame& frame, const WarpLightSpace& space,
  const LightSpaceBody& b, const LightView& fit, int texels)
{
  const glm::dmat4 clip = fit.ViewProjection();
  const double step = space.Diagonal * 1e-5;
  double texel = 0.0;
  for (const auto& p : frame.Body)
  {
    texel = std::max(texel, TexelAcrossLight(clip, p, space.Right, space.WarpAxis, step, texels));
  }
  return texel > 0.0 ? texel : std::max(b.Hi.x - b.Lo.x, b.Hi.y - b.Lo.y) / texels;
}
} // namespace

bool FitWarpedFrame(const WarpFrame& frame, int resolution, DirectionalWarp warp,
  const WarpOptions& options, LightView& fit)
{
  const int texels = std::max(resolution, 1);
  if (frame.Body.empty() || frame.Casters.IsEmpty())
  {
    return false;
  }
  const WarpLightSpace space = MakeWarpLightSpace(frame);
  const LightSpaceBody body = BodyInLightSpace(frame, space);

  // Fade: the strength k = (P_f - P_n) / n times a smoothstep in gamma, so that
  // n -> infinity continuously as the view and light lines become parallel (003, 000).
  const double warpDepth = body.Hi.y - body.Lo.y;
  const double warpNear = WarpNearInFrame(frame, warp, options, warpDepth);
  const double fade = WarpFade(frame.Gamma, options);
  const double rawStrength = warpNear > 0.0 ? fade * warpDepth / warpNear : 0.0;
  const double strength = std::isfinite(rawStrength) ? rawStrength : 0.0;
  const bool warped = strength > 0.0;

  const glm::dvec3 apexFoot(
    ProjectPoint(space.View, frame.Eye).x, body.Lo.y, -0.5 * (body.CasterNear + body.BodyFar));
  glm::dmat4 flipDepth(1.0);
  flipDepth[2][2] = -1.0; // map depth grows away from the light
  const glm::dmat4 toMap = flipDepth * MapTurn(space, fade) * WarpAlongY(apexFoot, strength, warpDepth);
  if (!FitMapBox(frame, space, body, toMap, warped, texels, fit))
  {
    return false;
  }
  fit.TexelConstant = ConservativeTexel(frame, space, body, fit, texels);
  fit.TexelPerUnitDistance = 0.0;
  return true;
}


LightView FitDirectionalWarped(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& sceneBounds, const glm::dvec3& lightDirection, int resolution, DirectionalWarp warp,
  const WarpOptions& options)
{
  const double lightLength = glm::length(lightDirection);
  const bool parallelCamera = std::abs(cameraProjection[2][3]) < 1e-12;
  if (warp == DirectionalWarp::Uniform || parallelCamera || sceneBounds.IsEmpty() ||
    !IsFinite(cameraView) || !IsFinite(cameraProjection) || !(lightLength > 0.0) ||
    !std::isfinite(lightLength))
  {
    return Uniform(cameraView, cameraProjection, sceneBounds, lightDirection, resolution);
  }
  const Aabb scene = NonDegenerate(sceneBounds);
  WarpFrame frame;
  frame.Body = IntersectFrustumWithBox(cameraProjection * cameraView, scene);
  const glm::dmat4 cameraToWorld = glm::inverse(cameraView);
  const glm::dvec3 viewRaw = -glm::dvec3(cameraToWorld[2]);
  if (frame.Body.empty() || !IsFinite(cameraToWorld) || !(glm::length(viewRaw) > 0.0))
  {
    return Uniform(cameraView, cameraProjection, sceneBounds, lightDirection, resolution);
  }
  frame.Casters = scene;
  frame.LightDirection = lightDirection / lightLength;
  frame.ViewDirection = glm::normalize(viewRaw);
  frame.Eye = glm::dvec3(cameraToWorld[3]);
  frame.CameraUp = glm::normalize(glm::dvec3(cameraToWorld[1]));
  frame.Gamma = ViewLightAngle(frame.ViewDirection, frame.LightDirection);
  SetCameraTerms(frame, cameraView, cameraProjection, frame.Body, frame.LightDirection);
  LightView fit;
  if (!FitWarpedFrame(frame, resolution, warp, options, fit))
  {
    return Uniform(cameraView, cameraProjection, sceneBounds, lightDirection, resolution);
  }
  return fit;
}

namespace
{
// GMNPR's lambda grows without bound toward the view axis, and carried into a
// spot's space its warp strengthens faster than the 2 to 12 degree fade: fixed
// points moved up to 7.9 texels per 0.1 degree step. Over 2 to 30 degrees they
// stay within the 2-texel bound (ShadowMapWarping.SpotWarpMovesContinuously...).
constexpr double GMNPRSpotFullWarpAboveDegrees = 30.0;

WarpOptions SpotWarpOptions(DirectionalWarp warp, WarpOptions options)
{
  if (warp == DirectionalWarp::GMNPR)
  {
    options.FullWarpAboveDegrees =
      std::max(options.FullWarpAboveDegrees, GMNPRSpotFullWarpAboveDegrees);
  }
  return options;
}
} // namespace

namespace
{
glm::dvec3 Centroid(const std::vector<glm::dvec3>& points)
{
  glm::dvec3 centroid(0.0);
  for (const auto& p : points)
  {
    centroid += p / double(points.size());
  }
  return centroid;
}

// The points' extent along the view direction projected perpendicular to a
// light ray (the warp axis in the world); 0 when the view is along the ray.
double ExtentAcrossRay(
  const std::vector<glm::dvec3>& points, const glm::dvec3& view, const glm::dvec3& ray)
{
  const glm::dvec3 projected = view - glm::dot(view, ray) * ray;
  if (!(glm::length(projected) > 1e-12))
  {
    return 0.0;
  }
  const glm::dvec3 axis = glm::normalize(projected);
  double lo = Infinity, hi = -Infinity;
  for (const auto& p : points)
  {
    lo = std::min(lo, glm::dot(p, axis));
    hi = std::max(hi, glm::dot(p, axis));
  }
  return hi - lo;
}

// The camera's eye, axis and up in the spot's post-perspective space: the
// camera's axis over B's depths is the image of that segment (projective maps
// keep lines); where it reaches behind the light, the axis through B's centroid.
// False when they degenerate.
bool SetCameraInSpotSpace(const glm::dmat4& toLightSpace, const glm::dvec3& eye,
  const glm::dvec3& view, const glm::dvec3& up, const glm::dvec3& centroid, double step,
  WarpFrame& frame)
{
  const glm::dvec4 a = toLightSpace * glm::dvec4(eye + view * frame.ZNear, 1.0);
  const glm::dvec4 b = toLightSpace * glm::dvec4(eye + view * frame.ZFar, 1.0);
  const glm::dvec3 centre = ProjectPoint(toLightSpace, centroid);
  if (a.w > 0.0 && b.w > 0.0 && frame.ZFar > frame.ZNear)
  {
    frame.Eye = glm::dvec3(a) / a.w;
    frame.ViewDirection = glm::dvec3(b) / b.w - frame.Eye;
  }
  else
  {
    frame.Eye = centre;
    frame.ViewDirection = ProjectPoint(toLightSpace, centroid + view * step) - centre;
  }
  frame.CameraUp = ProjectPoint(toLightSpace, centroid + up * step) - centre;
  if (!(glm::length(frame.ViewDirection) > 0.0) || !(glm::length(frame.CameraUp) > 0.0) ||
    !IsFiniteVector(frame.ViewDirection) || !IsFiniteVector(frame.CameraUp))
  {
    return false;
  }
  frame.ViewDirection = glm::normalize(frame.ViewDirection);
  frame.CameraUp = glm::normalize(frame.CameraUp);
  return true;
}
} // namespace

LightView FitSpotWarped(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& sceneBounds, const glm::dvec3& position, const glm::dvec3& direction,
  double coneAngleDegrees, int resolution, DirectionalWarp warp, const WarpOptions& options)
{
  const glm::dmat4 cameraViewProjection = cameraProjection * cameraView;
  const LightView cone =
    FitSpot(cameraViewProjection, sceneBounds, position, direction, coneAngleDegrees, resolution);
  const bool parallelCamera = std::abs(cameraProjection[2][3]) < 1e-12;
  const glm::dmat4 toLightSpace = cone.ViewProjection();
  if (warp == DirectionalWarp::Uniform || parallelCamera || sceneBounds.IsEmpty() ||
    !IsFinite(cameraView) || !IsFinite(cameraProjection) || !IsFinite(toLightSpace))
  {
    return cone;
  }

  // B in the world, kept inside the spot's frustum so that it maps with w > 0.
  const Aabb scene = NonDegenerate(sceneBounds);
  const SpotSpace space = FocusInSpotSpace(cameraViewProjection, scene, cone);
  const std::vector<glm::dvec3>& worldBody = space.WorldBody;
  WarpFrame frame;
  frame.Body = space.Body;
  if (frame.Body.empty())
  {
    return cone;
  }
  const glm::dvec3 centroid = Centroid(worldBody);

  const glm::dmat4 cameraToWorld = glm::inverse(cameraView);
  const glm::dvec3 view = glm::normalize(-glm::dvec3(cameraToWorld[2]));
  const glm::dvec3 up = glm::normalize(glm::dvec3(cameraToWorld[1]));
  const glm::dvec3 eye(cameraToWorld[3]);
  const glm::dvec3 toCentroid = centroid - position;
  if (!(glm::length(toCentroid) > 0.0) || !IsFinite(cameraToWorld))
  {
    return cone;
  }
  const glm::dvec3 ray = glm::normalize(toCentroid);
  frame.Gamma = ViewLightAngle(view, ray);
  SetCameraTerms(frame, cameraView, cameraProjection, worldBody, ray);
  frame.WarpDepthInWorld = ExtentAcrossRay(worldBody, view, ray);

  // In the spot's post-perspective space light travels along +z and every
  // caster lies between its near and far planes.
  frame.Casters = Aabb{ glm::dvec3(-1.0), glm::dvec3(1.0) };
  frame.LightDirection = glm::dvec3(0.0, 0.0, 1.0);
  const double step = 1e-3 * std::max(frame.ZFar - frame.ZNear, scene.Diagonal() * 1e-6);
  if (!SetCameraInSpotSpace(toLightSpace, eye, view, up, centroid, step, frame))
  {
    return cone;
  }

  LightView fit;
  if (!FitWarpedFrame(frame, resolution, warp, SpotWarpOptions(warp, options), fit))
  {
    return cone;
  }
  // The warp's W is a plane over the map there too, as for the spot's TSM.
  return FromSpotSpace(fit, cone);
}

} // namespace shadowmaps
