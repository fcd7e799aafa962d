// vtkCascadedShadowMapPass with a sun, the VTK way.
#include "ShadowRegression.h"
#include "vtkCascadedShadowMapPass.h"

int TestCascadedShadowMapPass(int argc, char* argv[])
{
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.5, -0.3, -1.0));
  shadowtest::TestScene scene;
  scene.SetSun(sun);
  vtkNew<vtkCascadedShadowMapPass> shadows;
  return shadowregression::RenderAndCheck(argc, argv, scene, shadows, "TestCascadedShadowMapPass",
    shadowtest::GroundShadowOfSphereCenter(sun), { -5, -4, 0 });
}
