// The window depth of a point drawn as a sphere, while casting: between its
// centre's (the point's own) and that of its point nearest the light
// (vtkShadowMapsSpriteVS), by the sphere's normal towards the viewer of the
// map; linear in window depth, exact for orthographic views.
flat in float vtkShadowSpriteNearDepth;

float vtkShadowSpriteDepth()
{
  vec2 p = 2.0 * gl_PointCoord - 1.0;
  return mix(gl_FragCoord.z, vtkShadowSpriteNearDepth, sqrt(max(1.0 - dot(p, p), 0.0)));
}
