// What the soft shadows of lights with a size (VTK_SHADOW_SIZED_LIGHTS) share,
// whatever the maps store: the kernel, its taps, and the penumbra's geometry.
// A representation's soft code (vtkShadowMapsSoftFS for depth maps,
// vtkShadowMapsSoftMomentsFS for moments) follows this block and defines
// vtkShadowSoftVisibility.
//
// Kernels are discs in world space, centred on the receiver, in the plane at
// right angles to its light ray, sheared along the ray onto the receiver's own
// plane (so that a flat receiver's taps lie on it and cannot shadow it). Each
// tap is a world point taken through its view's own matrix: the kernel keeps
// its world size whatever the map's texel size there, under every warp, in
// every cascade, and in the face of a cube that holds the tap, so it crosses
// faces and tiles without a seam. The warp's local texel size enters only as
// the floor of the kernels (about a texel, below which a narrower penumbra
// cannot be resolved).
//
// Under a disc light the visible fraction behind one straight edge is the
// fraction of a disc cut by a line; a uniform disc kernel of the penumbra's
// half width is exactly that, so the taps cover a disc evenly (a Vogel
// spiral, turned per map texel so that the pattern stays on the light's
// texels and does not crawl as the camera moves).

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

// A receiver's kernel: its two axes (world, a unit radius each), the light's
// distance, the map's texel size there, the taps' turn, the centre's map
// coordinates, and the radius of the first blocker search.
struct vtkShadowSoftKernel
{
  vec3 Axis1;
  vec3 Axis2;
  float LightDistance;
  float Texel;
  vec2 Rotation;
  vec3 Centre;
  float SearchRadius;
};

vtkShadowSoftKernel vtkShadowKernelAt(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int view, int features)
{
  vtkShadowSoftKernel kernel;
  vec3 toward = vtkShadowTowardLightAt(positionVC, light);
  vec4 towardLight = vtkShadowLights[light].TowardLightVC;
  kernel.LightDistance = length(towardLight.xyz - towardLight.w * positionVC);
  // The axes: at right angles to the ray, sheared along it onto the
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
  kernel.Axis1 = axis1 * min(1.0, VTK_SHADOW_MOST_STRETCH / length(axis1));
  kernel.Axis2 = axis2 * min(1.0, VTK_SHADOW_MOST_STRETCH / length(axis2));

  kernel.Texel = vtkShadowTexelWorldSize(positionVC, light, firstView, view, features);
  kernel.Centre = vtkShadowMapCoord(
    vtkShadowMapTransform(firstView, view, positionVC, features), view, features);
  kernel.Rotation =
    texture(vtkShadowNoise, kernel.Centre.xy * vtkShadowMapResolution / 32.0).xy;

  // The first search covers the disc where a blocker can hide part of the
  // light: as far along the ray as the scene reaches.
  float reach = vtkShadowBlockerReach(positionVC, light);
  if (towardLight.w != 0.0)
  {
    reach = min(reach, 0.8 * kernel.LightDistance);
  }
  kernel.SearchRadius =
    max(vtkShadowPenumbraHalfWidth(reach, kernel.LightDistance, light), kernel.Texel);
  return kernel;
}

// A kernel's tap: its world point, the view that holds it, its clip and map
// coordinates.
struct vtkShadowTap
{
  vec3 VC;
  int View;
  vec4 Clip;
  vec3 Map;
};

// Tap i of n of the kernel's disc of `radius` around positionVC (whose centre
// falls in view `view`); false where it falls outside its view's map.
bool vtkShadowKernelTapInMap(vec3 positionVC, vtkShadowSoftKernel kernel, int i, int n,
  float radius, int light, int firstView, int view, int viewLayout, int count, int features,
  out vtkShadowTap tap)
{
  vec2 disc = vtkShadowDiscTap(i, n, kernel.Rotation) * radius;
  tap.VC = positionVC + disc.x * kernel.Axis1 + disc.y * kernel.Axis2;
  tap.View = vtkShadowTapView(tap.VC, light, firstView, view, viewLayout, count, features);
  tap.Clip = vtkShadowMapTransform(firstView, tap.View, tap.VC, features);
  tap.Map = vtkShadowMapCoord(tap.Clip, tap.View, features);
  return vtkShadowInsideMap(tap.Clip, tap.View, features);
}
