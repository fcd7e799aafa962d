// vtkVarianceShadowMapPass: moments of the light depth (VSM, EVSM2, EVSM4, MSM,
// ESM), blurred and mipmapped, with every view layout; the reconstructions
// against their closed forms; contact shadows and light bleeding measured.
#include "ShadowTestUtilities.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkVarianceShadowMapPass.h"
#include "vtkVarianceShadowMapRepresentation.h"
#include "vtkWarpedShadowMapViews.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkShaderProgram.h"
#include "vtkSphereSource.h"
#include "ShadowMapVTKCompat.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <tuple>

using namespace shadowtest;

namespace
{
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(-0.4, 0.3, -1.0));

const char* MomentsName(int moments)
{
  switch (moments)
  {
    case vtkVarianceShadowMapPass::VSM:
      return "VSM";
    case vtkVarianceShadowMapPass::EVSM2:
      return "EVSM2";
    case vtkVarianceShadowMapPass::EVSM4:
      return "EVSM4";
    case vtkVarianceShadowMapPass::MSM:
      return "MSM";
    default:
      return "ESM";
  }
}

const int AllMoments[] = { vtkVarianceShadowMapPass::VSM, vtkVarianceShadowMapPass::EVSM2,
  vtkVarianceShadowMapPass::EVSM4, vtkVarianceShadowMapPass::MSM, vtkVarianceShadowMapPass::ESM };

vtkSmartPointer<vtkVarianceShadowMapPass> MakePass(int moments)
{
  auto pass = vtkSmartPointer<vtkVarianceShadowMapPass>::New();
  pass->SetMoments(moments);
  pass->SetResolution(512);
  return pass;
}

/// Sets the pass's views and the scene's light for a layout name.
void UseLayout(TestScene& scene, vtkVarianceShadowMapPass* pass, const std::string& layout)
{
  if (layout == "Spot")
  {
    scene.SetSpot({ 3.0, -3.0, 9.0 }, 40.0);
    return;
  }
  if (layout == "Point")
  {
    scene.SetPoint({ 3.0, -3.0, 6.0 });
    return;
  }
  scene.SetSun(SunDirection);
  if (layout == "Cascaded")
  {
    pass->SetViews(vtkSmartPointer<vtkCascadedShadowMapViews>::New());
  }
  else if (layout != "Uniform")
  {
    auto warped = vtkSmartPointer<vtkWarpedShadowMapViews>::New();
    warped->SetWarpMode(layout == "PSM" ? vtkWarpedShadowMapViews::PSM
        : layout == "TSM"               ? vtkWarpedShadowMapViews::TSM
        : layout == "GMNPR"             ? vtkWarpedShadowMapViews::GMNPR
                                        : vtkWarpedShadowMapViews::LISPSM);
    pass->SetViews(warped);
  }
}

glm::dvec3 ShadowOfSphere(const std::string& layout)
{
  return layout == "Spot" ? GroundShadowOfSphereCenterFrom({ 3.0, -3.0, 9.0 })
    : layout == "Point"   ? GroundShadowOfSphereCenterFrom({ 3.0, -3.0, 6.0 })
                          : GroundShadowOfSphereCenter(SunDirection);
}
} // namespace

class VarianceMomentsAndViews : public ::testing::TestWithParam<std::tuple<int, std::string>>
{
};

// The standard scene's sphere shadow is dark, and the ground and the casters'
// sunlit faces are lit (the 7 x 7 least luminance: no acne) with no bias at all.
TEST_P(VarianceMomentsAndViews, ShadowsAndLitFaces)
{
  const int moments = std::get<0>(GetParam());
  const std::string layout = std::get<1>(GetParam());
  TestScene scene;
  auto pass = MakePass(moments);
  UseLayout(scene, pass, layout);
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_LT(LuminanceAt(scene.Renderer, image, ShadowOfSphere(layout)), ShadowedBelow);
  EXPECT_GT(DarkestAround(scene.Renderer, image, { -5, -4, 0 }), LitAbove);
  EXPECT_GT(DarkestAround(scene.Renderer, image, { 4, 2, 1.5 }), LitAbove);
  const std::string name = std::string("Variance") + MomentsName(moments) + layout;
  const std::string difference = CompareWithBaseline(image, name);
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(Variance, VarianceMomentsAndViews,
  ::testing::Combine(::testing::ValuesIn(AllMoments),
    ::testing::Values("Uniform", "Cascaded", "LiSPSM", "Spot", "Point")),
  [](const ::testing::TestParamInfo<std::tuple<int, std::string>>& info) {
    return std::string(MomentsName(std::get<0>(info.param))) + std::get<1>(info.param);
  });

// The other warps, whose views store their own depth in other ways (PSM's
// post-perspective depth, TSM's and GMNPR's linear depth): the light depth is
// the same in all of them.
INSTANTIATE_TEST_SUITE_P(VarianceWarps, VarianceMomentsAndViews,
  ::testing::Combine(::testing::Values(vtkVarianceShadowMapPass::EVSM4),
    ::testing::Values("PSM", "TSM", "GMNPR")),
  [](const ::testing::TestParamInfo<std::tuple<int, std::string>>& info) {
    return std::string(MomentsName(std::get<0>(info.param))) + std::get<1>(info.param);
  });

namespace
{
/// The receivers' moment GLSL (Shaders/vtkShadowMapsMomentsFS.glsl and
/// vtkShadowMapsVarianceLookupFS.glsl) as `representation` defines it, with
/// the receiver globals they read, evaluated for `expression` of each case.
std::vector<glm::vec4> EvaluateMoments(vtkVarianceShadowMapRepresentation* representation,
  const std::string& expression, const std::vector<glm::vec4>& cases)
{
  const std::string functions = representation->GetReceiverDefinitions() +
    "uniform float vtkShadowMapResolution;\n"
    "vec2 vtkShadowMapDx = vec2(0.0);\nvec2 vtkShadowMapDy = vec2(0.0);\n"
    "vec2 vtkShadowLightDepthDxDy = vec2(0.0);\n"
    "struct vtkShadowView { float FilterScale; };\nuniform vtkShadowView vtkShadowViews[1];\n" +
    representation->GetReceiverLookupCode();
  return EvaluateGLSL(functions, expression, cases,
    [representation](vtkShaderProgram* program) { representation->SetReceiverUniforms(program, {}); });
}

/// Moments of occluders at depths `a` and `b`, half of the texel each.
glm::vec4 MixedMoments(vtkVarianceShadowMapRepresentation* representation, double a, double b)
{
  double ma[4];
  double mb[4];
  representation->GetMomentsOfDepth(a, ma);
  representation->GetMomentsOfDepth(b, mb);
  return glm::vec4(0.5 * (ma[0] + mb[0]), 0.5 * (ma[1] + mb[1]), 0.5 * (ma[2] + mb[2]),
    0.5 * (ma[3] + mb[3]));
}

/// Chebyshev's bound, the closed form: visibility of depth t for a mean and
/// second moment.
double Chebyshev(double mean, double second, double t, double minimumVariance)
{
  if (t <= mean)
  {
    return 1.0;
  }
  const double variance = std::max(second - mean * mean, minimumVariance);
  return variance / (variance + (t - mean) * (t - mean));
}

} // namespace

// What the casters store, evaluated on the GPU, against the C++ closed forms
// the cleared texels take (GetMomentsOfDepth).
TEST(Variance, StoredMomentsMatchTheirClosedForms)
{
  vtkNew<vtkVarianceShadowMapRepresentation> representation;
  const std::vector<glm::vec4> depths = { glm::vec4(0.0f), glm::vec4(0.25f), glm::vec4(0.5f),
    glm::vec4(0.8f), glm::vec4(1.0f) };
  const std::pair<int, int> settings[] = { { vtkVarianceShadowMapPass::VSM, 32 },
    { vtkVarianceShadowMapPass::EVSM2, 32 }, { vtkVarianceShadowMapPass::EVSM4, 32 },
    { vtkVarianceShadowMapPass::MSM, 32 }, { vtkVarianceShadowMapPass::MSM, 16 },
    { vtkVarianceShadowMapPass::ESM, 32 } };
  for (const auto& setting : settings)
  {
    const int moments = setting.first;
    SCOPED_TRACE(MomentsName(moments) + std::to_string(setting.second));
    representation->SetMoments(moments);
    representation->SetStorage(setting.second);
    representation->SetPositiveExponent(40.0);
    const std::vector<glm::vec4> stored =
      EvaluateMoments(representation, "vtkShadowMomentsOf(c.x)", depths);
    for (size_t i = 0; i < depths.size(); ++i)
    {
      double expected[4];
      representation->GetMomentsOfDepth(depths[i].x, expected);
      for (int k = 0; k < 4; ++k)
      {
        EXPECT_NEAR(stored[i][k], expected[k], 1e-5 * std::max(1.0, std::abs(expected[k])))
          << "depth " << depths[i].x << " moment " << k;
      }
    }
  }
}

// One occluder at depth 0.4: receivers in front of it are lit, receivers
// behind it are in shadow, by every reconstruction (evaluated on the GPU as the
// receivers run it, light-bleeding reduction off).
TEST(Variance, OneOccluderShadowsWhatIsBehindIt)
{
  vtkNew<vtkVarianceShadowMapRepresentation> representation;
  representation->SetLightBleedingReduction(0.0);
  for (int moments : AllMoments)
  {
    SCOPED_TRACE(MomentsName(moments));
    representation->SetMoments(moments);
    double stored[4];
    representation->GetMomentsOfDepth(0.4, stored);
    const glm::vec4 m(stored[0], stored[1], stored[2], stored[3]);
    std::vector<float> visibility;
    for (float t : { 0.3f, 0.4f, 0.45f, 0.8f })
    {
      const auto v = EvaluateMoments(representation,
        "vec4(vtkShadowMomentsVisibility(c, " + std::to_string(t) + ", 1e-6))", { m });
      visibility.push_back(v[0].x);
    }
    EXPECT_NEAR(visibility[0], 1.0f, 1e-4f);
    EXPECT_GT(visibility[1], 0.99f);
    if (moments == vtkVarianceShadowMapPass::ESM)
    {
      // exp(c (2 * 0.4 - 1)) / exp(c (2 t - 1)) = exp(-2 c (t - 0.4)), c the
      // largest exponent of 32-bit storage.
      const double c = representation->GetWarpExponent();
      EXPECT_GT(c, 80.0);
      EXPECT_NEAR(visibility[2], std::exp(-2.0 * c * 0.05), 1e-4);
    }
    else
    {
      EXPECT_LT(visibility[2], 0.02f);
    }
    EXPECT_LT(visibility[3], 1e-4f) << visibility[0] << " " << visibility[1] << " " << visibility[2];
  }
}

// Two occluders, half of the texel at depth 0.2, half at 0.5, and a receiver
// behind both at 0.6, fully in shadow: each reconstruction's known bleeding,
// against its closed form, without the reduction. VSM lets a quarter of the
// light through; EVSM's warps and MSM's four moments bound it much tighter.
TEST(Variance, TwoOccludersBleedAsEachReconstructionIsKnownTo)
{
  vtkNew<vtkVarianceShadowMapRepresentation> representation;
  representation->SetLightBleedingReduction(0.0);
  std::map<int, float> visibility;
  for (int moments : AllMoments)
  {
    representation->SetMoments(moments);
    const glm::vec4 m = MixedMoments(representation, 0.2, 0.5);
    visibility[moments] =
      EvaluateMoments(representation, "vec4(vtkShadowMomentsVisibility(c, 0.6, 1e-6))", { m })[0].x;
  }
  const double vsm = Chebyshev(0.35, 0.5 * (0.04 + 0.25), 0.6, 1e-6);
  EXPECT_NEAR(vsm, 0.0225 / (0.0225 + 0.0625), 1e-12);
  EXPECT_NEAR(visibility[vtkVarianceShadowMapPass::VSM], vsm, 1e-5);
  // EVSM: the same bound on each warp, the smaller of the two for EVSM4.
  const auto warp = [](double c, double d) { return std::exp(c * (2.0 * d - 1.0)); };
  const double p1 = warp(40.0, 0.2);
  const double p2 = warp(40.0, 0.5);
  const double positive =
    Chebyshev(0.5 * (p1 + p2), 0.5 * (p1 * p1 + p2 * p2), warp(40.0, 0.6), 0.0);
  const double n1 = -warp(-5.0, 0.2);
  const double n2 = -warp(-5.0, 0.5);
  const double negative =
    Chebyshev(0.5 * (n1 + n2), 0.5 * (n1 * n1 + n2 * n2), -warp(-5.0, 0.6), 0.0);
  EXPECT_NEAR(visibility[vtkVarianceShadowMapPass::EVSM2], positive, 1e-4);
  EXPECT_NEAR(visibility[vtkVarianceShadowMapPass::EVSM4], std::min(positive, negative), 1e-4);
  EXPECT_LT(visibility[vtkVarianceShadowMapPass::EVSM4], 0.05 * vsm);
  // MSM's bound holds for every distribution with the first two moments too.
  EXPECT_LE(visibility[vtkVarianceShadowMapPass::MSM], visibility[vtkVarianceShadowMapPass::VSM]);
  EXPECT_LT(visibility[vtkVarianceShadowMapPass::MSM], 0.05);
  // The reduction cuts VSM's leak to (p - 0.2) / 0.8.
  representation->SetMoments(vtkVarianceShadowMapPass::VSM);
  representation->SetLightBleedingReduction(0.2);
  const float reduced = EvaluateMoments(representation,
    "vec4(vtkShadowMomentsVisibility(c, 0.6, 1e-6))", { MixedMoments(representation, 0.2, 0.5) })[0]
                          .x;
  EXPECT_NEAR(reduced, (vsm - 0.2) / 0.8, 1e-5);
}

namespace
{
/// `moments` rounded to 16-bit normalized integers, as GL_RGBA16 stores them.
glm::vec4 RoundedTo16Bits(const glm::vec4& moments)
{
  glm::vec4 rounded;
  for (int k = 0; k < 4; ++k)
  {
    rounded[k] = static_cast<float>(std::round(moments[k] * 65535.0) / 65535.0);
  }
  return rounded;
}
} // namespace

// MSM in 16 bits: the Chebyshev basis keeps the reconstruction of 32-bit
// moments. Over texels that mix two occluders at random depths and receivers
// at several depths, the 16-bit maps' visibility (moments rounded to 16-bit
// normalized integers) stays within a few thousandths of the 32-bit maps' on
// average, several times closer than the four powers of depth rounded to 16
// bits would be (which is why the basis is there).
TEST(Variance, SixteenBitMSMRoundsLittle)
{
  vtkNew<vtkVarianceShadowMapRepresentation> chebyshev;
  chebyshev->SetMomentsToMSM();
  chebyshev->SetStorageToHalfFloat();
  vtkNew<vtkVarianceShadowMapRepresentation> powers;
  powers->SetMomentsToMSM();
  powers->SetStorageToFloat();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> depth(0.05, 0.95);
  std::uniform_real_distribution<double> weight(0.1, 0.9);
  std::vector<glm::vec4> exact;
  std::vector<glm::vec4> stored;
  std::vector<glm::vec4> roundedPowers;
  for (int i = 0; i < 150; ++i)
  {
    const double a = depth(random);
    const double b = depth(random);
    const double w = weight(random);
    const auto mix = [a, b, w](vtkVarianceShadowMapRepresentation* representation) {
      double ma[4];
      double mb[4];
      representation->GetMomentsOfDepth(a, ma);
      representation->GetMomentsOfDepth(b, mb);
      return glm::vec4(w * ma[0] + (1 - w) * mb[0], w * ma[1] + (1 - w) * mb[1],
        w * ma[2] + (1 - w) * mb[2], w * ma[3] + (1 - w) * mb[3]);
    };
    exact.push_back(mix(powers));
    stored.push_back(RoundedTo16Bits(mix(chebyshev)));
    roundedPowers.push_back(RoundedTo16Bits(exact.back()));
  }
  double chebyshevError = 0.0;
  double powersError = 0.0;
  int count = 0;
  for (const char* t : { "0.3", "0.5", "0.7", "0.9" })
  {
    const std::string visibility = std::string("vec4(vtkShadowMomentsVisibility(c, ") + t + ", 1e-6))";
    const auto reference = EvaluateMoments(powers, visibility, exact);
    const auto sixteen = EvaluateMoments(chebyshev, visibility, stored);
    const auto naive = EvaluateMoments(powers, visibility, roundedPowers);
    for (size_t i = 0; i < exact.size(); ++i)
    {
      ASSERT_GE(reference[i].x, 0.0f) << "the shader compiles";
      chebyshevError += std::abs(sixteen[i].x - reference[i].x);
      powersError += std::abs(naive[i].x - reference[i].x);
      ++count;
    }
  }
  chebyshevError /= count;
  powersError /= count;
  std::cout << "Mean |visibility - 32-bit visibility| over " << count
            << " texels: Chebyshev basis in 16 bits " << chebyshevError << ", powers in 16 bits "
            << powersError << "\n";
  EXPECT_LT(chebyshevError, 0.005);
  EXPECT_LT(chebyshevError * 4.0, powersError);
}

// Each stored Chebyshev coordinate spans all of [0, 1] over the depths (what
// spreads the rounding evenly), and depth 1 (the cleared texel) stores 1s.
TEST(Variance, ChebyshevMomentsSpanTheUnitInterval)
{
  vtkNew<vtkVarianceShadowMapRepresentation> representation;
  representation->SetMomentsToMSM();
  representation->SetStorageToHalfFloat();
  double least[4] = { 1, 1, 1, 1 };
  double most[4] = { 0, 0, 0, 0 };
  for (int i = 0; i <= 1000; ++i)
  {
    double moments[4];
    representation->GetMomentsOfDepth(i / 1000.0, moments);
    for (int k = 0; k < 4; ++k)
    {
      least[k] = std::min(least[k], moments[k]);
      most[k] = std::max(most[k], moments[k]);
    }
  }
  for (int k = 0; k < 4; ++k)
  {
    EXPECT_NEAR(least[k], 0.0, 1e-4) << "coordinate " << k;
    EXPECT_NEAR(most[k], 1.0, 1e-4) << "coordinate " << k;
  }
  double far[4];
  representation->GetMomentsOfDepth(1.0, far);
  EXPECT_EQ(glm::dvec4(far[0], far[1], far[2], far[3]), glm::dvec4(1.0));
}

// A receiver between the two occluders (at 0.35) sees half of them in front:
// MSM's reconstruction, which places three support points, gets close to the
// half; Chebyshev's bound on two moments says at most 0.9 of the light.
TEST(Variance, ReceiverBetweenOccluders)
{
  vtkNew<vtkVarianceShadowMapRepresentation> representation;
  representation->SetLightBleedingReduction(0.0);
  representation->SetMomentsToMSM();
  const float msm = EvaluateMoments(representation, "vec4(vtkShadowMomentsVisibility(c, 0.35, 1e-6))",
    { MixedMoments(representation, 0.2, 0.5) })[0]
                      .x;
  EXPECT_GT(msm, 0.4f);
  EXPECT_LT(msm, 0.75f);
  representation->SetMomentsToVSM();
  const float vsm = EvaluateMoments(representation, "vec4(vtkShadowMomentsVisibility(c, 0.35, 1e-6))",
    { MixedMoments(representation, 0.2, 0.5) })[0]
                      .x;
  EXPECT_NEAR(vsm, 1.0f, 1e-5f); // the mean, 0.35: Chebyshev says nothing
}

class VarianceMoments : public ::testing::TestWithParam<int>
{
};

// Contact shadows: next to where a box stands and a sphere touches the
// ground, on their shadow side, the ground stays dark (no bias pushes the
// shadow away from its caster).
TEST_P(VarianceMoments, ContactShadowsStayDark)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(-4.0, 2.0, 1.0);
  ball->SetRadius(1.0);
  ball->SetThetaResolution(48);
  ball->SetPhiResolution(48);
  AddSourceActor(scene.Renderer, ball);
  auto pass = MakePass(GetParam());
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  // The box spans x from 3.25; the sun travels toward -x, +y.
  EXPECT_LT(LuminanceAt(scene.Renderer, image, { 3.15, 2.0, 0.0 }), ShadowedBelow);
  // 0.1 from where the sphere touches the ground, away from the sun.
  const glm::dvec3 away = glm::normalize(glm::dvec3(SunDirection.x, SunDirection.y, 0.0));
  EXPECT_LT(LuminanceAt(scene.Renderer, image, glm::dvec3(-4.0, 2.0, 0.0) + 0.1 * away), ShadowedBelow);
  // And lit on the sun's side of both.
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { 5.0, 2.0, 0.0 }), LitAbove);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, glm::dvec3(-4.0, 2.0, 0.0) - 1.3 * away), LitAbove);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(Variance, VarianceMoments, ::testing::ValuesIn(AllMoments),
  [](const ::testing::TestParamInfo<int>& info) { return MomentsName(info.param); });

namespace
{
/// The most light that reaches the ground across the edge of the high small
/// plate's shadow, which lies inside the low large plate's: every point there
/// is in shadow, but the blurred texels mix the two plates' depths.
double BleedingAtTheLowPlatesShadow(int moments, double reduction, vtkImageData** frame = nullptr)
{
  TestScene scene;
  scene.Sphere->SetVisibility(false);
  scene.Box->SetVisibility(false);
  const glm::dvec3 down = glm::normalize(glm::dvec3(-0.2, 0.1, -1.0));
  scene.SetSun(down);
  AddBox(scene.Renderer, { 0.0, 0.0, 3.0 }, { 2.0, 2.0, 0.05 });
  AddBox(scene.Renderer, { 0.0, 0.0, 1.0 }, { 7.0, 7.0, 0.05 });
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(0.0, -9.0, 0.8);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  scene.Renderer->ResetCameraClippingRange();
  auto pass = MakePass(moments);
  pass->SetResolution(256);
  pass->SetLightBleedingReduction(reduction);
  pass->SetBlurRadius(6.0);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  // The high plate's shadow: its centre moved along the light to the ground,
  // one unit each side; swept across its two edges along x.
  const glm::dvec3 centre = glm::dvec3(0.0, 0.0, 3.0) + (3.0 / -down.z) * down;
  double most = 0.0;
  for (double across = 0.5; across <= 1.5; across += 0.05)
  {
    for (double side : { -1.0, 1.0 })
    {
      most = std::max(most,
        LuminanceAt(scene.Renderer, image, { centre.x + side * across, centre.y, 0.0 }));
    }
  }
  if (frame)
  {
    *frame = image;
    image->Register(nullptr);
  }
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
  return most;
}
} // namespace

// Light bleeding, measured: where the blurred texels mix two occluders'
// depths and the receiver is behind both, VSM lets light through; EVSM4's warps
// and MSM's four moments leak less, and the reduction cuts VSM's leak.
TEST(Variance, StackedOccludersBleedLessWithEVSM4AndMSM)
{
  vtkImageData* frame = nullptr;
  const double vsm = BleedingAtTheLowPlatesShadow(vtkVarianceShadowMapPass::VSM, 0.0, &frame);
  const std::string difference = CompareWithBaseline(frame, "VarianceStackedVSM");
  frame->Delete();
  EXPECT_TRUE(difference.empty()) << difference;
  const double evsm4 = BleedingAtTheLowPlatesShadow(vtkVarianceShadowMapPass::EVSM4, 0.0);
  const double msm = BleedingAtTheLowPlatesShadow(vtkVarianceShadowMapPass::MSM, 0.0);
  const double reduced = BleedingAtTheLowPlatesShadow(vtkVarianceShadowMapPass::VSM, 0.5);
  std::cout << "most luminance in the stacked shadows: VSM " << vsm << ", EVSM4 " << evsm4
            << ", MSM " << msm << ", VSM with reduction 0.5 " << reduced << "\n";
  EXPECT_GT(vsm, ShadowedBelow) << "VSM's bleeding shows";
  EXPECT_LT(evsm4, vsm - 20.0);
  EXPECT_LT(msm, vsm - 20.0);
  EXPECT_LT(reduced, vsm - 20.0);
}

// Parameters clamp; exponents that the storage cannot hold are reduced with a
// warning.
TEST(Variance, ParametersClamp)
{
  vtkNew<vtkVarianceShadowMapPass> pass;
  EXPECT_EQ(pass->GetMoments(), vtkVarianceShadowMapPass::EVSM4);
  EXPECT_EQ(pass->GetNormalOffset(), 0.0);
  pass->SetMoments(17);
  EXPECT_EQ(pass->GetMoments(), vtkVarianceShadowMapPass::ESM);
  pass->SetMoments(-3);
  EXPECT_EQ(pass->GetMoments(), vtkVarianceShadowMapPass::VSM);
  pass->SetBlurRadius(100.0);
  EXPECT_EQ(pass->GetBlurRadius(), 16.0);
  pass->SetLightBleedingReduction(1.0);
  EXPECT_EQ(pass->GetLightBleedingReduction(), 0.95);
  pass->SetAnisotropy(0.0);
  EXPECT_EQ(pass->GetAnisotropy(), 1.0);
  pass->SetPositiveExponent(std::nan(""));
  EXPECT_EQ(pass->GetPositiveExponent(), 40.0);

  pass->SetMomentsToEVSM4();
  ErrorCounter errors;
  pass->SetStorageToHalfFloat();
  EXPECT_EQ(errors.Warnings(), 1) << errors.Text();
  const double halfLimit = pass->GetVarianceRepresentation()->GetMaximumExponent();
  EXPECT_GT(halfLimit, 5.0);
  EXPECT_LT(halfLimit, 5.54);
  EXPECT_EQ(pass->GetPositiveExponent(), halfLimit);
  EXPECT_EQ(pass->GetNegativeExponent(), 5.0);
  pass->SetStorageToFloat();
  pass->SetPositiveExponent(1000.0);
  EXPECT_EQ(errors.Warnings(), 2) << errors.Text();
  EXPECT_GT(pass->GetPositiveExponent(), 41.0);
  EXPECT_LT(pass->GetPositiveExponent(), 44.4);
  pass->SetMomentsToESM();
  pass->SetPositiveExponent(1000.0);
  EXPECT_GT(pass->GetPositiveExponent(), 80.0);
  EXPECT_LT(pass->GetPositiveExponent(), 88.7);

  // MSM in 16 bits: four normalized 16-bit integers per texel and the
  // shared depth buffer; it warps no depth, so its storage clamps no exponent
  // (until moments that warp are chosen).
  TestScene scene;
  scene.SetSun(SunDirection);
  pass->SetMomentsToMSM();
  pass->SetStorageToHalfFloat();
  EXPECT_EQ(errors.Warnings(), 3) << errors.Text();
  EXPECT_GT(pass->GetPositiveExponent(), 80.0);
  pass->SetResolution(256);
  pass->SetMipmaps(false);
  scene.Renderer->SetPass(pass);
  RenderAndCapture(scene.Window);
  EXPECT_EQ(pass->GetShadowMapMemory(), 256u * 256u * 8u + 256u * 256u * 4u);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
  pass->SetMomentsToEVSM4();
  EXPECT_EQ(errors.Warnings(), 4) << errors.Text();
  EXPECT_EQ(pass->GetPositiveExponent(), halfLimit);
}

// Every setting of the moments a user can drag (ParaView's Moments Blur Radius
// slider among them), 20 steps: no shader built, memory flat, and each
// setting's last frame the one a fresh pass with its value draws, the shadow
// still dark.
TEST(Variance, DraggingASettingBuildsNoShader)
{
  using Setter = std::function<void(vtkVarianceShadowMapPass*, double)>;
  const std::tuple<std::string, int, double, double, Setter> sliders[] = {
    { "BlurRadius", vtkVarianceShadowMapPass::EVSM4, 1.0, 6.0,
      [](vtkVarianceShadowMapPass* pass, double v) { pass->SetBlurRadius(v); } },
    { "Anisotropy", vtkVarianceShadowMapPass::EVSM4, 8.0, 2.0,
      [](vtkVarianceShadowMapPass* pass, double v) { pass->SetAnisotropy(v); } },
    { "PositiveExponent", vtkVarianceShadowMapPass::EVSM4, 40.0, 10.0,
      [](vtkVarianceShadowMapPass* pass, double v) { pass->SetPositiveExponent(v); } },
    { "NegativeExponent", vtkVarianceShadowMapPass::EVSM4, 5.0, 15.0,
      [](vtkVarianceShadowMapPass* pass, double v) { pass->SetNegativeExponent(v); } },
    { "LightBleedingReduction", vtkVarianceShadowMapPass::VSM, 0.0, 0.6,
      [](vtkVarianceShadowMapPass* pass, double v) { pass->SetLightBleedingReduction(v); } },
    { "MinimumVariance", vtkVarianceShadowMapPass::VSM, 1e-6, 1e-3,
      [](vtkVarianceShadowMapPass* pass, double v) { pass->SetMinimumVariance(v); } },
    { "MomentBias", vtkVarianceShadowMapPass::MSM, 3e-5, 3e-3,
      [](vtkVarianceShadowMapPass* pass, double v) { pass->SetMomentBias(v); } },
  };
  for (const auto& [name, moments, from, to, set] : sliders)
  {
    TestScene scene;
    scene.SetSun(SunDirection);
    auto pass = MakePass(moments);
    pass->SetResolution(512);
    scene.Renderer->SetPass(pass);
    scene.Window->Render();
    scene.Window->Render();
    const int builds = pass->GetNumberOfShaderBuilds();
    const int updates = pass->GetNumberOfShadowMapUpdates();
    const double before = ResidentMiB();
    for (int step = 1; step <= 20; ++step)
    {
      set(pass, from + (to - from) * step / 20.0);
      scene.Window->Render();
    }
    const double grown = ResidentMiB() - before;
    EXPECT_EQ(pass->GetNumberOfShaderBuilds(), builds) << name << ": shaders built while dragged";
    EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates + 20) << name;
    // Before: 80 shaders and 59 to 90 MiB for 20 steps of the blur radius.
    EXPECT_LT(grown, 4.0) << name << ": MiB grown over 20 steps";
    const auto image = CaptureAsRendered(scene.Window);
    auto fresh = MakePass(moments);
    fresh->SetResolution(512);
    set(fresh, to);
    EXPECT_TRUE(RgbBytes(image) == FreshPassFrame(scene, fresh))
      << name << ": the dragged pass draws another frame than a fresh one";
    EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)),
      ShadowedBelow)
      << name;
  }
}

// Storage: two or four values of 16 or 32 bits, a third more for mipmaps.
TEST(Variance, MemoryFollowsTheStorage)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  auto pass = MakePass(vtkVarianceShadowMapPass::VSM);
  pass->SetResolution(256);
  scene.Renderer->SetPass(pass);
  const size_t texels = 256 * 256;
  struct Case
  {
    int Moments;
    int Bits;
    size_t BytesPerTexel;
  };
  for (const Case& c : { Case{ vtkVarianceShadowMapPass::VSM, 32, 8 },
         Case{ vtkVarianceShadowMapPass::VSM, 16, 4 }, Case{ vtkVarianceShadowMapPass::EVSM4, 32, 16 },
         Case{ vtkVarianceShadowMapPass::EVSM4, 16, 8 } })
  {
    pass->SetMoments(c.Moments);
    pass->SetStorage(c.Bits);
    pass->SetPositiveExponent(5.0);
    RenderAndCapture(scene.Window);
    const size_t values = texels * c.BytesPerTexel;
    EXPECT_EQ(pass->GetShadowMapMemory(), values + values / 3 + texels * 4)
      << MomentsName(c.Moments) << " " << c.Bits;
  }
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

namespace
{
/// Pixels between shadow and light along a line across the sphere's shadow,
/// with EVSM4 maps of 256^2 set up by `configure`; the shadow's centre must be
/// dark. `frame` (optional) gets the image.
int PenumbraSamples(const std::function<void(vtkVarianceShadowMapPass*)>& configure,
  vtkSmartPointer<vtkImageData>* frame = nullptr, size_t* memory = nullptr)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  auto pass = MakePass(vtkVarianceShadowMapPass::EVSM4);
  pass->SetResolution(256);
  configure(pass);
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  const glm::dvec3 centre = GroundShadowOfSphereCenter(SunDirection);
  int between = 0;
  for (double x = -2.0; x <= 2.0; x += 0.02)
  {
    const double luminance = LuminanceAt(scene.Renderer, image, centre + glm::dvec3(x, 0.0, 0.0));
    between += luminance > 50.0 && luminance < 200.0 ? 1 : 0;
  }
  EXPECT_LT(LuminanceAt(scene.Renderer, image, centre), ShadowedBelow);
  if (frame)
  {
    *frame = image;
  }
  if (memory)
  {
    *memory = pass->GetShadowMapMemory();
  }
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
  return between;
}
} // namespace

// The blur widens the penumbra: more pixels between shadow and light across
// the sphere's shadow edge, the same dark core.
TEST(Variance, BlurWidensThePenumbra)
{
  const int sharp = PenumbraSamples([](vtkVarianceShadowMapPass* pass) { pass->SetBlurRadius(0.0); });
  const int soft = PenumbraSamples([](vtkVarianceShadowMapPass* pass) { pass->SetBlurRadius(4.0); });
  std::cout << "penumbra samples: blur 0 " << sharp << ", blur 4 " << soft << "\n";
  EXPECT_GT(soft, 2 * sharp);
}

// Multisampled casters: each texel holds the moments of its samples, so
// without any blur the shadow's edge takes intermediate values where one
// sample per texel leaves a hard step. The samples' buffers count in the
// maps' memory.
TEST(Variance, MultisampledCastersSmoothTheEdges)
{
  {
    TestScene probe;
    probe.Window->Render();
    GLint most = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &most);
    if (most < 4)
    {
      GTEST_SKIP() << "GL offers " << most << " samples per texel, the test needs 4";
    }
  }
  size_t single = 0;
  size_t multi = 0;
  const auto configure = [](int samples) {
    return [samples](vtkVarianceShadowMapPass* pass) {
      pass->SetBlurRadius(0.0);
      pass->SetMipmaps(false);
      pass->SetResolution(128);
      pass->SetCasterSamples(samples);
    };
  };
  const int hard = PenumbraSamples(configure(1), nullptr, &single);
  vtkSmartPointer<vtkImageData> frame;
  const int smooth = PenumbraSamples(configure(4), &frame, &multi);
  std::cout << "penumbra samples: 1 sample " << hard << ", 4 samples " << smooth << "\n";
  EXPECT_GT(smooth, hard + 2);
  // Four samples of four floats and a 32-bit depth per texel.
  EXPECT_EQ(multi - single, 128u * 128u * 4u * (16u + 4u));
  const std::string difference = CompareWithBaseline(frame, "VarianceEVSM4Multisampled");
  EXPECT_TRUE(difference.empty()) << difference;
}

// The SHADOW_MAP analysis view shows the light depth of exponentially warped
// maps, not their exp(c d): the casters as shades of grey between the near
// black and the far white, for EVSM4 as for VSM.
TEST(Variance, ShadowMapViewShowsDepth)
{
  for (int moments : { vtkVarianceShadowMapPass::VSM, vtkVarianceShadowMapPass::EVSM4 })
  {
    SCOPED_TRACE(MomentsName(moments));
    TestScene scene;
    scene.SetSun(SunDirection);
    auto pass = MakePass(moments);
    pass->SetAnalysisView(vtkAbstractShadowMapPass::SHADOW_MAP);
    scene.Renderer->SetPass(pass);
    auto image = RenderAndCapture(scene.Window);
    int dims[3];
    image->GetDimensions(dims);
    int grey = 0;
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x)
      {
        const auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
        grey += rgb[0] > 20 && rgb[0] < 235 ? 1 : 0;
      }
    }
    EXPECT_GT(grey, dims[0] * dims[1] / 4) << "the ground and the casters in grey";
    scene.Renderer->SetPass(nullptr);
    pass->ReleaseGraphicsResources(scene.Window);
  }
}

class VarianceSixteenBits : public ::testing::TestWithParam<std::tuple<int, std::string>>
{
};

// 16-bit storage (EVSM4 in half floats with the exponents they hold, MSM in
// normalized integers in the Chebyshev basis) keeps the standard scene's
// shadow dark and its lit faces free of acne, for a sun and, for MSM, the
// positional lights, whose light depths near 0 its reconstruction must keep.
TEST_P(VarianceSixteenBits, ShadowsAndLitFaces)
{
  const int moments = std::get<0>(GetParam());
  const std::string layout = std::get<1>(GetParam());
  TestScene scene;
  auto pass = MakePass(moments);
  UseLayout(scene, pass, layout);
  pass->SetPositiveExponent(5.0);
  pass->SetNegativeExponent(5.0);
  pass->SetStorageToHalfFloat();
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_LT(LuminanceAt(scene.Renderer, image, ShadowOfSphere(layout)), ShadowedBelow);
  EXPECT_GT(DarkestAround(scene.Renderer, image, { -5, -4, 0 }), LitAbove);
  EXPECT_GT(DarkestAround(scene.Renderer, image, { 4, 2, 1.5 }), LitAbove);
  if (layout == "Uniform")
  {
    EXPECT_GT(DarkestAround(scene.Renderer, image, glm::dvec3(0, 0, 1.5) - SunDirection), LitAbove);
    // Four 16-bit values per texel, a third more for mipmaps, the shared depth.
    const size_t values = 512u * 512u * 8u;
    EXPECT_EQ(pass->GetShadowMapMemory(), values + values / 3 + 512u * 512u * 4u);
  }
  const std::string baseline = moments == vtkVarianceShadowMapPass::MSM
    ? "VarianceMSMSixteenBits" + std::string(layout == "Uniform" ? "" : layout)
    : "VarianceEVSM4HalfFloat";
  const std::string difference = CompareWithBaseline(image, baseline);
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(Variance, VarianceSixteenBits,
  ::testing::Values(std::make_tuple(int(vtkVarianceShadowMapPass::EVSM4), std::string("Uniform")),
    std::make_tuple(int(vtkVarianceShadowMapPass::MSM), std::string("Uniform")),
    std::make_tuple(int(vtkVarianceShadowMapPass::MSM), std::string("Spot")),
    std::make_tuple(int(vtkVarianceShadowMapPass::MSM), std::string("Point"))),
  [](const ::testing::TestParamInfo<std::tuple<int, std::string>>& info) {
    return std::string(MomentsName(std::get<0>(info.param))) + std::get<1>(info.param);
  });
