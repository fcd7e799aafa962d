// The PCF family (vtkDepthShadowMapRepresentation's filters) over a
// representation's comparison, defined before this block:
//   float vtkShadowCompare(vec2 uv, float depth, int layer)
// the visibility of a receiver at `depth` at texture coordinates uv of layer
// `layer`. Hard and 2x2 PCF are one comparison; N x N PCF and the Poisson disc
// are many.

// Per-texel rotations (cos, sin) of the Poisson disc.
uniform sampler2D vtkShadowNoise;
uniform float vtkShadowFilterRadius;

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

float vtkShadowLookup(vec3 mapCoord, int layer)
{
#if VTK_SHADOW_FILTER <= 1
  return vtkShadowCompare(mapCoord.xy, mapCoord.z, layer);
#elif VTK_SHADOW_FILTER == 2
  float texel = vtkShadowViews[layer].FilterScale / vtkShadowMapResolution;
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
  float radius = vtkShadowFilterRadius * vtkShadowViews[layer].FilterScale / vtkShadowMapResolution;
  float lit = 0.0;
  for (int i = 0; i < VTK_SHADOW_POISSON_SAMPLES; ++i)
  {
    lit += vtkShadowCompare(mapCoord.xy + rotate * vtkShadowPoissonDisc[i] * radius, mapCoord.z, layer);
  }
  return lit / float(VTK_SHADOW_POISSON_SAMPLES);
#endif
}
