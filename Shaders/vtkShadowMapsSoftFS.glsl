// Percentage-closer soft shadows (a blocker search, a penumbra estimate, a
// filter of that size; Fernando 2005) over maps of depths, after
// vtkShadowMapsSoftKernelFS, whose kernels they use. The representation gives
//   vec2 vtkShadowBlockerDepth(vec2 uv, int layer)  the depth in front of which a
//     receiver at uv is shadowed (x) and the nearest caster's depth (y)
//   float vtkShadowCompare(vec2 uv, float depth, int layer)
// in its map's depth convention (vtkShadowMapCoord's). Neither kernel has a
// ceiling: the taps are as many whatever the radius, and a kernel cut short
// would draw a penumbra too narrow.

const int VTK_SHADOW_BLOCKER_TAPS = 16;
const int VTK_SHADOW_SOFT_TAPS = 32;

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

// Casters in front of the receiver's plane over the kernel's disc of `radius`:
// how many taps found one (x), their mean distance along the ray (y) and how
// many taps fell in a map (z).
vec3 vtkShadowSearchBlockers(vec3 positionVC, vtkShadowSoftKernel kernel, float radius,
  int light, int firstView, int view, int viewLayout, int count, int features)
{
  float blockers = 0.0;
  float distance = 0.0;
  float inside = 0.0;
  for (int i = 0; i < VTK_SHADOW_BLOCKER_TAPS; ++i)
  {
    vtkShadowTap tap;
    if (!vtkShadowKernelTapInMap(positionVC, kernel, i, VTK_SHADOW_BLOCKER_TAPS, radius, light,
          firstView, view, viewLayout, count, features, tap))
    {
      continue;
    }
    inside += 1.0;
    vec2 stored = vtkShadowBlockerDepth(tap.Map.xy, tap.View);
    if (stored.x < tap.Map.z)
    {
      blockers += 1.0;
      distance += vtkShadowDistanceToDepth(
        tap.VC, tap.Clip, tap.Map, stored.y, light, firstView, tap.View, features);
    }
  }
  return vec3(blockers, blockers > 0.0 ? distance / blockers : 0.0, inside);
}

// Visibility of a sized light at a receiver (positionVC already moved along its
// normal) whose centre falls in view `view`.
float vtkShadowSoftVisibility(vec3 positionVC, vec3 normalVC, int light, int firstView, int view,
  int viewLayout, int count, int features)
{
  vtkShadowSoftKernel kernel =
    vtkShadowKernelAt(positionVC, normalVC, light, firstView, view, features);
  vec3 centre = kernel.Centre;
  float texel = kernel.Texel;

  // Blocker search over the disc where a blocker can hide part of the light,
  // then again over the disc the blockers found there reach: the first disc
  // also holds casters beyond the receiver's own (the rest of a wall whose
  // foot it stands at), whose distance would widen a contact's penumbra.
  float search = kernel.SearchRadius;
  vec3 found = vtkShadowSearchBlockers(
    positionVC, kernel, search, light, firstView, view, viewLayout, count, features);
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
  float nearer =
    max(vtkShadowPenumbraHalfWidth(blockerDistance, kernel.LightDistance, light), texel);
  if (nearer < search)
  {
    found = vtkShadowSearchBlockers(
      positionVC, kernel, nearer, light, firstView, view, viewLayout, count, features);
    blockerDistance = found.x > 0.0 ? found.y : blockerDistance;
  }
  float penumbra = vtkShadowPenumbraHalfWidth(blockerDistance, kernel.LightDistance, light);
#if VTK_SHADOW_FILTER == 0
  float radius = max(penumbra, 0.5 * texel);
#else
  // The maps' bilinear comparison blurs over about half a texel more. Below a
  // texel the penumbra is the comparison's own: a floor of half a texel (as the
  // nearest comparison above) let light into the umbra's edge pixel (bench
  // --setups soft: umbra purity 0 to 10 points lower than with this quarter).
  float radius = max(penumbra - 0.5 * texel, 0.25 * texel);
#endif

  // A disc of the penumbra's half width over the map's comparisons; taps
  // beyond the maps do not count.
  float lit = 0.0;
  float inside = 0.0;
  for (int i = 0; i < VTK_SHADOW_SOFT_TAPS; ++i)
  {
    vtkShadowTap tap;
    if (vtkShadowKernelTapInMap(positionVC, kernel, i, VTK_SHADOW_SOFT_TAPS, radius, light,
          firstView, view, viewLayout, count, features, tap))
    {
      lit += vtkShadowCompare(tap.Map.xy, tap.Map.z, tap.View);
      inside += 1.0;
    }
  }
  return inside > 0.0 ? lit / inside : vtkShadowCompare(centre.xy, centre.z, view);
}
