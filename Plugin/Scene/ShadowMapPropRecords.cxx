#include "ShadowMapPropRecords.h"

#include "ShadowMapCasterVersion.h"
#include "ShadowMapPropParts.h"
#include "ShadowMapVolumeReading.h"

#include "vtkActor.h"
#include "vtkCullerCollection.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

namespace shadowmaps
{
namespace
{
// Whether what `prop` draws translucent takes its colour and opacity from its
// property or scalars alone, which the transmittance branch reads: actors
// without textures. Textures (a vtkTexture's or a PBR material's alpha) and
// other props (image slices, 3D text) apply their alpha after the lighting,
// where that branch does not see it: they cast no translucent shadow.
bool TranslucentByColorAlone(vtkProp* prop)
{
  bool alone = true;
  ForEachPart(prop, [&alone](vtkProp* part, vtkMatrix4x4*) {
    auto* actor = vtkActor::SafeDownCast(part);
    alone = alone && actor && !actor->GetTexture() &&
      actor->GetProperty()->GetNumberOfTextures() == 0;
  });
  return alone;
}
} // namespace

//------------------------------------------------------------------------------
void PropRecords::BeginFrame(vtkRenderer* renderer, const ImpostorSizing& impostorSizing)
{
  this->Sizing = impostorSizing;
  // vtkRenderer::Render runs its cullers before its passes, and they ask every
  // visible prop its bounds, which updates its mapper's input.
  this->FirstInputsUpdated = renderer->GetCullers()->GetNumberOfItems() > 0;
  this->Current.clear();
  this->Current.reserve(this->Kept.size());
  this->ReadAgain = 0;
}

//------------------------------------------------------------------------------
const PropRecords::Record& PropRecords::Read(vtkProp* prop)
{
  const vtkMTimeType version = CasterVersion(prop, this->FirstInputsUpdated, this->Sizing);
  const auto kept = this->Kept.find(prop);
  // Only an actor's bounds are known to follow its version: other props (LOD
  // props, image stacks, assemblies of slices) are read every frame.
  if (kept != this->Kept.end() && kept->second.Version == version && vtkActor::SafeDownCast(prop))
  {
    return this->Current[prop] = kept->second;
  }
  ++this->ReadAgain;
  Record& record = this->Current[prop];
  record.Version = version;
  record.Bounds = Aabb::FromBounds(prop->GetBounds());
  // Points drawn as spheres and lines drawn as tubes reach beyond their
  // points: the layers that hold any of their shapes cast them. The fits keep
  // the points' bounds, which do not follow the camera: a shape's part beyond
  // them shades only receivers beyond them.
  record.CastingBounds = record.Bounds;
  const double reach = ImpostorReach(prop, record.Bounds, this->Sizing);
  if (reach > 0.0)
  {
    record.CastingBounds.Min -= glm::dvec3(reach);
    record.CastingBounds.Max += glm::dvec3(reach);
  }
  // Volumes keep vtkProp's default HasOpaqueGeometry() but draw nothing into a
  // depth map; those whose data can be marched cast into the transmittance maps.
  auto* volume = vtkVolume::SafeDownCast(prop);
  record.DrawsIntoDepthMaps = prop->HasOpaqueGeometry() && !volume;
  record.DrawsTranslucency = volume
    ? CanMarchVolume(volume)
    : prop->HasTranslucentPolygonalGeometry() && TranslucentByColorAlone(prop);
  return record;
}

//------------------------------------------------------------------------------
void PropRecords::EndFrame()
{
  this->Kept.swap(this->Current);
}
} // namespace shadowmaps
