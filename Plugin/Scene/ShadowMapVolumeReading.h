// What a vtkVolume's shadow is made of, read one way for both of its marchers:
// the passes' (shadowmaps::VolumeCasters, on the GPU) and the oracle's
// (shadoworacle::MarchedVolume). A volume is marched when it shows image data
// whose scalars, as its mapper selects them, are one component per point, on
// axes without a direction matrix, composited (VTK's default blend mode),
// without cropping, in a vtkVolume of one input; the first component's
// transfer functions then give each sample its colour and opacity, the
// mapper's clipping planes cut samples away (docs/TRANSLUCENT.md has the
// model). Not a VTK class.
#ifndef ShadowMapVolumeReading_h
#define ShadowMapVolumeReading_h

#include <glm/glm.hpp>

#include <string>
#include <vector>

class vtkDataArray;
class vtkImageData;
class vtkVolume;

namespace shadowmaps
{
/// Transfer-function entries over the scalars' range: finer than an 8-bit
/// colour step over any range a function bends in.
constexpr int VolumeTableSize = 4096;

/// Marching steps per smallest voxel side.
constexpr double VolumeStepsPerVoxel = 2.0;

struct VolumeReading
{
  vtkImageData* Image = nullptr;
  /// The scalars the mapper shows (point data, one component).
  vtkDataArray* Scalars = nullptr;
  glm::ivec3 Dimensions{ 0 };
  glm::dvec3 Origin{ 0.0 };
  glm::dvec3 Spacing{ 1.0 }; // signed, as the image's
  /// The image's bounds, in its data coordinates.
  glm::dvec3 BoxMin{ 0.0 };
  glm::dvec3 BoxMax{ 0.0 };
  /// The volume's matrix: data coordinates to world.
  glm::dmat4 DataToWorld{ 1.0 };
  /// The scalars' range, over which Table runs (Low < High).
  double Low = 0.0;
  double High = 1.0;
  /// VolumeTableSize entries from Low to High: colour, opacity.
  std::vector<glm::dvec4> Table;
  /// The property's ScalarOpacityUnitDistance: the data length the opacity
  /// is for (VTK's ray casters step and correct opacity in data lengths,
  /// whatever the volume's matrix scales).
  double UnitDistance = 1.0;
  /// The data length of a marching step.
  double Step = 1.0;
  /// The mapper's clipping planes in world coordinates (a, b, c, d: a sample
  /// at x is kept where a x + b y + c z + d >= 0, as VTK keeps the side its
  /// planes' normals point to).
  std::vector<glm::dvec4> ClippingPlanes;
};

/// The most clipping planes a marched volume takes (VTK's ray caster's own
/// limit); a volume with more casts no shadow.
constexpr int MostVolumeClippingPlanes = 6;

/// Whether `volume`'s data can be marched (without reading the transfer
/// functions); otherwise false, with why when `why` is given.
bool CanMarchVolume(vtkVolume* volume, std::string* why = nullptr);

/// Everything a marcher needs of `volume` but the table (reading.Table left
/// as it is); false with why when it cannot be marched.
bool ReadVolumeLayout(vtkVolume* volume, VolumeReading& reading, std::string& why);

/// reading.Table from `volume`'s transfer functions over reading's range.
void TabulateTransferFunctions(vtkVolume* volume, VolumeReading& reading);

/// Both: everything a marcher needs; false with why when it cannot be marched.
bool ReadVolume(vtkVolume* volume, VolumeReading& reading, std::string& why);
} // namespace shadowmaps

#endif
