#include "ShadowMapLayerDrawing.h"

#include "ShadowMapCasting.h"
#include "ShadowMapRendererMaps.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkVolume.h"
#include "ShadowMapVTKCompat.h" // For the GL functions

#include <algorithm>

namespace shadowmaps
{
//------------------------------------------------------------------------------
LayerDrawing::LayerDrawing() = default;
LayerDrawing::~LayerDrawing() = default;

//------------------------------------------------------------------------------
void LayerDrawing::BeginUpdate(const Update& update)
{
  this->Current = update;
  this->Current.Casting.LargestPointSize = this->LargestPointSize();
  this->Draws = 0;
  this->SceneCamera = update.Renderer->GetActiveCamera();
  update.Renderer->SetActiveCamera(this->LightCamera);
}

//------------------------------------------------------------------------------
void LayerDrawing::EndUpdate()
{
  this->Current.Renderer->SetActiveCamera(this->SceneCamera);
  this->SceneCamera = nullptr;
  // The maps, frame and programs belong to the pass; none is held past the update.
  this->Current = Update();
}

//------------------------------------------------------------------------------
bool LayerDrawing::Draw(const ShadowLight& light, std::size_t v, int layer,
  std::vector<vtkProp*>& casters, bool& bound, std::string& error)
{
  RendererMaps& maps = *this->Current.Maps;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(this->Current.Renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  const LightView& view = light.Views[v];
  const bool linearDepths = view.LinearDepth && IsDepth(maps.Storage.Format);
  const bool peeling = maps.Storage.SecondDepth == SecondDepthMethod::Peeling;
  const bool multisampled = maps.Storage.Samples > 1;
  const bool keepsLightDepths = this->Current.KeepsLightDepths;
  bound = multisampled
    ? maps.Maps.BindSamples(state, maps.Storage.Samples, error)
    : maps.Maps.BindLayer(state, layer, error, linearDepths || peeling || keepsLightDepths);
  if (!bound)
  {
    return false;
  }
  this->Current.Programs->SetCastingView(light, view, *this->Current.Frame, this->Current.Casting);
  const bool drawn = this->DrawCastersIntoView(view, casters, linearDepths);
  bool ok = !multisampled || maps.Maps.ResolveSamples(state, layer, error);
  ok = ok && (!linearDepths || maps.LinearDepths.Render(window, maps.Maps, layer, error));
  ok = ok && (!keepsLightDepths || maps.LightDepths.Keep(state, maps.Maps, layer, error));
  ok = ok && (!peeling || !drawn || this->PeelSecondSurface(layer, casters, error));
  return ok &&
    (!maps.Storage.Transmittance || this->DrawTransmittance(layer, light, view, casters, error));
}

//------------------------------------------------------------------------------
void LayerDrawing::ClearLayer(bool linearDepths)
{
  const RendererMaps& maps = *this->Current.Maps;
  const int resolution = this->Current.Casting.Resolution;
  vtkOpenGLState* state =
    static_cast<vtkOpenGLRenderWindow*>(this->Current.Renderer->GetRenderWindow())->GetState();
  state->vtkglViewport(0, 0, resolution, resolution);
  state->vtkglClearDepth(1.0);
  GLbitfield buffers = GL_DEPTH_BUFFER_BIT;
  if (!IsDepth(maps.Storage.Format))
  {
    const float* clear = maps.Storage.ClearValues;
    state->vtkglClearColor(clear[0], clear[1], clear[2], clear[3]);
    buffers |= GL_COLOR_BUFFER_BIT;
  }
  else if (linearDepths)
  {
    state->vtkglClearColor(1.0, 1.0, 1.0, 1.0);
    buffers |= GL_COLOR_BUFFER_BIT;
  }
  state->vtkglClear(buffers);
  if (this->Current.KeepsLightDepths)
  {
    // The casters' light depths: far where none draws.
    const float far[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
    glClearBufferfv(GL_COLOR, 1, far);
  }
}

//------------------------------------------------------------------------------
bool LayerDrawing::DrawCastersIntoView(
  const LightView& view, std::vector<vtkProp*>& casters, bool linearDepths)
{
  this->ClearLayer(linearDepths);
  if (casters.empty())
  {
    return false;
  }
  SetCameraToView(this->LightCamera, this->LightProjection, view,
    this->Current.Casting.SceneCameraParallel);
  this->Current.JoinCasters(casters.data(), static_cast<int>(casters.size()));
  this->Draws += this->DrawCasters(casters, this->OpaquePass);
  return true;
}

//------------------------------------------------------------------------------
int LayerDrawing::DrawCasters(std::vector<vtkProp*>& casters, vtkRenderPass* pass)
{
  vtkRenderState casterState(this->Current.Renderer);
  casterState.SetPropArrayAndCount(casters.data(), static_cast<int>(casters.size()));
  casterState.SetFrameBuffer(nullptr);
  pass->Render(&casterState);
  return pass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
bool LayerDrawing::PeelSecondSurface(int layer, std::vector<vtkProp*>& casters, std::string& error)
{
  // The first pass left the nearest surface in both values and in the second
  // output; this one keeps, in y only, the nearest surface behind it.
  RendererMaps& maps = *this->Current.Maps;
  const int unit = this->Current.PeelUnit;
  vtkOpenGLState* state =
    static_cast<vtkOpenGLRenderWindow*>(this->Current.Renderer->GetRenderWindow())->GetState();
  if (!maps.Maps.BindLayer(state, layer, error, false))
  {
    return false;
  }
  vtkOpenGLState::ScopedglColorMask keepMask(state);
  vtkOpenGLState::ScopedglClearColor keepClearColor(state);
  vtkOpenGLState::ScopedglActiveTexture keepUnit(state);
  state->vtkglColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE);
  state->vtkglClearColor(1.0, 1.0, 1.0, 1.0);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // Through the state cache: the casters' own textures find their units by it.
  state->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, maps.Maps.GetSecondOutput());
  this->Current.Programs->SetPeeling(true, unit);
  this->Draws += this->DrawCasters(casters, this->OpaquePass);
  this->Current.Programs->SetPeeling(false, unit);
  state->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, 0);
  return true;
}

//------------------------------------------------------------------------------
bool LayerDrawing::DrawTransmittance(int layer, const ShadowLight& light, const LightView& view,
  std::vector<vtkProp*>& casters, std::string& error)
{
  // The light camera still looks through the layer's view, and the casters
  // joined when the layer's depths were drawn.
  auto* window = static_cast<vtkOpenGLRenderWindow*>(this->Current.Renderer->GetRenderWindow());
  this->Current.Programs->SetTransmitting(true);
  const bool ok = this->Current.Maps->Transmittances.Render(window->GetState(), layer,
    [&]() {
      if (!casters.empty())
      {
        this->Draws += this->DrawCasters(casters, this->TranslucentPass);
      }
      this->Draws += this->MarchVolumes(window, light, view, casters);
    },
    error);
  this->Current.Programs->SetTransmitting(false);
  return ok;
}

//------------------------------------------------------------------------------
int LayerDrawing::MarchVolumes(vtkOpenGLRenderWindow* window, const ShadowLight& light,
  const LightView& view, const std::vector<vtkProp*>& casters)
{
  int marched = 0;
  for (vtkProp* prop : casters)
  {
    // Only the volumes that can be marched cast (PropRecords).
    auto* volume = vtkVolume::SafeDownCast(prop);
    if (!volume)
    {
      continue;
    }
    std::string why;
    if (this->Current.Maps->Volumes.Draw(window, volume, light, view, why))
    {
      ++marched;
    }
    else if (why != this->WarnedVolumeDraw)
    {
      // Its data did not fit the GL: it casts nothing, the others still do.
      this->Warnings.push_back("A volume casts no shadow: " + why + ".");
      this->WarnedVolumeDraw = why;
    }
  }
  return marched;
}

//------------------------------------------------------------------------------
std::vector<std::string> LayerDrawing::TakeWarnings()
{
  std::vector<std::string> warnings;
  warnings.swap(this->Warnings);
  return warnings;
}

//------------------------------------------------------------------------------
float LayerDrawing::LargestPointSize()
{
  if (this->PointSizeLimit <= 0.0f)
  {
    float sizes[2] = { 1.0f, 1.0f };
    glGetFloatv(GL_POINT_SIZE_RANGE, sizes);
    this->PointSizeLimit = std::max(sizes[1], 1.0f);
  }
  return this->PointSizeLimit;
}

//------------------------------------------------------------------------------
void LayerDrawing::ReleaseGraphicsResources(vtkWindow* window)
{
  this->PointSizeLimit = 0.0f;
  this->OpaquePass->ReleaseGraphicsResources(window);
  this->TranslucentPass->ReleaseGraphicsResources(window);
}
} // namespace shadowmaps
