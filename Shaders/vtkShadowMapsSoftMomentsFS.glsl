// Soft shadows of lights with a size over moment maps
// (vtkVarianceShadowMapRepresentation), after vtkShadowMapsSoftKernelFS and the
// moments' lookup (vtkShadowMapsVarianceLookupFS). The blocker search and the
// filter each average the moments over a disc of the kernel, and the moments
// say the rest (Yang et al. 2010 for variance maps, Peters et al. 2016 for
// moment shadow maps): the fraction of the disc's occluders at or beyond the
// receiver is the same bound the hard lookup takes, and the mean depth of the
// others follows from it. A fixed number of taps, each one mipmapped sample
// over its share of the disc, averages a disc of any radius: the cost does not
// grow with the penumbra. Each tap's moments are moved by the depth that the
// receiver's plane there lies from its centre: over the disc the receiver is
// then one depth, and the moments of a receiver and a blocker, two depths,
// which the bounds hold exactly (the plane's spread over a wide disc would
// loosen them and widen the penumbra).
//
// ESM keeps no variance to bound a fraction with; EVSM2's one warp, exp(c+ d),
// squeezes blockers far in front of the receiver into the last digits of the
// moments' mean, where their own mean is lost (TestShadowSoft: the edge's
// penumbra had no 10-90% crossing); maps without mipmaps cannot average a
// wide disc in a few samples. These draw hard shadows
// (vtkVarianceShadowMapRepresentation::GetSoftShadowCode).

const int VTK_SHADOW_MOMENT_SEARCH_TAPS = 8;
const int VTK_SHADOW_MOMENT_FILTER_TAPS = 12;
// A trilinear sample spreads over about twice its level's texel (the level's
// box, then the interpolation between boxes): a tap asks for a level of half
// the side of its share of the disc. Smaller made no measurable difference to
// the penumbra's width (TestShadowSoft), the full side widened it 10-20%.
const float VTK_SHADOW_MOMENT_SIDE = 0.5;

// The moments of depths that all moved by `shift` (away from the light where
// positive). The warps scale: exp(c+ (2d - 1)) by exp(2 c+ shift) and
// -exp(-c- (2d - 1)) by exp(-2 c- shift), each held to what depth 1 or 0
// stores (beyond, the squares overflow single precision). Power moments
// expand binomially, in the centred depth where MSM stores Chebyshev moments.
vec4 vtkShadowShiftMoments(vec4 m, float shift)
{
#if VTK_SHADOW_MOMENTS == 0
  return vec4(m.x + shift, m.y + 2.0 * shift * m.x + shift * shift, 0.0, 0.0);
#elif VTK_SHADOW_MOMENTS == 1 || VTK_SHADOW_MOMENTS == 2
  float positive = min(2.0 * vtkShadowPositiveExponent * shift, 80.0);
  vec2 farthest = vec2(exp(vtkShadowPositiveExponent), exp(2.0 * vtkShadowPositiveExponent));
  vec2 warped = min(m.xy * exp(vec2(positive, 2.0 * positive)), farthest);
#if VTK_SHADOW_MOMENTS == 2
  float negative = min(-2.0 * vtkShadowNegativeExponent * shift, 80.0);
  vec2 nearest = vec2(exp(vtkShadowNegativeExponent), exp(2.0 * vtkShadowNegativeExponent));
  vec2 scaled = m.zw * exp(vec2(negative, 2.0 * negative));
  return vec4(warped, max(scaled.x, -nearest.x), min(scaled.y, nearest.y));
#else
  return vec4(warped, 0.0, 0.0);
#endif
#elif VTK_SHADOW_MOMENTS == 3
#if VTK_SHADOW_CHEBYSHEV_BASIS
  vec4 b = vtkShadowCenteredMoments(m);
  float s = 2.0 * shift;
#else
  vec4 b = m;
  float s = shift;
#endif
  float s2 = s * s;
  vec4 moved = vec4(b.x + s, b.y + 2.0 * s * b.x + s2, b.z + 3.0 * s * b.y + 3.0 * s2 * b.x + s2 * s,
    b.w + 4.0 * s * b.z + 6.0 * s2 * b.y + 4.0 * s2 * s * b.x + s2 * s2);
#if VTK_SHADOW_CHEBYSHEV_BASIS
  // Back to the stored basis (vtkShadowCenteredMoments' inverse).
  vec4 polynomials = vec4(moved.x, 2.0 * moved.y - 1.0, 4.0 * moved.z - 3.0 * moved.x,
    8.0 * moved.w - 8.0 * moved.y + 1.0);
  return 0.5 + 0.5 * polynomials;
#else
  return moved;
#endif
#else
  return m;
#endif
}

// The side of the square over which each of n taps averages a disc of `radius`.
float vtkShadowMomentTapSide(float radius, int n)
{
  return VTK_SHADOW_MOMENT_SIDE * radius * sqrt(3.14159265 / float(n));
}

// The receiver's light depth (unclamped), the sum of its squared changes per
// unit along the kernel's two axes (its plane's slope), and its decrease per
// unit toward the light (along a light ray the distance from a positional
// light falls at unit rate): what every disc of the kernel compares with.
struct vtkShadowReceiverDepth
{
  float Depth;
  float SlopeSquared;
  float PerDistance;
};

vtkShadowReceiverDepth vtkShadowReceiverDepthAt(
  vec3 positionVC, vtkShadowSoftKernel kernel, int light)
{
  vtkShadowReceiverDepth receiver;
  receiver.Depth = vtkShadowLightDepth(positionVC, light);
  float perUnit1 = vtkShadowLightDepth(positionVC + kernel.Axis1, light) - receiver.Depth;
  float perUnit2 = vtkShadowLightDepth(positionVC + kernel.Axis2, light) - receiver.Depth;
  receiver.SlopeSquared = perUnit1 * perUnit1 + perUnit2 * perUnit2;
  vec3 toward = vtkShadowTowardLightAt(positionVC, light);
  receiver.PerDistance =
    vtkShadowLights[light].DepthPerDistance - dot(vtkShadowLights[light].DepthPlane.xyz, toward);
  return receiver;
}

// The moments averaged over the kernel's disc of `radius`: n taps, each a
// mipmapped sample over about the tap's share of the disc's area, the sides of
// its square along the kernel's axes taken into the tap's own view, its
// moments moved to the receiver's depth at the centre. `inside`: how many taps
// fell in a map (the others do not count).
vec4 vtkShadowDiscMoments(vec3 positionVC, vtkShadowSoftKernel kernel,
  vtkShadowReceiverDepth receiver, float radius, int n, int light, int firstView, int view,
  int viewLayout, int count, int features, out float inside)
{
  float side = vtkShadowMomentTapSide(radius, n);
  vec4 sum = vec4(0.0);
  inside = 0.0;
  for (int i = 0; i < n; ++i)
  {
    vtkShadowTap tap;
    if (!vtkShadowKernelTapInMap(positionVC, kernel, i, n, radius, light, firstView, view,
          viewLayout, count, features, tap))
    {
      continue;
    }
    vec2 dx = vtkShadowMapCoord(vtkShadowMapTransform(
                                  firstView, tap.View, tap.VC + side * kernel.Axis1, features),
                tap.View, features).xy - tap.Map.xy;
    vec2 dy = vtkShadowMapCoord(vtkShadowMapTransform(
                                  firstView, tap.View, tap.VC + side * kernel.Axis2, features),
                tap.View, features).xy - tap.Map.xy;
    vec4 moments = textureGrad(vtkShadowMaps, vec3(tap.Map.xy, float(tap.View)), dx, dy);
    sum += vtkShadowShiftMoments(moments, receiver.Depth - vtkShadowLightDepth(tap.VC, light));
    inside += 1.0;
  }
  return inside > 0.0 ? sum / inside : sum;
}

// The least variance of the depths a tap averages around the kernel's centre:
// the receiver's own plane, linear there (moving the moments flattens the
// plane between taps, not within one), over the tap's footprint (twice its
// square's `side`, its trilinear sample's spread, and no less than the texel
// its bilinear sample spans) and the maps' blur, over the representation's
// floor.
float vtkShadowTapVariance(
  vtkShadowSoftKernel kernel, vtkShadowReceiverDepth receiver, float side, int view)
{
  float footprint = max(2.0 * side, kernel.Texel);
  float blur = vtkShadowMomentsBlurSigma * vtkShadowViews[view].FilterScale * kernel.Texel;
  return vtkShadowMinimumVariance +
    receiver.SlopeSquared * (footprint * footprint / 12.0 + blur * blur);
}

// The mean light depth of the occluders in front of a receiver at t, among
// depths with `moments` of which the fraction `lit` lies at or beyond t: the
// others taken at t (Yang et al.), in the space where the moments average the
// depth (linear or warped), and back.
float vtkShadowMeanBlockerDepth(vec4 moments, float t, float lit)
{
  float blocked = max(1.0 - lit, 1e-6);
#if VTK_SHADOW_MOMENTS == 2
  // The negative warp's gentler exponent keeps the difference's digits.
  float warped = (moments.z - lit * vtkShadowWarpDepth(t).y) / blocked;
  return 0.5 - 0.5 * log(max(-warped, 1e-30)) / vtkShadowNegativeExponent;
#elif VTK_SHADOW_MOMENTS == 3 && VTK_SHADOW_CHEBYSHEV_BASIS
  float centred = (vtkShadowCenteredMoments(moments).x - lit * (2.0 * t - 1.0)) / blocked;
  return 0.5 + 0.5 * centred;
#else
  return (moments.x - lit * t) / blocked;
#endif
}

// The distance along the ray from the receiver to its blockers over the
// kernel's disc of `radius`, from their mean depth; 0 where none is in front.
float vtkShadowMomentBlockerDistance(vec3 positionVC, vtkShadowSoftKernel kernel,
  vtkShadowReceiverDepth receiver, float radius, int light, int firstView, int view,
  int viewLayout, int count, int features)
{
  float inside;
  vec4 moments = vtkShadowDiscMoments(positionVC, kernel, receiver, radius,
    VTK_SHADOW_MOMENT_SEARCH_TAPS, light, firstView, view, viewLayout, count, features, inside);
  float t = receiver.Depth;
  float side = vtkShadowMomentTapSide(radius, VTK_SHADOW_MOMENT_SEARCH_TAPS);
  float lit = vtkShadowMomentsBound(
    moments, clamp(t, 0.0, 1.0), vtkShadowTapVariance(kernel, receiver, side, view));
  // Fewer blockers than half a tap's share of the disc are the bound's own
  // slack, not casters: their mean depth, divided by so small a fraction, is
  // noise (an open ground's penumbrae grew over its neighbours' shadows).
  if (inside == 0.0 || lit > 1.0 - 0.5 / float(VTK_SHADOW_MOMENT_SEARCH_TAPS))
  {
    return 0.0;
  }
  float blocker =
    clamp(vtkShadowMeanBlockerDepth(moments, clamp(t, 0.0, 1.0), lit), 0.0, max(t, 0.0));
  float perDistance = receiver.PerDistance;
  return perDistance > 0.0 ? max(t - blocker, 0.0) / perDistance : 0.0;
}

// Visibility of a sized light at a receiver (positionVC already moved along its
// normal) whose centre falls in view `view`.
float vtkShadowSoftVisibility(vec3 positionVC, vec3 normalVC, int light, int firstView, int view,
  int viewLayout, int count, int features)
{
  vtkShadowSoftKernel kernel =
    vtkShadowKernelAt(positionVC, normalVC, light, firstView, view, features);
  vtkShadowReceiverDepth receiver = vtkShadowReceiverDepthAt(positionVC, kernel, light);
  // As the depth maps' search (vtkShadowMapsSoftFS): over the disc where a
  // blocker can hide part of the light, then over the disc those blockers
  // reach, whose own distance holds at a contact.
  float search = kernel.SearchRadius;
  float blockerDistance = vtkShadowMomentBlockerDistance(
    positionVC, kernel, receiver, search, light, firstView, view, viewLayout, count, features);
  float nearer = max(
    vtkShadowPenumbraHalfWidth(blockerDistance, kernel.LightDistance, light), kernel.Texel);
  if (blockerDistance > 0.0 && nearer < search)
  {
    float again = vtkShadowMomentBlockerDistance(
      positionVC, kernel, receiver, nearer, light, firstView, view, viewLayout, count, features);
    blockerDistance = again > 0.0 ? again : blockerDistance;
  }
  // At least half a texel: a caster a texel or two wide (a pole far off) keeps
  // its umbra.
  float radius = max(
    vtkShadowPenumbraHalfWidth(blockerDistance, kernel.LightDistance, light), 0.5 * kernel.Texel);
  float inside;
  vec4 moments = vtkShadowDiscMoments(positionVC, kernel, receiver, radius,
    VTK_SHADOW_MOMENT_FILTER_TAPS, light, firstView, view, viewLayout, count, features, inside);
  if (inside == 0.0)
  {
    // A disc wider than the maps around a receiver at their rim: its own texel.
    moments = textureLod(vtkShadowMaps, vec3(kernel.Centre.xy, float(view)), 0.0);
  }
  float side = vtkShadowMomentTapSide(radius, VTK_SHADOW_MOMENT_FILTER_TAPS);
  return vtkShadowMomentsVisibility(moments, clamp(receiver.Depth, 0.0, 1.0),
    vtkShadowTapVariance(kernel, receiver, side, view));
}
