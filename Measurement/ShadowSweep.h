// The robustness sweep behind `vtkshadows sweep`: every technique against the
// Embree oracle (ShadowOracle.h) on many random cases, each a scene, a camera
// and a light drawn from one 64-bit seed, so that any case can be replayed
// alone (`vtkshadows sweep --replay SEED`).
#ifndef ShadowSweep_h
#define ShadowSweep_h

#include "ShadowMapLightSituation.h"
#include "ShadowMetrics.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace shadowsweep
{

enum class LightKind
{
  Directional,
  Spot,
  Point
};

/// A light of a case. Scene lights hold world coordinates; camera lights hold
/// VTK's camera-light coordinates (the focal point at the origin, the camera at
/// (0, 0, 1), x to the right, y up).
struct LightCase
{
  LightKind Kind = LightKind::Directional;
  bool CameraLight = false;
  glm::dvec3 Position{ 0.0, 0.0, 1.0 };
  glm::dvec3 FocalPoint{ 0.0 };
  double ConeAngle = 180.0; ///< vtkLight's half-angle, degrees (spots below 90)
  /// vtkAbstractShadowMapPass::LIGHT_SIZE (0: none): a sun's angular diameter
  /// in degrees, a positional light's radius.
  double Size = 0.0;
  std::string Description;  ///< e.g. "sun along the view"
};

struct CameraCase
{
  glm::dvec3 Position{ 0.0, 0.0, 1.0 };
  glm::dvec3 FocalPoint{ 0.0 };
  glm::dvec3 ViewUp{ 0.0, 0.0, 1.0 };
  bool Parallel = false;
  double ViewAngle = 30.0;     ///< degrees, perspective cameras
  double ParallelScale = 1.0;  ///< parallel cameras
  double Near = 0.1;
  double Far = 100.0;
  std::string Description;     ///< e.g. "street level"
};

/// One case: everything below is drawn from Seed alone (and the scene's bounds).
struct Case
{
  std::uint64_t Seed = 0;
  std::string Scene;
  CameraCase Camera;
  LightCase Light;
  int Width = 0;
  int Height = 0;
};

/// The seed of case `index` of a sweep seeded with `sweepSeed`.
std::uint64_t CaseSeed(std::uint64_t sweepSeed, int index);

/// The scene of a case seed, one of shadowscenes::SweepSceneNames().
std::string SceneOfCase(std::uint64_t caseSeed);

/**
 * Draws the camera, light and window of a case in a scene whose visible props
 * have `bounds` (xmin, xmax, ymin, ymax, zmin, zmax). Cameras stand inside or
 * above the scene (street level in the city, inside the room), look anywhere
 * (mostly at the scene), perspective with view angles of 10 to 100 degrees or
 * parallel, with near/far ratios from 1e-1 down to 1e-5. Lights: directional
 * from any direction, exactly along or against the view among them; spots of
 * cones in (0, 90) degrees; point lights inside and outside the scene, and
 * (half of those of perspective cameras standing in the scene, but in the
 * room) a little behind and above the camera; camera lights. Windows are baseWidth x baseHeight scaled by 0.5 to 1.5 per side.
 */
Case DrawCase(std::uint64_t caseSeed, const double bounds[6], int baseWidth, int baseHeight);

/**
 * Gives the case's light a size drawn from its seed apart from everything
 * else (the case is otherwise the same): suns 0.25 to 8 degrees across,
 * positional lights a radius of 0.2% to 5% of the scene's diagonal, both
 * log-uniform.
 */
void DrawLightSize(Case& sweepCase, const double bounds[6]);

/// One line describing a case (scene, camera, light, window).
std::string Describe(const Case& sweepCase);

struct Options
{
  int Cases = 200;
  std::uint64_t Seed = 1;
  /// The sweep's cases FirstCase .. FirstCase + Cases - 1: a long sweep run in
  /// parts gives the same cases as in one run.
  int FirstCase = 0;
  /// Cases below MinimumCounted are drawn and judged by the truth but not
  /// rendered by the techniques (they enter no distribution; their flags go
  /// unseen): a sweep for distributions in about half the time.
  bool CountedOnly = false;
  /// Technique names of ShadowTechniques.h.
  std::vector<std::string> Techniques = { "uniform", "psm", "lispsm", "tsm", "gmnpr", "csm",
    "csm-tight", "csm-lispsm" };
  int Resolution = 2048;
  int BaseWidth = 192;
  int BaseHeight = 144;
  /// Cases with fewer counted pixels (visible, lit-facing) enter no distribution.
  int MinimumCounted = 300;
  /// Every case's light gets a size (DrawLightSize): soft shadows, measured
  /// against the oracle's visibility as well.
  bool SizedLights = false;
  std::string OutputDirectory = "sweep";
  /// Replay this case seed alone, with images and error maps.
  bool Replay = false;
  std::uint64_t ReplaySeed = 0;
};

/// What one technique did in one case.
struct TechniqueResult
{
  std::string Technique;
  shadowmetrics::Classification Errors;
  int GLErrors = 0;
  int VTKErrors = 0;
  int VTKWarnings = 0;
  /// Light views with a non-finite matrix (the pass reports and drops them).
  int NonFiniteViews = 0;
  /// The truth has shadow on counted pixels, the technique none on any of them.
  bool ShadowLost = false;
  /// Sized lights: the factor against the visibility (the truth the other
  /// figures use is that visibility thresholded at one half).
  bool Sized = false;
  shadowmetrics::VisibilityErrors Visibility;
  std::string Messages;

  bool Flagged() const;
  /// Why Flagged(), in a few words ("" if not).
  std::string Flags() const;
};

struct CaseResult
{
  Case Drawn;
  /// The light in world coordinates as rendered (camera lights too).
  glm::dvec3 LightWorldPosition{ 0.0 };
  glm::dvec3 LightWorldFocalPoint{ 0.0 };
  /// What the automatic pass chooses the light's views from.
  shadowmaps::LightSituation Situation;
  std::int64_t Counted = 0;
  std::int64_t TruthShadowed = 0;
  std::vector<TechniqueResult> Techniques;
};

/// Per technique over the cases with at least MinimumCounted counted pixels
/// (flags over every case).
struct Distribution
{
  std::string Technique;
  int Cases = 0;
  double Median = 0.0;
  double Percentile95 = 0.0;
  double Worst = 0.0;
  std::uint64_t WorstSeed = 0;
  /// Worst of the uniform map over the same cases (NaN if not measured).
  double UniformWorst = 0.0;
  /// Flagged cases among all cases, whatever their counted pixels.
  int Flagged = 0;
};

/// The distributions of `results` (one per technique, in the order measured).
std::vector<Distribution> Summarise(const std::vector<CaseResult>& results, int minimumCounted);

/// Sized lights: the distribution of the mean absolute visibility error per
/// technique (Distribution's fields in visibility, not percent; UniformWorst
/// the uniform map's worst mean error).
std::vector<Distribution> SummariseVisibility(
  const std::vector<CaseResult>& results, int minimumCounted);

/**
 * Measures given cases (a regression test builds its case by hand) with
 * options' techniques, resolution and, with Replay on, images in its output
 * directory. False with a one-line `error` on bad options or a scene that
 * cannot be built.
 */
bool MeasureCases(const std::vector<Case>& cases, const Options& options,
  std::vector<CaseResult>& results, std::ostream& log, std::string& error);

/**
 * Runs the sweep (or the replay of Options::ReplaySeed): prints a markdown
 * report on `out` (distributions, worst cases with their seeds, flagged cases)
 * and writes results.md and results.csv to the output directory, and for a
 * replay the frames (<seed>-<technique>.png, measured with white diffuse
 * materials; <seed>-none.png without shadows), error maps
 * (<seed>-<technique>-errors.png: leaks red, false shadows blue) and this
 * project's maps (<seed>-<technique>-maps.png, the SHADOW_MAP analysis view). Progress goes to `log`. The results are also returned
 * through `results` when given. Returns false with a one-line `error` on bad
 * options or failure to build a scene.
 */
bool Run(const Options& options, std::ostream& out, std::ostream& log, std::string& error,
  std::vector<CaseResult>* results = nullptr);

} // namespace shadowsweep

#endif
