// What the casters' branch of points drawn as spheres and lines drawn as tubes
// shares (vtkShadowMapsSpriteFS, vtkShadowMapsTubeFS): each finds where the
// ray of the map texel a fragment covers meets the shape it stands for, and
// writes that depth. The polygon offset every other caster's depth takes
// (glPolygonOffset: none for points in any case) does not reach a written
// depth: these take the same slope-scaled and constant offset here, in depth
// units (zero in linear-depth views, which offset the depth they store,
// vtkShadowMapsLinearDepthFS).
uniform mat4 vtkShadowImpostorWorldToClip;
uniform mat4 vtkShadowImpostorClipToWorld;
uniform vec2 vtkShadowImpostorDepthOffset;
uniform vec4 vtkShadowImpostorScale;
// Where the texel's ray leaves the shape (window depth, offset): the second
// surface of dual depth maps. Set with the depth where it enters.
float vtkShadowImpostorBackDepth = 1.0;

// The world point of the map's normalized device coordinates `ndc` at depth z.
vec3 vtkShadowImpostorRayPoint(vec2 ndc, float z)
{
  vec4 h = vtkShadowImpostorClipToWorld * vec4(ndc, z, 1.0);
  return h.xyz / h.w;
}

// The ray of the map texel the fragment covers, from the near plane (the
// casters' viewport is the whole layer, of vtkShadowImpostorScale.z texels;
// a point's square may lie off its centre's image: vtkShadowDrawPartInView).
void vtkShadowImpostorTexelRay(out vec3 origin, out vec3 direction)
{
  vec2 ndc = 2.0 * gl_FragCoord.xy / vtkShadowImpostorScale.z - 1.0;
  origin = vtkShadowImpostorRayPoint(ndc, -1.0);
  direction = normalize(vtkShadowImpostorRayPoint(ndc, 0.0) - origin);
}

// The offset window depth of the point `offset` (world units) from the point
// drawn at `clip`.
float vtkShadowImpostorOffsetDepth(vec4 clip, vec3 offset)
{
  vec4 h = clip + vtkShadowImpostorWorldToClip * vec4(offset, 0.0);
  float depth = 0.5 * h.z / h.w + 0.5;
  float slope = max(abs(dFdx(depth)), abs(dFdy(depth)));
  return clamp(
    depth + vtkShadowImpostorDepthOffset.x * slope + vtkShadowImpostorDepthOffset.y, 0.0, 1.0);
}
