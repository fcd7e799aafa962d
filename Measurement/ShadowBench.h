// The benchmark behind `vtkshadows bench` and `vtkshadows analyze`: every
// technique on every scene and light set-up, measured against the Embree
// oracle (ShadowOracle.h) with the metrics of ShadowMetrics.h, timed in the
// same run as no shadows and as VTK's vtkShadowMapPass.
#ifndef ShadowBench_h
#define ShadowBench_h

#include <iosfwd>
#include <string>
#include <vector>

namespace shadowbench
{

struct Options
{
  /// Benchmark scenes (shadowscenes::BenchmarkSceneNames) or, when ModelFile
  /// is set, that file alone.
  std::vector<std::string> Scenes;
  std::string ModelFile;
  /// shadowscenes::LightSetupNames.
  std::vector<std::string> Setups;
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
  /// Frames averaged per frame-time figure.
  int TimedFrames = 8;
  std::string OutputDirectory = "bench";
};

/// Default lists: every benchmark scene, every light set-up, the techniques
/// below, flicker along the path for the perpendicular sun.
Options DefaultOptions();

/// Runs the benchmark: prints the markdown table on `out` and writes into the
/// output directory results.md, results.csv, one error map PNG per case
/// (<scene>-<setup>-<technique>-errors.png: leaks red, false shadows blue,
/// agreement grey) and one chart PNG per scene and set-up. Progress goes to
/// `log`. Returns false with a one-line `error` on bad options or failure.
bool Run(const Options& options, std::ostream& out, std::ostream& log, std::string& error);

} // namespace shadowbench

#endif
