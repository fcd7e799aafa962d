// Image tests: each light kind and each filter, compared strictly with a
// baseline and probed: the ground under the sphere is dark, open ground is lit.
#include "ShadowTestUtilities.h"
#include "vtkWarpedShadowMapPass.h"

#include "vtkImageData.h"
#include "vtkRenderer.h"

#include <gtest/gtest.h>

using namespace shadowtest;

namespace
{
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(-0.4, 0.3, -1.0));
const glm::dvec3 SpotPosition(-2.0, 1.5, 9.0);
const glm::dvec3 PointPosition(-1.0, 0.5, 5.0);

void ExpectShadowAndLight(TestScene& scene, vtkImageData* image, const glm::dvec3& shadowed,
  const glm::dvec3& lit, const std::string& what)
{
  const double dark = LuminanceAt(scene.Renderer, image, shadowed);
  const double bright = LuminanceAt(scene.Renderer, image, lit);
  EXPECT_LT(dark, ShadowedBelow) << what << ": ground under the sphere should be in shadow";
  EXPECT_GT(bright, LitAbove) << what << ": open ground should be lit";
}

void RenderAndCheck(TestScene& scene, vtkAbstractShadowMapPass* pass, const std::string& name,
  const glm::dvec3& shadowed, const glm::dvec3& lit)
{
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors(), 0) << errors.Text();
  ExpectShadowAndLight(scene, image, shadowed, lit, name);
  const std::string difference = CompareWithBaseline(image, name);
  EXPECT_TRUE(difference.empty()) << difference;
}
} // namespace

TEST(ShadowImages, SunPcf2x2)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  RenderAndCheck(scene, pass, "SunPcf2x2", GroundShadowOfSphereCenter(SunDirection), { -5, -4, 0 });
  EXPECT_EQ(pass->GetNumberOfShadowedLights(), 1);
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 1);
}

TEST(ShadowImages, SpotPcf2x2)
{
  TestScene scene;
  scene.SetSpot(SpotPosition, 40.0);
  vtkNew<vtkWarpedShadowMapPass> pass;
  RenderAndCheck(scene, pass, "SpotPcf2x2", GroundShadowOfSphereCenterFrom(SpotPosition), { -3, -2, 0 });
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 1);
}

TEST(ShadowImages, PointPcf2x2)
{
  TestScene scene;
  scene.SetPoint(PointPosition);
  vtkNew<vtkWarpedShadowMapPass> pass;
  RenderAndCheck(scene, pass, "PointPcf2x2", GroundShadowOfSphereCenterFrom(PointPosition), { -3, -2, 0 });
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 6);
}

TEST(ShadowImages, SunHard)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  pass->SetFilter(vtkDepthShadowMapPass::HARD);
  RenderAndCheck(scene, pass, "SunHard", GroundShadowOfSphereCenter(SunDirection), { -5, -4, 0 });
}

TEST(ShadowImages, SunPcf5x5)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  pass->SetFilter(vtkDepthShadowMapPass::PCF_NXN);
  pass->SetKernelSize(5);
  pass->SetResolution(512);
  RenderAndCheck(scene, pass, "SunPcf5x5", GroundShadowOfSphereCenter(SunDirection), { -5, -4, 0 });
}

TEST(ShadowImages, SunPoisson)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  pass->SetFilter(vtkDepthShadowMapPass::POISSON);
  pass->SetFilterRadius(3.0);
  pass->SetResolution(512);
  RenderAndCheck(scene, pass, "SunPoisson", GroundShadowOfSphereCenter(SunDirection), { -5, -4, 0 });
}

// Soft filters blur the penumbra: across the shadow edge the hard filter
// jumps where the filtered ones ramp. Measured as the count of intermediate
// pixels along a line crossing the edge.
TEST(ShadowImages, FiltersSoftenThePenumbra)
{
  auto intermediatePixels = [](int filter) {
    TestScene scene;
    scene.SetSun(SunDirection);
    vtkNew<vtkWarpedShadowMapPass> pass;
    pass->SetResolution(256);
    pass->SetFilter(filter);
    pass->SetFilterRadius(3.0);
    scene.Renderer->SetPass(pass);
    auto image = RenderAndCapture(scene.Window);
    const glm::dvec3 center = GroundShadowOfSphereCenter(SunDirection);
    int count = 0;
    for (int i = 0; i <= 200; ++i)
    {
      const glm::dvec3 p = center + glm::dvec3(-3.0 + 6.0 * i / 200.0, 0.0, 0.0);
      const double l = LuminanceAt(scene.Renderer, image, p);
      count += (l > ShadowedBelow && l < LitAbove + 60.0) ? 1 : 0;
    }
    return count;
  };
  const int hard = intermediatePixels(vtkDepthShadowMapPass::HARD);
  const int poisson = intermediatePixels(vtkDepthShadowMapPass::POISSON);
  EXPECT_GT(poisson, hard);
}
