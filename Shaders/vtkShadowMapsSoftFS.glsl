// Contact-hardening soft shadows of lights with a size (percentage-closer soft
// shadows: a blocker search, a penumbra estimate, a filter of that size;
// Fernando 2005), appended after a representation's lookup when a light has a
// size (VTK_SHADOW_SIZED_LIGHTS). The representation gives
//   float vtkShadowBlockerDepth(vec2 uv, int layer)  the nearest caster's depth
//   float vtkShadowCompare(vec2 uv, float depth, int layer)
// in its map's depth convention (vtkShadowMapCoord's).
//
// Both kernels are discs in world space, centred on the receiver, in the plane
// at right angles to its light ray, sheared along the ray onto the receiver's
// own plane (so that a flat receiver's taps lie on it and cannot shadow it).
// Each tap is a world point taken through its view's own matrix: the kernel
// keeps its world size whatever the map's texel size there, under every warp,
// in every cascade, and in the face of a cube that holds the tap, so it
// crosses faces and tiles without a seam. The warp's local texel size enters
// only as the floor of both kernels (about a texel, below which a narrower
// penumbra cannot be resolved). Neither has a ceiling: the taps are as many whatever the
// radius, and a kernel cut short would draw a penumbra too narrow.
//
// Under a disc light the visible fraction behind one straight edge is the
// fraction of a disc cut by a line; a uniform disc kernel of the penumbra's
// half width over a hard map is exactly that, so the taps cover a disc
// evenly (a Vogel spiral, turned per map texel so that the pattern stays on
// the light's texels and does not crawl as the camera moves).

const int VTK_SHADOW_BLOCKER_TAPS = 16;
const int VTK_SHADOW_SOFT_TAPS = 32;
const float VTK_SHADOW_GOLDEN_ANGLE = 2.39996323;
const float VTK_SHADOW_MOST_STRETCH = 4.0;

// Tap i of n of a disc of radius 1, evenly spread, turned by `rotation` (cos, sin).
vec2 vtkShadowDiscTap(int i, int n, vec2 rotation)
{
  float radius = sqrt((float(i) + 0.5) / float(n));
  float angle = float(i) * VTK_SHADOW_GOLDEN_ANGLE;
  vec2 p = radius * vec2(cos(angle), sin(angle));
  return vec2(p.x * rotation.x - p.y * rotation.y, p.x * rotation.y + p.y * rotation.x);
}

// The view that holds a tap of a kernel centred in view `view`: the light's
// views that part space among themselves (cube faces, tiles) pick their own;
// cascades keep the receiver's, whose map holds the kernel around it.
int vtkShadowTapView(vec3 tapVC, int light, int firstView, int view, int viewLayout, int count,
  int features)
{
  if (viewLayout == VTK_SHADOW_LAYOUT_CUBE_FACES || viewLayout == VTK_SHADOW_LAYOUT_TILES ||
    viewLayout == VTK_SHADOW_LAYOUT_PERSPECTIVE_CUBE)
  {
    return vtkShadowSelectView(tapVC, vec3(0.0), light, firstView, viewLayout, count, features);
  }
  return view;
}

// A kernel's tap in the maps: the view that holds it, its clip and map
// coordinates; false outside that view's map.
bool vtkShadowTapInMap(vec3 tapVC, int light, int firstView, int view, int viewLayout, int count,
  int features, out int tapView, out vec4 tapClip, out vec3 tapMap)
{
  tapView = vtkShadowTapView(tapVC, light, firstView, view, viewLayout, count, features);
  tapClip = vtkShadowMapTransform(firstView, tapView, tapVC, features);
  tapMap = vtkShadowMapCoord(tapClip, tapView, features);
  return vtkShadowInsideMap(tapClip, tapView, features);
}

// Unit vector from a point toward the light.
vec3 vtkShadowTowardLightAt(vec3 pointVC, int light)
{
  vec4 toward = vtkShadowLights[light].TowardLightVC;
  return normalize(toward.xyz - toward.w * pointVC);
}

// How far along its light ray a blocker may lie from a receiver: to where the
// ray enters the scene (the light depth, which spans the scene, in world units).
float vtkShadowBlockerReach(vec3 pointVC, int light)
{
  vec4 plane = vtkShadowLights[light].DepthPlane;
  vec3 relative = pointVC - vtkShadowLights[light].DepthOrigin;
  float perDistance = vtkShadowLights[light].DepthPerDistance;
  float depth = dot(plane.xyz, relative) + plane.w + perDistance * length(relative);
  return max(depth, 0.0) / max(length(plane.xyz) + perDistance, 1e-30);
}

// Half width, at the receiver, of the shadow a blocker `blockerDistance` away
// along the ray casts: the light's size seen from the receiver (a sun's
// tan(half angle), a sphere's radius over the distance to it) times the
// blocker's distance, over what remains of the way to a positional light.
float vtkShadowPenumbraHalfWidth(float blockerDistance, float lightDistance, int light)
{
  float size = vtkShadowLights[light].Size;
  if (vtkShadowLights[light].TowardLightVC.w == 0.0)
  {
    return size * blockerDistance;
  }
  return size * blockerDistance / max(lightDistance - blockerDistance, 1e-3 * lightDistance);
}

// Distance from a tap along its light ray to the caster whose depth the map
// stores there. Along the ray the map coordinates stay put and the depth is a
// ratio of two linear functions of the distance, from the tap's clip
// coordinates and those of a point one unit further toward the light.
float vtkShadowDistanceToDepth(vec3 tapVC, vec4 tapClip, vec3 tapMap, float storedDepth,
  int light, int firstView, int view, int features)
{
  float depth = storedDepth;
  vec3 inverseW = vtkShadowViews[view].DepthInverseW;
  if (vtkShadowHas(features, VTK_SHADOW_FEATURE_LINEAR_DEPTHS) && inverseW != vec3(0.0))
  {
    depth = (storedDepth - 0.5) * dot(inverseW, vec3(tapMap.xy, 1.0)) + 0.5;
  }
  vec3 toward = vtkShadowTowardLightAt(tapVC, light);
  vec4 perUnit = vtkShadowMapTransform(firstView, view, tapVC + toward, features) - tapClip;
  float denominator = perUnit.z - depth * perUnit.w;
  if (abs(denominator) < 1e-30)
  {
    return 0.0;
  }
  return max((depth * tapClip.w - tapClip.z) / denominator, 0.0);
}

// Casters in front of the receiver's plane over a disc of `radius` (world, at
// right angles to the light ray) around the receiver: how many taps found one
// (x), their mean distance along the ray (y) and how many taps fell in a map
// (z).
vec3 vtkShadowSearchBlockers(vec3 positionVC, vec3 axis1, vec3 axis2, float radius,
  vec2 rotation, int light, int firstView, int view, int viewLayout, int count, int features)
{
  float blockers = 0.0;
  float distance = 0.0;
  float inside = 0.0;
  for (int i = 0; i < VTK_SHADOW_BLOCKER_TAPS; ++i)
  {
    vec2 disc = vtkShadowDiscTap(i, VTK_SHADOW_BLOCKER_TAPS, rotation) * radius;
    vec3 tapVC = positionVC + disc.x * axis1 + disc.y * axis2;
    int tapView;
    vec4 tapClip;
    vec3 tapMap;
    if (!vtkShadowTapInMap(
          tapVC, light, firstView, view, viewLayout, count, features, tapView, tapClip, tapMap))
    {
      continue;
    }
    inside += 1.0;
    float stored = vtkShadowBlockerDepth(tapMap.xy, tapView);
    if (stored < tapMap.z)
    {
      blockers += 1.0;
      distance += vtkShadowDistanceToDepth(
        tapVC, tapClip, tapMap, stored, light, firstView, tapView, features);
    }
  }
  return vec3(blockers, blockers > 0.0 ? distance / blockers : 0.0, inside);
}

// Visibility of a sized light at a receiver (positionVC already moved along its
// normal) whose centre falls in view `view`.
float vtkShadowSoftVisibility(vec3 positionVC, vec3 normalVC, int light, int firstView, int view,
  int viewLayout, int count, int features)
{
  vec3 toward = vtkShadowTowardLightAt(positionVC, light);
  vec4 towardLight = vtkShadowLights[light].TowardLightVC;
  float lightDistance = length(towardLight.xyz - towardLight.w * positionVC);
  // The kernel's axes: at right angles to the ray, sheared along it onto the
  // receiver's plane (taps that left the plane would shadow it). Where the
  // light grazes the receiver the disc stretches along the plane as the
  // penumbra does, but no further than VTK_SHADOW_MOST_STRETCH times: beyond
  // that the plane leaves the surface (into the ground at a wall's foot).
  float facing = max(dot(normalVC, toward), 1e-3);
  vec3 side = abs(toward.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 axis1 = normalize(cross(toward, side));
  vec3 axis2 = cross(toward, axis1);
  axis1 -= toward * (dot(normalVC, axis1) / facing);
  axis2 -= toward * (dot(normalVC, axis2) / facing);
  axis1 *= min(1.0, VTK_SHADOW_MOST_STRETCH / length(axis1));
  axis2 *= min(1.0, VTK_SHADOW_MOST_STRETCH / length(axis2));

  float texel = vtkShadowTexelWorldSize(positionVC, light, firstView, view, features);
  vec3 centre = vtkShadowMapCoord(
    vtkShadowMapTransform(firstView, view, positionVC, features), view, features);
  vec2 rotation = texture(vtkShadowNoise, centre.xy * vtkShadowMapResolution / 32.0).xy;

  // Blocker search over the disc where a blocker can hide part of the light,
  // then again over the disc the blockers found there reach: the first disc
  // also holds casters beyond the receiver's own (the rest of a wall whose
  // foot it stands at), whose distance would widen a contact's penumbra.
  float reach = vtkShadowBlockerReach(positionVC, light);
  if (towardLight.w != 0.0)
  {
    reach = min(reach, 0.8 * lightDistance);
  }
  float search = max(vtkShadowPenumbraHalfWidth(reach, lightDistance, light), texel);
  vec3 found = vtkShadowSearchBlockers(positionVC, axis1, axis2, search, rotation, light,
    firstView, view, viewLayout, count, features);
  if (found.z == 0.0)
  {
    // A disc wider than the maps around a receiver at their rim: the hard shadow.
    return vtkShadowCompare(centre.xy, centre.z, view);
  }
  if (found.x == 0.0)
  {
    // A caster thinner than the taps' spacing (a pole, a wire) may slip
    // between them: the hard shadow of the centre still holds.
    return vtkShadowCompare(centre.xy, centre.z, view);
  }
  float blockerDistance = found.y;
  float nearer = max(vtkShadowPenumbraHalfWidth(blockerDistance, lightDistance, light), texel);
  if (nearer < search)
  {
    found = vtkShadowSearchBlockers(positionVC, axis1, axis2, nearer, rotation, light, firstView,
      view, viewLayout, count, features);
    blockerDistance = found.x > 0.0 ? found.y : blockerDistance;
  }
  float penumbra = vtkShadowPenumbraHalfWidth(blockerDistance, lightDistance, light);
#if VTK_SHADOW_FILTER == 0
  float radius = max(penumbra, 0.5 * texel);
#else
  // The maps' bilinear comparison blurs over about half a texel more.
  float radius = max(penumbra - 0.5 * texel, 0.5 * texel);
#endif

  // A disc of the penumbra's half width over the map's comparisons; taps
  // beyond the maps do not count.
  float lit = 0.0;
  float inside = 0.0;
  for (int i = 0; i < VTK_SHADOW_SOFT_TAPS; ++i)
  {
    vec2 disc = vtkShadowDiscTap(i, VTK_SHADOW_SOFT_TAPS, rotation) * radius;
    vec3 tapVC = positionVC + disc.x * axis1 + disc.y * axis2;
    int tapView;
    vec4 tapClip;
    vec3 tapMap;
    if (vtkShadowTapInMap(
          tapVC, light, firstView, view, viewLayout, count, features, tapView, tapClip, tapMap))
    {
      lit += vtkShadowCompare(tapMap.xy, tapMap.z, tapView);
      inside += 1.0;
    }
  }
  return inside > 0.0 ? lit / inside : vtkShadowCompare(centre.xy, centre.z, view);
}
