#include "ShadowMapCrop.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowmaps
{
namespace
{
glm::dmat4 Relative(const glm::dmat4& first, const glm::dmat4& view)
{
  return view * glm::inverse(first);
}
} // namespace

//------------------------------------------------------------------------------
glm::dmat4 MapCrop::Matrix() const
{
  glm::dmat4 crop(1.0);
  for (int axis = 0; axis < 3; ++axis)
  {
    crop[axis][axis] = this->Scale[axis];
    crop[3][axis] = this->Offset[axis];
  }
  return crop;
}

//------------------------------------------------------------------------------
MapCrop CropBetween(const glm::dmat4& first, const glm::dmat4& view)
{
  const glm::dmat4 relative = Relative(first, view);
  MapCrop crop;
  for (int axis = 0; axis < 3; ++axis)
  {
    // glm is column-major: [column][row].
    crop.Scale[axis] = relative[axis][axis] / relative[3][3];
    crop.Offset[axis] = relative[3][axis] / relative[3][3];
  }
  return crop;
}

//------------------------------------------------------------------------------
double CropError(const glm::dmat4& first, const glm::dmat4& view)
{
  if (!(std::abs(glm::determinant(first)) > 0.0))
  {
    return std::numeric_limits<double>::infinity();
  }
  const glm::dmat4 relative = Relative(first, view);
  double kept = 0.0;
  double stray = 0.0;
  for (int column = 0; column < 4; ++column)
  {
    for (int row = 0; row < 4; ++row)
    {
      const double value = std::abs(relative[column][row]);
      if (!std::isfinite(value))
      {
        return std::numeric_limits<double>::infinity();
      }
      const bool keeps = column == row || (column == 3 && row < 3);
      (keeps ? kept : stray) = std::max(keeps ? kept : stray, value);
    }
  }
  return kept > 0.0 ? stray / kept : std::numeric_limits<double>::infinity();
}
} // namespace shadowmaps
