// Volumes for the oracle (ShadowOracle.h): what a vtkVolume of image data lets
// through along a light ray, marched through its scalar field and transfer
// functions. The model is the translucent surfaces' one
// (vtkAbstractShadowMapPass::GetTransmittance) applied to thin slices: a
// slice of thickness ds has the opacity VTK's ray casters give a sample,
// 1 - (1 - a)^(ds / u) for the scalar opacity a and the property's
// ScalarOpacityUnitDistance u (both data lengths, as VTK's ray casters
// measure them), and the colour c of the colour transfer
// function, and lets (1 - alpha)(1 - alpha + alpha c) through. As the slices
// thin this is exp(-integral of sigma (2 - c) ds) with sigma = -ln(1 - a) / u:
// for white, exactly the transmittance VTK's compositing gives the eye.
#ifndef ShadowOracleVolumes_h
#define ShadowOracleVolumes_h

#include "ShadowMapVolumeReading.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

class vtkVolume;

namespace shadoworacle
{

/// What a slice of a volume of thickness `length` lets through, of scalar
/// opacity `opacity` per `unitDistance` and colour `color` (the model above).
glm::dvec3 SliceTransmittance(
  const glm::dvec3& color, double opacity, double length, double unitDistance);

/// One volume, copied out of VTK for the oracle's threads: its point scalars,
/// placement and transfer functions, tabulated. Samples that are not numbers
/// (masked data) absorb nothing.
class MarchedVolume
{
public:
  /// The volume's data if the oracle can march it: image data with point
  /// scalars (the first component), the volume's first component's transfer
  /// functions. Otherwise false with why.
  static bool FromVolume(vtkVolume* volume, MarchedVolume& marched, std::string& why);

  /// What the volume lets through, per channel, along the segment from
  /// `origin` over `far` world units of the unit `direction`.
  glm::dvec3 Transmittance(const glm::dvec3& origin, const glm::dvec3& direction, double far) const;

  /// Whether that segment crosses the volume's box.
  bool Crosses(const glm::dvec3& origin, const glm::dvec3& direction, double far) const;

private:
  // The segment's parameters (world units along `direction`) inside the box.
  bool Clip(const glm::dvec3& origin, const glm::dvec3& direction, double far, double& enter,
    double& leave) const;
  double ScalarAt(const glm::dvec3& dataPoint) const;
  // Whether the mapper's clipping planes cut the sample at `worldPoint` away.
  bool ClippedAway(const glm::dvec3& worldPoint) const;

  std::vector<float> Scalars; // x fastest
  /// The rest of the volume as the passes read it (its data pointers unset:
  /// the oracle's threads read the copies here).
  shadowmaps::VolumeReading Volume;
  glm::dmat4 WorldToData{ 1.0 };
};

} // namespace shadoworacle

#endif
