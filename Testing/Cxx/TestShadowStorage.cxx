// The representation strategy (vtkShadowMapRepresentation), exercised by small
// subclasses defined here: a moments map (two filterable values per texel, the
// storage of variance shadow maps) and a nearest-front / nearest-back map
// written with minimum blending (the storage of dual-depth maps). Each runs with
// the uniform, cascaded and warped views: the two choices are independent.
#include "ShadowTestUtilities.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDepthShadowMapRepresentation.h"
#include "vtkShadowMapRepresentation.h"
#include "vtkShadowMapViews.h"
#include "vtkWarpedShadowMapViews.h"
#include "vtkWarpedShadowMapPass.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"

#include <gtest/gtest.h>

using namespace shadowtest;

namespace
{
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(-0.4, 0.3, -1.0));

/// Stores (depth, depth^2) with mipmaps and looks up with Chebyshev's bound.
class vtkTestMomentsRepresentation : public vtkShadowMapRepresentation
{
public:
  static vtkTestMomentsRepresentation* New();
  vtkTypeMacro(vtkTestMomentsRepresentation, vtkShadowMapRepresentation);
  int PostProcessCalls = 0;
  int PostProcessedLayers = 0;

  void GetMapStorage(shadowmaps::MapStorage& storage) const override
  {
    storage = shadowmaps::MapStorage();
    storage.Format = shadowmaps::TexelFormat::TwoFloats;
    storage.StoreCode = "  gl_FragData[0] = vec4(vtkShadowCasterDepth, "
                        "vtkShadowCasterDepth * vtkShadowCasterDepth, 0.0, 1.0);";
    storage.Mipmaps = true;
  }
  std::string GetReceiverLookupCode() const override
  {
    return R"(
uniform sampler2DArray vtkShadowMaps;
float vtkShadowLookup(vec3 mapCoord, int layer)
{
  vec2 moments = texture(vtkShadowMaps, vec3(mapCoord.xy, float(layer))).xy;
  if (mapCoord.z <= moments.x)
  {
    return 1.0;
  }
  float variance = max(moments.y - moments.x * moments.x, 1e-7);
  float d = mapCoord.z - moments.x;
  return clamp((variance / (variance + d * d) - 0.3) / 0.7, 0.0, 1.0);
}
)";
  }
  // The depth maps' default offset: the moments' mean stays just behind the
  // casters' lit faces, so that Chebyshev's bound does not darken them.
  shadowmaps::DepthOffset GetCasterDepthOffset() const override
  {
    shadowmaps::DepthOffset offset;
    offset.SlopeScaled = 2.0;
    offset.Constant = 4.0;
    return offset;
  }
  bool PostProcessMaps(vtkOpenGLRenderer*, shadowmaps::TextureArray& maps,
    const std::vector<shadowmaps::RenderedLayer>& layers) override
  {
    ++this->PostProcessCalls;
    this->PostProcessedLayers += static_cast<int>(layers.size());
    return maps.GetFormat() == shadowmaps::TexelFormat::TwoFloats && maps.GetTextureName() != 0;
  }
};
vtkStandardNewMacro(vtkTestMomentsRepresentation);

/// Keeps the nearest front face and the nearest back face of every texel and
/// compares receivers with their midpoint: no bias needed on closed casters.
class vtkTestFrontBackRepresentation : public vtkShadowMapRepresentation
{
public:
  static vtkTestFrontBackRepresentation* New();
  vtkTypeMacro(vtkTestFrontBackRepresentation, vtkShadowMapRepresentation);

  void GetMapStorage(shadowmaps::MapStorage& storage) const override
  {
    storage = shadowmaps::MapStorage();
    storage.Format = shadowmaps::TexelFormat::TwoFloats;
    storage.MinimumBlending = true;
    storage.StoreCode = "  gl_FragData[0] = gl_FrontFacing ? vec4(vtkShadowCasterDepth, 1.0, 0.0, 1.0)"
                        " : vec4(1.0, vtkShadowCasterDepth, 0.0, 1.0);";
  }
  bool GetLinearFiltering() const override { return false; }
  std::string GetReceiverLookupCode() const override
  {
    return R"(
uniform sampler2DArray vtkShadowMaps;
float vtkShadowLookup(vec3 mapCoord, int layer)
{
  vec2 frontBack = texture(vtkShadowMaps, vec3(mapCoord.xy, float(layer))).xy;
  return mapCoord.z <= 0.5 * (frontBack.x + frontBack.y) ? 1.0 : 0.0;
}
)";
  }
};
vtkStandardNewMacro(vtkTestFrontBackRepresentation);

/// Depth maps whose lookup code can be swapped for one that inverts visibility.
class vtkTestSwappedLookupRepresentation : public vtkDepthShadowMapRepresentation
{
public:
  static vtkTestSwappedLookupRepresentation* New();
  vtkTypeMacro(vtkTestSwappedLookupRepresentation, vtkDepthShadowMapRepresentation);
  void SetInverted(bool inverted)
  {
    this->Inverted = inverted;
    this->Modified();
  }
  void SetBroken(bool broken)
  {
    this->Broken = broken;
    this->Modified();
  }
  std::string GetReceiverLookupCode() const override
  {
    if (this->Broken)
    {
      return "this is not GLSL;\n";
    }
    if (!this->Inverted)
    {
      return this->Superclass::GetReceiverLookupCode();
    }
    return R"(
uniform sampler2DArrayShadow vtkShadowMaps;
uniform sampler2D vtkShadowNoise;
uniform float vtkShadowFilterRadius;
float vtkShadowLookup(vec3 mapCoord, int layer)
{
  return 1.0 - texture(vtkShadowMaps, vec4(mapCoord.xy, float(layer), mapCoord.z));
}
)";
  }

private:
  bool Inverted = false;
  bool Broken = false;
};
vtkStandardNewMacro(vtkTestSwappedLookupRepresentation);

/// The three views strategies, as the passes that preset them.
vtkSmartPointer<vtkAbstractShadowMapPass> MakePass(const std::string& views)
{
  if (views == "Cascaded")
  {
    return vtkSmartPointer<vtkCascadedShadowMapPass>::New();
  }
  if (views == "Warped")
  {
    auto warped = vtkSmartPointer<vtkWarpedShadowMapPass>::New();
    warped->SetWarpModeToLiSPSM();
    return warped;
  }
  return vtkSmartPointer<vtkDepthShadowMapPass>::New();
}

// Baseline name: the storage, then the views unless uniform.
std::string BaselineName(const std::string& storage, const std::string& views)
{
  return "Storage" + storage + (views == "Uniform" ? std::string() : views);
}

void ExpectShadowUnderSphere(TestScene& scene, vtkImageData* image)
{
  EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)),
    ShadowedBelow);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { -5, -4, 0 }), LitAbove);
}
} // namespace

class ShadowStorageViews : public ::testing::TestWithParam<std::string>
{
};

TEST_P(ShadowStorageViews, MomentsWithMipmaps)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  auto pass = MakePass(GetParam());
  vtkNew<vtkTestMomentsRepresentation> moments;
  pass->SetRepresentation(moments);
  pass->SetResolution(256);
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  ExpectShadowUnderSphere(scene, image);
  // Post-processing sees each re-rendered layer once, and only those. (The
  // capture renders with a copy of the camera: the next frame may differ.)
  EXPECT_GE(moments->PostProcessedLayers, pass->GetNumberOfShadowMapLayers());
  scene.Window->Render();
  const int calls = moments->PostProcessCalls;
  const int layers = moments->PostProcessedLayers;
  scene.Window->Render();
  EXPECT_EQ(moments->PostProcessCalls, calls) << "a steady frame";
  pass->Modified();
  scene.Window->Render();
  EXPECT_EQ(moments->PostProcessCalls, calls + 1);
  EXPECT_EQ(pass->GetNumberOfRenderedLayers(), pass->GetNumberOfShadowMapLayers());
  EXPECT_EQ(moments->PostProcessedLayers, layers + pass->GetNumberOfShadowMapLayers());
  // Two floats per texel plus a third for the mipmaps, and one shared depth buffer.
  const size_t values = 256 * 256 * 8 * pass->GetNumberOfShadowMapLayers();
  const size_t depth = 256 * 256 * 4;
  EXPECT_EQ(pass->GetShadowMapMemory(), values + values / 3 + depth);
  const std::string difference = CompareWithBaseline(image, BaselineName("Moments", GetParam()));
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

TEST_P(ShadowStorageViews, FrontAndBackByMinimumBlendingNeedNoBias)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  auto pass = MakePass(GetParam());
  vtkNew<vtkTestFrontBackRepresentation> frontBack;
  pass->SetRepresentation(frontBack);
  pass->SetNormalOffset(0.0);
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  ExpectShadowUnderSphere(scene, image);
  // The sphere's sunlit cap and the box's sunlit top are lit although no bias
  // is applied: the midpoint lies inside the casters.
  EXPECT_GT(LuminanceAt(scene.Renderer, image, glm::dvec3(0, 0, 1.5) - SunDirection), LitAbove);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { 4, 2, 1.5 }), LitAbove);
  const std::string difference = CompareWithBaseline(image, BaselineName("FrontBack", GetParam()));
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(Views, ShadowStorageViews,
  ::testing::Values("Uniform", "Cascaded", "Warped"),
  [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// A representation's lookup code is part of the receivers' shaders: when it
// changes, they are rebuilt.
TEST(ShadowStorage, ChangedLookupCodeRebuildsReceivers)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkDepthShadowMapPass> pass;
  vtkNew<vtkTestSwappedLookupRepresentation> swapped;
  pass->SetRepresentation(swapped);
  pass->SetResolution(256);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  ExpectShadowUnderSphere(scene, image);
  swapped->SetInverted(true);
  image = RenderAndCapture(scene.Window);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)), LitAbove);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, { -5, -4, 0 }), ShadowedBelow);
}

// A representation whose lookup does not compile: the mappers' shaders fail,
// VTK reports it, and the frame still renders, without a crash.
TEST(ShadowStorage, LookupThatDoesNotCompileDoesNotCrash)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkDepthShadowMapPass> pass;
  vtkNew<vtkTestSwappedLookupRepresentation> broken;
  broken->SetBroken(true);
  pass->SetRepresentation(broken);
  pass->SetResolution(256);
  scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  RenderAndCapture(scene.Window);
  scene.Renderer->GetActiveCamera()->Azimuth(5.0);
  RenderAndCapture(scene.Window);
  EXPECT_GT(errors.Errors(), 0) << "VTK reports the shader";
  broken->SetBroken(false);
  auto image = RenderAndCapture(scene.Window);
  ExpectShadowUnderSphere(scene, image);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

namespace
{
/// Depth maps whose post-processing fails (a GL failure after the casters drew).
class vtkTestFailingPostProcess : public vtkDepthShadowMapRepresentation
{
public:
  static vtkTestFailingPostProcess* New();
  vtkTypeMacro(vtkTestFailingPostProcess, vtkDepthShadowMapRepresentation);
  bool PostProcessMaps(vtkOpenGLRenderer*, shadowmaps::TextureArray&,
    const std::vector<shadowmaps::RenderedLayer>&) override
  {
    return false;
  }
};
vtkStandardNewMacro(vtkTestFailingPostProcess);
} // namespace

// A failure after the casters drew leaves the frame as it is without shadows:
// the scene's draws do not go through the casters' branch of the programs the
// casters just used.
TEST(ShadowStorage, AFailureAfterCastingRendersTheFrameWithoutShadows)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  const auto plain = RenderAndCapture(scene.Window);
  vtkNew<vtkDepthShadowMapPass> pass;
  vtkNew<vtkTestFailingPostProcess> failing;
  pass->SetRepresentation(failing);
  scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  const auto image = RenderAndCapture(scene.Window);
  EXPECT_NE(errors.Text().find("could not be post-processed"), std::string::npos);
  for (const glm::dvec3& point : { GroundShadowOfSphereCenter(SunDirection), glm::dvec3(-5, -4, 0) })
  {
    EXPECT_NEAR(LuminanceAt(scene.Renderer, image, point), LuminanceAt(scene.Renderer, plain, point), 1.0);
  }
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

// SetRepresentation(nullptr) and SetViews(nullptr) restore the preset's own.
TEST(ShadowStorage, NullRestoresThePresetStrategies)
{
  vtkNew<vtkWarpedShadowMapPass> pass;
  vtkShadowMapRepresentation* depth = pass->GetRepresentation();
  vtkShadowMapViews* warped = pass->GetViews();
  EXPECT_EQ(depth, pass->GetDepthRepresentation());
  EXPECT_EQ(warped, pass->GetWarpedViews());
  vtkNew<vtkTestMomentsRepresentation> moments;
  pass->SetRepresentation(moments);
  EXPECT_EQ(pass->GetRepresentation(), moments.Get());
  pass->SetRepresentation(nullptr);
  EXPECT_EQ(pass->GetRepresentation(), depth);
  pass->SetViews(nullptr);
  EXPECT_EQ(pass->GetViews(), warped);
}

// A parameter of a strategy is a parameter of the pass: changing it re-renders the maps.
TEST(ShadowStorage, StrategyParametersReRenderTheMaps)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  scene.Window->Render();
  scene.Window->Render();
  const int updates = pass->GetNumberOfShadowMapUpdates();
  pass->GetWarpedViews()->SetWarpModeToTSM();
  scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates + 1);
  pass->GetDepthRepresentation()->SetSlopeScaledBias(3.0);
  scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates + 2);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

// One representation may serve passes in two windows (two GL contexts): each
// frame's receivers read textures of their own context.
TEST(ShadowStorage, ARepresentationServesPassesInTwoWindows)
{
  TestScene first;
  TestScene second;
  first.SetSun(SunDirection);
  second.SetSun(SunDirection);
  vtkNew<vtkDepthShadowMapRepresentation> poisson;
  poisson->SetFilterToPoisson();
  vtkNew<vtkDepthShadowMapPass> firstPass;
  vtkNew<vtkWarpedShadowMapPass> secondPass;
  firstPass->SetRepresentation(poisson);
  secondPass->SetRepresentation(poisson);
  first.Renderer->SetPass(firstPass);
  second.Renderer->SetPass(secondPass);
  ErrorCounter errors;
  for (int frame = 0; frame < 2; ++frame)
  {
    auto firstImage = RenderAndCapture(first.Window);
    auto secondImage = RenderAndCapture(second.Window);
    ExpectShadowUnderSphere(first, firstImage);
    ExpectShadowUnderSphere(second, secondImage);
  }
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  first.Renderer->SetPass(nullptr);
  second.Renderer->SetPass(nullptr);
  firstPass->ReleaseGraphicsResources(first.Window);
  secondPass->ReleaseGraphicsResources(second.Window);
}
