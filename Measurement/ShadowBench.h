// The benchmark behind `vtkshadows bench` and `vtkshadows analyze`: every
// technique on every scene and light set-up, measured against the Embree
// oracle (ShadowOracle.h) with the metrics of ShadowMetrics.h, timed in the
// same run as no shadows and as VTK's vtkShadowMapPass.
#ifndef ShadowBench_h
#define ShadowBench_h

#include "ShadowMetrics.h"
#include "ShadowModelUp.h"

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace shadowbench
{

struct Options
{
  /// Benchmark scenes (shadowscenes::BenchmarkSceneNames) or, when ModelFile
  /// is set, that file alone.
  std::vector<std::string> Scenes;
  std::string ModelFile;
  /// The model file's up axis (Auto: shadowscenes::ChooseModelUp).
  shadowscenes::UpAxis Up = shadowscenes::UpAxis::Auto;
  /// shadowscenes::LightSetupNames.
  std::vector<std::string> Setups;
  /// When not empty, the (scene, set-up) pairs measured instead of every
  /// scene under every set-up.
  std::vector<std::pair<std::string, std::string>> Cases;
  /// TechniqueNames() (ShadowTechniques.h); by default DefaultTechniqueNames().
  std::vector<std::string> Techniques;
  /// Map resolution of this project's techniques; VTK's pass runs at its
  /// default (1024) and at the resolution of equal memory ("vtk-equal").
  int Resolution = 2048;
  int Width = 640;
  int Height = 360;
  /// Frames of the camera path for the flicker metric (0: no flicker), and the
  /// set-ups measured along it.
  int FlickerFrames = 60;
  std::vector<std::string> FlickerSetups;
  /// How far the camera turns over the path (shadowscenes::SetCameraPathFrame).
  double FlickerYawDegrees = 6.0;
  /// Frames averaged per frame-time figure.
  int TimedFrames = 8;
  std::string OutputDirectory = "bench";
  /// Also writes each case's frames: <scene>-<setup>-<technique>-frame.png and
  /// the ray-cast truth's <scene>-<setup>-truth.png, both as
  /// shadowmetrics::ShownFrame shows them.
  bool WriteFrames = false;
};

/// One technique's figures in one case, for callers that compose the
/// benchmark's outputs (the gallery).
struct CaseFigures
{
  std::string Scene;
  std::string Setup;
  std::string Technique;
  /// The automatic pass's choice for the light ("" for other techniques).
  std::string Choice;
  shadowmetrics::Classification Errors;
  /// Scenes with translucent casters or volumes: the mean over pixels and
  /// channels of |factor - transmittance| (Errors then counts the opaque
  /// casters' shadows alone as the truth).
  bool Translucent = false;
  double TransmittanceError = 0.0;
};

/// Default lists: every benchmark scene, every light set-up, the techniques
/// below, flicker along the path for the perpendicular sun.
Options DefaultOptions();

/// `vtkshadows analyze`'s: a quick answer (about a minute and a half for a
/// 110,000-triangle model on a 2-core machine with llvmpipe): the techniques
/// that differ most (QuickTechniqueNames), one set-up per light kind
/// (perpendicular, spot, point), 3 timed frames and 12 frames of flicker.
Options QuickAnalyzeOptions();

/// A technique is recommended if its frames stay within this many times the
/// uniform map's.
constexpr double RecommendationBudget = 1.25;

/// "<scene>-<setup>": the stem of every file the benchmark writes for a case.
std::string CaseName(const std::string& scene, const std::string& setup);

/// Runs the benchmark: prints the markdown table and the recommendation
/// (ShadowRecommendation.h) on `out` and writes into the output directory
/// results.md (both), results.csv, recommendation.json, one error map PNG per
/// case (<scene>-<setup>-<technique>-errors.png: leaks red, false shadows
/// blue, agreement grey; for a sized light or translucent casters, red or
/// blue in proportion to the light's error against the visibility or the
/// transmittance's mean channel) and one chart PNG per scene and set-up. Progress, with
/// the time left, goes to `log`, and for a model file the up axis it was given.
/// Returns false with a one-line `error` on bad options or failure.
/// `figures`, when given, receives every technique's figures in every case.
bool Run(const Options& options, std::ostream& out, std::ostream& log, std::string& error,
  std::vector<CaseFigures>* figures = nullptr);

} // namespace shadowbench

#endif
