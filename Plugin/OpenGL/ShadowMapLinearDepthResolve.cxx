#include "ShadowMapLinearDepthResolve.h"

#include "ShadowMapQuad.h"
#include "ShadowMapTextureArray.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsLinearDepthResolveFS.h"
#include "vtkTextureUnitManager.h"
#include "ShadowMapVTKCompat.h"

namespace shadowmaps
{

//------------------------------------------------------------------------------
LinearDepthResolve::LinearDepthResolve() = default;

//------------------------------------------------------------------------------
LinearDepthResolve::~LinearDepthResolve() = default;

//------------------------------------------------------------------------------
bool LinearDepthResolve::Render(
  vtkOpenGLRenderWindow* window, TextureArray& maps, int layer, std::string& error)
{
  vtkShaderProgram* program =
    ReadyQuadProgram(this->Quad, window, vtkShadowMapsLinearDepthResolveFS);
  if (!program)
  {
    error = "the linear-depth resolve shader did not compile";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  if (!maps.BindLayer(state, layer, error))
  {
    return false;
  }
  const int unit = window->GetTextureUnitManager()->Allocate();
  vtkOpenGLState::ScopedglActiveTexture keepUnit(state);
  state->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, maps.GetSecondOutput());
  program->SetUniformi("vtkShadowLinearDepths", unit);
  // The copy writes every texel: no offset, no test against what is there.
  state->vtkglDepthFunc(GL_ALWAYS);
  glPolygonOffset(0.0f, 0.0f);
  this->Quad->Render();
  state->vtkglDepthFunc(GL_LEQUAL);
  glBindTexture(GL_TEXTURE_2D, 0);
  window->GetTextureUnitManager()->Free(unit);
  return true;
}

//------------------------------------------------------------------------------
void LinearDepthResolve::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
}
} // namespace shadowmaps
