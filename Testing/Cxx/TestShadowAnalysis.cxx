// The analysis views of vtkAbstractShadowMapPass: what each shows at world
// points whose answer is known, and a strict baseline of each.
#include "ShadowTestUtilities.h"
#include "vtkWarpedShadowMapPass.h"

#include "vtkImageData.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

using namespace shadowtest;

namespace
{
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(-0.4, 0.3, -1.0));
const glm::dvec3 OpenGround(-5, -4, 0);

vtkSmartPointer<vtkImageData> RenderView(TestScene& scene, vtkWarpedShadowMapPass* pass, int view)
{
  pass->SetAnalysisView(view);
  scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  return image;
}

void ExpectBaseline(vtkImageData* image, const std::string& name)
{
  const std::string difference = CompareWithBaseline(image, name);
  EXPECT_TRUE(difference.empty()) << difference;
}
} // namespace

TEST(ShadowAnalysis, ShadowFactorIsBlackInShadowAndWhiteInLight)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  auto image = RenderView(scene, pass, vtkAbstractShadowMapPass::SHADOW_FACTOR);
  EXPECT_EQ(ColorAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)), glm::ivec3(0));
  EXPECT_EQ(ColorAt(scene.Renderer, image, OpenGround), glm::ivec3(255));
  ExpectBaseline(image, "AnalysisShadowFactor");
}

TEST(ShadowAnalysis, TexelDensityMarksUndersampledPixelsRed)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  // 64^2 texels over the visible ground: each texel covers several pixels.
  pass->SetResolution(64);
  auto coarse = RenderView(scene, pass, vtkAbstractShadowMapPass::TEXEL_DENSITY);
  EXPECT_EQ(ColorAt(scene.Renderer, coarse, OpenGround).r, 255);
  ExpectBaseline(coarse, "AnalysisTexelDensity64");
  pass->SetResolution(4096);
  auto fine = RenderView(scene, pass, vtkAbstractShadowMapPass::TEXEL_DENSITY);
  EXPECT_LE(ColorAt(scene.Renderer, fine, OpenGround).r, 128);
}

TEST(ShadowAnalysis, PartitionShowsTheSixCubeFaces)
{
  TestScene scene;
  scene.SetPoint({ -1.0, 0.5, 5.0 });
  vtkNew<vtkWarpedShadowMapPass> pass;
  auto image = RenderView(scene, pass, vtkAbstractShadowMapPass::PARTITION);
  // The ground right under the light is shaded from the -z face, ground far to
  // the side from a side face: two different colours.
  const glm::ivec3 below = ColorAt(scene.Renderer, image, { -1.0, 0.5, 0.0 });
  const glm::ivec3 side = ColorAt(scene.Renderer, image, { -9.0, -8.0, 0.0 });
  EXPECT_NE(below, side);
  EXPECT_NE(below, glm::ivec3(0));
  ExpectBaseline(image, "AnalysisPartitionPoint");
}

TEST(ShadowAnalysis, ShadowMapViewShowsTheLightsDepth)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  auto image = RenderView(scene, pass, vtkAbstractShadowMapPass::SHADOW_MAP);
  // The whole frame is the map: no background colour remains, and the sphere,
  // nearer the light than the ground, shows darker than the ground around it.
  std::set<std::tuple<int, int, int>> colors;
  int dims[3];
  image->GetDimensions(dims);
  for (int y = 0; y < dims[1]; y += 7)
  {
    for (int x = 0; x < dims[0]; x += 7)
    {
      auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      EXPECT_EQ(p[0], p[1]);
      EXPECT_EQ(p[1], p[2]);
      colors.insert({ p[0], p[1], p[2] });
    }
  }
  EXPECT_GT(colors.size(), 20u);
  ExpectBaseline(image, "AnalysisShadowMap");
}

TEST(ShadowAnalysis, AnalysedLightBeyondTheShadowedLightsRendersNormally)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  pass->SetAnalysisLight(3);
  auto image = RenderView(scene, pass, vtkAbstractShadowMapPass::SHADOW_FACTOR);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)), ShadowedBelow);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, OpenGround), LitAbove);
  EXPECT_NE(ColorAt(scene.Renderer, image, OpenGround), glm::ivec3(255));
}
