// The light depth (shadowmaps::LightDepth) of a position relative to the
// depth's origin: linear in light space and shared by all views of a light.
// Used by the casters' branch and by the volumes' marcher.
uniform vec4 vtkShadowLightDepthPlane;
uniform float vtkShadowLightDepthPerDistance;

float vtkShadowLightDepthOf(vec3 relative)
{
  float depth = dot(vtkShadowLightDepthPlane.xyz, relative) + vtkShadowLightDepthPlane.w +
    vtkShadowLightDepthPerDistance * length(relative);
  // A depth that is not a number (a degenerate view) stores the far value.
  return depth >= 0.0 ? min(depth, 1.0) : (depth < 0.0 ? 0.0 : 1.0);
}
