#include "ShadowMapCascades.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace shadowmaps
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
// Smallest positive depth a perspective near plane is raised to.
constexpr double TinyDepth = 1e-12;

bool Finite(double x)
{
  return std::isfinite(x);
}

// Smallest gap accepted between zNear and zFar.
double MinimumRange(double zNear)
{
  return std::max(1e-6 * std::abs(zNear), 1e-9);
}

// zNear/zFar made finite with zFar > zNear. Returns true if anything changed.
bool RepairRange(double& zNear, double& zFar)
{
  bool changed = false;
  if (!Finite(zNear))
  {
    zNear = 0.0;
    changed = true;
  }
  if (!Finite(zFar))
  {
    zFar = zNear + 1.0;
    changed = true;
  }
  if (!(zFar - zNear >= MinimumRange(zNear)))
  {
    zFar = zNear + MinimumRange(zNear);
    changed = true;
  }
  return changed;
}

// r rounded up to a multiple of 2^(floor(log2 r) - 4). Exact in binary floating point:
// the quantum is a power of two, so r / q, ceil and * q round nothing.
double RoundRadiusUp(double r)
{
  if (!(r > 0.0) || !Finite(r))
  {
    return 1.0;
  }
  int exponent = 0;
  std::frexp(r, &exponent); // r = f 2^exponent, f in [0.5, 1)
  const double quantum = std::ldexp(1.0, exponent - 1 - 4);
  const double rounded = std::ceil(r / quantum) * quantum;
  return Finite(rounded) ? rounded : r;
}

// Whole texels a stable cascade's centre moves by: a thirty-second of the map,
// so that a camera move re-renders the map only once its sphere has crossed
// that much (with one-texel steps an orbit re-rendered it nearly every frame);
// the map grows by the step to keep the sphere inside. Chosen by measurement:
// a sixteenth re-rendered hardly fewer layers and lost more accuracy.
double StableCentreStep(int resolution)
{
  return std::max(1.0, std::floor(resolution / 32.0));
}

// Orthographic projection of half-extent h around (cx, cy), depths [zNear, zFar] in
// front of the view (glm::ortho written out so that the x/y scale is exactly 1/h,
// bitwise the same for every centre).
glm::dmat4 CenteredOrtho(double cx, double cy, double h, double zNear, double zFar)
{
  glm::dmat4 p(1.0);
  p[0][0] = 1.0 / h;
  p[1][1] = 1.0 / h;
  p[3][0] = -cx / h;
  p[3][1] = -cy / h;
  p[2][2] = -2.0 / (zFar - zNear);
  p[3][2] = -(zFar + zNear) / (zFar - zNear);
  return p;
}
} // namespace

std::vector<double> PracticalSplits(double zNear, double zFar, int cascades, double lambda)
{
  RepairRange(zNear, zFar);
  const int m = std::max(cascades, 1);
  const double l = Finite(lambda) ? std::min(std::max(lambda, 0.0), 1.0) : 0.5;
  // The logarithmic term needs a positive start.
  const double logNear = zNear > 0.0 ? zNear : std::max(1e-3 * zFar, TinyDepth);
  const double logFar = std::max(zFar, logNear);
  std::vector<double> splits(m + 1);
  splits[0] = zNear;
  splits[m] = zFar;
  for (int i = 1; i < m; ++i)
  {
    const double t = double(i) / double(m);
    const double logarithmic = logNear * std::pow(logFar / logNear, t);
    const double uniform = zNear + (zFar - zNear) * t;
    const double c = l * logarithmic + (1.0 - l) * uniform;
    // Keep the list ordered even where the repaired log start lies beyond zNear.
    splits[i] = std::min(std::max(c, splits[i - 1]), zFar);
  }
  return splits;
}

namespace
{
// The splits strictly inside (zNear, zFar), sorted, and those that are not.
struct SplitSelection
{
  std::vector<double> Kept;
  std::vector<double> Dropped;
  bool WasSorted = true;
};

SplitSelection SelectInside(const std::vector<double>& explicitSplits, double zNear, double zFar)
{
  SplitSelection selection;
  for (double s : explicitSplits)
  {
    (Finite(s) && s > zNear && s < zFar ? selection.Kept : selection.Dropped).push_back(s);
  }
  selection.WasSorted = std::is_sorted(selection.Kept.begin(), selection.Kept.end());
  std::sort(selection.Kept.begin(), selection.Kept.end());
  return selection;
}

// zNear, the sorted splits without those within a tolerance of the previous one
// (or of zFar), and zFar; `duplicates` counts the removed ones.
std::vector<double> WithoutDuplicates(
  const std::vector<double>& sorted, double zNear, double zFar, int& duplicates)
{
  const double tolerance = 1e-9 * (zFar - zNear);
  std::vector<double> splits{ zNear };
  duplicates = 0;
  for (double s : sorted)
  {
    if (s - splits.back() <= tolerance)
    {
      ++duplicates;
      continue;
    }
    splits.push_back(s);
  }
  // The last interior split may sit within the tolerance of zFar.
  if (splits.size() > 1 && zFar - splits.back() <= tolerance)
  {
    splits.pop_back();
    ++duplicates;
  }
  splits.push_back(zFar);
  return splits;
}

// What was repaired, for the warning; empty when nothing was.
std::string RepairReport(const SplitSelection& selection, int duplicates, double zNear,
  double zFar, std::size_t cascades)
{
  std::ostringstream report;
  report.precision(17);
  if (!selection.Dropped.empty())
  {
    report << "ignored " << selection.Dropped.size()
           << " split distance(s) not strictly inside the depth range (" << zNear << ", " << zFar
           << "):";
    for (double s : selection.Dropped)
    {
      report << ' ' << s;
    }
    report << ". ";
  }
  if (!selection.WasSorted)
  {
    report << "split distances were not in increasing order and have been sorted. ";
  }
  if (duplicates > 0)
  {
    report << "removed " << duplicates << " duplicate split distance(s). ";
  }
  std::string text = report.str();
  if (text.empty())
  {
    return text;
  }
  text.pop_back(); // trailing space
  return text + " Using " + std::to_string(cascades) + " cascade(s).";
}
} // namespace

std::vector<double> SanitizeSplits(
  const std::vector<double>& explicitSplits, double zNear, double zFar, std::string* problem)
{
  const double givenNear = zNear;
  const double givenFar = zFar;
  if (RepairRange(zNear, zFar))
  {
    if (problem)
    {
      std::ostringstream report;
      report.precision(17);
      report << "the depth range [" << givenNear << ", " << givenFar
             << "] is not a valid range; using [" << zNear << ", " << zFar
             << "] as a single cascade.";
      *problem = report.str();
    }
    return { zNear, zFar };
  }
  const SplitSelection selection = SelectInside(explicitSplits, zNear, zFar);
  int duplicates = 0;
  std::vector<double> splits = WithoutDuplicates(selection.Kept, zNear, zFar, duplicates);
  if (problem)
  {
    *problem = RepairReport(selection, duplicates, zNear, zFar, splits.size() - 1);
  }
  return splits;
}

glm::dvec2 TightDepthRange(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const std::vector<Aabb>& props, double margin)
{
  const glm::dvec2 planes = ProjectionDepthRange(cameraProjection);
  const glm::dvec2 visible = VisibleDepthRange(cameraView, cameraProjection, props);
  if (!(visible.y > visible.x))
  {
    return planes;
  }
  return { std::max(planes.x, (1.0 - margin) * visible.x), std::min(planes.y, (1.0 + margin) * visible.y) };
}

glm::dvec2 QuantizedDepthRange(const glm::dvec2& range, int stepsPerOctave)
{
  if (stepsPerOctave < 1 || !(range.y > range.x) || !Finite(range.x) || !Finite(range.y) ||
    !(range.y > 0.0))
  {
    return range;
  }
  const double steps = double(stepsPerOctave);
  const auto level = [steps](double d) { return std::log2(d) * steps; };
  const auto depth = [steps](double k) { return std::exp2(k / steps); };
  // The small tolerance keeps a range that sits exactly on a level there.
  const double nearLevel = std::floor(level(range.x) + 1e-9);
  const double farLevel = std::ceil(level(range.y) - 1e-9);
  const glm::dvec2 quantized(range.x > 0.0 ? depth(nearLevel) : range.x, depth(farLevel));
  return Finite(quantized.x) && Finite(quantized.y) && quantized.y > quantized.x ? quantized : range;
}

glm::dmat4 SubFrustumProjection(
  const glm::dmat4& cameraProjection, double nearDistance, double farDistance)
{
  glm::dmat4 p = cameraProjection;
  const bool usable = IsFinite(cameraProjection) &&
    (cameraProjection[2][3] != 0.0 || cameraProjection[3][3] != 0.0);
  if (!usable)
  {
    p = glm::dmat4(1.0); // parallel, unit square
  }
  const double c = p[2][3];
  const double d = p[3][3];
  RepairRange(nearDistance, farDistance);
  if (c != 0.0 && nearDistance <= 0.0)
  {
    // A perspective frustum ends at the eye: its near plane must be in front of it.
    nearDistance = std::max(TinyDepth, 1e-9 * std::abs(farDistance));
    RepairRange(nearDistance, farDistance);
  }
  const double n = nearDistance;
  const double f = farDistance;
  // Solve (A z + B) / (c z + d) = -1 at z = -n and +1 at z = -f:
  //   -A n + B = c n - d,   -A f + B = d - c f.
  const double a = (c * (n + f) - 2.0 * d) / (f - n);
  const double b = c * n - d + a * n;
  p[0][2] = 0.0;
  p[1][2] = 0.0;
  p[2][2] = a;
  p[3][2] = b;
  return p;
}

namespace
{
// FrustumCorners of a projection; false if the projection, its inverse or a
// corner is not finite.
bool FiniteFrustumCorners(const glm::dmat4& projection, std::array<glm::dvec3, 8>& corners)
{
  if (!IsFinite(projection) || !IsFinite(glm::inverse(projection)))
  {
    return false;
  }
  corners = FrustumCorners(projection);
  return std::all_of(corners.begin(), corners.end(),
    [](const glm::dvec3& p) { return Finite(p.x + p.y + p.z); });
}

// The t of the smallest sphere centred on a + t e around the points: the
// squared distance to point i is E t^2 + beta_i t + gamma_i, so the largest of
// them is smallest at one parabola's vertex or where two parabolas cross (or at
// a few fixed t for a degenerate axis).
double SmallestEnclosingT(
  const std::array<glm::dvec3, 8>& points, const glm::dvec3& a, const glm::dvec3& e)
{
  const double curvature = glm::dot(e, e);
  std::array<double, 8> beta, gamma;
  for (int i = 0; i < 8; ++i)
  {
    beta[i] = 2.0 * glm::dot(e, a - points[i]);
    gamma[i] = glm::dot(a - points[i], a - points[i]);
  }
  auto squaredRadius = [&](double t) {
    double worst = 0.0;
    for (int i = 0; i < 8; ++i)
    {
      worst = std::max(worst, curvature * t * t + beta[i] * t + gamma[i]);
    }
    return worst;
  };
  std::vector<double> candidates{ 0.0, 0.5, 1.0 };
  if (curvature > 0.0)
  {
    for (int i = 0; i < 8; ++i)
    {
      candidates.push_back(-beta[i] / (2.0 * curvature));
      for (int j = i + 1; j < 8; ++j)
      {
        if (beta[i] != beta[j])
        {
          candidates.push_back((gamma[j] - gamma[i]) / (beta[i] - beta[j]));
        }
      }
    }
  }
  double bestT = 0.0;
  double best = Infinity;
  for (double t : candidates)
  {
    if (!Finite(t))
    {
      continue;
    }
    const double value = squaredRadius(t);
    if (value < best)
    {
      best = value;
      bestT = t;
    }
  }
  return bestT;
}
} // namespace

BoundingSphere CascadeBoundingSphere(const glm::dmat4& subProjection)
{
  const BoundingSphere fallback{ glm::dvec3(0.0), 1.0 };
  std::array<glm::dvec3, 8> corners;
  if (!FiniteFrustumCorners(subProjection, corners))
  {
    return fallback;
  }
  // The centre lies on the frustum's axis, from the near face's centre a to the far face's.
  glm::dvec3 nearCentre(0.0), farCentre(0.0);
  for (int i = 0; i < 8; ++i)
  {
    ((i & 4) ? farCentre : nearCentre) += 0.25 * corners[i];
  }
  const glm::dvec3 e = farCentre - nearCentre;
  BoundingSphere sphere;
  sphere.Center = nearCentre + SmallestEnclosingT(corners, nearCentre, e) * e;
  // Recompute from the chosen centre so rounding in the parabola form cannot shrink it.
  double radius = 0.0;
  for (const auto& p : corners)
  {
    radius = std::max(radius, glm::length(p - sphere.Center));
  }
  sphere.Radius = radius;
  if (!(radius > 0.0) || !Finite(radius))
  {
    return fallback;
  }
  return sphere;
}

LightView FitCascadeTight(const glm::dmat4& cameraView, const glm::dmat4& subProjection,
  const Aabb& scene, const glm::dvec3& lightDirection, int resolution)
{
  return FitDirectional(subProjection * cameraView, scene, lightDirection, resolution);
}

LightView FitCascadeStable(const glm::dmat4& cameraView, const glm::dmat4& subProjection,
  const Aabb& scene, const glm::dvec3& lightDirection, int resolution)
{
  const double texels = double(std::max(resolution, 1));
  const BoundingSphere sphere = CascadeBoundingSphere(subProjection);

  // Sphere centre in the world.
  glm::dmat4 viewToWorld(1.0);
  if (IsFinite(cameraView))
  {
    const glm::dmat4 inverse = glm::inverse(cameraView);
    if (IsFinite(inverse))
    {
      viewToWorld = inverse;
    }
  }
  glm::dvec3 centre = ProjectPoint(viewToWorld, sphere.Center);
  if (!Finite(centre.x + centre.y + centre.z))
  {
    centre = glm::dvec3(0.0);
  }

  LightView fit;
  fit.View = LightLookAt(glm::dvec3(0.0), SafeDirection(lightDirection));
  fit.Perspective = false;

  // Map size: depends on the projection only.
  const double margin = std::min(4.0, texels / 4.0);
  const double step = StableCentreStep(resolution);
  const double half =
    RoundRadiusUp(sphere.Radius) * texels / (texels - 2.0 * margin - (step - 1.0));
  // As the projection's scale gives it back (1 / (1 / half) may differ from half).
  const double texel = 2.0 / (1.0 / half) / texels;

  // Snap the centre to steps of whole texels of the world-fixed light grid.
  const glm::dvec3 c = ProjectPoint(fit.View, centre);
  const double cell = step * texel;
  const double cx = std::floor(c.x / cell + 0.5) * cell;
  const double cy = std::floor(c.y / cell + 0.5) * cell;

  // Depth: the scene inside the map's side planes, bounded behind by the sphere.
  const double sphereNear = -SnapUp(c.z + half, half / 8.0);
  const double sphereFar = SnapUp(-c.z + half, half / 8.0);
  double zNear = sphereNear;
  double zFar = sphereFar;
  if (!scene.IsEmpty())
  {
    const glm::dvec2 depth = ComputeNearAndFar(
      fit.View, glm::dvec2(cx - half, cy - half), glm::dvec2(cx + half, cy + half), scene);
    if (depth.y > depth.x)
    {
      zNear = depth.x;
      zFar = std::min(depth.y, sphereFar);
      if (!(zFar > zNear))
      {
        zFar = depth.y;
      }
    }
  }
  const double range = std::max(zFar - zNear, half * 1e-6);
  zNear -= range * 1e-3;
  zFar = zNear + range * 1.002;
  if (!Finite(zNear) || !Finite(zFar) || !(zFar > zNear))
  {
    zNear = -1.0;
    zFar = 1.0;
  }
  fit.Projection = CenteredOrtho(cx, cy, half, zNear, zFar);
  fit.TexelConstant = texel;
  return fit;
}

double BlendBandStart(const std::vector<double>& splits, int index, double blendFraction)
{
  const double fraction = std::min(std::max(blendFraction, 0.0), 1.0);
  return splits[index + 1] - fraction * (splits[index + 1] - splits[index]);
}

glm::dvec2 CascadeDepthRange(const std::vector<double>& splits, int index, double blendFraction)
{
  const int m = int(splits.size()) - 1;
  if (index < 0 || index >= m)
  {
    return { 0.0, 0.0 };
  }
  double zNear = splits[index];
  if (index > 0 && Finite(blendFraction))
  {
    zNear = BlendBandStart(splits, index - 1, blendFraction);
  }
  return { zNear, splits[index + 1] };
}

} // namespace shadowmaps
