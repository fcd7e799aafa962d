// The translucent casters' test scene (TestShadowTranslucent,
// TestShadowVolumes): a ground seen from above, one light of each kind, and
// what reaches the ground per channel against the transmission model.
#ifndef TranslucentScene_h
#define TranslucentScene_h

#include "ShadowTestUtilities.h"

#include "vtkAbstractShadowMapPass.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkVarianceShadowMapPass.h"
#include "vtkWarpedShadowMapPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <functional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace translucenttest
{
using namespace shadowtest;

inline const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(1.0, 0.5, -1.0));
inline const glm::dvec3 LampPosition(-6.0, -3.0, 8.0);

enum class LightKind
{
  Sun,
  Spot,
  Point
};

/// A 20 x 20 ground and square slabs above it, lit by one light, seen from
/// above by a parallel camera.
struct SlabScene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkLight> Light;
  LightKind Kind;

  explicit SlabScene(LightKind kind = LightKind::Sun)
    : Kind(kind)
  {
    this->Window->SetSize(400, 400);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->AutomaticLightCreationOff();
    this->Ground = this->Add(Square({ 0.0, 0.0, 0.0 }, 20.0));
    this->Light->SetLightTypeToSceneLight();
    this->Light->SetPositional(kind != LightKind::Sun);
    if (kind == LightKind::Sun)
    {
      this->Light->SetPosition(-SunDirection.x, -SunDirection.y, -SunDirection.z);
      this->Light->SetFocalPoint(0.0, 0.0, 0.0);
    }
    else
    {
      this->Light->SetPosition(LampPosition.x, LampPosition.y, LampPosition.z);
      this->Light->SetFocalPoint(2.0, 1.0, 0.0);
      this->Light->SetConeAngle(kind == LightKind::Spot ? 50.0 : 180.0);
    }
    this->Renderer->AddLight(this->Light);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetPosition(0.0, 0.0, 30.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(6.0);
  }

  static vtkSmartPointer<vtkPlaneSource> Square(const glm::dvec3& centre, double side)
  {
    auto square = vtkSmartPointer<vtkPlaneSource>::New();
    square->SetOrigin(centre.x - 0.5 * side, centre.y - 0.5 * side, centre.z);
    square->SetPoint1(centre.x + 0.5 * side, centre.y - 0.5 * side, centre.z);
    square->SetPoint2(centre.x - 0.5 * side, centre.y + 0.5 * side, centre.z);
    return square;
  }

  vtkActor* Add(vtkAlgorithm* source) { return AddSourceActor(this->Renderer, source); }

  /// A slab of `side` centred on `centre`, of colour and opacity.
  vtkActor* AddSlab(const glm::dvec3& centre, double side, const glm::dvec3& color, double opacity)
  {
    vtkActor* slab = this->Add(Square(centre, side));
    slab->GetProperty()->SetColor(color.x, color.y, color.z);
    slab->GetProperty()->SetOpacity(opacity);
    return slab;
  }

  /// Where the light carries `point` to the ground.
  glm::dvec3 GroundUnder(const glm::dvec3& point) const
  {
    const glm::dvec3 direction = this->Kind == LightKind::Sun ? SunDirection : point - LampPosition;
    return point - (point.z / direction.z) * direction;
  }

  /// The frame with receivers showing the light's visibility per channel
  /// (SHADOW_FACTOR), or shaded (`analysis` false).
  vtkSmartPointer<vtkImageData> Render(vtkAbstractShadowMapPass* pass, bool analysis = true)
  {
    analysis ? pass->SetAnalysisViewToShadowFactor() : pass->SetAnalysisViewToNone();
    this->Renderer->SetPass(pass);
    ErrorCounter errors;
    auto image = RenderAndCapture(this->Window);
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
    return image;
  }

  /// What reaches `world` of the light, per channel, in a SHADOW_FACTOR frame.
  glm::dvec3 Measured(vtkImageData* image, const glm::dvec3& world) const
  {
    return glm::dvec3(ColorAt(this->Renderer, image, world)) / 255.0;
  }

  vtkActor* Ground = nullptr;
};

inline glm::dvec3 Model(const glm::dvec3& color, double opacity)
{
  double transmitted[3];
  const double c[3] = { color.x, color.y, color.z };
  vtkAbstractShadowMapPass::GetTransmittance(c, opacity, transmitted);
  return { transmitted[0], transmitted[1], transmitted[2] };
}

inline std::string Text(const glm::dvec3& v)
{
  return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

inline void ExpectNear(const glm::dvec3& measured, const glm::dvec3& expected, double tolerance,
  const std::string& what)
{
  std::cout << "[ measured ] " << what << ": " << Text(measured) << ", expected "
            << Text(expected) << "\n";
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(measured[c], expected[c], tolerance) << what << ", channel " << c;
  }
}

using PassMaker = std::function<vtkSmartPointer<vtkAbstractShadowMapPass>()>;

template <typename Pass>
PassMaker Make()
{
  return [] { return vtkSmartPointer<vtkAbstractShadowMapPass>(vtkSmartPointer<Pass>::New()); };
}

/// Every representation, and the warped and cascaded layouts.
inline const std::vector<std::pair<std::string, PassMaker>> Passes = {
  { "depth", Make<vtkDepthShadowMapPass>() },
  { "warped", Make<vtkWarpedShadowMapPass>() },
  { "cascades", Make<vtkCascadedShadowMapPass>() },
  { "dual depth", Make<vtkDualDepthShadowMapPass>() },
  { "variance", Make<vtkVarianceShadowMapPass>() },
};

inline std::string KindName(LightKind kind)
{
  return kind == LightKind::Sun ? "sun" : kind == LightKind::Spot ? "spot" : "point light";
}
} // namespace translucenttest

#endif
