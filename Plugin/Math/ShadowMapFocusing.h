// Focusing math for shadow maps: plain C++ and GLM, no VTK state.
//
// Every function here is pure. Each one builds one explicit quantity (a body of
// points, a depth range, a view or projection matrix); the passes compose them.
// All matrices follow OpenGL conventions: right-handed view space looking down
// -z, clip space z in [-1, 1]. Double precision throughout so that scenes from
// 1e-4 to 1e5 units keep their texel grids.
#ifndef ShadowMapFocusing_h
#define ShadowMapFocusing_h

#include <array>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

namespace shadowmaps
{

/// Axis-aligned box. Default-constructed boxes are empty.
struct Aabb
{
  glm::dvec3 Min{ 1.0, 1.0, 1.0 };
  glm::dvec3 Max{ -1.0, -1.0, -1.0 };

  bool IsEmpty() const;
  /// Not empty, and of finite size: a box fits can use.
  bool IsUsable() const;
  void Add(const glm::dvec3& p);
  void Add(const Aabb& other);
  glm::dvec3 Center() const;
  double Diagonal() const;
  std::array<glm::dvec3, 8> Corners() const;
  static Aabb FromBounds(const double bounds[6]);
};

/// A plane n.p + d = 0; points with n.p + d >= 0 are inside.
struct Plane
{
  glm::dvec3 Normal{ 0.0, 0.0, 1.0 };
  double Offset = 0.0;
  double Distance(const glm::dvec3& p) const { return glm::dot(this->Normal, p) + this->Offset; }
};

/// m applied to the point p, divided by w.
glm::dvec3 ProjectPoint(const glm::dmat4& m, const glm::dvec3& p);

/// direction normalised; (0, 0, -1) when it has no finite, non-zero length.
glm::dvec3 SafeDirection(const glm::dvec3& direction);

/// The eight corners of the frustum whose clip transform is viewProjection
/// (inverse-projected NDC cube corners).
std::array<glm::dvec3, 8> FrustumCorners(const glm::dmat4& viewProjection);

/// The six inward planes of the frustum whose clip transform is viewProjection.
std::array<Plane, 6> FrustumPlanes(const glm::dmat4& viewProjection);

/// The six inward planes of a box.
std::array<Plane, 6> BoxPlanes(const Aabb& box);

/// Vertices of the convex polytope where every plane holds (n.p + d >= 0), by
/// solving each triple of planes and keeping the points inside all of them
/// (within 1e-9 scale, scale being the polytope's size). The set must be bounded
/// (include a box, say); points on an edge shared by more than three planes may
/// repeat. Empty when the planes have no common point.
std::vector<glm::dvec3> ConvexPolytopeVertices(const std::vector<Plane>& planes, double scale);

/// Vertices of the focus body of a spot light: camera frustum ∩ scene box ∩ the
/// spot's frustum (lightViewProjection). Empty when they do not meet.
std::vector<glm::dvec3> SpotFocusBody(
  const glm::dmat4& cameraViewProjection, const Aabb& scene, const glm::dmat4& lightViewProjection);

/// Points taken through a projection and divided by w; empty if any has w <= 0
/// (behind a light) or there are none.
std::vector<glm::dvec3> ProjectAheadOfTheLight(
  const std::vector<glm::dvec3>& points, const glm::dmat4& lightViewProjection);

/// Vertices of the convex body frustum ∩ box: frustum corners inside the box,
/// box corners inside the frustum, and the crossings of each body's edges with
/// the other's faces. Empty when they do not meet. With the scene bounds as box
/// this is the focus body B of the survey (§4.1). Extending B toward the light
/// moves points along light rays, which changes no light-space x/y: the fits
/// below cover the extension through ComputeNearAndFar alone.
std::vector<glm::dvec3> IntersectFrustumWithBox(const glm::dmat4& viewProjection, const Aabb& box);

/// Range {nearest, farthest} of view depths (distance along -z of cameraView) at
/// which any of the boxes is inside the camera frustum: each box is clipped to the
/// frustum on its own, so the empty space between boxes does not count (a camera
/// inside the scene's bounds still sees its nearest object some way off).
/// {0, 0} when no box is in view.
glm::dvec2 VisibleDepthRange(
  const glm::dmat4& cameraView, const glm::dmat4& cameraProjection, const std::vector<Aabb>& boxes);

/// Right-handed look-at view for a light looking along direction from eye.
/// The up vector is chosen stably (world z unless nearly parallel, then world y).
glm::dmat4 LightLookAt(const glm::dvec3& eye, const glm::dvec3& direction);

/// Depth range along -z of lightView covered by the box clipped to the light
/// frustum's side planes x in [xyMin.x, xyMax.x], y in [xyMin.y, xyMax.y] (the
/// Microsoft text's ComputeNearAndFar). Returns {near, far} as positive
/// distances in front of the light; {0, 0} if nothing of the box lies inside.
glm::dvec2 ComputeNearAndFar(
  const glm::dmat4& lightView, const glm::dvec2& xyMin, const glm::dvec2& xyMax, const Aabb& box);

/// One rendered view of a light: the matrices a shadow map is rendered with.
struct LightView
{
  glm::dmat4 View{ 1.0 };
  glm::dmat4 Projection{ 1.0 };
  bool Perspective = false;
  /// World-space size of one texel: Constant + PerUnitDistance * distance to the light.
  double TexelConstant = 0.0;
  double TexelPerUnitDistance = 0.0;
  /// Warped maps: texels vary too much across the map for the formula above;
  /// receivers take the texel size from the map's local derivative instead.
  bool TexelSizeFromGradient = false;
  /// Depth linear in light space (TSM): the stored depth is Z / W times W_p, where
  /// W_p = 1 / dot(NdcToInverseW(*this), (x_ndc, y_ndc, 1)) is the projection's W
  /// recovered from the map position (the projection's X, Y, W must not depend on
  /// light-space z). For an affine View that is clip Z itself, affine in the world;
  /// for a spot's TSM (View through the spot's own projection) it is the spot's
  /// post-perspective depth.
  bool LinearDepth = false;
  /// No receiver in view can be shaded from this map (a cube face the camera
  /// does not see into): it is cleared, and no caster is drawn into it.
  bool OutOfView = false;
  /// The camera view depths (along -z) of the receivers this map shades: a
  /// cascade's slice; every depth for other maps. Casters whose shadows cannot
  /// reach that part of the view are not drawn (ShadowMapCasterReach.h).
  glm::dvec2 ShadedDepths{ 0.0, std::numeric_limits<double>::infinity() };
  glm::dmat4 ViewProjection() const { return this->Projection * this->View; }
};

/// 0 at x <= low, 1 at x >= high, Hermite's 3 t^2 - 2 t^3 between: the fades
/// that take a warp continuously to the uniform map.
double SmoothStep(double low, double high, double x);

/// The world-space edge of the coarsest texel of the map `viewProjection` at
/// `p`, across the light: (2 / resolution) / sigma_min of the Jacobian of the
/// map's NDC x, y with respect to world moves along u and v (orthonormal,
/// perpendicular to the light's ray through p), by central differences of
/// `step`. 0 where it is not finite. The one texel-size estimator of the warped
/// fits (LiSPSM/GMNPR, TSM, PSM).
double TexelAcrossLight(const glm::dmat4& viewProjection, const glm::dvec3& p, const glm::dvec3& u,
  const glm::dvec3& v, double step, int resolution);

/// An angle as a whole number of quarter turns (the nearest) and what remains:
/// angle = Turns * pi / 2 + Residual, |Residual| <= pi / 4. A map turned by
/// quarter turns keeps its texel grid; the warps turn their maps toward the
/// nearest one as they fade in.
struct QuarterTurns
{
  long Turns = 0;
  double Residual = 0.0;
};
QuarterTurns NearestQuarterTurns(double angle);

/// The box with every zero-size axis given a small extent relative to the
/// largest one (or 1 if the box is a point), so that fits stay invertible.
Aabb NonDegenerate(const Aabb& box);

/// Focused uniform map for a directional light: an orthographic frustum fitted
/// to B in light space, its near plane pulled back to the nearest scene point
/// inside the light frustum's side planes. Falls back to the whole scene when B
/// is empty (camera looking away from the scene). `stable`: the window grows
/// outward to a grid (SnapWindowOutward over twice the scene's diagonal) and
/// B's far depth to a 64th of the diagonal, so that a small camera move leaves
/// the fit, and the map rendered with it, unchanged.
LightView FitDirectional(const glm::dmat4& cameraViewProjection, const Aabb& scene,
  const glm::dvec3& lightDirection, int resolution, bool stable = false);

/// The window [lo, hi] grown outward to the grid of span / 2^k with the largest
/// k that keeps a cell at most a sixteenth of the window's width (k >= 4): the
/// window moves only when what it covers crosses a grid line, and loses at most
/// two cells, an eighth of its width, of texel density.
void SnapWindowOutward(glm::dvec2& lo, glm::dvec2& hi, double span);

/// `value` rounded up to a multiple of `cell` (unchanged for cell <= 0).
double SnapUp(double value, double cell);

/// Spot light: the cone's square frustum (full angle 2 * coneAngleDegrees),
/// cropped to B's projection; near/far from the scene inside the cone.
/// `stable` as for FitSpotToBody.
LightView FitSpot(const glm::dmat4& cameraViewProjection, const Aabb& scene,
  const glm::dvec3& position, const glm::dvec3& direction, double coneAngleDegrees,
  int resolution, bool stable = false);

/// A spot light's own post-perspective space, where its rays are parallel to +z
/// and a directional warp can be built (003; 000 for point lights).
struct SpotSpace
{
  /// FitSpot's cone map: takes the world into the space.
  LightView Cone;
  /// The focus body B = camera frustum ∩ scene ∩ cone, in the world.
  std::vector<glm::dvec3> WorldBody;
  /// B in the space; empty when B is empty or reaches behind the light.
  std::vector<glm::dvec3> Body;
  glm::dmat4 ToSpace() const { return this->Cone.ViewProjection(); }
};

/// The focus body of `cone` (a FitSpot map) in the world and in its space.
SpotSpace FocusInSpotSpace(
  const glm::dmat4& cameraViewProjection, const Aabb& scene, const LightView& cone);

/// A map `fit` made inside the spot's space, as a map of the world. Its W is a
/// plane over the map there, so the depth it stores is the spot's own
/// post-perspective depth, linear in that space (LinearDepth); texels vary
/// over it as a warp's do (TexelSizeFromGradient) and grow with the distance
/// to the light as the cone's. The cone itself when the result is not finite.
LightView FromSpotSpace(LightView fit, const LightView& cone);

/// FitSpot's fit for given body points (B's vertices; the cone when the body is
/// empty or reaches behind the light); scene as is (FitSpot inflates it).
/// `stable`: the crop grows outward to a grid (SnapCropOutward) and the far
/// plane to the next eighth of an octave, so that a small change of the body
/// (a camera move) leaves the fit, and the map rendered with it, unchanged.
LightView FitSpotToBody(const std::vector<glm::dvec3>& body, const Aabb& scene,
  const glm::dvec3& position, const glm::dvec3& direction, double coneAngleDegrees, int resolution,
  bool stable = false);

/// The crop [lo, hi] of a cone of half-width t snapped as SnapWindowOutward over
/// the cone's width 2t, and kept inside the cone.
void SnapCropOutward(glm::dvec2& lo, glm::dvec2& hi, double t);

/// FitSpot's cone map cropped to the lit part of B = camera frustum ∩ scene ∩ the
/// cone (FitSpotToBody); the cone map itself when that part is empty. litBody,
/// when given, receives its vertices (empty with the cone map). `stable` as for
/// FitSpotToBody.
LightView FitSpotToLitBody(const glm::dmat4& cameraViewProjection, const Aabb& scene,
  const glm::dvec3& position, const glm::dvec3& direction, double coneAngleDegrees,
  int resolution, std::vector<glm::dvec3>* litBody = nullptr, bool stable = false);

/// How a map is laid out as tiles, row by row from its window's lower left:
/// tile (column, row) holds the core [column, column + 1] / Columns x [row,
/// row + 1] / Rows of the whole map's texture coordinates, and its window is
/// that core plus a margin of its neighbours' texels along its sides, where
/// filter kernels reach.
struct TileGrid
{
  int Columns = 1;
  int Rows = 1;
  /// A tile's window over the whole map's, per axis.
  glm::dvec2 WindowFraction{ 1.0 };

  /// Centre of tile (column, row) in the whole map's NDC.
  glm::dvec2 Center(int column, int row) const;
};

/// Columns x rows tiles of `resolution` texels whose cores cover a map, with
/// marginTexels of margin. Counts below 1 are taken as 1; the margin is clamped
/// to [0, resolution / 4].
TileGrid MakeTileGrid(int columns, int rows, int resolution, double marginTexels);

/// The map of `whole` as the grid's tiles: together the map of `whole` at
/// columns x rows times the tiles' resolution, in pieces that fit a texture
/// array's layers. The tiles' texel sizes are scaled to their share of the window.
std::vector<LightView> TileView(const LightView& whole, const TileGrid& grid);

/// Point light: six 90 degree faces in the order +x, -x, +y, -y, +z, -z, each
/// with near/far covering the scene.
std::array<LightView, 6> FitCubeFaces(const Aabb& scene, const glm::dvec3& position, int resolution);

/// FitCubeFaces with each face cropped, like a stable FitSpotToBody, to the part of it a
/// receiver in view can need: camera frustum ∩ scene ∩ the face's frustum. Faces
/// that part misses keep FitCubeFaces' fit and are marked OutOfView; all faces
/// keep it, unmarked, when the scene is empty or the camera matrix is not finite.
std::array<LightView, 6> FitCubeFacesToView(const glm::dmat4& cameraViewProjection,
  const Aabb& scene, const glm::dvec3& position, int resolution);

/// The part of the whole image a renderer draws while its window renders one
/// tile of it (vtkWindowToImageFilter with a scale, tiled displays): the window's
/// tile viewport and the renderer's viewport (xmin, ymin, xmax, ymax, fractions
/// of the window) give it in the renderer's normalized device coordinates,
/// (-1, -1, 1, 1) when the window renders the whole. Empty tiles give that too.
glm::dvec4 TileOfWholeImage(const glm::dvec4& tileViewport, const glm::dvec4& rendererViewport);

/// The projection of the whole image of which `tileProjection` draws `tile`
/// (TileOfWholeImage): the tile's projection maps that part of the whole's
/// normalized device coordinates onto [-1, 1]. Fits follow the whole image, so
/// that its tiles show the same shadows and share their maps.
glm::dmat4 WholeImageProjection(const glm::dmat4& tileProjection, const glm::dvec4& tile);

/// {near, far} depths (positive along -z) of a projection's near (clip z = -1) and far
/// (clip z = +1) planes. Works for perspective and parallel projections, off-axis
/// included, whose clip w row is (0, 0, c, d). {0, 0} if the planes are undefined.
glm::dvec2 ProjectionDepthRange(const glm::dmat4& projection);

/// Whether 16-bit normalized depth is precise enough for a view: its depth
/// step (where it is coarsest: anywhere for an orthographic view, at the far
/// plane for a perspective one) is at most 1/stepsPerTexel of the world size
/// of a texel there (16 by default), so the bias that covers a texel covers the
/// rounding too. False for warped and linear-depth views and for projections of
/// no other form.
bool SixteenBitDepthSuffices(const LightView& view, double stepsPerTexel = 16.0);

/// Maps clip space [-1, 1]^3 to texture space [0, 1]^3.
glm::dmat4 ClipToTexture();

/// True when every element of m is finite.
bool IsFinite(const glm::dmat4& m);
bool IsFiniteVector(const glm::dvec3& v);

} // namespace shadowmaps

#endif
