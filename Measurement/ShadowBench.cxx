#include "ShadowBench.h"

#include "ShadowFrameTimes.h"
#include "ShadowMetrics.h"
#include "ShadowOracle.h"
#include "ShadowProgress.h"
#include "ShadowRecommendation.h"

#include "vtkAutomaticShadowMapPass.h"
#include "ShadowScenes.h"
#include "ShadowTechniques.h"

#include "vtkAbstractShadowMapPass.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkWarpedShadowMapPass.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkAxis.h>
#include <vtkCamera.h>
#include <vtkCameraPass.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPNGWriter.h>
#include <vtkPlot.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderPassCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSequencePass.h>
#include <vtkShadowMapBakerPass.h>
#include <vtkShadowMapPass.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace shadowbench
{
namespace
{
using shadoworacle::Truth;
const double NotMeasured = std::numeric_limits<double>::quiet_NaN();

// --- techniques -------------------------------------------------------------------

// --- rendering and capture --------------------------------------------------------

struct View
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkCamera> InitialCamera;
  int Width = 0;
  int Height = 0;
};

/// The truth of the current view: primary rays, masked where the rasteriser
/// disagrees or `plain` (the frame without shadows) is black, then one shadow
/// ray per pixel; for a sized light, its
/// visibility (into `visibilityOut`, left empty for a light without a size)
/// thresholded at one half.
std::vector<Truth> TruthOfView(View& view, const shadoworacle::Oracle& oracle,
  const std::vector<std::uint8_t>& plain, shadoworacle::Surface* surfaceOut = nullptr,
  std::vector<float>* visibilityOut = nullptr)
{
  shadoworacle::Surface surface =
    VisibleSurface(oracle, view.Renderer, view.Window, view.Width, view.Height, plain);
  vtkLight* light = FirstLight(view.Renderer);
  std::vector<Truth> truth;
  std::vector<float> visibility;
  if (vtkAbstractShadowMapPass::GetLightSize(light) > 0.0)
  {
    visibility = oracle.Visibility(surface, light);
    truth = shadowmetrics::TruthAtHalf(visibility);
  }
  else
  {
    truth = oracle.Classify(surface, light);
  }
  if (surfaceOut)
  {
    *surfaceOut = std::move(surface);
  }
  if (visibilityOut)
  {
    *visibilityOut = std::move(visibility);
  }
  return truth;
}

/// How a technique's texels fall on the screen: the percentage of pixels
/// undersampled and the spread of texel footprints (ShadowMetrics.h).
struct Sampling
{
  double Undersampled = NotMeasured;
  double Spread = NotMeasured;
};

Sampling SamplingOf(const std::vector<double>& footprints, const std::vector<std::uint8_t>& valid)
{
  return { shadowmetrics::UndersampledFromFootprints(footprints, valid),
    shadowmetrics::FootprintSpread(footprints) };
}

/// Sampling of VTK's pass, from its light camera: the map texel coordinates
/// of every pixel's surface point, differentiated across pixels.
Sampling VTKSampling(const TechniqueInstance& technique, const shadoworacle::Surface& surface)
{
  auto* cameras = technique.VTK->GetShadowMapBakerPass()->GetLightCameras();
  if (!cameras || cameras->empty() || !(*cameras)[0])
  {
    return {};
  }
  vtkMatrix4x4* m = (*cameras)[0]->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0);
  std::vector<glm::dvec2> texel(surface.Position.size());
  std::vector<std::uint8_t> valid = surface.Valid;
  for (size_t i = 0; i < texel.size(); ++i)
  {
    const glm::dvec3& p = surface.Position[i];
    double clip[4];
    for (int r = 0; r < 4; ++r)
    {
      clip[r] = m->GetElement(r, 0) * p.x + m->GetElement(r, 1) * p.y + m->GetElement(r, 2) * p.z +
        m->GetElement(r, 3);
    }
    if (!valid[i] || clip[3] <= 0.0)
    {
      valid[i] = valid[i] && clip[3] > 0.0;
      continue;
    }
    texel[i] = (glm::dvec2(clip[0], clip[1]) / clip[3] * 0.5 + 0.5) * double(technique.Resolution);
  }
  return SamplingOf(
    shadowmetrics::TexelFootprints(texel, valid, surface.Width, surface.Height), surface.Valid);
}

Sampling OurSampling(View& view, const TechniqueInstance& technique,
  const std::vector<std::uint8_t>& valid)
{
  technique.Ours->SetAnalysisView(vtkAbstractShadowMapPass::TEXEL_DENSITY);
  view.Window->Render();
  const auto rgb = CaptureRGB(view.Window);
  technique.Ours->SetAnalysisView(vtkAbstractShadowMapPass::NO_ANALYSIS);
  return { shadowmetrics::UndersampledFromAnalysis(rgb, valid),
    shadowmetrics::FootprintSpread(shadowmetrics::FootprintsFromAnalysis(rgb, valid)) };
}

// --- one case ---------------------------------------------------------------------

struct Row
{
  std::string Scene;
  std::string Setup;
  std::string Technique;
  std::string PassClass; // this module's techniques only
  int Resolution = 0;
  double MemoryMiB = 0.0;
  /// Sized lights' truth thresholded at one half, as the factor is.
  shadowmetrics::Classification Errors;
  /// Sized lights only: the factor against the fractional visibility.
  bool Sized = false;
  shadowmetrics::VisibilityErrors Visibility;
  /// Scenes with translucent casters: the factor per channel against the
  /// transmittance.
  bool Translucent = false;
  shadowmetrics::TransmittanceErrors Transmittance;
  /// Light leaks where the truth's shadow ray meets two or more occluders (%).
  double Bleeding = NotMeasured;
  double Undersampled = NotMeasured;
  /// Octaves between the 10th and 90th percentile texel footprints.
  double DensitySpread = NotMeasured;
  double Flicker = NotMeasured;
  double Changes = NotMeasured;
  double TruthChanges = NotMeasured;
  /// The automatic pass: what it chose for the set-up's light ("" otherwise).
  std::string Choice;
  Timing Time;
};

void SetPathFrame(View& view, int frame, int frames)
{
  shadowscenes::SetCameraPathFrame(view.InitialCamera, view.Renderer->GetActiveCamera(), frame, frames);
}

/// Frame times of every technique (ShadowFrameTimes.h) along the start of the
/// benchmark's camera path, which moves the maps every frame.
std::vector<Timing> MeasureFrameTimes(
  View& view, const std::vector<TechniqueInstance>& techniques, int frames)
{
  std::vector<vtkRenderPass*> passes;
  for (const TechniqueInstance& technique : techniques)
  {
    passes.push_back(technique.Pass);
  }
  // The path's first frames: a quarter of it over all rounds.
  return shadowbench::MeasureFrameTimes(view.Window, view.Renderer, passes, frames,
    [&view](int frame, int count) { SetPathFrame(view, frame, 4 * count); });
}

// --- progress -----------------------------------------------------------------------
//
// Work is counted in frames rendered, roughly (measured on a 110,000-triangle
// model): the oracle's truth of a view with the plain render costs about
// eight, measuring a technique about four (a render, the texel density's, the
// classification and its error map), and a technique's frame of the flicker
// path two (a render and its capture).
constexpr int TruthFrames = 8;
constexpr int CaseFrames = 4;
constexpr int FlickerFrames = 2;

bool Flickers(const Options& options, const std::string& setup)
{
  return options.FlickerFrames > 1 &&
    std::find(options.FlickerSetups.begin(), options.FlickerSetups.end(), setup) !=
    options.FlickerSetups.end();
}

double TimingFrames(const Options& options)
{
  return 3.0 * (3.0 + 2.0 * options.TimedFrames); // MeasureFrameTimes' rounds and frames
}

double SetupWork(const Options& options, const std::string& setup)
{
  const double techniques = static_cast<double>(options.Techniques.size());
  double work = TruthFrames + techniques * (TimingFrames(options) + CaseFrames);
  if (Flickers(options, setup))
  {
    work += options.FlickerFrames * (FlickerFrames * techniques + TruthFrames);
  }
  return work;
}

/// Each scene measured, in order, with its set-ups.
using ScenePlan = std::vector<std::pair<std::string, std::vector<std::string>>>;

ScenePlan PlanOf(const Options& options)
{
  ScenePlan plan;
  if (!options.ModelFile.empty())
  {
    return { { "file", options.Setups } };
  }
  if (options.Cases.empty())
  {
    for (const std::string& scene : options.Scenes)
    {
      plan.emplace_back(scene, options.Setups);
    }
    return plan;
  }
  for (const auto& [scene, setup] : options.Cases)
  {
    auto planned = std::find_if(
      plan.begin(), plan.end(), [&](const auto& entry) { return entry.first == scene; });
    if (planned == plan.end())
    {
      planned = plan.insert(plan.end(), { scene, {} });
    }
    planned->second.push_back(setup);
  }
  return plan;
}

double TotalWork(const Options& options, const ScenePlan& plan)
{
  double work = 0.0;
  for (const auto& scene : plan)
  {
    for (const std::string& setup : scene.second)
    {
      work += SetupWork(options, setup);
    }
  }
  return work;
}

/// Flicker along the camera path: the mean over frame pairs of the pixels
/// whose state changed while the truth did not.
void MeasureFlicker(View& view, const shadoworacle::Oracle& oracle,
  std::vector<TechniqueInstance>& techniques, std::vector<Row>& rows, int frames, double yaw,
  Progress& progress, std::ostream& log)
{
  // The automatic pass's views of its first light along the path, as runs.
  std::vector<std::vector<std::pair<std::string, int>>> chosen(techniques.size());
  std::vector<std::vector<float>> previousFactor(techniques.size());
  std::vector<Truth> previousTruth;
  std::vector<double> flicker(techniques.size(), 0.0);
  std::vector<double> changes(techniques.size(), 0.0);
  double truthChanges = 0.0;
  for (int frame = 0; frame < frames; ++frame)
  {
    shadowscenes::SetCameraPathFrame(
      view.InitialCamera, view.Renderer->GetActiveCamera(), frame, frames, yaw);
    view.Renderer->SetPass(nullptr);
    view.Window->Render();
    const auto plain = CaptureRGB(view.Window);
    const auto truth = TruthOfView(view, oracle, plain);
    for (size_t t = 0; t < techniques.size(); ++t)
    {
      view.Renderer->SetPass(techniques[t].Pass);
      view.Window->Render();
      auto factor = shadowmetrics::FactorFromRenders(
        CaptureRGB(view.Window), plain, view.Width * view.Height);
      if (auto* automatic = vtkAutomaticShadowMapPass::SafeDownCast(techniques[t].Ours))
      {
        const std::string views = automatic->GetChosenViewsName(0);
        if (chosen[t].empty() || chosen[t].back().first != views)
        {
          chosen[t].emplace_back(views, frame);
        }
      }
      if (frame > 0)
      {
        flicker[t] += shadowmetrics::Flicker(previousTruth, previousFactor[t], truth, factor);
        changes[t] += shadowmetrics::StateChanges(previousTruth, previousFactor[t], truth, factor);
      }
      previousFactor[t] = std::move(factor);
    }
    if (frame > 0)
    {
      truthChanges += shadowmetrics::TruthChanges(previousTruth, truth);
    }
    previousTruth = truth;
    progress.Advance(static_cast<double>(FlickerFrames * techniques.size() + TruthFrames));
  }
  for (size_t t = 0; t < techniques.size(); ++t)
  {
    for (const auto& run : chosen[t])
    {
      log << "    " << rows[rows.size() - techniques.size() + t].Technique << ": " << run.first
          << " views from path frame " << run.second << std::endl;
    }
    rows[rows.size() - techniques.size() + t].Flicker = flicker[t] / (frames - 1);
    rows[rows.size() - techniques.size() + t].Changes = changes[t] / (frames - 1);
    rows[rows.size() - techniques.size() + t].TruthChanges = truthChanges / (frames - 1);
  }
  view.Renderer->SetPass(nullptr);
  SetPathFrame(view, 0, 2);
}

void WriteChart(const std::vector<Row>& rows, const std::string& path, const std::string& title);

void WriteShownFrame(const std::vector<std::uint8_t>& rgb, const std::vector<std::uint8_t>& plain,
  const View& view, const std::string& path, std::ostream& log)
{
  if (!WritePNG(shadowmetrics::ShownFrame(rgb, plain), view.Width, view.Height, path))
  {
    log << "  cannot write " << path << std::endl;
  }
}

bool RunSetup(View& view, const shadoworacle::Oracle& oracle, const std::string& scene,
  const std::string& setup, const Options& options, std::vector<Row>& rows, std::ostream& log,
  Progress& progress)
{
  view.Renderer->GetActiveCamera()->DeepCopy(view.InitialCamera);
  shadowscenes::AddLightSetup(view.Renderer, setup);
  view.Renderer->SetPass(nullptr);
  view.Window->Render();
  const auto plain = CaptureRGB(view.Window);
  shadoworacle::Surface surface;
  std::vector<float> visibility;
  const auto truth = TruthOfView(view, oracle, plain, &surface, &visibility);
  const std::vector<std::uint8_t>& valid = surface.Valid;
  const std::vector<unsigned char> occluders =
    oracle.CountOccluders(surface, FirstLight(view.Renderer), truth);
  const std::vector<glm::vec3> transmittance = oracle.GetNumberOfTranslucentTriangles() + oracle.GetNumberOfVolumes() > 0
    ? oracle.Transmittance(surface, FirstLight(view.Renderer))
    : std::vector<glm::vec3>();
  progress.Advance(TruthFrames);
  const std::string casePath = options.OutputDirectory + "/" + CaseName(scene, setup);
  if (options.WriteFrames)
  {
    WriteShownFrame(shadowmetrics::TruthFrame(plain, truth, visibility, transmittance), plain,
      view, casePath + "-truth.png", log);
  }

  std::vector<TechniqueInstance> techniques;
  for (const std::string& name : options.Techniques)
  {
    techniques.push_back(MakeTechnique(name, shadowscenes::LightKindOfSetup(setup) == "point", options.Resolution));
  }
  log << progress.Line() << "  " << scene << " / " << setup << ": frame times" << std::endl;
  const std::vector<Timing> timing = MeasureFrameTimes(view, techniques, options.TimedFrames);
  progress.Advance(TimingFrames(options) * static_cast<double>(techniques.size()));
  const size_t firstRow = rows.size();
  for (size_t t = 0; t < techniques.size(); ++t)
  {
    const std::string& name = options.Techniques[t];
    const TechniqueInstance& technique = techniques[t];
    log << progress.Line() << "  " << scene << " / " << setup << " / " << name << std::endl;
    view.Renderer->SetPass(technique.Pass);
    Row row;
    row.Scene = scene;
    row.Setup = setup;
    row.Technique = name;
    row.PassClass = technique.Ours ? technique.Ours->GetClassName() : "";
    row.Resolution = technique.Resolution;
    row.Time = timing[t];
    view.Window->Render();
    const auto rgb = CaptureRGB(view.Window);
    if (auto* automatic = vtkAutomaticShadowMapPass::SafeDownCast(technique.Ours))
    {
      row.Choice = std::string(automatic->GetChosenViewsName(0)) + " views, " +
        automatic->GetChosenRepresentationName(0);
    }
    const auto factor = shadowmetrics::FactorFromRenders(rgb, plain, view.Width * view.Height);
    row.Translucent = !transmittance.empty();
    if (row.Translucent)
    {
      row.Transmittance = shadowmetrics::CompareTransmittance(transmittance,
        shadowmetrics::ChannelFactorsFromRenders(rgb, plain, view.Width * view.Height),
        surface.SeenThroughTranslucent);
    }
    row.Errors = shadowmetrics::Classify(truth, factor, view.Width, view.Height);
    row.Bleeding = shadowmetrics::LeakBehindSeveral(occluders, factor);
    row.Sized = !visibility.empty();
    if (row.Sized)
    {
      row.Visibility = shadowmetrics::CompareVisibility(
        visibility, factor, occluders, view.Width, view.Height);
    }
    row.MemoryMiB = MemoryMiB(technique);
    const Sampling sampling = technique.Ours ? OurSampling(view, technique, valid)
      : technique.VTK                        ? VTKSampling(technique, surface)
                                             : Sampling{};
    row.Undersampled = sampling.Undersampled;
    row.DensitySpread = sampling.Spread;
    if (options.WriteFrames)
    {
      WriteShownFrame(rgb, plain, view, casePath + "-" + name + "-frame.png", log);
    }
    const std::string errors = casePath + "-" + name + "-errors.png";
    const auto errorMap = row.Translucent
      ? shadowmetrics::VisibilityErrorMap(
          shadowmetrics::MeanOfChannels(transmittance, surface.SeenThroughTranslucent), factor)
      : row.Sized ? shadowmetrics::VisibilityErrorMap(visibility, factor)
                  : shadowmetrics::ErrorMap(truth, factor);
    if (!WritePNG(errorMap, view.Width, view.Height, errors))
    {
      log << "  cannot write " << errors << std::endl;
    }
    rows.push_back(row);
    progress.Advance(CaseFrames);
  }
  if (Flickers(options, setup))
  {
    log << progress.Line() << "  " << scene << " / " << setup << ": flicker over "
        << options.FlickerFrames << " frames" << std::endl;
    MeasureFlicker(view, oracle, techniques, rows, options.FlickerFrames,
      options.FlickerYawDegrees, progress, log);
  }
  view.Renderer->SetPass(nullptr);
  for (TechniqueInstance& technique : techniques)
  {
    // VTK's baker pass complains if destroyed with its GL objects alive.
    if (technique.Pass)
    {
      technique.Pass->ReleaseGraphicsResources(view.Window);
    }
  }
  WriteChart(std::vector<Row>(rows.begin() + firstRow, rows.end()),
    options.OutputDirectory + "/" + CaseName(scene, setup) + "-chart.png",
    scene + ", " + setup + " light");
  return true;
}

bool BuildScene(View& view, const std::string& scene, const Options& options, std::ostream& log,
  std::string& error)
{
  if (options.ModelFile.empty())
  {
    if (!shadowscenes::BuildSceneByName(view.Renderer, scene, error))
    {
      return false;
    }
  }
  else
  {
    shadowscenes::ModelUp up;
    if (!shadowscenes::BuildFileScene(view.Renderer, options.ModelFile, options.Up, up, error))
    {
      return false;
    }
    log << shadowscenes::DescribeModelUp(up) << std::endl;
  }
  UseMeasurementMaterials(view.Renderer);
  view.InitialCamera->DeepCopy(view.Renderer->GetActiveCamera());
  view.Window->SetOffScreenRendering(1);
  view.Window->SetMultiSamples(0);
  view.Window->SetSize(view.Width, view.Height);
  view.Window->AddRenderer(view.Renderer);
  return true;
}

// --- output ------------------------------------------------------------------------

/// Frame time of `row` divided by that of technique `reference` in the same case.
double Ratio(const std::vector<Row>& rows, const Row& row, const std::string& reference,
  double Timing::*which)
{
  for (const Row& other : rows)
  {
    if (other.Scene == row.Scene && other.Setup == row.Setup && other.Technique == reference)
    {
      return other.Time.*which > 0.0 ? row.Time.*which / (other.Time.*which) : NotMeasured;
    }
  }
  return NotMeasured;
}

/// What the automatic pass chose in each set-up, beside its error and the most
/// accurate technique's of the same set-up.
void PrintAutomaticChoices(const std::vector<Row>& rows, std::ostream& out)
{
  bool header = false;
  for (const Row& row : rows)
  {
    if (row.Choice.empty())
    {
      continue;
    }
    const Row* best = nullptr;
    for (const Row& other : rows)
    {
      if (other.Scene == row.Scene && other.Setup == row.Setup && !other.PassClass.empty() &&
        (!best || other.Errors.Misclassified < best->Errors.Misclassified))
      {
        best = &other;
      }
    }
    if (!header)
    {
      out << "\nThe automatic pass's choices (vtkAutomaticShadowMapPass):\n\n| scene | light | "
             "chosen | misclassified % | most accurate measured | its misclassified % |\n"
             "|---|---|---|---:|---|---:|\n";
      header = true;
    }
    out << "| " << row.Scene << " | " << row.Setup << " | " << row.Choice << " | "
        << FormatNumber(row.Errors.Misclassified) << " | " << best->Technique << " | "
        << FormatNumber(best->Errors.Misclassified) << " |\n";
  }
}

void PrintTable(const std::vector<Row>& rows, std::ostream& out)
{
  out << "| scene | light | technique | map | MiB | misclassified % | false shadow % | leak % | "
         "bleeding % | inner % | mean abs. diff. | undersampled % | density spread | flicker % | "
         "changes % (truth %) | "
         "first frame / none | "
         "steady / none | steady / vtk | moving / none | moving / vtk |\n"
      << "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Row& row : rows)
  {
    out << "| " << row.Scene << " | " << row.Setup << " | " << row.Technique << " | "
        << (row.Resolution > 0 ? std::to_string(row.Resolution) + "²" : "-") << " | "
        << FormatNumber(row.MemoryMiB, 1) << " | " << FormatNumber(row.Errors.Misclassified) << " | "
        << FormatNumber(row.Errors.FalseShadow) << " | " << FormatNumber(row.Errors.LightLeak) << " | "
        << FormatNumber(row.Bleeding) << " | " << FormatNumber(row.Errors.InnerMisclassified) << " | "
        << FormatNumber(row.Errors.MeanAbsoluteDifference, 3) << " | " << FormatNumber(row.Undersampled)
        << " | " << FormatNumber(row.DensitySpread) << " | "
        << (std::isnan(row.Flicker) ? std::string("-") : FormatNumber(row.Flicker, 3)) << " | "
        << (std::isnan(row.Changes)
               ? std::string("-")
               : FormatNumber(row.Changes, 3) + " (" + FormatNumber(row.TruthChanges, 3) + ")")
        << " | " << FormatNumber(Ratio(rows, row, "none", &Timing::First)) << " | "
        << FormatNumber(Ratio(rows, row, "none", &Timing::Steady)) << " | "
        << FormatNumber(Ratio(rows, row, "vtk", &Timing::Steady)) << " | "
        << FormatNumber(Ratio(rows, row, "none", &Timing::Moving)) << " | "
        << FormatNumber(Ratio(rows, row, "vtk", &Timing::Moving)) << " |\n";
  }
}

/// The sized lights' table: the factor against the fractional visibility.
void PrintSizedTable(const std::vector<Row>& rows, std::ostream& out)
{
  if (std::none_of(rows.begin(), rows.end(), [](const Row& row) { return row.Sized; }))
  {
    return;
  }
  out << "\nSized lights: the shadow factor against the ray-traced fraction of the light that "
         "reaches each pixel\n\n"
      << "| scene | light | technique | visibility error: mean | 95th percentile | "
         "misclassified at 0.5 % | umbra pure % | inner umbra pure % | behind several % | "
         "lit pure % |\n"
      << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Row& row : rows)
  {
    if (!row.Sized)
    {
      continue;
    }
    const shadowmetrics::VisibilityErrors& v = row.Visibility;
    out << "| " << row.Scene << " | " << row.Setup << " | " << row.Technique << " | "
        << FormatNumber(v.MeanAbsolute, 4) << " | " << FormatNumber(v.Percentile95, 3) << " | "
        << FormatNumber(v.AtHalf.Misclassified) << " | " << FormatNumber(v.UmbraPure, 1) << " | "
        << FormatNumber(v.UmbraInnerPure, 1) << " | " << FormatNumber(v.UmbraBehindSeveralPure, 1) << " | " << FormatNumber(v.LitPure, 1)
        << " |\n";
  }
}

/// Scenes with translucent casters: the factor per channel against the
/// ray-traced transmittance.
void PrintTranslucentTable(const std::vector<Row>& rows, std::ostream& out)
{
  if (std::none_of(rows.begin(), rows.end(), [](const Row& row) { return row.Translucent; }))
  {
    return;
  }
  out << "\nTranslucent casters: the shadow factor per channel against the ray-traced "
         "transmittance (pixels seen through a translucent surface left out)\n\n"
      << "| scene | light | technique | mean error r | g | b | 95th percentile | "
         "partial pixels | their mean error r | g | b |\n"
      << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Row& row : rows)
  {
    if (!row.Translucent)
    {
      continue;
    }
    const shadowmetrics::TransmittanceErrors& t = row.Transmittance;
    out << "| " << row.Scene << " | " << row.Setup << " | " << row.Technique << " | "
        << FormatNumber(t.MeanAbsolute.x, 4) << " | " << FormatNumber(t.MeanAbsolute.y, 4) << " | "
        << FormatNumber(t.MeanAbsolute.z, 4) << " | " << FormatNumber(t.Percentile95, 3) << " | "
        << t.Partial << " | " << FormatNumber(t.PartialMeanAbsolute.x, 4) << " | "
        << FormatNumber(t.PartialMeanAbsolute.y, 4) << " | "
        << FormatNumber(t.PartialMeanAbsolute.z, 4) << " |\n";
  }
}

std::vector<Recommendation> RecommendationsOf(const std::vector<Row>& rows)
{
  std::vector<MeasuredCase> cases;
  for (const Row& row : rows)
  {
    cases.push_back({ row.Scene, row.Setup, row.Technique, row.PassClass, row.Resolution,
      row.Errors.Misclassified, row.Time.Steady, row.Time.Moving,
      static_cast<long long>(row.Errors.Counted) });
  }
  return Recommend(cases, RecommendationBudget);
}

void WriteCSV(const std::vector<Row>& rows, const std::string& path)
{
  std::ofstream csv(path);
  csv << "scene,light,technique,resolution,memory_mib,misclassified,false_shadow,leak,bleeding,inner,"
         "mean_abs_diff,undersampled,density_spread,flicker,changes,truth_changes,first_s,steady_s,moving_s,counted_pixels,"
         "visibility_mean_error,visibility_p95_error,umbra_pure,umbra_inner_pure,umbra_behind_several_pure,lit_pure,"
         "umbra_pixels,umbra_inner_pixels,"
         "transmittance_mean_error_r,transmittance_mean_error_g,transmittance_mean_error_b,"
         "transmittance_p95_error,transmittance_partial_pixels,transmittance_partial_error_r,"
         "transmittance_partial_error_g,transmittance_partial_error_b\n";
  // Enough digits for the recommendation to be recomputed from the file.
  csv << std::setprecision(12);
  for (const Row& row : rows)
  {
    csv << row.Scene << ',' << row.Setup << ',' << row.Technique << ',' << row.Resolution << ','
        << row.MemoryMiB << ',' << row.Errors.Misclassified << ',' << row.Errors.FalseShadow << ','
        << row.Errors.LightLeak << ',' << row.Bleeding << ',' << row.Errors.InnerMisclassified << ','
        << row.Errors.MeanAbsoluteDifference << ',' << row.Undersampled << ',' << row.DensitySpread << ',' << row.Flicker << ','
        << row.Changes << ',' << row.TruthChanges << ',' << row.Time.First << ',' << row.Time.Steady << ','
        << row.Time.Moving << ',' << row.Errors.Counted << ',';
    const shadowmetrics::VisibilityErrors& v = row.Visibility;
    if (row.Sized)
    {
      csv << v.MeanAbsolute << ',' << v.Percentile95 << ',' << v.UmbraPure << ','
          << v.UmbraInnerPure << ',' << v.UmbraBehindSeveralPure << ',' << v.LitPure << ','
          << v.Umbra << ',' << v.UmbraInner << ',';
    }
    else
    {
      csv << "nan,nan,nan,nan,nan,nan,nan,nan,";
    }
    const shadowmetrics::TransmittanceErrors& t = row.Transmittance;
    if (row.Translucent)
    {
      csv << t.MeanAbsolute.x << ',' << t.MeanAbsolute.y << ',' << t.MeanAbsolute.z << ','
          << t.Percentile95 << ',' << t.Partial << ',' << t.PartialMeanAbsolute.x << ','
          << t.PartialMeanAbsolute.y << ',' << t.PartialMeanAbsolute.z << '\n';
    }
    else
    {
      csv << "nan,nan,nan,nan,nan,nan,nan,nan\n";
    }
  }
}

/// Bars per technique: misclassified, inner misclassified, undersampled (%).
void WriteChart(const std::vector<Row>& rows, const std::string& path, const std::string& title)
{
  vtkNew<vtkTable> table;
  vtkNew<vtkDoubleArray> index;
  index->SetName("technique");
  table->AddColumn(index);
  const char* names[] = { "misclassified %", "inner misclassified %", "undersampled %" };
  for (const char* name : names)
  {
    vtkNew<vtkDoubleArray> column;
    column->SetName(name);
    table->AddColumn(column);
  }
  table->SetNumberOfRows(static_cast<vtkIdType>(rows.size()));
  vtkNew<vtkDoubleArray> ticks;
  vtkNew<vtkStringArray> labels;
  for (size_t i = 0; i < rows.size(); ++i)
  {
    const double values[] = { static_cast<double>(i), rows[i].Errors.Misclassified,
      rows[i].Errors.InnerMisclassified,
      std::isnan(rows[i].Undersampled) ? 0.0 : rows[i].Undersampled };
    for (int c = 0; c < 4; ++c)
    {
      table->SetValue(static_cast<vtkIdType>(i), c, values[c]);
    }
    ticks->InsertNextValue(static_cast<double>(i));
    labels->InsertNextValue(rows[i].Technique);
  }
  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(800, 450);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(title);
  chart->SetShowLegend(true);
  chart->SetBarWidthFraction(0.8f);
  const unsigned char colors[3][3] = { { 200, 60, 50 }, { 240, 150, 40 }, { 60, 110, 200 } };
  for (int c = 0; c < 3; ++c)
  {
    vtkPlot* bars = chart->AddPlot(vtkChart::BAR);
    bars->SetInputData(table, 0, c + 1);
    bars->SetColor(colors[c][0], colors[c][1], colors[c][2], 255);
  }
  chart->GetAxis(vtkAxis::BOTTOM)->SetCustomTickPositions(ticks, labels);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("");
  chart->GetAxis(vtkAxis::LEFT)->SetTitle("% of pixels");
  view->GetRenderWindow()->Render();
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(view->GetRenderWindow());
  capture->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(capture->GetOutputPort());
  writer->Write();
}

bool ValidateOptions(const Options& options, std::string& error)
{
  std::vector<std::string> setups;
  for (const auto& scene : PlanOf(options))
  {
    setups.insert(setups.end(), scene.second.begin(), scene.second.end());
  }
  if (!CheckTechniquesAndSetups(options.Techniques, setups, error))
  {
    return false;
  }
  if (options.Scenes.empty() && options.Cases.empty() && options.ModelFile.empty())
  {
    error = "no scene to measure";
    return false;
  }
  return MakeOutputDirectory(options.OutputDirectory, error);
}

/// Frame times are ratios to "none" and "vtk": measure them even if not asked.
Options WithReferences(Options options)
{
  options.Techniques = WithReferenceTechniques(options.Techniques);
  return options;
}
} // namespace

//------------------------------------------------------------------------------
std::string CaseName(const std::string& scene, const std::string& setup)
{
  return scene + "-" + setup;
}

//------------------------------------------------------------------------------
Options DefaultOptions()
{
  Options options;
  options.Scenes = shadowscenes::BenchmarkSceneNames();
  options.Setups = shadowscenes::LightSetupNames();
  options.Techniques = DefaultTechniqueNames();
  options.FlickerSetups = { "perpendicular" };
  return options;
}

//------------------------------------------------------------------------------
Options QuickAnalyzeOptions()
{
  Options options = DefaultOptions();
  options.Setups = { "perpendicular", "spot", "point" };
  options.Techniques = QuickTechniqueNames();
  options.TimedFrames = 3;
  options.FlickerFrames = 12;
  return options;
}

//------------------------------------------------------------------------------
bool Run(const Options& requested, std::ostream& out, std::ostream& log, std::string& error,
  std::vector<CaseFigures>* figures)
{
  if (!ValidateOptions(requested, error))
  {
    return false;
  }
  const Options options = WithReferences(requested);
  const ScenePlan plan = PlanOf(options);
  std::vector<Row> rows;
  Progress progress(TotalWork(options, plan));
  for (const auto& [scene, setups] : plan)
  {
    View view;
    view.Width = options.Width;
    view.Height = options.Height;
    if (!BuildScene(view, scene, options, log, error))
    {
      return false;
    }
    shadoworacle::Oracle oracle;
    if (!oracle.Build(view.Renderer, error))
    {
      error = scene + ": " + error;
      return false;
    }
    log << scene << ": " << oracle.GetNumberOfTriangles() << " triangles" << std::endl;
    for (const std::string& setup : setups)
    {
      if (!RunSetup(view, oracle, scene, setup, options, rows, log, progress))
      {
        return false;
      }
    }
  }
  log << progress.Line() << "  done" << std::endl;
  std::ostringstream report;
  PrintTable(rows, report);
  PrintSizedTable(rows, report);
  PrintTranslucentTable(rows, report);
  const std::vector<Recommendation> recommendations = RecommendationsOf(rows);
  WriteRecommendationsMarkdown(recommendations, report);
  PrintAutomaticChoices(rows, report);
  out << report.str();
  std::ofstream(options.OutputDirectory + "/results.md") << report.str();
  WriteCSV(rows, options.OutputDirectory + "/results.csv");
  std::ofstream json(options.OutputDirectory + "/recommendation.json");
  WriteRecommendationsJSON(recommendations, json);
  if (figures)
  {
    for (const Row& row : rows)
    {
      const glm::dvec3& light = row.Transmittance.MeanAbsolute;
      figures->push_back({ row.Scene, row.Setup, row.Technique, row.Choice, row.Errors,
        row.Translucent, row.Translucent ? (light.x + light.y + light.z) / 3.0 : NotMeasured });
    }
  }
  return true;
}

} // namespace shadowbench
