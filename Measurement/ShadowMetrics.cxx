#include "ShadowMetrics.h"

#include <glm/glm.hpp>

#include <limits>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace shadowmetrics
{
namespace
{
bool Counted(Truth truth)
{
  return truth != Truth::Ignored;
}

bool IsShadowed(float factor)
{
  return factor < ShadowedBelow;
}

double Percent(std::int64_t part, std::int64_t whole)
{
  return whole > 0 ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

// Each counted visibility as Shadowed where `shadowed(visibility)`, else Lit.
template <typename Predicate>
std::vector<Truth> TruthWhere(const std::vector<float>& visibility, Predicate shadowed)
{
  std::vector<Truth> truth(visibility.size(), Truth::Ignored);
  for (std::size_t i = 0; i < visibility.size(); ++i)
  {
    if (visibility[i] != shadoworacle::NotCounted)
    {
      truth[i] = shadowed(visibility[i]) ? Truth::Shadowed : Truth::Lit;
    }
  }
  return truth;
}
} // namespace

//------------------------------------------------------------------------------
std::vector<std::uint8_t> TruthEdges(const std::vector<Truth>& truth, int width, int height)
{
  std::vector<std::uint8_t> edges(truth.size(), 0);
  const int dx[4] = { 1, -1, 0, 0 };
  const int dy[4] = { 0, 0, 1, -1 };
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const Truth here = truth[y * width + x];
      if (!Counted(here))
      {
        continue;
      }
      for (int k = 0; k < 4; ++k)
      {
        const int nx = x + dx[k];
        const int ny = y + dy[k];
        if (nx < 0 || ny < 0 || nx >= width || ny >= height)
        {
          continue;
        }
        const Truth there = truth[ny * width + nx];
        if (Counted(there) && there != here)
        {
          edges[y * width + x] = 1;
          break;
        }
      }
    }
  }
  return edges;
}

//------------------------------------------------------------------------------
double LeakBehindSeveral(const std::vector<unsigned char>& occluders, const std::vector<float>& factor)
{
  std::int64_t behind = 0;
  std::int64_t lit = 0;
  for (std::size_t i = 0; i < occluders.size() && i < factor.size(); ++i)
  {
    if (occluders[i] >= 2)
    {
      ++behind;
      lit += factor[i] >= ShadowedBelow ? 1 : 0;
    }
  }
  return behind > 0 ? Percent(lit, behind) : std::numeric_limits<double>::quiet_NaN();
}

//------------------------------------------------------------------------------
Classification Classify(
  const std::vector<Truth>& truth, const std::vector<float>& factor, int width, int height)
{
  Classification result;
  const std::vector<std::uint8_t> edges = TruthEdges(truth, width, height);
  std::int64_t falseShadow = 0;
  std::int64_t leak = 0;
  std::int64_t innerWrong = 0;
  double absoluteDifference = 0.0;
  for (size_t i = 0; i < truth.size(); ++i)
  {
    if (!Counted(truth[i]))
    {
      continue;
    }
    ++result.Counted;
    const bool truthShadowed = truth[i] == Truth::Shadowed;
    const bool techniqueShadowed = IsShadowed(factor[i]);
    falseShadow += !truthShadowed && techniqueShadowed;
    leak += truthShadowed && !techniqueShadowed;
    absoluteDifference += std::abs(factor[i] - (truthShadowed ? 0.0 : 1.0));
    if (!edges[i])
    {
      ++result.Inner;
      innerWrong += truthShadowed != techniqueShadowed;
    }
  }
  result.FalseShadow = Percent(falseShadow, result.Counted);
  result.LightLeak = Percent(leak, result.Counted);
  result.Misclassified = Percent(falseShadow + leak, result.Counted);
  result.InnerMisclassified = Percent(innerWrong, result.Inner);
  result.MeanAbsoluteDifference =
    result.Counted > 0 ? absoluteDifference / static_cast<double>(result.Counted) : 0.0;
  return result;
}

//------------------------------------------------------------------------------
std::vector<Truth> TruthAtHalf(const std::vector<float>& visibility)
{
  return TruthWhere(visibility, IsShadowed);
}

//------------------------------------------------------------------------------
void IgnoreUnlitInRender(
  const std::vector<std::uint8_t>& unshadowedRgb, std::vector<std::uint8_t>& valid)
{
  if (unshadowedRgb.size() != 3 * valid.size())
  {
    std::cerr << "shadowmetrics: IgnoreUnlitInRender: a render of " << unshadowedRgb.size()
              << " bytes for " << valid.size() << " pixels: every pixel dropped\n";
    std::fill(valid.begin(), valid.end(), 0);
    return;
  }
  for (std::size_t i = 0; i < valid.size(); ++i)
  {
    if (unshadowedRgb[3 * i] + unshadowedRgb[3 * i + 1] + unshadowedRgb[3 * i + 2] == 0)
    {
      valid[i] = 0;
    }
  }
}

//------------------------------------------------------------------------------
VisibilityErrors CompareVisibility(const std::vector<float>& visibility,
  const std::vector<float>& factor, const std::vector<unsigned char>& occluders, int width,
  int height)
{
  VisibilityErrors result;
  if (factor.size() != visibility.size())
  {
    result.MeanAbsolute = result.Percentile95 = result.UmbraPure = result.UmbraInnerPure =
      result.LitPure = result.UmbraBehindSeveralPure = std::numeric_limits<double>::quiet_NaN();
    return result;
  }
  result.AtHalf = Classify(TruthAtHalf(visibility), factor, width, height);
  // The umbra against every other counted pixel.
  const std::vector<std::uint8_t> umbraEdges =
    TruthEdges(TruthWhere(visibility, [](float v) { return v == 0.0f; }), width, height);
  std::vector<double> errors;
  std::int64_t umbraPure = 0;
  std::int64_t innerPure = 0;
  std::int64_t litPure = 0;
  std::int64_t severalPure = 0;
  for (std::size_t i = 0; i < visibility.size(); ++i)
  {
    if (visibility[i] == shadoworacle::NotCounted)
    {
      continue;
    }
    errors.push_back(std::abs(static_cast<double>(factor[i]) - visibility[i]));
    if (visibility[i] == 0.0f)
    {
      const bool pure = factor[i] <= PureWithin;
      ++result.Umbra;
      umbraPure += pure;
      if (!umbraEdges[i])
      {
        ++result.UmbraInner;
        innerPure += pure;
      }
      if (i < occluders.size() && occluders[i] >= 2)
      {
        ++result.UmbraBehindSeveral;
        severalPure += pure;
      }
    }
    else if (visibility[i] == 1.0f)
    {
      ++result.Lit;
      litPure += factor[i] >= 1.0f - PureWithin;
    }
  }
  const double none = std::numeric_limits<double>::quiet_NaN();
  result.Counted = static_cast<std::int64_t>(errors.size());
  result.UmbraPure = result.Umbra > 0 ? Percent(umbraPure, result.Umbra) : none;
  result.UmbraInnerPure = result.UmbraInner > 0 ? Percent(innerPure, result.UmbraInner) : none;
  result.LitPure = result.Lit > 0 ? Percent(litPure, result.Lit) : none;
  result.UmbraBehindSeveralPure =
    result.UmbraBehindSeveral > 0 ? Percent(severalPure, result.UmbraBehindSeveral) : none;
  if (errors.empty())
  {
    result.MeanAbsolute = result.Percentile95 = none;
    return result;
  }
  double sum = 0.0;
  for (double error : errors)
  {
    sum += error;
  }
  result.MeanAbsolute = sum / static_cast<double>(errors.size());
  // The nearest-rank 95th percentile.
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * errors.size())) - 1;
  std::nth_element(errors.begin(), errors.begin() + rank, errors.end());
  result.Percentile95 = errors[rank];
  return result;
}

//------------------------------------------------------------------------------
std::vector<std::uint8_t> VisibilityErrorMap(
  const std::vector<float>& visibility, const std::vector<float>& factor)
{
  std::vector<std::uint8_t> rgb(3 * visibility.size(), 0);
  for (std::size_t i = 0; i < visibility.size(); ++i)
  {
    if (visibility[i] == shadoworacle::NotCounted)
    {
      continue;
    }
    const double grey = 60.0 + 130.0 * visibility[i];
    const double difference = static_cast<double>(factor[i]) - visibility[i];
    const double strength = std::min(1.0, std::abs(difference) / 0.5);
    const double toward[3] = { difference > 0.0 ? 230.0 : 0.0, 60.0 * (difference < 0.0),
      difference < 0.0 ? 230.0 : 0.0 };
    for (int c = 0; c < 3; ++c)
    {
      rgb[3 * i + c] =
        static_cast<std::uint8_t>(std::lround(grey + strength * (toward[c] - grey)));
    }
  }
  return rgb;
}

//------------------------------------------------------------------------------
std::vector<float> FactorFromRenders(const std::vector<std::uint8_t>& shadowedRgb,
  const std::vector<std::uint8_t>& unshadowedRgb, int pixelCount)
{
  std::vector<float> factor(pixelCount, 1.0f);
  for (int i = 0; i < pixelCount; ++i)
  {
    const int shadowed = shadowedRgb[3 * i] + shadowedRgb[3 * i + 1] + shadowedRgb[3 * i + 2];
    const int unshadowed =
      unshadowedRgb[3 * i] + unshadowedRgb[3 * i + 1] + unshadowedRgb[3 * i + 2];
    if (unshadowed > 0)
    {
      factor[i] = std::min(1.0f, static_cast<float>(shadowed) / static_cast<float>(unshadowed));
    }
  }
  return factor;
}

//------------------------------------------------------------------------------
std::vector<float> FactorFromAnalysis(const std::vector<std::uint8_t>& rgb, int pixelCount)
{
  std::vector<float> factor(pixelCount);
  for (int i = 0; i < pixelCount; ++i)
  {
    factor[i] = static_cast<float>(rgb[3 * i]) / 255.0f;
  }
  return factor;
}

//------------------------------------------------------------------------------
double UndersampledFromAnalysis(
  const std::vector<std::uint8_t>& rgb, const std::vector<std::uint8_t>& valid)
{
  std::int64_t visible = 0;
  std::int64_t undersampled = 0;
  for (size_t i = 0; i < valid.size(); ++i)
  {
    if (valid[i])
    {
      ++visible;
      undersampled += rgb[3 * i] == 255;
    }
  }
  return Percent(undersampled, visible);
}

//------------------------------------------------------------------------------
std::vector<double> FootprintsFromAnalysis(
  const std::vector<std::uint8_t>& rgb, const std::vector<std::uint8_t>& valid)
{
  // The inverse of vtkShadowDensityColor (Shaders/vtkShadowMapsAnalysisFS.glsl):
  // green runs from 0.2 to 0.9 over log2 footprints -4 to log2(1.5), then,
  // with red at 1, from 0.6 down to 0 over log2(1.5) to 6.
  const double limit = std::log2(UndersampledAbove);
  std::vector<double> footprints(valid.size(), std::nan(""));
  for (size_t i = 0; i < valid.size(); ++i)
  {
    const double red = rgb[3 * i] / 255.0;
    const double green = rgb[3 * i + 1] / 255.0;
    const double blue = rgb[3 * i + 2] / 255.0;
    if (!valid[i] || red + green + blue == 0.0)
    {
      continue;
    }
    const double octaves = rgb[3 * i] == 255
      ? limit + std::clamp(1.0 - green / 0.6, 0.0, 1.0) * (6.0 - limit)
      : -4.0 + std::clamp((green - 0.2) / 0.7, 0.0, 1.0) * (limit + 4.0);
    footprints[i] = std::exp2(octaves);
  }
  return footprints;
}

//------------------------------------------------------------------------------
double FootprintSpread(const std::vector<double>& footprints)
{
  std::vector<double> sorted;
  for (double footprint : footprints)
  {
    if (std::isfinite(footprint) && footprint > 0.0)
    {
      sorted.push_back(footprint);
    }
  }
  if (sorted.empty())
  {
    return std::nan("");
  }
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&](double fraction) {
    return sorted[static_cast<size_t>(fraction * static_cast<double>(sorted.size() - 1))];
  };
  return std::log2(at(0.9) / at(0.1));
}

//------------------------------------------------------------------------------
double UndersampledFromFootprints(
  const std::vector<double>& footprint, const std::vector<std::uint8_t>& valid)
{
  std::int64_t visible = 0;
  std::int64_t undersampled = 0;
  for (size_t i = 0; i < valid.size(); ++i)
  {
    if (valid[i])
    {
      ++visible;
      undersampled += footprint[i] > UndersampledAbove;
    }
  }
  return Percent(undersampled, visible);
}

//------------------------------------------------------------------------------
std::vector<double> TexelFootprints(const std::vector<glm::dvec2>& texel,
  const std::vector<std::uint8_t>& valid, int width, int height)
{
  std::vector<double> footprint(texel.size(), 0.0);
  for (int y = 0; y + 1 < height; ++y)
  {
    for (int x = 0; x + 1 < width; ++x)
    {
      const int i = y * width + x;
      if (!valid[i] || !valid[i + 1] || !valid[i + width])
      {
        continue;
      }
      const glm::dvec2 dx = texel[i + 1] - texel[i];
      const glm::dvec2 dy = texel[i + width] - texel[i];
      const double texelsPerPixelArea = std::abs(dx.x * dy.y - dx.y * dy.x);
      footprint[i] = 1.0 / std::sqrt(std::max(texelsPerPixelArea, 1e-24));
    }
  }
  return footprint;
}

//------------------------------------------------------------------------------
double Flicker(const std::vector<Truth>& truthBefore, const std::vector<float>& factorBefore,
  const std::vector<Truth>& truthAfter, const std::vector<float>& factorAfter)
{
  std::int64_t counted = 0;
  std::int64_t flickering = 0;
  for (size_t i = 0; i < truthBefore.size(); ++i)
  {
    if (!Counted(truthBefore[i]) || !Counted(truthAfter[i]))
    {
      continue;
    }
    ++counted;
    flickering += truthBefore[i] == truthAfter[i] &&
      IsShadowed(factorBefore[i]) != IsShadowed(factorAfter[i]);
  }
  return Percent(flickering, counted);
}

//------------------------------------------------------------------------------
double StateChanges(const std::vector<Truth>& truthBefore, const std::vector<float>& factorBefore,
  const std::vector<Truth>& truthAfter, const std::vector<float>& factorAfter)
{
  std::int64_t counted = 0;
  std::int64_t changed = 0;
  for (size_t i = 0; i < truthBefore.size(); ++i)
  {
    if (Counted(truthBefore[i]) && Counted(truthAfter[i]))
    {
      ++counted;
      changed += IsShadowed(factorBefore[i]) != IsShadowed(factorAfter[i]);
    }
  }
  return Percent(changed, counted);
}

//------------------------------------------------------------------------------
double TruthChanges(const std::vector<Truth>& truthBefore, const std::vector<Truth>& truthAfter)
{
  std::int64_t counted = 0;
  std::int64_t changed = 0;
  for (size_t i = 0; i < truthBefore.size(); ++i)
  {
    if (Counted(truthBefore[i]) && Counted(truthAfter[i]))
    {
      ++counted;
      changed += truthBefore[i] != truthAfter[i];
    }
  }
  return Percent(changed, counted);
}

//------------------------------------------------------------------------------
std::vector<std::uint8_t> ErrorMap(const std::vector<Truth>& truth, const std::vector<float>& factor)
{
  std::vector<std::uint8_t> rgb(3 * truth.size(), 0);
  for (size_t i = 0; i < truth.size(); ++i)
  {
    std::uint8_t color[3] = { 0, 0, 0 };
    if (Counted(truth[i]))
    {
      const bool truthShadowed = truth[i] == Truth::Shadowed;
      const bool techniqueShadowed = IsShadowed(factor[i]);
      if (truthShadowed && !techniqueShadowed)
      {
        color[0] = 230; // light leak
      }
      else if (!truthShadowed && techniqueShadowed)
      {
        color[2] = 230; // false shadow
        color[1] = 60;
      }
      else
      {
        color[0] = color[1] = color[2] = truthShadowed ? 90 : 190;
      }
    }
    std::copy(color, color + 3, rgb.begin() + 3 * i);
  }
  return rgb;
}

//------------------------------------------------------------------------------
std::vector<float> MeanOfChannels(
  const std::vector<glm::vec3>& transmittance, const std::vector<std::uint8_t>& excluded)
{
  std::vector<float> mean(transmittance.size());
  for (std::size_t i = 0; i < transmittance.size(); ++i)
  {
    const glm::vec3& t = transmittance[i];
    const bool left = t.x == shadoworacle::NotCounted || (i < excluded.size() && excluded[i]);
    mean[i] = left ? shadoworacle::NotCounted : (t.x + t.y + t.z) / 3.0f;
  }
  return mean;
}

//------------------------------------------------------------------------------
std::vector<glm::vec3> ChannelFactorsFromRenders(const std::vector<std::uint8_t>& shadowedRgb,
  const std::vector<std::uint8_t>& unshadowedRgb, int pixelCount)
{
  std::vector<glm::vec3> factor(pixelCount, glm::vec3(1.0f));
  for (int i = 0; i < pixelCount; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const int unshadowed = unshadowedRgb[3 * i + c];
      if (unshadowed > 0)
      {
        factor[i][c] =
          std::min(1.0f, static_cast<float>(shadowedRgb[3 * i + c]) / static_cast<float>(unshadowed));
      }
    }
  }
  return factor;
}

//------------------------------------------------------------------------------
TransmittanceErrors CompareTransmittance(const std::vector<glm::vec3>& transmittance,
  const std::vector<glm::vec3>& factor, const std::vector<std::uint8_t>& seenThroughTranslucent)
{
  TransmittanceErrors result;
  const double none = std::numeric_limits<double>::quiet_NaN();
  if (factor.size() != transmittance.size())
  {
    result.MeanAbsolute = result.PartialMeanAbsolute = glm::dvec3(none);
    result.Percentile95 = none;
    return result;
  }
  std::vector<double> largest;
  for (std::size_t i = 0; i < transmittance.size(); ++i)
  {
    const glm::vec3& truth = transmittance[i];
    if (truth.x == shadoworacle::NotCounted ||
      (i < seenThroughTranslucent.size() && seenThroughTranslucent[i]))
    {
      continue;
    }
    const glm::dvec3 error = glm::abs(glm::dvec3(factor[i]) - glm::dvec3(truth));
    result.MeanAbsolute += error;
    largest.push_back(std::max(error.x, std::max(error.y, error.z)));
    const bool partial = (truth.x > 0.0f && truth.x < 1.0f) || (truth.y > 0.0f && truth.y < 1.0f) ||
      (truth.z > 0.0f && truth.z < 1.0f);
    if (partial)
    {
      ++result.Partial;
      result.PartialMeanAbsolute += error;
    }
  }
  result.Counted = static_cast<std::int64_t>(largest.size());
  result.PartialMeanAbsolute = result.Partial > 0
    ? result.PartialMeanAbsolute / static_cast<double>(result.Partial)
    : glm::dvec3(none);
  if (largest.empty())
  {
    result.MeanAbsolute = glm::dvec3(none);
    result.Percentile95 = none;
    return result;
  }
  result.MeanAbsolute /= static_cast<double>(largest.size());
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * largest.size())) - 1;
  std::nth_element(largest.begin(), largest.begin() + rank, largest.end());
  result.Percentile95 = largest[rank];
  return result;
}
//------------------------------------------------------------------------------
std::vector<std::uint8_t> TruthFrame(const std::vector<std::uint8_t>& unshadowedRgb,
  const std::vector<Truth>& truth, const std::vector<float>& visibility,
  const std::vector<glm::vec3>& transmittance)
{
  std::vector<std::uint8_t> rgb = unshadowedRgb;
  for (size_t i = 0; i < truth.size() && 3 * i + 2 < rgb.size(); ++i)
  {
    if (!Counted(truth[i]))
    {
      continue;
    }
    const float light = !visibility.empty() ? visibility[i]
      : truth[i] == Truth::Shadowed         ? 0.0f
                                            : 1.0f;
    const glm::vec3 tint = !transmittance.empty() ? transmittance[i] : glm::vec3(light);
    for (int c = 0; c < 3; ++c)
    {
      const float scaled = static_cast<float>(rgb[3 * i + c]) * std::clamp(tint[c], 0.0f, 1.0f);
      rgb[3 * i + c] = static_cast<std::uint8_t>(std::lround(scaled));
    }
  }
  return rgb;
}

//------------------------------------------------------------------------------
std::vector<std::uint8_t> ShownFrame(
  const std::vector<std::uint8_t>& shadowedRgb, const std::vector<std::uint8_t>& unshadowedRgb)
{
  std::vector<std::uint8_t> rgb(shadowedRgb.size());
  for (size_t i = 0; i < rgb.size() && i < unshadowedRgb.size(); ++i)
  {
    const float shown = (1.0f - ShownAmbient) * shadowedRgb[i] + ShownAmbient * unshadowedRgb[i];
    rgb[i] = static_cast<std::uint8_t>(std::lround(std::min(255.0f, shown)));
  }
  return rgb;
}

} // namespace shadowmetrics
