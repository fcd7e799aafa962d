#include "ShadowAreaLight.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowarealight
{
namespace
{
// Two unit vectors completing `axis` to an orthonormal frame.
void Perpendiculars(const glm::dvec3& axis, glm::dvec3& e1, glm::dvec3& e2)
{
  const glm::dvec3 side = std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  e1 = glm::normalize(glm::cross(axis, side));
  e2 = glm::cross(axis, e1);
}

double UnitInterval(std::uint64_t bits)
{
  return static_cast<double>(bits >> 11) * (1.0 / 9007199254740992.0); // 53 bits
}

// Distance from `origin` along unit `direction` to the sphere's near surface;
// the tangent distance for a direction that grazes it.
double ToSphere(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& centre,
  double radius)
{
  const glm::dvec3 toCentre = centre - origin;
  const double along = glm::dot(direction, toCentre);
  const double discriminant = along * along - (glm::dot(toCentre, toCentre) - radius * radius);
  return std::max(0.0, along - std::sqrt(std::max(discriminant, 0.0)));
}
} // namespace

//------------------------------------------------------------------------------
std::uint64_t Mix(std::uint64_t a, std::uint64_t b)
{
  // splitmix64's finaliser over a combination of the two.
  std::uint64_t z = a * 0x9E3779B97F4A7C15ull + b + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

//------------------------------------------------------------------------------
LightCone SunCone(const glm::dvec3& towardLight, double diameterDegrees)
{
  LightCone cone;
  cone.Axis = glm::normalize(towardLight);
  cone.CosHalfAngle = std::cos(glm::radians(0.5 * std::max(diameterDegrees, 0.0)));
  return cone;
}

//------------------------------------------------------------------------------
LightCone SphereCone(const glm::dvec3& point, const glm::dvec3& centre, double radius)
{
  LightCone cone;
  cone.Centre = centre;
  cone.Radius = std::max(radius, 0.0);
  const glm::dvec3 toCentre = centre - point;
  const double distance = glm::length(toCentre);
  cone.Inside = distance <= cone.Radius;
  if (distance > 0.0)
  {
    cone.Axis = toCentre / distance;
  }
  if (!cone.Inside)
  {
    const double sine = cone.Radius / distance;
    cone.CosHalfAngle = std::sqrt(std::max(0.0, 1.0 - sine * sine));
  }
  return cone;
}

//------------------------------------------------------------------------------
glm::dvec2 ConcentricDisc(const glm::dvec2& square)
{
  const glm::dvec2 p = 2.0 * square - 1.0;
  if (p.x == 0.0 && p.y == 0.0)
  {
    return p;
  }
  const double quarter = 0.25 * glm::pi<double>();
  double radius;
  double angle;
  if (std::abs(p.x) > std::abs(p.y))
  {
    radius = p.x;
    angle = quarter * (p.y / p.x);
  }
  else
  {
    radius = p.y;
    angle = 2.0 * quarter - quarter * (p.x / p.y);
  }
  return radius * glm::dvec2(std::cos(angle), std::sin(angle));
}

//------------------------------------------------------------------------------
LightRay SampleCone(
  const LightCone& cone, const glm::dvec3& origin, int index, int strata, std::uint64_t seed)
{
  const int n = std::max(1, strata);
  const std::uint64_t bits = Mix(seed, static_cast<std::uint64_t>(index));
  const glm::dvec2 square((index % n + UnitInterval(bits)) / n,
    ((index / n) % n + UnitInterval(Mix(bits, 1))) / n);
  const glm::dvec2 disc = ConcentricDisc(square);
  // Uniform over the disc's area is uniform in r^2; uniform over the cone's
  // solid angle is uniform in cos(theta) from 1 to CosHalfAngle.
  const double r2 = std::min(1.0, glm::dot(disc, disc));
  const double cosTheta = 1.0 - r2 * (1.0 - cone.CosHalfAngle);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  const double r = std::sqrt(r2);
  const glm::dvec2 around = r > 0.0 ? disc / r : glm::dvec2(1.0, 0.0);
  glm::dvec3 e1;
  glm::dvec3 e2;
  Perpendiculars(cone.Axis, e1, e2);
  LightRay ray;
  ray.Direction =
    glm::normalize(cosTheta * cone.Axis + sinTheta * (around.x * e1 + around.y * e2));
  if (cone.Radius > 0.0)
  {
    ray.Length = ToSphere(origin, ray.Direction, cone.Centre, cone.Radius);
  }
  return ray;
}

} // namespace shadowarealight
