#include "ShadowTechniques.h"

#include "ShadowMetrics.h"
#include "ShadowScenes.h"

#include "vtkAbstractShadowMapPass.h"
#include "vtkAutomaticShadowMapPass.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkVarianceShadowMapPass.h"
#include "vtkWarpedShadowMapViews.h"
#include "vtkWarpedShadowMapPass.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCameraPass.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderPassCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSequencePass.h>
#include <vtkShadowMapBakerPass.h>
#include <vtkShadowMapPass.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>

namespace shadowbench
{
namespace
{
constexpr unsigned int VTKDefaultResolution = 1024;

/// Bytes of this project's maps for one light at `resolution`: one depth
/// layer (sun, spot) or six (point light).
double OurMapBytes(bool pointLight, int resolution)
{
  const double layers = pointLight ? 6.0 : 1.0;
  return layers * 4.0 * resolution * static_cast<double>(resolution);
}

/// VTK's pass holds one 32-bit float colour map per shadowed light and one
/// depth buffer of the same size for rendering them.
double VTKMapBytes(unsigned int resolution)
{
  return 2.0 * 4.0 * resolution * static_cast<double>(resolution);
}

unsigned int VTKEqualMemoryResolution(bool pointLight, int resolution)
{
  return static_cast<unsigned int>(std::floor(std::sqrt(OurMapBytes(pointLight, resolution) / 8.0)));
}

// The vtkWarpedShadowMapPass mode a technique name stands for; -1 if none.
int WarpModeOf(const std::string& name)
{
  static const std::map<std::string, int> modes = { { "uniform", vtkWarpedShadowMapPass::UNIFORM },
    { "psm", vtkWarpedShadowMapPass::PSM }, { "psm-cube", vtkWarpedShadowMapPass::PSM },
    { "psm-single", vtkWarpedShadowMapPass::PSM }, { "lispsm", vtkWarpedShadowMapPass::LISPSM },
    { "tsm", vtkWarpedShadowMapPass::TSM }, { "gmnpr", vtkWarpedShadowMapPass::GMNPR } };
  const auto found = modes.find(name);
  return found == modes.end() ? -1 : found->second;
}

// The PSMCubeMap choice of a PSM technique name: "psm-cube" every light's
// post-perspective cube map, "psm-single" none (suns and spots one map, point
// lights the uniform cube faces), "psm" the default.
int PSMCubeMapOf(const std::string& name)
{
  return name == "psm-cube" ? vtkWarpedShadowMapViews::PSM_CUBE_ALWAYS
    : name == "psm-single"  ? vtkWarpedShadowMapViews::PSM_CUBE_NEVER
                            : vtkWarpedShadowMapViews::PSM_CUBE_AUTOMATIC;
}

// The vtkDualDepthShadowMapPass mode and layer method a technique name stands
// for; mode -1 if none.
std::pair<int, int> DualDepthOf(const std::string& name)
{
  static const std::map<std::string, std::pair<int, int>> techniques = {
    { "second-depth", { vtkDualDepthShadowMapPass::SECOND_DEPTH, vtkDualDepthShadowMapPass::AUTO } },
    { "midpoint", { vtkDualDepthShadowMapPass::MIDPOINT, vtkDualDepthShadowMapPass::AUTO } },
    { "dual", { vtkDualDepthShadowMapPass::DUAL, vtkDualDepthShadowMapPass::AUTO } },
    { "dual-minblend",
      { vtkDualDepthShadowMapPass::DUAL, vtkDualDepthShadowMapPass::MINIMUM_BLENDING } },
    { "dual-peel", { vtkDualDepthShadowMapPass::DUAL, vtkDualDepthShadowMapPass::DEPTH_PEELING } },
  };
  const auto found = techniques.find(name);
  if (found != techniques.end())
  {
    return found->second;
  }
  return name.rfind("dual-offset", 0) == 0
    ? std::make_pair(static_cast<int>(vtkDualDepthShadowMapPass::DUAL),
        static_cast<int>(vtkDualDepthShadowMapPass::AUTO))
    : std::make_pair(-1, 0);
}

// The vtkVarianceShadowMapPass moments a technique name stands for ("vsm",
// "evsm2", "evsm4", "msm", "esm", each optionally followed by the variants of
// MomentVariants); -1: none.
int MomentsOf(const std::string& name)
{
  static const std::map<std::string, int> moments = {
    { "vsm", vtkVarianceShadowMapPass::VSM },
    { "evsm2", vtkVarianceShadowMapPass::EVSM2 },
    { "evsm4", vtkVarianceShadowMapPass::EVSM4 },
    { "msm", vtkVarianceShadowMapPass::MSM },
    { "esm", vtkVarianceShadowMapPass::ESM },
  };
  const auto found = moments.find(name.substr(0, name.find('-')));
  return found == moments.end() ? -1 : found->second;
}

// The parameter sweep of the moment maps: "-half" (16-bit storage, exponents 5;
// MSM's moments in the Chebyshev basis),
// "-bleedX" (LightBleedingReduction X), "-blurX" (BlurRadius X texels),
// "-samplesN" (CasterSamples N), "-biasX" (MomentBias X), "-hard" (soft
// shadows off: the fixed blur a sized light's soft shadows are measured against).
std::vector<std::string> MomentVariantNames()
{
  return { "vsm-bleed0", "vsm-bleed0.4", "evsm4-bleed0", "evsm4-half", "evsm4-blur0", "evsm4-blur2",
    "evsm4-blur4", "msm-bleed0", "evsm4-samples4", "msm-bias0.0001", "msm-bias0.001", "msm-half",
    "msm-half-bias0.0001", "msm-half-bias0.001",
    // The sweep that chose the defaults, when the reduction was 0.2:
    "evsm4-bleed0.2", "vsm-bleed0.2", "msm-bleed0.2", "evsm4-half-bleed0.2",
    "evsm4-blur0-bleed0.2", "evsm4-blur2-bleed0.2", "evsm4-blur4-bleed0.2" };
}

void ApplyMomentVariant(const std::string& name, vtkVarianceShadowMapPass* pass)
{
  const auto valueAfter = [&name](const std::string& key) {
    return std::stod(name.substr(name.find(key) + key.size()));
  };
  if (name.find("-half") != std::string::npos)
  {
    // Exponents that 16-bit storage holds, set first: no clamping warning.
    pass->SetPositiveExponent(5.0);
    pass->SetNegativeExponent(5.0);
    pass->SetStorageToHalfFloat();
  }
  if (name.find("-bleed") != std::string::npos)
  {
    pass->SetLightBleedingReduction(valueAfter("-bleed"));
  }
  if (name.find("-blur") != std::string::npos)
  {
    pass->SetBlurRadius(valueAfter("-blur"));
  }
  if (name.find("-bias") != std::string::npos)
  {
    pass->SetMomentBias(valueAfter("-bias"));
  }
  if (name.find("-samples") != std::string::npos)
  {
    pass->SetCasterSamples(static_cast<int>(valueAfter("-samples")));
  }
  if (name.find("-hard") != std::string::npos)
  {
    pass->SoftShadowsOff();
  }
}

// The fixed blurs of the default moments, soft shadows off.
std::vector<std::string> MomentBlurSweepNames()
{
  return { "evsm4-hard-blur0", "evsm4-hard-blur1", "evsm4-hard-blur2", "evsm4-hard-blur4",
    "evsm4-hard-blur8", "evsm4-hard-blur16" };
}

// The depth filters of the uniform map that soften like the moment maps'
// default blur: "pcf3" (3 x 3 bilinear PCF) and "poisson" (16 taps), and the
// fixed-radius filters a sized light's soft shadows are measured against:
// "poisson-r<R>", R texels, soft shadows off.
int DepthFilterOf(const std::string& name)
{
  return name == "pcf3"                                                ? vtkDepthShadowMapPass::PCF_NXN
    : name == "poisson" || name.rfind("poisson-r", 0) == 0 ? vtkDepthShadowMapPass::POISSON
                                                                       : -1;
}

std::vector<std::string> PoissonRadiusSweepNames()
{
  return { "poisson-r1", "poisson-r2", "poisson-r4", "poisson-r8", "poisson-r16" };
}

// The dual mode's offset sweep: "dual-offset<K>", K texels ("dual" is K = 2).
std::vector<std::string> DualOffsetSweepNames()
{
  return { "dual-offset0.5", "dual-offset1", "dual-offset4", "dual-offset8" };
}

// The uniform map's constant bias sweep: "uniform-bias<B>" (default normal
// offset) and "uniform-bias<B>-offset0".
const std::vector<int> SweptBiases = { 0, 1, 4, 16, 64 };

std::vector<std::string> BiasSweepNames()
{
  std::vector<std::string> names;
  for (const char* suffix : { "", "-offset0" })
  {
    for (int bias : SweptBiases)
    {
      names.push_back("uniform-bias" + std::to_string(bias) + suffix);
    }
  }
  return names;
}

// "<representation>+<views>": a representation a preset has ("depth": the
// uniform technique's depth map and filter; "dual": the dual technique;
// "evsm4": the moments' defaults) on any views ("uniform", "psm", "psm-cube",
// "lispsm", "lispsm-lloyd" (LiSPSM with vtkWarpedShadowMapViews::LloydFalloff),
// "tsm", "gmnpr"; "csm" and "csm-lispsm": four stable cascades of half the
// resolution, the latter tight and LiSPSM-warped as "csm-lispsm").
const std::vector<std::string> PairRepresentations = { "depth", "dual", "evsm4" };
const std::vector<std::string> PairViews = { "uniform", "psm", "psm-cube", "lispsm",
  "lispsm-lloyd", "tsm", "gmnpr", "csm", "csm-lispsm" };

std::vector<std::string> PairNames()
{
  std::vector<std::string> names;
  for (const std::string& representation : PairRepresentations)
  {
    for (const std::string& views : PairViews)
    {
      names.push_back(representation + "+" + views);
    }
  }
  return names;
}

/// The two halves of a pair's name; false if `name` is no pair.
bool SplitPair(const std::string& name, std::string& representation, std::string& views)
{
  const auto plus = name.find('+');
  if (plus == std::string::npos)
  {
    return false;
  }
  representation = name.substr(0, plus);
  views = name.substr(plus + 1);
  return std::find(PairRepresentations.begin(), PairRepresentations.end(), representation) !=
    PairRepresentations.end() &&
    std::find(PairViews.begin(), PairViews.end(), views) != PairViews.end();
}

vtkSmartPointer<vtkShadowMapViews> MakePairViews(const std::string& views)
{
  if (views.rfind("csm", 0) == 0)
  {
    auto cascades = vtkSmartPointer<vtkCascadedShadowMapViews>::New();
    if (views == "csm-lispsm")
    {
      cascades->SetFitModeToTight();
      cascades->SetCascadeWarpToLiSPSM();
    }
    return cascades;
  }
  auto warped = vtkSmartPointer<vtkWarpedShadowMapViews>::New();
  const bool lloyd = views == "lispsm-lloyd";
  warped->SetWarpMode(WarpModeOf(lloyd ? "lispsm" : views));
  warped->SetPSMCubeMap(PSMCubeMapOf(views));
  warped->SetLloydFalloff(lloyd);
  return warped;
}

vtkSmartPointer<vtkAbstractShadowMapPass> MakePairPass(const std::string& representation)
{
  if (representation == "dual")
  {
    auto pass = vtkSmartPointer<vtkDualDepthShadowMapPass>::New();
    pass->SetFilter(vtkDepthShadowMapPass::PCF_2X2);
    pass->SetModeToDual();
    pass->SetConstantBias(0.0);
    pass->SetSlopeScaledBias(0.0);
    pass->SetNormalOffset(0.0);
    return pass;
  }
  if (representation == "evsm4")
  {
    auto pass = vtkSmartPointer<vtkVarianceShadowMapPass>::New();
    pass->SetMoments(vtkVarianceShadowMapPass::EVSM4);
    return pass;
  }
  auto pass = vtkSmartPointer<vtkDepthShadowMapPass>::New();
  pass->SetFilter(vtkDepthShadowMapPass::PCF_2X2);
  return pass;
}

class CountingOutputWindow : public vtkOutputWindow
{
public:
  static CountingOutputWindow* New();
  vtkTypeMacro(CountingOutputWindow, vtkOutputWindow);
  void DisplayErrorText(const char* text) override
  {
    ++this->Errors;
    this->Log << "ERROR: " << text << "\n";
  }
  void DisplayWarningText(const char* text) override
  {
    ++this->Warnings;
    this->Log << "WARNING: " << text << "\n";
  }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayText(const char* text) override { this->Log << text << "\n"; }
  int Errors = 0;
  int Warnings = 0;
  std::ostringstream Log;
};
vtkStandardNewMacro(CountingOutputWindow);
} // namespace

//------------------------------------------------------------------------------
vtkSmartPointer<vtkRenderPass> MakeVTKShadowMapPass(unsigned int resolution, vtkShadowMapPass** shadows)
{
  vtkNew<vtkShadowMapPass> pass; // its opaque sequence renders lights + opaque geometry
  pass->GetShadowMapBakerPass()->SetResolution(resolution);
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(pass->GetShadowMapBakerPass());
  passes->AddItem(pass);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(passes);
  auto camera = vtkSmartPointer<vtkCameraPass>::New();
  camera->SetDelegatePass(sequence);
  if (shadows)
  {
    *shadows = pass;
  }
  return camera;
}

//------------------------------------------------------------------------------
std::vector<std::string> DefaultTechniqueNames()
{
  return { "none", "vtk", "vtk-equal", "uniform", "psm", "lispsm", "tsm", "gmnpr", "csm",
    "csm-tight", "csm-lispsm", "second-depth", "midpoint", "dual", "evsm4" };
}

//------------------------------------------------------------------------------
std::vector<std::string> QuickTechniqueNames()
{
  return { "none", "vtk", "uniform", "lispsm", "csm", "second-depth", "evsm4", "auto" };
}

//------------------------------------------------------------------------------
std::vector<std::string> TechniqueNames()
{
  std::vector<std::string> names = DefaultTechniqueNames();
  names.insert(names.end(), { "auto", "auto-cost6", "auto-full-drag", "psm-cube", "psm-single", "dual-minblend", "dual-peel", "vsm",
                              "evsm2", "msm", "esm", "pcf3", "poisson" });
  const std::vector<std::string> variants = MomentVariantNames();
  names.insert(names.end(), variants.begin(), variants.end());
  const std::vector<std::string> offsets = DualOffsetSweepNames();
  names.insert(names.end(), offsets.begin(), offsets.end());
  const std::vector<std::string> biases = BiasSweepNames();
  names.insert(names.end(), biases.begin(), biases.end());
  const std::vector<std::string> radii = PoissonRadiusSweepNames();
  names.insert(names.end(), radii.begin(), radii.end());
  const std::vector<std::string> blurs = MomentBlurSweepNames();
  names.insert(names.end(), blurs.begin(), blurs.end());
  const std::vector<std::string> pairs = PairNames();
  names.insert(names.end(), pairs.begin(), pairs.end());
  return names;
}

//------------------------------------------------------------------------------
bool IsTechnique(const std::string& name)
{
  const auto names = TechniqueNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

//------------------------------------------------------------------------------
bool CheckTechniquesAndSetups(const std::vector<std::string>& techniques,
  const std::vector<std::string>& setups, std::string& error)
{
  for (const std::string& name : techniques)
  {
    if (!IsTechnique(name))
    {
      error = "unknown technique '" + name + "'";
      return false;
    }
  }
  for (const std::string& setup : setups)
  {
    if (!shadowscenes::IsLightSetup(setup))
    {
      error = "unknown light set-up '" + setup + "'";
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
std::vector<std::string> WithReferenceTechniques(std::vector<std::string> techniques)
{
  for (const char* reference : { "vtk", "none" })
  {
    if (std::find(techniques.begin(), techniques.end(), reference) == techniques.end())
    {
      techniques.insert(techniques.begin(), reference);
    }
  }
  return techniques;
}

//------------------------------------------------------------------------------
TechniqueInstance MakeTechnique(const std::string& name, bool pointLight, int resolution)
{
  TechniqueInstance technique;
  std::string pairRepresentation;
  std::string pairViews;
  if (name.rfind("auto", 0) == 0)
  {
    auto pass = vtkSmartPointer<vtkAutomaticShadowMapPass>::New();
    pass->SetResolution(resolution); // halved by the pass for cascades
    pass->SetCostBudget(name == "auto-cost6" ? 6.0 : 1.0);
    if (name == "auto-full-drag")
    {
      pass->SetInteractiveResolutionScale(1.0);
    }
    technique.Ours = pass;
    technique.Pass = pass;
    technique.Resolution = resolution;
  }
  else if (SplitPair(name, pairRepresentation, pairViews))
  {
    auto pass = MakePairPass(pairRepresentation);
    pass->SetViews(MakePairViews(pairViews));
    // Cascades of half the resolution: four hold the memory of one map.
    pass->SetResolution(pairViews.rfind("csm", 0) == 0 ? std::max(resolution / 2, 64) : resolution);
    technique.Ours = pass;
    technique.Pass = pass;
    technique.Resolution = pass->GetResolution();
  }
  else if (name == "vtk" || name == "vtk-equal")
  {
    technique.Resolution = static_cast<int>(
      name == "vtk" ? VTKDefaultResolution : VTKEqualMemoryResolution(pointLight, resolution));
    technique.Pass = MakeVTKShadowMapPass(static_cast<unsigned int>(technique.Resolution), &technique.VTK);
  }
  else if (WarpModeOf(name) >= 0)
  {
    auto pass = vtkSmartPointer<vtkWarpedShadowMapPass>::New();
    pass->SetResolution(resolution);
    pass->SetFilter(vtkDepthShadowMapPass::PCF_2X2);
    pass->SetWarpMode(WarpModeOf(name));
    pass->SetPSMCubeMap(PSMCubeMapOf(name));
    technique.Ours = pass;
    technique.Pass = pass;
    technique.Resolution = resolution;
  }
  else if (name.rfind("uniform-bias", 0) == 0)
  {
    auto pass = vtkSmartPointer<vtkWarpedShadowMapPass>::New();
    pass->SetResolution(resolution);
    pass->SetFilter(vtkDepthShadowMapPass::PCF_2X2);
    pass->SetWarpModeToUniform();
    pass->SetConstantBias(std::stod(name.substr(std::string("uniform-bias").size())));
    if (name.find("-offset0") != std::string::npos)
    {
      pass->SetNormalOffset(0.0);
    }
    technique.Ours = pass;
    technique.Pass = pass;
    technique.Resolution = resolution;
  }
  else if (DualDepthOf(name).first >= 0)
  {
    // The uniform technique's views and filter, every bias at zero.
    auto pass = vtkSmartPointer<vtkDualDepthShadowMapPass>::New();
    auto views = vtkSmartPointer<vtkWarpedShadowMapViews>::New();
    views->SetWarpModeToUniform();
    pass->SetViews(views);
    pass->SetResolution(resolution);
    pass->SetFilter(vtkDepthShadowMapPass::PCF_2X2);
    pass->SetMode(DualDepthOf(name).first);
    pass->SetLayerMethod(DualDepthOf(name).second);
    pass->SetConstantBias(0.0);
    pass->SetSlopeScaledBias(0.0);
    pass->SetNormalOffset(0.0);
    if (name.rfind("dual-offset", 0) == 0)
    {
      pass->SetDualOffset(std::stod(name.substr(std::string("dual-offset").size())));
    }
    technique.Ours = pass;
    technique.Pass = pass;
    technique.Resolution = resolution;
  }
  else if (MomentsOf(name) >= 0)
  {
    // The uniform technique's views; the moments' defaults.
    auto pass = vtkSmartPointer<vtkVarianceShadowMapPass>::New();
    auto views = vtkSmartPointer<vtkWarpedShadowMapViews>::New();
    views->SetWarpModeToUniform();
    pass->SetViews(views);
    pass->SetResolution(resolution);
    pass->SetMoments(MomentsOf(name));
    ApplyMomentVariant(name, pass);
    technique.Ours = pass;
    technique.Pass = pass;
    technique.Resolution = resolution;
  }
  else if (DepthFilterOf(name) >= 0)
  {
    auto pass = vtkSmartPointer<vtkWarpedShadowMapPass>::New();
    pass->SetResolution(resolution);
    pass->SetWarpModeToUniform();
    pass->SetFilter(DepthFilterOf(name));
    pass->SetKernelSize(3);
    pass->SetFilterRadius(1.5);
    if (name.rfind("poisson-r", 0) == 0)
    {
      pass->SetFilterRadius(std::stod(name.substr(std::string("poisson-r").size())));
      pass->SetPoissonSamples(32);
      pass->SoftShadowsOff();
    }
    technique.Ours = pass;
    technique.Pass = pass;
    technique.Resolution = resolution;
  }
  else if (name == "csm" || name == "csm-tight" || name == "csm-lispsm")
  {
    // Four cascades of half the resolution: the memory of one map.
    auto pass = vtkSmartPointer<vtkCascadedShadowMapPass>::New();
    pass->SetResolution(std::max(resolution / 2, 64));
    pass->SetFilter(vtkDepthShadowMapPass::PCF_2X2);
    pass->SetFitMode(name == "csm" ? vtkCascadedShadowMapPass::STABLE : vtkCascadedShadowMapPass::TIGHT);
    if (name == "csm-lispsm")
    {
      pass->SetCascadeWarp(vtkCascadedShadowMapPass::LISPSM_WARP);
    }
    technique.Ours = pass;
    technique.Pass = pass;
    technique.Resolution = pass->GetResolution();
  }
  return technique;
}

//------------------------------------------------------------------------------
double MemoryMiB(const TechniqueInstance& technique)
{
  if (technique.Ours)
  {
    return technique.Ours->GetShadowMapMemory() / (1024.0 * 1024.0);
  }
  if (technique.VTK)
  {
    return VTKMapBytes(static_cast<unsigned int>(technique.Resolution)) / (1024.0 * 1024.0);
  }
  return 0.0;
}

//------------------------------------------------------------------------------
void UseMeasurementMaterials(vtkRenderer* renderer)
{
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    if (actor->HasTranslucentPolygonalGeometry())
    {
      continue; // a caster whose colour and opacity tint the light; never a measured receiver
    }
    vtkProperty* property = actor->GetProperty();
    property->SetColor(1.0, 1.0, 1.0);
    property->SetAmbient(0.0);
    property->SetDiffuse(1.0);
    property->SetSpecular(0.0);
    if (actor->GetMapper())
    {
      actor->GetMapper()->ScalarVisibilityOff();
    }
  }
  renderer->SetBackground(0.0, 0.0, 0.0);
}

//------------------------------------------------------------------------------
std::vector<std::uint8_t> CaptureRGB(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->SetInputBufferTypeToRGB();
  capture->ReadFrontBufferOff();
  capture->Update();
  vtkDataArray* scalars = capture->GetOutput()->GetPointData()->GetScalars();
  auto* bytes = static_cast<std::uint8_t*>(scalars->GetVoidPointer(0));
  return std::vector<std::uint8_t>(bytes, bytes + scalars->GetNumberOfValues());
}

//------------------------------------------------------------------------------
std::vector<float> CaptureDepth(vtkRenderWindow* window, int width, int height)
{
  vtkNew<vtkFloatArray> depth;
  window->GetZbufferData(0, 0, width - 1, height - 1, depth);
  return std::vector<float>(depth->GetPointer(0), depth->GetPointer(0) + depth->GetNumberOfValues());
}

//------------------------------------------------------------------------------
bool MakeOutputDirectory(const std::string& directory, std::string& error)
{
  std::error_code ignored;
  std::filesystem::create_directories(directory, ignored);
  if (!std::filesystem::is_directory(directory))
  {
    error = "cannot create output directory '" + directory + "'";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool WritePNG(const std::vector<std::uint8_t>& rgb, int width, int height, const std::string& path)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::copy(rgb.begin(), rgb.end(), static_cast<std::uint8_t*>(image->GetScalarPointer()));
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  return writer->GetErrorCode() == 0;
}

//------------------------------------------------------------------------------
std::string FormatNumber(double value, int digits)
{
  if (std::isnan(value))
  {
    return "n/a";
  }
  std::ostringstream text;
  text << std::fixed << std::setprecision(digits) << value;
  return text.str();
}

//------------------------------------------------------------------------------
shadoworacle::Surface VisibleSurface(const shadoworacle::Oracle& oracle, vtkRenderer* renderer,
  vtkRenderWindow* window, int width, int height, const std::vector<std::uint8_t>& unshadowedRgb)
{
  shadoworacle::Surface surface = oracle.Trace(renderer, width, height);
  shadoworacle::Oracle::MaskRasterMismatch(surface, renderer, CaptureDepth(window, width, height));
  shadowmetrics::IgnoreUnlitInRender(unshadowedRgb, surface.Valid);
  return surface;
}

//------------------------------------------------------------------------------
vtkLight* FirstLight(vtkRenderer* renderer)
{
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  return lights->GetNextItem();
}

//------------------------------------------------------------------------------
struct MessageLog::Impl
{
  vtkNew<CountingOutputWindow> Window;
  vtkSmartPointer<vtkOutputWindow> Previous;
};

MessageLog::MessageLog()
  : Pimpl(new Impl)
{
  this->Pimpl->Previous = vtkOutputWindow::GetInstance();
  vtkOutputWindow::SetInstance(this->Pimpl->Window);
}

MessageLog::~MessageLog()
{
  vtkOutputWindow::SetInstance(this->Pimpl->Previous);
  delete this->Pimpl;
}

int MessageLog::Errors() const
{
  return this->Pimpl->Window->Errors;
}

int MessageLog::Warnings() const
{
  return this->Pimpl->Window->Warnings;
}

std::string MessageLog::Text() const
{
  return this->Pimpl->Window->Log.str();
}

} // namespace shadowbench
