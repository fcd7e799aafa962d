// vtkWarpedShadowMapPass (LiSPSM) with a sun, the VTK way.
#include "ShadowRegression.h"
#include "vtkWarpedShadowMapPass.h"

int TestWarpedShadowMapPass(int argc, char* argv[])
{
  const glm::dvec3 sun = glm::normalize(glm::dvec3(-0.4, 0.3, -1.0));
  shadowtest::TestScene scene;
  scene.SetSun(sun);
  vtkNew<vtkWarpedShadowMapPass> shadows;
  shadows->SetWarpModeToLiSPSM();
  return shadowregression::RenderAndCheck(argc, argv, scene, shadows, "TestWarpedShadowMapPass",
    shadowtest::GroundShadowOfSphereCenter(sun), { -5, -4, 0 });
}
