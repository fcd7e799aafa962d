#include "ShadowMapRendererMaps.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

namespace shadowmaps
{
//------------------------------------------------------------------------------
void RendererMaps::SwitchMaps(int resolution, int spare)
{
  if (this->Maps.GetResolution() != resolution && this->Maps.GetResolution() != 0)
  {
    this->Maps.Swap(this->SpareMaps);
  }
  if (this->SpareMaps.GetResolution() != spare || spare == resolution)
  {
    this->SpareMaps.Release();
  }
}

//------------------------------------------------------------------------------
void RendererMaps::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Maps.Release();
  this->SpareMaps.Release();
  this->Transmittances.Release();
  this->Volumes.Release(window);
  this->LinearDepths.ReleaseGraphicsResources(window);
  this->LightDepths.ReleaseGraphicsResources(window);
  this->Updates.Invalidate();
  this->Layers = 0;
}

//------------------------------------------------------------------------------
RendererMaps& MapsByRenderer::Select(vtkRenderer* renderer)
{
  const int eye =
    renderer->GetRenderWindow()->GetStereoRender() && !renderer->GetActiveCamera()->GetLeftEye()
    ? 1
    : 0;
  std::unique_ptr<RendererMaps>& maps = this->Maps[{ renderer, eye }];
  if (!maps)
  {
    maps = std::make_unique<RendererMaps>();
  }
  this->CurrentMaps = maps.get();
  return *maps;
}

//------------------------------------------------------------------------------
bool MapsByRenderer::Holds(vtkRenderer* renderer) const
{
  for (const auto& maps : this->Maps)
  {
    if (maps.first.first == renderer)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void MapsByRenderer::Release(vtkRenderer* renderer, vtkWindow* window,
  const std::function<void(const RendererMaps*)>& forgetting)
{
  for (auto it = this->Maps.begin(); it != this->Maps.end();)
  {
    if (it->first.first != renderer)
    {
      ++it;
      continue;
    }
    forgetting(it->second.get());
    it->second->ReleaseGraphicsResources(window);
    this->CurrentMaps = this->CurrentMaps == it->second.get() ? nullptr : this->CurrentMaps;
    it = this->Maps.erase(it);
  }
}

//------------------------------------------------------------------------------
void MapsByRenderer::ReleaseAll(vtkWindow* window)
{
  for (auto& maps : this->Maps)
  {
    maps.second->ReleaseGraphicsResources(window);
  }
  this->Maps.clear();
  this->CurrentMaps = nullptr;
}

//------------------------------------------------------------------------------
std::size_t MapsByRenderer::MemoryBytes() const
{
  std::size_t bytes = 0;
  for (const auto& maps : this->Maps)
  {
    bytes += maps.second->Maps.GetMemoryBytes() + maps.second->SpareMaps.GetMemoryBytes() +
      maps.second->Transmittances.GetMemoryBytes() +
      maps.second->Volumes.GetMemoryBytes();
  }
  return bytes;
}
} // namespace shadowmaps
