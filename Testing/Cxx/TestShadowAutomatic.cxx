// vtkAutomaticShadowMapPass: each light gets the views of its row of the
// measured table (shadowmaps::ViewsRules) and the frame is the one those views
// give by hand; a choice changes only in still frames (no shader built while
// the camera moves) and only past the rows' margin; the user may pin the views
// of every light or of one; processes holding different pieces choose the
// same; shadows are where they fall, and the frame matches its baseline.
#include "ShadowMapAnalysis.h"
#include "ShadowMapGlm.h"
#include "ShadowMapLightChoices.h"
#include "ShadowMapViewsRules.h"
#include "ShadowTestUtilities.h"
#include "vtkDepthShadowMapRepresentation.h"
#include "vtkAutomaticShadowMapPass.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkShadowMapExchange.h"
#include "vtkUniformShadowMapViews.h"
#include "vtkWarpedShadowMapViews.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkWarpedShadowMapPass.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <glm/gtc/type_ptr.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <vector>

using namespace shadowtest;

namespace
{
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(1.0, 0.2, -0.45));
const glm::dvec3 SpotPosition(-3.0, -2.0, 6.0);
const glm::dvec3 PointPosition(3.0, -3.0, 5.0);
/// Maps where the choice, not the picture, is tested.
constexpr int SmallMaps = 512;

/// The test scene lit by a sun, a spot and a point light, seen from `azimuth`
/// degrees around the z axis (0: from -y), 20 degrees above the ground.
struct ThreeLights
{
  TestScene Scene;
  vtkLight* Sun = nullptr;
  vtkNew<vtkLight> Spot;
  vtkNew<vtkLight> Point;

  ThreeLights()
  {
    this->Sun = this->Scene.SetSun(SunDirection);
    this->Sun->SetIntensity(0.5);
    AddPositional(this->Spot, SpotPosition, 40.0);
    AddPositional(this->Point, PointPosition, 180.0);
    this->Look(0.0);
  }

  void AddPositional(vtkLight* light, const glm::dvec3& position, double cone)
  {
    light->SetLightTypeToSceneLight();
    light->SetPositional(true);
    light->SetPosition(position.x, position.y, position.z);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    light->SetConeAngle(cone);
    light->SetAttenuationValues(1.0, 0.0, 0.0);
    light->SetIntensity(0.4);
    this->Scene.Renderer->AddLight(light);
  }

  void Look(double azimuth)
  {
    const double a = vtkMath::RadiansFromDegrees(azimuth);
    const double e = vtkMath::RadiansFromDegrees(20.0);
    const double distance = 16.0;
    vtkCamera* camera = this->Scene.Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.5);
    camera->SetPosition(distance * std::cos(e) * std::sin(a), -distance * std::cos(e) * std::cos(a),
      0.5 + distance * std::sin(e));
    camera->SetViewUp(0.0, 0.0, 1.0);
    this->Scene.Renderer->ResetCameraClippingRange();
  }
};

/// A views object like the automatic pass's candidate of `chosen`.
vtkSmartPointer<vtkShadowMapViews> ViewsLike(int chosen)
{
  switch (chosen)
  {
    case vtkAutomaticShadowMapPass::CASCADED_VIEWS:
      return vtkSmartPointer<vtkCascadedShadowMapViews>::New();
    case vtkAutomaticShadowMapPass::UNIFORM_VIEWS:
      return vtkSmartPointer<vtkUniformShadowMapViews>::New();
    default:
    {
      auto warped = vtkSmartPointer<vtkWarpedShadowMapViews>::New();
      warped->SetWarpMode(chosen == vtkAutomaticShadowMapPass::LISPSM_VIEWS
          ? vtkWarpedShadowMapViews::LISPSM
          : chosen == vtkAutomaticShadowMapPass::TSM_VIEWS ? vtkWarpedShadowMapViews::TSM
                                                           : vtkWarpedShadowMapViews::PSM);
      if (chosen == vtkAutomaticShadowMapPass::PSM_CUBE_VIEWS)
      {
        warped->SetPSMCubeMapToAlways();
      }
      return warped;
    }
  }
}

/// A point light beside a street-level camera that walks from looking past it
/// at the whole scene (t = 0: every prop in view, so none builds its shader
/// later for entering it) to seeing the light side-on (t = 1).
struct WalkPastALamp
{
  TestScene Scene;
  WalkPastALamp() { this->Scene.SetPoint({ 8.0, 0.0, 3.0 }); }

  void Walk(double t)
  {
    const glm::dvec3 position = glm::mix(glm::dvec3(8.0, -10.0, 3.0), glm::dvec3(2.0, -2.0, 3.0), t);
    const glm::dvec3 focal = glm::mix(glm::dvec3(2.0, 0.0, 1.0), glm::dvec3(2.0, 10.0, 3.0), t);
    vtkCamera* camera = this->Scene.Renderer->GetActiveCamera();
    camera->SetPosition(position.x, position.y, position.z);
    camera->SetFocalPoint(focal.x, focal.y, focal.z);
    camera->SetViewUp(0.0, 0.0, 1.0);
    this->Scene.Renderer->ResetCameraClippingRange();
  }
};

/// The lamp's chosen views of a fresh pass at `t` of the walk.
int FreshChoice(double t)
{
  WalkPastALamp walk;
  walk.Walk(t);
  vtkNew<vtkAutomaticShadowMapPass> pass;
  pass->SetResolution(SmallMaps);
  walk.Scene.Renderer->SetPass(pass);
  walk.Scene.Window->Render();
  return pass->GetChosenViews(0);
}
/// One process of several whose others render still frames: whatever this
/// one asks, another says yes (a still frame somewhere, a translucent caster
/// somewhere); the maps' texels are this process's alone.
class OthersStill : public vtkShadowMapExchange
{
public:
  static OthersStill* New();
  vtkTypeMacro(OthersStill, vtkShadowMapExchange);
  bool AnyOf(bool) override { return true; }
  bool MinimumOf(std::vector<float>&) override { return true; }
};
vtkStandardNewMacro(OthersStill);
} // namespace

// Each light's views are its row's; the frame is the dual-depth pass's with
// the same views given by hand, at half the resolution while a light is in
// cascades.
TEST(ShadowAutomatic, EachLightGetsItsRowsViewsAndTheFrameTheyGive)
{
  ThreeLights automatic;
  vtkNew<vtkAutomaticShadowMapPass> pass;
  pass->SetResolution(SmallMaps);
  automatic.Scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  auto frame = RenderAndCapture(automatic.Scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  ASSERT_EQ(pass->GetNumberOfShadowedLights(), 3);
  EXPECT_EQ(pass->GetChosenViews(3), -2) << "no fourth light";

  const glm::dmat4 view = shadowmaps::ToGlm(
    automatic.Scene.Renderer->GetActiveCamera()->GetViewTransformMatrix());
  ThreeLights byHand;
  vtkNew<vtkDualDepthShadowMapPass> reference;
  vtkLight* lights[] = { byHand.Sun, byHand.Spot, byHand.Point };
  bool cascades = false;
  for (int i = 0; i < 3; ++i)
  {
    shadowmaps::ShadowLight light;
    vtkLight* original = i == 0 ? automatic.Sun : i == 1 ? automatic.Spot.Get() : automatic.Point.Get();
    light.Kind = i == 0 ? shadowmaps::LightKind::Directional
      : i == 1          ? shadowmaps::LightKind::Spot
                        : shadowmaps::LightKind::Point;
    light.Position = glm::make_vec3(original->GetPosition());
    light.Direction = glm::make_vec3(original->GetFocalPoint()) - light.Position;
    light.ConeAngle = original->GetConeAngle();
    const auto& rules = shadowmaps::ViewsRules();
    const int row = shadowmaps::ChooseViewsRule(rules, shadowmaps::SituationOf(light, view, false), -1);
    ASSERT_GE(row, 0);
    EXPECT_EQ(pass->GetChosenViews(i), static_cast<int>(rules[row].Views)) << "light " << i;
    EXPECT_EQ(pass->GetChosenRepresentation(i), vtkAutomaticShadowMapPass::DUAL_DEPTH_REPRESENTATION);
    EXPECT_STREQ(pass->GetChosenRepresentationName(i), "dual depth");
    reference->SetLightViews(lights[i], ViewsLike(pass->GetChosenViews(i)));
    cascades = cascades || pass->GetChosenViews(i) == vtkAutomaticShadowMapPass::CASCADED_VIEWS;
  }
  reference->SetResolution(cascades ? pass->GetResolution() / 2 : pass->GetResolution());
  byHand.Scene.Renderer->SetPass(reference);
  auto same = RenderAndCapture(byHand.Scene.Window);
  EXPECT_EQ(RgbBytes(frame), RgbBytes(same));
  EXPECT_EQ(pass->GetShadowMapMemory(), reference->GetShadowMapMemory());
}

// Walking past a lamp, from facing it to seeing it side-on, changes its row:
// interactive frames keep the row and build no shader; the still frame after
// takes the new row.
TEST(ShadowAutomatic, ChoicesChangeOnlyInStillFrames)
{
  const int first = FreshChoice(0.0);
  const int last = FreshChoice(1.0);
  ASSERT_NE(first, last) << "the table gives the lamp the same views at both ends of the walk";

  WalkPastALamp walk;
  vtkNew<vtkAutomaticShadowMapPass> pass;
  pass->SetResolution(SmallMaps);
  walk.Walk(0.0);
  walk.Scene.Renderer->SetPass(pass);
  walk.Scene.Window->Render();
  ASSERT_EQ(pass->GetChosenViews(0), first);
  const int builds = pass->GetNumberOfShaderBuilds();
  const int steps = 12;
  for (int i = 1; i <= steps; ++i)
  {
    walk.Scene.Window->SetDesiredUpdateRate(15.0);
    walk.Walk(static_cast<double>(i) / steps);
    walk.Scene.Window->Render();
    EXPECT_EQ(pass->GetChosenViews(0), first) << "step " << i;
  }
  EXPECT_EQ(pass->GetNumberOfShaderBuilds(), builds) << "a shader built while moving";
  walk.Scene.Window->SetDesiredUpdateRate(0.0001);
  walk.Scene.Window->Render();
  EXPECT_EQ(pass->GetChosenViews(0), last);
  EXPECT_GT(pass->GetNumberOfShaderBuilds(), builds) << "the new views' receivers";
}

// In parallel, a light's views change in the same frame on every process:
// while another process renders still frames, this one's interactive frames
// take the new row too.
TEST(ShadowAutomatic, ProcessesChangeViewsInTheSameFrame)
{
  const int last = FreshChoice(1.0);
  WalkPastALamp walk;
  vtkNew<vtkAutomaticShadowMapPass> pass;
  pass->SetResolution(SmallMaps);
  vtkNew<OthersStill> exchange;
  pass->SetExchange(exchange);
  walk.Walk(0.0);
  walk.Scene.Renderer->SetPass(pass);
  walk.Scene.Window->Render();
  ASSERT_NE(pass->GetChosenViews(0), last);
  walk.Scene.Window->SetDesiredUpdateRate(15.0);
  walk.Walk(1.0);
  walk.Scene.Window->Render();
  EXPECT_EQ(pass->GetChosenViews(0), last) << "an interactive frame here, a still one elsewhere";
}

// A lamp two renderers of the pass see differently (side-on in one, faced in
// the other) keeps one views: still frames build no shader after the first.
TEST(ShadowAutomatic, ALightTwoRenderersSeeDifferentlyKeepsItsViews)
{
  WalkPastALamp walk;
  walk.Walk(1.0);
  vtkNew<vtkRenderer> other;
  other->AutomaticLightCreationOff();
  other->AddLight(vtkLight::SafeDownCast(walk.Scene.Renderer->GetLights()->GetItemAsObject(0)));
  for (vtkActor* actor : { walk.Scene.Ground.Get(), walk.Scene.Sphere.Get(), walk.Scene.Box.Get() })
  {
    other->AddActor(actor);
  }
  walk.Scene.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
  other->SetViewport(0.5, 0.0, 1.0, 1.0);
  walk.Scene.Window->AddRenderer(other);
  other->GetActiveCamera()->SetPosition(8.0, -10.0, 3.0);
  other->GetActiveCamera()->SetFocalPoint(2.0, 0.0, 1.0);
  other->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  other->ResetCameraClippingRange();
  vtkNew<vtkAutomaticShadowMapPass> pass;
  pass->SetResolution(SmallMaps);
  walk.Scene.Renderer->SetPass(pass);
  other->SetPass(pass);
  walk.Scene.Window->Render();
  walk.Scene.Window->Render();
  const int builds = pass->GetNumberOfShaderBuilds();
  for (int i = 0; i < 3; ++i)
  {
    walk.Scene.Window->Render();
  }
  EXPECT_EQ(pass->GetNumberOfShaderBuilds(), builds);
  walk.Scene.Renderer->SetPass(nullptr);
  other->SetPass(nullptr);
}

// A light keeps its row while its situation stays within the margin past the
// row's range, and takes the row that holds it beyond.
TEST(ShadowAutomatic, ARowIsKeptWithinItsMargin)
{
  using shadowmaps::LightKind;
  using shadowmaps::ViewsKind;
  const std::vector<shadowmaps::ViewsRule> rules = {
    { LightKind::Directional, 0.0, 1.0, -1, -1, ViewsKind::TSM },
    { LightKind::Directional, -1.0, 1.0, -1, -1, ViewsKind::Cascades },
  };
  shadowmaps::LightSituation situation;
  situation.CosLightView = 0.02;
  EXPECT_EQ(shadowmaps::ChooseViewsRule(rules, situation, -1, 1.0, 0.05), 0);
  situation.CosLightView = -0.02;
  EXPECT_EQ(shadowmaps::ChooseViewsRule(rules, situation, -1, 1.0, 0.05), 1) << "fresh: the first row holding it";
  EXPECT_EQ(shadowmaps::ChooseViewsRule(rules, situation, 0, 1.0, 0.05), 0) << "within the margin";
  situation.CosLightView = -0.06;
  EXPECT_EQ(shadowmaps::ChooseViewsRule(rules, situation, 0, 1.0, 0.05), 1) << "past the margin";
  situation.CosLightView = 0.02;
  EXPECT_EQ(shadowmaps::ChooseViewsRule(rules, situation, 1, 1.0, 0.05), 1) << "the wider row keeps it";
  situation.CosLightView = 0.06;
  EXPECT_EQ(shadowmaps::ChooseViewsRule(rules, situation, 1, 1.0, 0.05), 0)
    << "the earlier row takes it past the margin";
  situation.CosLightView = 0.98;
  EXPECT_EQ(shadowmaps::ChooseViewsRule(rules, situation, 1, 1.0, 0.05), 0)
    << "the range's end at 1 is no boundary";
  situation.Kind = LightKind::Spot;
  EXPECT_EQ(shadowmaps::ChooseViewsRule(rules, situation, 1, 1.0, 0.05), -1) << "no row for spots";

  // A row over the budget is passed over.
  const std::vector<shadowmaps::ViewsRule> costly = {
    { LightKind::Directional, -1.0, 1.0, -1, -1, ViewsKind::PSMCube, 6.0 },
    { LightKind::Directional, -1.0, 1.0, -1, -1, ViewsKind::LiSPSM, 1.0 },
  };
  situation.Kind = LightKind::Directional;
  EXPECT_EQ(shadowmaps::ChooseViewsRule(costly, situation, -1, 1.0), 1);
  EXPECT_EQ(shadowmaps::ChooseViewsRule(costly, situation, -1, 6.0), 0);
  EXPECT_EQ(shadowmaps::ChooseViewsRule(costly, situation, 0, 2.0), 1) << "no longer allowed";

  // LightChoices: a known light keeps its row in interactive frames.
  vtkNew<vtkLight> light;
  shadowmaps::LightChoices choices;
  situation.Kind = LightKind::Directional;
  situation.CosLightView = 0.5;
  EXPECT_TRUE(choices.Update(nullptr, { { light, situation } }, true, rules));
  EXPECT_EQ(choices.Choices().front().Rule, 0) << "a new light is chosen for at once";
  situation.CosLightView = -0.5;
  EXPECT_FALSE(choices.Update(nullptr, { { light, situation } }, true, rules));
  EXPECT_EQ(choices.Choices().front().Rule, 0);
  EXPECT_TRUE(choices.Update(nullptr, { { light, situation } }, false, rules));
  EXPECT_EQ(choices.Choices().front().Rule, 1);
}

// Every light pinned to one views kind, and one light pinned to the user's
// views, which the pass leaves alone.
TEST(ShadowAutomatic, TheUserPinsEveryLightsViewsOrOnes)
{
  ThreeLights scene;
  vtkNew<vtkAutomaticShadowMapPass> pass;
  pass->SetResolution(SmallMaps);
  pass->SetViewsChoiceToTSM();
  scene.Scene.Renderer->SetPass(pass);
  scene.Scene.Window->Render();
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(pass->GetChosenViews(i), vtkAutomaticShadowMapPass::TSM_VIEWS);
    EXPECT_STREQ(pass->GetChosenViewsName(i), "tsm");
  }
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 1 + 1 + 6) << "the point light's cube faces";

  vtkNew<vtkUniformShadowMapViews> mine;
  pass->SetViewsChoiceToAutomatic();
  pass->SetLightViews(scene.Spot, mine);
  scene.Scene.Window->Render();
  EXPECT_EQ(pass->GetChosenViews(1), vtkAutomaticShadowMapPass::USER_VIEWS);
  EXPECT_STREQ(pass->GetChosenViewsName(1), "user");
  EXPECT_EQ(pass->GetLightViews(scene.Spot), mine.Get());
  EXPECT_NE(pass->GetChosenViews(0), vtkAutomaticShadowMapPass::USER_VIEWS);

  pass->SetLightViews(scene.Spot, nullptr);
  scene.Scene.Window->Render();
  EXPECT_NE(pass->GetChosenViews(1), vtkAutomaticShadowMapPass::USER_VIEWS) << "unpinned";

  // A light's representation: its own maps, reported as chosen.
  vtkNew<vtkDepthShadowMapRepresentation> depth;
  pass->SetLightRepresentation(scene.Spot, depth);
  scene.Scene.Window->Render();
  EXPECT_EQ(pass->GetChosenRepresentation(1), vtkAutomaticShadowMapPass::DEPTH_REPRESENTATION);
  EXPECT_STREQ(pass->GetChosenRepresentationName(1), "depth");
  EXPECT_STREQ(pass->GetChosenRepresentationName(0), "dual depth");
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 2);
  pass->SetLightRepresentation(scene.Spot, nullptr);
  scene.Scene.Window->Render();
  EXPECT_STREQ(pass->GetChosenRepresentationName(1), "dual depth");
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 1);

  // The budget: the sun's one map, or Kozlov's cube of up to six.
  EXPECT_EQ(pass->GetChosenViews(0), vtkAutomaticShadowMapPass::LISPSM_VIEWS);
  const int oneMap = pass->GetNumberOfShadowMapLayers();
  pass->SetCostBudget(6.0);
  scene.Scene.Window->Render();
  EXPECT_EQ(pass->GetChosenViews(0), vtkAutomaticShadowMapPass::PSM_CUBE_VIEWS);
  EXPECT_GT(pass->GetNumberOfShadowMapLayers(), oneMap);
  pass->SetCostBudget(100.0);
  EXPECT_EQ(pass->GetCostBudget(), 16.0) << "clamped";

  // The pass's InteractiveTexelRatio reaches the views it chooses.
  pass->SetInteractiveTexelRatio(1.0);
  scene.Scene.Window->Render();
  EXPECT_EQ(pass->GetLightViews(scene.Sun)->GetInteractiveTexelRatio(), 1.0);
  pass->SetViewsChoice(42);
  EXPECT_EQ(pass->GetViewsChoice(), vtkAutomaticShadowMapPass::AUTOMATIC_VIEWS) << "clamped";
}

// Processes holding different pieces of the scene choose the same: the
// choice reads the lights and the camera, not the props.
TEST(ShadowAutomatic, ProcessesHoldingDifferentPiecesChooseTheSame)
{
  for (double azimuth : { 0.0, 150.0 })
  {
    ThreeLights whole;
    ThreeLights piece;
    whole.Look(azimuth);
    piece.Look(azimuth);
    piece.Scene.Renderer->RemoveActor(piece.Scene.Sphere);
    piece.Scene.Renderer->RemoveActor(piece.Scene.Box);
    vtkNew<vtkAutomaticShadowMapPass> wholePass;
    vtkNew<vtkAutomaticShadowMapPass> piecePass;
    wholePass->SetResolution(SmallMaps);
    piecePass->SetResolution(SmallMaps);
    whole.Scene.Renderer->SetPass(wholePass);
    piece.Scene.Renderer->SetPass(piecePass);
    whole.Scene.Window->Render();
    piece.Scene.Window->Render();
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_EQ(wholePass->GetChosenViews(i), piecePass->GetChosenViews(i)) << azimuth;
    }
  }
}

// The sphere's shadow from each light is dark and the open ground lit; the
// frame matches its baseline.
TEST(ShadowAutomatic, ShadowsFallWhereTheyShould)
{
  for (int lightIndex = 0; lightIndex < 3; ++lightIndex)
  {
    TestScene scene;
    vtkLight* light = lightIndex == 0 ? scene.SetSun(SunDirection)
      : lightIndex == 1               ? scene.SetSpot(SpotPosition, 40.0)
                                      : scene.SetPoint(PointPosition);
    (void)light;
    vtkNew<vtkAutomaticShadowMapPass> pass;
    scene.Renderer->SetPass(pass);
    ErrorCounter errors;
    auto frame = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
    const glm::dvec3 shadow = lightIndex == 0 ? GroundShadowOfSphereCenter(SunDirection)
                                              : GroundShadowOfSphereCenterFrom(
                                                  lightIndex == 1 ? SpotPosition : PointPosition);
    const glm::dvec3 open = shadow + glm::dvec3(0.0, -2.5, 0.0);
    EXPECT_LT(LuminanceAt(scene.Renderer, frame, shadow), 0.6 * LuminanceAt(scene.Renderer, frame, open))
      << pass->GetChosenViewsName(0);
    const std::string name = std::string("AutomaticPass") + (lightIndex == 0 ? "Sun" : lightIndex == 1 ? "Spot" : "Point");
    EXPECT_EQ(CompareWithBaseline(frame, name), "") << name;
  }
}

// A drag that must draw the maps draws them at half the resolution, kept from
// then on in the drag; the still frame after draws them at full resolution,
// the same frame as a fresh pass's. The drag's maps are kept beside the still
// ones, so that later drags allocate nothing; no shader is built.
TEST(ShadowAutomatic, DragsDrawCoarserMapsAndStillFramesFullOnes)
{
  WalkPastALamp walk;
  vtkNew<vtkAutomaticShadowMapPass> pass;
  pass->SetResolution(SmallMaps);
  EXPECT_EQ(pass->GetInteractiveResolutionScale(), 0.5);
  walk.Walk(0.0);
  walk.Scene.Renderer->SetPass(pass);
  walk.Scene.Window->Render();
  EXPECT_EQ(pass->GetShadowMapResolution(), SmallMaps);
  const size_t stillMemory = pass->GetShadowMapMemory();
  const int builds = pass->GetNumberOfShaderBuilds();
  size_t memoryAfterFirstDrag = 0;
  for (int drag = 0; drag < 2; ++drag)
  {
    bool drawn = false;
    const int steps = 6;
    for (int i = 1; i <= steps; ++i)
    {
      walk.Scene.Window->SetDesiredUpdateRate(15.0);
      walk.Walk((drag == 0 ? 0.0 : 0.5) + 0.5 * i / steps);
      walk.Scene.Window->Render();
      drawn = drawn || pass->GetNumberOfRenderedLayers() > 0;
      EXPECT_EQ(pass->GetShadowMapResolution(), drawn ? SmallMaps / 2 : SmallMaps)
        << "drag " << drag << " step " << i;
    }
    ASSERT_TRUE(drawn) << "the drag kept the still frame's maps throughout";
    walk.Scene.Window->SetDesiredUpdateRate(0.0001);
    walk.Scene.Window->Render();
    EXPECT_EQ(pass->GetShadowMapResolution(), SmallMaps);
    EXPECT_GT(pass->GetNumberOfRenderedLayers(), 0) << "drag " << drag;
    auto still = RenderAndCapture(walk.Scene.Window);

    WalkPastALamp fresh;
    fresh.Walk(drag == 0 ? 0.5 : 1.0);
    vtkNew<vtkAutomaticShadowMapPass> freshPass;
    freshPass->SetResolution(SmallMaps);
    fresh.Scene.Renderer->SetPass(freshPass);
    auto expected = RenderAndCapture(fresh.Scene.Window);
    ASSERT_EQ(freshPass->GetChosenViews(0), pass->GetChosenViews(0));
    EXPECT_EQ(RgbBytes(still), RgbBytes(expected)) << "drag " << drag;
    fresh.Scene.Renderer->SetPass(nullptr);
    if (drag == 0)
    {
      memoryAfterFirstDrag = pass->GetShadowMapMemory();
      EXPECT_GT(memoryAfterFirstDrag, stillMemory) << "the drag's maps kept";
    }
  }
  EXPECT_EQ(pass->GetShadowMapMemory(), memoryAfterFirstDrag) << "the second drag reused them";
  EXPECT_GT(pass->GetNumberOfShaderBuilds(), builds) << "the lamp's new views, in a still frame";

  // Scale 1: drags draw full maps, and no spare is kept.
  pass->SetInteractiveResolutionScale(1.0);
  walk.Walk(0.0);
  walk.Scene.Window->SetDesiredUpdateRate(15.0);
  walk.Scene.Window->Render();
  EXPECT_GT(pass->GetNumberOfRenderedLayers(), 0);
  EXPECT_EQ(pass->GetShadowMapResolution(), SmallMaps);
  pass->SetInteractiveResolutionScale(0.0);
  EXPECT_EQ(pass->GetInteractiveResolutionScale(), 0.0625) << "clamped";
}

namespace
{
/// The colour most pixels of `image` have, the background's aside.
glm::ivec3 CommonestColour(vtkImageData* image)
{
  const std::vector<unsigned char> rgb = RgbBytes(image);
  std::map<std::tuple<int, int, int>, int> counts;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
  {
    ++counts[{ rgb[i], rgb[i + 1], rgb[i + 2] }];
  }
  for (auto it = counts.begin(); it != counts.end();)
  {
    const auto& [r, g, b] = it->first;
    const bool background = std::abs(r - 51) <= 1 && std::abs(g - 77) <= 1 &&
      std::abs(b - 102) <= 1; // TestScene's (0.2, 0.3, 0.4)
    it = background ? counts.erase(it) : std::next(it);
  }
  if (counts.empty())
  {
    return { -1, -1, -1 }; // nothing but background
  }
  const auto commonest = std::max_element(counts.begin(), counts.end(),
    [](const auto& a, const auto& b) { return a.second < b.second; });
  const auto& [r, g, b] = commonest->first;
  return { r, g, b };
}

/// Whether `colour` is the CHOSEN_VIEWS legend's for `kind`, in an even or an
/// odd map, lit.
bool IsLegendColour(const glm::ivec3& colour, const std::string& kind)
{
  const std::array<float, 3> legend = shadowmaps::ViewsKindColor(kind);
  for (double shade : { 1.0, 0.75 })
  {
    bool same = true;
    for (int c = 0; c < 3; ++c)
    {
      same = same && std::abs(colour[c] - 255.0 * shade * legend[c]) <= 1.0;
    }
    if (same)
    {
      return true;
    }
  }
  return false;
}

/// The kind of views (vtkShadowMapViews::GetKindName) a light of `kind` gets
/// from the automatic pass's `chosen` views.
std::string KindOfChosen(int chosen, shadowmaps::LightKind kind)
{
  if (kind == shadowmaps::LightKind::Point)
  {
    return chosen == vtkAutomaticShadowMapPass::PSM_VIEWS ||
        chosen == vtkAutomaticShadowMapPass::PSM_CUBE_VIEWS
      ? "psm-cube"
      : "cube faces";
  }
  return shadowmaps::ViewsKindName(static_cast<shadowmaps::ViewsKind>(chosen));
}
} // namespace

// The CHOSEN_VIEWS analysis view colours what each light got: the legend's
// colour of its chosen views covers most of the frame, and follows the choice
// when it changes.
TEST(ShadowAutomatic, ChosenViewsAnalysisColoursWhatEachLightGot)
{
  ThreeLights three;
  vtkNew<vtkAutomaticShadowMapPass> pass;
  pass->SetResolution(SmallMaps);
  pass->SetAnalysisViewToChosenViews();
  three.Scene.Renderer->SetPass(pass);
  const shadowmaps::LightKind kinds[] = { shadowmaps::LightKind::Directional,
    shadowmaps::LightKind::Spot, shadowmaps::LightKind::Point };
  std::set<std::tuple<int, int, int>> colours;
  for (int i = 0; i < 3; ++i)
  {
    pass->SetAnalysisLight(i);
    ErrorCounter errors;
    auto image = RenderAndCapture(three.Scene.Window);
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
    const std::string kind = KindOfChosen(pass->GetChosenViews(i), kinds[i]);
    const glm::ivec3 commonest = CommonestColour(image);
    EXPECT_TRUE(IsLegendColour(commonest, kind))
      << "light " << i << " got " << kind << "; the frame is mostly " << commonest.r << " "
      << commonest.g << " " << commonest.b;
    colours.insert({ commonest.r, commonest.g, commonest.b });
  }
  EXPECT_EQ(colours.size(), 3u) << "the sun, the spot and the point light got different views";

  // The lamp of the walk: its uniform cube faces first, Kozlov's cube side-on.
  for (double t : { 0.0, 1.0 })
  {
    WalkPastALamp walk;
    walk.Walk(t);
    vtkNew<vtkAutomaticShadowMapPass> lamp;
    lamp->SetResolution(SmallMaps);
    lamp->SetAnalysisViewToChosenViews();
    walk.Scene.Renderer->SetPass(lamp);
    auto image = RenderAndCapture(walk.Scene.Window);
    const std::string kind = KindOfChosen(lamp->GetChosenViews(0), shadowmaps::LightKind::Point);
    EXPECT_EQ(kind, t == 0.0 ? "cube faces" : "psm-cube");
    const glm::ivec3 commonest = CommonestColour(image);
    EXPECT_TRUE(IsLegendColour(commonest, kind))
      << "t = " << t << ": the frame is mostly " << commonest.r << " " << commonest.g << " "
      << commonest.b;
  }
}

// A warp that cannot be made (a parallel camera) falls back to the focused
// uniform map, and the chosen-views analysis colours what was rendered.
TEST(ShadowAutomatic, ChosenViewsAnalysisTellsAWarpsFallBack)
{
  for (const bool parallel : { false, true })
  {
    TestScene scene;
    scene.SetSun(glm::normalize(glm::dvec3(-0.4, 0.3, -1.0)));
    scene.Renderer->GetActiveCamera()->SetParallelProjection(parallel);
    vtkNew<vtkWarpedShadowMapPass> pass;
    pass->SetWarpModeToLiSPSM();
    pass->SetResolution(SmallMaps);
    pass->SetAnalysisViewToChosenViews();
    scene.Renderer->SetPass(pass);
    auto image = RenderAndCapture(scene.Window);
    const std::string kind = parallel ? "uniform" : "lispsm";
    const glm::ivec3 commonest = CommonestColour(image);
    EXPECT_TRUE(IsLegendColour(commonest, kind))
      << "parallel " << parallel << ": the frame is mostly " << commonest.r << " " << commonest.g
      << " " << commonest.b << ", not " << kind << "'s colour";
  }
}
