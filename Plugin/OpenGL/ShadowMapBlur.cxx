#include "ShadowMapBlur.h"

#include "ShadowMapQuad.h"
#include "ShadowMapTextureArray.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsBlurFS.h"
#include "vtkTextureUnitManager.h"
#include "ShadowMapVTKCompat.h"

#include <cmath>

namespace shadowmaps
{
namespace
{
// Taps each side of the centre: the kernel spans +-2 sigma.
int TapsEachSide(double radius)
{
  return static_cast<int>(std::ceil(2.0 * BlurSigma(radius) - 1e-6));
}
} // namespace

//------------------------------------------------------------------------------
MapBlur::MapBlur() = default;

//------------------------------------------------------------------------------
MapBlur::~MapBlur() = default;

//------------------------------------------------------------------------------
bool MapBlur::ReserveScratch(const TextureArray& maps, std::string& error)
{
  const int format = static_cast<int>(maps.GetFormat());
  if (this->Scratch != 0 && this->ScratchResolution == maps.GetResolution() &&
    this->ScratchFormat == format)
  {
    return true;
  }
  DeleteTexture(this->Scratch);
  ClearGLErrors();
  const int resolution = maps.GetResolution();
  {
    ScopedTextureBinding keep(true);
    glGenTextures(1, &this->Scratch);
    glBindTexture(GL_TEXTURE_2D_ARRAY, this->Scratch);
    AllocateValueLevels(resolution, 1, maps.GetFormat(), 1);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  if (this->ScratchFramebuffer == 0)
  {
    glGenFramebuffers(1, &this->ScratchFramebuffer);
  }
  if (glGetError() != GL_NO_ERROR)
  {
    error = "cannot allocate the shadow maps' blur layer";
    return false;
  }
  this->ScratchResolution = resolution;
  this->ScratchFormat = format;
  return true;
}

//------------------------------------------------------------------------------
void MapBlur::DrawPass(vtkOpenGLRenderWindow* window, unsigned int source, int layer, int unit,
  int dx, int dy, double radius)
{
  vtkShaderProgram* program = this->Quad->Program;
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, source);
  program->SetUniformi("vtkShadowBlurSource", unit);
  program->SetUniformi("vtkShadowBlurLayer", layer);
  const int step[2] = { dx, dy };
  program->SetUniform2i("vtkShadowBlurStep", step);
  program->SetUniformi("vtkShadowBlurTaps", TapsEachSide(radius));
  program->SetUniformf("vtkShadowBlurSigma", static_cast<float>(BlurSigma(radius)));
  this->Quad->Render();
}

//------------------------------------------------------------------------------
bool MapBlur::Blur(
  vtkOpenGLRenderWindow* window, TextureArray& maps, int layer, double radius, std::string& error)
{
  if (!(radius >= 0.5) || IsDepth(maps.GetFormat()))
  {
    return true;
  }
  vtkShaderProgram* program = ReadyQuadProgram(this->Quad, window, vtkShadowMapsBlurFS);
  if (!program)
  {
    error = "the shadow maps' blur shader did not compile";
    return false;
  }
  if (!this->ReserveScratch(maps, error))
  {
    return false;
  }
  const int unit = window->GetTextureUnitManager()->Allocate();
  if (unit < 0)
  {
    error = "no texture unit is free for the shadow maps' blur";
    return false;
  }
  bool ok = false;
  {
    const FullMapDrawState keep(window->GetState(), maps.GetResolution());
    ok = this->DrawBothPasses(window, maps, layer, unit, radius, error);
  }
  window->GetTextureUnitManager()->Free(unit);
  if (!ok && error.empty())
  {
    error = "the shadow maps' blur framebuffer is incomplete";
  }
  return ok;
}

//------------------------------------------------------------------------------
bool MapBlur::DrawBothPasses(vtkOpenGLRenderWindow* window, TextureArray& maps, int layer,
  int unit, double radius, std::string& error)
{
  vtkOpenGLState* state = window->GetState();
  state->vtkglBindFramebuffer(GL_FRAMEBUFFER, this->ScratchFramebuffer);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, this->Scratch, 0, 0);
  const unsigned int output = GL_COLOR_ATTACHMENT0;
  SelectBuffers(state, 1, &output, GL_COLOR_ATTACHMENT0);
  bool ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  if (ok)
  {
    this->DrawPass(window, maps.GetTextureName(), layer, unit, 1, 0, radius);
    ok = maps.BindLayer(state, layer, error);
  }
  if (ok)
  {
    this->DrawPass(window, this->Scratch, 0, unit, 0, 1, radius);
  }
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  return ok;
}

//------------------------------------------------------------------------------
void MapBlur::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  DeleteFramebuffer(this->ScratchFramebuffer);
  DeleteTexture(this->Scratch);
  this->ScratchResolution = 0;
  this->ScratchFormat = -1;
}
} // namespace shadowmaps
