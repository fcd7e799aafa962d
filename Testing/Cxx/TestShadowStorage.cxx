// The texel-storage hooks of vtkAbstractShadowMapPass, exercised by two small
// subclasses defined here: a moments map (two filterable values per texel, the
// storage of variance shadow maps) and a nearest-front / nearest-back map
// written with minimum blending (the storage of dual-depth maps).
#include "ShadowTestUtilities.h"
#include "vtkAbstractShadowMapPass.h"
#include "vtkShadowMapInternals.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"

#include <gtest/gtest.h>

using namespace shadowtest;

namespace
{
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(-0.4, 0.3, -1.0));

/// The focused uniform views; the subclasses below choose only the storage.
class vtkTestUniformViewsPass : public vtkAbstractShadowMapPass
{
public:
  vtkTypeMacro(vtkTestUniformViewsPass, vtkAbstractShadowMapPass);

protected:
  void ComputeLightViews(Internals& internals, int lightIndex) override
  {
    this->FitLightViewsUniform(internals, lightIndex);
  }
};

/// Stores (depth, depth^2) with mipmaps and looks up with Chebyshev's bound.
class vtkTestMomentsShadowMapPass : public vtkTestUniformViewsPass
{
public:
  static vtkTestMomentsShadowMapPass* New();
  vtkTypeMacro(vtkTestMomentsShadowMapPass, vtkTestUniformViewsPass);
  int PostProcessCalls = 0;

protected:
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
  bool PostProcessShadowMaps(vtkOpenGLRenderer*, shadowmaps::TextureArray& maps) override
  {
    ++this->PostProcessCalls;
    return maps.GetFormat() == shadowmaps::TexelFormat::TwoFloats && maps.GetTextureName() != 0;
  }
};
vtkStandardNewMacro(vtkTestMomentsShadowMapPass);

/// Keeps the nearest front face and the nearest back face of every texel and
/// compares receivers with their midpoint: no bias needed on closed casters.
class vtkTestFrontBackShadowMapPass : public vtkTestUniformViewsPass
{
public:
  static vtkTestFrontBackShadowMapPass* New();
  vtkTypeMacro(vtkTestFrontBackShadowMapPass, vtkTestUniformViewsPass);

protected:
  void GetMapStorage(shadowmaps::MapStorage& storage) const override
  {
    storage = shadowmaps::MapStorage();
    storage.Format = shadowmaps::TexelFormat::TwoFloats;
    storage.MinimumBlending = true;
    storage.StoreCode = "  gl_FragData[0] = gl_FrontFacing ? vec4(vtkShadowCasterDepth, 1.0, 0.0, 1.0)"
                        " : vec4(1.0, vtkShadowCasterDepth, 0.0, 1.0);";
  }
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
vtkStandardNewMacro(vtkTestFrontBackShadowMapPass);

/// Depth maps whose lookup code can be swapped for one that inverts visibility.
class vtkTestSwappedLookupPass : public vtkTestUniformViewsPass
{
public:
  static vtkTestSwappedLookupPass* New();
  vtkTypeMacro(vtkTestSwappedLookupPass, vtkTestUniformViewsPass);
  void SetInverted(bool inverted)
  {
    this->Inverted = inverted;
    this->Modified();
  }

protected:
  std::string GetReceiverLookupCode() const override
  {
    if (!this->Inverted)
    {
      return this->Superclass::GetReceiverLookupCode();
    }
    return R"(
uniform sampler2DArrayShadow vtkShadowMaps;
float vtkShadowLookup(vec3 mapCoord, int layer)
{
  return 1.0 - texture(vtkShadowMaps, vec4(mapCoord.xy, float(layer), mapCoord.z));
}
)";
  }
  bool Inverted = false;
};
vtkStandardNewMacro(vtkTestSwappedLookupPass);

void ExpectShadowUnderSphere(TestScene& scene, vtkImageData* image)
{
  EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)),
    ShadowedBelow);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { -5, -4, 0 }), LitAbove);
}
} // namespace

TEST(ShadowStorage, MomentsWithMipmaps)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkTestMomentsShadowMapPass> pass;
  pass->SetResolution(256);
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  ExpectShadowUnderSphere(scene, image);
  EXPECT_EQ(pass->PostProcessCalls, pass->GetNumberOfShadowMapUpdates());
  // Two floats per texel plus a third for the mipmaps, and one shared depth buffer.
  const size_t values = 256 * 256 * 8;
  EXPECT_EQ(pass->GetShadowMapMemory(), values + values / 3 + 256 * 256 * 4);
  const std::string difference = CompareWithBaseline(image, "StorageMoments");
  EXPECT_TRUE(difference.empty()) << difference;
}

TEST(ShadowStorage, FrontAndBackByMinimumBlendingNeedNoBias)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkTestFrontBackShadowMapPass> pass;
  pass->SetFilter(vtkAbstractShadowMapPass::HARD);
  pass->SetConstantBias(0.0);
  pass->SetSlopeScaledBias(0.0);
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
  const std::string difference = CompareWithBaseline(image, "StorageFrontBack");
  EXPECT_TRUE(difference.empty()) << difference;
}

// A subclass's lookup code is part of the receivers' shaders: when it changes,
// they are rebuilt.
TEST(ShadowStorage, ChangedLookupCodeRebuildsReceivers)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkTestSwappedLookupPass> pass;
  pass->SetResolution(256);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  ExpectShadowUnderSphere(scene, image);
  pass->SetInverted(true);
  image = RenderAndCapture(scene.Window);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)), LitAbove);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, { -5, -4, 0 }), ShadowedBelow);
}
