#include "ShadowMapReceiverTextures.h"

#include "ShadowMapRendererMaps.h"
#include "vtkShadowMapRepresentation.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureUnitManager.h"
#include "ShadowMapVTKCompat.h" // For the GL functions

namespace shadowmaps
{
namespace
{
// A unit of its own with no texture array bound, so that creating a texture,
// which binds it to the active unit, disturbs no other pass's texture (e.g.
// the tone-mapping pass's colour).
int AllocateEmptyUnit(vtkOpenGLRenderWindow* window)
{
  const int unit = window->GetTextureUnitManager()->Allocate();
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  return unit;
}

void FreeArrayUnit(vtkOpenGLRenderWindow* window, int& unit)
{
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  window->GetTextureUnitManager()->Free(unit);
  unit = -1;
}
} // namespace

//------------------------------------------------------------------------------
bool ReceiverTextures::Reserve(vtkOpenGLRenderWindow* window, const MapStorage& storage,
  bool rawDepths, vtkShadowMapRepresentation* representation)
{
  if (this->Reserved)
  {
    return false;
  }
  this->Receivers.Maps = AllocateEmptyUnit(window);
  if (storage.SecondDepth == SecondDepthMethod::Peeling)
  {
    this->PeelUnit = window->GetTextureUnitManager()->Allocate();
  }
  if (rawDepths)
  {
    this->Receivers.RawDepths = window->GetTextureUnitManager()->Allocate();
  }
  if (storage.Transmittance)
  {
    this->Receivers.Transmittances = AllocateEmptyUnit(window);
  }
  representation->ActivateReceiverResources(window);
  this->Reserved = true;
  return true;
}

//------------------------------------------------------------------------------
void ReceiverTextures::Bind(
  vtkOpenGLRenderWindow* window, RendererMaps& maps, vtkShadowMapRepresentation* representation)
{
  vtkOpenGLState* state = window->GetState();
  maps.Maps.SetLinearFiltering(representation->GetLinearFiltering());
  maps.Maps.BindToUnit(state, this->Receivers.Maps);
  if (this->Receivers.RawDepths >= 0)
  {
    maps.Maps.BindRawDepthToUnit(state, this->Receivers.RawDepths);
  }
  if (this->Receivers.Transmittances >= 0)
  {
    maps.Transmittances.BindToUnit(state, this->Receivers.Transmittances);
  }
}

//------------------------------------------------------------------------------
void ReceiverTextures::Release(
  vtkOpenGLRenderWindow* window, vtkShadowMapRepresentation* representation)
{
  if (!this->Reserved)
  {
    return;
  }
  FreeArrayUnit(window, this->Receivers.Maps);
  if (this->PeelUnit >= 0)
  {
    window->GetTextureUnitManager()->Free(this->PeelUnit);
    this->PeelUnit = -1;
  }
  if (this->Receivers.RawDepths >= 0)
  {
    TextureArray::UnbindRawDepth(window->GetState(), this->Receivers.RawDepths);
    window->GetTextureUnitManager()->Free(this->Receivers.RawDepths);
    this->Receivers.RawDepths = -1;
  }
  if (this->Receivers.Transmittances >= 0)
  {
    FreeArrayUnit(window, this->Receivers.Transmittances);
  }
  representation->DeactivateReceiverResources();
  this->Reserved = false;
}
} // namespace shadowmaps
