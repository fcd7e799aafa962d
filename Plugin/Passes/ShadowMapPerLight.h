// What a pass keeps for some of its lights (a light's own views or
// representation), each held while the light lives. Not a VTK class.
#ifndef ShadowMapPerLight_h
#define ShadowMapPerLight_h

#include "vtkLight.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace shadowmaps
{
template <typename T>
class PerLight
{
public:
  /// Gives `light` `value`, or takes its own away (null); whether that changed anything.
  bool Set(vtkLight* light, T* value)
  {
    auto entry = this->Find(light);
    if (!value)
    {
      if (entry == this->Entries.end())
      {
        return false;
      }
      this->Entries.erase(entry);
      return true;
    }
    if (entry == this->Entries.end())
    {
      this->Entries.emplace_back(light, value);
      return true;
    }
    const bool changes = entry->second != value;
    entry->second = value;
    return changes;
  }

  /// `light`'s own, or null.
  T* Get(vtkLight* light) const
  {
    auto entry = const_cast<PerLight*>(this)->Find(light);
    return light && entry != this->Entries.end() ? entry->second.Get() : nullptr;
  }

  /// Forgets the lights deleted since: whether it forgot any (the pass is
  /// then modified, so that no new light at a deleted one's address keeps
  /// what was the deleted one's).
  bool ForgetDeleted()
  {
    auto deleted = [](const Entry& entry) { return !entry.first; };
    const auto kept = std::remove_if(this->Entries.begin(), this->Entries.end(), deleted);
    const bool forgot = kept != this->Entries.end();
    this->Entries.erase(kept, this->Entries.end());
    return forgot;
  }

  /// The latest modification time of the values of living lights, or `time`.
  vtkMTimeType LatestMTime(vtkMTimeType time) const
  {
    for (const Entry& entry : this->Entries)
    {
      time = entry.first ? std::max(time, entry.second->GetMTime()) : time;
    }
    return time;
  }

  bool Empty() const { return this->Entries.empty(); }
  std::size_t Size() const { return this->Entries.size(); }

  /// Calls `visit(value)` for each value held.
  template <typename Visit>
  void ForEachValue(Visit&& visit) const
  {
    for (const Entry& entry : this->Entries)
    {
      visit(entry.second.Get());
    }
  }

private:
  using Entry = std::pair<vtkWeakPointer<vtkLight>, vtkSmartPointer<T>>;
  typename std::vector<Entry>::iterator Find(vtkLight* light)
  {
    return std::find_if(this->Entries.begin(), this->Entries.end(),
      [light](const Entry& candidate) { return candidate.first == light; });
  }
  std::vector<Entry> Entries;
};
} // namespace shadowmaps

#endif
