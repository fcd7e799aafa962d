// Unit tests for the directional-light warps in Plugin/ShadowMapWarping.{h,cxx}:
// LiSPSM (surveys 003 and 000) and GMNPR (Zhang et al., 002). The quantities the
// papers define are measured from the implemented matrices, never hard-coded.
#include "ShadowMapCascades.h"
#include "ShadowMapMotion.h"
#include "ShadowMapPerspective.h"
#include "ShadowMapTrapezoid.h"
#include "ShadowMapWarping.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace
{
using shadowmaps::Aabb;
using shadowmaps::DirectionalWarp;
using shadowmaps::LightView;
using shadowmaps::WarpOptions;

constexpr double Pi = 3.14159265358979323846;
constexpr int Resolution = 2048;
constexpr double ClipTolerance = 1e-9;
// 002's set-up: phi = pi/6 (field of view 60 degrees), n = 1, f = 100 and 800.
constexpr double Phi = Pi / 6.0;

struct Camera
{
  glm::dmat4 View{ 1.0 };
  glm::dmat4 Projection{ 1.0 };
};

// Camera at the origin looking down -z with up +y, vertical field of view 2 phi.
Camera MakeCamera(double zNear, double zFar, double aspect = 1.0)
{
  Camera camera;
  camera.View = glm::lookAt(glm::dvec3(0.0), glm::dvec3(0.0, 0.0, -1.0), glm::dvec3(0.0, 1.0, 0.0));
  camera.Projection = glm::perspective(2.0 * Phi, aspect, zNear, zFar);
  return camera;
}

// Bounds of the camera frustum, grown by 1%: B is then the whole frustum.
Aabb EnclosingScene(const Camera& camera)
{
  Aabb box;
  for (const auto& p : shadowmaps::FrustumCorners(camera.Projection * camera.View))
  {
    box.Add(p);
  }
  const glm::dvec3 grow = 0.01 * (box.Max - box.Min);
  box.Min -= grow;
  box.Max += grow;
  return box;
}

// A light in the camera's yz plane at angle theta to the view direction (-z),
// shining downward for theta > 0.
glm::dvec3 LightAtAngle(double theta)
{
  return { 0.0, -std::sin(theta), -std::cos(theta) };
}

// The papers' parameterization: z_n is the camera's near depth however near
// (no pseudo near plane), as the formulas these tests check assume.
WarpOptions PaperWarp()
{
  WarpOptions options;
  options.PseudoNearFraction = 0.0;
  return options;
}

glm::dvec4 Clip(const LightView& fit, const glm::dvec3& p)
{
  return fit.ViewProjection() * glm::dvec4(p, 1.0);
}

// Shadow-map texture coordinates in texels (x, y of ClipToTexture times resolution).
glm::dvec2 Texels(const LightView& fit, const glm::dvec3& p)
{
  const glm::dvec4 c = shadowmaps::ClipToTexture() * Clip(fit, p);
  return glm::dvec2(c) / c.w * double(Resolution);
}

// Perspective aliasing measured from the matrices (003's dp/ds = (1/z)(dz/ds)(cos a/cos b)
// without the projection term cos a / cos b, i.e. 002's F up to the constant 1/tan phi):
// the world point at view depth z on the camera's view axis is moved along that axis,
// mapped through ViewProjection to shadow-map texture coordinates s, and
//   E(z) = (1 / z) * (dz / ds) = 1 / (z * |ds/dz|),
// with ds/dz by central differences of step 1e-5 z. |ds/dz| is the length of the 2D
// texture-coordinate derivative (the map's axes may be turned by multiples of 90 degrees).
double MeasuredAliasing(const LightView& fit, const Camera& camera, double z)
{
  const glm::dmat4 cameraToWorld = glm::inverse(camera.View);
  const glm::dvec3 eye(cameraToWorld[3]);
  const glm::dvec3 view = -glm::normalize(glm::dvec3(cameraToWorld[2]));
  const double h = 1e-5 * z;
  const glm::dvec2 a = Texels(fit, eye + view * (z - h)) / double(Resolution);
  const glm::dvec2 b = Texels(fit, eye + view * (z + h)) / double(Resolution);
  const double dsdz = glm::length(b - a) / (2.0 * h);
  return 1.0 / (z * dsdz);
}

// The warp frustum's near distance n measured from the matrices: along the warp axis
// (view direction projected perpendicular to the light) a perspective warp maps the
// light-space coordinate t to u(t) = a + b / (t - t0), t0 the apex; three samples give
// t0, and n = (smallest warp-axis coordinate of B) - t0.
double MeasuredWarpNear(const LightView& fit, const Camera& camera, const glm::dvec3& light)
{
  const glm::dmat4 cameraToWorld = glm::inverse(camera.View);
  const glm::dvec3 view = -glm::normalize(glm::dvec3(cameraToWorld[2]));
  const glm::dvec3 l = glm::normalize(light);
  const glm::dvec3 axis = glm::normalize(view - glm::dot(view, l) * l);
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const auto& p : shadowmaps::FrustumCorners(camera.Projection * camera.View))
  {
    lo = std::min(lo, glm::dot(p, axis));
    hi = std::max(hi, glm::dot(p, axis));
  }
  const std::array<double, 3> t = { lo, 0.5 * (lo + hi), hi };
  std::array<glm::dvec2, 3> s;
  for (int i = 0; i < 3; ++i)
  {
    s[i] = Texels(fit, axis * t[i]);
  }
  // The map coordinate that varies along the warp axis.
  const int c = std::abs(s[2].x - s[0].x) > std::abs(s[2].y - s[0].y) ? 0 : 1;
  const double r = (s[0][c] - s[1][c]) / (s[1][c] - s[2][c]);
  const double k = (t[1] - t[0]) / (t[2] - t[1]);
  const double t0 = (k * t[2] - r * t[0]) / (k - r);
  return lo - t0;
}

// Points spread through the camera frustum of MakeCamera(1, far): B for every light.
std::vector<glm::dvec3> PointsInFrustum(double zFar)
{
  std::vector<glm::dvec3> points;
  const double tanPhi = std::tan(Phi);
  for (double fraction : { 0.002, 0.02, 0.1, 0.3, 0.6, 0.95 })
  {
    const double z = 1.0 + fraction * (zFar - 1.0);
    for (double u : { -0.9, 0.0, 0.9 })
    {
      for (double v : { -0.9, 0.0, 0.9 })
      {
        points.push_back({ u * z * tanPhi, v * z * tanPhi, -z });
      }
    }
  }
  return points;
}

// Largest move (texels) of any point between two maps, up to the symmetries of the
// square map that keep its texel grid: a quarter turn of the map about its centre
// samples the world at exactly the same places, so it is not a pop. Returns the
// smallest such largest move over the four turns.
double MoveUpToQuarterTurns(const std::vector<glm::dvec2>& before, const std::vector<glm::dvec2>& after)
{
  const glm::dvec2 centre(0.5 * Resolution);
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 4; ++k)
  {
    double worst = 0.0;
    for (size_t i = 0; i < before.size(); ++i)
    {
      glm::dvec2 q = after[i] - centre;
      for (int turn = 0; turn < k; ++turn)
      {
        q = glm::dvec2(-q.y, q.x);
      }
      worst = std::max(worst, glm::length(q + centre - before[i]));
    }
    best = std::min(best, worst);
  }
  return best;
}

bool InsideClipCube(const glm::dvec4& c)
{
  if (!(c.w > 0.0))
  {
    return false;
  }
  const glm::dvec3 ndc = glm::dvec3(c) / c.w;
  return std::abs(ndc.x) <= 1.0 + ClipTolerance && std::abs(ndc.y) <= 1.0 + ClipTolerance &&
    std::abs(ndc.z) <= 1.0 + ClipTolerance;
}

const char* Name(DirectionalWarp warp)
{
  return warp == DirectionalWarp::LiSPSM ? "LiSPSM" : (warp == DirectionalWarp::GMNPR ? "GMNPR" : "Uniform");
}

// ---------------------------------------------------------------------------
// Parameter functions.

TEST(ShadowMapWarping, LiSPSMFreeParameterIsNoptOverSinGamma)
{
  for (double f : { 100.0, 800.0 })
  {
    const double nOpt = 1.0 + std::sqrt(f * 1.0); // 003 / 000: z_n + sqrt(z_f z_n)
    EXPECT_NEAR(shadowmaps::LiSPSMFreeParameter(1.0, f, Pi / 2, Phi, false), nOpt, 1e-12 * nOpt);
    for (double degrees : { 5.0, 20.0, 30.0, 45.0, 60.0, 89.0 })
    {
      const double gamma = glm::radians(degrees);
      const double n = shadowmaps::LiSPSMFreeParameter(1.0, f, gamma, Phi, false);
      EXPECT_NEAR(n * std::sin(gamma), nOpt, 1e-12 * nOpt) << degrees;
    }
    EXPECT_TRUE(std::isinf(shadowmaps::LiSPSMFreeParameter(1.0, f, 0.0, Phi, false)));
  }
}

TEST(ShadowMapWarping, LiSPSMLloydFalloffIsFasterBelowPhiAndContinuous)
{
  const double f = 100.0;
  for (double degrees : { 30.5, 45.0, 90.0 })
  {
    const double gamma = glm::radians(degrees);
    EXPECT_DOUBLE_EQ(shadowmaps::LiSPSMFreeParameter(1.0, f, gamma, Phi, true),
      shadowmaps::LiSPSMFreeParameter(1.0, f, gamma, Phi, false));
  }
  const double below = shadowmaps::LiSPSMFreeParameter(1.0, f, Phi - 1e-9, Phi, true);
  const double above = shadowmaps::LiSPSMFreeParameter(1.0, f, Phi + 1e-9, Phi, true);
  EXPECT_NEAR(below, above, 1e-6 * above);
  for (double degrees : { 1.0, 10.0, 20.0, 29.0 })
  {
    const double gamma = glm::radians(degrees);
    const double plain = shadowmaps::LiSPSMFreeParameter(1.0, f, gamma, Phi, false);
    const double lloyd = shadowmaps::LiSPSMFreeParameter(1.0, f, gamma, Phi, true);
    EXPECT_GT(lloyd, plain) << degrees;
    EXPECT_NEAR(lloyd, plain * std::sin(Phi) / std::sin(gamma), 1e-12 * lloyd) << degrees;
  }
}

TEST(ShadowMapWarping, GMNPRLambdaIsContinuousAtPhi)
{
  for (double f : { 100.0, 800.0 })
  {
    const double atPhi = std::sqrt(f) / (2.0 * f); // 002 Eq. 5: lambda_1(phi)
    const double left = shadowmaps::GMNPRLambda(Phi * (1.0 - 1e-10), Phi, 1.0, f);
    const double right = shadowmaps::GMNPRLambda(Phi * (1.0 + 1e-10), Phi, 1.0, f);
    const double at = shadowmaps::GMNPRLambda(Phi, Phi, 1.0, f);
    EXPECT_NEAR(left, right, 1e-8 * atPhi);
    EXPECT_NEAR(at, atPhi, 1e-12 * atPhi);
    EXPECT_NEAR(left, atPhi, 1e-8 * atPhi);
  }
}

TEST(ShadowMapWarping, GMNPRLambdaGrowsWithoutBoundAsThetaGoesToZero)
{
  for (double f : { 100.0, 800.0 })
  {
    double previous = shadowmaps::GMNPRLambda(Phi, Phi, 1.0, f);
    for (double theta = Phi * 0.5; theta > 1e-12; theta *= 0.5)
    {
      const double lambda = shadowmaps::GMNPRLambda(theta, Phi, 1.0, f);
      EXPECT_GT(lambda, previous) << theta;
      previous = lambda;
    }
    EXPECT_GT(previous, 1e9);
    EXPECT_TRUE(std::isinf(shadowmaps::GMNPRLambda(0.0, Phi, 1.0, f)));
  }
}

// 002 Eq. 3 on Eq. 2: lambda_GMNPR equalizes F at z = n and z = f for theta >= phi;
// LiSPSM's lambda (Eq. 9) does so only at theta = pi/2.
TEST(ShadowMapWarping, GMNPRLambdaEqualizesModelAliasing)
{
  for (double f : { 100.0, 800.0 })
  {
    for (double degrees : { 31.0, 45.0, 60.0, 75.0, 90.0 })
    {
      const double theta = glm::radians(degrees);
      const double lambda = shadowmaps::GMNPRLambda(theta, Phi, 1.0, f);
      const double nearF = shadowmaps::GMNPRAliasing(lambda, theta, Phi, 1.0, f, 1.0);
      const double farF = shadowmaps::GMNPRAliasing(lambda, theta, Phi, 1.0, f, f);
      EXPECT_NEAR(nearF / farF, 1.0, 1e-9) << "f " << f << " theta " << degrees;
    }
    const double lispsm = shadowmaps::LiSPSMLambda(Pi / 2, Phi, 1.0, f);
    EXPECT_NEAR(lispsm, shadowmaps::GMNPRLambda(Pi / 2, Phi, 1.0, f), 1e-12);
  }
}

// ---------------------------------------------------------------------------
// The implemented matrices.

TEST(ShadowMapWarping, LiSPSMImplementedNearDistanceFollowsFalloff)
{
  for (double f : { 100.0, 800.0 })
  {
    const Camera camera = MakeCamera(1.0, f);
    const Aabb scene = EnclosingScene(camera);
    const double nOpt = 1.0 + std::sqrt(f);
    for (bool lloyd : { false, true })
    {
      WarpOptions options = PaperWarp();
      options.LloydFalloff = lloyd;
      for (double degrees : { 15.0, 20.0, 30.0, 45.0, 60.0, 75.0, 90.0 })
      {
        const double gamma = glm::radians(degrees);
        const glm::dvec3 light = LightAtAngle(gamma);
        const LightView fit = shadowmaps::FitDirectionalWarped(camera.View, camera.Projection,
          scene, light, Resolution, DirectionalWarp::LiSPSM, options);
        ASSERT_TRUE(fit.Perspective);
        double expected = nOpt / std::sin(gamma);
        if (lloyd && gamma < Phi)
        {
          expected *= std::sin(Phi) / std::sin(gamma);
        }
        const double measured = MeasuredWarpNear(fit, camera, light);
        EXPECT_NEAR(measured / expected, 1.0, 1e-4)
          << "f " << f << " gamma " << degrees << " lloyd " << lloyd;
        if (degrees == 90.0)
        {
          std::printf("[ LiSPSM   ] f=%g gamma=90: measured n = %.6f, z_n + sqrt(z_f z_n) = %.6f\n", f,
            measured, nOpt);
        }
      }
    }
  }
}

// A directional warp stores depth linear in light space: recovered from the
// map as the casters and receivers do (z / w times the W given by the map
// position), the stored depth is the same for points at one distance along the
// light, affine in that distance, in [-1, 1] over B, and the rasterized z / w
// stays inside the clip volume. (Stored as rasterized, the warp's depth crowds
// the far part of B into a sliver.)
TEST(ShadowMapWarping, PseudoNearRaisesOnlyANearerNearDepth)
{
  EXPECT_DOUBLE_EQ(shadowmaps::PseudoNear(1.0, 800.0, 0.01), 8.0);
  EXPECT_DOUBLE_EQ(shadowmaps::PseudoNear(20.0, 800.0, 0.01), 20.0);
  EXPECT_DOUBLE_EQ(shadowmaps::PseudoNear(1.0, 800.0, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(shadowmaps::PseudoNear(1.0, 800.0, -3.0), 1.0) << "clamped to 0";
  EXPECT_DOUBLE_EQ(shadowmaps::PseudoNear(1.0, 800.0, 7.0), 800.0) << "clamped to 1";
  EXPECT_DOUBLE_EQ(
    shadowmaps::PseudoNear(1.0, 800.0, std::numeric_limits<double>::quiet_NaN()), 1.0);
}

// By default LiSPSM and GMNPR take their n from a near depth no nearer than
// 0.3 % of B's far depth: a camera's near plane a hair in front of it (1e-6 of
// the far plane here) warps the map as one at 0.3 % does, and a near plane
// beyond it keeps the papers' n.
TEST(ShadowMapWarping, WarpsTakeTheirNearDepthNoNearerThanThePseudoNearPlane)
{
  const double f = 800.0;
  const double gamma = glm::radians(60.0);
  const glm::dvec3 light = LightAtAngle(gamma);
  for (double zNear : { 1e-6 * f, 1.0, 0.05 * f })
  {
    const Camera camera = MakeCamera(zNear, f);
    const Aabb scene = EnclosingScene(camera);
    const double used = std::max(zNear, WarpOptions().PseudoNearFraction * f);
    const double expected = (used + std::sqrt(f * used)) / std::sin(gamma);
    const LightView fit = shadowmaps::FitDirectionalWarped(
      camera.View, camera.Projection, scene, light, Resolution, DirectionalWarp::LiSPSM);
    ASSERT_TRUE(fit.Perspective);
    EXPECT_NEAR(MeasuredWarpNear(fit, camera, light) / expected, 1.0, 1e-4) << "near " << zNear;

    const LightView gmnpr = shadowmaps::FitDirectionalWarped(
      camera.View, camera.Projection, scene, light, Resolution, DirectionalWarp::GMNPR);
    const double gmnprExpected = shadowmaps::GMNPRLambda(gamma, Phi, used, f) *
      shadowmaps::WarpDepthOfFrustum(gamma, Phi, zNear, f);
    EXPECT_NEAR(MeasuredWarpNear(gmnpr, camera, light) / gmnprExpected, 1.0, 1e-4)
      << "near " << zNear;
  }
  EXPECT_DOUBLE_EQ(WarpOptions().PseudoNearFraction, 0.003);
}

TEST(ShadowMapWarping, DirectionalWarpsStoreLinearLightSpaceDepth)
{
  const Camera camera = MakeCamera(1.0, 100.0);
  const Aabb scene = EnclosingScene(camera);
  const glm::dvec3 light = LightAtAngle(glm::radians(45.0));
  for (DirectionalWarp warp : { DirectionalWarp::LiSPSM, DirectionalWarp::GMNPR })
  {
    const LightView fit = shadowmaps::FitDirectionalWarped(
      camera.View, camera.Projection, scene, light, Resolution, warp, PaperWarp());
    ASSERT_TRUE(fit.Perspective);
    ASSERT_TRUE(fit.LinearDepth);
    const glm::dvec3 inverseW = shadowmaps::NdcToInverseW(fit);
    auto stored = [&](const glm::dvec3& world) {
      const glm::dvec4 clip = fit.ViewProjection() * glm::dvec4(world, 1.0);
      EXPECT_LE(std::abs(clip.z / clip.w), 1.0);
      const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
      return clip.z / clip.w / glm::dot(inverseW, glm::dvec3(ndc, 1.0));
    };
    const glm::dvec3 across = glm::normalize(glm::cross(light, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 inB(0.0, 0.0, -20.0); // on the camera's axis, inside B
    const double a = stored(inB);
    EXPECT_NEAR(stored(inB + across * 3.0), a, 1e-9);
    const double b = stored(inB + light * 2.0);
    const double c = stored(inB + light * 5.0);
    EXPECT_GT(b, a) << "depth grows away from the light";
    EXPECT_NEAR((c - a) / 5.0, (b - a) / 2.0, 1e-9);
    for (const glm::dvec3& p : shadowmaps::IntersectFrustumWithBox(camera.Projection * camera.View, scene))
    {
      EXPECT_LE(std::abs(stored(p)), 1.0 + 1e-9);
    }
  }
}

TEST(ShadowMapWarping, GMNPRImplementedNearDistanceIsLambdaTimesWarpDepth)
{
  for (double f : { 100.0, 800.0 })
  {
    const Camera camera = MakeCamera(1.0, f);
    const Aabb scene = EnclosingScene(camera);
    for (double degrees : { 15.0, 29.0, 31.0, 45.0, 60.0, 90.0 })
    {
      const double theta = glm::radians(degrees);
      const glm::dvec3 light = LightAtAngle(theta);
      const LightView fit = shadowmaps::FitDirectionalWarped(
        camera.View, camera.Projection, scene, light, Resolution, DirectionalWarp::GMNPR, PaperWarp());
      const double expected = shadowmaps::GMNPRLambda(theta, Phi, 1.0, f) *
        shadowmaps::WarpDepthOfFrustum(theta, Phi, 1.0, f);
      EXPECT_NEAR(MeasuredWarpNear(fit, camera, light) / expected, 1.0, 1e-4)
        << "f " << f << " theta " << degrees;
    }
  }
}

// GMNPR's defining property (002 Eq. 3), measured from the matrices: for theta > phi
// the perspective aliasing E(z) of MeasuredAliasing is the same at z = n and z = f.
// LiSPSM's is not (002 Fig. 6), except in the ideal case theta = 90 degrees.
TEST(ShadowMapWarping, GMNPREqualizesMeasuredAliasingAtNearAndFar)
{
  for (double f : { 100.0, 800.0 })
  {
    const Camera camera = MakeCamera(1.0, f);
    const Aabb scene = EnclosingScene(camera);
    double worstLiSPSM = 0.0;
    for (double degrees : { 35.0, 45.0, 55.0, 60.0, 75.0, 85.0, 90.0 })
    {
      const double theta = glm::radians(degrees);
      double ratios[2] = { 0.0, 0.0 };
      for (DirectionalWarp warp : { DirectionalWarp::GMNPR, DirectionalWarp::LiSPSM })
      {
        const LightView fit = shadowmaps::FitDirectionalWarped(
          camera.View, camera.Projection, scene, LightAtAngle(theta), Resolution, warp, PaperWarp());
        const double ratio = MeasuredAliasing(fit, camera, 1.0) / MeasuredAliasing(fit, camera, f);
        ratios[warp == DirectionalWarp::LiSPSM] = ratio;
        std::printf("[ aliasing ] f=%g theta=%4.1f %-6s E(n)/E(f) = %.4f\n", f, degrees, Name(warp), ratio);
      }
      EXPECT_NEAR(ratios[0], 1.0, 0.05) << "GMNPR f " << f << " theta " << degrees;
      if (degrees < 90.0)
      {
        worstLiSPSM = std::max(worstLiSPSM, std::abs(ratios[1] - 1.0));
      }
      else
      {
        EXPECT_NEAR(ratios[1], 1.0, 0.05) << "LiSPSM is optimal at 90 degrees";
      }
    }
    EXPECT_GT(worstLiSPSM, 0.05) << "LiSPSM should not equalize near/far aliasing for f " << f;
  }
}

// The measured aliasing curve of the implemented LiSPSM follows 002's model F (Eq. 2)
// with LiSPSM's lambda (Eq. 9): the matrices implement the paper's parameterization.
TEST(ShadowMapWarping, LiSPSMMeasuredAliasingMatchesModel)
{
  const double f = 100.0;
  const Camera camera = MakeCamera(1.0, f);
  const Aabb scene = EnclosingScene(camera);
  for (double degrees : { 40.0, 60.0, 80.0 })
  {
    const double theta = glm::radians(degrees);
    const LightView fit = shadowmaps::FitDirectionalWarped(camera.View, camera.Projection, scene,
      LightAtAngle(theta), Resolution, DirectionalWarp::LiSPSM, PaperWarp());
    const double lambda = shadowmaps::LiSPSMLambda(theta, Phi, 1.0, f);
    const double reference = shadowmaps::GMNPRAliasing(lambda, theta, Phi, 1.0, f, f);
    const double measuredReference = MeasuredAliasing(fit, camera, f);
    for (double z : { 1.0, 3.0, 10.0, 30.0 })
    {
      const double model = shadowmaps::GMNPRAliasing(lambda, theta, Phi, 1.0, f, z) / reference;
      const double measured = MeasuredAliasing(fit, camera, z) / measuredReference;
      EXPECT_NEAR(measured / model, 1.0, 1e-3) << degrees << " z " << z;
    }
  }
}

// ---------------------------------------------------------------------------
// Robustness.

// The light turns through the view direction (and through its opposite) in 0.1 degree
// steps. Fixed points of B move per step by what the light's rotation itself causes
// (the focused uniform map FitDirectional moves them ~3 texels per step here: a point
// 100 units down the light moves 100 * 0.00175 units, ~18 texels per unit) plus less
// than 2 texels: no flip, no pop where the warp axis reverses.
TEST(ShadowMapWarping, WarpIsContinuousThroughDegenerateAngle)
{
  const double f = 100.0;
  const Camera camera = MakeCamera(1.0, f);
  const Aabb scene = EnclosingScene(camera);
  const std::vector<glm::dvec3> points = PointsInFrustum(f);
  for (DirectionalWarp warp : { DirectionalWarp::LiSPSM, DirectionalWarp::GMNPR })
  {
    for (double opposite : { 1.0, -1.0 })
    {
      shadowmaps::testing::ExcessMotion motion(points, Resolution);
      for (int step = -20; step <= 20; ++step)
      {
        const double t = glm::radians(0.1 * step);
        const glm::dvec3 light(0.0, -std::sin(t), -opposite * std::cos(t));
        motion.Step(shadowmaps::FitDirectionalWarped(
                      camera.View, camera.Projection, scene, light, Resolution, warp),
          shadowmaps::FitDirectional(camera.Projection * camera.View, scene, light, Resolution));
      }
      const double worstExcess = motion.Worst();
      const double worstWarped = motion.LargestMove();
      const double worstUniform = motion.LargestReferenceMove();
      std::printf("[ continuity ] %-6s %s: largest move per 0.1 deg step %.4f texels "
                  "(FitDirectional %.4f), largest excess %.4f\n",
        Name(warp), opposite > 0 ? "through view dir " : "through -view dir", worstWarped,
        worstUniform, worstExcess);
      EXPECT_LT(worstExcess, 2.0) << Name(warp) << " opposite " << opposite;
    }
  }
}

// As the light leaves the view direction the warp fades in continuously: no step of
// 0.1 degree moves a point of B by more than 5% of the map (a pop, e.g. a flipped or
// suddenly warped map, moves it by a large part of the map). The largest moves are
// reported; warped maps follow the light by design.
TEST(ShadowMapWarping, WarpFadesInWithoutPopping)
{
  const double f = 100.0;
  const Camera camera = MakeCamera(1.0, f);
  const Aabb scene = EnclosingScene(camera);
  const std::vector<glm::dvec3> points = PointsInFrustum(f);
  for (DirectionalWarp warp : { DirectionalWarp::LiSPSM, DirectionalWarp::GMNPR })
  {
    for (double azimuth : { 0.0, 30.0, 45.0, 90.0, 135.0 })
    {
      // Light at angle theta from the view direction, turned by `azimuth` about it.
      const double a = glm::radians(azimuth);
      double worstBand = 0.0, worstAbove = 0.0, worstBandAt = 0.0, worstAboveAt = 0.0;
      std::vector<glm::dvec2> previous;
      for (int step = 0; step <= 600; ++step)
      {
        const double degrees = 0.1 * step;
        const double theta = glm::radians(degrees);
        const glm::dvec3 light(-std::sin(theta) * std::sin(a), -std::sin(theta) * std::cos(a), -std::cos(theta));
        const LightView fit = shadowmaps::FitDirectionalWarped(
          camera.View, camera.Projection, scene, light, Resolution, warp);
        ASSERT_TRUE(shadowmaps::IsFinite(fit.ViewProjection()));
        std::vector<glm::dvec2> current;
        for (const auto& p : points)
        {
          current.push_back(Texels(fit, p));
        }
        if (!previous.empty())
        {
          const double move = MoveUpToQuarterTurns(previous, current);
          double& worst = degrees <= 12.0 ? worstBand : worstAbove;
          if (move > worst)
          {
            worst = move;
            (degrees <= 12.0 ? worstBandAt : worstAboveAt) = degrees;
          }
        }
        previous = current;
      }
      std::printf("[ fade-in  ] %-6s azimuth %5.1f: largest move per 0.1 deg: %.2f texels in 0..12 deg "
                  "(at %.1f), %.2f in 12..60 deg (at %.1f)\n",
        Name(warp), azimuth, worstBand, worstBandAt, worstAbove, worstAboveAt);
      EXPECT_LT(worstBand, 0.05 * Resolution) << Name(warp) << " azimuth " << azimuth;
      EXPECT_LT(worstAbove, 0.05 * Resolution) << Name(warp) << " azimuth " << azimuth;
    }
  }
}

TEST(ShadowMapWarping, WarpedBodyAndCastersMapInsideUnitCube)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  struct Case
  {
    Camera Cam;
    Aabb Scene;
    glm::dvec3 Light;
  };
  std::vector<Case> cases;
  for (double f : { 100.0, 800.0 })
  {
    const Camera camera = MakeCamera(1.0, f, 1.5);
    for (double degrees : { 0.0, 1.0, 5.0, 20.0, 30.0, 45.0, 70.0, 90.0, 120.0, 170.0, 180.0 })
    {
      Aabb scene = EnclosingScene(camera);
      cases.push_back({ camera, scene, LightAtAngle(glm::radians(degrees)) });
      // A scene that cuts the frustum: B is smaller than the frustum.
      scene.Max.z = -0.3 * f;
      scene.Min.y = -0.2 * f;
      cases.push_back({ camera, scene, LightAtAngle(glm::radians(degrees)) });
    }
  }
  for (int i = 0; i < 60; ++i)
  {
    Camera camera;
    const glm::dvec3 eye(20.0 * uniform(random), 20.0 * uniform(random), 5.0 + 5.0 * uniform(random));
    const glm::dvec3 target(10.0 * uniform(random), 10.0 * uniform(random), uniform(random));
    camera.View = glm::lookAt(eye, target, glm::dvec3(0.0, 0.0, 1.0));
    camera.Projection = glm::perspective(glm::radians(30.0 + 40.0 * (1.0 + uniform(random))), 1.3, 0.5, 200.0);
    Aabb scene;
    scene.Min = { -30.0, -30.0, 0.0 };
    scene.Max = { 30.0, 30.0, 8.0 };
    const glm::dvec3 light(uniform(random), uniform(random), -0.2 - std::abs(uniform(random)));
    cases.push_back({ camera, scene, light });
  }
  int checked = 0;
  for (const auto& c : cases)
  {
    const std::vector<glm::dvec3> body =
      shadowmaps::IntersectFrustumWithBox(c.Cam.Projection * c.Cam.View, c.Scene);
    for (DirectionalWarp warp : { DirectionalWarp::LiSPSM, DirectionalWarp::GMNPR })
    {
      const LightView fit = shadowmaps::FitDirectionalWarped(
        c.Cam.View, c.Cam.Projection, c.Scene, c.Light, Resolution, warp);
      ASSERT_TRUE(shadowmaps::IsFinite(fit.ViewProjection()));
      EXPECT_GT(fit.TexelConstant, 0.0);
      const glm::dvec3 toLight = -glm::normalize(c.Light);
      for (const auto& p : body)
      {
        EXPECT_TRUE(InsideClipCube(Clip(fit, p))) << Name(warp);
        // Casters between the point and the light, as long as they are in the scene.
        for (double t = 0.05; t < 10.0; t *= 1.5)
        {
          const glm::dvec3 q = p + toLight * (t * c.Scene.Diagonal());
          if (glm::all(glm::greaterThanEqual(q, c.Scene.Min)) && glm::all(glm::lessThanEqual(q, c.Scene.Max)))
          {
            EXPECT_TRUE(InsideClipCube(Clip(fit, q))) << Name(warp) << " caster";
          }
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(ShadowMapWarping, WarpNeverProducesNonFiniteMatrices)
{
  std::vector<Camera> cameras;
  cameras.push_back(MakeCamera(1.0, 100.0));
  cameras.push_back(MakeCamera(0.01, 1e5, 2.0));
  Camera parallel;
  parallel.View = cameras[0].View;
  parallel.Projection = glm::ortho(-10.0, 10.0, -10.0, 10.0, 1.0, 100.0);
  cameras.push_back(parallel);
  Camera tilted;
  tilted.View = glm::lookAt(glm::dvec3(3.0, 4.0, 5.0), glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 1.0));
  tilted.Projection = glm::perspective(glm::radians(45.0), 1.0, 0.1, 50.0);
  cameras.push_back(tilted);

  std::vector<Aabb> scenes;
  Aabb box;
  box.Min = { -50.0, -50.0, -120.0 };
  box.Max = { 50.0, 50.0, 10.0 };
  scenes.push_back(box); // camera inside the geometry
  Aabb point;
  point.Add(glm::dvec3(0.0, 0.0, -10.0));
  scenes.push_back(point);
  Aabb flat;
  flat.Min = { -20.0, -20.0, -30.0 };
  flat.Max = { 20.0, 20.0, -30.0 };
  scenes.push_back(flat);
  Aabb behind;
  behind.Min = { -1.0, -1.0, 10.0 };
  behind.Max = { 1.0, 1.0, 12.0 };
  scenes.push_back(behind); // B empty
  scenes.push_back(Aabb()); // empty scene

  std::vector<glm::dvec3> lights = { { 0.0, 0.0, -1.0 }, { 0.0, 0.0, 1.0 }, { 0.0, -1.0, 0.0 },
    { 1.0, 1.0, 1.0 }, { 0.0, 1e-15, -1.0 }, { -0.6, -0.8, 0.0 }, { 0.0, 0.0, 0.0 } };
  for (const auto& camera : cameras)
  {
    // Exactly along and against this camera's view direction.
    const glm::dvec3 view = -glm::dvec3(glm::inverse(camera.View)[2]);
    std::vector<glm::dvec3> all = lights;
    all.push_back(view);
    all.push_back(-view);
    for (const auto& scene : scenes)
    {
      for (const auto& light : all)
      {
        for (DirectionalWarp warp : { DirectionalWarp::Uniform, DirectionalWarp::LiSPSM, DirectionalWarp::GMNPR })
        {
          for (double n : { 0.0, 1e-6, 1e6 })
          {
            WarpOptions options;
            options.FreeParameterN = n;
            const LightView fit = shadowmaps::FitDirectionalWarped(
              camera.View, camera.Projection, scene, light, Resolution, warp, options);
            EXPECT_TRUE(shadowmaps::IsFinite(fit.ViewProjection())) << Name(warp);
            EXPECT_TRUE(std::isfinite(fit.TexelConstant) && std::isfinite(fit.TexelPerUnitDistance));
          }
        }
      }
    }
  }
}

TEST(ShadowMapWarping, ParallelCameraDegradesToUniform)
{
  Camera parallel = MakeCamera(1.0, 100.0);
  parallel.Projection = glm::ortho(-10.0, 10.0, -10.0, 10.0, 1.0, 100.0);
  Aabb scene;
  scene.Min = { -20.0, -20.0, -120.0 };
  scene.Max = { 20.0, 20.0, 0.0 };
  const glm::dvec3 light = LightAtAngle(glm::radians(60.0));
  const LightView uniform = shadowmaps::FitDirectional(parallel.Projection * parallel.View, scene, light, Resolution);
  for (DirectionalWarp warp : { DirectionalWarp::LiSPSM, DirectionalWarp::GMNPR })
  {
    const LightView fit = shadowmaps::FitDirectionalWarped(
      parallel.View, parallel.Projection, scene, light, Resolution, warp);
    EXPECT_FALSE(fit.Perspective);
    const glm::dmat4 a = fit.ViewProjection(), b = uniform.ViewProjection();
    for (int c = 0; c < 4; ++c)
    {
      for (int r = 0; r < 4; ++r)
      {
        EXPECT_DOUBLE_EQ(a[c][r], b[c][r]);
      }
    }
  }
}

// TexelConstant is conservative: at every sampled point of B, a world step of
// TexelConstant perpendicular to the light spans at least one texel (the texel
// there is no larger than TexelConstant).
TEST(ShadowMapWarping, TexelConstantBoundsWorldTexelOverBody)
{
  const double f = 100.0;
  const Camera camera = MakeCamera(1.0, f);
  const Aabb scene = EnclosingScene(camera);
  for (DirectionalWarp warp : { DirectionalWarp::LiSPSM, DirectionalWarp::GMNPR })
  {
    const glm::dvec3 light = LightAtAngle(glm::radians(60.0));
    const LightView fit = shadowmaps::FitDirectionalWarped(
      camera.View, camera.Projection, scene, light, Resolution, warp);
    const glm::dvec3 l = glm::normalize(light);
    const glm::dvec3 u = glm::normalize(glm::cross(l, glm::dvec3(1.0, 0.0, 0.0)));
    const glm::dvec3 v = glm::cross(l, u);
    double finest = std::numeric_limits<double>::infinity();
    for (const auto& p : PointsInFrustum(f))
    {
      for (const auto& axis : { u, v })
      {
        const double texels = glm::length(Texels(fit, p + axis * fit.TexelConstant) - Texels(fit, p));
        finest = std::min(finest, texels);
      }
    }
    EXPECT_GE(finest, 0.99) << Name(warp);
    std::printf("[ texel    ] %-6s TexelConstant = %.5f (uniform fit: %.5f)\n", Name(warp), fit.TexelConstant,
      shadowmaps::FitDirectional(camera.Projection * camera.View, scene, light, Resolution).TexelConstant);
  }
}

} // namespace

// The spot-light warps of vtkWarpedShadowMapPass: LiSPSM and GMNPR (FitSpotWarped),
// TSM (FitSpotTrapezoid) and PSM (FitSpotPerspective).
enum class SpotWarp
{
  LiSPSM,
  GMNPR,
  TSM,
  PSM
};
constexpr SpotWarp SpotWarps[] = { SpotWarp::LiSPSM, SpotWarp::GMNPR, SpotWarp::TSM, SpotWarp::PSM };

const char* Name(SpotWarp warp)
{
  switch (warp)
  {
    case SpotWarp::LiSPSM:
      return "LiSPSM";
    case SpotWarp::GMNPR:
      return "GMNPR";
    case SpotWarp::TSM:
      return "TSM";
    default:
      return "PSM";
  }
}

LightView FitSpotWith(SpotWarp warp, const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& scene, const glm::dvec3& position, const glm::dvec3& direction, double coneAngle,
  int resolution)
{
  if (warp == SpotWarp::TSM)
  {
    return shadowmaps::FitSpotTrapezoid(
      cameraView, cameraProjection, scene, position, direction, coneAngle, resolution);
  }
  if (warp == SpotWarp::PSM)
  {
    // As vtkWarpedShadowMapPass sets it up: slide-back sqrt(near far), the fade by
    // the angle between the view and the spot's axis.
    const glm::dvec2 planes = shadowmaps::ProjectionDepthRange(cameraProjection);
    const glm::dvec3 view = -glm::dvec3(glm::transpose(cameraView)[2]);
    return shadowmaps::FitSpotPerspective(cameraView, cameraProjection, scene, position, direction,
      coneAngle, resolution, std::sqrt(planes.x * planes.y),
      shadowmaps::PerspectiveWarpWeight(view, direction))
      .Light;
  }
  return shadowmaps::FitSpotWarped(cameraView, cameraProjection, scene, position, direction,
    coneAngle, resolution, warp == SpotWarp::GMNPR ? DirectionalWarp::GMNPR : DirectionalWarp::LiSPSM);
}

// The camera along the ground and a spot above the scene, shining at the origin.
struct SpotOverGround
{
  const glm::dmat4 cameraView =
    glm::lookAt(glm::dvec3(0.0, -9.5, 1.2), glm::dvec3(0.0, 0.0, 0.8), glm::dvec3(0.0, 0.0, 1.0));
  const glm::dmat4 cameraProjection = glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.1, 40.0);
  const shadowmaps::Aabb scene{ glm::dvec3(-10.0, -10.0, -0.1), glm::dvec3(10.0, 10.0, 2.5) };
  const glm::dvec3 spot{ 5.0, -2.0, 7.0 };
  const glm::dvec3 axis = glm::normalize(-spot);
};

// A spot light's warped map keeps what a shadow map needs: points on one ray
// from the light land on one texel, in depth order, and the focus body maps
// inside the unit cube.
TEST(ShadowMapWarping, SpotWarpKeepsLightRaysAndDepthOrder)
{
  const SpotOverGround set;
  const auto& [cameraView, cameraProjection, scene, spot, axis] = set;
  for (SpotWarp warp : SpotWarps)
  {
    const LightView fit = FitSpotWith(warp, cameraView, cameraProjection, scene, spot, axis, 30.0, 1024);
    ASSERT_TRUE(shadowmaps::IsFinite(fit.ViewProjection()));
    EXPECT_TRUE(fit.TexelSizeFromGradient);
    EXPECT_EQ(fit.LinearDepth, warp != SpotWarp::PSM) << Name(warp);
    const glm::dmat4 m = fit.ViewProjection();
    for (const glm::dvec3& ground : { glm::dvec3(-1.4, 0.5, 0.0), glm::dvec3(2.0, 4.0, 0.0),
           glm::dvec3(-3.0, -5.0, 0.0) })
    {
      const glm::dvec4 g = m * glm::dvec4(ground, 1.0);
      const glm::dvec4 c = m * glm::dvec4(spot + 0.7 * (ground - spot), 1.0);
      ASSERT_GT(g.w, 0.0);
      ASSERT_GT(c.w, 0.0);
      const glm::dvec3 gn = glm::dvec3(g) / g.w;
      const glm::dvec3 cn = glm::dvec3(c) / c.w;
      EXPECT_NEAR(gn.x, cn.x, 1e-9) << Name(warp);
      EXPECT_NEAR(gn.y, cn.y, 1e-9) << Name(warp);
      EXPECT_LT(cn.z, gn.z) << Name(warp) << ": the caster is nearer the light";
      // Receivers the camera sees lie in the map (PSM fits nothing else).
      const glm::dvec4 seen = cameraProjection * cameraView * glm::dvec4(ground, 1.0);
      if (std::abs(seen.x) <= seen.w && std::abs(seen.y) <= seen.w)
      {
        EXPECT_LE(std::abs(gn.x), 1.0) << Name(warp);
        EXPECT_LE(std::abs(gn.y), 1.0) << Name(warp);
        EXPECT_LE(std::abs(gn.z), 1.0) << Name(warp);
      }
    }
  }
}

// A spot's TSM, LiSPSM and GMNPR maps store the spot's own depth, not warped
// by the trapezoid or the light-space perspective: points at one depth of the
// cone map store one depth, and stored depth is affine in the cone map's. (Stored
// as rasterized, a warp crowds the depths far from the light into a sliver.)
TEST(ShadowMapWarping, SpotWarpsStoreTheConeMapsDepth)
{
  const SpotOverGround set;
  const auto& [cameraView, cameraProjection, scene, spot, axis] = set;
  const glm::dmat4 cone =
    shadowmaps::FitSpot(cameraProjection * cameraView, scene, spot, axis, 30.0, 1024).ViewProjection();
  for (SpotWarp warp : { SpotWarp::TSM, SpotWarp::LiSPSM, SpotWarp::GMNPR })
  {
    const LightView fit = FitSpotWith(warp, cameraView, cameraProjection, scene, spot, axis, 30.0, 1024);
    ASSERT_TRUE(fit.LinearDepth) << Name(warp);
    const glm::dvec3 inverseW = shadowmaps::NdcToInverseW(fit);
    // The stored depth (before the 0.5 z + 0.5 of the texture) of a cone-map point.
    auto stored = [&](const glm::dvec3& conePoint) {
      const glm::dvec4 world = glm::inverse(cone) * glm::dvec4(conePoint, 1.0);
      const glm::dvec4 clip = fit.ViewProjection() * world;
      const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
      return clip.z / clip.w / glm::dot(inverseW, glm::dvec3(ndc, 1.0));
    };
    const double a = stored({ -0.5, -0.3, 0.2 });
    EXPECT_NEAR(stored({ 0.6, 0.4, 0.2 }), a, 1e-9) << Name(warp);
    EXPECT_NEAR(stored({ 0.1, -0.7, 0.2 }), a, 1e-9) << Name(warp);
    const double b = stored({ 0.1, 0.2, 0.6 });
    const double c = stored({ -0.4, 0.5, 0.8 });
    EXPECT_GT(std::abs(b - a), 1e-3) << Name(warp);
    EXPECT_NEAR((c - a) / (0.8 - 0.2), (b - a) / (0.6 - 0.2), 1e-9) << Name(warp);
  }
}

// Degenerate spot set-ups give finite matrices: camera looking along the spot's
// axis, standing at the light, inside the scene, parallel projection, no scene.
TEST(ShadowMapWarping, SpotWarpStaysFiniteInDegenerateViews)
{
  const shadowmaps::Aabb scene{ glm::dvec3(-10.0, -10.0, 0.0), glm::dvec3(10.0, 10.0, 2.5) };
  const glm::dvec3 spot(0.0, 0.0, 8.0);
  const glm::dvec3 down(0.0, 0.0, -1.0);
  const glm::dmat4 perspective = glm::perspective(glm::radians(30.0), 1.0, 0.1, 40.0);
  const glm::dmat4 parallel = glm::ortho(-5.0, 5.0, -5.0, 5.0, 0.1, 40.0);
  struct Case
  {
    glm::dvec3 Eye, Target;
    glm::dmat4 Projection;
    shadowmaps::Aabb Scene;
  };
  const Case cases[] = {
    { spot + glm::dvec3(0.0, 0.0, 1.0), glm::dvec3(0.0), perspective, scene }, // along the axis
    { spot, glm::dvec3(0.0), perspective, scene },                             // at the light
    { glm::dvec3(0.0, 0.0, 1.0), glm::dvec3(0.0, 5.0, 1.0), perspective, scene }, // inside
    { glm::dvec3(0.0, -9.5, 1.2), glm::dvec3(0.0), parallel, scene },
    { glm::dvec3(0.0, -9.5, 1.2), glm::dvec3(0.0), perspective, shadowmaps::Aabb() },
  };
  for (SpotWarp warp : SpotWarps)
  {
    for (const Case& c : cases)
    {
      const glm::dvec3 forward = glm::normalize(c.Target - c.Eye);
      const glm::dvec3 up = std::abs(forward.z) > 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
      const LightView fit = FitSpotWith(
        warp, glm::lookAt(c.Eye, c.Target, up), c.Projection, c.Scene, spot, down, 40.0, 1024);
      EXPECT_TRUE(shadowmaps::IsFinite(fit.ViewProjection()))
        << Name(warp) << ", eye " << c.Eye.x << " " << c.Eye.y << " " << c.Eye.z;
    }
  }
}

// Issue property for spot lights: the spot swings in 0.1 degree steps through the
// camera's axis (its rays to the scene then run along the view, or against it when
// it faces the camera); the map coordinates of fixed points move by less than 2
// texels per step beyond the moves of the uniform cone map (FitSpot). The spot stays
// outside the scene's bounds, where the cone map's near plane does not jump.
// GMNPR does not meet the bound yet (issue #4): its moves are printed, not checked.
TEST(ShadowMapWarping, SpotWarpMovesContinuouslyThroughTheViewAxis)
{
  const glm::dvec3 eye(0.0, -9.5, 1.2);
  const glm::dvec3 view = glm::normalize(glm::dvec3(0.0, 9.5, -0.4));
  const glm::dmat4 cameraView = glm::lookAt(eye, eye + view, glm::dvec3(0.0, 0.0, 1.0));
  const glm::dmat4 cameraProjection = glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.1, 40.0);
  const Aabb scene{ glm::dvec3(-10.0, -10.0, -0.1), glm::dvec3(10.0, 10.0, 2.5) };
  const glm::dvec3 centre = eye + view * 8.0;
  const glm::dvec3 side = glm::normalize(glm::cross(view, glm::dvec3(0.0, 0.0, 1.0)));
  const glm::dvec3 up = glm::cross(side, view);
  std::vector<glm::dvec3> points;
  for (double x : { -1.5, 0.0, 1.5 })
  {
    for (double y : { -3.0, 0.0, 3.0 })
    {
      points.push_back(centre + side * x + glm::dvec3(0.0, y, 0.0) - glm::dvec3(0.0, 0.0, centre.z));
    }
  }
  for (SpotWarp warp : SpotWarps)
  {
    for (double facing : { 1.0, -1.0 })
    {
      for (const glm::dvec3& across : { up, side })
      {
        shadowmaps::testing::ExcessMotion motion(points, Resolution);
        for (int step = -20; step <= 20; ++step)
        {
          const double t = glm::radians(0.1 * step);
          const glm::dvec3 ray = facing * (std::cos(t) * view + std::sin(t) * across);
          const glm::dvec3 spot = centre - ray * 16.0;
          const LightView fit =
            FitSpotWith(warp, cameraView, cameraProjection, scene, spot, ray, 40.0, Resolution);
          ASSERT_TRUE(shadowmaps::IsFinite(fit.ViewProjection()));
          motion.Step(fit,
            shadowmaps::FitSpot(cameraProjection * cameraView, scene, spot, ray, 40.0, Resolution));
        }
        const double worstExcess = motion.Worst();
        std::printf("[ continuity ] spot %-6s %s, turning %s: largest excess %.4f texels\n",
          Name(warp), facing > 0 ? "behind the camera" : "facing it        ",
          across == up ? "up  " : "side", worstExcess);
        EXPECT_LT(worstExcess, 2.0) << Name(warp) << " facing " << facing;
      }
    }
  }
}
