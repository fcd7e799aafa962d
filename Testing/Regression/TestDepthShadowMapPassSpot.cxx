// vtkDepthShadowMapPass (uniform views, Poisson filter) with a spot light, the VTK way.
#include "ShadowRegression.h"
#include "vtkDepthShadowMapPass.h"

int TestDepthShadowMapPassSpot(int argc, char* argv[])
{
  const glm::dvec3 spot(-2.0, 1.5, 9.0);
  shadowtest::TestScene scene;
  scene.SetSpot(spot, 40.0);
  vtkNew<vtkDepthShadowMapPass> shadows;
  shadows->SetFilterToPoisson();
  return shadowregression::RenderAndCheck(argc, argv, scene, shadows, "TestDepthShadowMapPassSpot",
    shadowtest::GroundShadowOfSphereCenterFrom(spot), { -3, -2, 0 });
}
