// Points drawn as spheres (RenderPointsAsSpheres) are squares that the
// rasteriser sizes in pixels and the fragment shader rounds. Drawn into a map
// as they are, they would be the point's size in map texels. While casting,
// this sizes each point to the sphere the scene camera shows (VTK's rule: a
// radius of ZCalcR times the eye depth, ZCalcR being the point size over the
// width and the camera's P00, here the light camera's), measured in the map's
// texels, and passes the window depth of the sphere's point nearest the light
// (vtkShadowMapsSpriteFS mixes it with the centre's by the sphere's normal).
uniform mat4 vtkShadowSpriteWorldToClip;
uniform mat4 vtkShadowSpriteClipToWorld;
// xyz: the direction towards the light (w = 0), or the light's position (w = 1).
uniform vec4 vtkShadowSpriteLight;
// The scene camera's eye depth of a world point p: dot(xyz, p) + w.
uniform vec4 vtkShadowSpriteSceneDepth;
// x: the light camera's P00 over the scene camera's; y: 1 for a parallel scene
// camera (no eye depth in the radius); z: the map's size in texels.
uniform vec3 vtkShadowSpriteScale;
flat out float vtkShadowSpriteNearDepth;

void vtkShadowSizeSprite()
{
  vec4 h = vtkShadowSpriteClipToWorld * gl_Position;
  vec3 p = h.xyz / h.w;
  float eyeDepth = vtkShadowSpriteScale.y > 0.5 ? 1.0 :
    dot(vtkShadowSpriteSceneDepth.xyz, p) + vtkShadowSpriteSceneDepth.w;
  float radius = ZCalcR * vtkShadowSpriteScale.x * eyeDepth;
  vec3 toLight = vtkShadowSpriteLight.w > 0.5 ? normalize(vtkShadowSpriteLight.xyz - p) :
    vtkShadowSpriteLight.xyz;
  vec3 across = normalize(cross(toLight, abs(toLight.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0)));
  vec4 rim = vtkShadowSpriteWorldToClip * vec4(p + radius * across, 1.0);
  vec4 nearest = vtkShadowSpriteWorldToClip * vec4(p + radius * toLight, 1.0);
  // The rim's offset in normalized device coordinates is the radius over half
  // the map: the diameter in texels is that offset times the map's size.
  gl_PointSize = max(length(rim.xy / rim.w - gl_Position.xy / gl_Position.w) * vtkShadowSpriteScale.z, 1.0);
  vtkShadowSpriteNearDepth = 0.5 * nearest.z / nearest.w + 0.5;
}
