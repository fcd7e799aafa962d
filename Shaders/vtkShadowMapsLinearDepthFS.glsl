// Casters of maps whose depth is linear in light space (TSM). The rasterizer's
// window depth is Z / W, with W varying across the map; W is recovered from the
// fragment's window position (1 / W is a plane over the map) and the depth is
// multiplied back by it.
uniform vec3 vtkShadowWindowToInverseW;

float vtkShadowLinearDepth(float windowDepth)
{
  float w = 1.0 / dot(vtkShadowWindowToInverseW, vec3(gl_FragCoord.xy, 1.0));
  return clamp(0.5 * (2.0 * windowDepth - 1.0) * w + 0.5, 0.0, 1.0);
}
