// Per-frame state shared by vtkAbstractShadowMapPass and its subclasses.
#ifndef vtkShadowMapInternals_h
#define vtkShadowMapInternals_h

#include "ShadowMapFocusing.h"
#include "ShadowMapTextureArray.h"
#include "vtkAbstractShadowMapPass.h"

#include <string>
#include <vector>

#include <glm/glm.hpp>

class vtkLight;
class vtkProp;

namespace shadowmaps
{
enum class LightKind
{
  Directional,
  Spot,
  Point
};

/// A light that casts shadows this frame.
struct ShadowLight
{
  vtkLight* Light = nullptr;
  /// Index of the light in the mappers' generated lighting code (lightColor<i>).
  int ShaderIndex = 0;
  LightKind Kind = LightKind::Directional;
  /// Cube lights have six views, looked up by direction.
  bool Cube = false;
  glm::dvec3 Position{ 0.0 };
  /// From the light toward what it lights.
  glm::dvec3 Direction{ 0.0, 0.0, -1.0 };
  double ConeAngle = 90.0;
  float Attenuation = 1.0f;
  int FirstLayer = 0;
  std::vector<LightView> Views;
  /// Cascaded lights: Views are depth partitions of the camera frustum, picked
  /// per receiver by view depth (or map coverage) and blended at their splits.
  bool Cascaded = false;
  /// Tiled lights: Views are the tiles of one map, laid out by Tiles and picked
  /// per receiver by where it falls in that map; they fade out like cascades.
  bool Tiled = false;
  TileGrid Tiles;
  /// Per cascade: {first view depth it shades, its far split, start of its blend band}.
  std::vector<glm::dvec3> CascadeDepths;
  /// View depths over which the shadows fade out; no fade unless y > x.
  glm::dvec2 Fade{ 0.0, 0.0 };
  /// Cascades picked by map coverage instead of view depth: the finest map that
  /// holds the receiver, blended into the next over this outer fraction of the
  /// map's half-width. Negative: picked by depth.
  double CoverageBlendFraction = -1.0;

  /// The pass's settings may give this light warped views (texel sizes from
  /// the map's gradient) or linear-depth views. Set from the settings, not from
  /// this frame's fit, so that a fit turning uniform as the camera moves does
  /// not rebuild the receivers' shaders.
  bool MayWarp = false;
  bool MayStoreLinearDepth = false;

  /// Shader code of how the views cover receivers (vtkShadowMapsReceiverFS).
  int ViewKind() const { return this->Tiled ? 3 : this->Cascaded ? 2 : this->Cube ? 1 : 0; }

  /// Receiver code the views may need: bits vtkShadowGradientTexels (1),
  /// vtkShadowDistantTexels (2) and vtkShadowLinearDepths (4) of vtkShadowMapsReceiverFS.
  int ReceiverFeatures() const
  {
    bool gradient = this->MayWarp;
    bool distant = this->Kind != LightKind::Directional;
    bool linear = this->MayStoreLinearDepth;
    for (const LightView& view : this->Views)
    {
      gradient = gradient || view.TexelSizeFromGradient;
      distant = distant || view.TexelPerUnitDistance != 0.0;
      linear = linear || view.LinearDepth;
    }
    return (gradient ? 1 : 0) | (distant ? 2 : 0) | (linear ? 4 : 0);
  }
};

/// What a texel of a pass's maps holds and how the casters write it.
struct MapStorage
{
  TexelFormat Format = TexelFormat::Depth;
  /// TwoFloats: GLSL statements that read `float vtkShadowCasterDepth` (the
  /// fragment's window depth; gl_FrontFacing is available too) and write
  /// gl_FragData[0].xy. Ignored for depth storage.
  std::string StoreCode;
  /// TwoFloats: each channel keeps the minimum over all fragments of a texel
  /// (blending with GL_MIN, no depth test), e.g. nearest front and back faces.
  /// Otherwise the nearest fragment's values are kept (depth test).
  bool MinimumBlending = false;
  /// TwoFloats: values of a texel no caster covers.
  float ClearValues[2] = { 1.0f, 1.0f };
  /// TwoFloats: build a mipmap chain after rendering (filterable storage).
  bool Mipmaps = false;
};

/// A prop that renders into the maps, with its world bounds.
struct Caster
{
  vtkProp* Prop = nullptr;
  Aabb Bounds;
};
} // namespace shadowmaps

struct vtkAbstractShadowMapPass::Internals
{
  // The frame being rendered.
  glm::dmat4 CameraView{ 1.0 };
  glm::dmat4 CameraProjection{ 1.0 };
  shadowmaps::Aabb SceneBounds;
  /// Bounds of every visible prop (SceneBounds is their union).
  std::vector<shadowmaps::Aabb> PropBounds;
  std::vector<shadowmaps::ShadowLight> Lights;
  std::vector<shadowmaps::Caster> Casters;
  int Resolution = 0;

  glm::dmat4 CameraViewProjection() const { return this->CameraProjection * this->CameraView; }
};

#endif
