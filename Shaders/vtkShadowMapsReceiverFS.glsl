// Shadow-map receiver functions, injected into a mapper's fragment shader after
// its lighting declarations. The pass defines before this block:
//   VTK_SHADOW_FILTER          0 hard, 1 hardware 2x2 PCF, 2 N x N PCF, 3 Poisson
//   VTK_SHADOW_KERNEL          N of the N x N filter
//   VTK_SHADOW_POISSON_SAMPLES taps of the Poisson filter
//   VTK_SHADOW_MAX_VIEWS, VTK_SHADOW_MAX_LIGHTS  array sizes
// and appends after it the lookup of its texel storage, which declares the
// sampler vtkShadowMaps and defines vtkShadowLookup (vtkShadowMapsDepthLookupFS
// for depth maps).

uniform sampler2D vtkShadowNoise;
// Receivers are evaluated in the camera's view coordinates (VC): one matrix
// per map takes a VC point to map texture coordinates and depth.
uniform mat4 vtkShadowViewToWorld;
uniform mat4 vtkShadowViewToMap[VTK_SHADOW_MAX_VIEWS];
// World-space size of one texel of a view: x + y * (distance to the light);
// x < 0: warped map, size from the map's local gradient (vtkShadowGradientTexel).
uniform vec2 vtkShadowTexelSize[VTK_SHADOW_MAX_VIEWS];
// Views whose depth is linear in light space (TSM): 1 / W, the trapezoid's W, as a
// plane over texture coordinates (u, v, 1); their casters store z / w times W.
// Zero for views that store z / w.
uniform vec3 vtkShadowDepthInverseW[VTK_SHADOW_MAX_VIEWS];
// Cascades: per view, x = first view depth (-z in VC) it shades, y = its last
// (the next split), z = where the blend band into the next cascade starts,
// w = its texel size over the first cascade's (filter offsets are multiplied by
// its inverse so the kernel keeps its world size). Other views: (0, 1e38, 1e38, 1).
uniform vec4 vtkShadowCascade[VTK_SHADOW_MAX_VIEWS];
// Per light: x, y = view depths over which shadows fade out (x >= y: no fade);
// z >= 0: cascades selected by map coverage instead of depth, and blended into
// the next over this outer fraction of the map's half-width; z < 0: by depth.
uniform vec3 vtkShadowCascadeLight[VTK_SHADOW_MAX_LIGHTS];
// Per light whose views are tiles of one map (shadowmaps::TileGrid): columns,
// rows, and a tile's window over the whole map's along x and y.
uniform vec4 vtkShadowTileGrid[VTK_SHADOW_MAX_LIGHTS];
uniform vec3 vtkShadowLightPositionVC[VTK_SHADOW_MAX_LIGHTS];
uniform float vtkShadowAttenuation[VTK_SHADOW_MAX_LIGHTS];
uniform float vtkShadowMapResolution;
uniform float vtkShadowNormalOffset;
uniform float vtkShadowFilterRadius;

// Visibility in [0, 1] of the map point mapCoord (xy: texture coordinates,
// z: the receiver's depth in the map) in layer `layer`.
float vtkShadowLookup(vec3 mapCoord, int layer);

// Cube face order +x, -x, +y, -y, +z, -z (see shadowmaps::CubeFaceIndex).
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

// How a light's views cover the receivers (vtkAbstractShadowMapPass's LightViews).
const int vtkShadowSingleView = 0;
const int vtkShadowCubeViews = 1;
const int vtkShadowCascadeViews = 2;
const int vtkShadowTileViews = 3;

// What a light's views may need of the receiver (ShadowLight::ReceiverFeatures),
// a literal per light: code a light cannot need is compiled out, since
// software rasterisers run both sides of every branch.
const int vtkShadowGradientTexels = 1; // warped maps: texel size from the map's gradient
const int vtkShadowDistantTexels = 2;  // positional lights: texels grow with distance
const int vtkShadowLinearDepths = 4;   // TSM: depth stored unwarped, 1 / W recovered
bool vtkShadowHas(int features, int feature)
{
  return (features & feature) != 0;
}

vec4 vtkShadowMapClip(vec3 positionVC, vec3 normalVC, int light, int view, int features);
bool vtkShadowInsideMap(vec4 clip, int view, int features);

// The cascade that shades the receiver: by view depth, or the first (finest)
// whose map contains it.
int vtkShadowSelectCascade(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int count, int features)
{
  if (vtkShadowCascadeLight[light].z >= 0.0)
  {
    for (int i = 0; i < count - 1; ++i)
    {
      vec4 clip = vtkShadowMapClip(positionVC, normalVC, light, firstView + i, features);
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
    if (depth < vtkShadowCascade[firstView + i].y)
    {
      return firstView + i;
    }
  }
  return firstView + count - 1;
}

// The tile of one map (TileGrid::TileFromFirstTile) whose core holds the receiver, from
// its place in the first tile: one map transform, whatever the tile count.
int vtkShadowSelectTile(vec3 positionVC, vec3 normalVC, int light, int firstView, int features)
{
  vec4 grid = vtkShadowTileGrid[light];
  vec4 clip = vtkShadowMapClip(positionVC, normalVC, light, firstView, features);
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

// The view of light `light` that covers the receiver. The light's views start
// at layer firstView; a cube light has six of them, a cascaded or tiled light
// `count`.
int vtkShadowSelectView(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int kind, int count, int features)
{
  if (kind == vtkShadowCascadeViews)
  {
    return vtkShadowSelectCascade(positionVC, normalVC, light, firstView, count, features);
  }
  if (kind == vtkShadowTileViews)
  {
    return vtkShadowSelectTile(positionVC, normalVC, light, firstView, features);
  }
  if (kind != vtkShadowCubeViews)
  {
    return firstView;
  }
  // Cube faces are aligned with the world axes.
  vec3 fromLight = mat3(vtkShadowViewToWorld) * (positionVC - vtkShadowLightPositionVC[light]);
  return firstView + vtkShadowCubeFace(fromLight);
}

// Clip coordinates of the receiver in map `view`, moved along its normal by the
// world-space size of a texel there (normal offset, Kozlov, GPU Gems 14).
// World (= VC) length of one texel along the map's coarser axis at positionVC:
// 1 / (resolution * |grad t|), with grad t = (row_t - t row_w) / w the gradient of
// the projective map coordinate t in {u, v}.
float vtkShadowGradientTexel(vec3 positionVC, int view)
{
  mat4 m = vtkShadowViewToMap[view];
  vec4 q = m * vec4(positionVC, 1.0);
  vec3 rowW = vec3(m[0][3], m[1][3], m[2][3]);
  vec3 gradU = (vec3(m[0][0], m[1][0], m[2][0]) - (q.x / q.w) * rowW) / q.w;
  vec3 gradV = (vec3(m[0][1], m[1][1], m[2][1]) - (q.y / q.w) * rowW) / q.w;
  float slowest = min(length(gradU), length(gradV));
  return 1.0 / (vtkShadowMapResolution * max(slowest, 1e-20));
}

vec4 vtkShadowMapClip(vec3 positionVC, vec3 normalVC, int light, int view, int features)
{
  vec2 texelSize = vtkShadowTexelSize[view];
  float texel = texelSize.x;
  if (vtkShadowHas(features, vtkShadowDistantTexels))
  {
    texel += texelSize.y * length(positionVC - vtkShadowLightPositionVC[light]);
  }
  if (vtkShadowHas(features, vtkShadowGradientTexels) && texelSize.x < 0.0)
  {
    texel = vtkShadowGradientTexel(positionVC, view);
  }
  vec3 biased = positionVC + normalVC * (vtkShadowNormalOffset * texel);
  return vtkShadowViewToMap[view] * vec4(biased, 1.0);
}

// Texture coordinates and depth of the receiver in map `view`.
vec3 vtkShadowMapCoord(vec4 clip, int view, int features)
{
  vec3 mapCoord = clip.xyz / clip.w;
  vec3 inverseW = vtkShadowDepthInverseW[view];
  if (vtkShadowHas(features, vtkShadowLinearDepths) && inverseW != vec3(0.0))
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

float vtkShadowViewVisibility(vec3 positionVC, vec3 normalVC, int light, int view, int features)
{
  vec4 clip = vtkShadowMapClip(positionVC, normalVC, light, view, features);
  if (!vtkShadowInsideMap(clip, view, features))
  {
    return 1.0;
  }
  return vtkShadowLookup(vtkShadowMapCoord(clip, view, features), view);
}

// Weight of the next cascade in the blend band of cascade `view`: by depth over
// the band before its split; by coverage over the band along its map's border
// (a receiver the depth rule would give to a farther cascade is not blended:
// its own map is the finest that holds it).
float vtkShadowBlendIntoNext(
  vec3 positionVC, vec3 normalVC, int light, int view, float depth, int features)
{
  float band = vtkShadowCascadeLight[light].z;
  if (band < 0.0)
  {
    vec4 cascade = vtkShadowCascade[view];
    return clamp((depth - cascade.z) / max(cascade.y - cascade.z, 1e-30), 0.0, 1.0);
  }
  if (band <= 0.0)
  {
    return 0.0;
  }
  vec4 clip = vtkShadowMapClip(positionVC, normalVC, light, view, features);
  vec2 ndc = abs(2.0 * clip.xy / clip.w - 1.0);
  return clamp((max(ndc.x, ndc.y) - (1.0 - band)) / band, 0.0, 1.0);
}

// Fraction of light `light` reaching the receiver, in [0, 1]; 1 outside the maps.
// Cascades blend into the next one over the band before their split; cascades
// and tiles fade out toward the light's maximum shadow distance.
float vtkShadowVisibility(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int kind, int count, int features)
{
  int view = vtkShadowSelectView(positionVC, normalVC, light, firstView, kind, count, features);
  float visibility = vtkShadowViewVisibility(positionVC, normalVC, light, view, features);
  float depth = -positionVC.z;
  if (kind == vtkShadowCascadeViews)
  {
    float weight = vtkShadowBlendIntoNext(positionVC, normalVC, light, view, depth, features);
    if (view < firstView + count - 1 && weight > 0.0)
    {
      float next = vtkShadowViewVisibility(positionVC, normalVC, light, view + 1, features);
      visibility = mix(visibility, next, weight);
    }
  }
  if (kind == vtkShadowCascadeViews || kind == vtkShadowTileViews)
  {
    vec3 fade = vtkShadowCascadeLight[light];
    if (fade.y > fade.x)
    {
      visibility = mix(visibility, 1.0, smoothstep(fade.x, fade.y, depth));
    }
  }
  return visibility;
}

// Factor that scales the light's diffuse and specular terms.
float vtkShadowFactor(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int kind, int count, int features)
{
  float visibility =
    vtkShadowVisibility(positionVC, normalVC, light, firstView, kind, count, features);
  return 1.0 - vtkShadowAttenuation[light] * (1.0 - visibility);
}

#ifdef VTK_SHADOW_ANALYSIS
// Analysis views (vtkAbstractShadowMapPass::AnalysisView) replace the colour of
// the receivers: 1 the analysed light's visibility as grey; 2 the texel
// density as a heat map; 4 the map (partition) each pixel was shaded from.

// Screen pixels covered by one map texel, along one side: 1 / sqrt(|det J|)
// with J the derivative of texel coordinates by window pixels.
float vtkShadowTexelFootprint(vec4 clip)
{
  vec2 texel = clip.xy / clip.w * vtkShadowMapResolution;
  vec2 dx = dFdx(texel);
  vec2 dy = dFdy(texel);
  float texelsPerPixelArea = abs(dx.x * dy.y - dx.y * dy.x);
  return inversesqrt(max(texelsPerPixelArea, 1e-12));
}

// Not undersampled (footprint <= 1.5 pixels): blue (dense) to green (1.5), red
// channel at most 0.5. Undersampled: full red, the green fading from 0.6 as the
// footprint grows to 64 pixels; the benchmark counts red = 1 as undersampled.
vec3 vtkShadowDensityColor(float footprint)
{
  float octaves = log2(footprint);
  float limit = log2(1.5);
  if (octaves <= limit)
  {
    float t = clamp((octaves + 4.0) / (limit + 4.0), 0.0, 1.0);
    return mix(vec3(0.1, 0.2, 1.0), vec3(0.4, 0.9, 0.2), t);
  }
  float t = clamp((octaves - limit) / (6.0 - limit), 0.0, 1.0);
  return vec3(1.0, 0.6 * (1.0 - t), 0.0);
}

vec3 vtkShadowPartitionColor(int index)
{
  const vec3 palette[8] = vec3[8](vec3(0.9, 0.2, 0.2), vec3(0.2, 0.8, 0.2), vec3(0.2, 0.4, 1.0),
    vec3(0.95, 0.85, 0.2), vec3(0.8, 0.3, 0.9), vec3(0.2, 0.85, 0.85), vec3(1.0, 0.55, 0.1),
    vec3(0.6, 0.6, 0.6));
  return palette[index % 8];
}

vec4 vtkShadowAnalysisColor(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int kind, int count, int features)
{
  int view = vtkShadowSelectView(positionVC, normalVC, light, firstView, kind, count, features);
  vec4 clip = vtkShadowMapClip(positionVC, normalVC, light, view, features);
  float footprint = vtkShadowTexelFootprint(clip);
  float visibility =
    vtkShadowVisibility(positionVC, normalVC, light, firstView, kind, count, features);
#if VTK_SHADOW_ANALYSIS == 1
  return vec4(vec3(visibility), 1.0);
#elif VTK_SHADOW_ANALYSIS == 2
  return vec4(vtkShadowInsideMap(clip, view, features) ? vtkShadowDensityColor(footprint) : vec3(0.0), 1.0);
#else
  vec3 color = vtkShadowInsideMap(clip, view, features) ? vtkShadowPartitionColor(view - firstView) : vec3(0.0);
  return vec4(color * (0.5 + 0.5 * visibility), 1.0);
#endif
}
#endif
