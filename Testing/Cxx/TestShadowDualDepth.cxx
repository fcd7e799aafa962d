// vtkDualDepthShadowMapPass: second-depth, midpoint and dual maps, each made by
// minimum blending or depth peeling, rendered with every bias parameter at 0.
#include "ShadowTestUtilities.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkWarpedShadowMapViews.h"

#include "vtkActor.h"
#include "vtkContourFilter.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkRTAnalyticSource.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <tuple>

using namespace shadowtest;

namespace
{
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(-0.4, 0.3, -1.0));

const char* ModeName(int mode)
{
  return mode == vtkDualDepthShadowMapPass::SECOND_DEPTH ? "SecondDepth"
    : mode == vtkDualDepthShadowMapPass::MIDPOINT        ? "Midpoint"
                                                          : "Dual";
}

const char* MethodName(int method)
{
  return method == vtkDualDepthShadowMapPass::MINIMUM_BLENDING ? "MinimumBlending"
    : method == vtkDualDepthShadowMapPass::DEPTH_PEELING       ? "DepthPeeling"
                                                               : "Auto";
}

vtkSmartPointer<vtkActor> AddBox(vtkRenderer* renderer, const glm::dvec3& center, const glm::dvec3& size)
{
  vtkNew<vtkCubeSource> box;
  box->SetCenter(center.x, center.y, center.z);
  box->SetXLength(size.x);
  box->SetYLength(size.y);
  box->SetZLength(size.z);
  return AddSourceActor(renderer, box);
}

vtkSmartPointer<vtkDualDepthShadowMapPass> MakeUnbiasedPass(int mode, int method)
{
  auto pass = vtkSmartPointer<vtkDualDepthShadowMapPass>::New();
  pass->SetMode(mode);
  pass->SetLayerMethod(method);
  pass->SetResolution(512);
  // Every bias parameter at zero, whatever the defaults.
  pass->SetNormalOffset(0.0);
  pass->SetConstantBias(0.0);
  pass->SetSlopeScaledBias(0.0);
  return pass;
}
} // namespace

class DualDepthModes : public ::testing::TestWithParam<std::tuple<int, int>>
{
};

// The standard scene: the sphere's shadow on the ground, and the sunlit faces
// of the sphere, the box and the ground lit although nothing is biased.
TEST_P(DualDepthModes, ShadowsWithoutBias)
{
  const int mode = std::get<0>(GetParam());
  const int method = std::get<1>(GetParam());
  TestScene scene;
  scene.SetSun(SunDirection);
  auto pass = MakeUnbiasedPass(mode, method);
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)),
    ShadowedBelow);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { -5, -4, 0 }), LitAbove);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, glm::dvec3(0, 0, 1.5) - SunDirection), LitAbove);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { 4, 2, 1.5 }), LitAbove);
  const std::string difference =
    CompareWithBaseline(image, std::string("DualDepth") + ModeName(mode) + MethodName(method));
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(Modes, DualDepthModes,
  ::testing::Combine(::testing::Values(vtkDualDepthShadowMapPass::SECOND_DEPTH,
                       vtkDualDepthShadowMapPass::MIDPOINT, vtkDualDepthShadowMapPass::DUAL),
    ::testing::Values(vtkDualDepthShadowMapPass::MINIMUM_BLENDING,
      vtkDualDepthShadowMapPass::DEPTH_PEELING)),
  [](const ::testing::TestParamInfo<std::tuple<int, int>>& info) {
    return std::string(ModeName(std::get<0>(info.param))) + MethodName(std::get<1>(info.param));
  });

// AUTO peels when a caster is open (the ground plane), and makes both depths
// in one pass when every caster is closed (the sphere and the box).
TEST(DualDepth, AutoPeelsOnlyForOpenCasters)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  auto pass = MakeUnbiasedPass(vtkDualDepthShadowMapPass::DUAL, vtkDualDepthShadowMapPass::AUTO);
  scene.Renderer->SetPass(pass);
  RenderAndCapture(scene.Window);
  EXPECT_EQ(pass->GetNumberOfCasterPassesPerLayer(), 2);
  scene.Ground->GetPropertyKeys()->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  scene.Ground->Modified();
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(pass->GetNumberOfCasterPassesPerLayer(), 1);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)),
    ShadowedBelow);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

namespace
{
/// A scene of the spec's list on the test ground (the standard sphere and box
/// hidden), with where its probes are.
struct DualDepthScene
{
  std::string Name;
  std::function<void(TestScene&)> Build;
  /// Points the sun reaches: lit, with no acne.
  std::vector<glm::dvec3> Lit;
  /// Points in a shadow, contact shadows among them.
  std::vector<glm::dvec3> Shadowed;
};

glm::dvec3 GroundShadowOf(const glm::dvec3& point)
{
  return point + SunDirection * (point.z / -SunDirection.z);
}

std::vector<DualDepthScene> DualDepthScenes()
{
  std::vector<DualDepthScene> scenes;
  // An open plane casting on the ground: one surface per texel.
  scenes.push_back({ "OpenPlane",
    [](TestScene& scene) {
      vtkNew<vtkPlaneSource> plane;
      plane->SetOrigin(-1.5, -1.5, 1.5);
      plane->SetPoint1(1.5, -1.5, 1.5);
      plane->SetPoint2(-1.5, 1.5, 1.5);
      AddSourceActor(scene.Renderer, plane);
    },
    { { 0.0, -1.0, 1.5 }, { -5.0, -4.0, 0.0 } }, { GroundShadowOf({ 0.0, -1.0, 1.5 }) } });
  // An isosurface cut open by the volume's boundary (the bottom of its extent).
  scenes.push_back({ "Isosurface",
    [](TestScene& scene) {
      vtkNew<vtkRTAnalyticSource> field;
      field->SetWholeExtent(-10, 10, -10, 10, 0, 10);
      vtkNew<vtkContourFilter> contour;
      contour->SetInputConnection(field->GetOutputPort());
      contour->SetValue(0, 160.0);
      auto actor = AddSourceActor(scene.Renderer, contour);
      actor->GetMapper()->ScalarVisibilityOff();
      actor->SetScale(0.1);
      actor->SetPosition(0.0, 0.0, 1.5);
    },
    { { -5.0, -4.0, 0.0 } }, { GroundShadowOf({ 0.0, 0.0, 1.9 }) } });
  // Two boxes touching along a face, on the ground: contact shadows at their
  // feet, lit tops.
  scenes.push_back({ "TouchingBoxes",
    [](TestScene& scene) {
      AddBox(scene.Renderer, { -1.0, 0.0, 0.75 }, { 1.5, 1.5, 1.5 });
      AddBox(scene.Renderer, { 0.5, 0.0, 0.5 }, { 1.5, 1.5, 1.0 });
    },
    { { -1.0, -0.2, 1.5 }, { 0.5, -0.2, 1.0 }, { -5.0, -4.0, 0.0 } },
    { { -1.8, -0.5, 0.0 }, { -1.8, 0.5, 0.0 } } });
  // A sheet thinner than a texel, floating.
  scenes.push_back({ "ThinSheet",
    [](TestScene& scene) { AddBox(scene.Renderer, { 0.0, 0.0, 1.2 }, { 3.0, 3.0, 0.01 }); },
    { { 0.0, -1.0, 1.205 }, { -5.0, -4.0, 0.0 } }, { GroundShadowOf({ 0.0, -1.0, 1.2 }) } });
  return scenes;
}
} // namespace

class DualDepthScenesAndModes
  : public ::testing::TestWithParam<std::tuple<std::string, int>>
{
};

TEST_P(DualDepthScenesAndModes, LitFacesAndContactShadowsWithoutBias)
{
  const std::string name = std::get<0>(GetParam());
  const int mode = std::get<1>(GetParam());
  DualDepthScene spec;
  for (const auto& candidate : DualDepthScenes())
  {
    if (candidate.Name == name)
    {
      spec = candidate;
    }
  }
  TestScene scene;
  scene.SetSun(SunDirection);
  scene.Sphere->SetVisibility(false);
  scene.Box->SetVisibility(false);
  spec.Build(scene);
  auto pass = MakeUnbiasedPass(mode, vtkDualDepthShadowMapPass::AUTO);
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  for (const auto& point : spec.Lit)
  {
    EXPECT_GT(LuminanceAt(scene.Renderer, image, point), LitAbove)
      << "lit at " << point.x << ", " << point.y << ", " << point.z;
  }
  for (const auto& point : spec.Shadowed)
  {
    EXPECT_LT(LuminanceAt(scene.Renderer, image, point), ShadowedBelow)
      << "shadowed at " << point.x << ", " << point.y << ", " << point.z;
  }
  const std::string difference =
    CompareWithBaseline(image, "DualDepth" + name + ModeName(mode));
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(Scenes, DualDepthScenesAndModes,
  ::testing::Combine(::testing::Values("OpenPlane", "Isosurface", "TouchingBoxes", "ThinSheet"),
    ::testing::Values(vtkDualDepthShadowMapPass::SECOND_DEPTH, vtkDualDepthShadowMapPass::MIDPOINT,
      vtkDualDepthShadowMapPass::DUAL)),
  [](const ::testing::TestParamInfo<std::tuple<std::string, int>>& info) {
    return std::get<0>(info.param) + ModeName(std::get<1>(info.param));
  });
