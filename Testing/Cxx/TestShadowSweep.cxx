// The robustness sweep (Measurement/ShadowSweep.h): its case draws, the
// defects it found, each rebuilt by hand as a regression case, and a fixed-seed
// sweep held to bounds taken from the measured distribution.
#include "ShadowScenes.h"
#include "ShadowSweep.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <set>
#include <sstream>

namespace
{
using shadowsweep::Case;
using shadowsweep::CaseResult;
using shadowsweep::LightKind;

const double CityBounds[6] = { -96.0, 96.0, -96.0, 96.0, 0.0, 38.6 };

// --- the draws ------------------------------------------------------------------------

TEST(ShadowSweepDraws, ACaseIsReproducibleFromItsSeedAlone)
{
  for (int i = 0; i < 50; ++i)
  {
    const std::uint64_t seed = shadowsweep::CaseSeed(3, i);
    const Case a = shadowsweep::DrawCase(seed, CityBounds, 192, 144);
    const Case b = shadowsweep::DrawCase(seed, CityBounds, 192, 144);
    EXPECT_EQ(shadowsweep::Describe(a), shadowsweep::Describe(b));
    EXPECT_EQ(a.Camera.Position, b.Camera.Position);
    EXPECT_EQ(a.Light.Position, b.Light.Position);
    EXPECT_EQ(a.Scene, shadowsweep::SceneOfCase(seed));
  }
  EXPECT_NE(shadowsweep::CaseSeed(1, 0), shadowsweep::CaseSeed(1, 1));
  EXPECT_NE(shadowsweep::CaseSeed(1, 0), shadowsweep::CaseSeed(2, 0));
}

// Over many seeds the draws cover what the sweep promises, within its ranges.
TEST(ShadowSweepDraws, DrawsCoverEveryKindOfCaseWithinRange)
{
  std::set<std::string> scenes, lights, cameras;
  int parallel = 0, cameraLights = 0, nonSquare = 0;
  double smallestRatio = 1.0, largestRatio = 0.0;
  const int draws = 4000;
  for (int i = 0; i < draws; ++i)
  {
    const Case c = shadowsweep::DrawCase(shadowsweep::CaseSeed(5, i), CityBounds, 200, 100);
    scenes.insert(c.Scene);
    lights.insert(c.Light.Description.substr(0, c.Light.Description.find(" of ")));
    cameras.insert(c.Camera.Description.substr(0, c.Camera.Description.find(',')));
    parallel += c.Camera.Parallel ? 1 : 0;
    cameraLights += c.Light.CameraLight ? 1 : 0;
    nonSquare += c.Width != c.Height ? 1 : 0;
    if (!c.Camera.Parallel)
    {
      EXPECT_GE(c.Camera.ViewAngle, 10.0);
      EXPECT_LE(c.Camera.ViewAngle, 100.0);
    }
    const double ratio = c.Camera.Near / c.Camera.Far;
    smallestRatio = std::min(smallestRatio, ratio);
    largestRatio = std::max(largestRatio, ratio);
    EXPECT_GT(c.Camera.Near, 0.0);
    if (c.Light.Kind == LightKind::Spot)
    {
      EXPECT_GT(c.Light.ConeAngle, 0.0);
      EXPECT_LT(c.Light.ConeAngle, 90.0);
    }
    if (c.Light.Description == "point light behind and above the camera")
    {
      const glm::dvec3 lamp = c.Light.Position - c.Camera.Position;
      EXPECT_GT(lamp.z, 0.0);
      EXPECT_LE(glm::dot(glm::dvec2(lamp), glm::dvec2(c.Camera.FocalPoint - c.Camera.Position)), 0.0);
      EXPECT_FALSE(c.Camera.Parallel);
    }
    EXPECT_GE(c.Width, 100);
    EXPECT_LE(c.Width, 300);
    EXPECT_GE(c.Height, 50);
    EXPECT_LE(c.Height, 150);
    EXPECT_TRUE(std::isfinite(glm::length(c.Camera.FocalPoint - c.Camera.Position)));
    EXPECT_GT(glm::length(c.Camera.FocalPoint - c.Camera.Position), 0.0);
  }
  const auto sweepScenes = shadowscenes::SweepSceneNames();
  EXPECT_EQ(scenes, std::set<std::string>(sweepScenes.begin(), sweepScenes.end()));
  for (const char* light : { "sun from any direction", "sun along the view", "sun against the view",
         "spot", "point light inside the scene", "point light outside the scene",
         "point light behind and above the camera", "camera spot light",
         "camera directional light" })
  {
    EXPECT_EQ(lights.count(light), 1u) << light;
  }
  for (const char* camera : { "street level", "inside the room", "inside the scene", "above the scene" })
  {
    EXPECT_EQ(cameras.count(camera), 1u) << camera;
  }
  EXPECT_GT(parallel, draws / 8);
  EXPECT_GT(cameraLights, draws / 20);
  EXPECT_GT(nonSquare, draws / 2);
  EXPECT_LT(smallestRatio, 2e-5);
  EXPECT_GT(largestRatio, 0.05);
  EXPECT_LE(largestRatio, 0.1 + 1e-12);
  EXPECT_GE(smallestRatio, 1e-5 - 1e-12);
}

TEST(ShadowSweepDraws, SummariseTakesMedianPercentileAndWorstOverCountedCases)
{
  std::vector<CaseResult> results(4);
  const double uniform[] = { 1.0, 2.0, 3.0, 50.0 };
  const double warped[] = { 2.0, 0.5, 9.0, 80.0 };
  for (int i = 0; i < 4; ++i)
  {
    results[i].Drawn.Seed = 100 + i;
    results[i].Counted = i == 3 ? 10 : 1000; // the last one has too few pixels
    results[i].Techniques.resize(2);
    results[i].Techniques[0].Technique = "uniform";
    results[i].Techniques[0].Errors.Misclassified = uniform[i];
    results[i].Techniques[1].Technique = "lispsm";
    results[i].Techniques[1].Errors.Misclassified = warped[i];
  }
  results[3].Techniques[1].GLErrors = 1;
  const auto d = shadowsweep::Summarise(results, 300);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].Cases, 3);
  EXPECT_DOUBLE_EQ(d[0].Median, 2.0);
  EXPECT_DOUBLE_EQ(d[0].Worst, 3.0);
  EXPECT_DOUBLE_EQ(d[1].Median, 2.0);
  EXPECT_DOUBLE_EQ(d[1].Percentile95, 9.0);
  EXPECT_DOUBLE_EQ(d[1].Worst, 9.0);
  EXPECT_EQ(d[1].WorstSeed, 102u);
  EXPECT_DOUBLE_EQ(d[1].UniformWorst, 3.0);
  EXPECT_EQ(d[1].Flagged, 1);

  // A sweep measuring only counted cases (Options::CountedOnly) leaves the
  // others without results, first ones included: the same distributions.
  CaseResult unmeasured;
  unmeasured.Counted = 10;
  results.insert(results.begin(), unmeasured);
  results.push_back(unmeasured);
  const auto same = shadowsweep::Summarise(results, 300);
  ASSERT_EQ(same.size(), 2u);
  EXPECT_EQ(same[1].Technique, "lispsm");
  EXPECT_EQ(same[1].Cases, 3);
  EXPECT_DOUBLE_EQ(same[1].Percentile95, 9.0);
  EXPECT_EQ(same[1].Flagged, 1);
}

// --- the defects the sweep found, as hand-built cases ---------------------------------

shadowsweep::Options RegressionOptions(const std::vector<std::string>& techniques)
{
  shadowsweep::Options options;
  options.Techniques = techniques;
  options.OutputDirectory = SHADOWMAPS_TEST_OUTPUT_DIR;
  return options;
}

CaseResult MeasureOne(const Case& drawn, const std::vector<std::string>& techniques)
{
  std::vector<CaseResult> results;
  std::string error;
  std::ostringstream log;
  EXPECT_TRUE(shadowsweep::MeasureCases({ drawn }, RegressionOptions(techniques), results, log, error))
    << error;
  return results.empty() ? CaseResult() : results.front();
}

/// A perspective case by hand (the sweep prints these figures for a seed).
Case MakeCase(const std::string& scene, const glm::dvec3& eye, const glm::dvec3& focal,
  double viewAngle, double nearPlane, double farPlane, int width, int height)
{
  Case drawn;
  drawn.Scene = scene;
  drawn.Camera.Position = eye;
  drawn.Camera.FocalPoint = focal;
  drawn.Camera.ViewAngle = viewAngle;
  drawn.Camera.Near = nearPlane;
  drawn.Camera.Far = farPlane;
  drawn.Width = width;
  drawn.Height = height;
  return drawn;
}

Case CityCase(const glm::dvec3& eye, const glm::dvec3& focal, double viewAngle, double nearPlane,
  double farPlane, int width, int height)
{
  return MakeCase("city", eye, focal, viewAngle, nearPlane, farPlane, width, height);
}

/// Sets the case's light (camera lights in camera-light coordinates).
void SetLight(Case& drawn, LightKind kind, const glm::dvec3& position, const glm::dvec3& focal,
  double coneAngle = 180.0, bool cameraLight = false)
{
  drawn.Light.Kind = kind;
  drawn.Light.Position = position;
  drawn.Light.FocalPoint = focal;
  drawn.Light.ConeAngle = coneAngle;
  drawn.Light.CameraLight = cameraLight;
}

void ExpectNoFlags(const CaseResult& result)
{
  for (const auto& t : result.Techniques)
  {
    EXPECT_FALSE(t.Flagged()) << t.Technique << ": " << t.Flags() << "\n" << t.Messages;
  }
}

double Misclassified(const CaseResult& result, const std::string& technique)
{
  for (const auto& t : result.Techniques)
  {
    if (t.Technique == technique)
    {
      return t.Errors.Misclassified;
    }
  }
  ADD_FAILURE() << technique << " not measured";
  return 100.0;
}

// Sweep seed 14701471144409361684: a wide spot (52.9 degrees) at the city's
// edge shining across it. Its LiSPSM, GMNPR and TSM maps lit every shadowed
// pixel (92.86, 92.86, 63.13% misclassified against the uniform map's 0.20):
// the warp divided the spot's hyperbolic depth by its own w, and the slope-scaled
// offset taken on that depth pushed whole walls behind their receivers.
TEST(ShadowSweepDefects, WarpedSpotOverTheCityKeepsItsShadows)
{
  Case drawn = CityCase({ -15.6120837, -88.8140133, 25.8177729 },
    { -6.92328864, -16.4845458, 36.3250963 }, 44.8, 1.96153, 234.275, 273, 151);
  SetLight(drawn, LightKind::Spot, { -81.9046138, 62.4703818, 25.2727842 },
    { 31.792049, -30.0796561, 3.57617251 }, 52.8927);
  const CaseResult result = MeasureOne(drawn, { "uniform", "lispsm", "gmnpr", "tsm", "csm-lispsm" });
  ASSERT_GT(result.TruthShadowed, 5000);
  ExpectNoFlags(result);
  const double uniform = Misclassified(result, "uniform");
  EXPECT_LT(uniform, 0.5);
  for (const char* warped : { "lispsm", "gmnpr", "tsm", "csm-lispsm" })
  {
    // Measured after the fix: 0.68, 0.86, 0.53, 0.66.
    EXPECT_LT(Misclassified(result, warped), 1.5) << warped;
  }
}

// Sweep seed 17706865990832572029: a street-level camera with the sun behind it.
// PSM lost the shadow of the building over the camera's shoulder on the near
// street (27.52% misclassified against the uniform map's 0.08): that building
// lies behind the camera, where post-perspective space has w < 0 and the GPU
// clips it out of the map.
TEST(ShadowSweepDefects, PSMKeepsCastersBehindTheCamera)
{
  Case drawn = CityCase({ -22.1915206, -1.89835282, 1.5946588 },
    { -22.1915206, -84.0799536, -2.40510733 }, 79.8, 0.00202302, 163.705, 222, 210);
  SetLight(drawn, LightKind::Directional, { -170.28219, 133.587541, 187.77337 },
    { 0.0, 0.0, 19.314188 });
  const CaseResult result = MeasureOne(drawn, { "uniform", "psm" });
  ASSERT_GT(result.TruthShadowed, 20000);
  ExpectNoFlags(result);
  EXPECT_LT(Misclassified(result, "uniform"), 0.5);
  EXPECT_LT(Misclassified(result, "psm"), 0.5); // 0.06 after the fix
}

// The report: a spot ahead of a street-level viewer and above the
// street, where PSM covered the lit street with acne (false shadows on 59, 3.7
// and 18% of the counted pixels below, 0 for every other mode). Its point-light
// fit put the near plane at a thousandth of B's distance, leaving float depth
// too coarse near 1 to tell the street from itself.
TEST(ShadowSweepDefects, PSMSpotAheadOfAStreetLevelCameraHasNoAcne)
{
  const auto city = shadowscenes::GetCityLayout();
  const double x = city.StreetCenter(1);
  const double y = city.StreetCenter(0) - 10.0;
  const std::pair<double, double> placements[] = { { 10.0, 8.0 }, { 20.0, 15.0 }, { 40.0, 8.0 } };
  for (const auto& [ahead, height] : placements)
  {
    Case drawn = CityCase({ x, y, 1.7 }, { x, y + 30.0, 4.0 }, 60.0, 0.1, 300.0, 320, 180);
    SetLight(drawn, LightKind::Spot, { x, y + ahead, height }, { x, y + ahead + 10.0, 0.0 }, 45.0);
    const CaseResult result = MeasureOne(drawn, { "uniform", "psm" });
    ASSERT_GT(result.Counted, 300);
    ExpectNoFlags(result);
    EXPECT_LT(Misclassified(result, "uniform"), 0.1);
    EXPECT_LT(Misclassified(result, "psm"), 0.1) << ahead << " ahead, " << height << " up";
  }
}

// Sweep seed 3767396340924350328: a 75 degree spot just over the built-in
// scene's ground, in view of a camera high above it. PSM's post-perspective
// cube put its faces' near plane at a fixed share of their depth range, which
// held most of the world's depth around the light (57.95% false shadows
// against the uniform faces' 0); at a thousandth of the scene's reach in the
// world, float depth left acne around the light (8.09%); at a hundredth, none.
TEST(ShadowSweepDefects, PSMCubeOfALightAmongTheReceiversHasNoAcne)
{
  Case drawn = MakeCase("default", { 52.2208968, 61.6634567, 288.160774 },
    { 41.8619547, 39.7310948, 1.52082453 }, 32.0, 3.9972, 432.063, 163, 109);
  SetLight(drawn, LightKind::Spot, { -35.097907, -10.4518717, 2.67542445 },
    { -31.4570361, 99.5172986, 5.27298618 }, 75.2077);
  const CaseResult result = MeasureOne(drawn, { "uniform", "psm" });
  ASSERT_GT(result.Counted, 300);
  ExpectNoFlags(result);
  EXPECT_LT(Misclassified(result, "uniform"), 0.1);
  EXPECT_LT(Misclassified(result, "psm"), 0.5); // 0.00 after the fix
}

// Sized-light sweep (--lights sized, seed 40) case 8974905881529135808: a
// street-level camera in the city sees a strip of wall by a spot 3.1 in
// radius. The soft shadows' blocker search spread its disc beyond the spot's
// map, found no caster in it and lit the wall (100% misclassified, the hard
// filter 0): taps beyond the maps no longer count, and a disc with none
// inside keeps the hard shadow.
TEST(ShadowSweepDefects, SoftKernelWiderThanTheMapsKeepsTheShadow)
{
  Case drawn = CityCase({ 9.70104981, 74.4174163, 2.3821113 },
    { 90.8211052, 74.4174163, -11.3783483 }, 19.4, 0.0603944, 269.568, 208, 214);
  SetLight(drawn, LightKind::Spot, { -81.0271995, -71.3854717, 13.7687159 },
    { -38.8065383, 94.0083326, 23.4412747 }, 44.8511);
  drawn.Light.Size = 3.07148;
  const CaseResult result = MeasureOne(drawn, { "uniform", "poisson-r2" });
  ASSERT_GT(result.TruthShadowed, 250);
  ExpectNoFlags(result);
  EXPECT_LT(Misclassified(result, "poisson-r2"), 1.0);
  EXPECT_LT(Misclassified(result, "uniform"), 1.0); // 100 before the fix
}

// Sweep seed 11504923083347240446: a parallel camera high over the outdoor
// scene with a camera spot light. The camera's axis crossed the spot's space
// beside B, its near-plane centre and focus point lay before the hull's top,
// and TSM's delta, measured from the top to the focus, was clamped to almost
// nothing: the trapezoid warped B onto a sliver of the map, with no shadow at
// all (33.92% misclassified against the uniform map's 3.65). The focus span is
// now laid off from the top.
TEST(ShadowSweepDefects, TSMOfAParallelCameraKeepsItsShadow)
{
  Case drawn = MakeCase("outdoor", { -91.8934423, -213.582565, 187.322814 },
    { -193.839745, 30.1996377, 11.2924842 }, 30.0, 0.0380267, 645.054, 139, 152);
  drawn.Camera.Parallel = true;
  drawn.Camera.ParallelScale = 28.9;
  SetLight(drawn, LightKind::Spot, { 0.810233793, -0.492660125, 1.03350414 },
    { 0.196506443, 0.128543125, 0.0 }, 59.6994, true);
  const CaseResult result = MeasureOne(drawn, { "uniform", "tsm" });
  ASSERT_GT(result.TruthShadowed, 1000);
  ExpectNoFlags(result);
  const double uniform = Misclassified(result, "uniform");
  EXPECT_LT(Misclassified(result, "tsm"), 2.0 * uniform + 1.0); // 6.66 against 3.65
}

// Sweep seed 16779381718558883358: the camera among the outdoor poles, a hair
// of near plane (0.0078 of a 502 far), the sun below the ground. LiSPSM and GMNPR
// left most of the ground's shadow out (59.49 and 65.41% misclassified against
// the uniform map's 7.20): the slope-scaled offset taken on the warped depth
// pushed the ground behind the poles, and the warp, sized by the camera's near
// plane rather than the nearest visible prop, spent the map on empty air.
TEST(ShadowSweepDefects, LightSpaceWarpsOfANearCameraKeepTheirShadows)
{
  Case drawn = MakeCase("outdoor", { -198.112774, -50.247388, 6.55481869 },
    { -60.3179959, -129.677882, 7.4158134 }, 14.0, 0.00777166, 502.198, 118, 100);
  SetLight(drawn, LightKind::Directional, { -271.975303, -109.5064, -476.03903 }, { 0.0, 0.0, 8.0 });
  const CaseResult result = MeasureOne(drawn, { "uniform", "lispsm", "gmnpr" });
  ASSERT_GT(result.TruthShadowed, 1000);
  ExpectNoFlags(result);
  const double uniform = Misclassified(result, "uniform");
  for (const char* warped : { "lispsm", "gmnpr" })
  {
    EXPECT_LT(Misclassified(result, warped), 1.5 * uniform) << warped; // 6.62 against 7.20
  }
}

// Sweep seed 2026668004959669429: a camera light shining up from below the
// ground at the poles around a low camera. LiSPSM and GMNPR misclassified 20.90
// and 38.90% (uniform 4.63): their far texels are many times the map's mean,
// and the slope-scaled offset across such a texel took the grazing ground
// behind the poles it shadows. The slope-scaled term of directional linear-depth
// views is now capped.
TEST(ShadowSweepDefects, WarpedMapsCapTheirSlopeScaledBias)
{
  Case drawn = MakeCase("outdoor", { 79.3192044, 36.069493, 1.31014905 },
    { 110.129294, -127.392304, 4.48799495 }, 78.9, 0.0650592, 502.138, 152, 80);
  SetLight(drawn, LightKind::Directional, { -0.547604836, -0.554201624, 0.919559925 },
    { -0.0498706733, 0.0744071923, 0.0 }, 180.0, true);
  const CaseResult result = MeasureOne(drawn, { "uniform", "lispsm", "gmnpr" });
  ASSERT_GT(result.TruthShadowed, 1000);
  ExpectNoFlags(result);
  const double uniform = Misclassified(result, "uniform");
  for (const char* warped : { "lispsm", "gmnpr" })
  {
    EXPECT_LT(Misclassified(result, warped), 2.0 * uniform) << warped; // 5.93, 6.00 against 4.63
  }
}

// Sweep seed 17163050172880156331 (seed 3's 500 cases): a camera among the
// field's poles, looking up into a sun near its 96-degree view cone, with a near
// plane 4.3e-5 of its far. The poles are one prop whose bounds hold the camera,
// so the near depth pulled to the nearest visible prop stayed a hair in front of
// it, and n_opt = z_n + sqrt(z_f z_n) gave the map to that empty near field:
// LiSPSM and GMNPR misclassified 7.27 and 8.78% against the focused map's 0.77
// (here, built by hand: 7.62 and 9.46 against 0.44). Their near depth is now no
// nearer than 0.3% of B's far depth (a pseudo near plane): here 2.21 and 2.58.
// A larger fraction does better here but worse on the bench's outdoor scene
// (docs/WARPS.md).
TEST(ShadowSweepDefects, LightSpaceWarpsOfAHairNearPlaneKeepTheirShadows)
{
  Case drawn = MakeCase("field", { -15.9413401, 28.4479018, 1.06936798 },
    { -31.3030218, 3.96756788, 26.1367278 }, 96.2, 0.00455782, 106.427, 278, 134);
  SetLight(drawn, LightKind::Directional, { 2.3685758, -115.809257, 57.2257134 },
    { 0.0, 0.0, 3.88456054 });
  const CaseResult result = MeasureOne(drawn, { "dual", "dual+lispsm", "dual+gmnpr" });
  ASSERT_GT(result.TruthShadowed, 100);
  ExpectNoFlags(result);
  const double focused = Misclassified(result, "dual");
  for (const char* warped : { "dual+lispsm", "dual+gmnpr" })
  {
    EXPECT_LT(Misclassified(result, warped), 8.0 * focused) << warped;
  }
}

// The bench's lamp-behind set-up over the outdoor scene (a bulb 1 unit behind
// the camera and 16 above it, its shadows running away down the view): PSM's
// post-perspective cube misclassified 0.179% against the uniform cube faces'
// 0.102% (bench, 640 x 360). Its faces' texels there are up to 5.3 times longer
// one way than the other, and the normal offset, a texel of the coarser axis,
// moved the receivers' lookups that many of the finer axis's texels across the
// light, over shadow edges: false shadows. The faces now take the texel's mean
// size.
TEST(ShadowSweepDefects, CubeOfALampBehindTheViewerBeatsTheUniformFaces)
{
  Case drawn =
    MakeCase("outdoor", { 0.0, -170.0, 2.0 }, { 0.0, -150.0, 2.0 }, 30.0, 0.2, 300.0, 640, 360);
  SetLight(drawn, LightKind::Point, { 0.0, -171.0, 18.0 }, { 0.0, -171.0, 17.0 });
  const CaseResult result = MeasureOne(drawn, { "uniform", "psm" });
  ASSERT_GT(result.TruthShadowed, 1000);
  ExpectNoFlags(result);
  EXPECT_LE(Misclassified(result, "psm"), Misclassified(result, "uniform"));
}

} // namespace

namespace
{
// --- the fixed-seed sweep -----------------------------------------------------------

// 100 random cases at a small size, every technique of this project: no case
// may have a non-finite view, a GL error, a VTK error or warning or a lost
// shadow, and each technique's 95th percentile and worst case of misclassified
// pixels stay within the bounds below (tighter than the long sweep's rule of 3
// times the uniform map's worst case).
//
// Where the bounds come from: this very sweep (seed 2) measured at commit
// fb9992a, after the fixes above (52 of the 100 cases have the 300 counted
// pixels a distribution needs), 95th percentile / worst in %:
//   uniform 7.20 / 17.46, psm 5.92 / 17.46, lispsm 6.56 / 17.46, tsm 7.32 / 17.46,
//   gmnpr 6.50 / 17.46, csm, csm-tight and csm-lispsm 8.23 / 22.14.
// The worst case of all, for every technique, is the pole field seen from among
// the poles (seed 17456342516546928867), where poles thinner than a pixel decide
// most counted pixels. Each bound is the measured figure with about 25% of room.
// Before the fixes (commit ce51ee5) the same sweep measured LiSPSM 14.89 / 59.49
// and GMNPR 14.89 / 65.41 (a sun below the ground, seed 16779381718558883358),
// over these bounds and over 3 times the uniform map's worst.
struct SweepBound
{
  const char* Technique;
  double Percentile95;
  double Worst;
};
constexpr SweepBound SweepBounds[] = {
  { "uniform", 9.0, 22.0 },
  { "psm", 7.5, 22.0 },
  { "lispsm", 8.5, 22.0 },
  { "tsm", 9.5, 22.0 },
  { "gmnpr", 8.5, 22.0 },
  { "csm", 10.5, 28.0 },
  { "csm-tight", 10.5, 28.0 },
  { "csm-lispsm", 10.5, 28.0 },
};

TEST(ShadowSweep, FixedSeedSweepStaysWithinItsBounds)
{
  shadowsweep::Options options;
  options.Cases = 100;
  options.Seed = 2;
  options.BaseWidth = 160;
  options.BaseHeight = 120;
  // Not CLI.Sweep's folder: ctest may run the two side by side.
  options.OutputDirectory = std::string(SHADOWMAPS_TEST_OUTPUT_DIR) + "/fixed-seed-sweep";
  std::vector<CaseResult> results;
  std::ostringstream report, log;
  std::string error;
  ASSERT_TRUE(shadowsweep::Run(options, report, log, error, &results)) << error;
  std::cout << report.str();
  for (const CaseResult& result : results)
  {
    for (const auto& t : result.Techniques)
    {
      EXPECT_FALSE(t.Flagged()) << shadowsweep::Describe(result.Drawn) << ": " << t.Technique
                                << ": " << t.Flags() << "\n" << t.Messages;
    }
  }
  const auto distributions = shadowsweep::Summarise(results, options.MinimumCounted);
  ASSERT_EQ(distributions.size(), std::size(SweepBounds));
  for (std::size_t i = 0; i < distributions.size(); ++i)
  {
    const auto& d = distributions[i];
    ASSERT_EQ(d.Technique, SweepBounds[i].Technique);
    EXPECT_GT(d.Cases, 40) << d.Technique;
    EXPECT_LE(d.Percentile95, SweepBounds[i].Percentile95) << d.Technique;
    EXPECT_LE(d.Worst, SweepBounds[i].Worst) << d.Technique << ", worst seed " << d.WorstSeed;
  }
}
} // namespace
