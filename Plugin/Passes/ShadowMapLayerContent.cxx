#include "ShadowMapLayerContent.h"

#include <algorithm>
#include <cassert>
#include <functional>

namespace shadowmaps
{
namespace
{
bool PropBefore(const CasterStamp& a, const CasterStamp& b)
{
  return std::less<const void*>()(a.Prop, b.Prop);
}

// Whether `sorted` holds `stamp`'s prop with the same time.
bool Contains(const std::vector<CasterStamp>& sorted, const CasterStamp& stamp)
{
  const auto found = std::lower_bound(sorted.begin(), sorted.end(), stamp, PropBefore);
  return found != sorted.end() && found->Prop == stamp.Prop && found->Version == stamp.Version;
}
} // namespace

std::vector<CasterStamp> SortedByProp(std::vector<CasterStamp> stamps)
{
  std::sort(stamps.begin(), stamps.end(), PropBefore);
  return stamps;
}

LayerContent::LayerContent(std::vector<vtkMTimeType> view, std::vector<CasterStamp> drawn)
  : View(std::move(view))
  , Drawn(SortedByProp(std::move(drawn)))
{
}

bool LayerContent::Holds(const std::vector<vtkMTimeType>& view,
  const std::vector<CasterStamp>& needed, const std::vector<CasterStamp>& current) const
{
  assert(std::is_sorted(current.begin(), current.end(), PropBefore));
  if (this->View.empty() || view != this->View)
  {
    return false;
  }
  const auto drawn = [this](const CasterStamp& s) { return Contains(this->Drawn, s); };
  const auto stillCurrent = [&current](const CasterStamp& s) { return Contains(current, s); };
  return std::all_of(needed.begin(), needed.end(), drawn) &&
    std::all_of(this->Drawn.begin(), this->Drawn.end(), stillCurrent);
}

} // namespace shadowmaps
