// Full-screen draws of the passes' own shaders (the map view, the linear-depth
// resolve, the blur, the store from light depths): one vtkOpenGLQuadHelper
// each, made on first use, and the GL state of a draw over a whole map.
#ifndef ShadowMapQuad_h
#define ShadowMapQuad_h

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "ShadowMapVTKCompat.h"

#include <memory>

namespace shadowmaps
{
/// The quad's program, ready (bound) to draw with, made from `fragmentShader`
/// on first use; nullptr when it does not compile.
inline vtkShaderProgram* ReadyQuadProgram(
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, vtkOpenGLRenderWindow* window, const char* fragmentShader)
{
  if (!quad)
  {
    quad.reset(new vtkOpenGLQuadHelper(window, nullptr, fragmentShader, ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  vtkShaderProgram* program = quad->Program;
  return program && program->GetCompiled() ? program : nullptr;
}
/// The GL state of a draw over a whole map (the blur, the store from light
/// depths), kept and restored around it: the framebuffer bindings, viewport,
/// depth test, blending, scissor test and active unit. While it lives the
/// viewport is the map's and the tests and blending are off (the renderer's
/// scissor box is the window's, and every texel is written as it is).
class FullMapDrawState
{
public:
  FullMapDrawState(vtkOpenGLState* state, int resolution)
    : State(state)
    , Viewport(state)
    , DepthTest(state, GL_DEPTH_TEST)
    , Blend(state, GL_BLEND)
    , Scissor(state, GL_SCISSOR_TEST)
    , ActiveUnit(state)
  {
    state->PushFramebufferBindings();
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglViewport(0, 0, resolution, resolution);
  }
  ~FullMapDrawState() { this->State->PopFramebufferBindings(); }
  FullMapDrawState(const FullMapDrawState&) = delete;
  FullMapDrawState& operator=(const FullMapDrawState&) = delete;

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
  vtkOpenGLState::ScopedglActiveTexture ActiveUnit;
};
} // namespace shadowmaps

#endif
