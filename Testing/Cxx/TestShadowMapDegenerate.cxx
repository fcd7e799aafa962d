// Unit tests: Degenerate input to the fits, 16-bit depth, the texture mapping and finiteness checks (Plugin/Math/ShadowMapFocusing).
#include "FocusingTestHelpers.h"

using namespace focusingtest;

namespace
{
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
