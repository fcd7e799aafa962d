#include "ShadowMapPropRoles.h"

#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkProp.h"

#include <algorithm>
#include <iterator>
#include <unordered_map>

namespace shadowmaps
{
namespace
{
// By class name, so that ParaView's classes (and modules this one does not
// link) are known too; subclasses are matched through IsA.
const char* const AnnotationClasses[] = {
  "vtkActor2D",               // text, scalar bars, corner annotations, legends
  "vtkAxesActor",             // orientation axes
  "vtkAxisActor",             // one axis of vtkCubeAxesActor or vtkPolarAxesActor
  "vtkAxisFollower",          // axis labels that face the camera
  "vtkBillboardTextActor3D",  // labels placed in 3D
  "vtkCubeAxesActor",         // PyVista's show_grid() and show_bounds()
  "vtkGridAxes2DActor",       // ParaView's axes grid and data axes grid
  "vtkGridAxes3DActor",       //   (vtkPVGridAxes3DActor) up to 5.13,
  "vtkGridAxesPlane2DActor",  //   the classes VTK took over as
  "vtkGridAxesActor2D",       //   vtkGridAxesActor2D, vtkGridAxesActor3D and
  "vtkGridAxesActor3D",       //   vtkGridAxesPlaneActor2D (RenderingGridAxes)
  "vtkGridAxesPlaneActor2D",
  "vtkLegendScaleActor",
  "vtkPolarAxesActor",
  "vtkProp3DAxisFollower",
  "vtkPVAxesActor",           // ParaView's orientation axes
  "vtkPVCenterAxesActor",     // ParaView's center axes
  "vtkTextActor3D",
  "vtkWidgetRepresentation",  // every widget's handles, planes, boxes
};

// Set on an annotation's property keys, which its parts draw with.
vtkInformationIntegerKey* PartOfAnnotation()
{
  static vtkInformationIntegerKey* key =
    vtkInformationIntegerKey::MakeKey("PART_OF_ANNOTATION", "vtkShadowMapPropRoles");
  return key;
}

bool IsAnnotationClass(vtkProp* prop)
{
  // Asked for every prop several times a frame: remembered per class (the
  // name's address is one per class and library).
  thread_local std::unordered_map<const char*, bool> known;
  const char* name = prop->GetClassName();
  const auto found = known.find(name);
  if (found != known.end())
  {
    return found->second;
  }
  const bool annotation = std::any_of(std::begin(AnnotationClasses), std::end(AnnotationClasses),
    [prop](const char* annotationClass) { return prop->IsA(annotationClass) != 0; });
  return known[name] = annotation;
}
} // namespace

//------------------------------------------------------------------------------
bool IsEnabled(vtkInformation* info, vtkInformationIntegerKey* key)
{
  return !info || !info->Has(key) || info->Get(key) != 0;
}

//------------------------------------------------------------------------------
bool IsAnnotation(vtkProp* prop)
{
  vtkInformation* keys = prop->GetPropertyKeys();
  return (keys && keys->Has(PartOfAnnotation())) || IsAnnotationClass(prop);
}

//------------------------------------------------------------------------------
bool TakesPart(vtkProp* prop, vtkInformationIntegerKey* key)
{
  vtkInformation* keys = prop->GetPropertyKeys();
  const bool annotation = IsAnnotation(prop);
  if (annotation && keys && !keys->Has(PartOfAnnotation()))
  {
    // Before its parts draw with these keys (into the maps, when it casts).
    keys->Set(PartOfAnnotation(), 1);
  }
  return keys && keys->Has(key) ? keys->Get(key) != 0 : !annotation;
}
} // namespace shadowmaps
