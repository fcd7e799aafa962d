// Views of one light that differ only by where their window lies on the light's
// projection plane and how deep it reaches: unwarped cascades (one light
// rotation, an orthographic box each) and the tiles of one map. Each is its
// first view followed by a crop, a per-axis scale and offset of the clip
// coordinates, so that a receiver transforms once, by the first view, and crops
// for the view it picked (vtkShadowMapsReceiverFS's vtkShadowMapMatrix).
#ifndef ShadowMapCrop_h
#define ShadowMapCrop_h

#include <glm/glm.hpp>

namespace shadowmaps
{
/// clip' = (clip.xyz * Scale + clip.w * Offset, clip.w).
struct MapCrop
{
  glm::dvec3 Scale{ 1.0 };
  glm::dvec3 Offset{ 0.0 };

  glm::dmat4 Matrix() const;
};

/// The crop that takes clip coordinates of `first` to those of `view`
/// (view = crop * first), read off view * inverse(first). Meaningful only where
/// CropError is small.
MapCrop CropBetween(const glm::dmat4& first, const glm::dmat4& view);

/// The largest element of view * inverse(first) that a crop has to be zero, over
/// the largest it keeps: about 1e-16 for views that are crops of `first`, of the
/// order of 1 for views that are not. Infinite where `first` is singular.
double CropError(const glm::dmat4& first, const glm::dmat4& view);
} // namespace shadowmaps

#endif
