// The receivers' transmittance lookup (shadowmaps::TransmittanceMaps), compiled
// in only while some caster is translucent (VTK_SHADOW_TRANSMITTANCE). Each
// layer holds beside its map what the translucent casters let through (rgb, a
// product) and the light depth of the nearest of them (a).
uniform sampler2DArray vtkShadowTransmittances;

// The nearest translucent surface's own light depth, kept in a 16-bit float
// (steps of at most 2^-11), must not shadow it: it and what lies before it
// get all the light.
const float VTK_SHADOW_TRANSMITTANCE_BIAS = 1.0 / 1024.0;

// What the receiver itself lets through where it is a translucent caster (set
// in main(); 0 for an opaque one). Beyond the nearest translucent surface the
// map's product holds the receiver once: it does not shadow itself.
vec3 vtkShadowOwnTransmittance = vec3(0.0);

vec3 vtkShadowTransmittance(vec2 mapCoord, float lightDepth, int layer)
{
  vec4 transmitted = texture(vtkShadowTransmittances, vec3(mapCoord, float(layer)));
  if (!(lightDepth > transmitted.a + VTK_SHADOW_TRANSMITTANCE_BIAS))
  {
    return vec3(1.0);
  }
  vec3 own = vtkShadowOwnTransmittance;
  return all(greaterThan(own, vec3(1.0 / 256.0))) ? min(transmitted.rgb / own, vec3(1.0))
                                                  : transmitted.rgb;
}
