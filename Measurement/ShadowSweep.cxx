#include "ShadowSweep.h"

#include "ShadowOracle.h"
#include "ShadowScenes.h"
#include "ShadowTechniques.h"

#include "vtkAbstractShadowMapPass.h"

#include <vtkCamera.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleKey.h>
#include <vtkLight.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include "ShadowMapVTKCompat.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

namespace shadowsweep
{
namespace
{
using shadoworacle::Truth;
using shadowbench::FormatNumber;

// --- drawing cases ------------------------------------------------------------------

/// SplitMix64: a small, fast generator whose whole state is one seed, so a case
/// is reproducible from its seed on any platform (std distributions are not).
class Random
{
public:
  explicit Random(std::uint64_t seed)
    : State(seed)
  {
  }
  std::uint64_t Next()
  {
    std::uint64_t z = (this->State += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double Uniform(double a = 0.0, double b = 1.0)
  {
    return a + (b - a) * static_cast<double>(this->Next() >> 11) * 0x1.0p-53;
  }
  double LogUniform(double a, double b) { return a * std::pow(b / a, this->Uniform()); }
  bool Chance(double p) { return this->Uniform() < p; }
  int Index(int n) { return std::min(static_cast<int>(this->Uniform() * n), n - 1); }
  glm::dvec3 UnitVector()
  {
    const double z = this->Uniform(-1.0, 1.0);
    const double phi = this->Uniform(0.0, 2.0 * vtkMath::Pi());
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return { r * std::cos(phi), r * std::sin(phi), z };
  }
  glm::dvec3 InBox(const glm::dvec3& lower, const glm::dvec3& upper)
  {
    return { this->Uniform(lower.x, upper.x), this->Uniform(lower.y, upper.y),
      this->Uniform(lower.z, upper.z) };
  }

private:
  std::uint64_t State;
};

struct Box
{
  glm::dvec3 Min;
  glm::dvec3 Max;
  glm::dvec3 Center() const { return 0.5 * (this->Min + this->Max); }
  double Diagonal() const { return std::max(glm::length(this->Max - this->Min), 1e-6); }
};

Box BoxOf(const double bounds[6])
{
  return { { bounds[0], bounds[2], bounds[4] }, { bounds[1], bounds[3], bounds[5] } };
}

/// A case's first draw, so that its scene is known before the scene is built.
std::string DrawScene(Random& random)
{
  const auto scenes = shadowscenes::SweepSceneNames();
  return scenes[random.Index(static_cast<int>(scenes.size()))];
}

/// The city's streets at street level: along a random street, eye height.
glm::dvec3 StreetLevelPosition(Random& random)
{
  const shadowscenes::CityLayout city = shadowscenes::GetCityLayout();
  const double half = 0.5 * city.Blocks * city.Pitch;
  const double across =
    city.StreetCenter(random.Index(city.Blocks + 1)) + random.Uniform(-0.35, 0.35) * city.StreetWidth;
  const double along = random.Uniform(-half, half);
  const double height = random.Uniform(1.2, 3.0);
  return random.Chance(0.5) ? glm::dvec3(across, along, height) : glm::dvec3(along, across, height);
}

/// Down the street a street-level camera stands in, pitched from slightly down to up.
glm::dvec3 DownTheStreet(Random& random, const glm::dvec3& position)
{
  const shadowscenes::CityLayout city = shadowscenes::GetCityLayout();
  const double offX = std::abs(std::remainder(position.x - city.StreetCenter(0), city.Pitch));
  const double offY = std::abs(std::remainder(position.y - city.StreetCenter(0), city.Pitch));
  const glm::dvec2 along = offX < offY ? glm::dvec2(0.0, 1.0) : glm::dvec2(1.0, 0.0);
  const double sign = random.Chance(0.5) ? 1.0 : -1.0;
  const double pitch = vtkMath::RadiansFromDegrees(random.Uniform(-10.0, 25.0));
  return { sign * along.x * std::cos(pitch), sign * along.y * std::cos(pitch), std::sin(pitch) };
}

glm::dvec3 ViewUpFor(const glm::dvec3& direction)
{
  return std::abs(direction.z) > 0.999 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
}

CameraCase DrawCamera(Random& random, const std::string& scene, const Box& box)
{
  CameraCase camera;
  const double size = box.Diagonal();
  glm::dvec3 direction(0.0);
  if (scene == "city" && random.Chance(0.7))
  {
    camera.Position = StreetLevelPosition(random);
    camera.Description = "street level";
    if (random.Chance(0.5))
    {
      direction = DownTheStreet(random, camera.Position);
    }
  }
  else if (scene == "room")
  {
    const glm::dvec3 inset(0.3);
    camera.Position = random.InBox(box.Min + inset, box.Max - inset);
    camera.Description = "inside the room";
  }
  else if (random.Chance(0.5))
  {
    camera.Position = random.InBox(box.Min, box.Max);
    camera.Position.z = std::max(camera.Position.z, box.Min.z + 0.002 * size);
    camera.Description = "inside the scene";
  }
  else
  {
    const glm::dvec3 margin = 0.25 * (box.Max - box.Min);
    camera.Position = random.InBox(box.Min - margin, box.Max + margin);
    camera.Position.z = box.Max.z + random.Uniform(0.02, 1.0) * size;
    camera.Description = "above the scene";
  }
  double focalDistance = 0.3 * size;
  if (direction == glm::dvec3(0.0))
  {
    if (random.Chance(0.75))
    {
      const glm::dvec3 target = random.InBox(box.Min, box.Max);
      direction = target - camera.Position;
      focalDistance = glm::length(direction);
      camera.Description += ", looking into the scene";
    }
    else
    {
      direction = random.UnitVector();
      camera.Description += ", looking anywhere";
    }
  }
  if (!(glm::length(direction) > 1e-9 * size) || !(focalDistance > 1e-6 * size))
  {
    direction = glm::dvec3(0.0, 1.0, 0.0);
    focalDistance = 0.3 * size;
  }
  direction = glm::normalize(direction);
  camera.FocalPoint = camera.Position + focalDistance * direction;
  camera.ViewUp = ViewUpFor(direction);
  camera.Parallel = random.Chance(0.25);
  if (camera.Parallel)
  {
    camera.ParallelScale = random.LogUniform(0.02, 0.7) * size;
  }
  else
  {
    camera.ViewAngle = random.Uniform(10.0, 100.0);
  }
  double farthest = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const glm::dvec3 p((corner & 1) ? box.Max.x : box.Min.x, (corner & 2) ? box.Max.y : box.Min.y,
      (corner & 4) ? box.Max.z : box.Min.z);
    farthest = std::max(farthest, glm::length(p - camera.Position));
  }
  camera.Far = std::max(farthest, 1e-3 * size) * random.Uniform(1.0, 1.5);
  camera.Near = camera.Far / random.LogUniform(10.0, 1e5);
  return camera;
}

void DrawDirectional(Random& random, const Box& box, const CameraCase& camera, LightCase& light)
{
  light.Kind = LightKind::Directional;
  glm::dvec3 travel = random.UnitVector();
  light.Description = "sun from any direction";
  const double choice = random.Uniform();
  const glm::dvec3 view = glm::normalize(camera.FocalPoint - camera.Position);
  if (choice < 0.1)
  {
    travel = view;
    light.Description = "sun along the view";
  }
  else if (choice < 0.2)
  {
    travel = -view;
    light.Description = "sun against the view";
  }
  light.FocalPoint = box.Center();
  light.Position = light.FocalPoint - box.Diagonal() * travel;
}

/// Inside the box, or outside it within one diagonal of it.
glm::dvec3 InsideOrOutside(Random& random, const Box& box, bool inside)
{
  if (inside)
  {
    return random.InBox(box.Min, box.Max);
  }
  const glm::dvec3 margin(box.Diagonal());
  glm::dvec3 p = random.InBox(box.Min - margin, box.Max + margin);
  for (int attempt = 0; attempt < 16 && glm::all(glm::greaterThanEqual(p, box.Min)) &&
       glm::all(glm::lessThanEqual(p, box.Max));
       ++attempt)
  {
    p = random.InBox(box.Min - margin, box.Max + margin);
  }
  if (glm::all(glm::greaterThanEqual(p, box.Min)) && glm::all(glm::lessThanEqual(p, box.Max)))
  {
    p.z = box.Max.z + 0.5 * box.Diagonal();
  }
  return p;
}

void DrawPositional(Random& random, const Box& box, bool inside, bool spot, LightCase& light)
{
  light.Kind = spot ? LightKind::Spot : LightKind::Point;
  light.Position = InsideOrOutside(random, box, inside);
  if (spot)
  {
    light.FocalPoint = random.InBox(box.Min, box.Max);
    if (glm::length(light.FocalPoint - light.Position) < 1e-6 * box.Diagonal())
    {
      light.FocalPoint = light.Position - glm::dvec3(0.0, 0.0, 1.0);
    }
    light.ConeAngle = random.Uniform(0.5, 89.5);
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << "spot of " << light.ConeAngle << " deg "
         << (inside ? "inside" : "outside") << " the scene";
    light.Description = text.str();
  }
  else
  {
    light.FocalPoint = light.Position - glm::dvec3(0.0, 0.0, 1.0);
    light.ConeAngle = 180.0;
    light.Description = std::string("point light ") + (inside ? "inside" : "outside") + " the scene";
  }
}

// The share of the point lights of perspective cameras standing in the scene
// (the room's aside) moved over the camera's shoulder.
constexpr double LampBehindShare = 0.5;

/// A share of the point lights moved to a lamp a little behind and above a
/// perspective camera that stands in the scene, whose shadows run away down
/// the view over receivers as far as the camera sees (Kozlov's cube once lost
/// to the uniform faces there). A stream of its own: the rest of the case,
/// and every other case, is drawn as before.
void DrawLampBehind(std::uint64_t caseSeed, const std::string& scene, const Box& box,
  const CameraCase& camera, LightCase& light)
{
  const bool standsInScene = glm::all(glm::greaterThanEqual(camera.Position, box.Min)) &&
    glm::all(glm::lessThanEqual(camera.Position, box.Max));
  Random random(caseSeed ^ 0x4c414d50ull);
  if (light.Kind != LightKind::Point || scene == "room" || camera.Parallel || !standsInScene ||
    !random.Chance(LampBehindShare))
  {
    return;
  }
  const double size = box.Diagonal();
  glm::dvec3 back = camera.Position - camera.FocalPoint;
  back.z = 0.0;
  back = glm::length(back) > 1e-9 * size ? glm::normalize(back) : glm::dvec3(0.0, -1.0, 0.0);
  light.Position = camera.Position + random.LogUniform(0.002, 0.1) * size * back +
    glm::dvec3(0.0, 0.0, random.LogUniform(0.005, 0.3) * size);
  light.FocalPoint = light.Position - glm::dvec3(0.0, 0.0, 1.0);
  light.Description = "point light behind and above the camera";
}

void DrawCameraLight(Random& random, LightCase& light)
{
  light.CameraLight = true;
  light.Position = { random.Uniform(-1.0, 1.0), random.Uniform(-1.0, 1.0), random.Uniform(0.5, 1.5) };
  light.FocalPoint = { random.Uniform(-0.2, 0.2), random.Uniform(-0.2, 0.2), 0.0 };
  if (random.Chance(0.5))
  {
    light.Kind = LightKind::Spot;
    light.ConeAngle = random.Uniform(5.0, 80.0);
    light.Description = "camera spot light";
  }
  else
  {
    light.Kind = LightKind::Directional;
    light.Description = "camera directional light";
  }
}

LightCase DrawLight(Random& random, const std::string& scene, const Box& box, const CameraCase& camera)
{
  LightCase light;
  const double choice = random.Uniform();
  if (scene == "room" && choice < 0.75)
  {
    DrawPositional(random, box, true, choice >= 0.55, light);
  }
  else if (choice < 0.12)
  {
    DrawCameraLight(random, light);
  }
  else if (choice < 0.52)
  {
    DrawDirectional(random, box, camera, light);
  }
  else
  {
    DrawPositional(random, box, random.Chance(0.5), choice < 0.76, light);
  }
  return light;
}

// --- measuring a case ----------------------------------------------------------------

/// A scene built once for all of its cases, with its oracle.
struct SceneView
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  shadoworacle::Oracle Oracle;
  double Bounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
};

bool BuildSceneView(SceneView& view, const std::string& scene, std::string& error)
{
  if (!shadowscenes::BuildSceneByName(view.Renderer, scene, error))
  {
    return false;
  }
  shadowbench::UseMeasurementMaterials(view.Renderer);
  view.Renderer->ComputeVisiblePropBounds(view.Bounds);
  view.Window->SetOffScreenRendering(1);
  view.Window->SetMultiSamples(0);
  view.Window->AddRenderer(view.Renderer);
  if (!view.Oracle.Build(view.Renderer, error))
  {
    error = scene + ": " + error;
    return false;
  }
  return true;
}

void ApplyCamera(const CameraCase& drawn, vtkCamera* camera)
{
  camera->SetPosition(drawn.Position.x, drawn.Position.y, drawn.Position.z);
  camera->SetFocalPoint(drawn.FocalPoint.x, drawn.FocalPoint.y, drawn.FocalPoint.z);
  camera->SetViewUp(drawn.ViewUp.x, drawn.ViewUp.y, drawn.ViewUp.z);
  camera->OrthogonalizeViewUp();
  camera->SetParallelProjection(drawn.Parallel);
  camera->SetParallelScale(drawn.ParallelScale);
  camera->SetViewAngle(drawn.ViewAngle);
  camera->SetClippingRange(drawn.Near, drawn.Far);
}

void ApplyLight(const LightCase& drawn, vtkRenderer* renderer)
{
  vtkNew<vtkLight> light;
  if (drawn.CameraLight)
  {
    light->SetLightTypeToCameraLight();
  }
  else
  {
    light->SetLightTypeToSceneLight();
  }
  light->SetPositional(drawn.Kind != LightKind::Directional);
  light->SetConeAngle(drawn.ConeAngle);
  if (drawn.Size > 0.0)
  {
    light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), drawn.Size);
  }
  light->SetPosition(drawn.Position.x, drawn.Position.y, drawn.Position.z);
  light->SetFocalPoint(drawn.FocalPoint.x, drawn.FocalPoint.y, drawn.FocalPoint.z);
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  renderer->AddLight(light);
}

int CountGLErrors(vtkRenderWindow* window)
{
  window->MakeCurrent();
  int count = 0;
  while (glGetError() != GL_NO_ERROR && count < 64)
  {
    ++count;
  }
  return count;
}

bool LostTheShadow(const std::vector<Truth>& truth, const std::vector<float>& factor)
{
  constexpr int EnoughShadowedPixels = 50;
  int shadowed = 0;
  int shown = 0;
  for (std::size_t i = 0; i < truth.size(); ++i)
  {
    if (truth[i] == Truth::Shadowed)
    {
      ++shadowed;
      shown += factor[i] < shadowmetrics::ShadowedBelow ? 1 : 0;
    }
  }
  return shadowed >= EnoughShadowedPixels && shown == 0;
}

std::string ImagePath(const Options& options, const Case& drawn, const std::string& name)
{
  return options.OutputDirectory + "/" + std::to_string(drawn.Seed) + "-" + name + ".png";
}

/// The frame, its error map and, for this project's passes, the light's maps.
void WriteReplayImages(SceneView& view, const Case& drawn, const std::string& name,
  const shadowbench::TechniqueInstance& technique, const std::vector<std::uint8_t>& frame,
  const std::vector<std::uint8_t>& errors, const Options& options)
{
  shadowbench::WritePNG(frame, drawn.Width, drawn.Height, ImagePath(options, drawn, name));
  shadowbench::WritePNG(errors, drawn.Width, drawn.Height, ImagePath(options, drawn, name + "-errors"));
  if (technique.Ours)
  {
    technique.Ours->SetAnalysisView(vtkAbstractShadowMapPass::SHADOW_MAP);
    view.Window->Render();
    shadowbench::WritePNG(shadowbench::CaptureRGB(view.Window), drawn.Width, drawn.Height,
      ImagePath(options, drawn, name + "-maps"));
    technique.Ours->SetAnalysisView(vtkAbstractShadowMapPass::NO_ANALYSIS);
  }
}

TechniqueResult MeasureTechnique(SceneView& view, const Case& drawn, const std::string& name,
  const std::vector<std::uint8_t>& plain, const std::vector<Truth>& truth,
  const std::vector<float>& visibility, const Options& options)
{
  TechniqueResult result;
  result.Technique = name;
  shadowbench::TechniqueInstance technique = shadowbench::MakeTechnique(
    name, drawn.Light.Kind == LightKind::Point, options.Resolution);
  view.Renderer->SetPass(technique.Pass);
  CountGLErrors(view.Window);
  {
    shadowbench::MessageLog messages;
    view.Window->Render();
    result.VTKErrors = messages.Errors();
    result.VTKWarnings = messages.Warnings();
    result.Messages = messages.Text();
  }
  result.GLErrors = CountGLErrors(view.Window);
  const auto rgb = shadowbench::CaptureRGB(view.Window);
  const auto factor = shadowmetrics::FactorFromRenders(rgb, plain, drawn.Width * drawn.Height);
  result.Errors = shadowmetrics::Classify(truth, factor, drawn.Width, drawn.Height);
  result.ShadowLost = LostTheShadow(truth, factor);
  result.Sized = !visibility.empty();
  if (result.Sized)
  {
    result.Visibility =
      shadowmetrics::CompareVisibility(visibility, factor, {}, drawn.Width, drawn.Height);
  }
  if (technique.Ours)
  {
    result.NonFiniteViews = technique.Ours->GetNumberOfNonFiniteViews();
  }
  if (options.Replay)
  {
    WriteReplayImages(view, drawn, name, technique, rgb,
      result.Sized ? shadowmetrics::VisibilityErrorMap(visibility, factor)
                   : shadowmetrics::ErrorMap(truth, factor),
      options);
  }
  view.Renderer->SetPass(nullptr);
  technique.Pass->ReleaseGraphicsResources(view.Window);
  return result;
}

/// The situation of the renderer's first shadowed light, as the automatic pass reads it.
shadowmaps::LightSituation SituationOfFirstLight(vtkRenderer* renderer)
{
  const std::vector<shadowmaps::SituatedLight> lights = shadowmaps::ReadLightSituations(renderer,
    vtkAbstractShadowMapPass::CASTS_SHADOWS(), vtkAbstractShadowMapPass::LIGHT_SIZE(), 1);
  return lights.empty() ? shadowmaps::LightSituation() : lights.front().Situation;
}

CaseResult MeasureCase(SceneView& view, const Case& drawn, const Options& options)
{
  CaseResult result;
  result.Drawn = drawn;
  view.Window->SetSize(drawn.Width, drawn.Height);
  ApplyCamera(drawn.Camera, view.Renderer->GetActiveCamera());
  ApplyLight(drawn.Light, view.Renderer);
  view.Renderer->SetPass(nullptr);
  view.Window->Render();
  const auto plain = shadowbench::CaptureRGB(view.Window);
  vtkLight* light = shadowbench::FirstLight(view.Renderer);
  const shadoworacle::Surface surface =
    shadowbench::VisibleSurface(view.Oracle, view.Renderer, view.Window, drawn.Width, drawn.Height, plain);
  std::vector<float> visibility;
  std::vector<Truth> truth;
  if (drawn.Light.Size > 0.0)
  {
    visibility = view.Oracle.Visibility(surface, light);
    truth = shadowmetrics::TruthAtHalf(visibility);
  }
  else
  {
    truth = view.Oracle.Classify(surface, light);
  }
  light->GetTransformedPosition(glm::value_ptr(result.LightWorldPosition));
  light->GetTransformedFocalPoint(glm::value_ptr(result.LightWorldFocalPoint));
  result.Situation = SituationOfFirstLight(view.Renderer);
  result.Counted = std::count_if(
    truth.begin(), truth.end(), [](Truth t) { return t != Truth::Ignored; });
  result.TruthShadowed = std::count(truth.begin(), truth.end(), Truth::Shadowed);
  if (options.Replay)
  {
    shadowbench::WritePNG(plain, drawn.Width, drawn.Height, ImagePath(options, drawn, "none"));
  }
  if (options.CountedOnly && !options.Replay && result.Counted < options.MinimumCounted)
  {
    return result;
  }
  for (const std::string& name : options.Techniques)
  {
    result.Techniques.push_back(
      MeasureTechnique(view, drawn, name, plain, truth, visibility, options));
  }
  return result;
}

/// Measures items (case seeds or cases) one scene at a time, each scene built
/// once for all of its items; results in the items' order.
template <typename Item, typename SceneOf, typename Measure>
bool MeasureInSceneOrder(const std::vector<Item>& items, SceneOf sceneOf, Measure measure,
  std::vector<CaseResult>& results, std::ostream& log, std::string& error)
{
  std::map<std::string, std::vector<std::size_t>> itemsOfScene;
  for (std::size_t i = 0; i < items.size(); ++i)
  {
    itemsOfScene[sceneOf(items[i])].push_back(i);
  }
  results.assign(items.size(), CaseResult());
  std::size_t done = 0;
  for (const auto& [scene, indices] : itemsOfScene)
  {
    SceneView view;
    if (!BuildSceneView(view, scene, error))
    {
      return false;
    }
    for (std::size_t i : indices)
    {
      results[i] = measure(view, items[i]);
      log << "case " << ++done << "/" << items.size() << " " << Describe(results[i].Drawn)
          << std::endl;
    }
  }
  return true;
}

// --- reporting -------------------------------------------------------------------------

const TechniqueResult* Find(const CaseResult& result, const std::string& technique)
{
  for (const TechniqueResult& t : result.Techniques)
  {
    if (t.Technique == technique)
    {
      return &t;
    }
  }
  return nullptr;
}

double UniformMisclassified(const CaseResult& result)
{
  const TechniqueResult* uniform = Find(result, "uniform");
  return uniform ? uniform->Errors.Misclassified : std::numeric_limits<double>::quiet_NaN();
}

/// `unit`: " %" for misclassified percentages, "" for visibility errors.
void PrintDistributions(
  const std::vector<Distribution>& distributions, std::ostream& out, const std::string& unit = " %")
{
  out << "| technique | cases | median" << unit << " | 95th percentile" << unit << " | worst" << unit
      << " | worst seed | uniform's worst" << unit
      << " | worst / uniform's worst | flagged cases |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const int digits = unit.empty() ? 4 : 2;
  for (const Distribution& d : distributions)
  {
    out << "| " << d.Technique << " | " << d.Cases << " | " << FormatNumber(d.Median, digits)
        << " | " << FormatNumber(d.Percentile95, digits) << " | " << FormatNumber(d.Worst, digits)
        << " | " << d.WorstSeed << " | " << FormatNumber(d.UniformWorst, digits) << " | "
        << FormatNumber(d.UniformWorst > 0.0 ? d.Worst / d.UniformWorst
                                       : std::numeric_limits<double>::quiet_NaN())
        << " | " << d.Flagged << " |\n";
  }
}

/// Per technique, the cases it misclassifies most, beside the uniform map's figure.
void PrintWorstCases(const std::vector<CaseResult>& results, const Options& options,
  std::ostream& out)
{
  constexpr std::size_t Shown = 3;
  out << "\n| technique | seed | misclassified % | uniform % | case |\n|---|---:|---:|---:|---|\n";
  std::vector<const CaseResult*> counted;
  for (const CaseResult& result : results)
  {
    if (result.Counted >= options.MinimumCounted)
    {
      counted.push_back(&result);
    }
  }
  for (std::size_t t = 0; t < options.Techniques.size(); ++t)
  {
    const std::size_t shown = std::min(Shown, counted.size());
    std::partial_sort(counted.begin(), counted.begin() + shown, counted.end(),
      [t](const CaseResult* a, const CaseResult* b) {
        return a->Techniques[t].Errors.Misclassified > b->Techniques[t].Errors.Misclassified;
      });
    for (std::size_t i = 0; i < shown; ++i)
    {
      out << "| " << options.Techniques[t] << " | " << counted[i]->Drawn.Seed << " | "
          << FormatNumber(counted[i]->Techniques[t].Errors.Misclassified) << " | "
          << FormatNumber(UniformMisclassified(*counted[i])) << " | " << Describe(counted[i]->Drawn)
          << " |\n";
    }
  }
}

void PrintFlagged(const std::vector<CaseResult>& results, std::ostream& out)
{
  bool any = false;
  for (const CaseResult& result : results)
  {
    for (const TechniqueResult& t : result.Techniques)
    {
      if (!t.Flagged())
      {
        continue;
      }
      if (!any)
      {
        out << "\nFlagged cases:\n\n";
        any = true;
      }
      std::string firstMessage = t.Messages.substr(0, t.Messages.find('\n'));
      out << "- " << result.Drawn.Seed << " " << t.Technique << ": " << t.Flags() << " ("
          << Describe(result.Drawn) << ")" << (firstMessage.empty() ? "" : ": " + firstMessage)
          << "\n";
    }
  }
  if (!any)
  {
    out << "\nNo case has a non-finite view, a GL error, a VTK error or warning, or a lost shadow.\n";
  }
}

std::string Coordinates(const glm::dvec3& p)
{
  std::ostringstream text;
  text << std::setprecision(9) << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return text.str();
}

void PrintReplay(const CaseResult& result, std::ostream& out)
{
  const CameraCase& camera = result.Drawn.Camera;
  const LightCase& light = result.Drawn.Light;
  out << Describe(result.Drawn) << "\n\ncamera: position " << Coordinates(camera.Position)
      << ", focal point " << Coordinates(camera.FocalPoint) << ", view up "
      << Coordinates(camera.ViewUp) << ", clipping range [" << camera.Near << ", " << camera.Far
      << "]\nlight (" << (light.CameraLight ? "camera" : "scene") << " light): position "
      << Coordinates(light.Position) << ", focal point " << Coordinates(light.FocalPoint)
      << ", cone angle " << light.ConeAngle << "; in the world: position "
      << Coordinates(result.LightWorldPosition) << ", focal point "
      << Coordinates(result.LightWorldFocalPoint) << "\n\ncounted pixels " << result.Counted << ", shadowed in truth "
      << result.TruthShadowed << "\n\n| technique | misclassified % | false shadow % | leak % | "
      << "flags |\n|---|---:|---:|---:|---|\n";
  for (const TechniqueResult& t : result.Techniques)
  {
    out << "| " << t.Technique << " | " << FormatNumber(t.Errors.Misclassified) << " | "
        << FormatNumber(t.Errors.FalseShadow) << " | " << FormatNumber(t.Errors.LightLeak) << " | "
        << t.Flags() << " |\n";
  }
  for (const TechniqueResult& t : result.Techniques)
  {
    if (!t.Messages.empty())
    {
      out << "\n" << t.Technique << ":\n" << t.Messages;
    }
  }
}

void WriteCSV(const std::vector<CaseResult>& results, const std::string& path)
{
  std::ofstream csv(path);
  csv << "seed,scene,width,height,counted,truth_shadowed,technique,misclassified,false_shadow,"
         "leak,gl_errors,vtk_errors,vtk_warnings,nonfinite_views,shadow_lost,light_size,"
         "visibility_mean_error,visibility_p95_error,light_kind,cos_light_view,"
         "light_behind_camera,parallel_camera,case\n";
  for (const CaseResult& result : results)
  {
    for (const TechniqueResult& t : result.Techniques)
    {
      csv << result.Drawn.Seed << ',' << result.Drawn.Scene << ',' << result.Drawn.Width << ','
          << result.Drawn.Height << ',' << result.Counted << ',' << result.TruthShadowed << ','
          << t.Technique << ',' << t.Errors.Misclassified << ',' << t.Errors.FalseShadow << ','
          << t.Errors.LightLeak << ',' << t.GLErrors << ',' << t.VTKErrors << ','
          << t.VTKWarnings << ',' << t.NonFiniteViews << ',' << (t.ShadowLost ? 1 : 0) << ','
          << result.Drawn.Light.Size << ',';
      if (t.Sized)
      {
        csv << t.Visibility.MeanAbsolute << ',' << t.Visibility.Percentile95;
      }
      else
      {
        csv << "nan,nan";
      }
      const shadowmaps::LightSituation& situation = result.Situation;
      csv << ',' << shadowmaps::KindName(situation.Kind) << ',' << situation.CosLightView << ','
          << (situation.LightBehindCamera ? 1 : 0) << ',' << (situation.ParallelCamera ? 1 : 0);
      csv << ",\"" << Describe(result.Drawn) << "\"\n";
    }
  }
}

bool ValidateOptions(const Options& options, std::string& error)
{
  for (const std::string& name : options.Techniques)
  {
    if (!shadowbench::IsTechnique(name))
    {
      error = "unknown technique '" + name + "'";
      return false;
    }
    if (name == "none")
    {
      error = "technique 'none' has no shadows to sweep";
      return false;
    }
  }
  if (options.Techniques.empty())
  {
    error = "no technique to measure";
    return false;
  }
  if (options.Cases < 1)
  {
    error = "no case to draw";
    return false;
  }
  return shadowbench::MakeOutputDirectory(options.OutputDirectory, error);
}

double Percentile(std::vector<double> values, double fraction)
{
  if (values.empty())
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  std::sort(values.begin(), values.end());
  const std::size_t rank = static_cast<std::size_t>(std::ceil(fraction * values.size()));
  return values[std::min(values.size() - 1, rank > 0 ? rank - 1 : 0)];
}

/// Per technique, the distribution of `value` (NaN: the case does not
/// count) over the cases with at least `minimumCounted` counted pixels, and
/// the uniform map's worst of the same value.
template <typename Value>
std::vector<Distribution> SummariseBy(
  const std::vector<CaseResult>& results, int minimumCounted, Value value)
{
  std::vector<Distribution> distributions;
  // Cases left unmeasured (Options::CountedOnly) have no technique's result.
  const auto measuredCase = std::find_if(results.begin(), results.end(),
    [](const CaseResult& result) { return !result.Techniques.empty(); });
  if (measuredCase == results.end())
  {
    return distributions;
  }
  for (std::size_t t = 0; t < measuredCase->Techniques.size(); ++t)
  {
    Distribution d;
    d.Technique = measuredCase->Techniques[t].Technique;
    d.UniformWorst = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> values;
    for (const CaseResult& result : results)
    {
      if (result.Techniques.empty())
      {
        continue;
      }
      const TechniqueResult& measured = result.Techniques[t];
      d.Flagged += measured.Flagged() ? 1 : 0;
      const double figure = value(measured);
      if (result.Counted < minimumCounted || std::isnan(figure))
      {
        continue;
      }
      values.push_back(figure);
      if (values.size() == 1 || figure > d.Worst)
      {
        d.Worst = figure;
        d.WorstSeed = result.Drawn.Seed;
      }
      const TechniqueResult* uniform = Find(result, "uniform");
      const double uniformFigure =
        uniform ? value(*uniform) : std::numeric_limits<double>::quiet_NaN();
      if (!std::isnan(uniformFigure))
      {
        d.UniformWorst =
          std::isnan(d.UniformWorst) ? uniformFigure : std::max(d.UniformWorst, uniformFigure);
      }
    }
    d.Cases = static_cast<int>(values.size());
    d.Median = Percentile(values, 0.5);
    d.Percentile95 = Percentile(values, 0.95);
    distributions.push_back(d);
  }
  return distributions;
}
} // namespace

//------------------------------------------------------------------------------
bool TechniqueResult::Flagged() const
{
  return !this->Flags().empty();
}

//------------------------------------------------------------------------------
std::string TechniqueResult::Flags() const
{
  std::string flags;
  auto add = [&flags](bool present, const std::string& text) {
    if (present)
    {
      flags += (flags.empty() ? "" : ", ") + text;
    }
  };
  add(this->NonFiniteViews > 0, std::to_string(this->NonFiniteViews) + " non-finite view(s)");
  add(this->GLErrors > 0, std::to_string(this->GLErrors) + " GL error(s)");
  add(this->VTKErrors > 0, std::to_string(this->VTKErrors) + " VTK error(s)");
  add(this->VTKWarnings > 0, std::to_string(this->VTKWarnings) + " VTK warning(s)");
  add(this->ShadowLost, "shadow lost");
  return flags;
}

//------------------------------------------------------------------------------
std::uint64_t CaseSeed(std::uint64_t sweepSeed, int index)
{
  Random random(sweepSeed * 0x2545F4914F6CDD1Dull + static_cast<std::uint64_t>(index));
  return random.Next();
}

//------------------------------------------------------------------------------
std::string SceneOfCase(std::uint64_t caseSeed)
{
  Random random(caseSeed);
  return DrawScene(random);
}

//------------------------------------------------------------------------------
Case DrawCase(std::uint64_t caseSeed, const double bounds[6], int baseWidth, int baseHeight)
{
  Random random(caseSeed);
  Case drawn;
  drawn.Seed = caseSeed;
  drawn.Scene = DrawScene(random);
  const Box box = BoxOf(bounds);
  drawn.Camera = DrawCamera(random, drawn.Scene, box);
  drawn.Light = DrawLight(random, drawn.Scene, box, drawn.Camera);
  DrawLampBehind(caseSeed, drawn.Scene, box, drawn.Camera, drawn.Light);
  drawn.Width = std::max(16, static_cast<int>(std::lround(baseWidth * random.Uniform(0.5, 1.5))));
  drawn.Height = std::max(16, static_cast<int>(std::lround(baseHeight * random.Uniform(0.5, 1.5))));
  return drawn;
}

//------------------------------------------------------------------------------
std::string Describe(const Case& drawn)
{
  std::ostringstream text;
  text << "seed " << drawn.Seed << ": " << drawn.Scene << ", camera " << drawn.Camera.Description
       << ", ";
  if (drawn.Camera.Parallel)
  {
    text << "parallel (scale " << std::setprecision(3) << drawn.Camera.ParallelScale << ")";
  }
  else
  {
    text << std::fixed << std::setprecision(1) << drawn.Camera.ViewAngle << " deg";
  }
  text << std::defaultfloat << std::setprecision(2) << ", near/far "
       << drawn.Camera.Near / drawn.Camera.Far << "; " << drawn.Light.Description;
  if (drawn.Light.Size > 0.0)
  {
    text << (drawn.Light.Kind == LightKind::Directional ? ", " : ", radius ") << drawn.Light.Size
         << (drawn.Light.Kind == LightKind::Directional ? " deg across" : "");
  }
  text << "; " << drawn.Width << "x" << drawn.Height;
  return text.str();
}

//------------------------------------------------------------------------------
std::vector<Distribution> Summarise(const std::vector<CaseResult>& results, int minimumCounted)
{
  return SummariseBy(results, minimumCounted,
    [](const TechniqueResult& t) { return t.Errors.Misclassified; });
}

//------------------------------------------------------------------------------
std::vector<Distribution> SummariseVisibility(
  const std::vector<CaseResult>& results, int minimumCounted)
{
  return SummariseBy(results, minimumCounted, [](const TechniqueResult& t) {
    return t.Sized ? t.Visibility.MeanAbsolute : std::numeric_limits<double>::quiet_NaN();
  });
}

//------------------------------------------------------------------------------
void DrawLightSize(Case& sweepCase, const double bounds[6])
{
  // A stream of its own: the rest of the case is drawn as without a size.
  Random random(sweepCase.Seed ^ 0x5153495a45ull);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  sweepCase.Light.Size = sweepCase.Light.Kind == LightKind::Directional
    ? random.LogUniform(0.25, 8.0)
    : random.LogUniform(0.002, 0.05) * diagonal;
}

//------------------------------------------------------------------------------
bool MeasureCases(const std::vector<Case>& cases, const Options& options,
  std::vector<CaseResult>& results, std::ostream& log, std::string& error)
{
  if (!ValidateOptions(options, error))
  {
    return false;
  }
  return MeasureInSceneOrder(
    cases, [](const Case& drawn) { return drawn.Scene; },
    [&](SceneView& view, const Case& drawn) { return MeasureCase(view, drawn, options); }, results,
    log, error);
}

//------------------------------------------------------------------------------
bool Run(const Options& options, std::ostream& out, std::ostream& log, std::string& error,
  std::vector<CaseResult>* resultsOut)
{
  if (!ValidateOptions(options, error))
  {
    return false;
  }
  std::vector<std::uint64_t> seeds;
  if (options.Replay)
  {
    seeds.push_back(options.ReplaySeed);
  }
  else
  {
    for (int i = 0; i < options.Cases; ++i)
    {
      seeds.push_back(CaseSeed(options.Seed, options.FirstCase + i));
    }
  }
  std::vector<CaseResult> results;
  const bool measured = MeasureInSceneOrder(
    seeds, [](std::uint64_t seed) { return SceneOfCase(seed); },
    [&](SceneView& view, std::uint64_t seed) {
      Case drawn = DrawCase(seed, view.Bounds, options.BaseWidth, options.BaseHeight);
      if (options.SizedLights)
      {
        DrawLightSize(drawn, view.Bounds);
      }
      if (options.Replay)
      {
        out << "scene bounds: x [" << view.Bounds[0] << ", " << view.Bounds[1] << "], y ["
            << view.Bounds[2] << ", " << view.Bounds[3] << "], z [" << view.Bounds[4] << ", "
            << view.Bounds[5] << "]\n";
      }
      return MeasureCase(view, drawn, options);
    },
    results, log, error);
  if (!measured)
  {
    return false;
  }

  std::ostringstream report;
  if (options.Replay)
  {
    PrintReplay(results.front(), report);
  }
  else
  {
    report << "Sweep of " << options.Cases << " cases";
    if (options.FirstCase > 0)
    {
      report << " (" << options.FirstCase << " to " << options.FirstCase + options.Cases - 1 << ")";
    }
    report << ", seed " << options.Seed << ", maps of " << options.Resolution
           << "², distributions over the cases with at least " << options.MinimumCounted
           << " counted pixels" << (options.CountedOnly ? ", the only ones measured" : "")
           << ".\n\n";
    PrintDistributions(Summarise(results, options.MinimumCounted), report);
    if (options.SizedLights)
    {
      report << "\nSized lights: the mean absolute difference between the shadow factor and the "
                "ray-traced visibility, per case (not percent).\n\n";
      PrintDistributions(SummariseVisibility(results, options.MinimumCounted), report, "");
    }
    PrintWorstCases(results, options, report);
    PrintFlagged(results, report);
  }
  out << report.str();
  std::ofstream(options.OutputDirectory + "/results.md") << report.str();
  WriteCSV(results, options.OutputDirectory + "/results.csv");
  if (resultsOut)
  {
    *resultsOut = std::move(results);
  }
  return true;
}

} // namespace shadowsweep
