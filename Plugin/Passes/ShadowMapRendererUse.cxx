#include "ShadowMapRendererUse.h"

#include "vtkCommand.h"
#include "vtkRenderer.h"

#include <algorithm>

namespace shadowmaps
{
//------------------------------------------------------------------------------
RendererUse::RendererUse(std::function<void(vtkRenderer*)> dropped)
  : Dropped(std::move(dropped))
{
}

//------------------------------------------------------------------------------
RendererUse::~RendererUse()
{
  while (!this->Watches.empty())
  {
    this->Forget(this->Watches.begin());
  }
}

//------------------------------------------------------------------------------
void RendererUse::Drawn(vtkRenderer* renderer)
{
  auto watch = std::find_if(this->Watches.begin(), this->Watches.end(),
    [renderer](const Watch& w) { return w.Renderer == renderer; });
  if (watch == this->Watches.end())
  {
    Watch added;
    added.Renderer = renderer;
    added.EndObserver = renderer->AddObserver(vtkCommand::EndEvent, this, &RendererUse::FrameEnded);
    added.DeleteObserver = renderer->AddObserver(vtkCommand::DeleteEvent, this, &RendererUse::Deleted);
    watch = this->Watches.insert(this->Watches.end(), added);
  }
  watch->DrawnThisFrame = true;
}

//------------------------------------------------------------------------------
void RendererUse::FrameEnded(vtkObject* caller, unsigned long, void*)
{
  auto watch = std::find_if(this->Watches.begin(), this->Watches.end(),
    [caller](const Watch& w) { return w.Renderer == caller; });
  if (watch == this->Watches.end())
  {
    return;
  }
  if (watch->DrawnThisFrame)
  {
    watch->DrawnThisFrame = false;
    return;
  }
  auto* renderer = static_cast<vtkRenderer*>(caller);
  this->Forget(watch);
  this->Dropped(renderer);
}

//------------------------------------------------------------------------------
void RendererUse::Deleted(vtkObject* caller, unsigned long, void*)
{
  auto watch = std::find_if(this->Watches.begin(), this->Watches.end(),
    [caller](const Watch& w) { return w.Renderer == caller; });
  if (watch != this->Watches.end())
  {
    this->Forget(watch);
    this->Dropped(static_cast<vtkRenderer*>(caller));
  }
}

//------------------------------------------------------------------------------
void RendererUse::Forget(std::vector<Watch>::iterator watch)
{
  if (watch->Renderer)
  {
    watch->Renderer->RemoveObserver(watch->EndObserver);
    watch->Renderer->RemoveObserver(watch->DeleteObserver);
  }
  this->Watches.erase(watch);
}
} // namespace shadowmaps
