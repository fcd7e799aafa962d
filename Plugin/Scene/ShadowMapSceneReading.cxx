#include "ShadowMapSceneReading.h"

#include "ShadowMapGlm.h"
#include "ShadowMapPropRecords.h"
#include "ShadowMapVolumeReading.h"

#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkProperty.h"
#include "vtkActor.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationKeyLookup.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace shadowmaps
{
//------------------------------------------------------------------------------
vtkInformationDoubleKey* OSPRayRadiusKey()
{
  // Registered by name when VTK's ray tracing module is loaded (which may be
  // after the first frame): looked up until found.
  static vtkInformationDoubleKey* found = nullptr;
  if (!found)
  {
    found = vtkInformationDoubleKey::SafeDownCast(
      vtkInformationKeyLookup::Find("RADIUS", "vtkOSPRayLightNode"));
  }
  return found;
}

//------------------------------------------------------------------------------
double StoredLightSize(vtkLight* light, vtkInformationDoubleKey* key)
{
  vtkInformation* info = light ? light->GetInformation() : nullptr;
  vtkInformationDoubleKey* radius = OSPRayRadiusKey();
  return !info                    ? 0.0
    : info->Has(key)              ? info->Get(key)
    : radius && info->Has(radius) ? info->Get(radius)
                                  : 0.0;
}

//------------------------------------------------------------------------------
double LightSizeOf(vtkLight* light, vtkInformationDoubleKey* key, bool* clamped)
{
  const double stored = StoredLightSize(light, key);
  double size = std::isfinite(stored) ? std::max(stored, 0.0) : 0.0;
  // Suns at most WidestSun; lamps finite in the shaders' single precision.
  size = std::min(size, light && !light->GetPositional() ? WidestSun : 1e30);
  if (clamped)
  {
    *clamped = !(size == stored);
  }
  return size;
}

//------------------------------------------------------------------------------
std::vector<ShadowLight> CollectShadowedLights(vtkRenderer* renderer,
  vtkInformationIntegerKey* castsShadows, vtkInformationDoubleKey* lightSize, int maximum,
  int& skipped, std::vector<vtkLight*>& clampedSizes)
{
  std::vector<ShadowLight> lights;
  skipped = 0;
  clampedSizes.clear();
  int shaderIndex = 0;
  vtkCollectionSimpleIterator it;
  vtkLightCollection* collection = renderer->GetLights();
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (!light->GetSwitch())
    {
      continue; // switched-off lights get no index in the mappers' shaders
    }
    const int index = shaderIndex++;
    if (light->LightTypeIsHeadlight() || !IsEnabled(light->GetInformation(), castsShadows))
    {
      continue;
    }
    if (static_cast<int>(lights.size()) == maximum)
    {
      ++skipped;
      continue;
    }
    ShadowLight shadowLight;
    shadowLight.Light = light;
    shadowLight.ShaderIndex = index;
    shadowLight.Position = ToGlm(light->GetTransformedPosition());
    shadowLight.Direction = ToGlm(light->GetTransformedFocalPoint()) - shadowLight.Position;
    shadowLight.ConeAngle = light->GetConeAngle();
    shadowLight.Attenuation = std::min(std::max(light->GetShadowAttenuation(), 0.0f), 1.0f);
    shadowLight.Kind = !light->GetPositional() ? LightKind::Directional
      : shadowLight.ConeAngle < 90.0           ? LightKind::Spot
                                               : LightKind::Point;
    bool clamped = false;
    shadowLight.Size = LightSizeOf(light, lightSize, &clamped);
    if (clamped)
    {
      clampedSizes.push_back(light);
    }
    lights.push_back(shadowLight);
  }
  return lights;
}

//------------------------------------------------------------------------------
std::vector<float> IntensityShares(vtkRenderer* renderer, const std::vector<ShadowLight>& lights)
{
  auto strength = [](vtkLight* light) {
    const double* color = light->GetDiffuseColor();
    return light->GetIntensity() * (0.2126 * color[0] + 0.7152 * color[1] + 0.0722 * color[2]);
  };
  double total = 0.0;
  vtkCollectionSimpleIterator it;
  vtkLightCollection* collection = renderer->GetLights();
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    total += light->GetSwitch() ? std::max(strength(light), 0.0) : 0.0;
  }
  std::vector<float> shares;
  for (const ShadowLight& light : lights)
  {
    const double share = total > 0.0 ? std::max(strength(light.Light), 0.0) / total : 0.0;
    shares.push_back(std::isfinite(share) ? static_cast<float>(share) : 0.0f);
  }
  return shares;
}

//------------------------------------------------------------------------------
bool IsInteractiveRender(vtkRenderer* renderer, double interactiveUpdateRate)
{
  return interactiveUpdateRate < VTK_DOUBLE_MAX &&
    renderer->GetRenderWindow()->GetDesiredUpdateRate() >= interactiveUpdateRate;
}

//------------------------------------------------------------------------------
SceneCamera ReadSceneCamera(vtkRenderer* renderer, ShadowFrame& frame)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  frame.CameraView = ToGlm(camera->GetViewTransformMatrix());
  const glm::dmat4 drawn =
    ToGlm(camera->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1.0, 1.0));
  glm::dvec4 tileViewport;
  renderer->GetRenderWindow()->GetTileViewport(glm::value_ptr(tileViewport));
  frame.CameraProjection = WholeImageProjection(
    drawn, TileOfWholeImage(tileViewport, glm::make_vec4(renderer->GetViewport())));
  SceneCamera scene;
  scene.DrawnRadius = static_cast<float>(drawn[0][0] / frame.CameraProjection[0][0]);
  scene.Parallel = camera->GetParallelProjection() != 0;
  // vtkViewport::GetSize is the whole image's, in a tile of a larger one. A
  // parallel camera's impostors do not grow with the eye depth.
  const glm::dvec4 eyeDepth = scene.Parallel ? glm::dvec4(0.0) : glm::row(frame.CameraView, 2);
  scene.Sizing = { static_cast<double>(renderer->GetSize()[0]), frame.CameraProjection[0][0],
    eyeDepth.x, eyeDepth.y, eyeDepth.z, eyeDepth.w, scene.Parallel ? 1.0 : 0.0 };
  return scene;
}

//------------------------------------------------------------------------------
bool AnyTranslucent(const std::vector<Caster>& casters)
{
  return std::any_of(
    casters.begin(), casters.end(), [](const Caster& caster) { return caster.Translucent; });
}

//------------------------------------------------------------------------------
bool HoldsItsOwnTransmittance(vtkProp* prop, vtkInformationIntegerKey* castsShadows)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  if (!actor || !TakesPart(prop, castsShadows))
  {
    return false;
  }
  vtkProperty* property = actor->GetProperty();
  return !property->GetBackfaceCulling() && !property->GetFrontfaceCulling() &&
    !actor->GetBackfaceProperty();
}

//------------------------------------------------------------------------------
std::string CollectProps(vtkRenderer* renderer, const ImpostorSizing& sizing,
  vtkInformationIntegerKey* castsShadows, PropRecords& records, ShadowFrame& frame,
  std::vector<Caster>& casters)
{
  std::string unmarchedVolume;
  casters.clear();
  frame.PropBounds.clear();
  frame.SceneBounds = Aabb();
  records.BeginFrame(renderer, sizing);
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility())
    {
      continue;
    }
    if (!prop->GetPropertyKeys())
    {
      // Render passes create the keys on first use, which modifies the prop;
      // create them now so that this first use does not re-render the maps.
      vtkNew<vtkInformation> keys;
      prop->SetPropertyKeys(keys);
    }
    const PropRecords::Record& record = records.Read(prop);
    if (!record.Bounds.IsUsable())
    {
      continue;
    }
    frame.SceneBounds.Add(record.Bounds);
    frame.PropBounds.push_back(record.Bounds);
    if (!TakesPart(prop, castsShadows))
    {
      continue;
    }
    if (record.DrawsIntoDepthMaps || record.DrawsTranslucency)
    {
      casters.push_back({ prop, record.CastingBounds, record.Version, record.DrawsIntoDepthMaps,
        record.DrawsTranslucency });
    }
    else if (auto* volume = vtkVolume::SafeDownCast(prop))
    {
      std::string why;
      if (unmarchedVolume.empty() && !CanMarchVolume(volume, &why))
      {
        unmarchedVolume = why;
      }
    }
  }
  records.EndFrame();
  return unmarchedVolume;
}
} // namespace shadowmaps
