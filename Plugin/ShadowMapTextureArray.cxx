#include "ShadowMapTextureArray.h"

#include "vtkOpenGLState.h"
#include "vtk_glew.h"

#include <sstream>

namespace shadowmaps
{
namespace
{
std::string GLErrorText(GLenum code)
{
  std::ostringstream text;
  text << "GL error 0x" << std::hex << code;
  return text.str();
}

// Restores the array binding of the active unit, which may belong to someone else.
class ScopedArrayBinding
{
public:
  ScopedArrayBinding() { glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &this->Previous); }
  ~ScopedArrayBinding() { glBindTexture(GL_TEXTURE_2D_ARRAY, static_cast<GLuint>(this->Previous)); }
  ScopedArrayBinding(const ScopedArrayBinding&) = delete;
  ScopedArrayBinding& operator=(const ScopedArrayBinding&) = delete;

private:
  GLint Previous = 0;
};

void ClearGLErrors()
{
  while (glGetError() != GL_NO_ERROR)
  {
  }
}
} // namespace

bool TextureArray::Reserve(int resolution, int layers, std::string& error)
{
  if (this->Texture != 0 && this->Resolution == resolution && this->Layers >= layers)
  {
    return true;
  }
  this->Release();
  ClearGLErrors();
  ScopedArrayBinding keep;

  glGenTextures(1, &this->Texture);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->Texture);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, resolution, resolution, layers, 0,
    GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  this->LinearFiltering = 1;

  glGenFramebuffers(1, &this->Framebuffer);
  const GLenum code = glGetError();
  if (code != GL_NO_ERROR)
  {
    error = "cannot allocate " + std::to_string(layers) + " shadow maps of " +
      std::to_string(resolution) + "^2 (" + GLErrorText(code) + ")";
    this->Release();
    return false;
  }
  this->Resolution = resolution;
  this->Layers = layers;
  return true;
}

bool TextureArray::BindLayer(vtkOpenGLState* state, int layer, std::string& error)
{
  state->vtkglBindFramebuffer(GL_FRAMEBUFFER, this->Framebuffer);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, this->Texture, 0, layer);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
  {
    std::ostringstream text;
    text << "shadow-map framebuffer incomplete (status 0x" << std::hex << status << ")";
    error = text.str();
    return false;
  }
  return true;
}

void TextureArray::SetLinearFiltering(bool linear)
{
  if (this->Texture == 0 || this->LinearFiltering == static_cast<int>(linear))
  {
    return;
  }
  const GLint filter = linear ? GL_LINEAR : GL_NEAREST;
  ScopedArrayBinding keep;
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->Texture);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, filter);
  this->LinearFiltering = static_cast<int>(linear);
}

void TextureArray::BindToUnit(int unit) const
{
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->Texture);
}

void TextureArray::Release()
{
  if (this->Framebuffer != 0)
  {
    glDeleteFramebuffers(1, &this->Framebuffer);
  }
  if (this->Texture != 0)
  {
    glDeleteTextures(1, &this->Texture);
  }
  this->Framebuffer = 0;
  this->Texture = 0;
  this->Resolution = 0;
  this->Layers = 0;
  this->LinearFiltering = -1;
}

std::size_t TextureArray::GetMemoryBytes() const
{
  return static_cast<std::size_t>(this->Resolution) * this->Resolution * this->Layers * 4;
}

} // namespace shadowmaps
