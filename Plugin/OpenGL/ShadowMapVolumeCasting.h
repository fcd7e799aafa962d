// The volumes' casting into the transmittance maps (ShadowMapTransmittance.h):
// each vtkVolume whose data can be marched (ShadowMapVolumeReading.h) draws the
// faces of its box from a layer's light view, and each ray through them is
// marched where it leaves the box: the product of what its slices let through,
// and the light depth where it starts to absorb. The scalars go to a 3D
// texture of 16-bit steps over their range (the data's own texture in VTK's
// mapper is not reachable from outside it), the transfer functions to a table;
// both are made again only when the volume's version changes. Not a VTK class.
#ifndef ShadowMapVolumeCasting_h
#define ShadowMapVolumeCasting_h

#include "ShadowMapFocusing.h"   // For LightView
#include "ShadowMapLight.h"      // For ShadowLight
#include "ShadowMapVolumeReading.h" // For VolumeReading

#include "vtkNew.h"
#include "vtkTextureObject.h" // For vtkSmartPointer<vtkTextureObject>
#include "vtkVolume.h"        // For vtkWeakPointer<vtkVolume>
#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkWeakPointer.h"

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkWindow;

namespace shadowmaps
{
/// Steps a ray takes at most through one volume: the step grows past it.
constexpr int MostVolumeSteps = 1024;

class VolumeCasters
{
public:
  VolumeCasters();
  ~VolumeCasters();
  VolumeCasters(const VolumeCasters&) = delete;
  VolumeCasters& operator=(const VolumeCasters&) = delete;

  /// Draws what `volume` lets through into the
  /// bound transmittance layer, whose blending is set, seen through `view`
  /// of `light`. False, with `error`, when its data cannot be marched or a GL
  /// object cannot be made; nothing is drawn then.
  bool Draw(vtkOpenGLRenderWindow* window, vtkVolume* volume, const ShadowLight& light,
    const LightView& view, std::string& error);

  /// Frees the textures of every volume but `kept` (the frame's casters).
  void KeepOnly(const std::vector<vtkVolume*>& kept);

  /// Frees every GL object (`window`'s context current).
  void Release(vtkWindow* window);

  std::size_t GetMemoryBytes() const;

private:
  /// A volume's data as its marcher reads it. The scalars are read again only
  /// when they change (the mapper, its input or the array), the transfer
  /// functions when the property changes; the placement and clipping planes
  /// at every draw.
  struct Uploaded
  {
    vtkWeakPointer<vtkVolume> Volume;
    std::array<vtkMTimeType, 3> ScalarsKey{ { 0, 0, 0 } };
    vtkMTimeType TableKey = 0;
    vtkSmartPointer<vtkTextureObject> Scalars;
    vtkSmartPointer<vtkTextureObject> Table;
    /// Why the scalars could not be made into a texture, kept while they
    /// stay the same (empty: they could).
    std::string Failure;
    std::size_t Bytes = 0;
  };

  /// The volume's textures, made or kept, and its reading (its table only
  /// when made anew); null with `error` when it cannot be marched.
  Uploaded* Upload(vtkOpenGLRenderWindow* window, vtkVolume* volume, VolumeReading& reading,
    std::string& error);

  std::map<vtkVolume*, Uploaded> Volumes;
  vtkNew<vtkOpenGLVertexArrayObject> Box;
};
} // namespace shadowmaps

#endif
