// Views of a light's own (vtkAbstractShadowMapPass::SetLightViews): a sun in
// cascades and a spot in one uniform map in the same frame, whichever views
// the pass has for the others; the same frame either way round; no shader
// built while the camera moves; the light's views' parameters re-render the
// maps; a light deleted is forgotten.
#include "ShadowTestUtilities.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkUniformShadowMapViews.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLight.h"

#include <gtest/gtest.h>

using namespace shadowtest;

namespace
{
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(1.0, 0.3, -1.0));
const glm::dvec3 SpotPosition(-3.0, -2.0, 6.0);

struct SunAndSpot
{
  TestScene Scene;
  vtkLight* Sun = nullptr;
  vtkNew<vtkLight> Spot;

  SunAndSpot()
  {
    this->Sun = this->Scene.SetSun(SunDirection);
    this->Sun->SetIntensity(0.6);
    this->Spot->SetLightTypeToSceneLight();
    this->Spot->SetPositional(true);
    this->Spot->SetPosition(SpotPosition.x, SpotPosition.y, SpotPosition.z);
    this->Spot->SetFocalPoint(0.0, 0.0, 0.0);
    this->Spot->SetConeAngle(40.0);
    this->Spot->SetAttenuationValues(1.0, 0.0, 0.0);
    this->Spot->SetIntensity(0.6);
    this->Scene.Renderer->AddLight(this->Spot);
    vtkCamera* camera = this->Scene.Renderer->GetActiveCamera();
    camera->SetPosition(0.0, -14.0, 9.0);
    camera->SetFocalPoint(0.0, 0.0, 0.5);
    camera->SetViewUp(0.0, 0.0, 1.0);
    this->Scene.Renderer->ResetCameraClippingRange();
  }
};

vtkSmartPointer<vtkCascadedShadowMapViews> FourCascades()
{
  vtkNew<vtkCascadedShadowMapViews> cascades;
  cascades->SetNumberOfCascades(4);
  return cascades.Get();
}
} // namespace

// The pass's cascades for the sun, the spot's own single map, and the other
// way round: the same views per light give the same frame, in which each
// light's shadow is there.
TEST(ShadowLightViews, EachLightGetsItsOwnViewsWhicheverThePassHas)
{
  vtkSmartPointer<vtkCascadedShadowMapViews> cascades = FourCascades();
  vtkNew<vtkUniformShadowMapViews> single;

  SunAndSpot plain;
  auto withoutShadows = RenderAndCapture(plain.Scene.Window);

  SunAndSpot cascadedPass;
  vtkNew<vtkDepthShadowMapPass> first;
  first->SetViews(cascades);
  first->SetLightViews(cascadedPass.Spot, single);
  cascadedPass.Scene.Renderer->SetPass(first);
  ErrorCounter errors;
  auto frame = RenderAndCapture(cascadedPass.Scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_EQ(first->GetNumberOfShadowedLights(), 2);
  EXPECT_EQ(first->GetNumberOfShadowMapLayers(), 5) << "four cascades and one map";
  EXPECT_EQ(first->GetLightViews(cascadedPass.Spot), single.Get());
  EXPECT_EQ(first->GetLightViews(cascadedPass.Sun), cascades.Get());

  SunAndSpot uniformPass;
  vtkNew<vtkDepthShadowMapPass> second;
  second->SetViews(single);
  second->SetLightViews(uniformPass.Sun, cascades);
  uniformPass.Scene.Renderer->SetPass(second);
  auto same = RenderAndCapture(uniformPass.Scene.Window);
  EXPECT_EQ(second->GetNumberOfShadowMapLayers(), 5);
  EXPECT_EQ(RgbBytes(frame), RgbBytes(same)) << "the same views per light, the same frame";

  // Each light's shadow of the sphere: darker than the frame without shadows
  // (the other light still lights it).
  for (const glm::dvec3& shadow :
    { GroundShadowOfSphereCenter(SunDirection), GroundShadowOfSphereCenterFrom(SpotPosition) })
  {
    const double lit = LuminanceAt(plain.Scene.Renderer, withoutShadows, shadow);
    EXPECT_LT(LuminanceAt(cascadedPass.Scene.Renderer, frame, shadow), 0.75 * lit);
  }
}

// Both lights' views as the pass has them again: the spot back in cascades.
TEST(ShadowLightViews, NoViewsGivesTheLightThePassesViewsAgain)
{
  SunAndSpot scene;
  vtkNew<vtkDepthShadowMapPass> pass;
  pass->SetViews(FourCascades());
  scene.Scene.Renderer->SetPass(pass);
  RenderAndCapture(scene.Scene.Window);
  const int layersInCascades = pass->GetNumberOfShadowMapLayers();
  auto cascaded = RenderAndCapture(scene.Scene.Window);

  vtkNew<vtkUniformShadowMapViews> single;
  pass->SetLightViews(scene.Spot, single);
  RenderAndCapture(scene.Scene.Window);
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 5);
  EXPECT_GT(layersInCascades, 5) << "the spot's cascades";

  pass->SetLightViews(scene.Spot, nullptr);
  auto again = RenderAndCapture(scene.Scene.Window);
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), layersInCascades);
  EXPECT_EQ(pass->GetLightViews(scene.Spot), pass->GetViews());
  EXPECT_EQ(RgbBytes(cascaded), RgbBytes(again));
}

// Mixed views build each receiver's shader once: an orbit, still and
// interactive frames, builds none.
TEST(ShadowLightViews, AnOrbitWithMixedViewsBuildsNoShader)
{
  SunAndSpot scene;
  vtkNew<vtkDepthShadowMapPass> pass;
  pass->SetViews(FourCascades());
  vtkNew<vtkUniformShadowMapViews> single;
  pass->SetLightViews(scene.Spot, single);
  scene.Scene.Renderer->SetPass(pass);
  RenderAndCapture(scene.Scene.Window);
  const int builds = pass->GetNumberOfShaderBuilds();
  OrbitDraggedThenStill(scene.Scene);
  EXPECT_EQ(pass->GetNumberOfShaderBuilds(), builds);
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 5);
}

// A parameter of a light's own views re-renders the maps; once the light is
// deleted, its views are forgotten and change nothing.
TEST(ShadowLightViews, TheLightsViewsParametersRenderAndADeletedLightIsForgotten)
{
  SunAndSpot scene;
  vtkNew<vtkDepthShadowMapPass> pass;
  vtkSmartPointer<vtkCascadedShadowMapViews> cascades = FourCascades();
  pass->SetLightViews(scene.Sun, cascades);
  scene.Scene.Renderer->SetPass(pass);
  scene.Scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 5);
  cascades->SetNumberOfCascades(2);
  scene.Scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 3) << "two cascades and one map";

  scene.Scene.Renderer->RemoveLight(scene.Sun);
  scene.Sun = nullptr; // the renderer held the last reference
  scene.Scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowedLights(), 1);
  const vtkMTimeType before = pass->GetMTime();
  cascades->SetNumberOfCascades(3);
  EXPECT_EQ(pass->GetMTime(), before) << "a deleted light's views still count";
  const int updates = pass->GetNumberOfShadowMapUpdates();
  scene.Scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates);
}

// No light: a warning, and nothing changes.
TEST(ShadowLightViews, NoLightIsRefused)
{
  vtkNew<vtkDepthShadowMapPass> pass;
  vtkNew<vtkUniformShadowMapViews> single;
  ErrorCounter errors;
  pass->SetLightViews(nullptr, single);
  EXPECT_EQ(errors.Warnings(), 1);
  EXPECT_EQ(pass->GetLightViews(nullptr), pass->GetViews());
}
