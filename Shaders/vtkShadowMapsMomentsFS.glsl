// The moments filterable maps store (vtkVarianceShadowMapRepresentation),
// shared by the casters, which store them, and the receivers, which warp their
// own depth the same way. Before this block:
//   VTK_SHADOW_MOMENTS 0 VSM, 1 EVSM2, 2 EVSM4, 3 MSM, 4 ESM;
//   VTK_SHADOW_CHEBYSHEV_BASIS 1 where MSM's moments are stored for 16 bits.
// Depths are light depths in [0, 1] (shadowmaps::LightDepth). A program that
// both casts and receives gets this block twice.
#ifndef VTK_SHADOW_MOMENTS_FUNCTIONS
#define VTK_SHADOW_MOMENTS_FUNCTIONS

// The exponents of EVSM's warps (uniforms: a slider builds no shader).
uniform float vtkShadowPositiveExponent;
uniform float vtkShadowNegativeExponent;

// The exponential warps of depth moved to [-1, 1]: exp(c+ d) and -exp(-c- d),
// both increasing with depth.
vec2 vtkShadowWarpDepth(float depth)
{
  float d = 2.0 * depth - 1.0;
  return vec2(
    exp(vtkShadowPositiveExponent * d), -exp(-vtkShadowNegativeExponent * d));
}

#if VTK_SHADOW_CHEBYSHEV_BASIS
// MSM in 16-bit normalized storage. The power moments d, d^2, d^3, d^4 of
// depths in [0, 1] nearly coincide: what d^4 adds to the lower three stays
// within +-1/128 (the monic quartic of least maximum there is 2^-7 times a
// Chebyshev polynomial), so a 16-bit d^4 keeps only about 9 bits of it.
// Shifted Chebyshev polynomials T_k(2d - 1), k = 1..4, moved to [0, 1], are a
// triangular linear change of basis (averages stay averages, so blur and
// mipmaps commute with it) whose every coordinate spans all of [0, 1]: the
// rounding of what d^2, d^3 and d^4 add shrinks 4, 16 and 64 times.
vec4 vtkShadowChebyshevMoments(float d)
{
  float u = 2.0 * d - 1.0;
  float u2 = u * u;
  vec4 polynomials = vec4(u, 2.0 * u2 - 1.0, u * (4.0 * u2 - 3.0), 8.0 * u2 * (u2 - 1.0) + 1.0);
  return 0.5 + 0.5 * polynomials;
}

// The averaged moments of the centred depth u = 2d - 1 (u, u^2, u^3, u^4) from
// averaged vtkShadowChebyshevMoments: u^2 = (T2 + 1) / 2, u^3 = (T3 + 3u) / 4,
// u^4 = (T4 + 8u^2 - 1) / 8. Centred, they keep their digits in single
// precision at both ends of the depth range; the powers of d would not near
// d = 0 (d^4 from moments of u cancels to nothing).
vec4 vtkShadowCenteredMoments(vec4 stored)
{
  vec4 t = 2.0 * stored - 1.0;
  float u2 = 0.5 * (t.y + 1.0);
  return vec4(t.x, u2, 0.25 * (t.z + 3.0 * t.x), 0.125 * (t.w + 8.0 * u2 - 1.0));
}
#endif

// What a texel of one caster surface at `depth` stores.
vec4 vtkShadowMomentsOf(float depth)
{
  float d = clamp(depth, 0.0, 1.0);
#if VTK_SHADOW_MOMENTS == 0
  return vec4(d, d * d, 0.0, 0.0);
#elif VTK_SHADOW_MOMENTS == 1
  float positive = vtkShadowWarpDepth(d).x;
  return vec4(positive, positive * positive, 0.0, 0.0);
#elif VTK_SHADOW_MOMENTS == 2
  vec2 warped = vtkShadowWarpDepth(d);
  return vec4(warped.x, warped.x * warped.x, warped.y, warped.y * warped.y);
#elif VTK_SHADOW_MOMENTS == 3 && VTK_SHADOW_CHEBYSHEV_BASIS
  return vtkShadowChebyshevMoments(d);
#elif VTK_SHADOW_MOMENTS == 3
  float squared = d * d;
  return vec4(d, squared, squared * d, squared * squared);
#else
  return vec4(vtkShadowWarpDepth(d).x, 0.0, 0.0, 0.0);
#endif
}
#endif
