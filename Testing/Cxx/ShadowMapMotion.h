// Map motion for the continuity tests of the warps: how far fixed world points
// move on a shadow map from one step of a light's turn to the next, beyond the
// moves of a reference map (the uniform one) over the same steps.
#ifndef ShadowMapMotion_h
#define ShadowMapMotion_h

#include "ShadowMapFocusing.h"

#include <algorithm>
#include <vector>

#include <glm/glm.hpp>

namespace shadowmaps
{
namespace testing
{

/// The ground the warp tests fit their maps to: 100 x 100, 10 high.
inline Aabb WarpTestGround()
{
  Aabb box;
  box.Min = { -50.0, -50.0, 0.0 };
  box.Max = { 50.0, 50.0, 10.0 };
  return box;
}

/// Texture coordinates of a world point in texels of a resolution x resolution map.
inline glm::dvec2 MapTexels(const LightView& map, const glm::dvec3& world, int resolution)
{
  const glm::dvec4 c = ClipToTexture() * map.ViewProjection() * glm::dvec4(world, 1.0);
  return glm::dvec2(c) / c.w * double(resolution);
}

/// Feed one step's map and reference map; Worst() is the largest excess so far of
/// a point's move on the map over its move on the reference map.
class ExcessMotion
{
public:
  ExcessMotion(std::vector<glm::dvec3> points, int resolution)
    : Points(std::move(points))
    , Resolution(resolution)
  {
  }

  void Step(const LightView& map, const LightView& reference)
  {
    std::vector<glm::dvec2> current, currentReference;
    for (const auto& p : this->Points)
    {
      current.push_back(MapTexels(map, p, this->Resolution));
      currentReference.push_back(MapTexels(reference, p, this->Resolution));
    }
    for (size_t i = 0; i < this->Previous.size(); ++i)
    {
      const double move = glm::length(current[i] - this->Previous[i]);
      const double referenceMove = glm::length(currentReference[i] - this->PreviousReference[i]);
      this->WorstMove = std::max(this->WorstMove, move);
      this->WorstReferenceMove = std::max(this->WorstReferenceMove, referenceMove);
      this->WorstExcess = std::max(this->WorstExcess, move - referenceMove);
    }
    this->Previous = std::move(current);
    this->PreviousReference = std::move(currentReference);
  }

  double Worst() const { return this->WorstExcess; }
  double LargestMove() const { return this->WorstMove; }
  double LargestReferenceMove() const { return this->WorstReferenceMove; }

private:
  std::vector<glm::dvec3> Points;
  int Resolution;
  std::vector<glm::dvec2> Previous, PreviousReference;
  double WorstExcess = 0.0, WorstMove = 0.0, WorstReferenceMove = 0.0;
};

} // namespace testing
} // namespace shadowmaps

#endif
