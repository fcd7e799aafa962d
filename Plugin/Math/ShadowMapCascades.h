// Cascaded shadow maps (z-partitioning, PSSM, CSM) for directional lights.
// Plain C++17 and GLM (double precision), no VTK state; every function is pure.
//
// Sources (docs/REFERENCES.md):
//  - 003 (survey, Scherzer/Wimmer/Purgathofer) §4.3.1 z-partitioning: the view frustum
//    is cut along its depth into m sub-frusta with one equally sized map each; the
//    logarithmic split C_i = z_n (z_f/z_n)^(i/m), the uniform split
//    C_i = z_n + (z_f - z_n) i/m, and the practical blend of the two; stable fitting
//    (a map of constant size in a fixed orientation, moved in whole texels; here in
//    steps of a thirty-second of the map, so that a moving camera keeps it longer).
//  - 004 (Microsoft, "Common techniques to improve shadow depth maps"): near/far from
//    the scene box clipped to the light frustum's side planes (ComputeNearAndFar),
//    which keeps casters outside a cascade's sub-frustum in its map; moving the light
//    in texel-sized increments to stop shimmering; a bound of the view frustum that
//    does not change with the camera's orientation.
//
// Conventions as in ShadowMapFocusing.h: right-handed view space looking down -z,
// OpenGL clip space (z in [-1, 1]). "Depth" and "distance" of a camera point mean its
// view-space depth -z_view (positive in front of the camera), not the Euclidean
// distance to the eye; split distances are depths in this sense.
#ifndef ShadowMapCascades_h
#define ShadowMapCascades_h

#include "ShadowMapFocusing.h"

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shadowmaps
{

/// Practical split scheme (003 §4.3.1, PSSM): returns cascades + 1 depths
///   C_i = lambda * z_n (z_f/z_n)^(i/m) + (1 - lambda) * (z_n + (z_f - z_n) i/m),
/// with C_0 = zNear and C_m = zFar exactly. lambda = 1 is the logarithmic scheme,
/// lambda = 0 the uniform one. The caller is expected to pass sanitized input
/// (0 < zNear < zFar, cascades >= 1, lambda in [0, 1]); the function nevertheless never
/// returns NaN and always returns a non-decreasing list: cascades < 1 is taken as 1,
/// lambda is clamped to [0, 1], non-finite bounds are replaced (zNear by 0, zFar by
/// zNear + 1), zFar <= zNear is replaced by the smallest range above zNear, and when
/// zNear <= 0 (a parallel camera may have that) the logarithmic term uses
/// max(1e-3 zFar, tiny) instead of zNear as its start.
std::vector<double> PracticalSplits(double zNear, double zFar, int cascades, double lambda);

/// Turns user-given split depths into a valid split list.
/// explicitSplits are the INTERIOR boundaries only (m - 1 values for m cascades); the
/// result is the full list {zNear, sorted interior values, zFar}, strictly increasing.
/// Values that are not finite or not strictly inside (zNear, zFar) (negatives
/// included) are dropped, the rest sorted, and values closer than
/// 1e-9 (zFar - zNear) to the previous kept one are dropped as duplicates. When
/// anything was changed, *problem (if given) receives a human-readable sentence
/// saying what and why; otherwise it is cleared. If zNear/zFar themselves are not a
/// valid range (non-finite or zFar <= zNear) they are repaired as in PracticalSplits,
/// the result is {zNear, zFar'} and that is reported too.
std::vector<double> SanitizeSplits(
  const std::vector<double>& explicitSplits, double zNear, double zFar, std::string* problem);

/// The camera's depth range {near, far} tightened to the visible props: the
/// projection's planes (ProjectionDepthRange) clamped to VisibleDepthRange widened
/// by `margin` (a fraction) on both sides. The projection's planes when no prop is
/// visible. May be empty (far <= near) for degenerate projections.
glm::dvec2 TightDepthRange(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const std::vector<Aabb>& props, double margin = 0.0);

/// A depth range widened to the nearest levels of the geometric grid
/// 2^(k / stepsPerOctave): near rounded down, far rounded up. Stable cascades split
/// this range instead of the visible one, so that the splits (and with them each
/// cascade's sphere and texel size) stay put while the camera moves, and change
/// only when the visible range crosses a level. Ranges with near <= 0 keep their
/// near; invalid ranges and stepsPerOctave < 1 are returned unchanged.
glm::dvec2 QuantizedDepthRange(const glm::dvec2& range, int stepsPerOctave);

/// The same projection (perspective or parallel, possibly off-axis) with its near and
/// far planes moved to the depths nearDistance and farDistance (positive along -z).
/// Only the clip z row changes: x, y and w are those of cameraProjection, so the
/// sub-frustum has exactly the camera's side planes. Requires a clip w row of the form
/// (0, 0, c, d) (true of every OpenGL/VTK camera projection). Degenerate distances are
/// repaired so the result is always finite and invertible: for a perspective
/// projection nearDistance is raised to a tiny positive value, and farDistance is
/// raised to nearDistance + max(1e-6 |nearDistance|, 1e-9) when not beyond it.
/// A non-finite cameraProjection yields glm::ortho(-1, 1, -1, 1, near, far).
glm::dmat4 SubFrustumProjection(
  const glm::dmat4& cameraProjection, double nearDistance, double farDistance);

/// A sphere; CascadeBoundingSphere returns it in the camera's VIEW space.
struct BoundingSphere
{
  glm::dvec3 Center{ 0.0 };
  double Radius = 0.0;
};

/// The smallest sphere containing the 8 corners of the frustum of subProjection whose
/// centre lies on the line through the centres of the frustum's near and far faces
/// (the view axis for a symmetric frustum), in view space. It is a function of the
/// projection alone, so its radius does not change when the camera moves or turns.
/// Exact: the squared distances to the corners along that line are parabolas of equal
/// curvature, so the minimum of their maximum is at one parabola's vertex or at the
/// crossing of two; all candidates are tried. Degenerate (non-invertible or
/// non-finite) projections give the unit sphere at the origin.
BoundingSphere CascadeBoundingSphere(const glm::dmat4& subProjection);

/// Focused fit of one cascade: the map fitted to sub-frustum ∩ scene (003 §4.1 focusing
/// applied per partition). Delegates to FitDirectional with
/// subProjection * cameraView. Tightest texels, but the map changes size and position
/// continuously as the camera moves (shimmering edges).
LightView FitCascadeTight(const glm::dmat4& cameraView, const glm::dmat4& subProjection,
  const Aabb& scene, const glm::dvec3& lightDirection, int resolution);

/// Stable fit of one cascade (003 stable fitting, 004 texel-sized increments):
///  - bound: CascadeBoundingSphere(subProjection), radius r rounded UP to the next
///    multiple of 2^(floor(log2 r) - 4) (1/16 to 1/32 of r) so that small changes of the
///    split depths or field of view leave the map size unchanged;
///  - orientation fixed in the world: View = LightLookAt(world origin, lightDirection),
///    a pure rotation that depends on the light direction only;
///  - the sphere centre's light-space x, y are rounded to steps of s whole texels,
///    s = max(1, floor(N / 32)), N the resolution, so the world texel grid is the same
///    for every camera position and orientation, and a camera move changes the map
///    (and re-renders it) only once the sphere has crossed a thirty-second of it;
///  - orthographic x/y half-extent h = r' N / (N - 2 m - (s - 1)), m = 4 texels of
///    margin (at most N / 4): the sphere, half a step of snapping and m - 1/2 texels
///    for filter kernels always lie inside the map. Texel size 2 h / N.
///  - depth: near from ComputeNearAndFar of the scene box clipped to the map's side
///    planes (casters between the sub-frustum and the light stay in the map), far =
///    min(scene far, far side of the sphere rounded up to an eighth of h); the
///    sphere's depth range, rounded out to eighths of h, if the scene is empty or
///    misses the map.
///    TexelConstant = 2 h / N.
/// Always returns finite, invertible matrices (empty scene, zero light direction,
/// degenerate projections fall back to unit extents).
LightView FitCascadeStable(const glm::dmat4& cameraView, const glm::dmat4& subProjection,
  const Aabb& scene, const glm::dvec3& lightDirection, int resolution);

/// View depth where cascade index's blend band into cascade index + 1 starts: the
/// last blendFraction (clamped to [0, 1]) of its depth range
/// [splits[index], splits[index + 1]]. index + 1 must be a valid split.
double BlendBandStart(const std::vector<double>& splits, int index, double blendFraction);

/// Depth range {near, far} that cascade index's map must cover so that both its own
/// receivers and the blend band of the previous cascade (where it is sampled too, see
/// vtkShadowBlendIntoNext) are inside: near = start of cascade index - 1's blend band
/// (splits[index] for index 0 or blendFraction 0), far = splits[index + 1]. Pass it to
/// SubFrustumProjection. {0, 0} for an invalid index.
glm::dvec2 CascadeDepthRange(const std::vector<double>& splits, int index, double blendFraction);

} // namespace shadowmaps

#endif
