// The benchmark's error metrics on small hand-made images.
#include "ShadowMetrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

using shadowmetrics::Truth;

namespace
{
constexpr Truth L = Truth::Lit;
constexpr Truth S = Truth::Shadowed;
constexpr Truth I = Truth::Ignored;
} // namespace

TEST(ShadowMetrics, ClassifySplitsFalseShadowsAndLeaks)
{
  // 4 x 2, bottom row first.
  const std::vector<Truth> truth = { L, L, S, S, L, L, S, I };
  const std::vector<float> factor = { 1.0f, 0.2f, 0.0f, 0.9f, 1.0f, 1.0f, 0.0f, 0.0f };
  const auto c = shadowmetrics::Classify(truth, factor, 4, 2);
  EXPECT_EQ(c.Counted, 7);
  EXPECT_NEAR(c.FalseShadow, 100.0 / 7.0, 1e-9);
  EXPECT_NEAR(c.LightLeak, 100.0 / 7.0, 1e-9);
  EXPECT_NEAR(c.Misclassified, 200.0 / 7.0, 1e-9);
  EXPECT_NEAR(c.MeanAbsoluteDifference, (0.8 + 0.9) / 7.0, 1e-6);
}

TEST(ShadowMetrics, InnerExcludesTruthEdges)
{
  // Row of 5: L L | S S S; the two pixels beside the edge are excluded.
  const std::vector<Truth> truth = { L, L, S, S, S };
  const auto edges = shadowmetrics::TruthEdges(truth, 5, 1);
  EXPECT_EQ(edges, (std::vector<std::uint8_t>{ 0, 1, 1, 0, 0 }));
  // The technique misplaces the edge by one pixel: wrong only at an edge pixel.
  const std::vector<float> factor = { 1.0f, 0.0f, 0.0f, 0.0f, 0.0f };
  const auto c = shadowmetrics::Classify(truth, factor, 5, 1);
  EXPECT_NEAR(c.Misclassified, 20.0, 1e-9);
  EXPECT_EQ(c.Inner, 3);
  EXPECT_EQ(c.InnerMisclassified, 0.0);
}

TEST(ShadowMetrics, IgnoredNeighboursMakeNoEdge)
{
  const std::vector<Truth> truth = { L, I, S };
  EXPECT_EQ(shadowmetrics::TruthEdges(truth, 3, 1), (std::vector<std::uint8_t>{ 0, 0, 0 }));
}

TEST(ShadowMetrics, FactorFromRendersIsTheRatio)
{
  const std::vector<std::uint8_t> shadowed = { 50, 50, 50, 0, 0, 0, 200, 200, 200 };
  const std::vector<std::uint8_t> unshadowed = { 100, 100, 100, 0, 0, 0, 100, 100, 100 };
  const auto factor = shadowmetrics::FactorFromRenders(shadowed, unshadowed, 3);
  EXPECT_FLOAT_EQ(factor[0], 0.5f);
  EXPECT_FLOAT_EQ(factor[1], 1.0f); // black without shadows: no information, lit
  EXPECT_FLOAT_EQ(factor[2], 1.0f); // clamped
}

TEST(ShadowMetrics, TexelFootprintOfAKnownMapping)
{
  // Texel coordinates advancing half a texel per pixel: each texel spans two pixels.
  const int w = 4, h = 3;
  std::vector<glm::dvec2> texel(w * h);
  std::vector<std::uint8_t> valid(w * h, 1);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      texel[y * w + x] = glm::dvec2(0.5 * x, 0.5 * y);
    }
  }
  const auto footprint = shadowmetrics::TexelFootprints(texel, valid, w, h);
  EXPECT_NEAR(footprint[0], 2.0, 1e-12);
  EXPECT_EQ(footprint[w * h - 1], 0.0); // no right/upper neighbour
  EXPECT_NEAR(shadowmetrics::UndersampledFromFootprints(footprint, valid), 100.0 * 6 / 12, 1e-9);
}

TEST(ShadowMetrics, UndersampledFromAnalysisCountsFullRed)
{
  const std::vector<std::uint8_t> rgb = { 255, 10, 0, 254, 0, 0, 255, 150, 0, 255, 0, 0 };
  const std::vector<std::uint8_t> valid = { 1, 1, 1, 0 };
  EXPECT_NEAR(shadowmetrics::UndersampledFromAnalysis(rgb, valid), 200.0 / 3.0, 1e-9);
}

namespace
{
// vtkShadowDensityColor (Shaders/vtkShadowMapsAnalysisFS.glsl), rounded to bytes.
std::array<std::uint8_t, 3> DensityColor(double footprint)
{
  const double octaves = std::log2(footprint);
  const double limit = std::log2(1.5);
  const auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(v * 255.0)); };
  if (octaves <= limit)
  {
    const double t = std::clamp((octaves + 4.0) / (limit + 4.0), 0.0, 1.0);
    return { byte(0.1 + 0.3 * t), byte(0.2 + 0.7 * t), byte(1.0 - 0.8 * t) };
  }
  const double t = std::clamp((octaves - limit) / (6.0 - limit), 0.0, 1.0);
  return { 255, byte(0.6 * (1.0 - t)), 0 };
}
} // namespace

TEST(ShadowMetrics, FootprintsFromAnalysisInvertTheHeatMap)
{
  const std::vector<double> footprints = { 0.1, 0.5, 1.0, 1.4, 2.0, 8.0, 40.0 };
  std::vector<std::uint8_t> rgb;
  for (double footprint : footprints)
  {
    const auto color = DensityColor(footprint);
    rgb.insert(rgb.end(), color.begin(), color.end());
  }
  rgb.insert(rgb.end(), { 0, 0, 0, 255, 100, 0 }); // outside the maps; not valid
  std::vector<std::uint8_t> valid(footprints.size() + 1, 1);
  valid.push_back(0);
  const std::vector<double> decoded = shadowmetrics::FootprintsFromAnalysis(rgb, valid);
  ASSERT_EQ(decoded.size(), footprints.size() + 2);
  for (size_t i = 0; i < footprints.size(); ++i)
  {
    // A byte of green is 1/178 of 4.6 octaves below 1.5 pixels, 1/153 of 5.4 above.
    EXPECT_NEAR(std::log2(decoded[i]), std::log2(footprints[i]), 0.04) << footprints[i];
  }
  EXPECT_TRUE(std::isnan(decoded[footprints.size()]));
  EXPECT_TRUE(std::isnan(decoded[footprints.size() + 1]));
}

TEST(ShadowMetrics, FootprintSpreadIsTheOctavesBetweenTheTenthAndNinetiethPercentiles)
{
  std::vector<double> footprints;
  for (int i = 0; i <= 100; ++i)
  {
    footprints.push_back(std::exp2(i / 10.0)); // 0 to 10 octaves, evenly
  }
  footprints.push_back(std::nan(""));
  EXPECT_NEAR(shadowmetrics::FootprintSpread(footprints), 8.0, 1e-9);
  EXPECT_NEAR(shadowmetrics::FootprintSpread(std::vector<double>(7, 3.0)), 0.0, 1e-12);
  EXPECT_TRUE(std::isnan(shadowmetrics::FootprintSpread({ std::nan("") })));
}

TEST(ShadowMetrics, FlickerCountsChangesTheTruthDoesNotHave)
{
  const std::vector<Truth> before = { L, L, S, S, I };
  const std::vector<Truth> after = { L, S, S, S, L };
  const std::vector<float> factorBefore = { 1.0f, 1.0f, 0.0f, 0.0f, 1.0f };
  const std::vector<float> factorAfter = { 0.0f, 0.0f, 0.0f, 1.0f, 0.0f };
  // Pixel 0 and 3 flicker; pixel 1 follows the truth; pixel 4 is not counted.
  EXPECT_NEAR(shadowmetrics::Flicker(before, factorBefore, after, factorAfter), 50.0, 1e-9);
  EXPECT_NEAR(shadowmetrics::TruthChanges(before, after), 25.0, 1e-9);
  // Pixels 0, 1 and 3 change, whatever the truth did.
  EXPECT_NEAR(shadowmetrics::StateChanges(before, factorBefore, after, factorAfter), 75.0, 1e-9);
}

TEST(ShadowMetrics, ErrorMapColours)
{
  const std::vector<Truth> truth = { S, L, L, S, I };
  const std::vector<float> factor = { 1.0f, 0.0f, 1.0f, 0.0f, 0.0f };
  const auto rgb = shadowmetrics::ErrorMap(truth, factor);
  EXPECT_EQ(rgb[0], 230); // leak: red
  EXPECT_EQ(rgb[2], 0);
  EXPECT_EQ(rgb[5], 230); // false shadow: blue
  EXPECT_EQ(rgb[6], rgb[8]); // agreement: grey
  EXPECT_GT(rgb[6], rgb[9]); // lit lighter than shadowed
  EXPECT_EQ(rgb[12] + rgb[13] + rgb[14], 0);
}

TEST(ShadowMetrics, LeakBehindSeveralCountsOnlyPixelsBehindTwoOccluders)
{
  const std::vector<unsigned char> occluders = { 0, 1, 2, 2, 3, 2 };
  const std::vector<float> factor = { 1.0f, 1.0f, 0.9f, 0.1f, 0.5f, 0.0f };
  // Four pixels behind two or more occluders; two of them lit (0.9 and 0.5).
  EXPECT_NEAR(shadowmetrics::LeakBehindSeveral(occluders, factor), 50.0, 1e-9);
  EXPECT_TRUE(std::isnan(shadowmetrics::LeakBehindSeveral({ 0, 1 }, { 1.0f, 1.0f })));
}

TEST(ShadowMetrics, TruthAtHalfThresholdsTheVisibilityAsTheFactor)
{
  const float none = shadoworacle::NotCounted;
  const std::vector<float> visibility = { 0.0f, 0.49f, 0.5f, 1.0f, none };
  EXPECT_EQ(shadowmetrics::TruthAtHalf(visibility), (std::vector<Truth>{ S, S, L, L, I }));
}

TEST(ShadowMetrics, CompareVisibilityMeasuresErrorsPurityAndSeveralOccluders)
{
  const float none = shadoworacle::NotCounted;
  // 10 x 1: four umbra pixels (two behind two occluders), a penumbra of two,
  // three lit pixels and one not counted.
  const std::vector<float> visibility = { 0.0f, 0.0f, 0.0f, 0.0f, 0.3f, 0.7f, 1.0f, 1.0f, 1.0f,
    none };
  const std::vector<float> factor = { 0.0f, 0.04f, 0.2f, 0.0f, 0.5f, 0.7f, 1.0f, 0.9f, 0.96f,
    0.0f };
  const std::vector<unsigned char> occluders = { 1, 1, 2, 2, 1, 0, 0, 0, 0, 0 };
  const auto v = shadowmetrics::CompareVisibility(visibility, factor, occluders, 10, 1);
  EXPECT_EQ(v.Counted, 9);
  const std::array<double, 9> errors = { 0.0, 0.04, 0.2, 0.0, 0.2, 0.0, 0.0, 0.1, 0.04 };
  double sum = 0.0;
  for (double e : errors)
  {
    sum += e;
  }
  EXPECT_NEAR(v.MeanAbsolute, sum / 9.0, 1e-6);
  EXPECT_NEAR(v.Percentile95, 0.2, 1e-6); // the 9th of 9 by nearest rank
  EXPECT_EQ(v.Umbra, 4);
  EXPECT_NEAR(v.UmbraPure, 75.0, 1e-9);
  // Pixel 3 borders the penumbra: the inner umbra is pixels 0 to 2, one of
  // them (0.2) impure.
  EXPECT_EQ(v.UmbraInner, 3);
  EXPECT_NEAR(v.UmbraInnerPure, 200.0 / 3.0, 1e-9);
  EXPECT_EQ(v.UmbraBehindSeveral, 2);
  EXPECT_NEAR(v.UmbraBehindSeveralPure, 50.0, 1e-9);
  EXPECT_EQ(v.Lit, 3);
  EXPECT_NEAR(v.LitPure, 200.0 / 3.0, 1e-9);
  // At one half: pixel 4 (truth 0.3, factor 0.5) is a leak: lit where the
  // truth is mostly shadowed.
  EXPECT_EQ(v.AtHalf.Counted, 9);
  EXPECT_NEAR(v.AtHalf.LightLeak, 100.0 / 9.0, 1e-9);
  EXPECT_NEAR(v.AtHalf.FalseShadow, 0.0, 1e-9);
  // Nothing counted: NaN, not 0.
  const auto empty = shadowmetrics::CompareVisibility({ none }, { 1.0f }, {}, 1, 1);
  EXPECT_EQ(empty.Counted, 0);
  EXPECT_TRUE(std::isnan(empty.MeanAbsolute));
  EXPECT_TRUE(std::isnan(empty.UmbraPure));
  EXPECT_TRUE(std::isnan(empty.UmbraInnerPure));
  EXPECT_TRUE(std::isnan(empty.LitPure));
}

TEST(ShadowMetrics, IgnoreUnlitInRenderDropsPixelsTheRenderLeavesBlack)
{
  // Three pixels: lit grey, black (its shading faces away), dark but not black.
  const std::vector<std::uint8_t> unshadowed = { 90, 90, 90, 0, 0, 0, 0, 1, 0 };
  std::vector<std::uint8_t> valid = { 1, 1, 1 };
  shadowmetrics::IgnoreUnlitInRender(unshadowed, valid);
  EXPECT_EQ(valid, (std::vector<std::uint8_t>{ 1, 0, 1 }));
  // The factor there reads 1 (lit) whatever the technique drew, which is why.
  const std::vector<std::uint8_t> shadowed = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
  EXPECT_EQ(shadowmetrics::FactorFromRenders(shadowed, unshadowed, 3)[1], 1.0f);
  // A render of another size cannot be matched to the pixels: none is kept.
  std::vector<std::uint8_t> longer = { 1, 1, 1, 1 };
  shadowmetrics::IgnoreUnlitInRender(unshadowed, longer);
  EXPECT_EQ(longer, (std::vector<std::uint8_t>{ 0, 0, 0, 0 }));
}

TEST(ShadowMetrics, VisibilityErrorMapColoursTheSignedError)
{
  const float none = shadoworacle::NotCounted;
  const auto rgb = shadowmetrics::VisibilityErrorMap(
    { 0.0f, 1.0f, 0.2f, 0.8f, none }, { 0.0f, 1.0f, 0.7f, 0.3f, 0.5f });
  // Agreement: grey by the visibility.
  EXPECT_EQ(rgb[0], 60);
  EXPECT_EQ(rgb[0], rgb[1]);
  EXPECT_EQ(rgb[3], 190);
  // Too light by 0.5: full red; too dark by 0.5: full blue.
  EXPECT_EQ(rgb[6], 230);
  EXPECT_EQ(rgb[8], 0);
  EXPECT_EQ(rgb[9], 0);
  EXPECT_EQ(rgb[11], 230);
  // Not counted: black.
  EXPECT_EQ(rgb[12] + rgb[13] + rgb[14], 0);
}

TEST(ShadowMetrics, TruthFrameDarkensWhatTheTruthShadows)
{
  // Three pixels: lit, shadowed, ignored (the background keeps its colour).
  const std::vector<std::uint8_t> plain = { 200, 100, 50, 200, 100, 50, 10, 20, 30 };
  const std::vector<Truth> truth = { L, S, I };
  EXPECT_EQ(shadowmetrics::TruthFrame(plain, truth, {}, {}),
    (std::vector<std::uint8_t>{ 200, 100, 50, 0, 0, 0, 10, 20, 30 }));
  // A sized light's visibility scales every channel alike.
  EXPECT_EQ(shadowmetrics::TruthFrame(plain, truth, { 1.0f, 0.5f, 0.0f }, {}),
    (std::vector<std::uint8_t>{ 200, 100, 50, 100, 50, 25, 10, 20, 30 }));
  // A transmittance tints channel by channel.
  const std::vector<glm::vec3> transmittance = { glm::vec3(1.0f), glm::vec3(0.5f, 1.0f, 0.0f),
    glm::vec3(0.0f) };
  EXPECT_EQ(shadowmetrics::TruthFrame(plain, truth, {}, transmittance),
    (std::vector<std::uint8_t>{ 200, 100, 50, 100, 100, 0, 10, 20, 30 }));
}

TEST(ShadowMetrics, ShownFrameLiftsShadowsByTheAmbientShare)
{
  const std::vector<std::uint8_t> plain = { 200, 100, 0 };
  const std::vector<std::uint8_t> black = { 0, 0, 0 };
  EXPECT_EQ(shadowmetrics::ShownFrame(black, plain), (std::vector<std::uint8_t>{ 40, 20, 0 }));
  EXPECT_EQ(shadowmetrics::ShownFrame(plain, plain), plain);
}

TEST(ShadowMetrics, MeanOfChannelsLeavesOutWhatTheComparisonDoes)
{
  const float n = shadoworacle::NotCounted;
  const std::vector<glm::vec3> transmittance = { glm::vec3(0.3f, 0.6f, 0.9f), glm::vec3(n),
    glm::vec3(1.0f) };
  const auto mean = shadowmetrics::MeanOfChannels(transmittance, { 0, 0, 1 });
  EXPECT_NEAR(mean[0], 0.6f, 1e-6f);
  EXPECT_EQ(mean[1], n);
  EXPECT_EQ(mean[2], n);
}
