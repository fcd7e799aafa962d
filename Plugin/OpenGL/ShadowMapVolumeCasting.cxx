#include "ShadowMapVolumeCasting.h"

#include "ShadowMapTextureArray.h" // For ClearGLErrors, GLErrorText
#include "ShadowMapVolumeReading.h"
#include "vtkShadowMapsLightDepthFS.h"
#include "vtkShadowMapsTransmittedFS.h"
#include "vtkShadowMapsVolumeCastingFS.h"
#include "vtkShadowMapsVolumeCastingVS.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkVolumeProperty.h"
#include "ShadowMapVTKCompat.h" // For the GL functions

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtc/matrix_access.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace shadowmaps
{
namespace
{
// The unit cube's 12 triangles.
const std::array<float, 24> CubeCorners = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0,
  1, 0, 1, 1, 1, 1, 1 };
const std::array<GLuint, 36> CubeTriangles = { 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1,
  5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5 };

std::string MarcherFragmentShader()
{
  std::string fs = vtkShadowMapsVolumeCastingFS;
  vtkShaderProgram::Substitute(fs, "//VTK::Output::Dec",
    std::string("//VTK::Output::Dec\n") + vtkShadowMapsLightDepthFS + vtkShadowMapsTransmittedFS);
  return fs;
}

// The scalars as 16-bit steps over [low, high], and whether each sample has
// data (a second channel, only where some has none: NaN).
std::vector<std::uint16_t> Quantized(const VolumeReading& reading, bool& withDefined)
{
  vtkDataArray* scalars = reading.Scalars;
  const vtkIdType count = scalars->GetNumberOfTuples();
  const double scale = 65535.0 / (reading.High - reading.Low);
  std::vector<std::uint16_t> steps(static_cast<std::size_t>(count));
  withDefined = false;
  for (vtkIdType i = 0; i < count; ++i)
  {
    const double s = scalars->GetComponent(i, 0);
    withDefined = withDefined || std::isnan(s);
    const double step = std::isnan(s) ? 0.0 : std::round((s - reading.Low) * scale);
    steps[i] = static_cast<std::uint16_t>(std::min(std::max(step, 0.0), 65535.0));
  }
  if (!withDefined)
  {
    return steps;
  }
  std::vector<std::uint16_t> texels(2 * steps.size());
  for (vtkIdType i = 0; i < count; ++i)
  {
    texels[2 * i] = steps[i];
    texels[2 * i + 1] = std::isnan(scalars->GetComponent(i, 0)) ? 0 : 65535;
  }
  return texels;
}

vtkSmartPointer<vtkTextureObject> ScalarTexture(
  vtkOpenGLRenderWindow* window, const VolumeReading& reading, std::string& error)
{
  GLint largest = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
  if (glm::any(glm::greaterThan(reading.Dimensions, glm::ivec3(largest))))
  {
    error = "its " + std::to_string(reading.Dimensions.x) + " x " +
      std::to_string(reading.Dimensions.y) + " x " + std::to_string(reading.Dimensions.z) +
      " samples exceed this GL's 3D textures (" + std::to_string(largest) + " a side)";
    return nullptr;
  }
  bool withDefined = false;
  std::vector<std::uint16_t> texels = Quantized(reading, withDefined);
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetInternalFormat(withDefined ? GL_RG16 : GL_R16);
  texture->SetFormat(withDefined ? GL_RG : GL_RED);
  texture->SetDataType(GL_UNSIGNED_SHORT);
  vtkOpenGLState::ScopedglActiveTexture keepUnit(window->GetState());
  // VTK's own check of the upload reports nothing in release builds.
  ClearGLErrors();
  const bool created = texture->Create3DFromRaw(static_cast<unsigned int>(reading.Dimensions.x),
    static_cast<unsigned int>(reading.Dimensions.y),
    static_cast<unsigned int>(reading.Dimensions.z), withDefined ? 2 : 1, VTK_UNSIGNED_SHORT,
    texels.data());
  const GLenum code = glGetError();
  if (!created || code != GL_NO_ERROR)
  {
    error = "its scalars do not fit a 3D texture (" + GLErrorText(code) + ")";
    return nullptr;
  }
  if (!withDefined)
  {
    // Every sample has data: the marcher reads 1 where the second channel would be.
    texture->Bind();
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_SWIZZLE_G, GL_ONE);
  }
  return texture;
}

vtkSmartPointer<vtkTextureObject> TableTexture(
  vtkOpenGLRenderWindow* window, const VolumeReading& reading, std::string& error)
{
  std::vector<float> entries(reading.Table.size() * 4);
  for (std::size_t k = 0; k < reading.Table.size(); ++k)
  {
    for (int c = 0; c < 4; ++c)
    {
      entries[4 * k + c] = static_cast<float>(reading.Table[k][c]);
    }
  }
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  vtkOpenGLState::ScopedglActiveTexture keepUnit(window->GetState());
  if (!texture->Create2DFromRaw(
        static_cast<unsigned int>(reading.Table.size()), 1, 4, VTK_FLOAT, entries.data()))
  {
    error = "the volume's transfer functions do not fit a texture";
    return nullptr;
  }
  return texture;
}

// Box coordinates to texture coordinates: data point i of n along an axis is
// at box coordinate i / (n - 1) (reversed where the spacing is negative) and
// at texel centre (i + 0.5) / n.
void TextureMapping(const VolumeReading& reading, glm::dvec3& scale, glm::dvec3& shift)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    const double n = reading.Dimensions[axis];
    double s = (n - 1.0) / n;
    double t = 0.5 / n;
    if (reading.Spacing[axis] < 0.0)
    {
      t = 1.0 - t;
      s = -s;
    }
    scale[axis] = s;
    shift[axis] = t;
  }
}

// The mapper's clipping planes in box coordinates (a plane p of world
// points x, p . (x, 1) >= 0 kept, is (boxToWorld^T p) of box points).
void SetClippingPlanes(
  vtkShaderProgram* program, const std::vector<glm::dvec4>& planes, const glm::dmat4& boxToWorld)
{
  std::array<float, 4 * MostVolumeClippingPlanes> packed{};
  const int count = static_cast<int>(std::min<std::size_t>(planes.size(), MostVolumeClippingPlanes));
  for (int i = 0; i < count; ++i)
  {
    const glm::vec4 inBox(glm::transpose(boxToWorld) * planes[i]);
    std::copy(glm::value_ptr(inBox), glm::value_ptr(inBox) + 4, packed.begin() + 4 * i);
  }
  program->SetUniformi("vtkVolumeClippingPlaneCount", count);
  program->SetUniform4fv("vtkVolumeClippingPlanes", MostVolumeClippingPlanes,
    packed.data());
}

// The light in the box's coordinates: its position, or the direction it shines.
glm::dvec3 LightInBox(const ShadowLight& light, const glm::dmat4& worldToBox)
{
  return light.Kind == LightKind::Directional
    ? glm::dvec3(worldToBox * glm::dvec4(light.Direction, 0.0))
    : glm::dvec3(worldToBox * glm::dvec4(light.Position, 1.0));
}
} // namespace

//------------------------------------------------------------------------------
VolumeCasters::VolumeCasters() = default;
VolumeCasters::~VolumeCasters() = default;

//------------------------------------------------------------------------------
VolumeCasters::Uploaded* VolumeCasters::Upload(
  vtkOpenGLRenderWindow* window, vtkVolume* volume, VolumeReading& reading, std::string& error)
{
  if (!ReadVolumeLayout(volume, reading, error))
  {
    return nullptr;
  }
  Uploaded& uploaded = this->Volumes[volume];
  if (uploaded.Volume != volume)
  {
    uploaded = Uploaded(); // another volume where a deleted one was
    uploaded.Volume = volume;
  }
  const std::array<vtkMTimeType, 3> scalarsKey = { { volume->GetMapper()->GetMTime(),
    reading.Image->GetMTime(), reading.Scalars->GetMTime() } };
  if (uploaded.ScalarsKey != scalarsKey)
  {
    uploaded.ScalarsKey = scalarsKey;
    uploaded.Failure.clear();
    uploaded.Scalars = ScalarTexture(window, reading, uploaded.Failure);
    uploaded.TableKey = 0; // the table runs over the scalars' range
  }
  if (!uploaded.Failure.empty())
  {
    error = uploaded.Failure;
    return nullptr;
  }
  const vtkMTimeType tableKey = volume->GetProperty()->GetMTime();
  if (uploaded.TableKey != tableKey || !uploaded.Table)
  {
    TabulateTransferFunctions(volume, reading);
    uploaded.Table = TableTexture(window, reading, error);
    uploaded.TableKey = uploaded.Table ? tableKey : 0;
  }
  if (!uploaded.Table)
  {
    return nullptr;
  }
  uploaded.Bytes = static_cast<std::size_t>(uploaded.Scalars->GetTuples()) *
      static_cast<std::size_t>(uploaded.Scalars->GetComponents()) * sizeof(std::uint16_t) +
    static_cast<std::size_t>(VolumeTableSize) * 4 * sizeof(float);
  return &uploaded;
}

//------------------------------------------------------------------------------
bool VolumeCasters::Draw(vtkOpenGLRenderWindow* window, vtkVolume* volume,
  const ShadowLight& light, const LightView& view, std::string& error)
{
  VolumeReading reading;
  Uploaded* uploaded = this->Upload(window, volume, reading, error);
  if (!uploaded)
  {
    return false;
  }
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    vtkShadowMapsVolumeCastingVS, MarcherFragmentShader().c_str(), "");
  if (!program)
  {
    error = "the volumes' marcher does not compile";
    return false;
  }
  const glm::dmat4 boxToData = glm::scale(glm::translate(glm::dmat4(1.0), reading.BoxMin),
    glm::max(reading.BoxMax - reading.BoxMin, glm::dvec3(1e-30)));
  const glm::dmat4 boxToWorld = reading.DataToWorld * boxToData;
  // Positions relative to the light depth's origin, composed in double.
  const glm::dmat4 boxToLight = glm::translate(glm::dmat4(1.0), -light.Depth.Origin) * boxToWorld;
  const glm::dmat4 boxToClip = view.ViewProjection() * boxToWorld;
  const glm::dvec3 sides(boxToData[0][0], boxToData[1][1], boxToData[2][2]);
  glm::dvec3 textureScale;
  glm::dvec3 textureShift;
  TextureMapping(reading, textureScale, textureShift);
  glm::mat4 toClip(boxToClip);
  glm::mat4 toLight(boxToLight);
  program->SetUniformMatrix4x4("vtkVolumeBoxToClip", glm::value_ptr(toClip));
  program->SetUniformMatrix4x4("vtkVolumeBoxToLight", glm::value_ptr(toLight));
  program->SetUniform3f("vtkVolumeLight",
    glm::value_ptr(glm::vec3(LightInBox(light, glm::inverse(boxToWorld)))));
  program->SetUniformi("vtkVolumePositional", light.Kind == LightKind::Directional ? 0 : 1);
  program->SetUniform3f("vtkVolumeBoxSides", glm::value_ptr(glm::vec3(sides)));
  program->SetUniform3f("vtkVolumeTextureScale", glm::value_ptr(glm::vec3(textureScale)));
  program->SetUniform3f("vtkVolumeTextureShift", glm::value_ptr(glm::vec3(textureShift)));
  program->SetUniformf("vtkVolumeDataStep", static_cast<float>(reading.Step));
  program->SetUniformi("vtkVolumeMostSteps", MostVolumeSteps);
  program->SetUniformf("vtkVolumeUnitDistance", static_cast<float>(reading.UnitDistance));
  program->SetUniformi("vtkVolumeTableSize", VolumeTableSize);
  SetClippingPlanes(program, reading.ClippingPlanes, boxToWorld);
  program->SetUniform4f("vtkShadowLightDepthPlane", glm::value_ptr(glm::vec4(light.Depth.Plane)));
  program->SetUniformf("vtkShadowLightDepthPerDistance", static_cast<float>(light.Depth.PerDistance));
  uploaded->Scalars->Activate();
  uploaded->Table->Activate();
  program->SetUniformi("vtkVolumeScalars", uploaded->Scalars->GetTextureUnit());
  program->SetUniformi("vtkVolumeTable", uploaded->Table->GetTextureUnit());
  // Every face counts (the shader keeps the one each ray leaves by, whichever
  // way the view's projection turns it), and faces beyond the view's depth
  // range still end their rays.
  vtkOpenGLState::ScopedglEnableDisable keepCulling(window->GetState(), GL_CULL_FACE);
  window->GetState()->vtkglDisable(GL_CULL_FACE);
  const GLboolean depthClamp = glIsEnabled(GL_DEPTH_CLAMP);
  glEnable(GL_DEPTH_CLAMP);
  std::array<float, 24> corners = CubeCorners;
  std::array<GLuint, 36> triangles = CubeTriangles;
  vtkOpenGLRenderUtilities::RenderTriangles(corners.data(), 8, triangles.data(), 36, nullptr,
    program, this->Box);
  if (!depthClamp)
  {
    glDisable(GL_DEPTH_CLAMP);
  }
  uploaded->Table->Deactivate();
  uploaded->Scalars->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void VolumeCasters::KeepOnly(const std::vector<vtkVolume*>& kept)
{
  for (auto it = this->Volumes.begin(); it != this->Volumes.end();)
  {
    const bool keep = it->second.Volume &&
      std::find(kept.begin(), kept.end(), it->first) != kept.end();
    it = keep ? std::next(it) : this->Volumes.erase(it);
  }
}

//------------------------------------------------------------------------------
void VolumeCasters::Release(vtkWindow* window)
{
  for (auto& entry : this->Volumes)
  {
    for (vtkTextureObject* texture : { entry.second.Scalars.Get(), entry.second.Table.Get() })
    {
      if (texture)
      {
        texture->ReleaseGraphicsResources(window);
      }
    }
  }
  this->Volumes.clear();
  this->Box->ReleaseGraphicsResources();
}

//------------------------------------------------------------------------------
std::size_t VolumeCasters::GetMemoryBytes() const
{
  std::size_t bytes = 0;
  for (const auto& entry : this->Volumes)
  {
    bytes += entry.second.Bytes;
  }
  return bytes;
}
} // namespace shadowmaps
