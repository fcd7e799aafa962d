// vtkWarpedShadowMapPass's warp modes (PSM, LiSPSM, TSM, GMNPR) on the standard
// test scene with the sun perpendicular to the view, behind the viewer and
// facing it: strict baselines, probes near and far from the camera, and the
// warp's effect on texel density seen through the TEXEL_DENSITY analysis view.
#include "ShadowTestUtilities.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkVarianceShadowMapPass.h"
#include "vtkWarpedShadowMapPass.h"
#include "vtkWarpedShadowMapViews.h"

#include "vtkCamera.h"
#include "vtkImageData.h"

#include <gtest/gtest.h>

#include <iostream>
#include <set>
#include <tuple>

using namespace shadowtest;

namespace
{
// The camera looks along +y, 1.2 above the ground. Light at right angles to the
// view; travelling with the view (sun behind the viewer); toward the viewer
// (sun facing it, the dueling frusta).
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(1.0, 0.15, -0.8));
const glm::dvec3 SunBehind = glm::normalize(glm::dvec3(0.25, 1.0, -0.9));
const glm::dvec3 SunFacing = glm::normalize(glm::dvec3(0.25, -1.0, -0.9));

void LookAlongTheGround(TestScene& scene)
{
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(0.0, -9.5, 1.2);
  camera->SetFocalPoint(0.0, 0.0, 0.8);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetClippingRange(0.1, 40.0);
}

struct SetUp
{
  const char* Name;
  glm::dvec3 Direction;
  // Ground points lit by this sun near and far from the camera.
  glm::dvec3 LitNear;
  glm::dvec3 LitFar;
};

const SetUp SetUps[] = {
  { "Perpendicular", SunDirection, { -2.0, -3.0, 0.0 }, { -3.0, 6.0, 0.0 } },
  { "Behind", SunBehind, { -2.0, -3.0, 0.0 }, { -3.0, 6.0, 0.0 } },
  { "Facing", SunFacing, { -2.0, -3.0, 0.0 }, { -3.0, 6.0, 0.0 } },
};

struct Mode
{
  int Value;
  const char* Name;
};

const Mode WarpModes[] = { { vtkWarpedShadowMapPass::PSM, "PSM" },
  { vtkWarpedShadowMapPass::LISPSM, "LiSPSM" }, { vtkWarpedShadowMapPass::TSM, "TSM" },
  { vtkWarpedShadowMapPass::GMNPR, "GMNPR" } };

// Renders `scene` with the warp mode: no errors, the point `shadowed` dark, the lit
// ground near and far lit, and the frame matches its baseline `name`.
void RenderAndProbe(TestScene& scene, int mode, const std::string& name, const glm::dvec3& shadowed,
  const glm::dvec3& litNear, const glm::dvec3& litFar)
{
  vtkNew<vtkWarpedShadowMapPass> pass;
  pass->SetWarpMode(mode);
  pass->SetResolution(512);
  scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  for (const glm::dvec3& probe : { shadowed, litNear, litFar })
  {
    ASSERT_GE(ColorAt(scene.Renderer, image, probe).r, 0) << name << ": probe off the image";
  }
  EXPECT_LT(LuminanceAt(scene.Renderer, image, shadowed), ShadowedBelow) << name;
  EXPECT_GT(LuminanceAt(scene.Renderer, image, litNear), LitAbove) << name;
  EXPECT_GT(LuminanceAt(scene.Renderer, image, litFar), LitAbove) << name;
  const std::string difference = CompareWithBaseline(image, name);
  EXPECT_TRUE(difference.empty()) << difference;
}

// The sphere's shadow is dark and the lit ground near and far from the camera
// is lit; the frame matches its baseline.
void CheckMode(const Mode& mode, const SetUp& setUp)
{
  TestScene scene;
  LookAlongTheGround(scene);
  scene.SetSun(setUp.Direction);
  RenderAndProbe(scene, mode.Value, std::string("Warp") + mode.Name + setUp.Name,
    GroundShadowOfSphereCenter(setUp.Direction), setUp.LitNear, setUp.LitFar);
}

class WarpModeAndSetUp : public ::testing::TestWithParam<std::tuple<int, int>>
{
};

TEST_P(WarpModeAndSetUp, ShadowsNearAndFarMatchTheBaseline)
{
  CheckMode(WarpModes[std::get<0>(GetParam())], SetUps[std::get<1>(GetParam())]);
}

INSTANTIATE_TEST_SUITE_P(ShadowWarps, WarpModeAndSetUp,
  ::testing::Combine(::testing::Range(0, 4), ::testing::Range(0, 3)),
  [](const ::testing::TestParamInfo<std::tuple<int, int>>& info) {
    return std::string(WarpModes[std::get<0>(info.param)].Name) +
      SetUps[std::get<1>(info.param)].Name;
  });
} // namespace

// Receivers compile only the code a light's views may need (gradient texel
// sizes, linear depth): switching modes on a live pass must rebuild them, so
// each frame matches a fresh pass's baseline.
TEST(ShadowWarps, SwitchingModesOnALivePassMatchesFreshPasses)
{
  TestScene scene;
  LookAlongTheGround(scene);
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  pass->SetResolution(512);
  scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  RenderAndCapture(scene.Window);
  for (const Mode& mode : WarpModes)
  {
    pass->SetWarpMode(mode.Value);
    auto image = RenderAndCapture(scene.Window);
    const std::string difference =
      CompareWithBaseline(image, std::string("Warp") + mode.Name + "Perpendicular");
    EXPECT_TRUE(difference.empty()) << mode.Name << ": " << difference;
  }
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
}

TEST(ShadowWarps, PSMWithoutSlideBackAndWithALongOneStillShadows)
{
  for (double slideBack : { 0.0, 30.0 })
  {
    TestScene scene;
    LookAlongTheGround(scene);
    scene.SetSun(SunBehind);
    vtkNew<vtkWarpedShadowMapPass> pass;
    pass->SetWarpMode(vtkWarpedShadowMapPass::PSM);
    pass->SetPSMSlideBack(slideBack);
    pass->SetResolution(512);
    scene.Renderer->SetPass(pass);
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
    EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunBehind)), ShadowedBelow)
      << "slide-back " << slideBack;
    EXPECT_GT(LuminanceAt(scene.Renderer, image, { -2.0, -3.0, 0.0 }), LitAbove) << "slide-back " << slideBack;
  }
}

// Light exactly along and against the view line, and a camera inside the
// sphere: every mode renders without warnings, and the lit ground stays lit.
TEST(ShadowWarps, DegenerateViewsRenderCleanly)
{
  const glm::dvec3 eye(0.0, -10.0, 10.0);
  const glm::dvec3 along = glm::normalize(-eye);
  for (const Mode& mode : WarpModes)
  {
    for (const glm::dvec3& sun : { along, glm::dvec3(0.0, 0.0, -1.0) })
    {
      TestScene scene;
      vtkCamera* camera = scene.Renderer->GetActiveCamera();
      camera->SetPosition(eye.x, eye.y, eye.z);
      camera->SetFocalPoint(0.0, 0.0, 0.0);
      camera->SetClippingRange(0.1, 60.0);
      if (sun.y == 0.0)
      {
        // Looking straight down along the sun, from inside the sphere.
        camera->SetPosition(0.0, 0.0, 1.5);
        camera->SetViewUp(0.0, 1.0, 0.0);
      }
      scene.SetSun(sun);
      vtkNew<vtkWarpedShadowMapPass> pass;
      pass->SetWarpMode(mode.Value);
      scene.Renderer->SetPass(pass);
      ErrorCounter errors;
      auto image = RenderAndCapture(scene.Window);
      EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << mode.Name << ": " << errors.Text();
      EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 1) << mode.Name;
      if (sun.y != 0.0)
      {
        EXPECT_GT(LuminanceAt(scene.Renderer, image, { -4.0, -2.0, 0.0 }), LitAbove) << mode.Name;
      }
    }
  }
}

TEST(ShadowWarps, WarpsUndersampleFewerPixelsThanTheUniformMap)
{
  int undersampled[5] = { 0, 0, 0, 0, 0 };
  for (int mode = vtkWarpedShadowMapPass::UNIFORM; mode <= vtkWarpedShadowMapPass::TSM; ++mode)
  {
    TestScene scene;
    LookAlongTheGround(scene);
    scene.SetSun(SunDirection);
    vtkNew<vtkWarpedShadowMapPass> pass;
    pass->SetWarpMode(mode);
    // At 512^2 the uniform map undersamples the ground near the camera.
    pass->SetResolution(512);
    pass->SetAnalysisView(vtkAbstractShadowMapPass::TEXEL_DENSITY);
    scene.Renderer->SetPass(pass);
    undersampled[mode] = CountUndersampled(RenderAndCapture(scene.Window));
  }
  std::cout << "undersampled pixels: uniform " << undersampled[0] << ", LiSPSM " << undersampled[1]
            << ", GMNPR " << undersampled[2] << ", PSM " << undersampled[3] << ", TSM "
            << undersampled[4] << "\n";
  EXPECT_GT(undersampled[vtkWarpedShadowMapPass::UNIFORM], 1000);
  EXPECT_LT(undersampled[vtkWarpedShadowMapPass::LISPSM],
    undersampled[vtkWarpedShadowMapPass::UNIFORM] / 2);
  EXPECT_LT(undersampled[vtkWarpedShadowMapPass::GMNPR],
    undersampled[vtkWarpedShadowMapPass::UNIFORM] / 2);
}

TEST(ShadowWarps, WarpModeClampsAndParallelCameraRenders)
{
  vtkNew<vtkWarpedShadowMapPass> pass;
  pass->SetWarpMode(99);
  EXPECT_EQ(pass->GetWarpMode(), vtkWarpedShadowMapPass::TSM);
  pass->SetWarpMode(-1);
  EXPECT_EQ(pass->GetWarpMode(), vtkWarpedShadowMapPass::UNIFORM);
  pass->SetLiSPSMFreeParameter(-5.0);
  EXPECT_EQ(pass->GetLiSPSMFreeParameter(), 0.0);
  EXPECT_EQ(pass->GetPSMSlideBack(), -1.0); // automatic
  pass->SetPSMSlideBack(-7.0);
  EXPECT_EQ(pass->GetPSMSlideBack(), -1.0);
  pass->SetTSMFocusDistance(-1.0);
  EXPECT_EQ(pass->GetTSMFocusDistance(), 0.0);
  pass->SetTSMFocusFraction(1.5);
  EXPECT_EQ(pass->GetTSMFocusFraction(), 0.95);

  // Every mode degrades to the uniform map for a parallel-projection camera.
  for (const Mode& mode : WarpModes)
  {
    TestScene scene;
    scene.Renderer->GetActiveCamera()->ParallelProjectionOn();
    scene.SetSun(SunDirection);
    pass->SetWarpMode(mode.Value);
    scene.Renderer->SetPass(pass);
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << mode.Name << ": " << errors.Text();
    EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)),
      ShadowedBelow)
      << mode.Name;
  }
}

namespace
{
const glm::dvec3 SpotPosition(5.0, -2.0, 7.0);

// The standard scene seen along the ground, lit by a spot at SpotPosition.
void LookAlongTheGroundUnderTheSpot(TestScene& scene, double coneAngle)
{
  LookAlongTheGround(scene);
  scene.SetSpot(SpotPosition, coneAngle);
}
} // namespace

// Spot lights are warped in their own post-perspective space (LiSPSM, GMNPR, TSM)
// or the camera's (PSM): the sphere's shadow stays dark and the lit ground lit,
// near and far.
TEST(ShadowWarps, SpotLightWarpsShadowNearAndFar)
{
  const glm::dvec3& spot = SpotPosition;
  for (const Mode& mode : WarpModes)
  {
    TestScene scene;
    LookAlongTheGroundUnderTheSpot(scene, 60.0);
    RenderAndProbe(scene, mode.Value, std::string("WarpSpot") + mode.Name,
      GroundShadowOfSphereCenterFrom(spot), { -2.0, -3.0, 0.0 }, { -3.0, 6.0, 0.0 });
  }
}

// A spot wider than one map holds gets six faces in every warp mode: the
// foundation's cube faces (the warps fit one map), or in PSM mode the
// post-perspective cube's, and still shadows.
TEST(ShadowWarps, WideSpotKeepsCubeFacesInEveryMode)
{
  const glm::dvec3& spot = SpotPosition;
  for (const Mode& mode : WarpModes)
  {
    TestScene scene;
    LookAlongTheGroundUnderTheSpot(scene, 75.0);
    vtkNew<vtkWarpedShadowMapPass> pass;
    pass->SetWarpMode(mode.Value);
    pass->SetResolution(512);
    scene.Renderer->SetPass(pass);
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << mode.Name << ": " << errors.Text();
    EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 6) << mode.Name;
    EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenterFrom(spot)), ShadowedBelow)
      << mode.Name;
  }
}

namespace
{
// A point light at street level just ahead of the camera and above it: its
// light reaches from the camera's feet to the far end of the ground.
const glm::dvec3 StreetLight(1.0, -6.0, 3.0);

void RenderCube(TestScene& scene, vtkWarpedShadowMapPass* pass, int cubeMap, int resolution)
{
  pass->SetWarpModeToPSM();
  pass->SetPSMCubeMap(cubeMap);
  pass->SetResolution(resolution);
  scene.Renderer->SetPass(pass);
}

// The street light's frame through `pass` (already set on the scene's
// renderer): no error, six layers, the sphere's shadow dark and the ground near
// and far lit. The point light's ground dims with distance and incidence, so
// the probes compare with `plain`, the frame without shadows.
vtkSmartPointer<vtkImageData> RenderAndProbeStreetLight(
  TestScene& scene, vtkAbstractShadowMapPass* pass, vtkImageData* plain)
{
  ErrorCounter errors;
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 6);
  const glm::dvec3 shadowed = GroundShadowOfSphereCenterFrom(StreetLight);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, shadowed),
    0.5 * LuminanceAt(scene.Renderer, plain, shadowed));
  for (const glm::dvec3& lit : { glm::dvec3(-2.0, -3.0, 0.0), glm::dvec3(2.0, 3.0, 0.0),
         glm::dvec3(-5.0, 8.0, 0.0) })
  {
    EXPECT_GT(LuminanceAt(scene.Renderer, image, lit), 0.95 * LuminanceAt(scene.Renderer, plain, lit))
      << lit.x << "," << lit.y;
  }
  return image;
}
} // namespace

// Kozlov's post-perspective cube map (PSM mode): a point light near the
// viewer, a spot wider than one map holds, and, asked for, the sun facing the
// viewer (its light in post-perspective space just beyond the far plane). The
// sphere's shadow is dark, the ground near and far lit, the frames match their
// baselines.
TEST(ShadowWarps, PostPerspectiveCubeShadowsNearAndFar)
{
  {
    TestScene scene;
    LookAlongTheGround(scene);
    scene.SetPoint(StreetLight);
    auto plain = RenderAndCapture(scene.Window);
    vtkNew<vtkWarpedShadowMapPass> pass;
    RenderCube(scene, pass, vtkWarpedShadowMapViews::PSM_CUBE_AUTOMATIC, 512);
    auto image = RenderAndProbeStreetLight(scene, pass, plain);
    pass->SetPSMCubeMapToNever(); // the cube, not the uniform faces it falls back to
    EXPECT_NE(RgbBytes(RenderAndCapture(scene.Window)), RgbBytes(image));
    const std::string difference = CompareWithBaseline(image, "WarpPSMCubePoint");
    EXPECT_TRUE(difference.empty()) << difference;
  }
  {
    TestScene scene;
    LookAlongTheGroundUnderTheSpot(scene, 75.0);
    RenderAndProbe(scene, vtkWarpedShadowMapPass::PSM, "WarpPSMCubeWideSpot",
      GroundShadowOfSphereCenterFrom(SpotPosition), { -2.0, -3.0, 0.0 }, { -3.0, 6.0, 0.0 });
  }
  for (const auto& setUp : SetUps)
  {
    TestScene scene;
    LookAlongTheGround(scene);
    scene.SetSun(setUp.Direction);
    vtkNew<vtkWarpedShadowMapPass> pass;
    RenderCube(scene, pass, vtkWarpedShadowMapViews::PSM_CUBE_ALWAYS, 512);
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << setUp.Name << ": " << errors.Text();
    EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 6) << setUp.Name;
    EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(setUp.Direction)),
      ShadowedBelow)
      << setUp.Name;
    EXPECT_GT(LuminanceAt(scene.Renderer, image, setUp.LitNear), LitAbove) << setUp.Name;
    EXPECT_GT(LuminanceAt(scene.Renderer, image, setUp.LitFar), LitAbove) << setUp.Name;
    const std::string difference =
      CompareWithBaseline(image, std::string("WarpPSMCube") + setUp.Name);
    EXPECT_TRUE(difference.empty()) << difference;
  }
}

// The cube's faces spread texels by screen area: with the light near the
// viewer and no slide-back (Kozlov's cube map as the seed gives it), far fewer
// pixels are undersampled than with the uniform cube faces of the same
// resolution (PSMCubeMap NEVER), which spend as many texels per world area far
// away as near. The automatic slide-back gives some of the near field's texels
// to the far field, and still undersamples no more than the uniform faces.
TEST(ShadowWarps, PostPerspectiveCubeUndersamplesFewerPixelsThanUniformCubeFaces)
{
  struct Choice
  {
    int CubeMap;
    double SlideBack;
  };
  const Choice choices[3] = { { vtkWarpedShadowMapViews::PSM_CUBE_NEVER, -1.0 },
    { vtkWarpedShadowMapViews::PSM_CUBE_AUTOMATIC, 0.0 },
    { vtkWarpedShadowMapViews::PSM_CUBE_AUTOMATIC, -1.0 } };
  int undersampled[3] = { 0, 0, 0 };
  for (int i = 0; i < 3; ++i)
  {
    TestScene scene;
    LookAlongTheGround(scene);
    scene.SetPoint(StreetLight);
    vtkNew<vtkWarpedShadowMapPass> pass;
    RenderCube(scene, pass, choices[i].CubeMap, 256);
    pass->SetPSMSlideBack(choices[i].SlideBack);
    pass->SetAnalysisView(vtkAbstractShadowMapPass::TEXEL_DENSITY);
    undersampled[i] = CountUndersampled(RenderAndCapture(scene.Window));
  }
  std::cout << "undersampled pixels at 256^2: uniform cube faces " << undersampled[0]
            << ", post-perspective cube " << undersampled[1] << " (no slide-back), "
            << undersampled[2] << " (automatic slide-back)\n";
  EXPECT_GT(undersampled[0], 2000);
  EXPECT_LT(undersampled[1], undersampled[0] / 4);
  EXPECT_LE(undersampled[2], undersampled[0]);
}

// The analysis views show the cube: the partition colours the faces that shade
// the view (more than one), the shadow-map view tiles the six layers.
TEST(ShadowWarps, PostPerspectiveCubeInTheAnalysisViews)
{
  TestScene scene;
  LookAlongTheGround(scene);
  scene.SetPoint(StreetLight);
  vtkNew<vtkWarpedShadowMapPass> pass;
  RenderCube(scene, pass, vtkWarpedShadowMapViews::PSM_CUBE_AUTOMATIC, 256);
  ErrorCounter errors;
  pass->SetAnalysisView(vtkAbstractShadowMapPass::PARTITION);
  const std::vector<unsigned char> partition = RgbBytes(RenderAndCapture(scene.Window));
  std::set<int> colours;
  for (size_t i = 0; i + 2 < partition.size(); i += 3)
  {
    // Lit pixels of a face show its palette colour at full brightness.
    colours.insert((partition[i] << 16) | (partition[i + 1] << 8) | partition[i + 2]);
  }
  pass->SetAnalysisView(vtkAbstractShadowMapPass::SHADOW_MAP);
  auto maps = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 6);
  int faces = 0;
  for (const glm::ivec3 face : { glm::ivec3(230, 51, 51), glm::ivec3(51, 204, 51),
         glm::ivec3(51, 102, 255), glm::ivec3(242, 217, 51), glm::ivec3(204, 77, 230),
         glm::ivec3(51, 217, 217) })
  {
    faces += colours.count((face.r << 16) | (face.g << 8) | face.b) > 0 ? 1 : 0;
  }
  EXPECT_GE(faces, 2);
  const std::string difference = CompareWithBaseline(maps, "WarpPSMCubeShadowMaps");
  EXPECT_TRUE(difference.empty()) << difference;
}

// Every representation takes the cube's faces: depth, dual depth (no bias) and
// moments (the light depth, the same in every face). The sphere's shadow is
// dark and the ground near and far lit, against the frame without shadows.
TEST(ShadowWarps, PostPerspectiveCubeComposesWithEveryRepresentation)
{
  vtkNew<vtkWarpedShadowMapViews> views;
  views->SetWarpModeToPSM();
  vtkNew<vtkDepthShadowMapPass> depth;
  vtkNew<vtkDualDepthShadowMapPass> dual;
  vtkNew<vtkVarianceShadowMapPass> moments;
  vtkAbstractShadowMapPass* passes[] = { depth, dual, moments };
  for (vtkAbstractShadowMapPass* pass : passes)
  {
    SCOPED_TRACE(pass->GetClassName());
    TestScene scene;
    LookAlongTheGround(scene);
    scene.SetPoint(StreetLight);
    auto plain = RenderAndCapture(scene.Window);
    pass->SetViews(views);
    pass->SetResolution(512);
    scene.Renderer->SetPass(pass);
    const std::vector<unsigned char> cube = RgbBytes(RenderAndProbeStreetLight(scene, pass, plain));
    // The cube, not the uniform faces it falls back to.
    views->SetPSMCubeMapToNever();
    EXPECT_NE(RgbBytes(RenderAndCapture(scene.Window)), cube);
    views->SetPSMCubeMapToAutomatic();
    scene.Renderer->SetPass(nullptr);
    pass->ReleaseGraphicsResources(scene.Window);
  }
}
