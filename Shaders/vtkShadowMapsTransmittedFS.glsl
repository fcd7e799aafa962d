// What a translucent caster of colour c and opacity a lets through, per
// channel: (1 - a)(1 - a + a c) (vtkAbstractShadowMapPass::GetTransmittance).
// Used by the casters' branch and, slice by slice, by the volumes' marcher.
// (Parameter names unlike the mapper's variables, which the pass looks for.)
vec3 vtkShadowTransmitted(vec3 c, float alpha)
{
  float a = clamp(alpha, 0.0, 1.0);
  return (1.0 - a) * ((1.0 - a) + a * clamp(c, 0.0, 1.0));
}
