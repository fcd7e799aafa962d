// The speed benchmark behind `vtkshadows speed`: first, steady and moving
// frame times of no shadows, VTK's vtkShadowMapPass and this module's
// techniques, in one process with interleaved rounds, on the benchmark scenes
// and a many-actor street, at a resolution and at 64^2 (where the maps cost
// almost nothing and what is left is per-frame and per-actor work).
#ifndef ShadowSpeed_h
#define ShadowSpeed_h

#include <iosfwd>
#include <string>
#include <vector>

namespace shadowbench
{

struct SpeedOptions
{
  /// shadowscenes::BuildSceneByName names.
  std::vector<std::string> Scenes{ "outdoor", "paraview", "model", "street" };
  /// shadowscenes::LightSetupNames(): a sun and a spot.
  std::vector<std::string> Setups{ "perpendicular", "spot" };
  /// TechniqueNames(); none and vtk are always measured (the references).
  std::vector<std::string> Techniques{ "uniform", "lispsm", "csm" };
  /// Map resolutions of this project's techniques; VTK's pass keeps its own.
  std::vector<int> Resolutions{ 2048, 64 };
  int Width = 960;
  int Height = 540;
  int TimedFrames = 8;
  /// Moving frames orbit the camera by this many degrees each.
  double OrbitDegrees = 0.3;
  /// Moving frames are rendered as a user's drag, or at the still rate as a
  /// scripted animation is (MovingCameraRenders).
  bool InteractiveMoving = true;
  /// Our passes keep views in still renders (AnimationKeepsViews), as a movie
  /// maker asks them to.
  bool AnimationKeepsViews = false;
  /// Moving frames keep the camera and play the scene's time-varying data
  /// instead (shadowscenes::AdvanceTimeVaryingData, run before the clock
  /// starts), at the still rate as an animation plays.
  bool MovingData = false;
  std::string OutputDirectory = "speed";
};

/// Runs the speed benchmark: prints a markdown table on `out` (milliseconds and
/// the ratios the acceptance bounds of issue 20 are stated in) and writes it to
/// speed.md and speed.csv in the output directory. Progress goes to `log`.
/// Returns false with a one-line `error` on bad options or failure.
bool RunSpeed(const SpeedOptions& options, std::ostream& out, std::ostream& log, std::string& error);

} // namespace shadowbench

#endif
