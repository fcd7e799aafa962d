// Shadow-map receiver functions, injected into a mapper's fragment shader after
// its lighting declarations. The pass defines before this block:
//   VTK_SHADOW_FILTER          0 hard, 1 hardware 2x2 PCF, 2 N x N PCF, 3 Poisson
//   VTK_SHADOW_KERNEL          N of the N x N filter
//   VTK_SHADOW_POISSON_SAMPLES taps of the Poisson filter
//   VTK_SHADOW_MAX_VIEWS, VTK_SHADOW_MAX_LIGHTS  array sizes
// Hard and 2x2 PCF differ only in the map's texture filter (nearest / linear).

uniform sampler2DArrayShadow vtkShadowMaps;
uniform sampler2D vtkShadowNoise;
uniform mat4 vtkShadowViewToWorld;
uniform mat4 vtkShadowWorldToMap[VTK_SHADOW_MAX_VIEWS];
// World-space size of one texel of a view: x + y * (distance to the light).
uniform vec2 vtkShadowTexelSize[VTK_SHADOW_MAX_VIEWS];
uniform vec3 vtkShadowLightPosition[VTK_SHADOW_MAX_LIGHTS];
uniform float vtkShadowAttenuation[VTK_SHADOW_MAX_LIGHTS];
uniform float vtkShadowMapResolution;
uniform float vtkShadowNormalOffset;
uniform float vtkShadowFilterRadius;

float vtkShadowCompare(vec2 uv, float depth, int layer)
{
  return texture(vtkShadowMaps, vec4(uv, float(layer), depth));
}

#if VTK_SHADOW_FILTER == 3
const vec2 vtkShadowPoissonDisc[32] = vec2[32](
  vec2(-0.07715,  0.11050),
  vec2( 0.52063, -0.82075),
  vec2(-0.67777, -0.69881),
  vec2( 0.92308,  0.14918),
  vec2( 0.18536,  0.95820),
  vec2(-0.59377,  0.72913),
  vec2(-0.80419,  0.13205),
  vec2(-0.06911, -0.53213),
  vec2( 0.47625, -0.18105),
  vec2( 0.48004,  0.46008),
  vec2( 0.71296, -0.52120),
  vec2( 0.27264,  0.12799),
  vec2(-0.58942, -0.13518),
  vec2(-0.39218, -0.46753),
  vec2(-0.15692, -0.21866),
  vec2(-0.92379, -0.14748),
  vec2( 0.64832,  0.69979),
  vec2(-0.32454,  0.84309),
  vec2( 0.79514, -0.24135),
  vec2( 0.23012, -0.80377),
  vec2(-0.80895,  0.41527),
  vec2( 0.87014,  0.42569),
  vec2(-0.52399,  0.15874),
  vec2( 0.32156,  0.69152),
  vec2( 0.33903, -0.41794),
  vec2(-0.25980, -0.72586),
  vec2( 0.66557,  0.25388),
  vec2(-0.82350, -0.47555),
  vec2( 0.21536,  0.43079),
  vec2(-0.41076,  0.53799),
  vec2(-0.17378,  0.34734),
  vec2( 0.02811,  0.75739));
#endif

float vtkShadowFilteredCompare(vec3 mapCoord, int layer)
{
#if VTK_SHADOW_FILTER <= 1
  return vtkShadowCompare(mapCoord.xy, mapCoord.z, layer);
#elif VTK_SHADOW_FILTER == 2
  float texel = 1.0 / vtkShadowMapResolution;
  float center = 0.5 * float(VTK_SHADOW_KERNEL - 1);
  float lit = 0.0;
  for (int j = 0; j < VTK_SHADOW_KERNEL; ++j)
  {
    for (int i = 0; i < VTK_SHADOW_KERNEL; ++i)
    {
      vec2 offset = (vec2(float(i), float(j)) - center) * texel;
      lit += vtkShadowCompare(mapCoord.xy + offset, mapCoord.z, layer);
    }
  }
  return lit / float(VTK_SHADOW_KERNEL * VTK_SHADOW_KERNEL);
#else
  // The rotation is looked up per shadow-map texel, so the pattern is fixed to
  // the light and does not crawl when the camera moves (thesis 000, jittered PCF).
  vec2 rotation = texture(vtkShadowNoise, mapCoord.xy * vtkShadowMapResolution / 32.0).xy;
  mat2 rotate = mat2(rotation.x, rotation.y, -rotation.y, rotation.x);
  float radius = vtkShadowFilterRadius / vtkShadowMapResolution;
  float lit = 0.0;
  for (int i = 0; i < VTK_SHADOW_POISSON_SAMPLES; ++i)
  {
    lit += vtkShadowCompare(mapCoord.xy + rotate * vtkShadowPoissonDisc[i] * radius, mapCoord.z, layer);
  }
  return lit / float(VTK_SHADOW_POISSON_SAMPLES);
#endif
}

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

// Fraction of light `light` reaching the receiver, in [0, 1]. The light's views
// start at layer firstView; a cube light has six of them.
float vtkShadowVisibility(vec3 positionWorld, vec3 normalWorld, int light, int firstView, bool cube)
{
  vec3 fromLight = positionWorld - vtkShadowLightPosition[light];
  int view = cube ? firstView + vtkShadowCubeFace(fromLight) : firstView;
  vec2 texelSize = vtkShadowTexelSize[view];
  float texel = texelSize.x + texelSize.y * length(fromLight);
  // Normal offset scaled by the world-space texel size (Kozlov, GPU Gems 14).
  vec3 biased = positionWorld + normalWorld * (vtkShadowNormalOffset * texel);
  vec4 clip = vtkShadowWorldToMap[view] * vec4(biased, 1.0);
  if (clip.w <= 0.0)
  {
    return 1.0;
  }
  vec3 mapCoord = clip.xyz / clip.w;
  if (any(lessThan(mapCoord, vec3(0.0))) || any(greaterThan(mapCoord, vec3(1.0))))
  {
    return 1.0;
  }
  return vtkShadowFilteredCompare(mapCoord, view);
}

// Factor that scales the light's diffuse and specular terms.
float vtkShadowFactor(vec3 positionWorld, vec3 normalWorld, int light, int firstView, bool cube)
{
  float visibility = vtkShadowVisibility(positionWorld, normalWorld, light, firstView, cube);
  return 1.0 - vtkShadowAttenuation[light] * (1.0 - visibility);
}
