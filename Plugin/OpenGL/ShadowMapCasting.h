// How a light view's casters are drawn: the VTK camera that looks through the
// view and the GL state they render with. Used by the pass for every layer it
// re-renders.
#ifndef ShadowMapCasting_h
#define ShadowMapCasting_h

#include "vtkOpenGLState.h"

#include <glm/glm.hpp>

#include <array>

class vtkCamera;
class vtkMatrix4x4;

namespace shadowmaps
{
struct LightView;

/// The frame SetCameraToView gives the light camera (world to the camera):
/// the view itself when it is rigid. A non-rigid view (PSM: the light camera
/// times the viewer's post-perspective transform) cannot be a camera frame; the
/// camera then sits at the origin, turned so that its x axis runs along the
/// first row of the view-projection: VTK sizes impostors (points as spheres,
/// lines as tubes) by the camera projection's first element, which a warp
/// whose image x has no world x term (a post-perspective cube face looking
/// along the camera's x) would leave at 0.
glm::dmat4 CameraFrameOf(const LightView& view);

/// The projection SetCameraToView gives the light camera: the view-projection
/// after CameraFrameOf (the view's own projection for a rigid view).
glm::dmat4 CameraProjectionOf(const LightView& view);

/// Points `camera` at a light view: CameraFrameOf becomes the camera's frame
/// and CameraProjectionOf its explicit projection (stored in `projection`), so
/// VTK's tiled aspect ratio cannot distort the map. The camera stays parallel
/// or perspective as the scene's camera is (CasterShader::RouteCameraParallel
/// says why).
void SetCameraToView(
  vtkCamera* camera, vtkMatrix4x4* projection, const LightView& view, bool sceneParallel);

/// 1 / W as a plane over window coordinates (gl_FragCoord.xy) of a map of
/// `resolution` texels, for casters of linear-depth views; (0, 0, 1) for the others.
std::array<float, 3> WindowToInverseW(const LightView& view, int resolution);

/// The GL state casters render with, set for the lifetime of the object and
/// restored after: the maps' framebuffer bindings, depth test (or, for value
/// maps kept by minimum blending (MapStorage::MinimumBlending), GL_MIN blending
/// instead), polygon offset, and
/// depth clamping: casters nearer the light than a view's near plane are
/// clamped onto it rather than clipped ("pancaking"), so they still occlude all
/// that lies behind them, and a fit may put its near plane where depth
/// precision is needed.
class CasterGLState
{
public:
  CasterGLState(vtkOpenGLState* state, bool minimumBlending);
  ~CasterGLState();
  CasterGLState(const CasterGLState&) = delete;
  CasterGLState& operator=(const CasterGLState&) = delete;

  /// Whether the next draw takes its point size from its vertex shader: on for
  /// points drawn as spheres (ImpostorShader::IsSized), whose size in the
  /// map is the size of the sphere they show, off for other points.
  void UseProgramPointSize(bool on);

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable Offset;
  vtkOpenGLState::ScopedglEnableDisable Multisample;
  vtkOpenGLState::ScopedglDepthFunc DepthFunc;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
  vtkOpenGLState::ScopedglClearColor ClearColor;
  vtkOpenGLState::ScopedglActiveTexture ActiveTexture;
  int BlendEquation[2] = { 0, 0 };
  float PolygonOffset[2] = { 0.0f, 0.0f };
  unsigned char DepthClampWasOn;
  unsigned char ProgramPointSizeWasOn;
  bool ProgramPointSize = false;
  bool MinimumBlending;
};
} // namespace shadowmaps

#endif
