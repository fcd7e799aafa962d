// vtkDepthShadowMapPass with a point light (six cube faces), the VTK way.
#include "ShadowRegression.h"
#include "vtkDepthShadowMapPass.h"

int TestDepthShadowMapPassPoint(int argc, char* argv[])
{
  const glm::dvec3 point(-1.0, 0.5, 5.0);
  shadowtest::TestScene scene;
  scene.SetPoint(point);
  vtkNew<vtkDepthShadowMapPass> shadows;
  return shadowregression::RenderAndCheck(argc, argv, scene, shadows,
    "TestDepthShadowMapPassPoint", shadowtest::GroundShadowOfSphereCenterFrom(point), { -3, -2, 0 });
}
