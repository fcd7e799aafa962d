#include "ShadowMapTextureArray.h"

#include "vtkOpenGLState.h"
#include "ShadowMapVTKCompat.h"

#include <algorithm>
#include <sstream>

namespace shadowmaps
{
namespace
{
int MipmapLevels(int resolution)
{
  int levels = 1;
  while ((resolution >>= 1) > 0)
  {
    ++levels;
  }
  return levels;
}
} // namespace

std::string GLErrorText(unsigned int code)
{
  std::ostringstream text;
  text << "GL error 0x" << std::hex << code;
  return text.str();
}

ScopedTextureBinding::ScopedTextureBinding(bool array)
  : Array(array)
{
  glGetIntegerv(array ? GL_TEXTURE_BINDING_2D_ARRAY : GL_TEXTURE_BINDING_2D, &this->Previous);
}

ScopedTextureBinding::~ScopedTextureBinding()
{
  glBindTexture(this->Array ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, static_cast<GLuint>(this->Previous));
}

void ClearGLErrors()
{
  while (glGetError() != GL_NO_ERROR)
  {
  }
}

void DeleteTexture(unsigned int& name)
{
  if (name != 0)
  {
    glDeleteTextures(1, &name);
  }
  name = 0;
}

void DeleteFramebuffer(unsigned int& name)
{
  if (name != 0)
  {
    glDeleteFramebuffers(1, &name);
  }
  name = 0;
}

void DeleteRenderbuffer(unsigned int& name)
{
  if (name != 0)
  {
    glDeleteRenderbuffers(1, &name);
  }
  name = 0;
}

void SelectBuffers(vtkOpenGLState* state, int count, const unsigned int* draws, unsigned int read)
{
  unsigned int buffers[2] = { draws[0], count > 1 ? draws[1] : GL_NONE };
  if (count == 1)
  {
    state->vtkglDrawBuffer(buffers[0]);
  }
  else
  {
    state->vtkglDrawBuffers(count, buffers);
    // The state may have skipped the call on a stale second entry.
    glDrawBuffers(count, buffers);
  }
  state->vtkglReadBuffer(read);
}

void AllocateValueLevels(int resolution, int layers, TexelFormat format, int levels)
{
  const GLint internal = InternalFormat(format);
  const GLenum channels = ValueChannels(format) == 4 ? GL_RGBA : GL_RG;
  for (int level = 0, size = resolution; level < levels; ++level, size = std::max(size / 2, 1))
  {
    glTexImage3D(GL_TEXTURE_2D_ARRAY, level, internal, size, size, layers, 0, channels, GL_FLOAT,
      nullptr);
  }
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, levels - 1);
}

unsigned int InternalFormat(TexelFormat format)
{
  switch (format)
  {
    case TexelFormat::Depth:
      return GL_DEPTH_COMPONENT32F;
    case TexelFormat::Depth16:
      return GL_DEPTH_COMPONENT16;
    case TexelFormat::TwoFloats:
      return GL_RG32F;
    case TexelFormat::FourFloats:
      return GL_RGBA32F;
    case TexelFormat::TwoHalfFloats:
      return GL_RG16F;
    case TexelFormat::FourHalfFloats:
      return GL_RGBA16F;
    case TexelFormat::FourNormalized16:
      return GL_RGBA16;
  }
  return GL_RG32F;
}

bool TextureArray::Reserve(int resolution, int layers, TexelFormat format, bool mipmaps,
  std::string& error, bool depthTest)
{
  mipmaps = mipmaps && !IsDepth(format);
  if (this->H.Texture != 0 && this->H.Resolution == resolution && this->H.Layers >= layers &&
    this->H.Format == format && this->H.Mipmaps == mipmaps && this->H.DepthTest == depthTest)
  {
    return true;
  }
  this->Release();
  ++this->H.Allocations;
  ClearGLErrors();
  ScopedTextureBinding keep(true);
  this->H.Format = format;
  this->H.Mipmaps = mipmaps;
  this->H.DepthTest = depthTest;

  glGenTextures(1, &this->H.Texture);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->H.Texture);
  if (IsDepth(format))
  {
    this->AllocateDepthLayers(resolution, layers, format);
  }
  else
  {
    this->AllocateValueLayers(resolution, layers, format);
  }
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  this->H.LinearFiltering = -1;
  this->ApplyFiltering(true);

  glGenFramebuffers(1, &this->H.Framebuffer);
  const GLenum code = glGetError();
  if (code != GL_NO_ERROR)
  {
    error = "cannot allocate " + std::to_string(layers) + " shadow maps of " +
      std::to_string(resolution) + "^2 (" + GLErrorText(code) + ")";
    this->Release();
    return false;
  }
  this->H.Resolution = resolution;
  this->H.Layers = layers;
  return true;
}

void TextureArray::AllocateDepthLayers(int resolution, int layers, TexelFormat format)
{
  const GLenum type = format == TexelFormat::Depth16 ? GL_UNSIGNED_SHORT : GL_FLOAT;
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, InternalFormat(format), resolution, resolution, layers, 0,
    GL_DEPTH_COMPONENT, type, nullptr);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

void TextureArray::AllocateValueLayers(int resolution, int layers, TexelFormat format)
{
  AllocateValueLevels(resolution, layers, format, this->H.Mipmaps ? MipmapLevels(resolution) : 1);
  if (!this->H.DepthTest)
  {
    return;
  }
  glGenRenderbuffers(1, &this->H.DepthBuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, this->H.DepthBuffer);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, resolution, resolution);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
}

bool TextureArray::BindLayer(vtkOpenGLState* state, int layer, std::string& error, bool secondOutput)
{
  state->vtkglBindFramebuffer(GL_FRAMEBUFFER, this->H.Framebuffer);
  if (secondOutput && this->H.SecondOutput == 0)
  {
    ScopedTextureBinding keep(false);
    glGenTextures(1, &this->H.SecondOutput);
    glBindTexture(GL_TEXTURE_2D, this->H.SecondOutput);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, this->H.Resolution, this->H.Resolution, 0, GL_RED,
      GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  const GLuint second = secondOutput ? this->H.SecondOutput : 0;
  if (IsDepth(this->H.Format))
  {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, this->H.Texture, 0, layer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, second, 0);
    const unsigned int outputs[2] = { GL_NONE, GL_COLOR_ATTACHMENT0 };
    SelectBuffers(state, secondOutput ? 2 : 1, outputs, GL_NONE);
  }
  else
  {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, this->H.Texture, 0, layer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, this->H.DepthBuffer);
    // Detached when not asked for: a texture sampled while attached would
    // make a feedback loop.
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, second, 0);
    const unsigned int outputs[2] = { GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1 };
    SelectBuffers(state, secondOutput ? 2 : 1, outputs, GL_COLOR_ATTACHMENT0);
  }
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

bool TextureArray::BindSamples(vtkOpenGLState* state, int samples, std::string& error)
{
  if (this->H.SampleFramebuffer != 0 && this->H.Samples != samples)
  {
    this->ReleaseSamples();
  }
  if (this->H.SampleFramebuffer == 0)
  {
    ClearGLErrors();
    glGenRenderbuffers(1, &this->H.SampleColor);
    glBindRenderbuffer(GL_RENDERBUFFER, this->H.SampleColor);
    glRenderbufferStorageMultisample(
      GL_RENDERBUFFER, samples, InternalFormat(this->H.Format), this->H.Resolution, this->H.Resolution);
    glGenRenderbuffers(1, &this->H.SampleDepth);
    glBindRenderbuffer(GL_RENDERBUFFER, this->H.SampleDepth);
    glRenderbufferStorageMultisample(
      GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT32F, this->H.Resolution, this->H.Resolution);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glGenFramebuffers(1, &this->H.SampleFramebuffer);
    // GL may round the count up to one it supports: the memory counts those.
    GLint allocated = samples;
    glBindRenderbuffer(GL_RENDERBUFFER, this->H.SampleColor);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &allocated);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    this->H.Samples = samples;
    this->H.AllocatedSamples = std::max(static_cast<int>(allocated), samples);
    const GLenum code = glGetError();
    if (code != GL_NO_ERROR)
    {
      error = "cannot allocate " + std::to_string(samples) + " samples per shadow-map texel (" +
        GLErrorText(code) + ")";
      this->ReleaseSamples();
      return false;
    }
  }
  state->vtkglBindFramebuffer(GL_FRAMEBUFFER, this->H.SampleFramebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, this->H.SampleColor);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, this->H.SampleDepth);
  const unsigned int output = GL_COLOR_ATTACHMENT0;
  SelectBuffers(state, 1, &output, GL_COLOR_ATTACHMENT0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
  {
    error = "multisampled shadow-map framebuffer incomplete";
    return false;
  }
  return true;
}

bool TextureArray::ResolveSamples(vtkOpenGLState* state, int layer, std::string& error)
{
  if (!this->BindLayer(state, layer, error))
  {
    return false;
  }
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, this->H.SampleFramebuffer);
  state->vtkglReadBuffer(GL_COLOR_ATTACHMENT0);
  ClearGLErrors();
  glBlitFramebuffer(0, 0, this->H.Resolution, this->H.Resolution, 0, 0, this->H.Resolution,
    this->H.Resolution, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  const GLenum code = glGetError();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, this->H.Framebuffer);
  if (code != GL_NO_ERROR)
  {
    error = "cannot resolve the shadow map's samples (" + GLErrorText(code) + ")";
    return false;
  }
  return true;
}

void TextureArray::ReleaseSamples()
{
  DeleteFramebuffer(this->H.SampleFramebuffer);
  DeleteRenderbuffer(this->H.SampleColor);
  DeleteRenderbuffer(this->H.SampleDepth);
  this->H.Samples = 0;
  this->H.AllocatedSamples = 0;
}

void TextureArray::SetLinearFiltering(bool linear)
{
  if (this->H.Texture == 0 || this->H.LinearFiltering == static_cast<int>(linear))
  {
    return;
  }
  ScopedTextureBinding keep(true);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->H.Texture);
  this->ApplyFiltering(linear);
}

// Expects the array bound to the active unit.
void TextureArray::ApplyFiltering(bool linear)
{
  GLint minification = linear ? GL_LINEAR : GL_NEAREST;
  if (linear && this->H.Mipmaps)
  {
    minification = GL_LINEAR_MIPMAP_LINEAR;
  }
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, minification);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, linear ? GL_LINEAR : GL_NEAREST);
  this->H.LinearFiltering = static_cast<int>(linear);
}

void TextureArray::SetDepthComparison(bool compare)
{
  if (this->H.Texture == 0 || !IsDepth(this->H.Format))
  {
    return;
  }
  ScopedTextureBinding keep(true);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->H.Texture);
  glTexParameteri(
    GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
}

void TextureArray::GenerateMipmaps()
{
  if (this->H.Texture == 0 || !this->H.Mipmaps)
  {
    return;
  }
  ScopedTextureBinding keep(true);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->H.Texture);
  glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
}

namespace
{
// The client-side format of a texel format's texels as floats: a depth, or its values.
GLenum TexelsAsFloats(TexelFormat format)
{
  return IsDepth(format) ? GL_DEPTH_COMPONENT : ValueChannels(format) == 2 ? GL_RG : GL_RGBA;
}
} // namespace

std::size_t TextureArray::FloatsPerLayer() const
{
  const int channels = IsDepth(this->H.Format) ? 1 : ValueChannels(this->H.Format);
  return static_cast<std::size_t>(this->H.Resolution) * this->H.Resolution * channels;
}

bool TextureArray::ReadTexels(
  vtkOpenGLState* state, int layers, std::vector<float>& texels, std::string& error) const
{
  if (this->H.Texture == 0 || layers < 1 || layers > this->H.Layers)
  {
    error = "no such shadow maps to read";
    return false;
  }
  texels.resize(this->FloatsPerLayer() * this->H.Layers);
  ScopedTextureBinding keep(true);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->H.Texture);
  ClearGLErrors();
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  // GL reads a whole level: every allocated layer, then the used ones are kept.
  glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, TexelsAsFloats(this->H.Format), GL_FLOAT, texels.data());
  texels.resize(this->FloatsPerLayer() * layers);
  const GLenum code = glGetError();
  if (code != GL_NO_ERROR)
  {
    error = "cannot read the shadow maps back (" + GLErrorText(code) + ")";
    return false;
  }
  return true;
}

bool TextureArray::WriteTexels(
  vtkOpenGLState* state, int layers, const std::vector<float>& texels, std::string& error)
{
  if (this->H.Texture == 0 || layers < 1 || layers > this->H.Layers ||
    texels.size() != this->FloatsPerLayer() * layers)
  {
    error = "no shadow maps of that size to write";
    return false;
  }
  ScopedTextureBinding keep(true);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->H.Texture);
  ClearGLErrors();
  state->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, this->H.Resolution, this->H.Resolution, layers,
    TexelsAsFloats(this->H.Format), GL_FLOAT, texels.data());
  const GLenum code = glGetError();
  if (code != GL_NO_ERROR)
  {
    error = "cannot write the combined shadow maps (" + GLErrorText(code) + ")";
    return false;
  }
  return true;
}

void TextureArray::BindToUnit(vtkOpenGLState* state, int unit) const
{
  state->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->H.Texture);
}

bool SamplerObjectsAvailable()
{
  return glGenSamplers && glBindSampler && glSamplerParameteri && glDeleteSamplers;
}

bool TextureArray::BindRawDepthToUnit(vtkOpenGLState* state, int unit)
{
  if (!SamplerObjectsAvailable())
  {
    return false;
  }
  if (this->H.RawDepthSampler == 0)
  {
    glGenSamplers(1, &this->H.RawDepthSampler);
    glSamplerParameteri(this->H.RawDepthSampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(this->H.RawDepthSampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(this->H.RawDepthSampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(this->H.RawDepthSampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(this->H.RawDepthSampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  this->BindToUnit(state, unit);
  glBindSampler(static_cast<GLuint>(unit), this->H.RawDepthSampler);
  return true;
}

void TextureArray::UnbindRawDepth(vtkOpenGLState* state, int unit)
{
  state->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  if (glBindSampler)
  {
    glBindSampler(static_cast<GLuint>(unit), 0);
  }
}

void TextureArray::ReleaseSecondOutput()
{
  DeleteTexture(this->H.SecondOutput);
}

void TextureArray::Release()
{
  DeleteFramebuffer(this->H.Framebuffer);
  this->ReleaseSecondOutput();
  this->ReleaseSamples();
  DeleteRenderbuffer(this->H.DepthBuffer);
  DeleteTexture(this->H.Texture);
  if (this->H.RawDepthSampler != 0)
  {
    glDeleteSamplers(1, &this->H.RawDepthSampler);
    this->H.RawDepthSampler = 0;
  }
  this->H.Resolution = 0;
  this->H.Layers = 0;
  this->H.LinearFiltering = -1;
}

std::size_t TextureArray::GetMemoryBytes() const
{
  const std::size_t texels = static_cast<std::size_t>(this->H.Resolution) * this->H.Resolution;
  const std::size_t secondOutput = this->H.SecondOutput != 0 ? texels * 4 : 0;
  const std::size_t layers = texels * this->H.Layers * TexelBytes(this->H.Format);
  if (IsDepth(this->H.Format))
  {
    return layers + secondOutput;
  }
  // A full mipmap chain adds a third; the depth buffer is shared by all layers.
  const std::size_t values = layers;
  const std::size_t samples =
    texels * static_cast<std::size_t>(this->H.AllocatedSamples) * (TexelBytes(this->H.Format) + 4);
  const std::size_t depth = this->H.DepthBuffer != 0 ? texels * 4 : 0;
  return (this->H.Mipmaps ? values + values / 3 : values) + depth + secondOutput + samples;
}

} // namespace shadowmaps
