// Casters of maps whose depth is linear in light space (TSM) or is a spot's own
// post-perspective depth (warped spots). The rasterizer's window depth is Z / W,
// with W varying across the map; W is recovered from the fragment's window
// position (1 / W is a plane over the map) and the depth is multiplied back by it.
// Such views take their bias here, on the depth they store: the slope the
// rasterizer would offset by is that of Z / W, which a warp can make thousands
// of times steeper than the stored depth's. The slope-scaled term is capped: a
// warp's far texels are many times the map's mean, and a ground at a grazing
// light, offset by the slope across such a texel, went behind the poles on it.
// Receivers there take their offset along the normal, scaled by the texel.
uniform vec3 vtkShadowWindowToInverseW;
// x: slope-scaled factor, y: constant offset, z: cap of the slope-scaled term,
// all in depth units.
uniform vec3 vtkShadowLinearDepthBias;

float vtkShadowLinearDepth(float windowDepth)
{
  float w = 1.0 / dot(vtkShadowWindowToInverseW, vec3(gl_FragCoord.xy, 1.0));
  float depth = 0.5 * (2.0 * windowDepth - 1.0) * w + 0.5;
  float slope = max(abs(dFdx(depth)), abs(dFdy(depth)));
  float slopeScaled = min(vtkShadowLinearDepthBias.x * slope, vtkShadowLinearDepthBias.z);
  return clamp(depth + slopeScaled + vtkShadowLinearDepthBias.y, 0.0, 1.0);
}
