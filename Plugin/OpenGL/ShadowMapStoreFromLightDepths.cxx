#include "ShadowMapStoreFromLightDepths.h"

#include "ShadowMapQuad.h"
#include "ShadowMapTextureArray.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureUnitManager.h"
#include "ShadowMapVTKCompat.h"

#include <algorithm>

namespace shadowmaps
{

//------------------------------------------------------------------------------
StoreFromLightDepths::StoreFromLightDepths() = default;

//------------------------------------------------------------------------------
StoreFromLightDepths::~StoreFromLightDepths() = default;

//------------------------------------------------------------------------------
void StoreFromLightDepths::Reset(const TextureArray& maps, int layers)
{
  const std::size_t texels = static_cast<std::size_t>(maps.GetResolution()) * maps.GetResolution();
  this->Depths.assign(texels * static_cast<std::size_t>(std::max(layers, 0)), 1.0f);
}

//------------------------------------------------------------------------------
bool StoreFromLightDepths::Keep(
  vtkOpenGLState* state, const TextureArray& maps, int layer, std::string& error)
{
  const std::size_t texels = static_cast<std::size_t>(maps.GetResolution()) * maps.GetResolution();
  if (maps.GetSecondOutput() == 0 || (layer + 1) * texels > this->Depths.size())
  {
    error = "no light depths to keep for shadow-map layer " + std::to_string(layer);
    return false;
  }
  ScopedTextureBinding keep(false);
  ClearGLErrors();
  glBindTexture(GL_TEXTURE_2D, maps.GetSecondOutput());
  // Through the state: VTK 9.1 caches pixel alignment and skips calls it thinks are made.
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, this->Depths.data() + layer * texels);
  const GLenum code = glGetError();
  if (code != GL_NO_ERROR)
  {
    error = "cannot read the casters' light depths (" + GLErrorText(code) + ")";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool StoreFromLightDepths::ReadyProgram(
  vtkOpenGLRenderWindow* window, const std::string& storeFunctions, const std::string& storeCode)
{
  const std::string shader = "//VTK::System::Dec\n" + storeFunctions +
    "\nin vec2 texCoord;\nuniform sampler2D vtkShadowLightDepths;\n//VTK::Output::Dec\n"
    "void main()\n{\n"
    "  ivec2 texel = ivec2(texCoord * vec2(textureSize(vtkShadowLightDepths, 0)));\n"
    "  float vtkShadowCasterDepth = texelFetch(vtkShadowLightDepths, texel, 0).r;\n" +
    storeCode + "\n}\n";
  if (shader != this->QuadShader && this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  this->QuadShader = shader;
  return ReadyQuadProgram(this->Quad, window, this->QuadShader.c_str()) != nullptr;
}

//------------------------------------------------------------------------------
bool StoreFromLightDepths::UploadLayer(vtkOpenGLState* state, int layer, int resolution)
{
  ClearGLErrors();
  if (this->Source == 0 || this->SourceResolution != resolution)
  {
    DeleteTexture(this->Source);
    glGenTextures(1, &this->Source);
    glBindTexture(GL_TEXTURE_2D, this->Source);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, resolution, resolution, 0, GL_RED, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    this->SourceResolution = resolution;
  }
  glBindTexture(GL_TEXTURE_2D, this->Source);
  state->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  const std::size_t texels = static_cast<std::size_t>(resolution) * resolution;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, resolution, resolution, GL_RED, GL_FLOAT,
    this->Depths.data() + layer * texels);
  return glGetError() == GL_NO_ERROR;
}

//------------------------------------------------------------------------------
bool StoreFromLightDepths::Store(vtkOpenGLRenderWindow* window, TextureArray& maps, int layer,
  const std::string& storeFunctions, const std::string& storeCode,
  const FloatUniforms& storeUniforms, std::string& error)
{
  const int resolution = maps.GetResolution();
  const std::size_t texels = static_cast<std::size_t>(resolution) * resolution;
  if ((layer + 1) * texels > this->Depths.size())
  {
    error = "no light depths for shadow-map layer " + std::to_string(layer);
    return false;
  }
  if (!this->ReadyProgram(window, storeFunctions, storeCode))
  {
    error = "the shader that stores combined light depths did not compile";
    return false;
  }
  const int unit = window->GetTextureUnitManager()->Allocate();
  if (unit < 0)
  {
    error = "no texture unit is free to store combined light depths";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  bool ok = false;
  {
    const FullMapDrawState keep(state, resolution);
    state->vtkglActiveTexture(GL_TEXTURE0 + unit);
    ok = this->UploadLayer(state, layer, resolution);
    if (!ok)
    {
      error = "cannot upload the combined light depths";
    }
    ok = ok && maps.BindLayer(state, layer, error);
    if (ok)
    {
      this->Quad->Program->SetUniformi("vtkShadowLightDepths", unit);
      SetFloatUniforms(this->Quad->Program, storeUniforms);
      this->Quad->Render();
    }
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  window->GetTextureUnitManager()->Free(unit);
  return ok;
}

//------------------------------------------------------------------------------
void StoreFromLightDepths::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  this->QuadShader.clear();
  DeleteTexture(this->Source);
  this->SourceResolution = 0;
  this->Depths.clear();
  this->Depths.shrink_to_fit();
}
} // namespace shadowmaps
