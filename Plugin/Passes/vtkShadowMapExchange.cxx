#include "vtkShadowMapExchange.h"

//------------------------------------------------------------------------------
bool vtkShadowMapExchange::AllBoxes(std::vector<double>&)
{
  return false;
}

//------------------------------------------------------------------------------
bool vtkShadowMapExchange::ProductOf(std::vector<float>&)
{
  return false;
}

//------------------------------------------------------------------------------
bool vtkShadowMapExchange::NearestTwoOf(std::vector<float>& pairs)
{
  const std::size_t count = pairs.size() / 2;
  std::vector<float> nearest(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    nearest[i] = pairs[2 * i];
  }
  // Both collectives are made whatever the first gave: every process makes the same calls.
  const bool nearestCombined = this->MinimumOf(nearest);
  std::vector<float> behind(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    const float x = pairs[2 * i];
    behind[i] = x > nearest[i] ? x : pairs[2 * i + 1];
  }
  if (!this->MinimumOf(behind) || !nearestCombined)
  {
    return false;
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    pairs[2 * i] = nearest[i];
    pairs[2 * i + 1] = behind[i];
  }
  return true;
}
