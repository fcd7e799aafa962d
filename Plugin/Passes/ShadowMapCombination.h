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
class TransmittanceMaps;

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
/// What every process agrees on at the start of every frame: whether every
/// one renders interactively, and whether any has a translucent caster (all
/// then make transmittance maps, and combine them).
struct FrameAgreement
{
  bool AllInteractive = false;
  bool AnyTranslucent = false;
};

/// Called on every process every frame that has shadowed lights (two AnyOf).
FrameAgreement AgreeOnFrame(vtkShadowMapExchange* exchange, bool interactive, bool translucent);

/// Called on every process once all rendered their maps: whether every one's
/// are of the same resolution, layers, combination and transmittance (the
/// texels' reductions that follow need arrays of one size).
bool AgreeOnShape(vtkShadowMapExchange* exchange, int resolution, int layers, Combination how,
  bool transmittance);

/// Called on every process once all rendered their `layers` transmittance
/// layers of resolution^2 texels: the colours become their product over the
/// processes (vtkShadowMapExchange::ProductOf), the depths the nearest, and
/// are written back. `multiplied` false: the exchange multiplied nothing on
/// some process, and every process keeps its own maps. False, with `error`,
/// when a process could not read its maps or the exchange fails.
bool CombineTransmittances(vtkShadowMapExchange* exchange, vtkOpenGLRenderWindow* window,
  TransmittanceMaps& maps, int layers, int resolution, bool& multiplied, std::string& error);
} // namespace shadowmaps

#endif
