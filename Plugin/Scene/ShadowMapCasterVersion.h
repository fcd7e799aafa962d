// What a caster's depths depend on, reduced to one number that changes
// whenever any of it does: the props a prop draws (an assembly's parts, a prop
// assembly's props), their transforms (a follower's turns with the camera),
// mappers, clipping planes (moved in place by plane widgets) and every input of
// every mapper port (a glyph mapper's source too), brought up to date.
#ifndef ShadowMapCasterVersion_h
#define ShadowMapCasterVersion_h

#include "vtkType.h" // For vtkMTimeType

class vtkProp;

namespace shadowmaps
{
/// A number that differs whenever anything `prop` draws into a depth map
/// differs: equal numbers mean the same depths. Updates the mappers' inputs,
/// but for their first port with `firstInputsUpdated` (VTK's cullers, which
/// ask every visible prop its bounds, brought those up to date this frame).
vtkMTimeType CasterVersion(vtkProp* prop, bool firstInputsUpdated = false);
} // namespace shadowmaps

#endif
