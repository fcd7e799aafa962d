#include "ShadowMapClosedSurfaces.h"

#include "vtkAOSDataArrayTemplate.h"
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
#include "vtkSetGet.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

// A time series brings new casters every frame, so this runs per frame on
// millions of triangles, and most changing casters (isosurfaces cut by their
// volume's boundary) are open. One pass sums, at each point, a hash of each
// neighbour it has an edge to minus one of each it has an edge from (no memory
// per edge): where a sum does not cancel, the few edges there are paired
// exactly, which tells most open surfaces. Sums that all cancel allow an edge
// twice each way (a surface given with its reverse), so a surface that passes
// has every edge paired exactly, grouped by their lower point.
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

// Calls visit(ids, size) for each polygon of `cells` if they are held in plain
// arrays of `Id` (VTK's 32- and 64-bit storage), reading them directly: a
// cell iterator's call per cell costs more than the pass's work on a triangle.
// False for other storage (VTK 9.6's fixed-size and generic cell arrays).
template <typename Id, typename Visitor>
bool ForEachPolygonIn(vtkCellArray* cells, Visitor& visit)
{
  using IdArray = vtkAOSDataArrayTemplate<Id>;
  auto* offsetArray = vtkArrayDownCast<IdArray>(cells->GetOffsetsArray());
  auto* connectivityArray = vtkArrayDownCast<IdArray>(cells->GetConnectivityArray());
  if (!offsetArray || !connectivityArray)
  {
    return false;
  }
  const auto* offsets = offsetArray->GetPointer(0);
  const auto* connectivity = connectivityArray->GetPointer(0);
  const vtkIdType cellCount = cells->GetNumberOfCells();
  for (vtkIdType cell = 0; cell < cellCount; ++cell)
  {
    visit(connectivity + offsets[cell], static_cast<vtkIdType>(offsets[cell + 1] - offsets[cell]));
  }
  return true;
}

// Calls visit(from, to) for each edge of the oriented faces, in point ids as
// stored. Strips join with degenerate triangles, which bound nothing. False if
// some face names a point the surface does not have (such edges are left out).
template <typename Visitor>
bool ForEachEdge(vtkPolyData* surface, Visitor&& visit)
{
  // In 64 bits whatever vtkIdType is: a 64-bit cell array's ids are checked
  // before they could wrap.
  const std::int64_t pointCount = surface->GetNumberOfPoints();
  bool idsInRange = true;
  auto edge = [&visit, &idsInRange, pointCount](std::int64_t from, std::int64_t to) {
    if (from < 0 || to < 0 || from >= pointCount || to >= pointCount)
    {
      idsInRange = false;
    }
    else if (from != to) // a degenerate edge bounds nothing
    {
      visit(static_cast<std::uint32_t>(from), static_cast<std::uint32_t>(to));
    }
  };
  auto polygon = [&edge](const auto* ids, vtkIdType size) {
    for (vtkIdType i = 0; i + 1 < size; ++i)
    {
      edge(ids[i], ids[i + 1]);
    }
    if (size > 1)
    {
      edge(ids[size - 1], ids[0]);
    }
  };
  vtkIdType size;
  const vtkIdType* ids;
  vtkCellArray* polys = surface->GetPolys();
  if (!ForEachPolygonIn<vtkTypeInt64>(polys, polygon) &&
    !ForEachPolygonIn<vtkTypeInt32>(polys, polygon))
  {
    for (auto cell = vtk::TakeSmartPointer(polys->NewIterator()); !cell->IsDoneWithTraversal();
         cell->GoToNextCell())
    {
      cell->GetCurrentCell(size, ids);
      polygon(ids, size);
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
  return idsInRange;
}

std::uint64_t Mix(std::uint64_t h)
{
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  return h ^ (h >> 33);
}

// Per point, the hashes of the points its edges go to less those of the points
// its edges come from: zero where every edge there is matched by one the other
// way (up to a collision of 64-bit hashes). A non-linear hash, so that no
// arithmetic among neighbours' ids cancels.
struct EdgeBalance
{
  std::vector<std::uint64_t> PerPoint;
  bool AnyEdge = false;
  bool IdsInRange = true;
};

EdgeBalance BalanceEdges(vtkPolyData* surface)
{
  EdgeBalance balance;
  balance.PerPoint.assign(static_cast<std::size_t>(surface->GetNumberOfPoints()), 0);
  balance.IdsInRange = ForEachEdge(surface, [&balance](std::uint32_t from, std::uint32_t to) {
    balance.PerPoint[from] += Mix(to + 1);
    balance.PerPoint[to] -= Mix(from + 1);
    balance.AnyEdge = true;
  });
  return balance;
}

enum class Pairing
{
  NoEdges, // bounds nothing
  EachOnceEachWay,
  SomeUnpaired,
  SomeTwiceOneWay, // open, or inconsistently wound, whatever points merge
};

// An edge as its group (its lower point) keeps it: the other point, shifted,
// with the direction in bit 0.
std::uint32_t KeyInGroup(std::uint32_t from, std::uint32_t to)
{
  return (std::max(from, to) << 1) | (from < to ? 1u : 0u);
}

// Pairs the edges of one group, those whose lower point is `low`: `others`
// holds each one's other point, shifted, with its direction in bit 0, sorted.
// False if some edge is there twice one way or more than twice; `unpaired`
// receives those that are there once only.
bool PairGroup(std::uint32_t low, const std::uint32_t* first, const std::uint32_t* last,
  std::vector<Edge>& unpaired)
{
  for (const std::uint32_t* it = first; it != last;)
  {
    const std::uint32_t high = *it >> 1;
    const bool pairAhead = it + 1 != last && (*(it + 1) >> 1) == high;
    if (pairAhead && ((*it & 1) == (*(it + 1) & 1) || (it + 2 != last && (*(it + 2) >> 1) == high)))
    {
      return false;
    }
    if (!pairAhead)
    {
      unpaired.push_back((*it & 1) ? Edge{ low, high } : Edge{ high, low });
    }
    it += pairAhead ? 2 : 1;
  }
  return true;
}

Pairing Outcome(bool any, bool onceOneWayAtMost, const std::vector<Edge>& unpaired)
{
  if (!onceOneWayAtMost)
  {
    return Pairing::SomeTwiceOneWay;
  }
  if (!any)
  {
    return Pairing::NoEdges;
  }
  return unpaired.empty() ? Pairing::EachOnceEachWay : Pairing::SomeUnpaired;
}

// Whether each edge of a surface is there once each way; `unpaired` receives
// those that are there once only. forEachEdge(visit) calls visit(from, to) per
// edge, and is called twice. Edges are grouped by their lower point in arrays
// of the surface's size, counted then filled (sorted only within a group,
// which holds a few edges on a mesh).
template <typename EdgeSource>
Pairing PairEdges(EdgeSource&& forEachEdge, std::size_t pointCount, std::vector<Edge>& unpaired)
{
  std::vector<std::uint32_t> groupStart(pointCount + 1, 0);
  forEachEdge([&](std::uint32_t from, std::uint32_t to) { ++groupStart[std::min(from, to) + 1]; });
  for (std::size_t point = 0; point < pointCount; ++point)
  {
    groupStart[point + 1] += groupStart[point];
  }
  std::vector<std::uint32_t> others(groupStart.back());
  std::vector<std::uint32_t> next(groupStart.begin(), groupStart.end() - 1);
  forEachEdge([&](std::uint32_t from, std::uint32_t to) {
    others[next[std::min(from, to)]++] = KeyInGroup(from, to);
  });
  bool onceOneWayAtMost = true;
  for (std::uint32_t low = 0; onceOneWayAtMost && low < pointCount; ++low)
  {
    std::uint32_t* first = others.data() + groupStart[low];
    std::uint32_t* last = others.data() + groupStart[low + 1];
    std::sort(first, last);
    onceOneWayAtMost = PairGroup(low, first, last, unpaired);
  }
  return Outcome(!others.empty(), onceOneWayAtMost, unpaired);
}

// PairEdges for a few edges of a big surface: sorted, in memory of their number.
Pairing PairEdgeList(const std::vector<Edge>& edges, std::vector<Edge>& unpaired)
{
  std::vector<std::uint64_t> keys;
  keys.reserve(edges.size());
  for (const Edge& edge : edges)
  {
    const std::uint64_t low = std::min(edge.From, edge.To);
    keys.push_back((low << 32) | KeyInGroup(edge.From, edge.To));
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::uint32_t> group;
  bool onceOneWayAtMost = true;
  for (std::size_t first = 0; onceOneWayAtMost && first < keys.size();)
  {
    const std::uint32_t low = static_cast<std::uint32_t>(keys[first] >> 32);
    group.clear();
    std::size_t last = first;
    for (; last < keys.size() && (keys[last] >> 32) == low; ++last)
    {
      group.push_back(static_cast<std::uint32_t>(keys[last]));
    }
    onceOneWayAtMost = PairGroup(low, group.data(), group.data() + group.size(), unpaired);
    first = last;
  }
  return Outcome(!edges.empty(), onceOneWayAtMost, unpaired);
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

// Whether edges paired as `pairing` says are each there once each way, edges
// without a partner paired again with points at one place made one; edges
// paired as stored stay paired when other points coincide with theirs.
bool PairedOnceMerged(Pairing pairing, const std::vector<Edge>& unpaired, vtkPoints* points)
{
  switch (pairing)
  {
    case Pairing::EachOnceEachWay:
      return true;
    case Pairing::NoEdges:
    case Pairing::SomeTwiceOneWay:
      return false;
    case Pairing::SomeUnpaired:
      break;
  }
  std::vector<Edge> stillUnpaired;
  return PairEdgeList(MergedPlaces(unpaired, points), stillUnpaired) == Pairing::EachOnceEachWay;
}

// The data an actor's mapper draws; null for other props.
vtkDataObject* DrawnData(vtkProp* prop)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  return mapper && mapper->GetNumberOfInputConnections(0) > 0 ? mapper->GetInputDataObject(0, 0)
                                                              : nullptr;
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
  const EdgeBalance balance = BalanceEdges(surface);
  if (!balance.IdsInRange)
  {
    vtkGenericWarningMacro("A caster's faces name points it does not have: it counts as open.");
    return false;
  }
  const std::size_t pointCount = balance.PerPoint.size();
  const std::vector<std::uint64_t>& sums = balance.PerPoint;
  if (!std::all_of(sums.begin(), sums.end(), [](std::uint64_t sum) { return sum == 0; }))
  {
    // The edges at points whose sums do not cancel must pair among themselves.
    std::vector<Edge> atUnbalancedPoints;
    ForEachEdge(surface, [&](std::uint32_t from, std::uint32_t to) {
      if (sums[from] != 0 || sums[to] != 0)
      {
        atUnbalancedPoints.push_back({ from, to });
      }
    });
    std::vector<Edge> unpaired;
    if (!PairedOnceMerged(
          PairEdgeList(atUnbalancedPoints, unpaired), unpaired, surface->GetPoints()))
    {
      return false;
    }
  }
  std::vector<Edge> unpaired;
  return PairedOnceMerged(
    PairEdges([surface](auto visit) { ForEachEdge(surface, visit); }, pointCount, unpaired),
    unpaired, surface->GetPoints());
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
vtkIdType CellsDrawn(vtkProp* prop)
{
  vtkDataObject* data = DrawnData(prop);
  return data ? data->GetNumberOfElements(vtkDataObject::CELL) : 0;
}

//------------------------------------------------------------------------------
bool DrawsClosedSurface(vtkProp* prop)
{
  vtkDataObject* data = DrawnData(prop);
  if (!data)
  {
    return false;
  }
  auto* actor = static_cast<vtkActor*>(prop);
  vtkPlaneCollection* clipping = actor->GetMapper()->GetClippingPlanes();
  // Clipping planes cut the drawn surface open.
  return actor->GetProperty()->GetRepresentation() == VTK_SURFACE &&
    !(clipping && clipping->GetNumberOfItems() > 0) && IsClosedData(data);
}

//------------------------------------------------------------------------------
bool ClosedCasters::AllClosed(const std::vector<std::pair<vtkProp*, vtkMTimeType>>& casters)
{
  // Only the current casters are kept: a deleted prop's address may come back.
  std::unordered_map<vtkProp*, std::pair<vtkMTimeType, bool>> known;
  struct Unknown
  {
    vtkProp* Prop;
    vtkMTimeType Version;
    vtkIdType Cells;
  };
  std::vector<Unknown> unknown;
  for (const auto& caster : casters)
  {
    auto found = this->Known.find(caster.first);
    if (found != this->Known.end() && found->second.first == caster.second)
    {
      known.insert(*found);
    }
    else
    {
      unknown.push_back({ caster.first, caster.second, 0 });
    }
  }
  this->Known = std::move(known);
  // One open caster settles the answer: the answers known come first, then the
  // smallest casters, so that a ground plane spares a changing isosurface its
  // analysis at every step.
  auto open = [](const auto& entry) { return !entry.second.second; };
  if (std::any_of(this->Known.begin(), this->Known.end(), open))
  {
    return false;
  }
  for (Unknown& caster : unknown)
  {
    caster.Cells = CellsDrawn(caster.Prop);
  }
  std::stable_sort(unknown.begin(), unknown.end(),
    [](const Unknown& a, const Unknown& b) { return a.Cells < b.Cells; });
  for (const Unknown& caster : unknown)
  {
    const bool closed = DrawsClosedSurface(caster.Prop);
    ++this->Analyses;
    this->Known[caster.Prop] = { caster.Version, closed };
    if (!closed)
    {
      return false;
    }
  }
  return true;
}
} // namespace shadowmaps
