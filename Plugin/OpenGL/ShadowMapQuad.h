// Full-screen draws of the passes' own shaders (the map view, the linear-depth
// resolve): one vtkOpenGLQuadHelper each, made on first use.
#ifndef ShadowMapQuad_h
#define ShadowMapQuad_h

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"

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
} // namespace shadowmaps

#endif
