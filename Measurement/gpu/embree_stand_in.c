/* Stands in for Embree in the GPU bundle (make_bundle.sh): vtkshadows speed
   traces no ray, and a call would be a bug, so each aborts. */
#include <stdlib.h>
#define STAND_IN(name) \
  void* name(void) { abort(); }
STAND_IN(rtcAttachGeometry) STAND_IN(rtcCommitGeometry) STAND_IN(rtcCommitScene)
STAND_IN(rtcGetDeviceError) STAND_IN(rtcIntersect1) STAND_IN(rtcNewDevice)
STAND_IN(rtcNewGeometry) STAND_IN(rtcNewScene) STAND_IN(rtcOccluded1)
STAND_IN(rtcReleaseDevice) STAND_IN(rtcReleaseGeometry) STAND_IN(rtcReleaseScene)
STAND_IN(rtcSetNewGeometryBuffer) STAND_IN(rtcSetSceneBuildQuality) STAND_IN(rtcSetSceneFlags)
