// Points drawn as spheres (RenderPointsAsSpheres) are squares that the
// rasteriser sizes in pixels and the fragment shader rounds. Drawn into a map
// as they are, they would be the point's size in map texels. While casting,
// this sizes each point to the sphere the scene camera shows
// (vtkShadowMapsImpostorSizes), measured in the map's texels, and passes the
// window depth of the sphere's point nearest the light (vtkShadowMapsSpriteFS
// mixes it with the centre's by the sphere's normal).
flat out float vtkShadowSpriteNearDepth;

void vtkShadowSizeSprite()
{
  vec3 p = vtkShadowImpostorWorld(gl_Position);
  float radius = vtkShadowImpostorRadius(p);
  vec3 toLight = vtkShadowImpostorToLight(p);
  vec4 rim = vtkShadowImpostorClip(p + radius * vtkShadowImpostorAcross(toLight, vec3(0.0, 0.0, 1.0)));
  // The rim's offset in normalized device coordinates is the radius over half
  // the map: the diameter in texels is that offset times the map's size.
  gl_PointSize = max(length(rim.xy / rim.w - gl_Position.xy / gl_Position.w) * vtkShadowImpostorScale.z, 1.0);
  vtkShadowSpriteNearDepth = vtkShadowImpostorWindowDepth(p + radius * toLight);
}
