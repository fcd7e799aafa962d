// Error metrics of a shadow technique against the oracle's truth, per pixel
// of one view and one light. Pure functions over images stored row by row,
// row 0 at the bottom (VTK's pixel order), index = y * width + x.
#ifndef ShadowMetrics_h
#define ShadowMetrics_h

#include "ShadowOracle.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace shadowmetrics
{
using shadoworacle::Truth;

/// A shadow factor below this counts as shadowed.
constexpr float ShadowedBelow = 0.5f;

/// Texel footprints (screen pixels per map texel, along one side) above this
/// count as undersampled.
constexpr double UndersampledAbove = 1.5;

struct Classification
{
  /// Pixels where the truth is Lit or Shadowed (visible, lit-facing).
  std::int64_t Counted = 0;
  /// Counted pixels not on a truth shadow edge (no 4-neighbour of another state).
  std::int64_t Inner = 0;
  /// Percentages of Counted: disagreements, split into false shadows (truth
  /// lit, technique shadowed) and light leaks (truth shadowed, technique lit).
  double Misclassified = 0.0;
  double FalseShadow = 0.0;
  double LightLeak = 0.0;
  /// Percentage of Inner pixels that disagree.
  double InnerMisclassified = 0.0;
  /// Mean |factor - truth| over Counted pixels (truth 1 lit, 0 shadowed).
  double MeanAbsoluteDifference = 0.0;
};

/// Clears `valid` (a Surface's) where the unshadowed render is black: there
/// the renderer's own shading does not light the surface (its interpolated
/// normal faces away from the light while the oracle's geometric normal does
/// not, as on an isosurface's folds), so no shadow factor can be read from the
/// renders. Without this such pixels counted as lit for every technique (the
/// factor reads 1): 854 pixels of the paraview scene's view under its sun. A render
/// of another size than `valid` clears every pixel, with a message on
/// std::cerr (as Oracle::MaskRasterMismatch does for its z-buffer).
void IgnoreUnlitInRender(
  const std::vector<std::uint8_t>& unshadowedRgb, std::vector<std::uint8_t>& valid);

/// Compares the technique's shadow factor (1 lit, 0 shadowed) with the truth.
Classification Classify(
  const std::vector<Truth>& truth, const std::vector<float>& factor, int width, int height);

// --- sized lights: the technique's factor against fractional visibility ------------

/// The truth of a fractional visibility (Oracle::Visibility) thresholded at
/// ShadowedBelow, as the technique's factor is: Ignored where NotCounted.
std::vector<Truth> TruthAtHalf(const std::vector<float>& visibility);

/// Where the visibility is this close to 0 (umbra) or 1 (lit), the factor
/// must be too, to count as pure.
constexpr float PureWithin = 0.05f;

struct VisibilityErrors
{
  /// Pixels with a visibility (not NotCounted).
  std::int64_t Counted = 0;
  /// |factor - visibility| over them: mean and 95th percentile.
  double MeanAbsolute = 0.0;
  double Percentile95 = 0.0;
  /// Both thresholded at ShadowedBelow (TruthAtHalf).
  Classification AtHalf;
  /// Umbra pixels (visibility 0) and the percentage of them whose factor is at
  /// most PureWithin; lit pixels (visibility 1) and the percentage at least
  /// 1 - PureWithin; NaN without any.
  std::int64_t Umbra = 0;
  double UmbraPure = 0.0;
  std::int64_t Lit = 0;
  double LitPure = 0.0;
  /// The umbra pixels none of whose counted 4-neighbours has a visibility above
  /// 0 (more than a pixel from the truth's penumbra or light; TruthEdges), and
  /// the percentage of them at most PureWithin: the purity the pixel grid
  /// leaves to the technique, where UmbraPure also holds the pixels that
  /// straddle the umbra's edge.
  std::int64_t UmbraInner = 0;
  double UmbraInnerPure = 0.0;
  /// The umbra pixels behind two or more occluders (Oracle::CountOccluders of
  /// TruthAtHalf), where moments leak, reported apart.
  std::int64_t UmbraBehindSeveral = 0;
  double UmbraBehindSeveralPure = 0.0;
};

/// Compares the technique's factor with the visibility of a sized light.
/// `occluders` may be empty (UmbraBehindSeveral 0).
VisibilityErrors CompareVisibility(const std::vector<float>& visibility,
  const std::vector<float>& factor, const std::vector<unsigned char>& occluders, int width,
  int height);

/// Signed visibility error as RGB bytes: factor above the visibility (light
/// where the truth has less) red, below it blue, in proportion to the
/// difference (full at 0.5); agreement grey by the visibility; not counted
/// black.
std::vector<std::uint8_t> VisibilityErrorMap(
  const std::vector<float>& visibility, const std::vector<float>& factor);

// --- translucent casters: the factor per channel against the transmittance --------

/// Per pixel and channel, the shadow factor from two renders of the same view
/// with white, purely diffuse receivers: with the technique and without
/// shadows (FactorFromRenders channel by channel); 1 where the unshadowed
/// channel is black.
std::vector<glm::vec3> ChannelFactorsFromRenders(const std::vector<std::uint8_t>& shadowedRgb,
  const std::vector<std::uint8_t>& unshadowedRgb, int pixelCount);

struct TransmittanceErrors
{
  /// Pixels with a transmittance (not NotCounted) and not seen through a
  /// translucent surface (whose colour the renders blend in).
  std::int64_t Counted = 0;
  /// |factor - transmittance| per channel over them, and the nearest-rank
  /// 95th percentile of each pixel's largest channel error.
  glm::dvec3 MeanAbsolute{ 0.0 };
  double Percentile95 = 0.0;
  /// The counted pixels whose transmittance is partial (some channel strictly
  /// between 0 and 1: under translucent casters or in a penumbra), and the
  /// mean absolute error per channel over them (NaN without any).
  std::int64_t Partial = 0;
  glm::dvec3 PartialMeanAbsolute{ 0.0 };
};

/// The mean of each pixel's channels, NotCounted where it was or where
/// `excluded` (empty: nowhere) is set: a transmittance as one visibility, for
/// VisibilityErrorMap, leaving out the pixels CompareTransmittance leaves out.
std::vector<float> MeanOfChannels(
  const std::vector<glm::vec3>& transmittance, const std::vector<std::uint8_t>& excluded);

/// Compares the technique's factor per channel with the oracle's
/// transmittance (Oracle::Transmittance), leaving out the pixels
/// `seenThroughTranslucent` marks (Surface::SeenThroughTranslucent; empty:
/// none). NaN everywhere when the sizes differ.
TransmittanceErrors CompareTransmittance(const std::vector<glm::vec3>& transmittance,
  const std::vector<glm::vec3>& factor, const std::vector<std::uint8_t>& seenThroughTranslucent);

/// Light bleeding: the percentage of the pixels whose truth's shadow ray meets
/// two or more occluders (Oracle::CountOccluders >= 2) that the technique
/// lights (factor at or above ShadowedBelow); NaN where there are none.
double LeakBehindSeveral(const std::vector<unsigned char>& occluders, const std::vector<float>& factor);

/// True where the truth has a different non-ignored state at a 4-neighbour.
std::vector<std::uint8_t> TruthEdges(const std::vector<Truth>& truth, int width, int height);

/// The shadow factor of every pixel from two renders of the same view with
/// white, purely diffuse materials: with the technique and without shadows.
/// Where the unshadowed render is black the factor is 1 (IgnoreUnlitInRender
/// leaves those pixels out).
std::vector<float> FactorFromRenders(const std::vector<std::uint8_t>& shadowedRgb,
  const std::vector<std::uint8_t>& unshadowedRgb, int pixelCount);

/// The shadow factor from a SHADOW_FACTOR analysis render (grey = factor).
std::vector<float> FactorFromAnalysis(const std::vector<std::uint8_t>& rgb, int pixelCount);

/// Percentage of the valid pixels whose texel-density analysis colour is
/// undersampled (red channel 255; see vtkAbstractShadowMapPass::TEXEL_DENSITY).
double UndersampledFromAnalysis(
  const std::vector<std::uint8_t>& rgb, const std::vector<std::uint8_t>& valid);

/// Each valid pixel's texel footprint (screen pixels per map texel, along one
/// side) decoded from a texel-density analysis render's heat map; NaN for
/// pixels outside the maps (black) and invalid ones. Footprints below 1/16 and
/// above 64 pixels read as those bounds (the heat map's own).
std::vector<double> FootprintsFromAnalysis(
  const std::vector<std::uint8_t>& rgb, const std::vector<std::uint8_t>& valid);

/// How unevenly texels spread over the view: log2 of the 90th over the 10th
/// percentile of the finite, positive footprints, in octaves (0: every pixel
/// gets the same texel size); NaN without any.
double FootprintSpread(const std::vector<double>& footprints);

/// Percentage of the valid pixels whose footprint exceeds UndersampledAbove.
double UndersampledFromFootprints(
  const std::vector<double>& footprint, const std::vector<std::uint8_t>& valid);

/// Screen pixels covered by one map texel along one side, 1 / sqrt(|det J|),
/// with J the derivative of map texel coordinates by window pixel, taken by
/// finite differences of `texel` (the map texel coordinates of every pixel's
/// surface point) toward the right and upper neighbours. Pixels without valid
/// neighbours get 0 (never undersampled).
std::vector<double> TexelFootprints(const std::vector<glm::dvec2>& texel,
  const std::vector<std::uint8_t>& valid, int width, int height);

/// Flicker between two consecutive frames: percentage of the pixels counted in
/// both frames whose technique state changed while their truth did not.
double Flicker(const std::vector<Truth>& truthBefore, const std::vector<float>& factorBefore,
  const std::vector<Truth>& truthAfter, const std::vector<float>& factorAfter);

/// Percentage of the pixels counted in both frames whose technique state changed,
/// whether or not the truth did. Set beside TruthChanges it shows whether a
/// technique's shadows change more than the scene's (swimming edges add changes;
/// an edge that is only offset or blurred moves over as many pixels as the truth's).
double StateChanges(const std::vector<Truth>& truthBefore, const std::vector<float>& factorBefore,
  const std::vector<Truth>& truthAfter, const std::vector<float>& factorAfter);

/// Percentage of the pixels counted in both frames whose truth changed.
double TruthChanges(const std::vector<Truth>& truthBefore, const std::vector<Truth>& truthAfter);

/// Error map as RGB bytes: light leaks red, false shadows blue, agreement grey
/// (light where lit, dark where shadowed), ignored pixels black.
std::vector<std::uint8_t> ErrorMap(const std::vector<Truth>& truth, const std::vector<float>& factor);

// --- pictures: what a technique's frame and the truth look like ------------------

/// The frame a technique without error renders, from the frame without
/// shadows: each counted pixel scaled by the truth's light, per channel where
/// `transmittance` is given (translucent casters), else by `visibility` where
/// given (a sized light), else 1 lit and 0 shadowed; other pixels as without
/// shadows.
std::vector<std::uint8_t> TruthFrame(const std::vector<std::uint8_t>& unshadowedRgb,
  const std::vector<Truth>& truth, const std::vector<float>& visibility,
  const std::vector<glm::vec3>& transmittance);

/// A frame as the gallery shows it: the measurement's materials have no
/// ambient term, so a shadow is black; this lifts every pixel by
/// `ambient` of the frame without shadows, the look of a white material with
/// that ambient, so that shapes stay readable inside shadows.
constexpr float ShownAmbient = 0.2f;
std::vector<std::uint8_t> ShownFrame(
  const std::vector<std::uint8_t>& shadowedRgb, const std::vector<std::uint8_t>& unshadowedRgb);

} // namespace shadowmetrics

#endif
