// Whether a prop casts and receives shadows. Its property keys decide where
// they set CASTS_SHADOWS or RECEIVES_SHADOWS; otherwise every prop does but
// annotations (axes, grids, labels, 3D text, 2D overlays and the
// representations of widgets), which users expect to neither cast nor receive
// (VTK's own pass casts only the props tagged as occluders). Not a VTK class.
#ifndef ShadowMapPropRoles_h
#define ShadowMapPropRoles_h

class vtkInformation;
class vtkInformationIntegerKey;
class vtkProp;

namespace shadowmaps
{
/// An opt-out key: absent (or no information at all) means yes.
bool IsEnabled(vtkInformation* info, vtkInformationIntegerKey* key);

/// Whether `prop` is an annotation: an instance of one of VTK's or ParaView's
/// axes, grid, label, 3D text, overlay or widget representation classes, or a
/// part drawn with the property keys of one (vtkCubeAxesActor's axes and
/// labels, a widget representation's actors), once that one was seen by
/// TakesPart.
bool IsAnnotation(vtkProp* prop);

/// Whether `prop` takes part in what `key` (CASTS_SHADOWS or
/// RECEIVES_SHADOWS) opts out of: the key's value where the prop's property
/// keys hold it, else !IsAnnotation(prop).
bool TakesPart(vtkProp* prop, vtkInformationIntegerKey* key);
} // namespace shadowmaps

#endif
