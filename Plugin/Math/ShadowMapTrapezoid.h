// Trapezoidal shadow maps (Martin & Tan, EGSR 2004 [MT04]) for directional
// lights: plain C++ and GLM, pure functions.
//
// Construction as described in the thesis (literature/000, section "Trapéz
// shadow map-ek"): in light space the focus body B (survey, literature/003
// §4.1) is projected onto the light's image plane, its 2D convex hull is
// enclosed by a trapezoid whose top and base are perpendicular to the
// projected view axis (the centre line), and the trapezoid is mapped onto the
// square by N_T = T1 R T2 H S1 N T3 S2. The side edges meet in the vanishing
// point q, placed so that the point at distance delta from the near plane maps
// to the 80% line of the map.
//
// Depth stays linear in light space (thesis: "z is not transformed, it stays in
// light space"): TrapezoidToSquare acts on light-space x, y only, and depth is
// the affine DepthRow.
#ifndef ShadowMapTrapezoid_h
#define ShadowMapTrapezoid_h

#include "ShadowMapFocusing.h"

#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace shadowmaps
{

/// A trapezoidal shadow map for a directional light.
///
/// Texture space: u across the centre line, v along it; v = 0 on the top edge
/// (nearest the camera's near plane), v = 1 on the base edge. The focus point
/// maps to v = FocusLine (0.8 with the paper's 80% rule when fully warped).
struct TrapezoidMap
{
  /// World -> light space: orthographic view looking along the light (-z).
  glm::dmat4 LightView{ 1.0 };
  /// N_T: homogeneous light-space (x, y, 1) -> homogeneous NDC (X, Y, W),
  /// X/W and Y/W in [-1, 1] over the trapezoid; W >= 1 on the trapezoid.
  glm::dmat3 TrapezoidToSquare{ 1.0 };
  /// Linear light-space depth range: distances along the light direction.
  double DepthNear = 0.0;
  double DepthFar = 1.0;
  /// Trapezoid corners in light-space xy, in the order that maps to NDC
  /// (-1,-1), (1,-1), (1,1), (-1,1): top edge first, then base edge.
  std::array<glm::dvec2, 4> Corners{};
  /// 2D convex hull (counter-clockwise) of B projected on the light's plane.
  std::vector<glm::dvec2> Hull;
  /// The focus point P_L (on the centre line, delta from the near plane) in light xy.
  glm::dvec2 FocusPoint{ 0.0 };
  /// Texture v that the focus point maps to.
  double FocusLine = 0.8;
  /// 1: paper's warp; 0: degenerate trapezoid = rectangle = uniform map.
  /// A smoothstep of the angle between the view and light lines (FitTrapezoid).
  double WarpWeight = 1.0;
  /// Distance from the top edge to q along the centre line (eta); infinite for a rectangle.
  double VanishingDistance = 0.0;
  /// Counter-clockwise quarter turns (0..3) of the texture square after N_T, which
  /// keep the map's orientation continuous (FitTrapezoid). Corners, FocusLine and
  /// TrapezoidToNdc are before the turn; MapToTexture and TrapezoidLightView after it.
  int QuarterTurns = 0;
};

/// 2D convex hull, counter-clockwise, without collinear points (monotone chain).
std::vector<glm::dvec2> ConvexHull2D(std::vector<glm::dvec2> points);

/// Builds the trapezoid map for a directional light.
///
/// focusDistance is delta of [MT04]: distance from the camera's near plane
/// along the view axis whose shadows must be sharp; focusFraction is the share
/// of the map given to it (0.8 = the 80% line). The warp fades out continuously
/// (FocusLine -> the unwarped position, q -> infinity) as the light turns
/// within fadeAngleDegrees of the view axis (a smoothstep of the angle, the
/// rectangle itself within 2 degrees), so that light along or against the
/// view gives the uniform, focused rectangle (thesis: TSM degrades to a
/// standard map there). Parallel-projection cameras work the same way.
///
/// Orientation: the centre line reverses where the light crosses the view axis,
/// so the rectangle the warp fades into is oriented by the camera's up instead
/// (projected on the light's plane). Inside the fade band the trapezoid's frame
/// turns from the centre line toward the nearest quarter turn of that up, and the
/// square is turned back by those quarter turns (QuarterTurns), which keeps every
/// texel on the same world-space grid. Fixed points thus move continuously as the
/// light passes through the view axis.
TrapezoidMap FitTrapezoid(const glm::dmat4& cameraViewProjection, const Aabb& scene,
  const glm::dvec3& lightDirection, double focusDistance, double focusFraction = 0.8,
  double fadeAngleDegrees = 15.0);

/// What a trapezoid is built from, in a space where the light is directional: the
/// world for a directional light (FitTrapezoid), a spot light's post-perspective
/// space for a spot (FitSpotTrapezoid).
struct TrapezoidFrame
{
  /// Vertices of the focus body B (empty: the corners of Casters), and a box
  /// holding every caster.
  std::vector<glm::dvec3> Body;
  Aabb Casters;
  /// Unit direction the light travels.
  glm::dvec3 LightDirection{ 0.0, 0.0, -1.0 };
  /// The camera's axis: where it enters B's depth range (the near-plane centre),
  /// its unit direction, the camera's up there, and the focus point delta
  /// beyond the near plane on it [MT04].
  glm::dvec3 NearCentre{ 0.0 };
  glm::dvec3 ViewAxis{ 0.0, 0.0, -1.0 };
  glm::dvec3 CameraUp{ 0.0, 1.0, 0.0 };
  glm::dvec3 Focus{ 0.0 };
  /// Angle (radians) between the view and light lines that sets the warp weight;
  /// negative: measured in this space. A spot measures it in the world, where it
  /// changes as fast as the light turns; its post-perspective space magnifies it.
  double Gamma = -1.0;
};

/// The trapezoid of FitTrapezoid for any frame.
TrapezoidMap FitTrapezoidFrame(
  const TrapezoidFrame& frame, double focusFraction = 0.8, double fadeAngleDegrees = 15.0);

/// Trapezoidal map of a spot light. The spot's cone map S = FitSpot(...) takes the
/// world to its post-perspective space, where light rays run along +z; B = camera
/// frustum ∩ scene ∩ the spot's frustum, the camera's axis over B's depth range and
/// the focus point (focusDistance beyond B's nearest depth, <= 0: a fifth of B's
/// depth range) are mapped there and the trapezoid is built as for a directional
/// light (FitTrapezoidFrame). Result: View = trapezoid light view * S, not rigid;
/// LinearDepth: the stored depth is the spot's own post-perspective depth, not
/// warped by the trapezoid; TexelSizeFromGradient is set. Falls back to
/// the cone map S when B is empty or the camera's axis leaves the spot's side.
LightView FitSpotTrapezoid(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const Aabb& scene, const glm::dvec3& position, const glm::dvec3& direction,
  double coneAngleDegrees, int resolution, double focusDistance = 0.0, double focusFraction = 0.8);

/// Light-space xy -> NDC xy of the trapezoid map (projective division by W).
glm::dvec2 TrapezoidToNdc(const TrapezoidMap& map, const glm::dvec2& lightXY);

/// World point -> (u, v, linear depth), each in [0, 1] for points of B.
glm::dvec3 MapToTexture(const TrapezoidMap& map, const glm::dvec3& world);

/// World -> linear depth in [0, 1]: depth = dot(DepthRow(map), (world, 1)).
glm::dvec4 DepthRow(const TrapezoidMap& map);

/// A LightView whose ViewProjection() gives clip (X, Y, Z, W) with X/W, Y/W the
/// trapezoid mapping. Z = (linear NDC depth) is affine, so Z/W is depth divided
/// by W: monotone along each light ray (W depends on x, y only) and inside the
/// clip volume (|Z| <= 1 <= W), so hardware depth testing orders casters
/// correctly, but Z/W is NOT the linear depth. LinearDepth is set: casters
/// write Z itself to gl_FragDepth, W recovered with NdcToInverseW (thesis:
/// multiply z back by w in the pixel shader); receivers compare against
/// MapToTexture's z. Texel sizes: the largest world-space texel
/// edge over the trapezoid (TexelConstant), for bias.
LightView TrapezoidLightView(const TrapezoidMap& map, int resolution);

/// For a LinearDepth view: the row r with 1 / W = dot(r, (x_ndc, y_ndc, 1)), which
/// lets a caster's fragment shader turn its window depth Z / W back into the
/// linear Z (the thesis's "multiply z back by w"). (0, 0, 1) for views whose W is 1
/// and for singular projections.
glm::dvec3 NdcToInverseW(const LightView& view);

/// NdcToInverseW over texture coordinates (u, v, 1) instead of NDC, for
/// receivers of linear-depth views; zero for the other views.
glm::dvec3 TextureToInverseW(const LightView& view);

} // namespace shadowmaps

#endif
