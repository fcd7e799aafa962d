// What a views strategy (vtkShadowMapViews) receives and fills: the frame being
// rendered and one shadowed light with its views. Plain data, no VTK state.
#ifndef ShadowMapLight_h
#define ShadowMapLight_h

#include "ShadowMapFocusing.h"  // For Aabb, LightView, TileGrid
#include "ShadowMapLightDepth.h" // For LightDepth

#include <vector>

#include <glm/glm.hpp>

class vtkLight;

namespace shadowmaps
{
enum class LightKind
{
  Directional,
  Spot,
  Point
};

/// How a light's views cover the receivers; the receivers' shader picks a view
/// by it (vtkShadowSelectView). The values are emitted into the GLSL as the
/// VTK_SHADOW_LAYOUT_* defines (ReceiverShaderConstants).
enum class ViewLayout
{
  /// One view.
  Single = 0,
  /// Six 90 degree faces around the light, +x, -x, +y, -y, +z, -z, picked by
  /// the direction from the light.
  CubeFaces = 1,
  /// Depth partitions of the camera frustum, picked by view depth (or map
  /// coverage) and blended at their splits (ShadowLight::CascadeDepths).
  Cascades = 2,
  /// The tiles of one map (ShadowLight::Tiles), picked by where the receiver
  /// falls in that map.
  Tiles = 3,
  /// Kozlov's cube map in the camera's post-perspective space
  /// (ShadowMapPerspectiveCube.h): six faces, picked by the largest of their
  /// clip w times ShadowLight::FaceSelection.
  PerspectiveCube = 4
};

/// Receiver code a light's views may need, as bits. Code a light cannot need is
/// compiled out of its receivers (software rasterisers run both sides of every
/// branch). Emitted into the GLSL as the VTK_SHADOW_FEATURE_* defines.
enum ReceiverFeature : int
{
  /// Warped maps: the texel size comes from the map's local gradient.
  GradientTexels = 1,
  /// Positional lights: texels grow with the distance to the light.
  DistantTexels = 2,
  /// Maps that store depth linear in light space; 1 / W is recovered.
  LinearDepths = 4,
  /// Not a need but a promise of the views strategy: every view of the light is
  /// its first followed by a crop (ShadowMapCrop.h), as unwarped cascades and
  /// tiles are. Receivers then transform by the first view only.
  CroppedViews = 8,
  /// Cascades with a blend band: receivers in it look up two cascades.
  CascadeBlends = 16,
  /// A light with a size (ShadowLight::Size): contact-hardening soft shadows.
  SizedLight = 32
};

/// Cones wider than this (half angle, degrees) are rendered as six cube faces:
/// one perspective map that wide wastes most of its texels at the rim.
constexpr double WidestSingleMapCone = 60.0;

/// A light that casts shadows this frame.
struct ShadowLight
{
  vtkLight* Light = nullptr;
  /// Index of the light in the mappers' generated lighting code (lightColor<i>).
  int ShaderIndex = 0;
  LightKind Kind = LightKind::Directional;
  glm::dvec3 Position{ 0.0 };
  /// From the light toward what it lights.
  glm::dvec3 Direction{ 0.0, 0.0, -1.0 };
  double ConeAngle = 90.0;
  float Attenuation = 1.0f;
  /// vtkAbstractShadowMapPass::LIGHT_SIZE as validated by LightSizeOf: a
  /// sun's angular diameter in degrees, a positional light's radius; 0: a
  /// point source. The pass zeroes it where its representation has no soft
  /// shadows.
  double Size = 0.0;
  /// The first map layer of the light's views (set by the pass).
  int FirstLayer = 0;

  ViewLayout Layout = ViewLayout::Single;
  std::vector<LightView> Views;
  /// Tiles layout: how the views tile one map.
  TileGrid Tiles;
  /// Cascades layout, per cascade: {first view depth it shades, its far split,
  /// start of its blend band into the next (NoBlendBand: none)}.
  std::vector<glm::dvec3> CascadeDepths;
  /// Cascades layout: picked by map coverage instead of view depth, the finest
  /// map that holds the receiver, blended into the next over this outer
  /// fraction of the map's half-width. Negative: picked by depth.
  double CoverageBlendFraction = -1.0;
  /// The light depth over the scene (set by the pass for every light): what
  /// representations that store MapStorage::LightDepth store.
  LightDepth Depth;
  /// PerspectiveCube layout, per view: PerspectiveCube::Selection.
  std::vector<double> FaceSelection;
  /// View depths over which the shadows fade out; no fade unless y > x.
  glm::dvec2 Fade{ 0.0, 0.0 };
  /// ReceiverFeature bits the views strategy's settings may produce for this
  /// light, whatever this frame's fit: a fit turning uniform as the camera
  /// moves must not rebuild the receivers' shaders.
  int PossibleFeatures = 0;
  /// Set by the pass before the fit: the views the light's maps were last
  /// rendered with, when only the camera has changed since (the same light,
  /// scene bounds, settings and resolution); empty otherwise. A strategy may
  /// give them again in interactive frames (ShadowFrame::Interactive).
  std::vector<LightView> LastViews;
  /// With LastViews, the FaceSelection they were rendered with.
  std::vector<double> LastFaceSelection;
};

/// Cascade blend-band start meaning "no band".
constexpr double NoBlendBand = 1e38;

/// True for the lights one perspective map cannot hold: point lights and spots
/// wider than WidestSingleMapCone. Every views strategy gives them cube faces.
inline bool NeedsCubeFaces(const ShadowLight& light)
{
  return light.Kind == LightKind::Point ||
    (light.Kind == LightKind::Spot && light.ConeAngle > WidestSingleMapCone);
}

/// The homogeneous point toward the light: (position, 1) for a positional
/// light, (-direction, 0) for a sun.
inline glm::dvec4 TowardLight(const ShadowLight& light)
{
  return light.Kind == LightKind::Directional ? glm::dvec4(-SafeDirection(light.Direction), 0.0)
                                              : glm::dvec4(light.Position, 1.0);
}

/// The ReceiverFeature bits the light's receivers are compiled with: the
/// possible ones and whatever this frame's views need.
inline int ReceiverFeatures(const ShadowLight& light)
{
  int features = light.PossibleFeatures | (light.Size > 0.0 ? SizedLight : 0);
  if (light.Kind != LightKind::Directional)
  {
    features |= DistantTexels;
  }
  for (const LightView& view : light.Views)
  {
    features |= (view.TexelSizeFromGradient ? GradientTexels : 0) |
      (view.TexelPerUnitDistance != 0.0 ? DistantTexels : 0) | (view.LinearDepth ? LinearDepths : 0);
  }
  if (light.Layout == ViewLayout::Cascades && light.Views.size() > 1)
  {
    for (const glm::dvec3& cascade : light.CascadeDepths)
    {
      features |= cascade.z < NoBlendBand ? CascadeBlends : 0;
    }
    features |= light.CoverageBlendFraction > 0.0 ? CascadeBlends : 0;
  }
  return features;
}

/// The light's first view's texel size over view `index`'s (1 but for
/// cascades): filters whose size is given in texels scale by it so that they
/// keep one world size in every cascade.
inline double FilterScale(const ShadowLight& light, std::size_t index)
{
  if (light.Layout != ViewLayout::Cascades || index >= light.CascadeDepths.size())
  {
    return 1.0;
  }
  // Cascades of one light share their texel formula's kind (constant for
  // directional, per unit distance for spot), so the sum compares them.
  const LightView& first = light.Views.front();
  const LightView& view = light.Views[index];
  const double firstTexel = first.TexelConstant + first.TexelPerUnitDistance;
  const double texel = view.TexelConstant + view.TexelPerUnitDistance;
  return firstTexel > 0.0 && texel > 0.0 ? firstTexel / texel : 1.0;
}

/// The frame a light's views are fitted for.
struct ShadowFrame
{
  glm::dmat4 CameraView{ 1.0 };
  glm::dmat4 CameraProjection{ 1.0 };
  /// Union of PropBounds.
  Aabb SceneBounds;
  /// Bounds of every visible prop.
  std::vector<Aabb> PropBounds;
  /// Map width and height in texels.
  int Resolution = 0;
  /// How far the representation's filter reaches from a receiver's texel, in
  /// texels (vtkShadowMapRepresentation::GetFilterReachTexels): tiles keep a
  /// border that wide.
  double FilterReachTexels = 1.0;
  /// The user is moving the camera (the render window's desired update rate
  /// is at least the pass's InteractiveUpdateRate): a strategy whose views
  /// follow the camera may keep a light's LastViews while they still serve,
  /// and re-render its maps only every few frames. Still frames fit anew.
  bool Interactive = false;
  /// A still render of a pass whose AnimationKeepsViews is on (a scripted
  /// camera path): it may keep views as interactive frames do, but draws full
  /// maps, which the still frames after it keep.
  bool StillKeepsViews = false;

  glm::dmat4 CameraViewProjection() const { return this->CameraProjection * this->CameraView; }
};
} // namespace shadowmaps

#endif
