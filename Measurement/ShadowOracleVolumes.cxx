#include "ShadowOracleVolumes.h"

#include "ShadowMapGlm.h"
#include "ShadowMapVolumeReading.h"
#include "vtkAbstractShadowMapPass.h"

#include <vtkDataArray.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadoworacle
{
namespace
{
constexpr int TableSize = shadowmaps::VolumeTableSize;
} // namespace

//------------------------------------------------------------------------------
glm::dvec3 SliceTransmittance(
  const glm::dvec3& color, double opacity, double length, double unitDistance)
{
  const double a = std::min(1.0, std::max(0.0, opacity));
  const double alpha = a >= 1.0 ? 1.0 : 1.0 - std::pow(1.0 - a, length / unitDistance);
  glm::dvec3 transmitted;
  vtkAbstractShadowMapPass::GetTransmittance(
    glm::value_ptr(color), alpha, glm::value_ptr(transmitted));
  return transmitted;
}

//------------------------------------------------------------------------------
bool MarchedVolume::FromVolume(vtkVolume* volume, MarchedVolume& marched, std::string& why)
{
  shadowmaps::VolumeReading reading;
  if (!shadowmaps::ReadVolume(volume, reading, why))
  {
    return false;
  }
  const vtkIdType count = reading.Scalars->GetNumberOfTuples();
  marched.Scalars.resize(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    marched.Scalars[i] = static_cast<float>(reading.Scalars->GetComponent(i, 0));
  }
  marched.WorldToData = glm::inverse(reading.DataToWorld);
  marched.Volume = std::move(reading);
  marched.Volume.Image = nullptr;
  marched.Volume.Scalars = nullptr;
  return true;
}

//------------------------------------------------------------------------------
bool MarchedVolume::Clip(const glm::dvec3& origin, const glm::dvec3& direction, double far,
  double& enter, double& leave) const
{
  const glm::dvec3 o = glm::dvec3(this->WorldToData * glm::dvec4(origin, 1.0));
  const glm::dvec3 d = glm::dvec3(this->WorldToData * glm::dvec4(direction, 0.0));
  enter = 0.0;
  leave = far;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (d[axis] == 0.0)
    {
      if (o[axis] < this->Volume.BoxMin[axis] || o[axis] > this->Volume.BoxMax[axis])
      {
        return false;
      }
      continue;
    }
    double t0 = (this->Volume.BoxMin[axis] - o[axis]) / d[axis];
    double t1 = (this->Volume.BoxMax[axis] - o[axis]) / d[axis];
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter < leave;
}

//------------------------------------------------------------------------------
bool MarchedVolume::Crosses(const glm::dvec3& origin, const glm::dvec3& direction, double far) const
{
  double enter = 0.0;
  double leave = 0.0;
  return this->Clip(origin, direction, far, enter, leave);
}

//------------------------------------------------------------------------------
bool MarchedVolume::ClippedAway(const glm::dvec3& worldPoint) const
{
  return std::any_of(this->Volume.ClippingPlanes.begin(), this->Volume.ClippingPlanes.end(),
    [&worldPoint](const glm::dvec4& plane) {
      return glm::dot(glm::dvec3(plane), worldPoint) + plane.w < 0.0;
    });
}

//------------------------------------------------------------------------------
double MarchedVolume::ScalarAt(const glm::dvec3& dataPoint) const
{
  const glm::dvec3 last = glm::dvec3(glm::max(this->Volume.Dimensions - 1, glm::ivec3(0)));
  const glm::dvec3 index = glm::clamp((dataPoint - this->Volume.Origin) / this->Volume.Spacing, glm::dvec3(0.0), last);
  const glm::ivec3 low = glm::min(glm::ivec3(glm::floor(index)), glm::ivec3(last));
  const glm::ivec3 high = glm::min(low + 1, glm::ivec3(last));
  const glm::dvec3 f = index - glm::dvec3(low);
  auto at = [this](int x, int y, int z) {
    return static_cast<double>(this->Scalars[static_cast<std::size_t>(
      (static_cast<long long>(z) * this->Volume.Dimensions.y + y) * this->Volume.Dimensions.x + x)]);
  };
  const double x00 = glm::mix(at(low.x, low.y, low.z), at(high.x, low.y, low.z), f.x);
  const double x10 = glm::mix(at(low.x, high.y, low.z), at(high.x, high.y, low.z), f.x);
  const double x01 = glm::mix(at(low.x, low.y, high.z), at(high.x, low.y, high.z), f.x);
  const double x11 = glm::mix(at(low.x, high.y, high.z), at(high.x, high.y, high.z), f.x);
  return glm::mix(glm::mix(x00, x10, f.y), glm::mix(x01, x11, f.y), f.z);
}

//------------------------------------------------------------------------------
glm::dvec3 MarchedVolume::Transmittance(
  const glm::dvec3& origin, const glm::dvec3& direction, double far) const
{
  double enter = 0.0;
  double leave = 0.0;
  glm::dvec3 product(1.0);
  if (this->Scalars.empty() || !this->Clip(origin, direction, far, enter, leave))
  {
    return product;
  }
  // Steps of Step in data space, whose lengths VTK's ray casters correct the
  // opacity by (data and world lengths along a line keep one ratio under the
  // volume's affine matrix).
  const double dataPerParameter =
    glm::length(glm::dvec3(this->WorldToData * glm::dvec4(direction, 0.0)));
  const double dataLength = (leave - enter) * dataPerParameter;
  const int steps = std::max(1, static_cast<int>(std::ceil(dataLength / this->Volume.Step)));
  const double dt = (leave - enter) / steps;
  const double dataStep = dt * dataPerParameter;
  const glm::dvec3 o = glm::dvec3(this->WorldToData * glm::dvec4(origin, 1.0));
  const glm::dvec3 d = glm::dvec3(this->WorldToData * glm::dvec4(direction, 0.0));
  const double scale = (TableSize - 1.0) / (this->Volume.High - this->Volume.Low);
  for (int i = 0; i < steps; ++i)
  {
    const double t = enter + (i + 0.5) * dt;
    if (this->ClippedAway(origin + t * direction))
    {
      continue;
    }
    const double s = this->ScalarAt(o + t * d);
    if (std::isnan(s))
    {
      continue; // no data: nothing absorbs
    }
    const double position = std::min(std::max((s - this->Volume.Low) * scale, 0.0), TableSize - 1.0);
    const int k = std::min(static_cast<int>(position), TableSize - 2);
    const glm::dvec4 entry = glm::mix(this->Volume.Table[k], this->Volume.Table[k + 1], position - k);
    product *= SliceTransmittance(glm::dvec3(entry), entry.w, dataStep, this->Volume.UnitDistance);
    if (product == glm::dvec3(0.0))
    {
      break;
    }
  }
  return product;
}
} // namespace shadoworacle
