// What a pass reads of each visible prop every frame: its world bounds,
// whether it draws into depth maps, and its caster version. The bounds update
// each mapper's pipeline, which with thousands of props was most of the pass's
// own CPU time; an actor's are kept from frame to frame and read again only
// when its version changes (which covers all they depend on: its transform,
// mapper and inputs). Other props are read every frame.
#ifndef ShadowMapPropRecords_h
#define ShadowMapPropRecords_h

#include "ShadowMapCasterVersion.h" // For ImpostorSizing
#include "ShadowMapFocusing.h" // For Aabb

#include "vtkType.h" // For vtkMTimeType

#include <unordered_map>

class vtkProp;
class vtkRenderer;

namespace shadowmaps
{
class PropRecords
{
public:
  struct Record
  {
    /// The prop's own bounds (its points'): what the views are fitted to.
    Aabb Bounds;
    /// Its bounds as a caster: grown by the radius of the spheres and tubes
    /// it draws at its points (ImpostorReach), which the scene camera sizes.
    Aabb CastingBounds;
    bool DrawsIntoDepthMaps = false;
    /// It draws translucent polygons (VTK's translucent pass), or it is a
    /// volume whose data can be marched (ShadowMapVolumeReading.h): the
    /// transmittance maps take it.
    bool DrawsTranslucency = false;
    vtkMTimeType Version = 0;
  };

  /// Starts a frame of `renderer`, after its cullers ran (or not), whose
  /// camera sizes impostors by `impostorSizing`.
  void BeginFrame(vtkRenderer* renderer, const ImpostorSizing& impostorSizing);

  /// The record of a visible prop this frame.
  const Record& Read(vtkProp* prop);

  /// Forgets the props not read since BeginFrame.
  void EndFrame();

  /// Records read again (their version changed, or new) and kept, this frame.
  int GetNumberOfReadAgain() const { return this->ReadAgain; }

private:
  std::unordered_map<vtkProp*, Record> Kept;
  std::unordered_map<vtkProp*, Record> Current;
  bool FirstInputsUpdated = false;
  ImpostorSizing Sizing{};
  int ReadAgain = 0;
};
} // namespace shadowmaps

#endif
