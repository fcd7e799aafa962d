// Comparison of moment maps (vtkVarianceShadowMapRepresentation), after
// vtkShadowMapsMomentsFS. A receiver at light depth t reads the moments of the
// occluders' depths over its filter footprint, one trilinear (mipmapped)
// sample over the pixel's footprint in the map (vtkShadowMapDx, vtkShadowMapDy),
// and bounds the fraction of them in front of it (thesis 000 on [DL06],
// [Lau06]; text 003; Peters and Klein's moment shadow maps for MSM).

uniform sampler2DArray vtkShadowMaps;
// Visibilities below it become 0, the rest is stretched over [0, 1].
uniform float vtkShadowLightBleeding;
// Least variance of the depth distribution (squared light depth).
uniform float vtkShadowMinimumVariance;
// MSM: the weight of the safe moment vector mixed into the stored one.
uniform float vtkShadowMomentBias;
// The Gaussian blur of the maps, in texels of a light's first view.
uniform float vtkShadowMomentsBlurSigma;
// Mipmaps: how elongated a footprint may be before its long axis picks the level.
uniform float vtkShadowAnisotropy;
// Per-texel rotations (cos, sin) of the soft shadows' kernels.
uniform sampler2D vtkShadowNoise;

// Chebyshev's one-sided bound on the fraction of the distribution with mean
// and second moment `moments` that lies at or beyond t: the visibility.
float vtkShadowChebyshev(vec2 moments, float t, float minimumVariance)
{
  if (t <= moments.x)
  {
    return 1.0;
  }
  float variance = max(moments.y - moments.x * moments.x, minimumVariance);
  float d = t - moments.x;
  return variance / (variance + d * d);
}

// Peters and Klein's Hamburger reconstruction: the least fraction of the
// occluders that can lie in front of z among all depth distributions with the
// four power moments b (biased toward those of a distribution on two depths
// around all others, which keeps the Hankel matrix invertible). Returns the
// visibility.
float vtkShadowHamburger(vec4 b, float z)
{
  // B c = (1, z, z^2) with B = [1 b1 b2; b1 b2 b3; b2 b3 b4], by LDL^T.
  float d2 = max(b.y - b.x * b.x, 1e-12);
  float l32 = (b.z - b.x * b.y) / d2;
  float d3 = max(b.w - b.y * b.y - l32 * l32 * d2, 1e-12);
  float y2 = z - b.x;
  float y3 = z * z - b.y - l32 * y2;
  float c3 = y3 / d3;
  float c2 = y2 / d2 - l32 * c3;
  float c1 = 1.0 - b.x * c2 - b.y * c3;
  // The other two support points: the roots of c1 + c2 x + c3 x^2.
  float discriminant = max(c2 * c2 - 4.0 * c3 * c1, 0.0);
  float root = sqrt(discriminant);
  float q = -0.5 * (c2 + (c2 < 0.0 ? -root : root));
  float r1 = q / (abs(c3) > 1e-30 ? c3 : (c3 < 0.0 ? -1e-30 : 1e-30));
  float r2 = c1 / (abs(q) > 1e-30 ? q : (q < 0.0 ? -1e-30 : 1e-30));
  float z2 = min(r1, r2);
  float z3 = max(r1, r2);
  float shadow;
  if (z <= z2)
  {
    shadow = 0.0;
  }
  else if (z <= z3)
  {
    // The weight of z2, the only support point in front of z.
    shadow = (z * z3 - b.x * (z + z3) + b.y) / ((z3 - z2) * (z - z2));
  }
  else
  {
    // All but the weight of z itself.
    shadow = 1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((z - z2) * (z - z3));
  }
  return 1.0 - clamp(shadow, 0.0, 1.0);
}

// The variance a receiver's own plane has over the filter at t: its depth
// change per texel (from the footprint's screen derivatives), squared, times
// the texel's own variance (1/12) and the blur's (sigma^2 in this layer's
// texels).
float vtkShadowReceiverVariance(int layer)
{
  float det = vtkShadowMapDx.x * vtkShadowMapDy.y - vtkShadowMapDx.y * vtkShadowMapDy.x;
  if (!(abs(det) > 1e-30))
  {
    return 0.0;
  }
  vec2 perUV = vec2(vtkShadowLightDepthDxDy.x * vtkShadowMapDy.y - vtkShadowLightDepthDxDy.y * vtkShadowMapDx.y,
                 vtkShadowMapDx.x * vtkShadowLightDepthDxDy.y - vtkShadowMapDy.x * vtkShadowLightDepthDxDy.x) /
    det;
  vec2 perTexel = perUV / vtkShadowMapResolution;
  float sigma = vtkShadowMomentsBlurSigma * vtkShadowViews[layer].FilterScale;
  return dot(perTexel, perTexel) * (1.0 / 12.0 + sigma * sigma);
}

float vtkShadowReduceBleeding(float visibility)
{
  return clamp((visibility - vtkShadowLightBleeding) / (1.0 - vtkShadowLightBleeding), 0.0, 1.0);
}

// The mipmap level of the pixel's footprint in the map: that of its short
// axis, or of its long axis over vtkShadowAnisotropy if coarser. Without
// mipmaps every level but 0 is clamped away.
float vtkShadowMomentsLevel()
{
  float x = length(vtkShadowMapDx) * vtkShadowMapResolution;
  float y = length(vtkShadowMapDy) * vtkShadowMapResolution;
  float texels = max(max(x, y) / vtkShadowAnisotropy, min(x, y));
  return log2(max(texels, 1.0));
}

// The fraction of the occluders' depths whose moments are `moments` that lies
// at or beyond a receiver at light depth t, with `variance` the least variance
// of the depth distribution: the visibility before light-bleeding reduction.
float vtkShadowMomentsBound(vec4 moments, float t, float variance)
{
#if VTK_SHADOW_MOMENTS == 0
  float visibility = vtkShadowChebyshev(moments.xy, t, variance);
#elif VTK_SHADOW_MOMENTS == 1 || VTK_SHADOW_MOMENTS == 2
  // The variance floor in each warped space: depth variance times the warp's
  // slope squared (d/dt of exp(c (2t - 1)) is 2c exp(c (2t - 1))) at the
  // occluders' mean, where a depth spread of theirs would be; at the
  // receiver's, far behind them, the slope would be many times steeper.
  vec2 warped = vtkShadowWarpDepth(t);
  vec2 slopes = 2.0 * vec2(vtkShadowPositiveExponent, vtkShadowNegativeExponent) *
    abs(vec2(moments.x, moments.z));
  float visibility = vtkShadowChebyshev(moments.xy, warped.x, variance * slopes.x * slopes.x);
#if VTK_SHADOW_MOMENTS == 2
  visibility =
    min(visibility, vtkShadowChebyshev(moments.zw, warped.y, variance * slopes.y * slopes.y));
#endif
#elif VTK_SHADOW_MOMENTS == 3 && VTK_SHADOW_CHEBYSHEV_BASIS
  // In the centred depth 2d - 1, biased toward half at -1, half at 1 (the
  // distribution of the 32-bit maps' bias). The receiver moves toward the
  // light by 4 16-bit steps of d (8 of u): the stored depth's rounding (half a
  // step) and what the higher moments' rounding does to the reconstruction
  // would otherwise shadow surfaces near their casters. On the benchmark's
  // spot, point and perpendicular set-ups, half a step and 2 steps
  // misclassified more; 8 as much in all, leaking more light (docs/VARIANCE.md).
  vec4 centered =
    mix(vtkShadowCenteredMoments(moments), vec4(0.0, 1.0, 0.0, 1.0), vtkShadowMomentBias);
  float visibility = vtkShadowHamburger(centered, 2.0 * t - 1.0 - 8.0 / 65535.0);
#elif VTK_SHADOW_MOMENTS == 3
  // Biased toward half at depth 0, half at 1.
  float visibility = vtkShadowHamburger(mix(moments, vec4(0.5), vtkShadowMomentBias), t);
#else
  // ESM: exp(c (2d - 1)) averaged over the occluders, over the receiver's.
  float visibility = clamp(moments.x / vtkShadowWarpDepth(t).x, 0.0, 1.0);
#endif
  return visibility;
}

// The visibility of a receiver at light depth t from the stored moments.
float vtkShadowMomentsVisibility(vec4 moments, float t, float variance)
{
#if VTK_SHADOW_MOMENTS == 4
  return vtkShadowMomentsBound(moments, t, variance);
#else
  return vtkShadowReduceBleeding(vtkShadowMomentsBound(moments, t, variance));
#endif
}

float vtkShadowLookup(vec3 mapCoord, int layer)
{
  vec4 moments =
    textureLod(vtkShadowMaps, vec3(mapCoord.xy, float(layer)), vtkShadowMomentsLevel());
  float variance = vtkShadowMinimumVariance + vtkShadowReceiverVariance(layer);
  return vtkShadowMomentsVisibility(moments, clamp(mapCoord.z, 0.0, 1.0), variance);
}
