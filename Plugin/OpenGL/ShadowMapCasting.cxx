#include "ShadowMapCasting.h"

#include "ShadowMapFocusing.h"
#include "ShadowMapLight.h"
#include "ShadowMapGlm.h"
#include "ShadowMapTrapezoid.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "ShadowMapVTKCompat.h"

#include <algorithm>
#include <cmath>

namespace shadowmaps
{
namespace
{
bool IsRigid(const glm::dmat4& m)
{
  const glm::dmat3 rotation(m);
  const glm::dmat3 error = glm::transpose(rotation) * rotation - glm::dmat3(1.0);
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    largest = std::max({ largest, std::abs(error[c].x), std::abs(error[c].y), std::abs(error[c].z) });
  }
  return largest < 1e-9 && m[0][3] == 0.0 && m[1][3] == 0.0 && m[2][3] == 0.0 && m[3][3] == 1.0;
}
} // namespace

//------------------------------------------------------------------------------
glm::dmat4 CameraFrameOf(const LightView& view)
{
  if (IsRigid(view.View))
  {
    return view.View;
  }
  const glm::dmat4 transposed = glm::transpose(view.ViewProjection());
  const glm::dvec3 x = SafeDirection(glm::dvec3(transposed[0]));
  glm::dvec3 y = glm::dvec3(transposed[1]) - glm::dot(glm::dvec3(transposed[1]), x) * x;
  if (!(glm::length(y) > 1e-12 * glm::length(glm::dvec3(transposed[1]))))
  {
    y = glm::cross(x, std::abs(x.z) < 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(0.0, 1.0, 0.0));
  }
  y = glm::normalize(y);
  const glm::dvec3 z = glm::cross(x, y);
  // Rows x, y, z: the world's coordinates along them.
  return glm::transpose(glm::dmat4(glm::dvec4(x, 0.0), glm::dvec4(y, 0.0), glm::dvec4(z, 0.0),
    glm::dvec4(0.0, 0.0, 0.0, 1.0)));
}

//------------------------------------------------------------------------------
glm::dmat4 CameraProjectionOf(const LightView& view)
{
  return IsRigid(view.View) ? view.Projection
                            : view.ViewProjection() * glm::inverse(CameraFrameOf(view));
}

//------------------------------------------------------------------------------
void SetCameraToView(
  vtkCamera* camera, vtkMatrix4x4* projection, const LightView& view, bool sceneParallel)
{
  const glm::dmat4 frame = glm::inverse(CameraFrameOf(view));
  const glm::dvec3 eye(frame[3]);
  const glm::dvec3 forward(-frame[2]);
  const glm::dvec3 up(frame[1]);
  camera->SetPosition(eye.x, eye.y, eye.z);
  camera->SetFocalPoint(eye.x + forward.x, eye.y + forward.y, eye.z + forward.z);
  camera->SetViewUp(up.x, up.y, up.z);
  camera->SetParallelProjection(sceneParallel);
  ToVtk(CameraProjectionOf(view), projection);
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->UseExplicitProjectionTransformMatrixOn();
  camera->Modified();
}

//------------------------------------------------------------------------------
std::array<float, 3> WindowToInverseW(const LightView& view, int resolution)
{
  if (!view.LinearDepth)
  {
    return { { 0.0f, 0.0f, 1.0f } };
  }
  // u = x_window / resolution.
  const glm::vec3 t(TextureToInverseW(view));
  const float scale = 1.0f / static_cast<float>(std::max(resolution, 1));
  return { { t.x * scale, t.y * scale, t.z } };
}

//------------------------------------------------------------------------------
CasterGLState::CasterGLState(vtkOpenGLState* state, bool minimumBlending)
  : State(state)
  , Viewport(state)
  , Scissor(state, GL_SCISSOR_TEST)
  , Blend(state, GL_BLEND)
  , DepthTest(state, GL_DEPTH_TEST)
  , Offset(state, GL_POLYGON_OFFSET_FILL)
  , Multisample(state, GL_MULTISAMPLE)
  , DepthFunc(state)
  , DepthMask(state)
  , ClearColor(state)
  , ActiveTexture(state)
  , DepthClampWasOn(glIsEnabled(GL_DEPTH_CLAMP))
  , ProgramPointSizeWasOn(glIsEnabled(GL_PROGRAM_POINT_SIZE))
  , MinimumBlending(minimumBlending)
{
  this->ProgramPointSize = this->ProgramPointSizeWasOn;
  state->vtkglGetIntegerv(GL_BLEND_EQUATION_RGB, &this->BlendEquation[0]);
  state->vtkglGetIntegerv(GL_BLEND_EQUATION_ALPHA, &this->BlendEquation[1]);
  glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &this->PolygonOffset[0]);
  glGetFloatv(GL_POLYGON_OFFSET_UNITS, &this->PolygonOffset[1]);
  state->PushFramebufferBindings();
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglEnable(GL_POLYGON_OFFSET_FILL);
  // Multisampled value maps need it; other mappers may have turned it off.
  state->vtkglEnable(GL_MULTISAMPLE);
  glEnable(GL_DEPTH_CLAMP);
  if (this->MinimumBlending)
  {
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendEquation(GL_MIN);
  }
}

//------------------------------------------------------------------------------
void CasterGLState::UseProgramPointSize(bool on)
{
  if (on != this->ProgramPointSize)
  {
    on ? glEnable(GL_PROGRAM_POINT_SIZE) : glDisable(GL_PROGRAM_POINT_SIZE);
    this->ProgramPointSize = on;
  }
}

//------------------------------------------------------------------------------
CasterGLState::~CasterGLState()
{
  // What the caster draws set: the depth function, mask, clear colour and
  // active texture unit go back with their scoped members.
  glPolygonOffset(this->PolygonOffset[0], this->PolygonOffset[1]);
  if (!this->DepthClampWasOn)
  {
    glDisable(GL_DEPTH_CLAMP);
  }
  this->UseProgramPointSize(this->ProgramPointSizeWasOn);
  this->State->vtkglBlendEquationSeparate(
    static_cast<unsigned int>(this->BlendEquation[0]), static_cast<unsigned int>(this->BlendEquation[1]));
  this->State->PopFramebufferBindings();
}
} // namespace shadowmaps
