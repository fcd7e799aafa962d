// Which technique `vtkshadows analyze` recommends (Measurement/
// ShadowRecommendation.h), the light kinds of the set-ups it groups by
// (ShadowScenes.h), and its progress line (ShadowProgress.h).
#include "ShadowProgress.h"
#include "ShadowRecommendation.h"
#include "ShadowScenes.h"

#include "vtkAbstractShadowMapPass.h"

#include <vtkCamera.h>
#include <vtkInformation.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <sstream>

namespace
{
using shadowbench::MeasuredCase;
using shadowbench::Recommend;

MeasuredCase Case(const std::string& setup, const std::string& technique, double misclassified,
  double steady, double moving, bool ours = true)
{
  return { "file", setup, technique, ours ? "vtkSomePass" : "", 1024, misclassified, steady, moving,
    1000 };
}

// The size a set-up gives its light (vtkAbstractShadowMapPass::LIGHT_SIZE).
double SetupLightSize(const std::string& setup)
{
  vtkNew<vtkRenderer> renderer;
  renderer->GetActiveCamera()->SetPosition(0.0, -10.0, 0.0); // 10 from the focal point
  EXPECT_TRUE(shadowscenes::AddLightSetup(renderer, setup)) << setup;
  return vtkAbstractShadowMapPass::GetLightSize(
    vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0)));
}

TEST(ShadowScenesSetups, SizedSetupsNameTheirLightsKindAndSize)
{
  for (const char* setup : { "soft-spot", "soft-spot-5", "soft-spot-25" })
  {
    EXPECT_EQ(shadowscenes::LightKindOfSetup(setup), "spot") << setup;
  }
  for (const char* setup : { "soft-point", "soft-point-0.5" })
  {
    EXPECT_EQ(shadowscenes::LightKindOfSetup(setup), "point") << setup;
  }
  EXPECT_EQ(shadowscenes::LightKindOfSetup("soft-sun-8"), "sun");
  for (const char* setup : { "soft-spot-0", "soft-spot-26", "soft-point-x", "soft-spot-",
         "soft-sun-31", "soft-lamp-5" })
  {
    EXPECT_FALSE(shadowscenes::IsLightSetup(setup)) << setup;
  }
  EXPECT_NEAR(SetupLightSize("soft-spot"), 0.2, 1e-9); // 2% of the distance
  EXPECT_NEAR(SetupLightSize("soft-spot-5"), 0.5, 1e-9);
  EXPECT_NEAR(SetupLightSize("soft-point-0.5"), 0.05, 1e-9);
  EXPECT_NEAR(SetupLightSize("soft-sun"), 0.53, 1e-9); // degrees
  EXPECT_NEAR(SetupLightSize("soft-sun-8"), 8.0, 1e-9);
}

// The lamp behind the viewer stands over the camera itself, not over the focal
// point: its shadows run away down the view from the camera's feet.
TEST(ShadowScenesSetups, LampBehindStandsBehindAndAboveTheCamera)
{
  vtkNew<vtkRenderer> renderer;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(3.0, -10.0, 2.0); // looking along +y and down, 10 from its focal point
  camera->SetFocalPoint(3.0, -2.0, -4.0);
  ASSERT_TRUE(shadowscenes::AddLightSetup(renderer, "lamp-behind"));
  EXPECT_EQ(shadowscenes::LightKindOfSetup("lamp-behind"), "point");
  vtkLight* lamp = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
  ASSERT_NE(lamp, nullptr);
  EXPECT_TRUE(lamp->GetPositional());
  EXPECT_EQ(lamp->GetConeAngle(), 180.0);
  double position[3];
  lamp->GetPosition(position);
  EXPECT_NEAR(position[0], 3.0, 1e-9);
  EXPECT_NEAR(position[1], -10.5, 1e-9); // 0.05 d behind the camera along the ground
  EXPECT_NEAR(position[2], 10.0, 1e-9);  // 0.8 d above it
}

TEST(ShadowRecommendation, TheMostAccurateWithinTheBudgetAndTheRunnerUp)
{
  const std::vector<MeasuredCase> cases = {
    Case("perpendicular", "none", 9.0, 0.8, 0.8, false),
    Case("perpendicular", "vtk", 20.0, 0.9, 0.9, false),
    Case("perpendicular", "uniform", 1.0, 1.0, 1.0),
    Case("perpendicular", "csm", 0.4, 1.2, 1.24),
    Case("perpendicular", "lispsm", 0.6, 1.1, 1.1),
    Case("perpendicular", "second-depth", 0.1, 1.2, 1.6), // moving over the budget
  };
  const auto recommendations = Recommend(cases, 1.25);
  ASSERT_EQ(recommendations.size(), 1u);
  const auto& r = recommendations[0];
  EXPECT_EQ(r.LightKind, "sun");
  ASSERT_TRUE(r.HasBest);
  EXPECT_EQ(r.Best.Technique, "csm");
  EXPECT_NEAR(r.Best.Cost, 1.24, 1e-12) << "the larger of the steady and moving ratios";
  ASSERT_TRUE(r.HasRunnerUp);
  EXPECT_EQ(r.RunnerUp.Technique, "lispsm");
  ASSERT_TRUE(r.HasOverBudget);
  EXPECT_EQ(r.MostAccurate.Technique, "second-depth");
  EXPECT_NE(r.Why.find("second-depth"), std::string::npos) << r.Why;
}

TEST(ShadowRecommendation, OneRecommendationPerLightKindAveragedOverItsSetups)
{
  const std::vector<MeasuredCase> cases = {
    Case("perpendicular", "uniform", 1.0, 1.0, 1.0),
    Case("perpendicular", "csm", 0.2, 1.1, 1.1),
    Case("facing", "uniform", 1.0, 1.0, 1.0),
    Case("facing", "csm", 2.0, 1.1, 1.1), // mean 1.1: worse than the uniform map's 1.0
    Case("spot", "uniform", 0.5, 1.0, 1.0),
    Case("spot", "csm", 0.3, 2.0, 2.0),
    Case("point", "csm", 0.1, 1.0, 1.0), // no uniform map measured here
  };
  const auto recommendations = Recommend(cases, 1.25);
  ASSERT_EQ(recommendations.size(), 3u);
  EXPECT_EQ(recommendations[0].LightKind, "sun");
  EXPECT_EQ(recommendations[0].Setups, (std::vector<std::string>{ "perpendicular", "facing" }));
  EXPECT_EQ(recommendations[0].Best.Technique, "uniform");
  EXPECT_NEAR(recommendations[0].RunnerUp.Misclassified, 1.1, 1e-12);
  EXPECT_EQ(recommendations[1].LightKind, "spot");
  EXPECT_EQ(recommendations[1].Best.Technique, "uniform") << "csm is over the budget";
  EXPECT_FALSE(recommendations[1].HasRunnerUp);
  EXPECT_EQ(recommendations[2].LightKind, "point");
  EXPECT_FALSE(recommendations[2].HasBest) << "no cost reference";
  EXPECT_NE(recommendations[2].Why.find("uniform"), std::string::npos);
}

// An error over no counted pixel (a view with no receiver) was not measured:
// its 0% must not win.
TEST(ShadowRecommendation, ErrorsOverNoPixelAreNotMeasurements)
{
  MeasuredCase empty = Case("perpendicular", "csm", 0.0, 1.0, 1.0);
  empty.Counted = 0;
  const std::vector<MeasuredCase> cases = { Case("perpendicular", "uniform", 1.0, 1.0, 1.0),
    Case("perpendicular", "lispsm", 0.5, 1.1, 1.1), empty };
  const auto recommendations = Recommend(cases, 1.25);
  ASSERT_EQ(recommendations.size(), 1u);
  EXPECT_EQ(recommendations[0].Best.Technique, "lispsm");
  EXPECT_EQ(recommendations[0].RunnerUp.Technique, "uniform");
}

TEST(ShadowRecommendation, WrittenAsMarkdownAndJSON)
{
  const std::vector<MeasuredCase> cases = { Case("spot", "uniform", 0.5, 1.0, 1.0),
    Case("spot", "lispsm", 0.25, 1.0, 1.1) };
  const auto recommendations = Recommend(cases, 1.25);
  std::ostringstream markdown;
  shadowbench::WriteRecommendationsMarkdown(recommendations, markdown);
  EXPECT_NE(markdown.str().find("| file | spot | spot | lispsm |"), std::string::npos) << markdown.str();
  std::ostringstream json;
  shadowbench::WriteRecommendationsJSON(recommendations, json);
  EXPECT_NE(json.str().find("\"best\": {\"technique\": \"lispsm\""), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"runner_up\": {\"technique\": \"uniform\""), std::string::npos);
  MeasuredCase odd = Case("spot", "uniform", 0.5, 1.0, 1.0);
  odd.Scene = "a \"quoted\"\tscene\n";
  std::ostringstream escaped;
  shadowbench::WriteRecommendationsJSON(Recommend({ odd }, 1.25), escaped);
  EXPECT_NE(escaped.str().find("\"a \\\"quoted\\\"\\u0009scene\\u000a\""), std::string::npos)
    << escaped.str();
}

TEST(ShadowProgress, TheTimeLeftFollowsTheWorkDone)
{
  EXPECT_EQ(shadowbench::ProgressLine(0.0, 100.0, 0.0), "[0%, 0:00 so far]");
  EXPECT_EQ(shadowbench::ProgressLine(25.0, 100.0, 30.0), "[25%, 0:30 so far, about 1:30 left]");
  EXPECT_EQ(shadowbench::ProgressLine(50.0, 100.0, 61.0), "[50%, 1:01 so far, about 1:01 left]");
  EXPECT_EQ(shadowbench::ProgressLine(100.0, 100.0, 90.0), "[100%, 1:30 so far]");
  EXPECT_EQ(shadowbench::ProgressLine(150.0, 100.0, 90.0), "[100%, 1:30 so far]") << "clamped";
}
} // namespace
