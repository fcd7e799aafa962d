// Sampling a sized light for the oracle (ShadowOracle.h): a sun of some
// angular diameter or a sphere of some radius, seen from a surface point, is a
// cone of directions of uniform radiance. Its visibility is the fraction of
// that cone's solid angle that reaches the light unoccluded, estimated with
// stratified, jittered rays. Pure functions; the jitter is a hash of the
// pixel, so results do not depend on threads or order.
#ifndef ShadowAreaLight_h
#define ShadowAreaLight_h

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>

namespace shadowarealight
{

/// The directions from a point toward a light.
struct LightCone
{
  /// Unit vector from the point toward the light's centre.
  glm::dvec3 Axis{ 0.0, 0.0, 1.0 };
  /// Cosine of the cone's half angle (1: a point source).
  double CosHalfAngle = 1.0;
  /// Spheres: the light's centre and radius; rays end on its surface. Suns
  /// (Radius 0) are infinitely far.
  glm::dvec3 Centre{ 0.0 };
  double Radius = 0.0;
  /// The point is inside a sphere light: it sees all of it.
  bool Inside = false;
};

/// A sun of `diameterDegrees` (angular diameter) in the direction `towardLight`.
LightCone SunCone(const glm::dvec3& towardLight, double diameterDegrees);

/// A sphere light of `radius` at `centre`, seen from `point`.
LightCone SphereCone(const glm::dvec3& point, const glm::dvec3& centre, double radius);

/// One ray toward the light.
struct LightRay
{
  glm::dvec3 Direction; ///< unit
  double Length = std::numeric_limits<double>::infinity();
};

/// Sample `index` of `strata` x `strata` stratified samples of the cone,
/// uniform over its solid angle, jittered within its stratum by `seed`.
LightRay SampleCone(const LightCone& cone, const glm::dvec3& origin, int index, int strata,
  std::uint64_t seed);

/// A point of the unit disc for a point of the unit square, area-preserving
/// and with little distortion (Shirley and Chiu's concentric map).
glm::dvec2 ConcentricDisc(const glm::dvec2& square);

/// A well-mixed 64-bit hash of two values (the pixel, the pass).
std::uint64_t Mix(std::uint64_t a, std::uint64_t b);

} // namespace shadowarealight

#endif
