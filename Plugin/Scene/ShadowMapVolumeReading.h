// What a vtkVolume's shadow is made of, read one way for both of its marchers:
// the passes' (shadowmaps::VolumeCasters, on the GPU) and the oracle's
// (shadoworacle::MarchedVolume). A volume is marched when it shows image data
// whose scalars, as its mapper selects them, are one component per point, on
// axes without a direction matrix; the first component's transfer functions
// then give each sample its colour and opacity (docs/TRANSLUCENT.md has the
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
  /// The property's ScalarOpacityUnitDistance: the length the opacity is for.
  double UnitDistance = 1.0;
  /// The data length of a marching step.
  double Step = 1.0;
};

/// Whether `volume`'s data can be marched (without reading the transfer
/// functions); otherwise false, with why when `why` is given.
bool CanMarchVolume(vtkVolume* volume, std::string* why = nullptr);

/// Everything a marcher needs of `volume`, transfer functions tabulated; false
/// with why when it cannot be marched.
bool ReadVolume(vtkVolume* volume, VolumeReading& reading, std::string& why);
} // namespace shadowmaps

#endif
