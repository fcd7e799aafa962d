#include "ShadowMapTransmittance.h"

#include "vtkOpenGLState.h"
#include "ShadowMapVTKCompat.h" // For the GL functions

namespace shadowmaps
{
namespace
{
// What Render changes, put back when it goes.
class TransmittanceBlending
{
public:
  explicit TransmittanceBlending(vtkOpenGLState* state)
    : State(state)
    , Blend(state, GL_BLEND)
    , DepthTest(state, GL_DEPTH_TEST)
    , Offset(state, GL_POLYGON_OFFSET_FILL)
    , BlendFunction(state)
    , ClearColor(state)
  {
    state->vtkglGetIntegerv(GL_BLEND_EQUATION_RGB, &this->Equation[0]);
    state->vtkglGetIntegerv(GL_BLEND_EQUATION_ALPHA, &this->Equation[1]);
    // Every translucent fragment counts, whatever its depth.
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_POLYGON_OFFSET_FILL);
    state->vtkglEnable(GL_BLEND);
    // rgb: destination times source (a product in any order); alpha: the least.
    state->vtkglBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ONE, GL_ONE);
    state->vtkglBlendEquationSeparate(GL_FUNC_ADD, GL_MIN);
  }
  ~TransmittanceBlending()
  {
    this->State->vtkglBlendEquationSeparate(
      static_cast<unsigned int>(this->Equation[0]), static_cast<unsigned int>(this->Equation[1]));
  }
  TransmittanceBlending(const TransmittanceBlending&) = delete;
  TransmittanceBlending& operator=(const TransmittanceBlending&) = delete;

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable Offset;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunction;
  vtkOpenGLState::ScopedglClearColor ClearColor;
  int Equation[2] = { GL_FUNC_ADD, GL_FUNC_ADD };
};
} // namespace

//------------------------------------------------------------------------------
bool TransmittanceMaps::Reserve(int resolution, int layers, std::string& error)
{
  // 32-bit floats: the light depth compared with receivers needs their
  // precision (16-bit floats step by 2^-11 of the light's depth range), and
  // products of two crossings then come out the same in either order.
  if (!this->Layers.Reserve(resolution, layers, TexelFormat::FourFloats, false, error, false))
  {
    error = "transmittance maps: " + error;
    return false;
  }
  this->Layers.SetLinearFiltering(false);
  return true;
}

//------------------------------------------------------------------------------
bool TransmittanceMaps::Render(
  vtkOpenGLState* state, int layer, const std::function<void()>& draw, std::string& error)
{
  if (!this->Layers.BindLayer(state, layer, error))
  {
    error = "transmittance maps: " + error;
    return false;
  }
  TransmittanceBlending blending(state);
  const int resolution = this->Layers.GetResolution();
  state->vtkglViewport(0, 0, resolution, resolution);
  // All light, and the far light depth: no translucent surface yet.
  state->vtkglClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  draw();
  return true;
}

//------------------------------------------------------------------------------
void TransmittanceMaps::BindToUnit(vtkOpenGLState* state, int unit) const
{
  this->Layers.BindToUnit(state, unit);
}
} // namespace shadowmaps
