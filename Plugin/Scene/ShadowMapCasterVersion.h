// What a caster's depths depend on, reduced to one number that changes
// whenever any of it does: the props a prop draws (an assembly's parts, a prop
// assembly's props), their transforms (a follower's turns with the camera),
// mappers, clipping planes (moved in place by plane widgets) and every input of
// every mapper port (a glyph mapper's source too), brought up to date.
#ifndef ShadowMapCasterVersion_h
#define ShadowMapCasterVersion_h

#include "vtkType.h" // For vtkMTimeType

#include <array>

class vtkProp;

namespace shadowmaps
{
struct Aabb;
}

namespace shadowmaps
{
/// What the scene camera sizes VTK's impostors by (points drawn as spheres,
/// lines drawn as tubes: a world radius of the size in pixels over the image's
/// width times P00, times the eye depth): the image's width in pixels, P00,
/// the eye depth's row and whether the camera is parallel. The depths such a
/// prop casts change with them.
using ImpostorSizing = std::array<double, 7>;

/// A number that differs whenever anything `prop` draws into a depth map
/// differs: equal numbers mean the same depths. Updates the mappers' inputs,
/// but for their first port with `firstInputsUpdated` (VTK's cullers, which
/// ask every visible prop its bounds, brought those up to date this frame).
/// Parts drawing impostors mix in `impostorSizing`.
vtkMTimeType CasterVersion(
  vtkProp* prop, bool firstInputsUpdated = false, const ImpostorSizing& impostorSizing = {});

/// The largest world radius of the impostors `prop` draws inside `bounds` (its
/// points' or lines' bounds), as `impostorSizing` sizes them; 0 where it
/// draws none. Their shapes reach that far beyond the bounds.
double ImpostorReach(vtkProp* prop, const Aabb& bounds, const ImpostorSizing& impostorSizing);
} // namespace shadowmaps

#endif
