// The shadow factor reaches every light's terms in the mappers' shaders of the
// VTK the module is built against: every light kind x Phong and PBR x every
// representation shades its shadow, and no light that a receiver's shader
// lights with is left unpatched (the check issue 37 asks for on each stack:
// a VTK whose mapper writes its lighting differently fails here, not as a
// frame quietly without shadows).
#include "ShadowMapVTKCompat.h" // the GL loader first

#include "ShadowMapGlslLiteral.h"
#include "ShadowMapLight.h"
#include "ShadowMapQuad.h"
#include "ShadowMapReceiverShader.h"
#include "ShadowMapShaderGroup.h"
#include "ShadowTestUtilities.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkVarianceShadowMapPass.h"

#include "vtkActor.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProperty.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

using namespace shadowtest;

namespace
{
enum class LightKind
{
  Sun,
  Spot,
  Point,
  CameraLight
};

const glm::dvec3 LampPosition(-1.0, 0.5, 6.0);

void SetLight(TestScene& scene, LightKind kind)
{
  switch (kind)
  {
    case LightKind::Sun:
      scene.SetSun({ 0.3, 0.2, -1.0 });
      break;
    case LightKind::Spot:
      scene.SetSpot(LampPosition, 45.0);
      break;
    case LightKind::Point:
      scene.SetPoint(LampPosition);
      break;
    case LightKind::CameraLight:
    {
      // Above and to the right of the camera, toward what it looks at.
      vtkLight* light = scene.SetSun({ 0.0, 0.0, -1.0 });
      light->SetLightTypeToCameraLight();
      light->SetPosition(0.4, 1.0, 1.0);
      light->SetFocalPoint(0.0, 0.0, 0.0);
      break;
    }
  }
}

// Where the sphere's centre casts its shadow, from the light as rendered.
glm::dvec3 ShadowOfSphereCenter(vtkLight* light)
{
  const double* position = light->GetTransformedPosition();
  if (light->GetPositional())
  {
    return GroundShadowOfSphereCenterFrom({ position[0], position[1], position[2] });
  }
  const double* focalPoint = light->GetTransformedFocalPoint();
  return GroundShadowOfSphereCenter({ focalPoint[0] - position[0], focalPoint[1] - position[1],
    focalPoint[2] - position[2] });
}

vtkSmartPointer<vtkAbstractShadowMapPass> MakePass(const std::string& representation)
{
  if (representation == "DualDepth")
  {
    return vtkSmartPointer<vtkDualDepthShadowMapPass>::New();
  }
  if (representation == "Moments")
  {
    return vtkSmartPointer<vtkVarianceShadowMapPass>::New();
  }
  return vtkSmartPointer<vtkDepthShadowMapPass>::New();
}

const char* Name(LightKind kind)
{
  const char* names[] = { "Sun", "Spot", "Point", "CameraLight" };
  return names[static_cast<int>(kind)];
}

using InjectionCase = std::tuple<LightKind, bool, std::string>;

class ShadowInjectionCases : public testing::TestWithParam<InjectionCase>
{
};
} // namespace

TEST_P(ShadowInjectionCases, ShadesTheShadowAndPatchesEveryLight)
{
  const auto& [kind, pbr, representation] = GetParam();
  ErrorCounter errors;
  TestScene scene;
  SetLight(scene, kind);
  for (vtkActor* actor : { scene.Ground.Get(), scene.Sphere.Get(), scene.Box.Get() })
  {
    if (pbr)
    {
      actor->GetProperty()->SetInterpolationToPBR();
      actor->GetProperty()->SetRoughness(0.8);
      actor->GetProperty()->SetMetallic(0.0);
    }
  }
  vtkSmartPointer<vtkAbstractShadowMapPass> pass = MakePass(representation);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors(), 0) << errors.Text();
  EXPECT_EQ(pass->GetNumberOfShadowedLights(), 1);
  EXPECT_EQ(pass->GetNumberOfUnpatchedReceiverLights(), 0);

  vtkLight* light = vtkLight::SafeDownCast(scene.Renderer->GetLights()->GetItemAsObject(0));
  const glm::dvec3 shadowed = ShadowOfSphereCenter(light);
  const double dark = LuminanceAt(scene.Renderer, image, shadowed);
  const double lit = LuminanceAt(scene.Renderer, image, { 2.5, -2.5, 0.0 });
  EXPECT_GT(lit, 60.0);
  EXPECT_LT(dark, 0.5 * lit) << "at " << shadowed.x << ", " << shadowed.y;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(ShadowInjection, ShadowInjectionCases,
  testing::Combine(
    testing::Values(LightKind::Sun, LightKind::Spot, LightKind::Point, LightKind::CameraLight),
    testing::Bool(), testing::Values("Depth", "DualDepth", "Moments")),
  [](const testing::TestParamInfo<InjectionCase>& info) {
    return std::string(Name(std::get<0>(info.param))) + (std::get<1>(info.param) ? "PBR" : "Phong") +
      std::get<2>(info.param);
  });

// The count the test above relies on can fail: lighting code none of the
// patterns knows is counted, code without the light is not.
TEST(ShadowInjection, LightingCodeItCannotPatchIsCounted)
{
  shadowmaps::ShadowLight light;
  light.ShaderIndex = 0;
  const std::vector<shadowmaps::ShadowLight> lights{ light };
  shadowmaps::ReceiverCode code;
  const shadowmaps::ShaderGroup group;
  const std::string head = "//VTK::System::Dec\nuniform vec3 lightColor0;\n//VTK::Light::Dec\n"
                           "void main()\n{\n  vec3 diffuse = vec3(0.0);\n  float df = 1.0;\n"
                           "  //VTK::Light::Impl\n";
  std::string known = head + "  diffuse += (df * lightColor0);\n}\n";
  shadowmaps::ReceiverShader::MarkInjectionPoints(known);
  EXPECT_EQ(shadowmaps::ReceiverShader::Inject(known, lights, 1, code, true, false, false, group), 0);
  EXPECT_NE(known.find("lightColor0 * vtkShadowFactor0"), std::string::npos);

  std::string unknown = head + "  diffuse += df * lightColor0 * 0.5;\n}\n";
  shadowmaps::ReceiverShader::MarkInjectionPoints(unknown);
  EXPECT_EQ(shadowmaps::ReceiverShader::Inject(unknown, lights, 1, code, true, false, false, group), 1);
  EXPECT_EQ(unknown.find("vtkShadowFactor"), std::string::npos);
  shadowmaps::ReceiverShader::ClearMarkers(unknown);
  EXPECT_EQ(unknown.find("//VTK::ShadowMaps"), std::string::npos);

  // lightColor01 is another light's; an unlit shader names none.
  std::string other = "uniform vec3 lightColor01;\nvoid main()\n{\n}\n";
  EXPECT_EQ(shadowmaps::ReceiverShader::Inject(other, lights, 1, code, true, false, false, group), 0);

  // VTK declares the light's colour for props it draws unlit, and uses it nowhere.
  std::string unlit = head + "  gl_FragData[0] = vec4(1.0);\n}\n";
  shadowmaps::ReceiverShader::MarkInjectionPoints(unlit);
  EXPECT_EQ(shadowmaps::ReceiverShader::Inject(unlit, lights, 1, code, true, false, false, group), 0);
}

// Numbers #define'd into GLSL are float literals the GL parses, huge and tiny
// ones included: each compiles as the initialiser of a float.
TEST(ShadowInjection, GlslLiteralsCompileForEveryValue)
{
  const std::vector<std::pair<double, std::string>> literals = { { 2.0, "2.00000000" },
    { 1e30, "1.00000000e+30" }, { -1e30, "-1.00000000e+30" }, { 1e-30, "1.00000000e-30" },
    { 0.0, "0.00000000" }, { 1e300, "1.00000000e+38" }, { -1e300, "-1.00000000e+38" },
    { std::nan(""), "0.00000000" } };
  std::string code = "//VTK::System::Dec\n//VTK::Output::Dec\nin vec2 texCoord;\nvoid main()\n{\n"
                     "  float sum = 0.0;\n";
  for (const auto& literal : literals)
  {
    EXPECT_EQ(shadowmaps::GlslFloat(literal.first), literal.second);
    code += "  sum += " + shadowmaps::GlslFloat(literal.first) + " * texCoord.x;\n";
  }
  code += "  gl_FragData[0] = vec4(sum);\n}\n";
  TestScene scene;
  scene.Window->Render();
  std::unique_ptr<vtkOpenGLQuadHelper> quad;
  EXPECT_NE(shadowmaps::ReadyQuadProgram(
              quad, vtkOpenGLRenderWindow::SafeDownCast(scene.Window), code.c_str()),
    nullptr);
  quad.reset();
  scene.Window->ReleaseGraphicsResources(scene.Window);
}
