#include "ShadowMapLightSituation.h"

#include "ShadowMapSceneReading.h"

#include "vtkRenderer.h"

#include <algorithm>

namespace shadowmaps
{
//------------------------------------------------------------------------------
LightSituation SituationOf(const ShadowLight& light, const glm::dmat4& cameraView, bool parallel)
{
  LightSituation situation;
  situation.Kind = light.Kind;
  if (light.Kind == LightKind::Spot && NeedsCubeFaces(light))
  {
    situation.Kind = LightKind::Point;
  }
  situation.ParallelCamera = parallel;
  const glm::dmat4 eyeToWorld = glm::inverse(cameraView);
  const glm::dvec3 eye(eyeToWorld[3]);
  const glm::dvec3 viewDirection = SafeDirection(-glm::dvec3(eyeToWorld[2]));
  glm::dvec3 lightDirection = SafeDirection(light.Direction);
  const glm::dvec3 toEye = eye - light.Position;
  const bool atTheEye =
    glm::length(toEye) <= 1e-9 * std::max(1.0, glm::length(eye) + glm::length(light.Position));
  if (light.Kind != LightKind::Directional && !atTheEye)
  {
    lightDirection = SafeDirection(toEye);
    const glm::dvec4 lightInEye = cameraView * glm::dvec4(light.Position, 1.0);
    situation.LightBehindCamera = !parallel && lightInEye.z > 0.0;
  }
  // A light at the eye (a flashlight) shines along its own direction; the
  // direction to the eye would be rounding noise.
  situation.CosLightView = glm::clamp(glm::dot(viewDirection, lightDirection), -1.0, 1.0);
  return situation;
}

//------------------------------------------------------------------------------
std::vector<SituatedLight> ReadLightSituations(vtkRenderer* renderer,
  vtkInformationIntegerKey* castsShadows, vtkInformationDoubleKey* lightSize, int maximum)
{
  // Camera lights where this frame's camera puts them (the frame update does
  // the same later).
  renderer->UpdateLightsGeometryToFollowCamera();
  int skipped = 0;
  std::vector<vtkLight*> clamped;
  ShadowFrame frame;
  const bool parallel = ReadSceneCamera(renderer, frame).Parallel;
  std::vector<SituatedLight> situated;
  for (const ShadowLight& light :
    CollectShadowedLights(renderer, castsShadows, lightSize, maximum, skipped, clamped))
  {
    situated.push_back({ light.Light, SituationOf(light, frame.CameraView, parallel) });
  }
  return situated;
}

//------------------------------------------------------------------------------
std::string KindName(LightKind kind)
{
  return kind == LightKind::Directional ? "sun" : kind == LightKind::Spot ? "spot" : "point";
}
} // namespace shadowmaps
