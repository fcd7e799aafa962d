// How the maps of processes that each render a piece of the scene combine
// into the maps of the whole (vtkAbstractShadowMapPass::SetExchange): which
// combination a storage takes, the props' boxes every process's fits see, and
// the exchange of the maps' texels. The pass coordinates; these do the work.
// Not a VTK class: it holds no VTK state.
#ifndef ShadowMapCombination_h
#define ShadowMapCombination_h

#include <string>

class vtkOpenGLRenderWindow;
class vtkShadowMapExchange;

namespace shadowmaps
{
struct MapStorage;
struct ShadowFrame;
class StoreFromLightDepths;
class TextureArray;

/// How the processes' maps combine into the nearest surfaces over all of them.
enum class Combination : int
{
  /// Not at all (values that are no light depth): each keeps its own.
  None,
  /// Each texel's values, the smallest (depths; front and back faces' depths).
  NearestTexels,
  /// Peeled texels (x, y), the nearest two (vtkShadowMapExchange::NearestTwoOf).
  NearestTwoSurfaces,
  /// Light depths the casters also write, the smallest; then the values from them.
  NearestLightDepths
};

/// How maps of `storage` (its second-depth method chosen) combine.
Combination CombinationOf(const MapStorage& storage);

/// Called on every process: the fits' prop boxes (`frame.PropBounds`) become
/// every process's (vtkShadowMapExchange::AllBoxes) and, unless the scene
/// bounds were given, the scene bounds their union. False when the exchange
/// gathers none: the fits then see the scene bounds alone.
bool GatherPropBounds(vtkShadowMapExchange* exchange, ShadowFrame& frame, bool sceneBoundsGiven);

/// Called on every process once all rendered their `layers` layers of
/// resolution^2 texels: agrees on the maps' shape and kind, combines their
/// texels as `how` says and writes them back (for light depths, `lightDepths`
/// kept them and stores the values with `storage`'s store code). False, with
/// `error`, when the shapes differ or GL or the exchange fails.
bool CombineTexels(vtkShadowMapExchange* exchange, vtkOpenGLRenderWindow* window, Combination how,
  TextureArray& maps, const MapStorage& storage, StoreFromLightDepths& lightDepths, int layers,
  int resolution, std::string& error);
} // namespace shadowmaps

#endif
