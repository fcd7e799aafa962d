#include "ShadowMapProgramUniforms.h"

#include "ShadowMapCasting.h"
#include "ShadowMapRendererMaps.h"

#include "vtkShaderProgram.h"
#include "vtkShadowMapRepresentation.h"
#include "ShadowMapVTKCompat.h"

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <limits>

namespace shadowmaps
{
namespace
{
// Window coordinates (pixels of a resolution^2 map, window depth) to world.
glm::dmat4 WindowToWorld(const LightView& view, int resolution)
{
  const double half = 0.5 * resolution;
  glm::dmat4 viewport(1.0);
  viewport[0][0] = viewport[1][1] = half;
  viewport[3][0] = viewport[3][1] = half;
  viewport[2][2] = 0.5;
  viewport[3][2] = 0.5;
  return glm::inverse(viewport * view.ViewProjection());
}
} // namespace

//------------------------------------------------------------------------------
void ProgramUniforms::SetGroup(int index)
{
  if (index != this->Group.Index())
  {
    this->Group = ShaderGroup(index);
    this->Casters.SetGroup(index);
    this->Clear();
  }
}

//------------------------------------------------------------------------------
void ProgramUniforms::SetCastingView(const ShadowLight& light, const LightView& view,
  const ShadowFrame& frame, const CastingSettings& settings)
{
  // 32-bit depth (linear-depth views are never 16-bit): one polygon-offset unit
  // is 2^-24 for depths in [0.5, 1).
  constexpr float DepthUnit = 1.0f / 16777216.0f;
  const std::array<float, 3> windowToInverseW = WindowToInverseW(view, settings.Resolution);
  const auto slope = static_cast<float>(settings.SlopeScaledOffset);
  const auto constant = static_cast<float>(settings.ConstantOffset);
  if (view.LinearDepth)
  {
    // A directional light's linear depth spans its casters and B: its
    // slope-scaled term is capped at what a 45 degree surface needs in a
    // uniform map as deep as it is wide (SlopeScaledBias texels' worth, 2 /
    // resolution at the default). A spot's stored depth is its post-perspective
    // depth, crowded toward 1: no such cap.
    const float cap = light.Kind == LightKind::Directional
      ? slope / static_cast<float>(std::max(settings.Resolution, 1))
      : std::numeric_limits<float>::max();
    glPolygonOffset(0.0f, 0.0f);
    this->Casters.SetView(
      windowToInverseW, { { slope, constant * DepthUnit, cap } }, !view.Perspective);
    this->Casters.Impostors().SetDepthOffset(glm::vec2(0.0f));
  }
  else
  {
    glPolygonOffset(slope, constant);
    this->Casters.SetView(windowToInverseW, { { 0.0f, 0.0f, 0.0f } }, !view.Perspective);
    const float unit = settings.Depth16 ? 1.0f / 65535.0f : DepthUnit;
    this->Casters.Impostors().SetDepthOffset(glm::vec2(slope, constant * unit));
  }
  if (settings.LightDepth)
  {
    // Positions relative to the depth's origin, composed in double: no large
    // world coordinate is formed in float.
    const LightDepth& depth = light.Depth;
    const glm::dmat4 windowToLight =
      glm::translate(glm::dmat4(1.0), -depth.Origin) * WindowToWorld(view, settings.Resolution);
    this->Casters.SetLightDepth(
      glm::mat4(windowToLight), glm::vec4(depth.Plane), static_cast<float>(depth.PerDistance));
  }
  // Impostors (points as spheres, wide lines): their sizes follow the scene camera.
  const glm::dmat4 lightCameraProjection = CameraProjectionOf(view);
  this->Casters.Impostors().Set(view.ViewProjection(), glm::vec4(TowardLight(light)),
    glm::vec4(-glm::row(frame.CameraView, 2)),
    glm::vec4(static_cast<float>(lightCameraProjection[0][0] / frame.CameraProjection[0][0]),
      settings.SceneCameraParallel ? 1.0f : 0.0f, static_cast<float>(settings.Resolution),
      settings.LargestPointSize));
  this->StoreUniforms = settings.StoreUniforms;
  this->CasterPrograms.Invalidate();
}

//------------------------------------------------------------------------------
void ProgramUniforms::SetPeeling(bool secondPass, int peelUnit)
{
  this->Casters.SetPeeling(secondPass, peelUnit);
  this->CasterPrograms.Invalidate();
}

//------------------------------------------------------------------------------
void ProgramUniforms::SetTransmitting(bool transmitting)
{
  this->Casters.SetTransmitting(transmitting);
  this->CasterPrograms.Invalidate();
}

//------------------------------------------------------------------------------
void ProgramUniforms::SetDrawnRadius(float radius)
{
  this->Casters.Impostors().SetDrawnRadius(radius);
}

//------------------------------------------------------------------------------
void ProgramUniforms::Casting(vtkShaderProgram* program, const ReceiverTextureUnits& units,
  vtkShadowMapRepresentation* representation)
{
  if (!this->CasterPrograms.FirstUse(program))
  {
    return;
  }
  this->CastSinceSceneDraw.insert(program);
  this->Casters.ApplyCasting(program);
  SetFloatUniforms(program, this->StoreUniforms, this->Group.Suffix());
  // Not sampled while casting, but a sampler must not share a unit with one
  // of another type.
  this->ApplyReceiverSamplers(program, units, representation);
}

//------------------------------------------------------------------------------
bool ProgramUniforms::ApplyReceiverSamplers(vtkShaderProgram* program,
  const ReceiverTextureUnits& units, vtkShadowMapRepresentation* representation) const
{
  const std::string& suffix = this->Group.Suffix();
  if (!ReceiverUniforms::IsReceiver(program, suffix))
  {
    return false;
  }
  ReceiverUniforms::ApplyTextureUnits(program, units, suffix);
  representation->SetReceiverUniforms(program, suffix);
  return true;
}

//------------------------------------------------------------------------------
void ProgramUniforms::WhileOthersCast(vtkShaderProgram* program,
  const ReceiverTextureUnits& units, vtkShadowMapRepresentation* representation)
{
  if (!this->OthersCastingPrograms.FirstUse(program))
  {
    return;
  }
  this->Casters.ApplyPeelUnit(program);
  this->ApplyReceiverSamplers(program, units, representation);
}

//------------------------------------------------------------------------------
void ProgramUniforms::Receiving(vtkShaderProgram* program, RendererMaps& maps,
  const ReceiverTextureUnits& units, int resolution, double normalOffset, vtkShadowMapRepresentation* representation)
{
  if (!maps.Uniforms.FirstUseThisFrame(program))
  {
    return;
  }
  this->Casters.ApplyReceiving(program);
  const RendererMaps*& lastDrawnFor = this->LastDrawnFor[program];
  const bool anotherView = lastDrawnFor != &maps;
  lastDrawnFor = &maps;
  if (this->CastSinceSceneDraw.erase(program) > 0 || anotherView)
  {
    // The renderer sets a program's lighting uniforms again only when the
    // lights or the camera changed after it last did; the light cameras
    // changed after the scene's camera, and the casters' draws of this
    // program left the lights in their frames. Another renderer (or eye)
    // sharing the program left them in its camera's frame.
    program->SetUniformGroupUpdateTime(vtkShaderProgram::LightingGroup, 0);
  }
  const std::string& suffix = this->Group.Suffix();
  if (ReceiverUniforms::IsReceiver(program, suffix))
  {
    maps.Uniforms.Apply(program, units, resolution, normalOffset, suffix);
    representation->SetReceiverUniforms(program, suffix);
  }
}

//------------------------------------------------------------------------------
void ProgramUniforms::DrawnWithoutThePass(vtkShaderProgram* program,
  const ReceiverTextureUnits& units, vtkShadowMapRepresentation* representation)
{
  if (!this->ElsewherePrograms.FirstUse(program))
  {
    return;
  }
  this->Casters.ApplyReceiving(program);
  // The renderer sends its lights only when they changed since the program's
  // last lighting; the pass's renderer sent its own since.
  program->SetUniformGroupUpdateTime(vtkShaderProgram::LightingGroup, 0);
  this->LastDrawnFor[program] = nullptr;
  if (this->ApplyReceiverSamplers(program, units, representation))
  {
    program->SetUniformi(this->Group.Name("vtkShadowReceiving").c_str(), 0);
  }
}

//------------------------------------------------------------------------------
void ProgramUniforms::Forget(const RendererMaps* maps)
{
  for (auto& program : this->LastDrawnFor)
  {
    program.second = program.second == maps ? nullptr : program.second;
  }
}

//------------------------------------------------------------------------------
void ProgramUniforms::Clear()
{
  this->CasterPrograms.Clear();
  this->ElsewherePrograms.Clear();
  this->OthersCastingPrograms.Clear();
  this->CastSinceSceneDraw.clear();
  this->LastDrawnFor.clear();
}
} // namespace shadowmaps
