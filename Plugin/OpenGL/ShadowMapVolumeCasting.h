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

#include "vtkNew.h"
#include "vtkTextureObject.h" // For vtkSmartPointer<vtkTextureObject>
#include "vtkVolume.h"        // For vtkWeakPointer<vtkVolume>
#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkWeakPointer.h"

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

  /// Draws what `volume` (of caster version `version`) lets through into the
  /// bound transmittance layer, whose blending is set, seen through `view`
  /// of `light`. False, with `error`, when its data cannot be marched or a GL
  /// object cannot be made; nothing is drawn then.
  bool Draw(vtkOpenGLRenderWindow* window, vtkVolume* volume, vtkMTimeType version,
    const ShadowLight& light, const LightView& view, std::string& error);

  /// Frees the textures of every volume but `kept` (the frame's casters).
  void KeepOnly(const std::vector<vtkVolume*>& kept);

  /// Frees every GL object (`window`'s context current).
  void Release(vtkWindow* window);

  std::size_t GetMemoryBytes() const;

private:
  /// A volume's data as its marcher reads it.
  struct Uploaded
  {
    vtkWeakPointer<vtkVolume> Volume;
    vtkMTimeType Version = 0;
    vtkSmartPointer<vtkTextureObject> Scalars;
    vtkSmartPointer<vtkTextureObject> Table;
    /// The unit cube to data coordinates, and the world matrix of those.
    glm::dmat4 BoxToData{ 1.0 };
    glm::dmat4 DataToWorld{ 1.0 };
    glm::dvec3 TextureScale{ 1.0 };
    glm::dvec3 TextureShift{ 0.0 };
    double Step = 1.0;
    double UnitDistance = 1.0;
    std::size_t Bytes = 0;
  };

  Uploaded* Upload(vtkOpenGLRenderWindow* window, vtkVolume* volume, vtkMTimeType version,
    std::string& error);

  std::map<vtkVolume*, Uploaded> Volumes;
  vtkNew<vtkOpenGLVertexArrayObject> Box;
};
} // namespace shadowmaps

#endif
