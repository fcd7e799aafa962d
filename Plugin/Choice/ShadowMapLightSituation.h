// What the automatic pass chooses a light's views from: the light's kind and
// where it shines relative to the camera. Read from the light and the camera
// alone, never from the props a process holds, so that every process of a
// parallel renderer reads the same. Plain data and pure functions.
#ifndef ShadowMapLightSituation_h
#define ShadowMapLightSituation_h

#include "ShadowMapLight.h" // For LightKind, ShadowLight

#include <glm/glm.hpp>

#include <string>
#include <vector>

class vtkInformationDoubleKey;
class vtkInformationIntegerKey;
class vtkRenderer;

namespace shadowmaps
{
/// The kinds of light the choice tells apart: a positional light one map
/// cannot hold (NeedsCubeFaces) is a Point light here whatever its cone.
struct LightSituation
{
  LightKind Kind = LightKind::Directional;
  /// Cosine of the angle between the camera's view direction and the light's
  /// (a sun's direction; a positional light's from the light to the camera):
  /// 1 with the light behind the viewer, -1 facing it.
  double CosLightView = 0.0;
  /// A positional light behind the camera's eye plane (post-perspective, it
  /// lies beyond infinity: PSM's inverted case).
  bool LightBehindCamera = false;
  bool ParallelCamera = false;
};

/// The situation of `light` (its Kind, Position, Direction and ConeAngle read)
/// seen by a camera of world-to-eye `cameraView` (VTK's eye space, looking
/// down -z).
LightSituation SituationOf(const ShadowLight& light, const glm::dmat4& cameraView, bool parallel);

/// A shadowed light and its situation.
struct SituatedLight
{
  vtkLight* Light = nullptr;
  LightSituation Situation;
};

/// `renderer`'s shadowed lights (CollectShadowedLights: `castsShadows`,
/// `lightSize`, at most `maximum`) and their situations seen by its active
/// camera, camera lights placed for that camera first.
std::vector<SituatedLight> ReadLightSituations(vtkRenderer* renderer,
  vtkInformationIntegerKey* castsShadows, vtkInformationDoubleKey* lightSize, int maximum);

/// "sun", "spot" or "point" (cube faces).
std::string KindName(LightKind kind);
} // namespace shadowmaps

#endif
