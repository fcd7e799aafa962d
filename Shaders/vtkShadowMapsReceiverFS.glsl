// Shadow-map receiver functions, injected into a mapper's fragment shader after
// its lighting declarations (shadowmaps::ReceiverShader). Before this block
// come the constants shared with C++ (VTK_SHADOW_LAYOUT_*, VTK_SHADOW_FEATURE_*:
// shadowmaps::ReceiverShaderConstants), the representation's definitions and
//   VTK_SHADOW_MAX_VIEWS, VTK_SHADOW_MAX_LIGHTS  array sizes;
// after it the representation's lookup, which declares the sampler
// vtkShadowMaps and defines vtkShadowLookup (vtkShadowMapsDepthLookupFS for
// depth maps).

// Lookups that compare with their own surface (VTK_SHADOW_RECEIVER_PLANE) or
// filter over the receiver's footprint in the map (VTK_SHADOW_MAP_FOOTPRINT)
// take the position's screen derivatives where control flow is uniform.
#if defined(VTK_SHADOW_RECEIVER_PLANE) || defined(VTK_SHADOW_MAP_FOOTPRINT)
#define VTK_SHADOW_POSITION_DERIVATIVES
#endif

// A light's visibility: one value, or one per colour channel where translucent
// casters tint it (VTK_SHADOW_TRANSMITTANCE).
#ifdef VTK_SHADOW_TRANSMITTANCE
#define VTK_SHADOW_VALUE vec3
vec3 vtkShadowTransmittance(vec2 mapCoord, float lightDepth, int layer);
// False for receivers that take the opaque casters' shadows only (volumes,
// whose own absorption the maps hold at one depth per texel).
bool vtkShadowTransmittanceReceived = true;
#else
#define VTK_SHADOW_VALUE float
#endif

// Receivers are evaluated in the camera's view coordinates (VC).
uniform mat4 vtkShadowViewToWorld;

// One per map layer (shadowmaps::ReceiverUniforms).
struct vtkShadowView
{
  // Takes a VC point to map texture coordinates and depth.
  mat4 ViewToMap;
  // World-space size of one texel: x + y * (distance to the light); x < 0:
  // warped map, size from the map's local gradient (vtkShadowGradientTexel).
  vec2 TexelSize;
  // Views whose depth is linear in light space: 1 / W as a plane over texture
  // coordinates (u, v, 1); their casters store z / w times W. Zero for views
  // that store z / w.
  vec3 DepthInverseW;
  // How its layout picks the view. Cascades: x = first view depth (-z in VC)
  // it shades, y = its last (the next split), z = where the blend band into
  // the next cascade starts. Post-perspective cube faces: x = 1 / the light's
  // distance to the face's platform, 0 for a face toward the light
  // (shadowmaps::PerspectiveCube::Selection). Other views: (0, 1e38, 1e38).
  vec3 Selection;
  // Its light's first view's texel size over its own (1 but for cascades):
  // filter offsets in texels are multiplied by it so that a kernel keeps its
  // world size in every cascade.
  float FilterScale;
  // Lights with VTK_SHADOW_FEATURE_CROPPED_VIEWS: the view is its light's first
  // followed by this scale and offset of the map coordinates (shadowmaps::MapCrop).
  vec3 CropScale;
  vec3 CropOffset;
};
uniform vtkShadowView vtkShadowViews[VTK_SHADOW_MAX_VIEWS];

// One per shadowed light.
struct vtkShadowLight
{
  vec3 PositionVC;
  // How much of the light a shadow takes away.
  float Attenuation;
  // View depths over which shadows fade out (x >= y: no fade).
  vec2 Fade;
  // >= 0: cascades selected by map coverage instead of depth, and blended into
  // the next over this outer fraction of the map's half-width; < 0: by depth.
  float CoverageBand;
  // Tiles viewLayout (shadowmaps::TileGrid): columns, rows, and a tile's window
  // over the whole map's along x and y.
  vec4 TileGrid;
  // The light depth (shadowmaps::LightDepth) in VC: with r = p - DepthOrigin,
  // dot(DepthPlane.xyz, r) + DepthPlane.w + DepthPerDistance * |r|.
  vec4 DepthPlane;
  vec3 DepthOrigin;
  float DepthPerDistance;
  // Lights with a size (VTK_SHADOW_FEATURE_SIZED_LIGHT): (position, 1) or
  // (unit direction toward a sun, 0), and the size as the penumbra needs it:
  // a sun's tan(half its angular diameter), a positional light's radius.
  vec4 TowardLightVC;
  float Size;
};
uniform vtkShadowLight vtkShadowLights[VTK_SHADOW_MAX_LIGHTS];

uniform float vtkShadowMapResolution;
uniform float vtkShadowNormalOffset;

// Visibility in [0, 1] of the map point mapCoord (xy: texture coordinates,
// z: the receiver's depth in the map) in layer `layer`.
float vtkShadowLookup(vec3 mapCoord, int layer);

// Cube face order +x, -x, +y, -y, +z, -z (shadowmaps::ViewLayout::CubeFaces).
int vtkShadowCubeFace(vec3 d)
{
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z)
  {
    return d.x >= 0.0 ? 0 : 1;
  }
  if (a.y >= a.z)
  {
    return d.y >= 0.0 ? 2 : 3;
  }
  return d.z >= 0.0 ? 4 : 5;
}

// What a light's views may need of the receiver (shadowmaps::ReceiverFeature),
// a literal per light: code a light cannot need is compiled out, since
// software rasterisers run both sides of every branch.
bool vtkShadowHas(int features, int feature)
{
  return (features & feature) != 0;
}

// Cropped views (VTK_SHADOW_FEATURE_CROPPED_VIEWS) are their light's first
// view followed by this crop of `view`, applied to homogeneous map coordinates.
// They read the first view's matrix, indexed by a literal, and only the crop by
// the view that varies from fragment to fragment: software rasterisers gather
// per fragment whatever such a view indexes.
vec4 vtkShadowCrop(vec4 mapPoint, int view)
{
  return vec4(mapPoint.xyz * vtkShadowViews[view].CropScale +
      mapPoint.w * vtkShadowViews[view].CropOffset,
    mapPoint.w);
}

// The matrix of map `view` of a light whose views start at layer firstView.
mat4 vtkShadowMapMatrix(int firstView, int view, int features)
{
  if (!vtkShadowHas(features, VTK_SHADOW_FEATURE_CROPPED_VIEWS))
  {
    return vtkShadowViews[view].ViewToMap;
  }
  mat4 m = vtkShadowViews[firstView].ViewToMap;
  for (int column = 0; column < 4; ++column)
  {
    m[column] = vtkShadowCrop(m[column], view);
  }
  return m;
}

// The map's clip coordinates of a VC point: vtkShadowMapMatrix(...) * point,
// without building a cropped view's matrix.
vec4 vtkShadowMapTransform(int firstView, int view, vec3 positionVC, int features)
{
  if (!vtkShadowHas(features, VTK_SHADOW_FEATURE_CROPPED_VIEWS))
  {
    return vtkShadowViews[view].ViewToMap * vec4(positionVC, 1.0);
  }
  return vtkShadowCrop(vtkShadowViews[firstView].ViewToMap * vec4(positionVC, 1.0), view);
}

vec4 vtkShadowMapClip(vec3 positionVC, vec3 normalVC, int light, int firstView, int view,
  int viewLayout, int features);
bool vtkShadowInsideMap(vec4 clip, int view, int features);

// The cascade that shades the receiver: by view depth, or the first (finest)
// whose map contains it.
int vtkShadowSelectCascade(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int count, int features)
{
  if (vtkShadowLights[light].CoverageBand >= 0.0)
  {
    for (int i = 0; i < count - 1; ++i)
    {
      vec4 clip = vtkShadowMapClip(positionVC, normalVC, light, firstView, firstView + i,
        VTK_SHADOW_LAYOUT_CASCADES, features);
      if (vtkShadowInsideMap(clip, firstView + i, features))
      {
        return firstView + i;
      }
    }
    return firstView + count - 1;
  }
  float depth = -positionVC.z;
  for (int i = 0; i < count - 1; ++i)
  {
    if (depth < vtkShadowViews[firstView + i].Selection.y)
    {
      return firstView + i;
    }
  }
  return firstView + count - 1;
}

// The tile of one map (shadowmaps::TileGrid) whose core holds the receiver, from
// its place in the first tile: one map transform, whatever the tile count.
int vtkShadowSelectTile(vec3 positionVC, vec3 normalVC, int light, int firstView, int features)
{
  vec4 grid = vtkShadowLights[light].TileGrid;
  vec4 clip = vtkShadowMapClip(
    positionVC, normalVC, light, firstView, firstView, VTK_SHADOW_LAYOUT_TILES, features);
  if (clip.w <= 0.0)
  {
    return firstView; // behind the light: outside every tile, lit
  }
  // The maps' matrices give texture coordinates; the grid works in NDC.
  vec2 ndc = 2.0 * clip.xy / clip.w - 1.0;
  vec2 whole = ndc * grid.zw + (1.0 / grid.xy - 1.0);
  vec2 cell = clamp(floor((whole * 0.5 + 0.5) * grid.xy), vec2(0.0), grid.xy - 1.0);
  return firstView + int(cell.y * grid.x + cell.x);
}

// The face of a post-perspective cube that holds the receiver (Kozlov's
// displaced-centre lookup): the largest clip w times the face's Selection.x,
// from the faces' matrices' w rows.
int vtkShadowSelectPerspectiveFace(vec3 positionVC, int firstView)
{
  int face = firstView;
  float largest = 0.0;
  for (int i = 0; i < 6; ++i)
  {
    mat4 m = vtkShadowViews[firstView + i].ViewToMap;
    float w = m[0][3] * positionVC.x + m[1][3] * positionVC.y + m[2][3] * positionVC.z + m[3][3];
    float reach = w * vtkShadowViews[firstView + i].Selection.x;
    if (reach > largest)
    {
      largest = reach;
      face = firstView + i;
    }
  }
  return face;
}

// The view of light `light` that covers the receiver. The light's views start
// at layer firstView; a cube light has six of them, a cascaded or tiled light
// `count`.
int vtkShadowSelectView(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int viewLayout, int count, int features)
{
  if (viewLayout == VTK_SHADOW_LAYOUT_CASCADES)
  {
    return vtkShadowSelectCascade(positionVC, normalVC, light, firstView, count, features);
  }
  if (viewLayout == VTK_SHADOW_LAYOUT_TILES)
  {
    return vtkShadowSelectTile(positionVC, normalVC, light, firstView, features);
  }
  if (viewLayout == VTK_SHADOW_LAYOUT_PERSPECTIVE_CUBE)
  {
    return vtkShadowSelectPerspectiveFace(positionVC, firstView);
  }
  if (viewLayout != VTK_SHADOW_LAYOUT_CUBE_FACES)
  {
    return firstView;
  }
  // Cube faces are aligned with the world axes.
  vec3 fromLight = mat3(vtkShadowViewToWorld) * (positionVC - vtkShadowLights[light].PositionVC);
  return firstView + vtkShadowCubeFace(fromLight);
}

// Gradients at positionVC of the projective map coordinates t in {u, v}:
// grad t = (row_t - t row_w) / w.
void vtkShadowMapGradients(
  vec3 positionVC, int firstView, int view, int features, out vec3 gradU, out vec3 gradV)
{
  mat4 m = vtkShadowMapMatrix(firstView, view, features);
  vec4 q = m * vec4(positionVC, 1.0);
  vec3 rowW = vec3(m[0][3], m[1][3], m[2][3]);
  gradU = (vec3(m[0][0], m[1][0], m[2][0]) - (q.x / q.w) * rowW) / q.w;
  gradV = (vec3(m[0][1], m[1][1], m[2][1]) - (q.y / q.w) * rowW) / q.w;
}

// World (= VC) length of one texel at positionVC: along the map's coarser axis,
// 1 / (resolution * |grad t|), or (mean) the side of a square of the texel's
// area, 1 / (resolution * sqrt(|grad u| |grad v|)).
float vtkShadowGradientTexel(vec3 positionVC, int firstView, int view, int features, bool mean)
{
  vec3 gradU;
  vec3 gradV;
  vtkShadowMapGradients(positionVC, firstView, view, features, gradU, gradV);
  float rate = mean ? sqrt(length(gradU) * length(gradV)) : min(length(gradU), length(gradV));
  return 1.0 / (vtkShadowMapResolution * max(rate, 1e-20));
}

// World size of one texel of map `view` at the receiver.
float vtkShadowTexelWorldSize(vec3 positionVC, int light, int firstView, int view, int features)
{
  vec2 texelSize = vtkShadowViews[view].TexelSize;
  float texel = texelSize.x;
  if (vtkShadowHas(features, VTK_SHADOW_FEATURE_DISTANT_TEXELS))
  {
    texel += texelSize.y * length(positionVC - vtkShadowLights[light].PositionVC);
  }
  if (vtkShadowHas(features, VTK_SHADOW_FEATURE_GRADIENT_TEXELS) && texelSize.x < 0.0)
  {
    texel = vtkShadowGradientTexel(positionVC, firstView, view, features, false);
  }
  return texel;
}

// The receiver moved along its normal by the world-space size of a texel there
// (normal offset, Kozlov, GPU Gems 14), and its clip coordinates in map `view`.
// The offset also moves the receiver across the light. A post-perspective cube
// face's texels can be several times longer one way than the other (5.3 times
// under the bench's lamp-behind), and an offset of the coarser axis moved the
// lookup that many of the finer axis's texels, over shadow edges: those faces
// take the texel's mean size (docs/WARPS.md).
vec3 vtkShadowOffsetAlongNormal(vec3 positionVC, vec3 normalVC, int light, int firstView,
  int view, int viewLayout, int features)
{
  float texel = viewLayout == VTK_SHADOW_LAYOUT_PERSPECTIVE_CUBE
    ? vtkShadowGradientTexel(positionVC, firstView, view, features, true)
    : vtkShadowTexelWorldSize(positionVC, light, firstView, view, features);
  return positionVC + normalVC * (vtkShadowNormalOffset * texel);
}

vec4 vtkShadowMapClip(vec3 positionVC, vec3 normalVC, int light, int firstView, int view,
  int viewLayout, int features)
{
  vec3 biased =
    vtkShadowOffsetAlongNormal(positionVC, normalVC, light, firstView, view, viewLayout, features);
  return vtkShadowMapTransform(firstView, view, biased, features);
}

// Texture coordinates and depth of the receiver in map `view`.
vec3 vtkShadowMapCoord(vec4 clip, int view, int features)
{
  vec3 mapCoord = clip.xyz / clip.w;
  vec3 inverseW = vtkShadowViews[view].DepthInverseW;
  if (vtkShadowHas(features, VTK_SHADOW_FEATURE_LINEAR_DEPTHS) && inverseW != vec3(0.0))
  {
    mapCoord.z = (mapCoord.z - 0.5) / dot(inverseW, vec3(mapCoord.xy, 1.0)) + 0.5;
  }
  return mapCoord;
}

bool vtkShadowInsideMap(vec4 clip, int view, int features)
{
  vec3 mapCoord = vtkShadowMapCoord(clip, view, features);
  return clip.w > 0.0 && all(greaterThanEqual(mapCoord, vec3(0.0))) &&
    all(lessThanEqual(mapCoord, vec3(1.0)));
}

#ifdef VTK_SHADOW_POSITION_DERIVATIVES
// The drawn surface's screen derivatives. They are taken where VTK's shaders
// keep control flow uniform (ReceiverShader::Inject); shaders that shape their
// own surface (impostors) leave them zero.
vec3 vtkShadowPositionDx = vec3(0.0);
vec3 vtkShadowPositionDy = vec3(0.0);
#endif

#if defined(VTK_SHADOW_LIGHT_DEPTH) || defined(VTK_SHADOW_TRANSMITTANCE)
// The light depth of a receiver (MapStorage::LightDepth), unclamped.
float vtkShadowLightDepth(vec3 positionVC, int light)
{
  vec4 plane = vtkShadowLights[light].DepthPlane;
  vec3 relative = positionVC - vtkShadowLights[light].DepthOrigin;
  return dot(plane.xyz, relative) + plane.w + vtkShadowLights[light].DepthPerDistance * length(relative);
}
#endif

#ifdef VTK_SHADOW_MAP_FOOTPRINT
// For lookups that filter over the pixel's footprint in the map (mipmaps,
// a variance floor from the receiver's slope), set before each vtkShadowLookup:
// the map coordinates' and the light depth's changes over one pixel along x
// and y. They come from the position's derivatives through the map's own
// gradients, not from derivatives of the map coordinates, which jump where
// neighbouring pixels pick different views (cascades, cube faces).
vec2 vtkShadowMapDx = vec2(0.0);
vec2 vtkShadowMapDy = vec2(0.0);
vec2 vtkShadowLightDepthDxDy = vec2(0.0);

void vtkShadowMeasureFootprint(vec3 positionVC, int light, int firstView, int view, int features)
{
  vec3 gradU;
  vec3 gradV;
  vtkShadowMapGradients(positionVC, firstView, view, features, gradU, gradV);
  vtkShadowMapDx = vec2(dot(gradU, vtkShadowPositionDx), dot(gradV, vtkShadowPositionDx));
  vtkShadowMapDy = vec2(dot(gradU, vtkShadowPositionDy), dot(gradV, vtkShadowPositionDy));
  vec3 relative = positionVC - vtkShadowLights[light].DepthOrigin;
  vec3 gradDepth = vtkShadowLights[light].DepthPlane.xyz +
    vtkShadowLights[light].DepthPerDistance * relative / max(length(relative), 1e-30);
  vtkShadowLightDepthDxDy =
    vec2(dot(gradDepth, vtkShadowPositionDx), dot(gradDepth, vtkShadowPositionDy));
}
#endif

#ifdef VTK_SHADOW_RECEIVER_PLANE
// For lookups that compare with a surface of their own behind the casters'
// (dual-depth maps), set before each vtkShadowLookup:
// - vtkShadowDepthPerTexel: how much the map's depth grows over one texel's
//   world size along the light ray at the receiver. The ray is where both map
//   coordinates stay put, so it comes from the map's matrix alone, for every
//   kind of view (warped, linear-depth and perspective ones included).
// - vtkShadowReceiverSlope: the map depth of the receiver's plane per
//   unit of map coordinates, so that a texel is compared with the receiver's
//   plane where the texel's own depth was taken (its centre), not where the
//   receiver is: a sloped surface then matches its own texels however thin it
//   is. Limited to VTK_SHADOW_MAX_PLANE_TEXELS ray texels of depth per texel,
//   as a surface seen edge-on from the light has no slope to speak of.
float vtkShadowDepthPerTexel = 0.0;
vec2 vtkShadowReceiverSlope = vec2(0.0);
const float VTK_SHADOW_MAX_PLANE_TEXELS = 8.0;

// The receiver's plane is that of the drawn facet, from the position's screen
// derivatives, not the interpolated shading normal: a tessellated sphere's
// facets tilt away from its shading normals, and over a filter's taps the
// difference shows as acne. Without derivatives (impostors) the shading normal
// stands in.
vec3 vtkShadowPlaneNormalVC = vec3(0.0, 0.0, 1.0);

void vtkShadowSetReceiverPlane(vec3 shadingNormalVC)
{
  vec3 facet = cross(vtkShadowPositionDx, vtkShadowPositionDy);
  float facetLength = length(facet);
  vtkShadowPlaneNormalVC = !(facetLength > 0.0) ? shadingNormalVC
    : dot(facet, shadingNormalVC) < 0.0        ? -facet / facetLength
                                               : facet / facetLength;
}

vec3 vtkShadowMapPoint(vec3 positionVC, mat4 viewToMap, int view, int features)
{
  return vtkShadowMapCoord(viewToMap * vec4(positionVC, 1.0), view, features);
}

void vtkShadowMeasureReceiver(vec3 positionVC, vec3 normalVC, vec3 mapCoord, int light,
  int firstView, int view, int features)
{
  vtkShadowDepthPerTexel = 0.0;
  vtkShadowReceiverSlope = vec2(0.0);
  vec3 gradU;
  vec3 gradV;
  vtkShadowMapGradients(positionVC, firstView, view, features, gradU, gradV);
  vec3 ray = cross(gradU, gradV);
  float rayLength = length(ray);
  if (!(rayLength > 0.0))
  {
    return;
  }
  float texel = vtkShadowTexelWorldSize(positionVC, light, firstView, view, features);
  mat4 viewToMap = vtkShadowMapMatrix(firstView, view, features);
  vtkShadowDepthPerTexel =
    abs(vtkShadowMapPoint(positionVC + ray * (texel / rayLength), viewToMap, view, features).z -
      mapCoord.z);
  // Two tangents of the receiver, a texel long, in map coordinates.
  vec3 side = abs(normalVC.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 t1 = normalize(cross(normalVC, side)) * texel;
  vec3 t2 = normalize(cross(normalVC, t1)) * texel;
  vec3 m1 = vtkShadowMapPoint(positionVC + t1, viewToMap, view, features) - mapCoord;
  vec3 m2 = vtkShadowMapPoint(positionVC + t2, viewToMap, view, features) - mapCoord;
  float det = m1.x * m2.y - m1.y * m2.x;
  if (abs(det) > 1e-30)
  {
    vec2 slope = vec2(m1.z * m2.y - m2.z * m1.y, m1.x * m2.z - m2.x * m1.z) / det;
    float mostPerTexel = VTK_SHADOW_MAX_PLANE_TEXELS * vtkShadowDepthPerTexel;
    float perTexel = max(abs(slope.x), abs(slope.y)) / vtkShadowMapResolution;
    vtkShadowReceiverSlope = perTexel > mostPerTexel ? slope * (mostPerTexel / perTexel) : slope;
  }
}
#endif

#ifdef VTK_SHADOW_SIZED_LIGHTS
float vtkShadowSoftVisibility(vec3 positionVC, vec3 normalVC, int light, int firstView, int view,
  int viewLayout, int count, int features);
#endif

// What the opaque casters let through to the receiver, moved to `biased`, at
// mapCoord of map `view`.
float vtkShadowOpaqueVisibility(vec3 biased, vec3 normalVC, vec3 mapCoord, int light,
  int firstView, int view, int viewLayout, int count, int features)
{
#ifdef VTK_SHADOW_RECEIVER_PLANE
  vtkShadowMeasureReceiver(
    biased, vtkShadowPlaneNormalVC, mapCoord, light, firstView, view, features);
#endif
#ifdef VTK_SHADOW_SIZED_LIGHTS
  if (vtkShadowHas(features, VTK_SHADOW_FEATURE_SIZED_LIGHT))
  {
    return vtkShadowSoftVisibility(
      biased, normalVC, light, firstView, view, viewLayout, count, features);
  }
#endif
#ifdef VTK_SHADOW_MAP_FOOTPRINT
  vtkShadowMeasureFootprint(biased, light, firstView, view, features);
#endif
#ifdef VTK_SHADOW_LIGHT_DEPTH
  mapCoord.z = vtkShadowLightDepth(biased, light);
#endif
  return vtkShadowLookup(mapCoord, view);
}

VTK_SHADOW_VALUE vtkShadowViewVisibility(vec3 positionVC, vec3 normalVC, int light,
  int firstView, int view, int viewLayout, int count, int features)
{
  vec3 biased =
    vtkShadowOffsetAlongNormal(positionVC, normalVC, light, firstView, view, viewLayout, features);
  vec4 clip = vtkShadowMapTransform(firstView, view, biased, features);
  if (!vtkShadowInsideMap(clip, view, features))
  {
    return VTK_SHADOW_VALUE(1.0);
  }
  vec3 mapCoord = vtkShadowMapCoord(clip, view, features);
  float visibility = vtkShadowOpaqueVisibility(
    biased, normalVC, mapCoord, light, firstView, view, viewLayout, count, features);
#ifdef VTK_SHADOW_TRANSMITTANCE
  if (!vtkShadowTransmittanceReceived)
  {
    return VTK_SHADOW_VALUE(visibility);
  }
  return visibility * vtkShadowTransmittance(mapCoord.xy, vtkShadowLightDepth(biased, light), view);
#else
  return visibility;
#endif
}

// Weight of the next cascade in the blend band of cascade `view`: by depth over
// the band before its split; by coverage over the band along its map's border
// (a receiver the depth rule would give to a farther cascade is not blended:
// its own map is the finest that holds it).
float vtkShadowBlendIntoNext(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int view, float depth, int features)
{
  float band = vtkShadowLights[light].CoverageBand;
  if (band < 0.0)
  {
    vec3 cascade = vtkShadowViews[view].Selection;
    return clamp((depth - cascade.z) / max(cascade.y - cascade.z, 1e-30), 0.0, 1.0);
  }
  if (band <= 0.0)
  {
    return 0.0;
  }
  vec4 clip = vtkShadowMapClip(
    positionVC, normalVC, light, firstView, view, VTK_SHADOW_LAYOUT_CASCADES, features);
  vec2 ndc = abs(2.0 * clip.xy / clip.w - 1.0);
  return clamp((max(ndc.x, ndc.y) - (1.0 - band)) / band, 0.0, 1.0);
}

// Fraction of light `light` reaching the receiver, in [0, 1] (per channel where
// translucent casters tint it); 1 outside the maps.
// Cascades blend into the next one over the band before their split; cascades
// and tiles fade out toward the light's maximum shadow distance.
VTK_SHADOW_VALUE vtkShadowVisibility(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int viewLayout, int count, int features)
{
  int view = vtkShadowSelectView(positionVC, normalVC, light, firstView, viewLayout, count, features);
  VTK_SHADOW_VALUE visibility = vtkShadowViewVisibility(
    positionVC, normalVC, light, firstView, view, viewLayout, count, features);
  float depth = -positionVC.z;
  if (viewLayout == VTK_SHADOW_LAYOUT_CASCADES &&
    vtkShadowHas(features, VTK_SHADOW_FEATURE_CASCADE_BLENDS))
  {
    float weight =
      vtkShadowBlendIntoNext(positionVC, normalVC, light, firstView, view, depth, features);
    if (view < firstView + count - 1 && weight > 0.0)
    {
      VTK_SHADOW_VALUE next =
        vtkShadowViewVisibility(
          positionVC, normalVC, light, firstView, view + 1, viewLayout, count, features);
      visibility = mix(visibility, next, weight);
    }
  }
  if (viewLayout == VTK_SHADOW_LAYOUT_CASCADES || viewLayout == VTK_SHADOW_LAYOUT_TILES)
  {
    vec2 fade = vtkShadowLights[light].Fade;
    if (fade.y > fade.x)
    {
      visibility = mix(visibility, VTK_SHADOW_VALUE(1.0), smoothstep(fade.x, fade.y, depth));
    }
  }
  return visibility;
}

// Factor that scales the light's diffuse and specular terms.
VTK_SHADOW_VALUE vtkShadowFactor(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int viewLayout, int count, int features)
{
  VTK_SHADOW_VALUE visibility =
    vtkShadowVisibility(positionVC, normalVC, light, firstView, viewLayout, count, features);
  return 1.0 - vtkShadowLights[light].Attenuation * (1.0 - visibility);
}
