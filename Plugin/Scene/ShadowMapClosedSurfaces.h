// Whether a caster is closed, i.e. bounds a volume: every light ray then meets
// its surface an even number of times, so the nearest front face and the
// nearest back face along the ray are the first two surfaces. Dual-depth maps
// rely on that to make both depths in one caster pass (minimum blending); for
// open casters (planes, isosurface pieces cut by the volume's boundary, clipped
// data) they need depth peeling instead (shadowmaps::SecondDepthMethod::Auto).
#ifndef ShadowMapClosedSurfaces_h
#define ShadowMapClosedSurfaces_h

#include "vtkType.h" // For vtkMTimeType

#include <cstddef>
#include <unordered_map>
#include <utility>
#include <vector>

class vtkDataObject;
class vtkPolyData;
class vtkProp;

namespace shadowmaps
{
/// True if every edge of the polygons and strips is shared by exactly two of
/// them, wound opposite ways (a consistently oriented surface: minimum
/// blending tells its entries from its exits by facing), and there are no lines
/// or vertices. Edges without a partner pair up with points that have the same
/// coordinates made one (sources such as vtkCubeSource repeat corners per
/// face); edges paired as stored count as paired even where other points
/// coincide with theirs. An edge of more than two faces (a face given twice or
/// with its reverse, surfaces meeting along an edge) leaves the surface open.
/// False, with a warning, for faces naming points the surface does not have,
/// and for data without polygons. Linear in the size of the surface, and one
/// pass with a number per point for most open ones: it runs for every new
/// version of a caster's data.
bool IsClosedSurface(vtkPolyData* surface);

/// IsClosedSurface of every leaf of composite data; false for data that is not
/// polygonal (its drawn surface is not known here).
bool IsClosedData(vtkDataObject* data);

/// Whether a prop draws a closed surface: an actor drawn as a surface, without
/// clipping planes, whose mapper input IsClosedData. Other props (impostors,
/// glyphs, volumes) count as open, the answer that is right for any geometry.
bool DrawsClosedSurface(vtkProp* prop);

/// The number of cells of what an actor's mapper draws (0 for other props).
vtkIdType CellsDrawn(vtkProp* prop);

/// Whether DrawsClosedSurface holds for every caster, each caster's answer kept
/// per modification time of what it draws. It stops at the first open caster,
/// taking the answers known first and then the smallest casters.
class ClosedCasters
{
public:
  /// `casters`: each prop with the modification time of its data.
  bool AllClosed(const std::vector<std::pair<vtkProp*, vtkMTimeType>>& casters);

  /// How many casters' surfaces AllClosed has analysed so far.
  std::size_t GetNumberOfAnalyses() const { return this->Analyses; }

private:
  std::unordered_map<vtkProp*, std::pair<vtkMTimeType, bool>> Known;
  std::size_t Analyses = 0;
};
} // namespace shadowmaps

#endif
