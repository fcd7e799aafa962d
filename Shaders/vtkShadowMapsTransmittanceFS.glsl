// The receivers' transmittance lookup (shadowmaps::TransmittanceMaps), compiled
// in only while some caster is translucent (VTK_SHADOW_TRANSMITTANCE). Each
// layer holds beside its map what the translucent casters let through (rgb, a
// product) and the light depth of the nearest of them (a), both 32-bit floats.
uniform sampler2DArray vtkShadowTransmittances;

// The nearest translucent surface, lit directly, and what lies between it and
// the light keep all the light. Its stored depth is already moved back by
// its slope over two texels (vtkShadowTransmittedDepth); this covers the
// rounding of the light depth and its interpolation.
const float VTK_SHADOW_TRANSMITTANCE_BIAS = 1.0 / 65536.0;

// What the receiver itself lets through where it is a translucent caster
// whose share the maps hold (set in main() for such props; 0 otherwise).
// Beyond the nearest translucent surface the product holds the receiver once:
// it does not shadow itself. A channel it stops all but 1/256 of cannot be
// divided out and is taken as it is.
vec3 vtkShadowOwnTransmittance = vec3(0.0);

// One texel's transmittance for a receiver at lightDepth.
vec3 vtkShadowTexelTransmittance(ivec3 texel, float lightDepth)
{
  vec4 transmitted = texelFetch(vtkShadowTransmittances, texel, 0);
  if (!(lightDepth > transmitted.a + VTK_SHADOW_TRANSMITTANCE_BIAS))
  {
    return vec3(1.0);
  }
  vec3 own = vtkShadowOwnTransmittance;
  vec3 divided = mix(transmitted.rgb, transmitted.rgb / max(own, vec3(1e-30)),
    greaterThan(own, vec3(1.0 / 256.0)));
  return clamp(divided, 0.0, 1.0);
}

// Each of the four nearest texels compared with the receiver's depth on its
// own, then weighted bilinearly: a texel's depth is never averaged with its
// neighbour's (or with the empty texels' far value at a caster's border).
vec3 vtkShadowTransmittance(vec2 mapCoord, float lightDepth, int layer)
{
  ivec2 size = textureSize(vtkShadowTransmittances, 0).xy;
  vec2 texel = mapCoord * vec2(size) - 0.5;
  ivec2 base = ivec2(floor(texel));
  vec2 f = texel - vec2(base);
  ivec2 last = size - 1;
  vec3 t00 = vtkShadowTexelTransmittance(ivec3(clamp(base, ivec2(0), last), layer), lightDepth);
  vec3 t10 = vtkShadowTexelTransmittance(
    ivec3(clamp(base + ivec2(1, 0), ivec2(0), last), layer), lightDepth);
  vec3 t01 = vtkShadowTexelTransmittance(
    ivec3(clamp(base + ivec2(0, 1), ivec2(0), last), layer), lightDepth);
  vec3 t11 = vtkShadowTexelTransmittance(
    ivec3(clamp(base + ivec2(1, 1), ivec2(0), last), layer), lightDepth);
  return mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
}
