// vtkCascadedShadowMapPass on the standard test scene seen along the ground:
// floating cubes whose shadows land at chosen view depths probe the first and
// last cascade, a blend band and the maximum shadow distance; a pole behind the
// camera must shadow into the first cascade; bad input clamps with warnings.
#include "ShadowTestUtilities.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkWarpedShadowMapPass.h"

#include "ShadowMapCrop.h"
#include "ShadowMapLight.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

using namespace shadowtest;

namespace
{
const glm::dvec3 Eye(0.0, -9.5, 1.2);
const glm::dvec3 Target(0.0, 0.0, 0.8);
const glm::dvec3 Sun = glm::normalize(glm::dvec3(1.0, 0.15, -0.8));

void LookAlongTheGround(TestScene& scene)
{
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(Eye.x, Eye.y, Eye.z);
  camera->SetFocalPoint(Target.x, Target.y, Target.z);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetClippingRange(0.1, 40.0);
}

// The ground point at view depth `depth` on the line x = `x`.
glm::dvec3 GroundAtDepth(double depth, double x)
{
  const glm::dvec3 v = glm::normalize(Target - Eye);
  const double y = (depth - (x - Eye.x) * v.x + Eye.z * v.z) / v.y + Eye.y;
  return { x, y, 0.0 };
}

void AddBox(TestScene& scene, const glm::dvec3& center, const glm::dvec3& size)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(center.x, center.y, center.z);
  cube->SetXLength(size.x);
  cube->SetYLength(size.y);
  cube->SetZLength(size.z);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.5, 0.8, 0.5);
  scene.Renderer->AddActor(actor);
}

// A box floating 1 above the ground whose centre's shadow falls on `ground`,
// long along the view so that its shadow stays several pixels tall far away.
void AddFloatingCubeShadowingAt(TestScene& scene, const glm::dvec3& ground)
{
  AddBox(scene, ground - Sun * (1.0 / -Sun.z), { 0.6, 2.5, 0.6 });
}

// Explicit splits 6, 11, 15.5; shadows end at 18.5 (fading from 16.65).
const double ProbeDepths[] = { 5.0, 10.75, 14.0, 16.0, 19.0 };
constexpr double ProbeX = -1.0;

vtkSmartPointer<vtkCascadedShadowMapPass> MakeProbedPass()
{
  auto pass = vtkSmartPointer<vtkCascadedShadowMapPass>::New();
  pass->AddSplitDistance(6.0);
  pass->AddSplitDistance(11.0);
  pass->AddSplitDistance(15.5);
  pass->SetMaximumShadowDistance(18.5);
  pass->SetResolution(512);
  return pass;
}

void BuildProbedScene(TestScene& scene)
{
  LookAlongTheGround(scene);
  scene.SetSun(Sun);
  for (double depth : ProbeDepths)
  {
    AddFloatingCubeShadowingAt(scene, GroundAtDepth(depth, ProbeX));
  }
}

double DepthOf(const glm::dvec3& p)
{
  return glm::dot(p - Eye, glm::normalize(Target - Eye));
}

// View depth of every pixel from the depth buffer (the background gets +inf).
std::vector<double> PixelDepths(TestScene& scene)
{
  int* size = scene.Window->GetSize();
  std::vector<float> z(static_cast<size_t>(size[0]) * size[1]);
  scene.Window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, z.data());
  double range[2];
  scene.Renderer->GetActiveCamera()->GetClippingRange(range);
  std::vector<double> depth(z.size());
  for (size_t i = 0; i < z.size(); ++i)
  {
    const double ndc = 2.0 * z[i] - 1.0;
    depth[i] = z[i] >= 1.0f ? INFINITY
                            : 2.0 * range[0] * range[1] / (range[1] + range[0] - ndc * (range[1] - range[0]));
  }
  return depth;
}

// What the probed scene must show: the four probes shadowed, ground past the
// maximum shadow distance lit, and lit ground beside the shadows, near and far.
void ExpectProbesShadowedAndGroundLit(TestScene& scene, vtkImageData* image, const std::string& name)
{
  for (int i = 0; i < 4; ++i)
  {
    const glm::dvec3 probe = GroundAtDepth(ProbeDepths[i], ProbeX);
    ASSERT_GE(ColorAt(scene.Renderer, image, probe).r, 0) << "probe " << i << " off the image";
    EXPECT_LT(LuminanceAt(scene.Renderer, image, probe), ShadowedBelow) << name << " probe " << i;
  }
  EXPECT_GT(LuminanceAt(scene.Renderer, image, GroundAtDepth(ProbeDepths[4], ProbeX)), LitAbove) << name;
  EXPECT_GT(LuminanceAt(scene.Renderer, image, GroundAtDepth(5.0, 0.8)), LitAbove) << name;
  EXPECT_GT(LuminanceAt(scene.Renderer, image, GroundAtDepth(14.0, -3.5)), LitAbove) << name;
}
} // namespace

TEST(ShadowCascades, ProbesInEveryCascadeTheBlendBandAndPastTheMaximumDistance)
{
  for (int fit : { vtkCascadedShadowMapPass::STABLE, vtkCascadedShadowMapPass::TIGHT })
  {
    TestScene scene;
    BuildProbedScene(scene);
    auto pass = MakeProbedPass();
    pass->SetFitMode(fit);
    scene.Renderer->SetPass(pass);
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    const std::string name = fit == vtkCascadedShadowMapPass::STABLE ? "CascadesStable" : "CascadesTight";
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
    ASSERT_EQ(pass->GetNumberOfSplits(), 5);
    EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 4);
    EXPECT_DOUBLE_EQ(pass->GetSplit(1), 6.0);
    EXPECT_DOUBLE_EQ(pass->GetSplit(4), 18.5);
    // First cascade, blend band of the second, third, last, past the maximum distance.
    EXPECT_LT(DepthOf(GroundAtDepth(ProbeDepths[0], ProbeX)), pass->GetSplit(1));
    EXPECT_GT(ProbeDepths[1], 11.0 - 0.1 * (11.0 - 6.0));
    EXPECT_GT(ProbeDepths[3], pass->GetSplit(3));
    ExpectProbesShadowedAndGroundLit(scene, image, name);
    const std::string difference = CompareWithBaseline(image, name);
    EXPECT_TRUE(difference.empty()) << difference;
  }
}

TEST(ShadowCascades, PartitionViewShowsTheCascades)
{
  TestScene scene;
  BuildProbedScene(scene);
  auto pass = MakeProbedPass();
  pass->SetAnalysisView(vtkAbstractShadowMapPass::PARTITION);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  // Palette: cascade 0 red, 1 green, 2 blue, 3 yellow (see vtkShadowPartitionColor).
  const glm::ivec3 first = ColorAt(scene.Renderer, image, GroundAtDepth(4.5, 0.8));
  const glm::ivec3 third = ColorAt(scene.Renderer, image, GroundAtDepth(13.0, -3.5));
  EXPECT_GT(first.r, 2 * first.g);
  EXPECT_GT(first.r, 2 * first.b);
  EXPECT_GT(third.b, 2 * third.r);
  EXPECT_GT(third.b, third.g);
}

TEST(ShadowCascades, CasterBehindTheCameraShadowsTheFirstCascade)
{
  TestScene scene;
  LookAlongTheGround(scene);
  const glm::dvec3 sunBehind = glm::normalize(glm::dvec3(0.25, 1.0, -0.9));
  scene.SetSun(sunBehind);
  // A pole 8 high behind the camera, outside every sub-frustum.
  const glm::dvec3 foot(-2.0, -12.0, 0.0);
  AddBox(scene, foot + glm::dvec3(0.0, 0.0, 4.0), { 0.4, 0.4, 8.0 });
  auto pass = vtkSmartPointer<vtkCascadedShadowMapPass>::New();
  pass->SetResolution(512);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  // The shadow of the pole's point 7 up.
  const glm::dvec3 shadow = foot + glm::dvec3(sunBehind.x, sunBehind.y, 0.0) * (7.0 / -sunBehind.z);
  ASSERT_GE(ColorAt(scene.Renderer, image, shadow).r, 0);
  EXPECT_LT(DepthOf(shadow), pass->GetSplit(1)) << "the shadow is in the first cascade";
  EXPECT_LT(LuminanceAt(scene.Renderer, image, shadow), ShadowedBelow);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, shadow + glm::dvec3(1.5, 0.0, 0.0)), LitAbove);
}

TEST(ShadowCascades, EachCascadeDrawsOnlyTheCastersItSees)
{
  TestScene scene;
  BuildProbedScene(scene);
  auto single = MakeProbedPass();
  single->RemoveAllSplitDistances();
  single->SetNumberOfCascades(1);
  scene.Renderer->SetPass(single);
  RenderAndCapture(scene.Window);
  const int casters = single->GetNumberOfCasterDraws();
  EXPECT_EQ(casters, 3 + 5) << "ground, sphere, box and five cubes";

  // Without the culling by shadow reach, every caster is in some cascade.
  auto four = MakeProbedPass();
  four->ShadowReachCullingOff();
  scene.Renderer->SetPass(four);
  RenderAndCapture(scene.Window);
  EXPECT_GE(four->GetNumberOfCasterDraws(), casters);
  EXPECT_LT(four->GetNumberOfCasterDraws(), 4 * casters);
}


// Boxes on a grid around the probed scene, many beside or behind the view, some
// just outside it, whose shadows may or may not reach what the camera sees.
void AddBoxesAround(TestScene& scene)
{
  for (int i = -4; i <= 4; ++i)
  {
    for (int j = -2; j <= 6; ++j)
    {
      AddBox(scene, { 3.0 * i + 0.5, 3.0 * j, 0.75 }, { 0.5, 0.5, 1.5 });
    }
  }
}

// A view draws only the casters whose shadows can reach what it shades: fewer
// draws, and not one pixel changes, whatever the views, the light, the window's
// shape, the fade and the representation (two-surface maps keep the casters
// behind the receivers).
class ReachCulling : public ::testing::TestWithParam<std::string>
{
public:
  vtkSmartPointer<vtkAbstractShadowMapPass> MakePass() const
  {
    const std::string& kind = GetParam();
    if (kind == "StableCascades" || kind == "Spot" || kind == "Point")
    {
      return MakeProbedPass();
    }
    if (kind == "TightLiSPSMCascades" || kind == "CascadesWithoutFade")
    {
      auto pass = MakeProbedPass();
      if (kind == "TightLiSPSMCascades")
      {
        pass->SetFitModeToTight();
        pass->SetCascadeWarp(vtkCascadedShadowMapPass::LISPSM_WARP);
      }
      else
      {
        pass->SetFadeFraction(0.0);
      }
      return pass;
    }
    if (kind == "DualDepthCascades")
    {
      auto pass = vtkSmartPointer<vtkDualDepthShadowMapPass>::New();
      pass->SetViews(vtkSmartPointer<vtkCascadedShadowMapViews>::New());
      pass->SetResolution(512);
      return pass;
    }
    auto pass = vtkSmartPointer<vtkWarpedShadowMapPass>::New();
    pass->SetResolution(512);
    return pass;
  }
};

TEST_P(ReachCulling, DrawsFewerCastersAndChangesNoPixel)
{
  const std::string& kind = GetParam();
  TestScene scene(kind == "WideUniform" ? 600 : 400, kind == "WideUniform" ? 150 : 300);
  BuildProbedScene(scene);
  AddBoxesAround(scene);
  if (kind == "Spot")
  {
    scene.SetSpot({ 2.0, -4.0, 9.0 }, 50.0);
  }
  else if (kind == "Point")
  {
    scene.SetPoint({ 2.0, -4.0, 5.0 });
  }
  auto culled = MakePass();
  scene.Renderer->SetPass(culled);
  auto withCulling = RenderAndCapture(scene.Window);
  const int culledDraws = culled->GetNumberOfCasterDraws();
  auto all = MakePass();
  all->ShadowReachCullingOff();
  scene.Renderer->SetPass(all);
  auto withoutCulling = RenderAndCapture(scene.Window);
  EXPECT_LE(culledDraws, all->GetNumberOfCasterDraws());
  if (kind == "StableCascades")
  {
    EXPECT_LT(culledDraws, all->GetNumberOfCasterDraws() * 3 / 4);
  }
  EXPECT_EQ(RgbBytes(withCulling), RgbBytes(withoutCulling));
}

INSTANTIATE_TEST_SUITE_P(ShadowCascades, ReachCulling,
  ::testing::Values("StableCascades", "TightLiSPSMCascades", "CascadesWithoutFade",
    "DualDepthCascades", "WideUniform", "Spot", "Point"),
  [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// While the user drags, cascades keep their views as the camera turns, and a
// layer re-rendered then takes every caster in its view, not only those whose
// shadows reach what the camera sees at that moment: casters the turning camera
// brings into reach are already drawn, and their layers stay. The still frame
// that ends the drag is a fresh pass's.
TEST(ShadowCascades, ADragKeepsLayersAsCastersComeIntoReach)
{
  constexpr int Frames = 24;
  TestScene scene;
  BuildProbedScene(scene);
  AddBoxesAround(scene);
  auto pass = MakeProbedPass();
  scene.Renderer->SetPass(pass);
  scene.Window->Render();
  scene.Window->SetDesiredUpdateRate(15.0);
  int rendered = 0;
  for (int frame = 0; frame < Frames; ++frame)
  {
    scene.Renderer->GetActiveCamera()->Azimuth(1.0);
    scene.Window->Render();
    rendered += pass->GetNumberOfRenderedLayers();
  }
  std::cout << "[ measured ] layers re-rendered in " << Frames
            << " dragged frames of a degree: " << rendered << "\n";
  // Measured: 16 when a dragged frame's layers took only the casters reaching
  // its receivers; 6 now: the first dragged frame re-renders the three
  // cascades whose reach took in new casters, and the finest cascade is
  // fitted again three times.
  const int layers = pass->GetNumberOfShadowMapLayers();
  EXPECT_LE(rendered, 2 * layers);

  scene.Window->SetDesiredUpdateRate(0.0001);
  const auto stillFrame = RgbBytes(RenderAndCapture(scene.Window));
  EXPECT_LT(pass->GetNumberOfRenderedLayers(), layers) << "the still frame kept dragged layers";
  EXPECT_EQ(stillFrame, FreshPassFrame(scene, MakeProbedPass()));

  // Every layer re-rendered in a drag with the camera still, then kept by the
  // still frame: the casters beyond the reach change no pixel.
  scene.Window->Render();
  scene.Window->SetDesiredUpdateRate(15.0);
  scene.Ground->Modified();
  scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfRenderedLayers(), layers) << "the ground is in every cascade";
  scene.Window->SetDesiredUpdateRate(0.0001);
  const auto keptFrame = RgbBytes(RenderAndCapture(scene.Window));
  EXPECT_EQ(pass->GetNumberOfRenderedLayers(), 0);
  EXPECT_EQ(keptFrame, FreshPassFrame(scene, MakeProbedPass()));
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

TEST(ShadowCascades, BadInputClampsWithWarningsAndRenders)
{
  vtkNew<vtkCascadedShadowMapPass> pass;
  {
    ErrorCounter errors;
    pass->SetNumberOfCascades(0);
    EXPECT_EQ(pass->GetNumberOfCascades(), 1);
    pass->SetNumberOfCascades(9);
    EXPECT_EQ(pass->GetNumberOfCascades(), 8);
    pass->SetSplitLambda(-0.5);
    EXPECT_EQ(pass->GetSplitLambda(), 0.0);
    pass->SetSplitLambda(1.5);
    EXPECT_EQ(pass->GetSplitLambda(), 1.0);
    pass->SetMaximumShadowDistance(-3.0);
    EXPECT_EQ(pass->GetMaximumShadowDistance(), 0.0);
    EXPECT_EQ(errors.Warnings(), 5) << errors.Text();
  }
  TestScene scene;
  LookAlongTheGround(scene);
  scene.SetSun(Sun);
  scene.Renderer->SetPass(pass);
  pass->SetNumberOfCascades(4);
  for (double split : { 14.0, -2.0, 7.0, 7.0, 500.0 })
  {
    pass->AddSplitDistance(split);
  }
  {
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Errors(), 0) << errors.Text();
    EXPECT_EQ(errors.Warnings(), 1) << errors.Text();
    ASSERT_EQ(pass->GetNumberOfSplits(), 4) << "splits 7 and 14 kept";
    EXPECT_EQ(pass->GetSplit(1), 7.0);
    EXPECT_EQ(pass->GetSplit(2), 14.0);
    EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(Sun)), ShadowedBelow);
  }
  // A maximum distance before the nearest visible ground.
  pass->RemoveAllSplitDistances();
  pass->SetMaximumShadowDistance(0.5);
  {
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Errors(), 0) << errors.Text();
    EXPECT_EQ(errors.Warnings(), 1) << errors.Text();
    EXPECT_GT(LuminanceAt(scene.Renderer, image, GroundAtDepth(8.0, -3.0)), LitAbove);
  }
}

TEST(ShadowCascades, SelectionByCoverageShadowsEveryProbe)
{
  TestScene scene;
  BuildProbedScene(scene);
  auto pass = MakeProbedPass();
  pass->SetSelection(vtkCascadedShadowMapPass::BY_COVERAGE);
  scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  ExpectProbesShadowedAndGroundLit(scene, image, "coverage");
  const std::string difference = CompareWithBaseline(image, "CascadesCoverage");
  EXPECT_TRUE(difference.empty()) << difference;

  // A stable cascade's sphere reaches beyond its split, so coverage gives some
  // of the ground past a split to the finer cascade before it: the third
  // cascade's ground (blue by depth) is shaded from the second (green).
  pass->SetAnalysisView(vtkAbstractShadowMapPass::PARTITION);
  image = RenderAndCapture(scene.Window);
  const glm::ivec3 past = ColorAt(scene.Renderer, image, GroundAtDepth(11.5, -3.5));
  EXPECT_GT(past.g, 2 * past.r) << "coverage keeps depth 11.5 in cascade 1";
  EXPECT_GT(past.g, past.b);
}

TEST(ShadowCascades, WarpedCascadesShadowEveryProbe)
{
  for (int warp : { vtkCascadedShadowMapPass::LISPSM_WARP, vtkCascadedShadowMapPass::GMNPR_WARP })
  {
    TestScene scene;
    BuildProbedScene(scene);
    auto pass = MakeProbedPass();
    pass->SetFitMode(vtkCascadedShadowMapPass::TIGHT);
    pass->SetCascadeWarp(warp);
    scene.Renderer->SetPass(pass);
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    const std::string name =
      warp == vtkCascadedShadowMapPass::LISPSM_WARP ? "CascadesLiSPSM" : "CascadesGMNPR";
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
    ExpectProbesShadowedAndGroundLit(scene, image, name);
    const std::string difference = CompareWithBaseline(image, name);
    EXPECT_TRUE(difference.empty()) << difference;
  }
}

// The blend band changes the shadow factor only where it is: over the last
// BlendFraction of each cascade before its split. Seen in the factor view so
// that every receiver's visibility is compared.
TEST(ShadowCascades, BlendingChangesOnlyTheBands)
{
  constexpr double Fraction = 0.2;
  TestScene scene;
  BuildProbedScene(scene);
  auto blended = MakeProbedPass();
  blended->SetBlendFraction(Fraction);
  blended->SetAnalysisView(vtkAbstractShadowMapPass::SHADOW_FACTOR);
  auto sharp = MakeProbedPass();
  sharp->SetBlendFraction(0.0);
  sharp->SetAnalysisView(vtkAbstractShadowMapPass::SHADOW_FACTOR);
  scene.Renderer->SetPass(blended);
  auto withBands = RenderAndCapture(scene.Window);
  const std::vector<double> depth = PixelDepths(scene);
  scene.Renderer->SetPass(sharp);
  auto withoutBands = RenderAndCapture(scene.Window);

  const auto* a = static_cast<const unsigned char*>(withBands->GetScalarPointer());
  const auto* b = static_cast<const unsigned char*>(withoutBands->GetScalarPointer());
  const double margin = 0.02; // depth-buffer and rasterisation slack
  int changed = 0;
  int outside = 0;
  for (size_t i = 0; i < depth.size(); ++i)
  {
    if (std::abs(int(a[3 * i]) - int(b[3 * i])) <= 2)
    {
      continue;
    }
    ++changed;
    bool inBand = false;
    for (int c = 1; c <= 3; ++c)
    {
      const double split = blended->GetSplit(c);
      const double start = split - Fraction * (split - blended->GetSplit(c - 1));
      inBand = inBand || (depth[i] > start - margin && depth[i] < split + margin);
    }
    outside += !inBand;
  }
  EXPECT_GT(changed, 20) << "the band at the probe at depth 10.75 blends two maps";
  // Each blended cascade's map also covers its predecessor's band, so its
  // sphere, texels and window differ from the sharp one's: a shadow edge may
  // move by a texel (one pixel here since stable cascades move in steps of a
  // thirty-second of the map). A band in the wrong place changes a hundred.
  EXPECT_LE(outside, 2) << "of " << changed << " changed pixels";
}

// Stable cascades split a quantized depth range: moving the camera a little
// changes the visible depth (tight splits follow it) but not the stable splits.
TEST(ShadowCascades, StableSplitsStayWhenTheCameraMovesALittle)
{
  for (int fit : { vtkCascadedShadowMapPass::STABLE, vtkCascadedShadowMapPass::TIGHT })
  {
    TestScene scene;
    BuildProbedScene(scene);
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->SetClippingRange(0.1, 200.0); // the ground ends well before the far plane
    auto pass = vtkSmartPointer<vtkCascadedShadowMapPass>::New();
    pass->SetResolution(256);
    pass->SetFitMode(fit);
    scene.Renderer->SetPass(pass);
    RenderAndCapture(scene.Window);
    std::vector<double> before;
    for (int i = 0; i < pass->GetNumberOfSplits(); ++i)
    {
      before.push_back(pass->GetSplit(i));
    }
    ASSERT_EQ(before.size(), 5u);
    EXPECT_LT(before.back(), 100.0) << "split range tightened to the ground";
    camera->Dolly(1.01);
    RenderAndCapture(scene.Window);
    bool same = true;
    for (int i = 0; i < 5; ++i)
    {
      same = same && pass->GetSplit(i) == before[i];
    }
    if (fit == vtkCascadedShadowMapPass::STABLE)
    {
      EXPECT_TRUE(same) << "stable splits moved: far " << before.back() << " -> " << pass->GetSplit(4);
      const double level = 4.0 * std::log2(before.back());
      EXPECT_NEAR(level, std::round(level), 1e-9) << "the far split is a level of the grid";
    }
    else
    {
      EXPECT_FALSE(same) << "tight splits follow the visible depth";
    }
  }
}

// A spot light's layers hold one cone map in tiles: the frame of the
// foundation's map at twice the resolution (2 x 2 tiles of 512²), with the
// probes' shadows near and far. A point light keeps its six cube faces.
namespace
{
const glm::dvec3 TiledSpot(1.5, 2.0, 14.0);

// A box 1 above the ground on the line from the spot to the ground at
// GroundAtDepth(place), long along the view so that its shadow stays several
// pixels tall far away; returns that ground point.
glm::dvec3 AddBoxShadowingGroundAt(TestScene& scene, const glm::dvec2& place)
{
  const glm::dvec3 ground = GroundAtDepth(place.x, place.y);
  const glm::dvec3 center = TiledSpot + (ground - TiledSpot) * ((TiledSpot.z - 1.0) / TiledSpot.z);
  AddBox(scene, center, { 0.6, 2.5, 0.6 });
  return ground;
}

// A spot over the ground seen along it, with boxes whose shadows fall near,
// mid-way and far; returns where the shadows of the boxes' centres fall.
std::vector<glm::dvec3> BuildTiledSpotScene(TestScene& scene)
{
  LookAlongTheGround(scene);
  scene.Sphere->SetVisibility(false);
  scene.Box->SetVisibility(false);
  scene.SetSpot(TiledSpot, 50.0);
  std::vector<glm::dvec3> shadows;
  for (const glm::dvec2 place : { glm::dvec2(4.0, -1.5), glm::dvec2(9.0, 0.0), glm::dvec2(16.0, 1.5) })
  {
    shadows.push_back(AddBoxShadowingGroundAt(scene, place));
  }
  return shadows;
}


void ExpectShadowsAndLightBeside(
  TestScene& scene, vtkImageData* image, const std::vector<glm::dvec3>& shadows)
{
  for (size_t i = 0; i < shadows.size(); ++i)
  {
    ASSERT_GE(ColorAt(scene.Renderer, image, shadows[i]).r, 0) << "shadow " << i << " off the image";
    EXPECT_LT(LuminanceAt(scene.Renderer, image, shadows[i]), ShadowedBelow) << "shadow " << i;
    const glm::dvec3 beside = shadows[i] + glm::dvec3(1.2, 0.0, 0.0);
    EXPECT_GT(LuminanceAt(scene.Renderer, image, beside), LitAbove) << "beside shadow " << i;
  }
}

// Compares a tiled spot's frame with the foundation's untiled map of the same
// spot (the cone cropped to B by FitSpot, a little wider than the tiles' window,
// which is cropped to B's lit part; tile cores lose the margin's texels), or
// with the warped pass's map in `warpMode`. The texel grids differ, so shadow
// edges move by a pixel; away from edges, where a seam or a wrong tile would
// show, nothing may differ.
void ExpectTheUntiledMapsFrameAwayFromEdges(TestScene& scene, vtkImageData* image,
  int untiledResolution, int warpMode = vtkWarpedShadowMapPass::UNIFORM)
{
  vtkNew<vtkWarpedShadowMapPass> whole;
  whole->SetResolution(untiledResolution);
  whole->SetWarpMode(warpMode);
  scene.Renderer->SetPass(whole);
  auto wholeImage = RenderAndCapture(scene.Window);
  int dims[3];
  image->GetDimensions(dims);
  const auto* tiled = static_cast<const unsigned char*>(image->GetScalarPointer());
  const auto* untiled = static_cast<const unsigned char*>(wholeImage->GetScalarPointer());
  auto red = [&](const unsigned char* pixels, int x, int y) { return int(pixels[3 * (y * dims[0] + x)]); };
  int onEdges = 0;
  int awayFromEdges = 0;
  for (int y = 1; y + 1 < dims[1]; ++y)
  {
    for (int x = 1; x + 1 < dims[0]; ++x)
    {
      if (std::abs(red(tiled, x, y) - red(untiled, x, y)) <= 8)
      {
        continue;
      }
      int low = 255;
      int high = 0;
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          low = std::min(low, red(untiled, x + dx, y + dy));
          high = std::max(high, red(untiled, x + dx, y + dy));
        }
      }
      ++(high - low > 16 ? onEdges : awayFromEdges);
    }
  }
  EXPECT_EQ(awayFromEdges, 0) << "pixels that differ from the untiled map's frame away from edges";
  EXPECT_LT(onEdges, dims[0] * dims[1] / 100) << "edge pixels that differ";
}


// Renders the tiled spot scene with `pass` (four cascades): no warning, 2 x 2 tiles.
vtkSmartPointer<vtkImageData> RenderFourTiles(TestScene& scene, vtkCascadedShadowMapPass* pass)
{
  pass->SetMaximumShadowDistance(0.0);
  scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 4) << "2 x 2 tiles";
  return image;
}
} // namespace

TEST(ShadowCascades, SpotLightsAreOneTiledMapPointLightsKeepCubeFaces)
{
  TestScene scene;
  const std::vector<glm::dvec3> shadows = BuildTiledSpotScene(scene);
  auto pass = MakeProbedPass();
  auto image = RenderFourTiles(scene, pass);
  ExpectShadowsAndLightBeside(scene, image, shadows);
  const std::string difference = CompareWithBaseline(image, "CascadesSpot");
  EXPECT_TRUE(difference.empty()) << difference;
  ExpectTheUntiledMapsFrameAwayFromEdges(scene, image, 2 * pass->GetResolution());

  scene.Renderer->SetPass(pass);
  scene.SetPoint(TiledSpot);
  image = RenderAndCapture(scene.Window);
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 6) << "a point light keeps its cube faces";
  EXPECT_LT(LuminanceAt(scene.Renderer, image, shadows.back()), ShadowedBelow);
}

// With TIGHT fitting, CascadeWarp warps a spot's whole map before it is tiled.
TEST(ShadowCascades, CascadeWarpWarpsTheSpotsTiledMap)
{
  TestScene scene;
  const std::vector<glm::dvec3> shadows = BuildTiledSpotScene(scene);
  auto pass = MakeProbedPass();
  pass->SetFitMode(vtkCascadedShadowMapPass::TIGHT);
  pass->SetCascadeWarp(vtkCascadedShadowMapPass::LISPSM_WARP);
  auto image = RenderFourTiles(scene, pass);
  // Shading checks; unwarped tiles would pass them too.
  ExpectShadowsAndLightBeside(scene, image, shadows);
  ExpectTheUntiledMapsFrameAwayFromEdges(
    scene, image, 2 * pass->GetResolution(), vtkWarpedShadowMapPass::LISPSM);

  // What tells warped tiles from unwarped ones: the warp moves texels toward the
  // viewer. At 2 x 2 tiles of 256^2 unwarped tiles undersample much of the
  // ground near the camera.
  auto undersampled = [&](int warp)
  {
    pass->SetCascadeWarp(warp);
    pass->SetResolution(256);
    pass->SetAnalysisView(vtkAbstractShadowMapPass::TEXEL_DENSITY);
    scene.Renderer->SetPass(pass);
    return CountUndersampled(RenderAndCapture(scene.Window));
  };
  const int uniform = undersampled(vtkCascadedShadowMapPass::NO_WARP);
  const int warped = undersampled(vtkCascadedShadowMapPass::LISPSM_WARP);
  std::cout << "undersampled pixels: unwarped tiles " << uniform << ", LiSPSM tiles " << warped
            << "\n";
  const int* size = scene.Window->GetSize();
  EXPECT_GT(uniform, size[0] * size[1] / 10);
  EXPECT_LT(warped, uniform / 2);
}

TEST(ShadowCascades, SpotTilesOfEveryGridShadeLikeTheUntiledMap)
{
  // Three cascades give 3 x 1 tiles, six give 3 x 2, eight 4 x 2.
  for (const int cascades : { 3, 6, 8 })
  {
    SCOPED_TRACE(std::to_string(cascades) + " cascades");
    TestScene scene;
    std::vector<glm::dvec3> shadows = BuildTiledSpotScene(scene);
    // One more to the side, in the map's last column of three or four.
    shadows.push_back(AddBoxShadowingGroundAt(scene, { 16.0, 4.0 }));
    auto pass = MakeProbedPass();
    pass->SetNumberOfCascades(cascades);
    pass->RemoveAllSplitDistances();
    pass->SetMaximumShadowDistance(0.0);
    scene.Renderer->SetPass(pass);
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), cascades);
    ExpectShadowsAndLightBeside(scene, image, shadows);
    ExpectTheUntiledMapsFrameAwayFromEdges(scene, image, 2 * pass->GetResolution());
  }
}

// A pole outside the view whose shadow falls into it, near the view's edge:
// the culling must keep it.
TEST_P(ReachCulling, KeepsTheShadowOfACasterOutsideTheView)
{
  const std::string& kind = GetParam();
  TestScene scene(kind == "WideUniform" ? 600 : 400, kind == "WideUniform" ? 150 : 300);
  scene.Sphere->SetVisibility(false);
  scene.Box->SetVisibility(false);
  AddBox(scene, { -11.8, 0.0, 1.5 }, { 0.3, 0.3, 3.0 });
  if (kind == "Spot")
  {
    scene.SetSpot({ -14.0, 0.0, 6.0 }, 50.0);
  }
  else if (kind == "Point")
  {
    scene.SetPoint({ -12.0, 0.0, 5.0 });
  }
  else
  {
    scene.SetSun(glm::normalize(glm::dvec3(1.0, 0.0, -0.5)));
  }
  auto culled = MakePass();
  scene.Renderer->SetPass(culled);
  auto withCulling = RenderAndCapture(scene.Window);
  auto all = MakePass();
  all->ShadowReachCullingOff();
  scene.Renderer->SetPass(all);
  auto withoutCulling = RenderAndCapture(scene.Window);
  EXPECT_EQ(RgbBytes(withCulling), RgbBytes(withoutCulling));
  // The pole is not in the picture, its shadow is.
  int dark = 0;
  int dims[3];
  withoutCulling->GetDimensions(dims);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      dark += static_cast<unsigned char*>(withoutCulling->GetScalarPointer(x, y, 0))[0] < 80 ? 1 : 0;
    }
  }
  EXPECT_GT(dark, 20) << "the pole's shadow is in view";
}

namespace
{
// A camera at street level over a 120 x 120 scene, 16:9, and 1024² maps.
shadowmaps::ShadowFrame StreetLevelFrame()
{
  shadowmaps::ShadowFrame frame;
  frame.CameraView = glm::lookAt(glm::dvec3(0.0, -40.0, 9.0), glm::dvec3(0.0, 0.0, 0.0),
    glm::dvec3(0.0, 0.0, 1.0));
  frame.CameraProjection = glm::perspective(glm::radians(45.0), 16.0 / 9.0, 0.5, 200.0);
  frame.SceneBounds = { glm::dvec3(-60.0, -60.0, 0.0), glm::dvec3(60.0, 60.0, 12.0) };
  frame.PropBounds = { frame.SceneBounds };
  frame.Resolution = 1024;
  return frame;
}

// An oblique light over StreetLevelFrame's scene: a sun, or a spot of `cone`.
shadowmaps::ShadowLight StreetLevelLight(shadowmaps::LightKind kind, double cone)
{
  shadowmaps::ShadowLight light;
  light.Kind = kind;
  light.ConeAngle = cone;
  light.Position = glm::dvec3(10.0, -15.0, 30.0);
  light.Direction = glm::normalize(glm::dvec3(-0.3, 0.4, -1.0));
  return light;
}

// The receivers' shader relies on every view of a light whose strategy promises
// CroppedViews being a crop of its first (ShadowMapCrop): fitted through the
// strategy itself, for every setting that makes the promise, and not made where
// the views are not crops (warped cascades, cube faces).
TEST(ShadowCascades, CroppedViewsPromiseHoldsForEveryFitThatMakesIt)
{
  const shadowmaps::ShadowFrame frame = StreetLevelFrame();

  struct Setting
  {
    const char* Name;
    int FitMode;
    int Warp;
    shadowmaps::LightKind Kind;
    double Cone;
    bool Promised;
  };
  const Setting settings[] = {
    { "stable sun", vtkCascadedShadowMapViews::STABLE, vtkCascadedShadowMapViews::NO_WARP,
      shadowmaps::LightKind::Directional, 90.0, true },
    { "stable sun, warp set (unused)", vtkCascadedShadowMapViews::STABLE,
      vtkCascadedShadowMapViews::LISPSM_WARP, shadowmaps::LightKind::Directional, 90.0, true },
    { "tight sun", vtkCascadedShadowMapViews::TIGHT, vtkCascadedShadowMapViews::NO_WARP,
      shadowmaps::LightKind::Directional, 90.0, true },
    { "tight LiSPSM sun", vtkCascadedShadowMapViews::TIGHT, vtkCascadedShadowMapViews::LISPSM_WARP,
      shadowmaps::LightKind::Directional, 90.0, false },
    { "spot tiles", vtkCascadedShadowMapViews::STABLE, vtkCascadedShadowMapViews::NO_WARP,
      shadowmaps::LightKind::Spot, 35.0, true },
    { "warped spot tiles", vtkCascadedShadowMapViews::TIGHT, vtkCascadedShadowMapViews::LISPSM_WARP,
      shadowmaps::LightKind::Spot, 35.0, true },
    { "wide spot (cube faces)", vtkCascadedShadowMapViews::STABLE,
      vtkCascadedShadowMapViews::NO_WARP, shadowmaps::LightKind::Spot, 75.0, false },
  };
  for (const Setting& setting : settings)
  {
    vtkNew<vtkCascadedShadowMapViews> views;
    views->SetNumberOfCascades(4);
    views->SetFitMode(setting.FitMode);
    views->SetCascadeWarp(setting.Warp);
    shadowmaps::ShadowLight light = StreetLevelLight(setting.Kind, setting.Cone);
    views->FitLight(frame, light);
    const bool promised = (shadowmaps::ReceiverFeatures(light) & shadowmaps::CroppedViews) != 0;
    EXPECT_EQ(promised, setting.Promised) << setting.Name;
    ASSERT_GE(light.Views.size(), 2u) << setting.Name;
    const glm::dmat4 first = shadowmaps::ClipToTexture() * light.Views.front().ViewProjection();
    double largest = 0.0;
    for (const shadowmaps::LightView& view : light.Views)
    {
      largest = std::max(largest,
        shadowmaps::CropError(first, shadowmaps::ClipToTexture() * view.ViewProjection()));
    }
    if (setting.Promised)
    {
      EXPECT_LT(largest, 1e-9) << setting.Name;
    }
    else if (setting.Kind == shadowmaps::LightKind::Directional)
    {
      EXPECT_GT(largest, 1e-3) << setting.Name << ": warped cascades are not crops";
    }
  }
}

// Receivers look up a second cascade only for lights that have a blend band
// (ReceiverFeature CascadeBlends); without one the second lookup, which
// software rasterisers run at every pixel, is compiled out.
TEST(ShadowCascades, OnlyCascadesWithABlendBandCompileTheSecondLookup)
{
  const shadowmaps::ShadowFrame frame = StreetLevelFrame();
  struct Setting
  {
    const char* Name;
    int Cascades;
    double BlendFraction;
    int Selection;
    shadowmaps::LightKind Kind;
    bool Blends;
  };
  const int byDepth = vtkCascadedShadowMapViews::BY_DEPTH;
  const int byCoverage = vtkCascadedShadowMapViews::BY_COVERAGE;
  const auto sun = shadowmaps::LightKind::Directional;
  const Setting settings[] = {
    { "four cascades by depth", 4, 0.1, byDepth, sun, true },
    { "four cascades by coverage", 4, 0.1, byCoverage, sun, true },
    { "no band, by depth", 4, 0.0, byDepth, sun, false },
    { "no band, by coverage", 4, 0.0, byCoverage, sun, false },
    { "one cascade", 1, 0.1, byDepth, sun, false },
    { "one cascade, by coverage", 1, 0.1, byCoverage, sun, false },
    { "spot tiles", 4, 0.1, byDepth, shadowmaps::LightKind::Spot, false },
  };
  for (const Setting& setting : settings)
  {
    vtkNew<vtkCascadedShadowMapViews> views;
    views->SetNumberOfCascades(setting.Cascades);
    views->SetBlendFraction(setting.BlendFraction);
    views->SetSelection(setting.Selection);
    shadowmaps::ShadowLight light = StreetLevelLight(setting.Kind, 35.0);
    views->FitLight(frame, light);
    const bool blends = (shadowmaps::ReceiverFeatures(light) & shadowmaps::CascadeBlends) != 0;
    EXPECT_EQ(blends, setting.Blends) << setting.Name;
  }
}
} // namespace
