// Perspective warping of directional-light shadow maps: LiSPSM and GMNPR.
// Plain C++17 and GLM (double precision), no VTK state; every function is pure.
//
// Sources (docs/REFERENCES.md):
//  - 003 (survey, Scherzer/Wimmer/Purgathofer): LiSPSM light space, the warp frustum P
//    of free near distance n between z_n (PSM) and infinity (uniform), n_opt, the
//    1/sin(gamma) falloff and Lloyd's remark on it; error dp/ds = (1/z)(dz/ds)(cos a/cos b).
//  - 000 (thesis): light space axes (y along the view direction), n_opt = z_n + sqrt(z_f z_n),
//    n growing to infinity when the camera looks along or against the light.
//  - 002 (Zhang, Sun, Zhao, Wang, GMNPR): aliasing F(lambda, theta, z) (Eq. 2), the
//    minimum-norm lambda (Eq. 8) and LiSPSM's lambda (Eq. 9); lambda = P_n / (P_f - P_n).
//
// Conventions as in ShadowMapFocusing.h: OpenGL clip space, z in [-1, 1].
#ifndef ShadowMapWarping_h
#define ShadowMapWarping_h

#include "ShadowMapFocusing.h"

#include <vector>

#include <glm/glm.hpp>

namespace shadowmaps
{

/// Which reparameterization a directional light's map uses.
enum class DirectionalWarp
{
  Uniform, ///< FitDirectional: focused orthographic map.
  LiSPSM,  ///< Wimmer et al.: n = n_opt / sin(gamma) (003, 000).
  GMNPR    ///< Zhang et al.: n = lambda_GMNPR(theta) * (P_f - P_n) (002, Eq. 8).
};

/// Tuning of the warped fits.
struct WarpOptions
{
  /// Near distance n of the warp frustum in world units; <= 0 selects the automatic
  /// value of the chosen warp. An explicit n is still faded out near gamma = 0.
  double FreeParameterN = 0.0;
  /// LiSPSM only: fall off faster than 1/sin(gamma) once gamma < phi (see
  /// LiSPSMFreeParameter).
  bool LloydFalloff = false;
  /// LiSPSM and GMNPR: the view depth z_n their n is chosen from is taken no nearer
  /// than this fraction of B's far depth z_f (a pseudo near plane, 003 section 4.2.2
  /// after Lloyd). A camera whose near plane sits a hair in front of it, inside the
  /// bounds of what it sees, would otherwise spend the map on the empty space there.
  /// The default was measured (docs/WARPS.md); 0 takes z_n as it is.
  double PseudoNearFraction = 0.003;
  /// Below this angle (degrees) between view and light lines the map is uniform;
  /// between it and FullWarpAboveDegrees the warp strength (P_f - P_n) / n is
  /// multiplied by a smoothstep, so every mode reaches the uniform map continuously.
  /// Clamped to [0, 89]; FullWarpAboveDegrees is clamped to [UniformBelowDegrees, 90].
  double UniformBelowDegrees = 2.0;
  double FullWarpAboveDegrees = 12.0;
};

/// Angle between the lines of the view and light directions, folded into [0, pi/2]
/// (002 considers only 0 <= theta <= pi/2 by symmetry). 0 for degenerate input.
double ViewLightAngle(const glm::dvec3& viewDirection, const glm::dvec3& lightDirection);

/// LiSPSM near distance of the warp frustum (003, 000): n_opt = z_n + sqrt(z_f z_n),
/// divided by sin(gamma) (the original falloff n'_opt = n_opt / sin gamma, 003).
/// With lloyd, below gamma = phi (where a view-frustum face becomes parallel to the
/// light, the point past which 003 says 1/sin(gamma) is too slow) an extra factor
/// sin(phi)/sin(gamma) is applied: n = n_opt sin(phi) / sin^2(gamma). This is our own
/// choice satisfying that requirement continuously; Lloyd's exact formula (his thesis
/// 5.1.2) is not in the literature set. Returns +infinity at gamma = 0.
double LiSPSMFreeParameter(double zNear, double zFar, double gammaRadians, double phiRadians, bool lloyd);

/// The view depth LiSPSM and GMNPR take as z_n: zNear, or `fraction` (clamped to
/// [0, 1]) of zFar where that is farther (WarpOptions::PseudoNearFraction).
double PseudoNear(double zNear, double zFar, double fraction);

/// GMNPR lambda (002, Eq. 8): theta in [phi, pi/2]:
///   lambda_1 = (n + sqrt(f n) - n tan(phi)/tan(theta)) / (f - n + (f + n) tan(phi)/tan(theta));
/// theta in [0, phi):  lambda_2* = sqrt(f n) / (2 f) / tan(theta pi / (4 phi))  (Eq. 7).
/// Both equal sqrt(f n)/(2 f) at theta = phi (Eq. 5); +infinity at theta = 0 (Eq. 6).
/// theta is folded into [0, pi/2]; n, f are the view near and far distances.
double GMNPRLambda(double theta, double phi, double n, double f);

/// LiSPSM's lambda (002, Eq. 9): P_n / (P_f - P_n) with P_n = (n + sqrt(f n)) / sin(theta)
/// and P_f - P_n the extent of the view frustum along the warp axis (WarpDepthOfFrustum).
double LiSPSMLambda(double theta, double phi, double n, double f);

/// Extent P_f - P_n of the view frustum (near n, far f, half angle phi in the plane of
/// view and light) along the warp axis, the denominators of 002 Eq. 9:
/// theta >= phi: (f - n + (f + n) tan(phi)/tan(theta)) sin(theta); else 2 f tan(phi) cos(theta).
double WarpDepthOfFrustum(double theta, double phi, double n, double f);

/// Aliasing of 002 Eq. 2 for a warp of parameter lambda: F = psi (z + varphi)^2 / z,
/// with psi and varphi from the two branches of Eq. 2. For tests and plots.
double GMNPRAliasing(double lambda, double theta, double phi, double n, double f, double z);

/// 002 normalizes the warp frustum's depth range: lambda = P_n / (P_f - P_n). These
/// convert between lambda and the near distance P_n for a given depth range P_f - P_n.
double WarpNearFromLambda(double lambda, double warpDepth);
double LambdaFromWarpNear(double warpNear, double warpDepth);

/// Smooth weight in [0, 1] that the warp strength is multiplied by: 0 below
/// options.UniformBelowDegrees, 1 above options.FullWarpAboveDegrees, smoothstep between.
double WarpFade(double gammaRadians, const WarpOptions& options);

/// What a warp needs, in a space where the light is directional: the world for a
/// directional light, a spot light's post-perspective space for a spot (FitSpotWarped).
struct WarpFrame
{
  /// Vertices of the focus body B, and a box holding every caster, in this space.
  std::vector<glm::dvec3> Body;
  Aabb Casters;
  /// Unit direction the light travels, and the camera's axis, a point on it and
  /// its up direction, in this space.
  glm::dvec3 LightDirection{ 0.0, 0.0, -1.0 };
  glm::dvec3 ViewDirection{ 0.0, 0.0, -1.0 };
  glm::dvec3 Eye{ 0.0 };
  glm::dvec3 CameraUp{ 0.0, 1.0, 0.0 };
  /// Measured in the world: the angle between the view and light lines at B, the
  /// view-depth range [ZNear, ZFar] of B, the camera's half angle Phi in the plane
  /// of view and light, and B's extent along the warp axis (0: this space is the
  /// world, extents need no conversion). The warp's near distance n is chosen in
  /// world units and carried over keeping its ratio to B's warp-axis extent.
  double Gamma = 0.0;
  double ZNear = 0.0;
  double ZFar = 0.0;
  double Phi = 0.0;
  double WarpDepthInWorld = 0.0;
};

/// The warped fit of FitDirectionalWarped for any frame: light space, the warp
/// frustum of near distance n from LiSPSM / GMNPR / options, the orthographic fit of
/// the warped B, in the frame's space. False (fit unchanged) when no finite fit exists.
bool FitWarpedFrame(const WarpFrame& frame, int resolution, DirectionalWarp warp,
  const WarpOptions& options, LightView& fit);

/// Warped (or uniform) map of a directional light, focused on B = camera frustum ∩ scene.
/// Light space: view axis along lightDirection, warp axis = view direction projected
/// perpendicular to the light (000, 003). A perspective warp along that axis, apex at
/// distance n before B's near side (n from LiSPSM / GMNPR / options.FreeParameterN),
/// is followed by an orthographic fit of the warped B into [-1, 1]^3. Casters between
/// B and the light stay inside: the depth range reaches the nearest scene point over
/// B's light-space footprint (ComputeNearAndFar).
///
/// Degenerate directions: the warp strength (P_f - P_n) / n is multiplied by WarpFade,
/// so n -> infinity continuously as gamma -> 0 (or pi); the warp is written so that
/// strength 0 is exactly the orthographic fit. The map's in-plane orientation is the
/// camera's up projected perpendicular to the light where the warp is faded out (it
/// does not flip where the warp axis reverses) and the nearest quarter turn of the warp
/// axis where the warp is full (a quarter turn keeps the texel grid in world space),
/// blended by the fade. Known limit: inside the fade band, a light crossing the
/// azimuth where the warp axis is at 45 degrees to the camera's up turns the map by
/// 90 * min(fade, 1 - fade) degrees at once.
///
/// Result: ViewProjection() maps B and its casters into clip [-1, 1]^3 with w > 0.
/// Perspective = true when a warp is applied (strength > 0). TexelConstant = the
/// largest world-space texel edge over B's vertices (at the far end of the warp, the
/// coarsest part of the map), TexelPerUnitDistance = 0: a directional light has no
/// position to measure a distance from. This is conservative and, for strong warps,
/// much larger than the texels near the viewer.
///
/// Falls back to FitDirectional for DirectionalWarp::Uniform, parallel-projection
/// cameras, an empty scene or B, and non-finite input.
LightView FitDirectionalWarped(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& scene, const glm::dvec3& lightDirection, int resolution, DirectionalWarp warp,
  const WarpOptions& options = WarpOptions());

/// Warped map of a spot light (003 and 000 for point lights: the light's own
/// perspective makes it directional, the warp is then built in that space). The
/// spot's cone map S = FitSpot(...) takes the world to its post-perspective space,
/// where light rays are parallel to +z; B = camera frustum ∩ scene ∩ the spot's
/// frustum is mapped there and warped as a directional light's (FitWarpedFrame),
/// with gamma, z_n, z_f and phi measured in the world at B (gamma between the view
/// direction and the spot's ray to B's centroid). Result: View = light view * S,
/// not rigid; TexelSizeFromGradient is set. Falls back to the cone map S for
/// DirectionalWarp::Uniform, parallel cameras, B empty or a fit that fails.
LightView FitSpotWarped(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& scene, const glm::dvec3& position, const glm::dvec3& direction,
  double coneAngleDegrees, int resolution, DirectionalWarp warp,
  const WarpOptions& options = WarpOptions());

} // namespace shadowmaps

#endif
