// The oracle's Embree calls that differ between Embree 3 (Debian 12 and 13) and
// Embree 4 (sid): the header's folder, and the ray queries, which took an
// intersect context in 3 and take optional arguments in 4. The oracle calls
// these two functions and includes no Embree header itself.
#ifndef ShadowOracleEmbree_h
#define ShadowOracleEmbree_h

#if __has_include(<embree4/rtcore.h>)
#include <embree4/rtcore.h>
#define SHADOWMAPS_EMBREE_4 1
#else
#include <embree3/rtcore.h>
#define SHADOWMAPS_EMBREE_4 0
#endif

namespace shadoworacle
{
/// The nearest hit along `rayHit.ray`, written into `rayHit.hit`.
inline void IntersectNearest(RTCScene scene, RTCRayHit& rayHit)
{
#if SHADOWMAPS_EMBREE_4
  rtcIntersect1(scene, &rayHit);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene, &context, &rayHit);
#endif
}

/// Whether anything lies along `ray`; Embree sets its tfar to -inf if so.
inline void TestOcclusion(RTCScene scene, RTCRay& ray)
{
#if SHADOWMAPS_EMBREE_4
  rtcOccluded1(scene, &ray);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(scene, &context, &ray);
#endif
}
}

#endif
