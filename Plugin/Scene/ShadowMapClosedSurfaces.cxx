#include "ShadowMapClosedSurfaces.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkMapper.h"
#include "vtkPlaneCollection.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

// A time series brings new casters every frame, so this runs per frame on
// millions of triangles: edges are grouped by their lower point id in flat
// arrays (no hashing of edges, no allocation per edge), and coincident points
// are merged only where an edge found no partner.
namespace shadowmaps
{
namespace
{
constexpr std::uint32_t NoPoint = std::numeric_limits<std::uint32_t>::max();

struct Edge
{
  std::uint32_t From;
  std::uint32_t To;
};

// Calls visit(from, to) for each edge of the oriented faces, in point ids as
// stored. Strips join with degenerate triangles, which bound nothing.
template <typename Visitor>
void ForEachEdge(vtkPolyData* surface, Visitor&& visit)
{
  auto edge = [&visit](vtkIdType from, vtkIdType to) {
    if (from != to) // a degenerate edge bounds nothing
    {
      visit(static_cast<std::uint32_t>(from), static_cast<std::uint32_t>(to));
    }
  };
  vtkIdType size;
  const vtkIdType* ids;
  for (auto cell = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
       !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    cell->GetCurrentCell(size, ids);
    for (vtkIdType i = 0; i < size; ++i)
    {
      edge(ids[i], ids[(i + 1) % size]);
    }
  }
  for (auto cell = vtk::TakeSmartPointer(surface->GetStrips()->NewIterator());
       !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    cell->GetCurrentCell(size, ids);
    // Triangle k of a strip is (k, k+1, k+2), wound the other way for odd k.
    for (vtkIdType k = 0; k + 2 < size; ++k)
    {
      const vtkIdType a = ids[k + (k % 2)];
      const vtkIdType b = ids[k + 1 - (k % 2)];
      const vtkIdType c = ids[k + 2];
      if (a != b && b != c && c != a)
      {
        edge(a, b);
        edge(b, c);
        edge(c, a);
      }
    }
  }
}

enum class Pairing
{
  NoEdges, // bounds nothing
  EachOnceEachWay,
  SomeUnpaired,
  SomeTwiceOneWay, // open, or inconsistently wound, whatever points merge
};

// Whether each edge is there once each way; `unpaired` receives those that
// are there once only. forEachEdge(visit) calls visit(from, to) per edge, and
// is called twice. Edges are grouped by their lower point, whose groups hold a
// few edges each on a mesh.
template <typename EdgeSource>
Pairing PairEdges(EdgeSource&& forEachEdge, std::size_t pointCount, std::vector<Edge>& unpaired)
{
  std::vector<std::uint32_t> groupStart(pointCount + 1, 0);
  forEachEdge([&](std::uint32_t from, std::uint32_t to) { ++groupStart[std::min(from, to) + 1]; });
  for (std::size_t point = 0; point < pointCount; ++point)
  {
    groupStart[point + 1] += groupStart[point];
  }
  // Each group holds the other point, shifted, with the direction in bit 0.
  std::vector<std::uint32_t> others(groupStart.back());
  std::vector<std::uint32_t> next(groupStart.begin(), groupStart.end() - 1);
  forEachEdge([&](std::uint32_t from, std::uint32_t to) {
    const bool upward = from < to;
    others[next[upward ? from : to]++] = (std::max(from, to) << 1) | upward;
  });
  for (std::uint32_t low = 0; low < pointCount; ++low)
  {
    auto first = others.begin() + groupStart[low];
    auto last = others.begin() + groupStart[low + 1];
    std::sort(first, last);
    for (auto it = first; it != last;)
    {
      const std::uint32_t high = *it >> 1;
      const bool pairAhead = it + 1 != last && (*(it + 1) >> 1) == high;
      if (pairAhead && (*it & 1) == (*(it + 1) & 1))
      {
        return Pairing::SomeTwiceOneWay;
      }
      if (pairAhead && it + 2 != last && (*(it + 2) >> 1) == high)
      {
        return Pairing::SomeTwiceOneWay;
      }
      if (!pairAhead)
      {
        unpaired.push_back((*it & 1) ? Edge{ low, high } : Edge{ high, low });
      }
      it += pairAhead ? 2 : 1;
    }
  }
  if (others.empty())
  {
    return Pairing::NoEdges;
  }
  return unpaired.empty() ? Pairing::EachOnceEachWay : Pairing::SomeUnpaired;
}

std::size_t PowerOfTwoAtLeast(std::size_t n)
{
  std::size_t size = 16;
  while (size < n)
  {
    size *= 2;
  }
  return size;
}

std::uint64_t Mix(std::uint64_t h)
{
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  return h ^ (h >> 33);
}

std::uint64_t HashOfPlace(const double* p)
{
  std::uint64_t h = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double value = p[axis] + 0.0; // -0 and +0 are one place
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    h = Mix(h ^ bits);
  }
  return h;
}

// The edges with each point replaced by the first of the edges' points at its
// place (sources such as vtkCubeSource repeat corners per face), edges that
// become degenerate left out.
std::vector<Edge> MergedPlaces(const std::vector<Edge>& edges, vtkPoints* points)
{
  std::vector<std::uint32_t> ids;
  ids.reserve(2 * edges.size());
  for (const Edge& edge : edges)
  {
    ids.push_back(edge.From);
    ids.push_back(edge.To);
  }
  std::vector<std::uint32_t> firstAt(PowerOfTwoAtLeast(2 * ids.size()), NoPoint);
  const std::size_t mask = firstAt.size() - 1;
  for (std::uint32_t& id : ids)
  {
    double p[3];
    double q[3];
    points->GetPoint(id, p);
    std::size_t slot = HashOfPlace(p) & mask;
    for (; firstAt[slot] != NoPoint; slot = (slot + 1) & mask)
    {
      points->GetPoint(firstAt[slot], q);
      if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2])
      {
        break;
      }
    }
    if (firstAt[slot] == NoPoint)
    {
      firstAt[slot] = id;
    }
    id = firstAt[slot];
  }
  std::vector<Edge> merged;
  for (std::size_t i = 0; i < ids.size(); i += 2)
  {
    if (ids[i] != ids[i + 1])
    {
      merged.push_back({ ids[i], ids[i + 1] });
    }
  }
  return merged;
}
} // namespace

//------------------------------------------------------------------------------
bool IsClosedSurface(vtkPolyData* surface)
{
  if (!surface || !surface->GetPoints() || surface->GetNumberOfLines() > 0 ||
    surface->GetNumberOfVerts() > 0)
  {
    return false;
  }
  // Point ids go to 31 bits, so that a direction fits beside one, and edges
  // are counted in 32; a bigger surface counts as open, which peeling handles.
  const vtkIdType mostEdges = surface->GetPolys()->GetNumberOfConnectivityIds() +
    3 * surface->GetStrips()->GetNumberOfConnectivityIds();
  if (surface->GetNumberOfPoints() >= (vtkIdType(1) << 31) || mostEdges >= (vtkIdType(1) << 32))
  {
    return false;
  }
  const std::size_t pointCount = static_cast<std::size_t>(surface->GetNumberOfPoints());
  std::vector<Edge> unpaired;
  switch (PairEdges([surface](auto visit) { ForEachEdge(surface, visit); }, pointCount, unpaired))
  {
    case Pairing::EachOnceEachWay:
      return true;
    case Pairing::NoEdges:
    case Pairing::SomeTwiceOneWay:
      return false;
    case Pairing::SomeUnpaired:
      break;
  }
  // Edges paired as stored stay paired when points merge; the others must pair
  // among themselves once their points are merged.
  const std::vector<Edge> merged = MergedPlaces(unpaired, surface->GetPoints());
  auto forEachMerged = [&merged](auto visit) {
    for (const Edge& edge : merged)
    {
      visit(edge.From, edge.To);
    }
  };
  std::vector<Edge> stillUnpaired;
  return PairEdges(forEachMerged, pointCount, stillUnpaired) == Pairing::EachOnceEachWay;
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
