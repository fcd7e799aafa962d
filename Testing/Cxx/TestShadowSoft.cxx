// Soft shadows of lights with a size (vtkAbstractShadowMapPass::LIGHT_SIZE):
// the penumbra of a straight edge against its closed form, under the uniform
// map, LiSPSM and cascades, for suns and spots at several blocker heights;
// contact hardening; hard shadows untouched by the soft code; bad sizes.
#include "ShadowTestUtilities.h"

#include "ShadowMapSceneReading.h"
#include "vtkAbstractShadowMapPass.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkVarianceShadowMapPass.h"
#include "vtkWarpedShadowMapPass.h"
#include "vtkWarpedShadowMapViews.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// Stands in for VTK's ray tracing module, not loaded here: its light node's
// RADIUS key, registered by the same name and place.
class vtkOSPRayLightNode
{
public:
  static vtkInformationDoubleKey* RADIUS();
};
vtkInformationKeyMacro(vtkOSPRayLightNode, RADIUS, Double);

constexpr double Pi = 3.14159265358979323846;

/// The fraction of a uniform unit disc on the side u < c of a line.
double DiscFractionBelow(double c)
{
  c = std::max(-1.0, std::min(1.0, c));
  return 0.5 + (c * std::sqrt(1.0 - c * c) + std::asin(c)) / Pi;
}

/// A ground (z = 0) and, at `height`, a half-plane occluder over x < 0, lit
/// by one light; a perspective camera looks down at the edge's shadow.
struct EdgeScene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkLight> Light;
  double Height;

  explicit EdgeScene(double height)
    : Height(height)
  {
    this->Window->SetSize(400, 400);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->AutomaticLightCreationOff();
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->AddQuad({ -20.0, -20.0, 0.0 }, { 20.0, -20.0, 0.0 }, { -20.0, 20.0, 0.0 });
    this->AddQuad({ -20.0, -20.0, height }, { 0.0, -20.0, height }, { -20.0, 20.0, height });
    this->Light->SetLightTypeToSceneLight();
    this->Renderer->AddLight(this->Light);
  }

  void AddQuad(const glm::dvec3& origin, const glm::dvec3& point1, const glm::dvec3& point2)
  {
    vtkNew<vtkPlaneSource> quad;
    quad->SetOrigin(origin.x, origin.y, origin.z);
    quad->SetPoint1(point1.x, point1.y, point1.z);
    quad->SetPoint2(point2.x, point2.y, point2.z);
    quad->SetResolution(16, 16);
    vtkSmartPointer<vtkActor> actor = shadowtest::AddSourceActor(this->Renderer, quad);
    actor->GetProperty()->SetAmbient(0.0);
    actor->GetProperty()->SetDiffuse(1.0);
    actor->GetProperty()->SetSpecular(0.0);
  }

  /// A sun shining from `towardLight` with an angular diameter in degrees.
  void SetSun(const glm::dvec3& towardLight, double diameter)
  {
    this->Light->SetPositional(false);
    this->Light->SetPosition(towardLight.x, towardLight.y, towardLight.z);
    this->Light->SetFocalPoint(0.0, 0.0, 0.0);
    this->Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), diameter);
  }

  /// A spot at `position` of `radius`, aimed at `focus`.
  void SetSpot(const glm::dvec3& position, const glm::dvec3& focus, double radius)
  {
    this->Light->SetPositional(true);
    this->Light->SetPosition(position.x, position.y, position.z);
    this->Light->SetFocalPoint(focus.x, focus.y, focus.z);
    this->Light->SetConeAngle(60.0);
    this->Light->SetAttenuationValues(1.0, 0.0, 0.0);
    this->Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), radius);
  }

  /// Looks down at `focus` from `distance`, or from above the occluder.
  void LookAt(const glm::dvec3& focus, double distance)
  {
    distance = std::max(distance, 2.0 * this->Height);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(focus.x, focus.y, focus.z);
    camera->SetPosition(focus.x + 0.2 * distance, focus.y - 0.5 * distance, focus.z + distance);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(30.0);
    this->Renderer->ResetCameraClippingRange();
  }

  /// Renders through the renderer's pass and returns the frame's bytes, read
  /// as rendered (a capture that re-renders nudges the camera).
  std::vector<unsigned char> StillFrame()
  {
    this->Window->Render();
    return shadowtest::RgbBytes(shadowtest::CaptureAsRendered(this->Window));
  }

  /// The shadow factor at ground points x along y = 0 (white diffuse surfaces,
  /// no ambient light: the ratio of the shadowed to the unshadowed render).
  std::vector<double> FactorAlongX(vtkRenderPass* pass, const std::vector<double>& xs)
  {
    std::vector<glm::dvec3> points;
    for (double x : xs)
    {
      points.emplace_back(x, 0.0, 0.0);
    }
    return this->FactorAt(pass, points);
  }

  /// The shadow factor at world points (seen in the view).
  std::vector<double> FactorAt(vtkRenderPass* pass, const std::vector<glm::dvec3>& points)
  {
    this->Renderer->SetPass(nullptr);
    vtkSmartPointer<vtkImageData> plain = shadowtest::RenderAndCapture(this->Window);
    this->Renderer->SetPass(pass);
    vtkSmartPointer<vtkImageData> shadowed = shadowtest::RenderAndCapture(this->Window);
    this->Renderer->SetPass(nullptr);
    std::vector<double> factor;
    for (const glm::dvec3& point : points)
    {
      const double lit = shadowtest::LuminanceAt(this->Renderer, plain, point);
      factor.push_back(
        lit > 0.0 ? shadowtest::LuminanceAt(this->Renderer, shadowed, point) / lit : 1.0);
    }
    return factor;
  }
};

/// The visibility of the light at ground point (x, 0, 0) behind the edge, from
/// the light's axis (unit, toward it) and the sine of its angular radius there.
double EdgeVisibility(double x, double height, const glm::dvec3& axis, double sinRadius)
{
  // The plane through the point and the edge (x = 0, z = height).
  const glm::dvec3 normal = glm::normalize(glm::dvec3(height, 0.0, x));
  // Rays toward the light on the side of the plane away from the occluder
  // (toward +x at the edge's height) pass it.
  return DiscFractionBelow(glm::dot(axis, normal) / sinRadius);
}

/// A spot's penumbra behind the scene's edge: where on the ground the light's
/// centre sees the edge, the penumbra's half width there and the light's
/// visibility along x.
struct SpotEdge
{
  double Centre = 0.0;
  double HalfWidth = 0.0;
  std::function<double(double)> Visibility;
};

/// Puts a spot of `radius` at `lamp`, aimed at its edge's shadow, and the
/// camera over that shadow.
SpotEdge AimSpotAtEdge(EdgeScene& scene, const glm::dvec3& lamp, double radius)
{
  const double height = scene.Height;
  SpotEdge edge;
  edge.Centre = height * -lamp.x / (lamp.z - height);
  scene.SetSpot(lamp, { edge.Centre, 0.0, 0.0 }, radius);
  edge.HalfWidth = radius * height / (lamp.z - height);
  scene.LookAt({ edge.Centre, 0.0, 0.0 }, 12.0 * edge.HalfWidth);
  edge.Visibility = [lamp, radius, height](double x) {
    const glm::dvec3 toLamp = lamp - glm::dvec3(x, 0.0, 0.0);
    return EdgeVisibility(x, height, glm::normalize(toLamp), radius / glm::length(toLamp));
  };
  return edge;
}

/// Where a monotonic profile first reaches `level`, by linear interpolation.
double Crossing(const std::vector<double>& xs, const std::vector<double>& values, double level)
{
  for (std::size_t i = 1; i < xs.size(); ++i)
  {
    if ((values[i - 1] - level) * (values[i] - level) <= 0.0 && values[i] != values[i - 1])
    {
      return xs[i - 1] + (level - values[i - 1]) / (values[i] - values[i - 1]) * (xs[i] - xs[i - 1]);
    }
  }
  return std::nan("");
}

struct Measured
{
  double Width = 0.0;
  double Expected = 0.0;
  double Texel = 0.0;
};

/// The 10-90% width of the rendered penumbra and of the analytic one.
Measured MeasurePenumbra(EdgeScene& scene, vtkRenderPass* pass,
  const std::function<double(double)>& visibility, double centre, double halfWidth)
{
  std::vector<double> xs;
  for (int i = 0; i <= 400; ++i)
  {
    xs.push_back(centre - 2.0 * halfWidth + 4.0 * halfWidth * i / 400.0);
  }
  std::vector<double> truth;
  for (double x : xs)
  {
    truth.push_back(visibility(x));
  }
  const std::vector<double> factor = scene.FactorAlongX(pass, xs);
  Measured m;
  m.Expected = std::abs(Crossing(xs, truth, 0.9) - Crossing(xs, truth, 0.1));
  m.Width = std::abs(Crossing(xs, factor, 0.9) - Crossing(xs, factor, 0.1));
  return m;
}

/// The views of a kind: the uniform map, LiSPSM or cascades.
vtkSmartPointer<vtkShadowMapViews> MakeViews(const std::string& views)
{
  if (views == "cascades")
  {
    return vtkSmartPointer<vtkCascadedShadowMapViews>::New();
  }
  auto warped = vtkSmartPointer<vtkWarpedShadowMapViews>::New();
  warped->SetWarpMode(
    views == "lispsm" ? vtkWarpedShadowMapViews::LISPSM : vtkWarpedShadowMapViews::UNIFORM);
  return warped;
}

/// A pass of maps of `maps` ("depth", "dual", or moments "evsm4", "evsm2",
/// "vsm", "msm", and "evsm4-half", "msm-half" in 16 bits) over views of a kind.
vtkSmartPointer<vtkAbstractShadowMapPass> MakePass(
  const std::string& views, int resolution, const std::string& maps = "depth")
{
  vtkSmartPointer<vtkAbstractShadowMapPass> pass;
  if (maps == "depth")
  {
    pass = vtkSmartPointer<vtkDepthShadowMapPass>::New();
  }
  else if (maps == "dual")
  {
    pass = vtkSmartPointer<vtkDualDepthShadowMapPass>::New();
  }
  else
  {
    auto moments = vtkSmartPointer<vtkVarianceShadowMapPass>::New();
    const std::string kind = maps.substr(0, maps.find('-'));
    moments->SetMoments(kind == "vsm" ? vtkVarianceShadowMapRepresentation::VSM
        : kind == "msm"               ? vtkVarianceShadowMapRepresentation::MSM
        : kind == "evsm2"             ? vtkVarianceShadowMapRepresentation::EVSM2
                                      : vtkVarianceShadowMapRepresentation::EVSM4);
    if (maps.find("-half") != std::string::npos)
    {
      // Exponents 16-bit storage holds, set first (no clamping warning).
      moments->SetPositiveExponent(5.0);
      moments->SetNegativeExponent(5.0);
      moments->SetStorageToHalfFloat();
    }
    pass = moments;
  }
  pass->SetViews(MakeViews(views));
  pass->SetResolution(resolution);
  return pass;
}

const char* const ViewKinds[] = { "uniform", "lispsm", "cascades" };
const std::vector<std::string> AllMaps = { "depth", "dual", "evsm4", "vsm", "msm" };

/// The penumbra width's tolerance, a fraction of the analytic width.
constexpr double WidthTolerance = 0.1;
constexpr int Resolution = 2048;

/// The 10-90% width of the penumbra within 10% of the analytic one under the
/// uniform map, LiSPSM and cascades, for each kind of maps.
void ExpectPenumbraWidthsInEveryView(EdgeScene& scene,
  const std::function<double(double)>& visibility, double centre, double halfWidth,
  const std::string& light, const std::vector<std::string>& mapKinds = { "depth" })
{
  for (const std::string& maps : mapKinds)
  {
    for (const char* views : ViewKinds)
    {
      vtkSmartPointer<vtkRenderPass> pass = MakePass(views, Resolution, maps);
      const Measured m = MeasurePenumbra(scene, pass, visibility, centre, halfWidth);
      std::cout << "[ measured ] " << light << ", edge at " << scene.Height << ", " << maps
                << " maps, " << views << ": 10-90% width " << m.Width << " (analytic "
                << m.Expected << ", " << 100.0 * (m.Width / m.Expected - 1.0) << "%)\n";
      EXPECT_NEAR(m.Width, m.Expected, WidthTolerance * m.Expected)
        << maps << " maps, " << views << " at height " << scene.Height;
      pass->ReleaseGraphicsResources(scene.Window);
    }
  }
}
} // namespace

TEST(ShadowSoft, SunPenumbraWidthOfAnEdgeIsTheDiscs)
{
  const double diameter = 4.0;
  const double elevation = 55.0;
  const glm::dvec3 towardLight(
    -std::cos(glm::radians(elevation)), 0.0, std::sin(glm::radians(elevation)));
  const double sinRadius = std::sin(glm::radians(0.5 * diameter));
  for (double height : { 0.5, 1.5, 3.0 })
  {
    EdgeScene scene(height);
    scene.SetSun(towardLight, diameter);
    const double centre = height * towardLight.x / -towardLight.z;
    const double halfWidth = height * std::tan(glm::radians(0.5 * diameter)) /
      (towardLight.z * towardLight.z);
    scene.LookAt({ centre, 0.0, 0.0 }, 12.0 * halfWidth);
    ExpectPenumbraWidthsInEveryView(scene,
      [&](double x) { return EdgeVisibility(x, height, towardLight, sinRadius); }, centre,
      halfWidth, "sun " + std::to_string(diameter) + " deg", AllMaps);
  }
}

TEST(ShadowSoft, SpotPenumbraWidthOfAnEdgeIsTheSpheres)
{
  const glm::dvec3 lamp(-3.0, 0.0, 8.0);
  const double radius = 0.4;
  for (double height : { 0.5, 1.5, 3.0 })
  {
    EdgeScene scene(height);
    const SpotEdge edge = AimSpotAtEdge(scene, lamp, radius);
    ExpectPenumbraWidthsInEveryView(scene, edge.Visibility, edge.Centre, edge.HalfWidth,
      "spot radius " + std::to_string(radius), AllMaps);
  }
}

// The same spot a tenth of the size, the lamp less than a unit from the ground:
// the blocker's distance along the ray comes from the light depth's own rate
// of change (a unit step toward so near a lamp would pass it).
TEST(ShadowSoft, ASmallSpotsPenumbraScalesWithIt)
{
  const glm::dvec3 lamp(-0.3, 0.0, 0.8);
  const double radius = 0.04;
  const double height = 0.15;
  EdgeScene scene(height);
  const SpotEdge edge = AimSpotAtEdge(scene, lamp, radius);
  for (const char* maps : { "depth", "evsm4" })
  {
    vtkSmartPointer<vtkAbstractShadowMapPass> pass = MakePass("uniform", Resolution, maps);
    const Measured m = MeasurePenumbra(scene, pass, edge.Visibility, edge.Centre, edge.HalfWidth);
    std::cout << "[ measured ] spot radius " << radius << ", edge at " << height << ", " << maps
              << ": 10-90% width " << m.Width << " (analytic " << m.Expected << ")\n";
    EXPECT_NEAR(m.Width, m.Expected, WidthTolerance * m.Expected) << maps;
    pass->ReleaseGraphicsResources(scene.Window);
  }
}

// Every kind of moments with soft shadows compiles its soft code and draws the
// edge's penumbra: 16-bit EVSM4 and MSM (the Chebyshev basis) beside the kinds
// the tests above measure in every view.
TEST(ShadowSoft, EveryKindOfMomentsDrawsTheEdgesPenumbra)
{
  const double diameter = 4.0;
  const glm::dvec3 towardLight(
    -std::cos(glm::radians(55.0)), 0.0, std::sin(glm::radians(55.0)));
  const double sinRadius = std::sin(glm::radians(0.5 * diameter));
  const double height = 1.5;
  EdgeScene scene(height);
  scene.SetSun(towardLight, diameter);
  const double centre = height * towardLight.x / -towardLight.z;
  const double halfWidth =
    height * std::tan(glm::radians(0.5 * diameter)) / (towardLight.z * towardLight.z);
  scene.LookAt({ centre, 0.0, 0.0 }, 12.0 * halfWidth);
  for (const char* maps : { "evsm4-half", "msm-half", "vsm", "msm" })
  {
    vtkSmartPointer<vtkAbstractShadowMapPass> pass = MakePass("uniform", Resolution, maps);
    shadowtest::ErrorCounter counter;
    const Measured m = MeasurePenumbra(scene, pass,
      [&](double x) { return EdgeVisibility(x, height, towardLight, sinRadius); }, centre,
      halfWidth);
    std::cout << "[ measured ] sun " << diameter << " deg, edge at " << height << ", " << maps
              << ": 10-90% width " << m.Width << " (analytic " << m.Expected << ")\n";
    EXPECT_NEAR(m.Width, m.Expected, WidthTolerance * m.Expected) << maps;
    const std::vector<double> ends =
      scene.FactorAlongX(pass, { centre - 2.0 * halfWidth, centre + 2.0 * halfWidth });
    EXPECT_LT(ends[0], 0.05) << maps << ": the umbra is dark";
    EXPECT_GT(ends[1], 0.95) << maps << ": the light is lit";
    EXPECT_EQ(counter.Errors() + counter.Warnings(), 0) << maps << ": " << counter.Text();
    pass->ReleaseGraphicsResources(scene.Window);
  }
}

// A point light whose edge shadow falls across the boundary of two cube faces
// (the direction from the light to the penumbra's centre is the faces'
// diagonal): the width holds, and the profile has no step at the seam, for
// the uniform cube faces and the post-perspective cube.
TEST(ShadowSoft, PointPenumbraCrossesCubeFacesWithoutASeam)
{
  const double height = 1.0;
  const glm::dvec3 lamp(-3.0, 0.0, 4.0);
  const double radius = 0.3;
  const double centre = height * -lamp.x / (lamp.z - height); // 1: from the lamp, (4, 0, -4)
  EdgeScene scene(height);
  scene.SetSpot(lamp, { lamp.x, 0.0, 0.0 }, radius);
  scene.Light->SetConeAngle(180.0);
  const double halfWidth = radius * height / (lamp.z - height);
  scene.LookAt({ centre, 0.0, 0.0 }, 12.0 * halfWidth);
  const auto visibility = [&](double x) {
    const glm::dvec3 toLamp = lamp - glm::dvec3(x, 0.0, 0.0);
    return EdgeVisibility(x, height, glm::normalize(toLamp), radius / glm::length(toLamp));
  };
  for (const std::string& maps : std::vector<std::string>{ "depth", "dual", "evsm4" })
  {
    for (int mode : { vtkWarpedShadowMapViews::UNIFORM, vtkWarpedShadowMapViews::PSM })
    {
      vtkSmartPointer<vtkAbstractShadowMapPass> pass = MakePass("uniform", Resolution, maps);
      vtkWarpedShadowMapViews::SafeDownCast(pass->GetViews())->SetWarpMode(mode);
      const std::string what = maps + " maps, warp " + std::to_string(mode);
      const Measured m = MeasurePenumbra(scene, pass, visibility, centre, halfWidth);
      std::cout << "[ measured ] point radius " << radius << " across cube faces, " << what
                << ": 10-90% width " << m.Width << " (analytic " << m.Expected << ")\n";
      EXPECT_NEAR(m.Width, m.Expected, WidthTolerance * m.Expected) << what;
      // No step: neighbouring samples (a 200th of the penumbra apart) differ
      // by little, and the profile only rises.
      std::vector<double> xs;
      for (int i = 0; i <= 200; ++i)
      {
        xs.push_back(centre - 1.2 * halfWidth + 2.4 * halfWidth * i / 200.0);
      }
      const std::vector<double> factor = scene.FactorAlongX(pass, xs);
      double largestStep = 0.0;
      double largestDrop = 0.0;
      for (std::size_t i = 1; i < factor.size(); ++i)
      {
        largestStep = std::max(largestStep, std::abs(factor[i] - factor[i - 1]));
        largestDrop = std::max(largestDrop, factor[i - 1] - factor[i]);
      }
      EXPECT_LT(largestStep, 0.06) << what;
      EXPECT_LT(largestDrop, 0.04) << what;
      pass->ReleaseGraphicsResources(scene.Window);
    }
  }
}

// Size 0, a negative or non-finite size: the hard shadow, byte for byte, and a
// warning only for the bad values. Maps without soft shadows (ESM and EVSM2
// moments, moments without mipmaps) draw the hard shadow with one warning.
TEST(ShadowSoft, BadSizesAndRepresentationsWithoutSoftShadowsCastHardShadows)
{
  EdgeScene scene(1.0);
  const glm::dvec3 towardLight(-0.5, 0.0, 0.8);
  scene.SetSun(towardLight, 0.0);
  scene.Light->GetInformation()->Remove(vtkAbstractShadowMapPass::LIGHT_SIZE());
  scene.LookAt({ 0.6, 0.0, 0.0 }, 3.0);
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  const std::vector<unsigned char> hard =
    shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window));
  for (double size : { 0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity() })
  {
    scene.Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), size);
    shadowtest::ErrorCounter counter;
    EXPECT_EQ(shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window)), hard) << size;
    shadowtest::RenderAndCapture(scene.Window);
    EXPECT_EQ(counter.Errors(), 0) << counter.Text();
    EXPECT_EQ(counter.Warnings(), size == 0.0 ? 0 : 1) << size << ": " << counter.Text();
    if (size != 0.0)
    {
      EXPECT_NE(counter.Text().find("LIGHT_SIZE"), std::string::npos) << counter.Text();
    }
  }
  // A sun wider than 30 degrees is drawn as a 30 degree one.
  scene.Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), 30.0);
  const std::vector<unsigned char> widest =
    shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window));
  EXPECT_NE(widest, hard);
  scene.Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), 50.0);
  {
    shadowtest::ErrorCounter counter;
    EXPECT_EQ(shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window)), widest);
    EXPECT_EQ(counter.Warnings(), 1) << counter.Text();
  }
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);

  // Size 0 leaves the dual-depth and moment maps' hard frames as they were.
  for (const char* maps : { "dual", "evsm4" })
  {
    vtkSmartPointer<vtkAbstractShadowMapPass> other = MakePass("uniform", 1024, maps);
    scene.Light->GetInformation()->Remove(vtkAbstractShadowMapPass::LIGHT_SIZE());
    scene.Renderer->SetPass(other);
    const std::vector<unsigned char> unsized =
      shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window));
    scene.Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), 0.0);
    EXPECT_EQ(shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window)), unsized) << maps;
    scene.Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), 2.0);
    EXPECT_NE(shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window)), unsized)
      << maps << ": a sized light softens the shadow";
    scene.Renderer->SetPass(nullptr);
    other->ReleaseGraphicsResources(scene.Window);
  }

  // Maps without soft shadows: the hard shadow, one warning.
  vtkNew<vtkVarianceShadowMapPass> exponential;
  exponential->SetMomentsToESM();
  vtkNew<vtkVarianceShadowMapPass> oneWarp;
  oneWarp->SetMomentsToEVSM2();
  vtkNew<vtkVarianceShadowMapPass> unfiltered;
  unfiltered->SetMipmaps(false);
  for (vtkAbstractShadowMapPass* hardOnly : { static_cast<vtkAbstractShadowMapPass*>(exponential),
         static_cast<vtkAbstractShadowMapPass*>(oneWarp),
         static_cast<vtkAbstractShadowMapPass*>(unfiltered) })
  {
    scene.Light->GetInformation()->Remove(vtkAbstractShadowMapPass::LIGHT_SIZE());
    scene.Renderer->SetPass(hardOnly);
    const std::vector<unsigned char> hardFrame =
      shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window));
    EXPECT_NE(hardFrame, widest) << hardOnly->GetClassName() << " draws a shadow";
    scene.Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), 2.0);
    shadowtest::ErrorCounter counter;
    EXPECT_EQ(shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window)), hardFrame)
      << hardOnly->GetClassName();
    shadowtest::RenderAndCapture(scene.Window);
    EXPECT_EQ(counter.Errors(), 0) << counter.Text();
    EXPECT_EQ(counter.Warnings(), 1) << counter.Text();
    EXPECT_NE(counter.Text().find("hard shadows"), std::string::npos) << counter.Text();
    EXPECT_EQ(hardOnly->GetNumberOfShadowedLights(), 1) << hardOnly->GetClassName();
    scene.Renderer->SetPass(nullptr);
    hardOnly->ReleaseGraphicsResources(scene.Window);
  }
}

// A still camera: giving the light a size, changing it and taking it away each
// redraw the shadow at once (a light's MTime does not follow its information),
// and taking it away gives back the hard frame byte for byte.
TEST(ShadowSoft, ChangingTheSizeRedrawsAtOnce)
{
  EdgeScene scene(1.0);
  scene.SetSun({ -0.5, 0.0, 0.8 }, 0.0);
  scene.LookAt({ 0.6, 0.0, 0.0 }, 3.0);
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  const auto frame = [&]() { return scene.StillFrame(); };
  const auto hard = frame();
  EXPECT_EQ(frame(), hard);
  scene.Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), 4.0);
  const auto soft = frame();
  EXPECT_NE(soft, hard);
  scene.Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), 8.0);
  const auto softer = frame();
  EXPECT_NE(softer, soft);
  scene.Light->GetInformation()->Remove(vtkAbstractShadowMapPass::LIGHT_SIZE());
  EXPECT_EQ(frame(), hard);
  pass->SoftShadowsOff();
  scene.Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), 4.0);
  EXPECT_EQ(frame(), hard) << "SoftShadowsOff draws the hard shadow";
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

// Contact hardening: a wall standing on the ground (the plane x = 0, from
// y = -20 to y = 1, 3 high), a sun from +x 45 degrees up. The shadow of the
// wall's end (the vertical edge at y = 1) runs along y = 1 from the wall's foot
// (x = 0) to x = -3: its penumbra is sharp at the foot and widens to about
// 3 sqrt(2) tan(3 deg) = 0.22 on each side at the far end. And a still
// camera's frames are the same, byte for byte.
TEST(ShadowSoft, PenumbraeHardenAtContactAndStillFramesRepeat)
{
  EdgeScene scene(3.0);
  scene.Renderer->RemoveAllViewProps();
  scene.AddQuad({ -20.0, -20.0, 0.0 }, { 20.0, -20.0, 0.0 }, { -20.0, 20.0, 0.0 });
  scene.AddQuad({ 0.0, -20.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, -20.0, 3.0 });
  const double diameter = 6.0;
  scene.SetSun({ 1.0, 0.0, 1.0 }, diameter);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(-1.5, 1.0, 0.0);
  camera->SetPosition(-1.5, 0.0, 5.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  scene.Renderer->ResetCameraClippingRange();
  for (const std::string& maps : std::vector<std::string>{ "depth", "dual", "evsm4" })
  {
    for (const char* viewKind : ViewKinds)
    {
      const std::string views = maps + " maps, " + viewKind;
      vtkSmartPointer<vtkRenderPass> pass = MakePass(viewKind, Resolution, maps);
      scene.Renderer->SetPass(pass);
      const auto first = shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window));
      const auto second = shadowtest::RgbBytes(shadowtest::RenderAndCapture(scene.Window));
      EXPECT_EQ(first, second) << views << ": a still camera's frames repeat";
      scene.Renderer->SetPass(nullptr);
      // Profiles across y = 1 near the foot and toward the far end, 0.01 apart.
      const auto width = [&](double x) {
        std::vector<glm::dvec3> points;
        std::vector<double> ys;
        for (int i = 0; i <= 80; ++i)
        {
          ys.push_back(0.6 + 0.8 * i / 80.0);
          points.emplace_back(x, ys.back(), 0.0);
        }
        const auto factor = scene.FactorAt(pass, points);
        return std::abs(Crossing(ys, factor, 0.9) - Crossing(ys, factor, 0.1));
      };
      const double nearFoot = width(-0.15);
      // Short of the far end, where the top edge's own penumbra begins.
      const double farEnd = width(-2.5);
      // The analytic 10-90% widths: 2 x 0.687 x the penumbra's half width.
      const double expectedFar = 2.0 * 0.687 * 2.5 * std::sqrt(2.0) * std::tan(glm::radians(3.0));
      std::cout << "[ measured ] " << views << ": 10-90% width " << nearFoot << " near the foot, "
                << farEnd << " at the far end (analytic " << expectedFar << ")\n";
      const double expectedNear = 2.0 * 0.687 * 0.15 * std::sqrt(2.0) * std::tan(glm::radians(3.0));
      EXPECT_NEAR(farEnd, expectedFar, 0.1 * expectedFar) << views;
      EXPECT_NEAR(nearFoot, expectedNear, 0.01) << views << ": hard at the contact";
      pass->ReleaseGraphicsResources(scene.Window);
    }
  }
}

// A light sized for OSPRay (vtkOSPRayLightNode::RADIUS, ParaView's light
// Radius) and without LIGHT_SIZE casts the same soft shadow; LIGHT_SIZE wins
// where both are set.
TEST(ShadowSoft, OSPRayRadiusSizesTheLight)
{
  ASSERT_EQ(shadowmaps::OSPRayRadiusKey(), vtkOSPRayLightNode::RADIUS());
  EdgeScene scene(1.0);
  scene.SetSun({ -0.5, 0.0, 0.8 }, 4.0);
  scene.LookAt({ 0.6, 0.0, 0.0 }, 3.0);
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  const auto frame = [&]() { return scene.StillFrame(); };
  const auto sized = frame();
  scene.Light->GetInformation()->Remove(vtkAbstractShadowMapPass::LIGHT_SIZE());
  const auto hard = frame();
  EXPECT_NE(sized, hard);
  scene.Light->GetInformation()->Set(vtkOSPRayLightNode::RADIUS(), 4.0);
  EXPECT_EQ(vtkAbstractShadowMapPass::GetLightSize(scene.Light), 4.0);
  EXPECT_EQ(frame(), sized);
  {
    // A bad radius is named as such.
    scene.Light->GetInformation()->Set(vtkOSPRayLightNode::RADIUS(), 50.0);
    shadowtest::ErrorCounter counter;
    frame();
    EXPECT_EQ(counter.Warnings(), 1) << counter.Text();
    EXPECT_NE(counter.Text().find("first's 50 is taken as 30"), std::string::npos)
      << counter.Text();
  }
  scene.Light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), 0.0);
  EXPECT_EQ(frame(), hard) << "LIGHT_SIZE 0 says hard, whatever OSPRay's radius";
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}
