// The moments filterable maps store (vtkVarianceShadowMapRepresentation),
// shared by the casters, which store them, and the receivers, which warp their
// own depth the same way. Before this block:
//   VTK_SHADOW_MOMENTS 0 VSM, 1 EVSM2, 2 EVSM4, 3 MSM, 4 ESM;
//   VTK_SHADOW_POSITIVE_EXPONENT, VTK_SHADOW_NEGATIVE_EXPONENT (floats).
// Depths are light depths in [0, 1] (shadowmaps::LightDepth). A program that
// both casts and receives gets this block twice.
#ifndef VTK_SHADOW_MOMENTS_FUNCTIONS
#define VTK_SHADOW_MOMENTS_FUNCTIONS

// The exponential warps of depth moved to [-1, 1]: exp(c+ d) and -exp(-c- d),
// both increasing with depth.
vec2 vtkShadowWarpDepth(float depth)
{
  float d = 2.0 * depth - 1.0;
  return vec2(
    exp(VTK_SHADOW_POSITIVE_EXPONENT * d), -exp(-VTK_SHADOW_NEGATIVE_EXPONENT * d));
}

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
#elif VTK_SHADOW_MOMENTS == 3
  float squared = d * d;
  return vec4(d, squared, squared * d, squared * squared);
#else
  return vec4(vtkShadowWarpDepth(d).x, 0.0, 0.0, 0.0);
#endif
}
#endif
