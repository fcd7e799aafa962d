#include "ShadowMapClosedSurfaces.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkIdList.h"
#include "vtkMapper.h"
#include "vtkPlaneCollection.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cstdint>
#include <map>
#include <unordered_map>

namespace shadowmaps
{
namespace
{
// Point ids made equal where coordinates are.
std::vector<vtkIdType> MergedPointIds(vtkPoints* points)
{
  std::map<std::array<double, 3>, vtkIdType> first;
  std::vector<vtkIdType> merged(static_cast<size_t>(points->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    points->GetPoint(i, p.data());
    merged[static_cast<size_t>(i)] = first.emplace(p, i).first->second;
  }
  return merged;
}

// Directed edges of oriented faces, points merged: a closed, consistently
// wound surface has each edge once in each direction.
class EdgeCounter
{
public:
  explicit EdgeCounter(std::vector<vtkIdType> ids)
    : Ids(std::move(ids))
  {
  }

  void Add(vtkIdType from, vtkIdType to)
  {
    const vtkIdType a = this->Ids[static_cast<size_t>(from)];
    const vtkIdType b = this->Ids[static_cast<size_t>(to)];
    if (a == b)
    {
      return; // a degenerate edge bounds nothing
    }
    const auto key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) ^
      static_cast<std::uint64_t>(std::max(a, b));
    auto& directions = this->Counts[key];
    ++(a < b ? directions.first : directions.second);
  }

  // Strips join with degenerate triangles, which bound nothing.
  void AddTriangle(vtkIdType a, vtkIdType b, vtkIdType c)
  {
    const vtkIdType ma = this->Ids[static_cast<size_t>(a)];
    const vtkIdType mb = this->Ids[static_cast<size_t>(b)];
    const vtkIdType mc = this->Ids[static_cast<size_t>(c)];
    if (ma != mb && mb != mc && mc != ma)
    {
      this->Add(a, b);
      this->Add(b, c);
      this->Add(c, a);
    }
  }

  bool EachEdgeOnceEachWay() const
  {
    for (const auto& edge : this->Counts)
    {
      if (edge.second.first != 1 || edge.second.second != 1)
      {
        return false;
      }
    }
    return !this->Counts.empty();
  }

private:
  std::vector<vtkIdType> Ids;
  std::unordered_map<std::uint64_t, std::pair<int, int>> Counts;
};
} // namespace

//------------------------------------------------------------------------------
bool IsClosedSurface(vtkPolyData* surface)
{
  if (!surface || !surface->GetPoints() || surface->GetNumberOfLines() > 0 ||
    surface->GetNumberOfVerts() > 0)
  {
    return false;
  }
  EdgeCounter edges(MergedPointIds(surface->GetPoints()));
  vtkNew<vtkIdList> cell;
  for (auto polys = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
       !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(cell);
    for (vtkIdType i = 0; i < cell->GetNumberOfIds(); ++i)
    {
      edges.Add(cell->GetId(i), cell->GetId((i + 1) % cell->GetNumberOfIds()));
    }
  }
  for (auto strips = vtk::TakeSmartPointer(surface->GetStrips()->NewIterator());
       !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    strips->GetCurrentCell(cell);
    // Triangle k of a strip is (k, k+1, k+2), wound the other way for odd k.
    for (vtkIdType k = 0; k + 2 < cell->GetNumberOfIds(); ++k)
    {
      const vtkIdType first = cell->GetId(k + (k % 2));
      const vtkIdType second = cell->GetId(k + 1 - (k % 2));
      edges.AddTriangle(first, second, cell->GetId(k + 2));
    }
  }
  return edges.EachEdgeOnceEachWay();
}

//------------------------------------------------------------------------------
bool IsClosedData(vtkDataObject* data)
{
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    bool any = false;
    auto it = vtk::TakeSmartPointer(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (!IsClosedData(it->GetCurrentDataObject()))
      {
        return false;
      }
      any = true;
    }
    return any;
  }
  return IsClosedSurface(vtkPolyData::SafeDownCast(data));
}

//------------------------------------------------------------------------------
bool DrawsClosedSurface(vtkProp* prop)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  // Clipping planes cut the drawn surface open.
  if (!mapper || actor->GetProperty()->GetRepresentation() != VTK_SURFACE ||
    mapper->GetNumberOfInputConnections(0) < 1 ||
    (mapper->GetClippingPlanes() && mapper->GetClippingPlanes()->GetNumberOfItems() > 0))
  {
    return false;
  }
  return IsClosedData(mapper->GetInputDataObject(0, 0));
}

//------------------------------------------------------------------------------
bool ClosedCasters::AllClosed(const std::vector<std::pair<vtkProp*, vtkMTimeType>>& casters)
{
  std::unordered_map<vtkProp*, std::pair<vtkMTimeType, bool>> known;
  bool all = true;
  for (const auto& caster : casters)
  {
    auto found = this->Known.find(caster.first);
    const bool closed = found != this->Known.end() && found->second.first == caster.second
      ? found->second.second
      : DrawsClosedSurface(caster.first);
    known[caster.first] = { caster.second, closed };
    all = all && closed;
  }
  // Only the current casters are kept: a deleted prop's address may come back.
  this->Known = std::move(known);
  return all;
}
} // namespace shadowmaps
