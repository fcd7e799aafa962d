// Comparison of dual-depth maps (vtkDualDepthShadowMapRepresentation). Each
// texel holds the nearest caster surface along its light ray, Z1, and the next
// one, Z2 (the far value 1 where there is none). A receiver is compared with a
// virtual surface between the two, so that the casters' own lit faces, at Z1,
// are in front of it without any bias (thesis 000 on [WM94], [Woo92], [WE03]):
//   VTK_SHADOW_DUAL_MODE 0, second depth: Z2;
//                        1, midpoint: (Z1 + Z2) / 2;
//                        2, dual: Z1 + min((Z2 - Z1) / 2, offset).
// Where a texel has one surface (a lone open surface, or the edge of a caster),
// every mode takes Z1 + offset: a farther virtual surface would lose the shadow
// the surface casts, a nearer one would let it shadow its own lit face.
// `offset` is vtkShadowDualOffset texels of world size, converted to depth
// along the light ray at the receiver (vtkShadowDepthPerTexel). Each texel is
// compared with the receiver's tangent plane at the texel's centre
// (vtkShadowReceiverSlope), so a caster's lit face meets its own depth there
// and the virtual surface only has to clear the depth precision: thin casters
// need no bias either.
// vtkShadowMapsFilterFS builds the PCF family on vtkShadowCompare.

uniform sampler2DArray vtkShadowMaps;
uniform float vtkShadowDualOffset;

// The least gap kept between Z1 and the virtual surface: a few steps of 32-bit
// depth near 1, so that a caster whose two surfaces are closer than the depth
// precision (a sheet thinner than that) still lights its own face.
const float vtkShadowDepthPrecision = 4.0 / 16777216.0;

// The virtual surface of a texel's two stored depths, in either order: a
// one-pass map keeps the nearest front face in x and the nearest back face in
// y, and an open surface seen from behind has only the second.
float vtkShadowVirtualSurface(vec2 stored, float offset)
{
  float first = min(stored.x, stored.y);
  float second = max(stored.x, stored.y);
  float behind = offset;
  if (second < 1.0)
  {
    float gap = second - first;
#if VTK_SHADOW_DUAL_MODE == 0
    behind = gap;
#elif VTK_SHADOW_DUAL_MODE == 1
    behind = 0.5 * gap;
#else
    behind = min(0.5 * gap, offset);
#endif
  }
  return first + max(behind, vtkShadowDepthPrecision);
}

// The receiver's plane (vtkShadowReceiverSlope) is compared where the texel's
// depths were taken, its centre.
float vtkShadowCompareTexel(ivec2 texel, vec2 uv, float depth, int layer, float offset)
{
  int last = int(vtkShadowMapResolution) - 1;
  ivec2 clamped = clamp(texel, ivec2(0), ivec2(last));
  vec2 center = (vec2(clamped) + 0.5) / vtkShadowMapResolution;
  float planeDepth = depth + dot(vtkShadowReceiverSlope, center - uv);
  vec2 stored = texelFetch(vtkShadowMaps, ivec3(clamped, layer), 0).xy;
  return planeDepth <= vtkShadowVirtualSurface(stored, offset) ? 1.0 : 0.0;
}

#ifdef VTK_SHADOW_SIZED_LIGHTS
// For the soft shadows' blocker search (vtkShadowMapsSoftFS): the virtual
// surface of the texel at uv, moved along the receiver's plane from the
// texel's centre to uv, so that it lies in front of a receiver at uv exactly
// where vtkShadowCompare finds it shadowed there (x); the nearest caster
// surface, whose distance sets the penumbra in every mode (y).
vec2 vtkShadowBlockerDepth(vec2 uv, int layer)
{
  int last = int(vtkShadowMapResolution) - 1;
  ivec2 texel = clamp(ivec2(floor(uv * vtkShadowMapResolution)), ivec2(0), ivec2(last));
  vec2 center = (vec2(texel) + 0.5) / vtkShadowMapResolution;
  vec2 stored = texelFetch(vtkShadowMaps, ivec3(texel, layer), 0).xy;
  float offset = vtkShadowDualOffset * vtkShadowDepthPerTexel;
  float shift = dot(vtkShadowReceiverSlope, center - uv);
  return vec2(vtkShadowVirtualSurface(stored, offset) - shift, min(stored.x, stored.y));
}
#endif

// One comparison as the depth maps' hardware makes it: of the nearest texel
// (hard), or the bilinear weighting of the four around uv (the other filters).
float vtkShadowCompare(vec2 uv, float depth, int layer)
{
  float offset = vtkShadowDualOffset * vtkShadowDepthPerTexel;
  vec2 texels = uv * vtkShadowMapResolution;
#if VTK_SHADOW_FILTER == 0
  return vtkShadowCompareTexel(ivec2(floor(texels)), uv, depth, layer, offset);
#else
  vec2 st = texels - 0.5;
  ivec2 base = ivec2(floor(st));
  vec2 f = st - floor(st);
  float c00 = vtkShadowCompareTexel(base, uv, depth, layer, offset);
  float c10 = vtkShadowCompareTexel(base + ivec2(1, 0), uv, depth, layer, offset);
  float c01 = vtkShadowCompareTexel(base + ivec2(0, 1), uv, depth, layer, offset);
  float c11 = vtkShadowCompareTexel(base + ivec2(1, 1), uv, depth, layer, offset);
  return mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y);
#endif
}
