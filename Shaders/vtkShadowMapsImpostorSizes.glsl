// VTK's round impostors, points drawn as spheres and lines drawn as tubes, are
// sized in the scene camera's pixels: a radius of ZCalcR times the eye depth,
// ZCalcR being the point size (line width) over the renderer's width and the
// camera's P00. While casting ZCalcR holds the light camera's P00; these give
// the world radius the scene camera shows, and where points lie in the map.
uniform mat4 vtkShadowImpostorWorldToClip;
uniform mat4 vtkShadowImpostorClipToWorld;
// xyz: the direction towards the light (w = 0), or the light's position (w = 1).
uniform vec4 vtkShadowImpostorLight;
// The scene camera's eye depth of a world point p: dot(xyz, p) + w.
uniform vec4 vtkShadowImpostorSceneDepth;
// x: the light camera's P00 over the scene camera's; y: 1 for a parallel scene
// camera (no eye depth in the radius); z: the map's size in texels; w: the
// largest point size the GL draws.
uniform vec4 vtkShadowImpostorScale;

vec3 vtkShadowImpostorWorld(vec4 clip)
{
  vec4 h = vtkShadowImpostorClipToWorld * clip;
  return h.xyz / h.w;
}

// The clip position `offset` (world units) from the point drawn at `clip`.
// Offsets from the drawn point rather than positions: a point recovered through
// the inverse of a perspective view can carry float error along the light's
// rays, which an offset keeps out of the positions the casters draw.
vec4 vtkShadowImpostorClipOffset(vec4 clip, vec3 offset)
{
  return clip + vtkShadowImpostorWorldToClip * vec4(offset, 0.0);
}

float vtkShadowImpostorRadius(vec3 world)
{
  // Behind the scene camera nothing is drawn: no radius (rather than a
  // negative one that would turn a tube's quad inside out).
  float eyeDepth = vtkShadowImpostorScale.y > 0.5 ? 1.0 :
    max(dot(vtkShadowImpostorSceneDepth.xyz, world) + vtkShadowImpostorSceneDepth.w, 0.0);
  return ZCalcR * vtkShadowImpostorScale.x * eyeDepth;
}

// The radius of the circle where the light's tangent cone to a sphere (or the
// tangent planes to a tube) of `radius` at `world` meet the plane through it
// across the light: wider than the shape, by more the nearer a positional
// light is.
float vtkShadowImpostorConeRadius(vec3 world, float radius)
{
  float distance = vtkShadowImpostorLight.w > 0.5 ? length(vtkShadowImpostorLight.xyz - world) : 0.0;
  float ratio = distance > 0.0 ? min(radius / distance, 0.99) : 0.0;
  return radius / sqrt(1.0 - ratio * ratio);
}

vec3 vtkShadowImpostorToLight(vec3 world)
{
  return vtkShadowImpostorLight.w > 0.5 ? normalize(vtkShadowImpostorLight.xyz - world) :
    vtkShadowImpostorLight.xyz;
}

// A unit vector across `direction`, and across `preferred` where it can be.
vec3 vtkShadowImpostorAcross(vec3 direction, vec3 preferred)
{
  vec3 across = cross(direction, preferred);
  if (dot(across, across) <= 1e-12 * dot(direction, direction) * dot(preferred, preferred))
  {
    vec3 unit = normalize(direction);
    across = cross(unit, abs(unit.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0));
  }
  return normalize(across);
}
