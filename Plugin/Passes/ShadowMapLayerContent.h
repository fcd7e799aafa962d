// What a map layer was rendered from, and whether it still shows what a frame
// needs, so that a moving camera re-renders only the layers whose view or
// casters changed. Not a VTK class: it holds no VTK state.
#ifndef ShadowMapLayerContent_h
#define ShadowMapLayerContent_h

#include "vtkType.h"

#include <vector>

namespace shadowmaps
{

/// A caster, by identity, with the version of everything its depth depends on
/// (shadowmaps::CasterVersion).
struct CasterStamp
{
  const void* Prop = nullptr;
  vtkMTimeType Version = 0;
};

bool operator==(const CasterStamp& a, const CasterStamp& b);

/// `stamps` sorted by prop, for LayerContent.
std::vector<CasterStamp> SortedByProp(std::vector<CasterStamp> stamps);

/// What a layer was rendered from: its view (the bits of everything about it
/// that reaches the texels), the casters drawn into it, the generation of the
/// frame's casters then (a number that changes whenever the frame's set of
/// casters, one of their versions or one of their bounds does) and whether they were every caster
/// in the view.
class LayerContent
{
public:
  /// Never rendered, or to be re-rendered: holds nothing.
  LayerContent() = default;
  /// `view` must not be empty; `drawn` must be among the casters of
  /// `generation`.
  LayerContent(std::vector<vtkMTimeType> view, std::vector<CasterStamp> drawn,
    unsigned long long generation, bool everyCasterInView);

  /// Whether the layer still shows `view` for casters of `generation` because it
  /// was drawn with every caster in that view of those casters: whatever a frame
  /// needs, it holds, with no caster to compare.
  bool HoldsEveryCasterInView(const std::vector<vtkMTimeType>& view, unsigned long long generation) const;

  /// Whether the layer still shows `view` with the `needed` casters: the same
  /// view, every needed caster drawn with its current data, and every drawn
  /// caster still among the frame's casters (`current`, SortedByProp) with the
  /// data it was drawn with. A caster drawn but not needed (the camera turned
  /// away from where its shadow falls, or a layer re-rendered in a drag took
  /// every caster in its view) stays: its depths are still right, and lie where
  /// no receiver in view looks them up (coarse mip levels of a filtered map may
  /// still average them in, as they would had it been needed; drags add none
  /// to mipmapped maps). A drawn caster whose data changed re-renders the layer.
  /// Where `generation` is still the layer's, the drawn casters are known to be
  /// current without comparing.
  bool Holds(const std::vector<vtkMTimeType>& view, const std::vector<CasterStamp>& needed,
    const std::vector<CasterStamp>& current, unsigned long long generation) const;

private:
  std::vector<vtkMTimeType> View; // empty: never rendered
  std::vector<CasterStamp> Drawn; // SortedByProp
  unsigned long long Generation = 0;
  bool EveryCasterInView = false;
};

} // namespace shadowmaps

#endif
