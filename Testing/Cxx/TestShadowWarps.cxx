// vtkWarpedShadowMapPass's LiSPSM and GMNPR modes on the standard test scene:
// strict baselines, probes near and far from the camera, and the warp's
// effect on texel density seen through the TEXEL_DENSITY analysis view.
#include "ShadowTestUtilities.h"
#include "vtkWarpedShadowMapPass.h"

#include "vtkCamera.h"
#include "vtkImageData.h"

#include <gtest/gtest.h>

using namespace shadowtest;

namespace
{
// Light at right angles to the view (the camera looks along +y).
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(1.0, 0.15, -0.8));

void LookAlongTheGround(TestScene& scene)
{
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(0.0, -9.5, 1.2);
  camera->SetFocalPoint(0.0, 0.0, 0.8);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetClippingRange(0.1, 40.0);
}

int CountUndersampled(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  int count = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      count += static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0))[0] == 255;
    }
  }
  return count;
}

void CheckMode(int mode, const std::string& name)
{
  TestScene scene;
  LookAlongTheGround(scene);
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  pass->SetWarpMode(mode);
  pass->SetResolution(512);
  scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  // The sphere's shadow, lit ground near the camera and far from it.
  const glm::dvec3 shadowed = GroundShadowOfSphereCenter(SunDirection);
  const glm::dvec3 litNear(-2.0, -3.0, 0.0);
  const glm::dvec3 litFar(-3.0, 6.0, 0.0);
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
} // namespace

TEST(ShadowWarps, LiSPSMPerpendicularSun)
{
  CheckMode(vtkWarpedShadowMapPass::LISPSM, "WarpLiSPSM");
}

TEST(ShadowWarps, GMNPRPerpendicularSun)
{
  CheckMode(vtkWarpedShadowMapPass::GMNPR, "WarpGMNPR");
}

TEST(ShadowWarps, WarpsUndersampleFewerPixelsThanTheUniformMap)
{
  int undersampled[3] = { 0, 0, 0 };
  for (int mode : { vtkWarpedShadowMapPass::UNIFORM, vtkWarpedShadowMapPass::LISPSM,
         vtkWarpedShadowMapPass::GMNPR })
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
  EXPECT_EQ(pass->GetWarpMode(), vtkWarpedShadowMapPass::GMNPR);
  pass->SetWarpMode(-1);
  EXPECT_EQ(pass->GetWarpMode(), vtkWarpedShadowMapPass::UNIFORM);
  pass->SetLiSPSMFreeParameter(-5.0);
  EXPECT_EQ(pass->GetLiSPSMFreeParameter(), 0.0);

  TestScene scene;
  scene.Renderer->GetActiveCamera()->ParallelProjectionOn();
  scene.SetSun(SunDirection);
  pass->SetWarpMode(vtkWarpedShadowMapPass::LISPSM);
  scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)),
    ShadowedBelow);
}
