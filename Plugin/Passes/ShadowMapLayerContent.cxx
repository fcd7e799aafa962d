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
  return found != sorted.end() && *found == stamp;
}
} // namespace

bool operator==(const CasterStamp& a, const CasterStamp& b)
{
  return a.Prop == b.Prop && a.Version == b.Version;
}

std::vector<CasterStamp> SortedByProp(std::vector<CasterStamp> stamps)
{
  std::sort(stamps.begin(), stamps.end(), PropBefore);
  return stamps;
}

LayerContent::LayerContent(std::vector<vtkMTimeType> view, std::vector<CasterStamp> drawn,
  unsigned long long generation, bool everyCasterInView)
  : View(std::move(view))
  , Drawn(SortedByProp(std::move(drawn)))
  , Generation(generation)
  , EveryCasterInView(everyCasterInView)
{
}

bool LayerContent::HoldsEveryCasterInView(
  const std::vector<vtkMTimeType>& view, unsigned long long generation) const
{
  // The same casters in the same view: the same casters in view, a superset of
  // any frame's needed ones.
  return this->EveryCasterInView && generation == this->Generation && !this->View.empty() &&
    view == this->View;
}

bool LayerContent::Holds(const std::vector<vtkMTimeType>& view,
  const std::vector<CasterStamp>& needed, const std::vector<CasterStamp>& current,
  unsigned long long generation) const
{
  assert(std::is_sorted(current.begin(), current.end(), PropBefore));
  if (this->View.empty() || view != this->View)
  {
    return false;
  }
  const auto drawn = [this](const CasterStamp& s) { return Contains(this->Drawn, s); };
  if (!std::all_of(needed.begin(), needed.end(), drawn))
  {
    return false;
  }
  if (generation == this->Generation)
  {
    return true; // the drawn casters were among these very ones
  }
  // Both sorted: each search starts where the last one ended.
  auto next = current.begin();
  for (const CasterStamp& s : this->Drawn)
  {
    next = std::lower_bound(next, current.end(), s, PropBefore);
    if (next == current.end() || !(*next == s))
    {
      return false;
    }
  }
  return true;
}

} // namespace shadowmaps
