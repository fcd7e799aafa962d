// An exact shadow-visibility oracle, the ground truth of the shadow-map
// benchmarks: Embree 3 traces one primary ray through every pixel centre of a
// VTK view and, per light, one occlusion ray from each visible surface point.
//
// Typical use, after the window has rendered the view once (the render sets
// camera-light transforms and fills the z-buffer):
//
//   shadoworacle::Oracle oracle;
//   std::string error;
//   if (!oracle.Build(renderer, error)) { ... }
//   int* size = renderer->GetSize();
//   auto surface = oracle.Trace(renderer, size[0], size[1]);
//   shadoworacle::Oracle::MaskRasterMismatch(surface, renderer, zbuffer);
//   auto truth = oracle.Classify(surface, light);
#ifndef ShadowOracle_h
#define ShadowOracle_h

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

class vtkLight;
class vtkRenderer;

namespace shadoworacle
{

/// One sample per pixel; row 0 is the bottom row (VTK's pixel order) and the
/// index of pixel (x, y) is y * Width + x.
struct Surface
{
  int Width = 0, Height = 0;
  std::vector<unsigned char> Valid;  ///< 1: a primary ray hit geometry and it was kept
  std::vector<glm::dvec3> Position;  ///< world-space hit point
  std::vector<glm::dvec3> Normal;    ///< unit geometric normal, flipped to face the camera
  std::vector<double> ViewDepth;     ///< distance along the camera's view direction
  /// 1 where a translucent caster lies between the camera and the hit (a
  /// render blends its colour in there); empty when nobody traced them.
  std::vector<unsigned char> SeenThroughTranslucent;
};

/// Oracle::Visibility of a pixel it does not count.
constexpr float NotCounted = -1.0f;

/// How Oracle::Visibility sampled its lights.
struct VisibilityRays
{
  /// Pixels counted, and those sampled with the full set of rays.
  long long Counted = 0;
  long long Refined = 0;
  /// Rays traced in all.
  long long Rays = 0;
  /// The fewest rays behind a visibility strictly between 0 and 1 (0: none).
  int FewestAtPartial = 0;
};

enum class Truth : unsigned char
{
  Ignored = 0,
  Lit = 1,
  Shadowed = 2
};

/**
 * What a translucent surface of `color` and `opacity` (a, clamped to [0, 1])
 * lets through of the light that crosses it, per channel c:
 * (1 - a) (1 - a + a c). A white surface lets 1 - a through, what VTK's
 * blending shows of what lies behind it; a coloured one also filters that
 * light toward its colour in proportion to its opacity; an opaque one (a = 1)
 * lets nothing through. Crossings multiply, so their order does not matter.
 * The passes' transmittance layers use the same model (docs/TRANSLUCENT.md).
 */
glm::dvec3 SurfaceTransmittance(const glm::dvec3& color, double opacity);

/**
 * The triangles of a renderer's shadow casters in Embree BVHs: one of the
 * opaque casters, one of the translucent ones.
 *
 * Geometry is triangulated exactly as VTK 9.1's OpenGL mapper does (polygons
 * as fans from their first point, strips with alternating winding), in single
 * precision like the rasteriser; rays and hit points are computed in double.
 *
 * Movable, not copyable. Tracing and classification run on all cores, one row
 * at a time; every pixel is computed independently, so results do not depend
 * on the number of threads.
 */
class Oracle
{
public:
  Oracle();
  ~Oracle();
  Oracle(Oracle&&) noexcept;
  Oracle& operator=(Oracle&&) noexcept;
  Oracle(const Oracle&) = delete;
  Oracle& operator=(const Oracle&) = delete;

  /**
   * Builds the BVHs from the renderer's visible vtkActors of non-zero opacity
   * that cast shadows (no vtkAbstractShadowMapPass::CASTS_SHADOWS() key in
   * their property keys, or a non-zero one), each placed by
   * actor->GetMatrix(). A caster is translucent where its colour's alpha is
   * below 1: the actor's opacity times a composite block's, times the alpha
   * of the mapper's scalar colours (lookup tables with alpha, direct RGBA
   * scalars); its colour is the mapped scalars' or else the block's or the
   * property's diffuse colour, per triangle corner (interpolated as vertex
   * colours; scalars interpolated before mapping and textures are not read,
   * a translucent texture with a warning). Opaque casters are the only
   * occluders of Classify, Visibility and CountOccluders, and the only
   * surfaces Trace sees; Transmittance also crosses the translucent ones,
   * and marches the visible, casting vtkVolumes of image data
   * (ShadowOracleVolumes.h: the same model in thin slices; others are
   * skipped with a warning).
   * Mappers: vtkPolyDataMapper (its input after Update), the composite
   * polydata mapper (every polydata leaf whose block is visible) and vtkGlyph3DMapper (the same glyphs built by
   * vtkGlyph3D; configurations vtkGlyph3D cannot reproduce are skipped with a
   * warning on std::cerr, as are other mappers and non-actor props).
   * Polygons and strips become triangles; lines and vertices are ignored.
   * Returns false with a one-line `error` when there are no opaque triangles
   * to trace or Embree fails; the previous BVHs are then gone.
   */
  bool Build(vtkRenderer* renderer, std::string& error);

  /**
   * One primary ray through each pixel centre of the renderer's active camera
   * (perspective or parallel) for a view of width x height pixels, which
   * should be the renderer's size in pixels (its viewport of the window). Rays
   * run from the near to the far clipping plane, so clipped geometry is not
   * seen, as in the rasteriser. They hit opaque casters only, and mark
   * SeenThroughTranslucent where a translucent one lies before the hit.
   */
  Surface Trace(vtkRenderer* renderer, int width, int height) const;

  /**
   * Marks invalid the pixels where the rasterised depth disagrees with the ray
   * hit: silhouettes, geometry the oracle skipped, background. `zbuffer` holds
   * window depths in [0, 1] as returned by vtkRenderWindow::GetZbufferData for
   * the renderer's pixels, in Surface order. A pixel is kept when the view
   * depths differ by at most relativeTolerance times the ray's view depth
   * (perspective) or times the clipping range's length (parallel projection,
   * where depth resolution is uniform). A z-buffer of the wrong size
   * invalidates every pixel, with a message on std::cerr.
   */
  static void MaskRasterMismatch(Surface& surface, vtkRenderer* renderer,
    const std::vector<float>& zbuffer, double relativeTolerance = 1e-3);

  /**
   * Per pixel: Ignored where the surface is not Valid, where N.L <=
   * minimumCosine (L: unit vector from the point to the light), or outside a
   * spot light's cone (positional light with a cone angle below 90 degrees,
   * VTK's convention); otherwise Lit or Shadowed by one occlusion ray from the
   * point, moved off the surface along its normal by GetSurfaceOffset(), to
   * the light: to infinity for directional lights, up to the light's position
   * for positional ones.
   *
   * The light is read through vtkLight::GetTransformedPosition and
   * GetTransformedFocalPoint, which are world coordinates for scene lights at
   * any time, and for camera lights and headlights only once a render of this
   * renderer has set the light's transform matrix (or moved it to the camera):
   * classify after rendering the view.
   */
  std::vector<Truth> Classify(
    const Surface& surface, vtkLight* light, double minimumCosine = 0.1) const;

  /**
   * Per pixel, the fraction of a sized light that reaches the surface point:
   * vtkAbstractShadowMapPass::GetLightSize, a sun's angular diameter or a
   * positional light's radius (a sphere). NotCounted where Classify ignores
   * the pixel (judged from the light's centre). Rays start off the surface as
   * Classify's and cover the light's cone of directions, stratified and
   * jittered, uniform over its solid angle (a sphere of uniform radiance is a
   * disc of uniform radiance from any point). A first pass traces
   * CoarseRays; pixels whose rays disagree, or within two pixels of one that
   * disagrees or whose rays agree otherwise, are traced again with
   * RefinedRays, so that
   * every visibility strictly between 0 and 1 comes from at least that many.
   * A light without a size gets one ray per pixel: 0 or 1, as Classify.
   * `rays` (when given) reports the counts.
   */
  std::vector<float> Visibility(const Surface& surface, vtkLight* light,
    double minimumCosine = 0.1, VisibilityRays* rays = nullptr) const;

  /**
   * Per pixel and channel, the fraction of the light's colour that reaches
   * the surface point through the opaque and translucent casters: each ray
   * carries 0 if an opaque caster blocks it, or else the product of
   * SurfaceTransmittance over the translucent surfaces it crosses and of
   * what the volumes it crosses let through (MarchedVolume). A sized
   * light's rays are Visibility's (refined where they disagree) and averaged;
   * a light without a size gets its centre ray. NotCounted in every channel
   * where Classify ignores the pixel. Without translucent casters and
   * volumes, each channel equals Visibility.
   */
  std::vector<glm::vec3> Transmittance(const Surface& surface, vtkLight* light,
    double minimumCosine = 0.1, VisibilityRays* rays = nullptr) const;

  /// Rays per pixel of Visibility's two passes (8 x 8 and 16 x 16 strata).
  static constexpr int CoarseRays = 64;
  static constexpr int RefinedRays = 256;

  /**
   * Per pixel, for the pixels `truth` (Classify's for the same surface and
   * light) marks Shadowed: how many distinct occluders (BVH geometries: one
   * per polydata leaf) the pixel's shadow ray meets, counted up to `most`;
   * 0 elsewhere. Where two or more are met, filtered maps that average the
   * occluders' depths may let light through (light bleeding).
   */
  std::vector<unsigned char> CountOccluders(const Surface& surface, vtkLight* light,
    const std::vector<Truth>& truth, int most = 2) const;

  /// Triangles of opaque casters (0 before a successful Build).
  std::size_t GetNumberOfTriangles() const;

  /// Triangles of translucent casters.
  std::size_t GetNumberOfTranslucentTriangles() const;

  /// Volumes Transmittance marches.
  std::size_t GetNumberOfVolumes() const;

  /// How far shadow rays start off the surface: 1e-5 of the scene's size
  /// (the larger of its bounding-box diagonal and its largest coordinate).
  double GetSurfaceOffset() const;

private:
  struct Impl;
  std::unique_ptr<Impl> Pimpl;

  // The built oracle if the surface and light can be sampled; null (after
  // a warning) otherwise.
  const Impl* SampleableImpl(const Surface& surface, vtkLight* light, double minimumCosine) const;
};

} // namespace shadoworacle

#endif
