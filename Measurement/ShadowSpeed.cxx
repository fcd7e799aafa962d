#include "ShadowSpeed.h"

#include "ShadowFrameTimes.h"
#include "ShadowGLCalls.h"
#include "ShadowScenes.h"
#include "ShadowTechniques.h"

#include "vtkAbstractShadowMapPass.h"

#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace shadowbench
{
namespace
{
constexpr int MovingFramesCounted = 8;

/// What one of our passes does in moving frames after its first: shader sources
/// built (0 when casters and receivers keep their programs), map layers
/// re-rendered per frame, of the layers in use, and caster draws per frame.
struct MovingCounts
{
  int ShaderBuilds = -1;
  double LayersPerFrame = -1.0;
  int Layers = -1;
  double CasterDrawsPerFrame = -1.0;
  /// Milliseconds per frame in each of the pass's frame steps
  /// (vtkAbstractShadowMapPass::GetFrameStepMilliseconds); empty: not ours.
  std::vector<double> StepMillisecondsPerFrame;
};

struct SpeedRow
{
  std::string Scene;
  std::string Setup;
  int Resolution = 0;
  std::string Technique;
  Timing Time;
  MovingCounts Counts; // ours only
  GLCallCounts SteadyCalls;
  int Props = 0;
};

struct SpeedView
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkCamera> Initial;
};

bool ValidateSpeedOptions(const SpeedOptions& options, std::string& error)
{
  if (!CheckTechniquesAndSetups(options.Techniques, options.Setups, error))
  {
    return false;
  }
  if (options.Scenes.empty() || options.Setups.empty() || options.Resolutions.empty())
  {
    error = "nothing to measure";
    return false;
  }
  // Before any scene is measured: a run must not end on its last scene.
  for (const std::string& scene : options.Scenes)
  {
    if (options.MovingData && !shadowscenes::HasTimeVaryingData(scene))
    {
      error = "scene '" + scene + "' has no time-varying data to play (--moving data: contour, timesteps)";
      return false;
    }
  }
  return MakeOutputDirectory(options.OutputDirectory, error);
}

bool BuildSpeedView(SpeedView& view, const std::string& scene, const SpeedOptions& options,
  std::string& error)
{
  if (!shadowscenes::BuildSceneByName(view.Renderer, scene, error))
  {
    return false;
  }
  view.Initial->DeepCopy(view.Renderer->GetActiveCamera());
  view.Window->SetOffScreenRendering(1);
  view.Window->SetMultiSamples(0);
  view.Window->SetSize(options.Width, options.Height);
  view.Window->AddRenderer(view.Renderer);
  return true;
}

/// Moving frames orbit the focal point as an interactor would, resetting the
/// clipping range.
CameraMotion Orbit(SpeedView& view, double degreesPerFrame)
{
  return [&view, degreesPerFrame](int frame, int) {
    vtkCamera* camera = view.Renderer->GetActiveCamera();
    camera->DeepCopy(view.Initial);
    camera->Azimuth(degreesPerFrame * frame);
    view.Renderer->ResetCameraClippingRange();
  };
}

/// Moving frames play the scene's time-varying data with the camera still.
CameraMotion PlayData(SpeedView& view)
{
  return [&view](int frame, int) { shadowscenes::AdvanceTimeVaryingData(view.Renderer, frame); };
}

/// What moving frames do: play the data or orbit.
CameraMotion MotionOf(SpeedView& view, const SpeedOptions& options)
{
  return options.MovingData ? PlayData(view) : Orbit(view, options.OrbitDegrees);
}

/// Counts one of our passes' work over `frames` moving frames after its first.
MovingCounts CountMovingWork(SpeedView& view, const TechniqueInstance& technique,
  const CameraMotion& orbit, int frames, bool interactive)
{
  MovingCounts counts;
  if (!technique.Ours)
  {
    return counts;
  }
  // A prop first drawn since the pass switch builds its program then: the orbit
  // once over before counting, still and as counted (a drag's maps may take in
  // casters that still frames' maps cull).
  view.Renderer->SetPass(technique.Pass);
  const auto orbitOnce = [&](bool drag) {
    const MovingCameraRenders renders(view.Window, drag);
    for (int frame = 0; frame < frames + 2; ++frame)
    {
      orbit(frame, frames + 2);
      view.Window->Render();
    }
  };
  orbitOnce(false);
  if (interactive)
  {
    orbitOnce(true);
  }
  orbit(0, frames + 2);
  view.Window->Render();
  orbit(1, frames + 2);
  view.Window->Render();
  const int before = technique.Ours->GetNumberOfShaderBuilds();
  int layers = 0;
  int casterDraws = 0;
  std::vector<double> steps(vtkAbstractShadowMapPass::NUMBER_OF_FRAME_STEPS, 0.0);
  {
    const MovingCameraRenders drag(view.Window, interactive);
    for (int frame = 2; frame < frames + 2; ++frame)
    {
      orbit(frame, frames + 2);
      view.Window->Render();
      int frameLayers = 0;
      int frameDraws = 0;
      ReadMapWork(technique.Ours, frameLayers, frameDraws);
      layers += frameLayers;
      casterDraws += frameDraws;
      for (std::size_t step = 0; step < steps.size(); ++step)
      {
        steps[step] += technique.Ours->GetFrameStepMilliseconds(static_cast<int>(step));
      }
    }
  }
  orbit(0, frames + 2);
  counts.ShaderBuilds = technique.Ours->GetNumberOfShaderBuilds() - before;
  counts.LayersPerFrame = double(layers) / double(frames);
  counts.Layers = technique.Ours->GetNumberOfShadowMapLayers();
  counts.CasterDrawsPerFrame = double(casterDraws) / double(frames);
  for (double& total : steps)
  {
    total /= double(frames);
  }
  counts.StepMillisecondsPerFrame = steps;
  return counts;
}

/// The GL calls of one steady frame of `pass` (nullptr: no shadows).
GLCallCounts CountSteadyGLCalls(SpeedView& view, vtkRenderPass* pass)
{
  view.Renderer->SetPass(pass);
  for (int i = 0; i < 3; ++i)
  {
    view.Window->Render();
  }
  view.Window->MakeCurrent();
  StartCountingGLCalls();
  view.Window->Render();
  return StopCountingGLCalls();
}

int CountProps(vtkRenderer* renderer)
{
  return renderer->GetViewProps()->GetNumberOfItems();
}

void MeasureCase(SpeedView& view, const std::string& scene, const std::string& setup,
  int resolution, const SpeedOptions& options, std::vector<SpeedRow>& rows)
{
  const std::vector<std::string> names = WithReferenceTechniques(options.Techniques);
  std::vector<TechniqueInstance> techniques;
  std::vector<vtkRenderPass*> passes;
  for (const std::string& name : names)
  {
    techniques.push_back(MakeTechnique(name, shadowscenes::LightKindOfSetup(setup) == "point", resolution));
    if (techniques.back().Ours)
    {
      techniques.back().Ours->SetAnimationKeepsViews(options.AnimationKeepsViews);
    }
    passes.push_back(techniques.back().Pass);
  }
  const bool interactive = options.InteractiveMoving && !options.MovingData;
  const std::vector<Timing> timing = MeasureFrameTimes(view.Window, view.Renderer, passes,
    options.TimedFrames, MotionOf(view, options), interactive);
  for (size_t t = 0; t < techniques.size(); ++t)
  {
    SpeedRow row{ scene, setup, resolution, names[t], timing[t],
      CountMovingWork(
        view, techniques[t], MotionOf(view, options), MovingFramesCounted, interactive),
      CountSteadyGLCalls(view, techniques[t].Pass), CountProps(view.Renderer) };
    rows.push_back(row);
  }
  view.Renderer->SetPass(nullptr);
  for (const TechniqueInstance& technique : techniques)
  {
    if (technique.Pass)
    {
      technique.Pass->ReleaseGraphicsResources(view.Window);
    }
  }
}

const SpeedRow* Reference(const std::vector<SpeedRow>& rows, const SpeedRow& row, const char* name)
{
  for (const SpeedRow& other : rows)
  {
    if (other.Scene == row.Scene && other.Setup == row.Setup &&
      other.Resolution == row.Resolution && other.Technique == name)
    {
      return &other;
    }
  }
  return nullptr;
}

std::string Ratio(double value, const SpeedRow* reference, double Timing::*which)
{
  return reference && reference->Time.*which > 0.0
    ? FormatNumber(value / (reference->Time.*which))
    : std::string("n/a");
}

/// The rendering thread's CPU time per prop beyond no shadows', in
/// microseconds: the median over the rounds of the difference within each.
std::string CpuPerProp(
  const SpeedRow& row, const SpeedRow* none, std::vector<double> Timing::*perRound)
{
  const std::vector<double>& mine = row.Time.*perRound;
  if (!none || row.Props <= 0 || mine.size() != (none->Time.*perRound).size() || mine.empty())
  {
    return "n/a";
  }
  std::vector<double> differences;
  for (std::size_t i = 0; i < mine.size(); ++i)
  {
    differences.push_back(mine[i] - (none->Time.*perRound)[i]);
  }
  return FormatNumber(1e6 * Median(differences) / row.Props, 2);
}

std::string CallCounts(const GLCallCounts& calls)
{
  return std::to_string(calls.Draws) + " / " + std::to_string(calls.UniformSets) + " / " +
    std::to_string(calls.All());
}

/// The pass's milliseconds per moving frame in each frame step, "a / b / ...".
std::string FrameStepsText(const MovingCounts& counts)
{
  std::string text;
  for (double milliseconds : counts.StepMillisecondsPerFrame)
  {
    text += (text.empty() ? "" : " / ") + FormatNumber(milliseconds, 1);
  }
  return text;
}

void PrintSpeedTable(const std::vector<SpeedRow>& rows, std::ostream& out)
{
  out << "| scene | light | map | technique | first ms | steady ms | moving ms | moving mean ms "
         "| moving / steady | steady / none | moving / none | moving / vtk | moving mean / vtk "
         "| shaders built in 8 moving frames | layers per moving frame "
         "| caster draws per moving frame | steady CPU µs per prop over none | moving CPU µs per prop over none "
         "| steady GL draws / uniform sets / counted calls "
         "| pass ms per moving frame: reading / fitting / storage / shaders / drawing / finishing |\n"
         "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const SpeedRow& row : rows)
  {
    const SpeedRow* none = Reference(rows, row, "none");
    const SpeedRow* vtk = Reference(rows, row, "vtk");
    out << "| " << row.Scene << " | " << row.Setup << " | " << row.Resolution << " | "
        << row.Technique << " | " << FormatNumber(1000.0 * row.Time.First, 1) << " | "
        << FormatNumber(1000.0 * row.Time.Steady, 1) << " | "
        << FormatNumber(1000.0 * row.Time.Moving, 1) << " | "
        << FormatNumber(1000.0 * row.Time.MovingMean, 1) << " | "
        << FormatNumber(row.Time.Moving / row.Time.Steady) << " | "
        << Ratio(row.Time.Steady, none, &Timing::Steady) << " | "
        << Ratio(row.Time.Moving, none, &Timing::Moving) << " | "
        << Ratio(row.Time.Moving, vtk, &Timing::Moving) << " | "
        << Ratio(row.Time.MovingMean, vtk, &Timing::MovingMean) << " | "
        << (row.Counts.ShaderBuilds < 0 ? std::string("") : std::to_string(row.Counts.ShaderBuilds))
        << " | "
        << (row.Counts.Layers < 0 ? std::string("")
                                  : FormatNumber(row.Counts.LayersPerFrame, 2) + " of " +
               std::to_string(row.Counts.Layers))
        << " | "
        << (row.Counts.CasterDrawsPerFrame < 0 ? std::string("")
                                               : FormatNumber(row.Counts.CasterDrawsPerFrame, 1))
        << " | " << CpuPerProp(row, none, &Timing::SteadyMainThreadCpuPerRound) << " | "
        << CpuPerProp(row, none, &Timing::MovingMainThreadCpuPerRound) << " | "
        << CallCounts(row.SteadyCalls) << " | " << FrameStepsText(row.Counts) << " |\n";
  }
}

void WriteSpeedCSV(const std::vector<SpeedRow>& rows, const std::string& path)
{
  std::ofstream csv(path);
  csv << "scene,setup,resolution,technique,first_s,steady_s,moving_s,moving_mean_s,"
         "shader_builds_in_8_moving_frames,layers_per_moving_frame,layers,props,"
         "steady_main_thread_cpu_s,moving_main_thread_cpu_s,steady_gl_draws,"
         "steady_gl_uniform_sets,steady_gl_counted_calls,caster_draws_per_moving_frame";
  for (const char* frame : { "moving_", "first_" })
  {
    for (int step = 0; step < vtkAbstractShadowMapPass::NUMBER_OF_FRAME_STEPS; ++step)
    {
      csv << ',' << frame << vtkAbstractShadowMapPass::GetFrameStepName(step) << "_ms";
    }
  }
  csv << '\n';
  csv << std::setprecision(6);
  for (const SpeedRow& row : rows)
  {
    csv << row.Scene << ',' << row.Setup << ',' << row.Resolution << ',' << row.Technique << ','
        << row.Time.First << ',' << row.Time.Steady << ',' << row.Time.Moving << ','
        << row.Time.MovingMean << ',' << row.Counts.ShaderBuilds << ',' << row.Counts.LayersPerFrame << ','
        << row.Counts.Layers << ',' << row.Props << ',' << row.Time.SteadyMainThreadCpu << ','
        << row.Time.MovingMainThreadCpu << ',' << row.SteadyCalls.Draws << ','
        << row.SteadyCalls.UniformSets << ',' << row.SteadyCalls.All() << ','
        << row.Counts.CasterDrawsPerFrame;
    for (const std::vector<double>* steps :
      { &row.Counts.StepMillisecondsPerFrame, &row.Time.FirstStepMilliseconds })
    {
      for (int step = 0; step < vtkAbstractShadowMapPass::NUMBER_OF_FRAME_STEPS; ++step)
      {
        csv << ',' << (steps->empty() ? -1.0 : (*steps)[static_cast<std::size_t>(step)]);
      }
    }
    csv << '\n';
  }
}

/// Every timed frame: which frames of a motion cost what, and whether they
/// rendered layers.
void WriteFramesCSV(const std::vector<SpeedRow>& rows, const std::string& path)
{
  std::ofstream csv(path);
  csv << "scene,setup,resolution,technique,frames,index,wall_s,main_thread_cpu_s,layers,"
         "caster_draws\n";
  csv << std::setprecision(6);
  const auto write = [&](const SpeedRow& row, const char* kind,
                       const std::vector<FrameTime>& frames) {
    for (std::size_t i = 0; i < frames.size(); ++i)
    {
      csv << row.Scene << ',' << row.Setup << ',' << row.Resolution << ',' << row.Technique << ','
          << kind << ',' << i << ',' << frames[i].Wall << ',' << frames[i].MainThreadCpu << ','
          << frames[i].Layers << ',' << frames[i].CasterDraws << '\n';
    }
  };
  for (const SpeedRow& row : rows)
  {
    write(row, "steady", row.Time.SteadyFrames);
    write(row, "moving", row.Time.MovingFrames);
  }
}

} // namespace

//------------------------------------------------------------------------------
bool RunSpeed(const SpeedOptions& options, std::ostream& out, std::ostream& log, std::string& error)
{
  if (!ValidateSpeedOptions(options, error))
  {
    return false;
  }
  std::vector<SpeedRow> rows;
  for (const std::string& scene : options.Scenes)
  {
    SpeedView view;
    if (!BuildSpeedView(view, scene, options, error))
    {
      return false;
    }
    log << scene << ": " << CountProps(view.Renderer) << " actors" << std::endl;
    if (rows.empty())
    {
      view.Window->Render();
      log << "GL renderer: " << GLRendererName() << std::endl;
    }
    for (const std::string& setup : options.Setups)
    {
      for (const int resolution : options.Resolutions)
      {
        log << "  " << scene << " / " << setup << " / " << resolution << std::endl;
        view.Renderer->GetActiveCamera()->DeepCopy(view.Initial);
        shadowscenes::AddLightSetup(view.Renderer, setup);
        MeasureCase(view, scene, setup, resolution, options, rows);
      }
    }
  }
  std::ostringstream table;
  PrintSpeedTable(rows, table);
  out << table.str();
  std::ofstream(options.OutputDirectory + "/speed.md") << table.str();
  WriteSpeedCSV(rows, options.OutputDirectory + "/speed.csv");
  WriteFramesCSV(rows, options.OutputDirectory + "/frames.csv");
  return true;
}

} // namespace shadowbench
