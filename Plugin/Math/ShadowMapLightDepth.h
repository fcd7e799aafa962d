// The light depth: how far along a light's rays a point lies, as one number in
// [0, 1] over the scene, the same for every view of the light. Filterable
// representations (moments) store and compare it: linear in light space, so
// that an exponent or a blur means the same in every view, whatever the view's
// own projection (warped, perspective, cube face) does to its depth.
#ifndef ShadowMapLightDepth_h
#define ShadowMapLightDepth_h

#include "ShadowMapFocusing.h" // For Aabb

#include <glm/glm.hpp>

namespace shadowmaps
{
/// depth(p) = dot(Plane.xyz, p - Origin) + Plane.w + PerDistance * |p - Origin|:
/// along the direction of a directional light (PerDistance 0; Origin the
/// scene's centre), or the distance from a positional light (Plane.xyz 0;
/// Origin the light). Positions are taken relative to Origin so that shaders
/// never form large coordinates in single precision.
struct LightDepth
{
  glm::dvec4 Plane{ 0.0, 0.0, 0.0, 0.0 };
  double PerDistance = 0.0;
  glm::dvec3 Origin{ 0.0 };
};

/// Depth along `direction` (from the light toward what it lights), 0 and 1 a
/// little beyond the scene's nearest and farthest corners.
LightDepth DirectionalLightDepth(const glm::dvec3& direction, const Aabb& scene);

/// Distance from `position`, 0 and 1 a little beyond the scene's nearest point
/// (0 from inside it) and farthest corner.
LightDepth PositionalLightDepth(const glm::dvec3& position, const Aabb& scene);

/// The light depth of `p`, unclamped.
double EvaluateLightDepth(const LightDepth& depth, const glm::dvec3& p);

/// The same function of points given in the frame `rigid` (a rotation and a
/// translation, such as a camera's view matrix) takes world points to.
LightDepth TransformLightDepth(const LightDepth& depth, const glm::dmat4& rigid);
} // namespace shadowmaps

#endif
