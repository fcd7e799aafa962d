// Per-frame state shared by vtkAbstractShadowMapPass and its subclasses.
#ifndef vtkShadowMapInternals_h
#define vtkShadowMapInternals_h

#include "ShadowMapFocusing.h"
#include "ShadowMapTextureArray.h"
#include "vtkAbstractShadowMapPass.h"

#include <vector>

#include <glm/glm.hpp>

class vtkLight;
class vtkProp;

namespace shadowmaps
{
enum class LightKind
{
  Directional,
  Spot,
  Point
};

/// A light that casts shadows this frame.
struct ShadowLight
{
  vtkLight* Light = nullptr;
  /// Index of the light in the mappers' generated lighting code (lightColor<i>).
  int ShaderIndex = 0;
  LightKind Kind = LightKind::Directional;
  /// Cube lights have six views, looked up by direction.
  bool Cube = false;
  glm::dvec3 Position{ 0.0 };
  /// From the light toward what it lights.
  glm::dvec3 Direction{ 0.0, 0.0, -1.0 };
  double ConeAngle = 90.0;
  float Attenuation = 1.0f;
  int FirstLayer = 0;
  std::vector<LightView> Views;
};

/// A prop that renders into the maps, with its world bounds.
struct Caster
{
  vtkProp* Prop = nullptr;
  Aabb Bounds;
};
} // namespace shadowmaps

struct vtkAbstractShadowMapPass::Internals
{
  // The frame being rendered.
  glm::dmat4 CameraView{ 1.0 };
  glm::dmat4 CameraProjection{ 1.0 };
  shadowmaps::Aabb SceneBounds;
  std::vector<shadowmaps::ShadowLight> Lights;
  std::vector<shadowmaps::Caster> Casters;
  int Resolution = 0;

  glm::dmat4 CameraViewProjection() const { return this->CameraProjection * this->CameraView; }
};

#endif
