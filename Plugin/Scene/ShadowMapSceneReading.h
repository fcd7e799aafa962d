// What a frame's shadows are made of, read from a renderer: the shadowed
// lights, the scene camera, the visible props' bounds and the casters. The
// pass reads these first every frame; nothing here touches the GL. Not a VTK
// class.
#ifndef ShadowMapSceneReading_h
#define ShadowMapSceneReading_h

#include "ShadowMapCasterVersion.h" // For ImpostorSizing
#include "ShadowMapLight.h"         // For ShadowLight, ShadowFrame, Aabb
#include "ShadowMapPropRoles.h"     // For IsEnabled, TakesPart

#include "vtkType.h" // For vtkMTimeType

#include <string>
#include <vector>

class vtkInformation;
class vtkInformationDoubleKey;
class vtkInformationIntegerKey;
class vtkLight;
class vtkProp;
class vtkRenderer;

namespace shadowmaps
{
class PropRecords;

/// A prop that renders into the maps: its world bounds (grown by its
/// impostors' reach) and the version of everything its depth depends on
/// (CasterVersion).
struct Caster
{
  vtkProp* Prop = nullptr;
  Aabb Bounds;
  vtkMTimeType Version = 0;
  /// What it draws into the maps: depth (opaque geometry), transmittance
  /// (translucent polygons, or a volume marched), or both (an assembly of
  /// both kinds).
  bool Opaque = true;
  bool Translucent = false;
};

/// Whether any of `casters` draws into the transmittance maps.
bool AnyTranslucent(const std::vector<Caster>& casters);

/// Whether the transmittance maps hold what `prop`, drawn as a receiver,
/// lets through itself where it is translucent: it casts (TakesPart in
/// `castsShadows`),
/// with the same faces and colours toward the light as toward the camera (an
/// actor without face culling or a back-face property). Its receivers then
/// divide their own share out of the maps' product.
bool HoldsItsOwnTransmittance(vtkProp* prop, vtkInformationIntegerKey* castsShadows);

/// Suns wider than this (degrees) are clamped to it: wider is a lamp.
constexpr double WidestSun = 30.0;

/// OSPRay's light radius key (vtkOSPRayLightNode::RADIUS, which ParaView's
/// Light Inspector sets), found by name: nullptr without VTK's ray tracing.
vtkInformationDoubleKey* OSPRayRadiusKey();

/// The value stored under `key` (vtkAbstractShadowMapPass::LIGHT_SIZE), or
/// else under OSPRayRadiusKey() (the same units); 0 when neither is set.
double StoredLightSize(vtkLight* light, vtkInformationDoubleKey* key);

/// StoredLightSize made usable:
/// 0 when absent, not finite or negative, a sun's at most WidestSun, a
/// positional light's at most 1e30 (single precision). Sets
/// `clamped` (when given) to whether that changed the stored value.
double LightSizeOf(vtkLight* light, vtkInformationDoubleKey* key, bool* clamped = nullptr);

/// The renderer's switched-on lights that cast shadows (not headlights, not
/// opted out by `castsShadows`), at most `maximum` of them, without views;
/// `skipped` counts those beyond the maximum. Each keeps its index among the
/// switched-on lights, the mappers' shaders' light index, and its size
/// (LightSizeOf `lightSize`); `clampedSizes` lists the lights whose stored
/// size was not usable as it was.
std::vector<ShadowLight> CollectShadowedLights(vtkRenderer* renderer,
  vtkInformationIntegerKey* castsShadows, vtkInformationDoubleKey* lightSize, int maximum,
  int& skipped, std::vector<vtkLight*>& clampedSizes);

/// Each of `lights`' share of the intensity of `renderer`'s switched-on lights
/// (intensity times the luminance of their colour), in their order; zeros
/// when they have none.
std::vector<float> IntensityShares(vtkRenderer* renderer, const std::vector<ShadowLight>& lights);

/// Whether the user is moving the camera: `renderer`'s window asks for at
/// least `interactiveUpdateRate` frames a second (VTK_DOUBLE_MAX: never).
bool IsInteractiveRender(vtkRenderer* renderer, double interactiveUpdateRate);

/// The scene camera as the frame needs it.
struct SceneCamera
{
  /// What the camera sizes impostors by (points as spheres, tubes).
  ImpostorSizing Sizing{};
  /// The drawn projection's x scale over the whole image's: a tile of a larger
  /// image draws impostors at the whole image's size.
  float DrawnRadius = 1.0f;
  bool Parallel = false;
};

/// Reads the camera's view and whole-image projection into `frame`.
SceneCamera ReadSceneCamera(vtkRenderer* renderer, ShadowFrame& frame);

/// The visible props' bounds into `frame` (SceneBounds, PropBounds) and the
/// casters among them (props that draw opaque or translucent polygons, or
/// volumes that can be marched, and take part in `castsShadows`), through
/// `records`, which reads a prop again only when it changed. Returns why the
/// first volume that would cast cannot be marched (empty: none such).
std::string CollectProps(vtkRenderer* renderer, const ImpostorSizing& sizing,
  vtkInformationIntegerKey* castsShadows, PropRecords& records, ShadowFrame& frame,
  std::vector<Caster>& casters);
} // namespace shadowmaps

#endif
