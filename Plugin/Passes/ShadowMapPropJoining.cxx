#include "ShadowMapPropJoining.h"

#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkProp.h"
#include "vtkRenderer.h"

#include <algorithm>

namespace shadowmaps
{
namespace
{
bool HasRenderPass(vtkInformation* info, vtkObjectBase* pass)
{
  vtkInformationObjectBaseVectorKey* key = vtkOpenGLRenderPass::RenderPasses();
  for (int i = 0; info->Has(key) && i < info->Length(key); ++i)
  {
    if (info->Get(key, i) == pass)
    {
      return true;
    }
  }
  return false;
}

// Whether another renderer of `renderer`'s window shows `prop` and draws it
// through no pass at all: with any pass of its own it would draw the prop with
// that pass's code, which the shadow pass's would join.
bool SharedWithARendererWithoutPasses(vtkProp* prop, vtkRenderer* renderer)
{
  for (int i = 0; i < prop->GetNumberOfConsumers(); ++i)
  {
    auto* other = vtkRenderer::SafeDownCast(prop->GetConsumer(i));
    if (other && other != renderer && other->GetRenderWindow() == renderer->GetRenderWindow() &&
      !other->GetPass())
    {
      return true;
    }
  }
  return false;
}

// Takes off `keys` the shadow passes but `pass` that kept the prop past their
// frames: a program holds one shadow pass's code.
void YieldKeptPlaces(vtkInformation* keys, vtkObjectBase* pass)
{
  vtkInformationObjectBaseVectorKey* key = vtkOpenGLRenderPass::RenderPasses();
  for (int i = keys->Has(key) ? keys->Length(key) - 1 : -1; i >= 0; --i)
  {
    vtkObjectBase* other = keys->Get(key, i);
    if (other != pass && other->IsA("vtkAbstractShadowMapPass"))
    {
      keys->Remove(key, other);
    }
  }
}

bool Holds(const std::vector<vtkWeakPointer<vtkProp>>& props, vtkProp* prop)
{
  return std::any_of(props.begin(), props.end(),
    [prop](const vtkWeakPointer<vtkProp>& held) { return held == prop; });
}
} // namespace

//------------------------------------------------------------------------------
PropJoining::PropJoining(vtkObjectBase* pass)
  : Pass(pass)
{
}

//------------------------------------------------------------------------------
PropJoining::~PropJoining()
{
  this->LeaveAll();
}

//------------------------------------------------------------------------------
void PropJoining::Join(
  vtkProp* const* props, int count, const std::function<bool(vtkProp*)>& takesPart)
{
  for (int i = 0; i < count; ++i)
  {
    vtkProp* prop = props[i];
    if (!prop->GetPropertyKeys())
    {
      vtkNew<vtkInformation> keys;
      prop->SetPropertyKeys(keys);
    }
    if (!takesPart(prop) || Holds(this->Joined, prop))
    {
      continue;
    }
    YieldKeptPlaces(prop->GetPropertyKeys(), this->Pass);
    if (!HasRenderPass(prop->GetPropertyKeys(), this->Pass))
    {
      prop->GetPropertyKeys()->Append(vtkOpenGLRenderPass::RenderPasses(), this->Pass);
    }
    this->Joined.emplace_back(prop);
  }
}

//------------------------------------------------------------------------------
void PropJoining::EndFrame(vtkRenderer* renderer)
{
  std::vector<vtkWeakPointer<vtkProp>> kept;
  for (const vtkWeakPointer<vtkProp>& prop : this->Joined)
  {
    if (prop && SharedWithARendererWithoutPasses(prop, renderer))
    {
      kept.push_back(prop);
    }
    else if (prop)
    {
      this->Leave(prop);
    }
  }
  // Kept by an earlier frame, and not drawn in this one.
  for (const vtkWeakPointer<vtkProp>& prop : this->Kept)
  {
    if (prop && !Holds(kept, prop) && !Holds(this->Joined, prop))
    {
      this->Leave(prop);
    }
  }
  this->Joined.clear();
  this->Kept.swap(kept);
}

//------------------------------------------------------------------------------
void PropJoining::LeaveAll()
{
  for (auto* props : { &this->Joined, &this->Kept })
  {
    for (const vtkWeakPointer<vtkProp>& prop : *props)
    {
      if (prop)
      {
        this->Leave(prop);
      }
    }
    props->clear();
  }
}

//------------------------------------------------------------------------------
void PropJoining::Leave(vtkProp* prop)
{
  vtkInformation* keys = prop->GetPropertyKeys();
  if (!HasRenderPass(keys, this->Pass))
  {
    return; // another shadow pass took its place (YieldKeptPlaces)
  }
  keys->Remove(vtkOpenGLRenderPass::RenderPasses(), this->Pass);
  // An empty list left behind tells VTK 9.1's volume ray caster that a pass
  // is still on the volume, whose last entry it then reads past the list.
  if (keys->Length(vtkOpenGLRenderPass::RenderPasses()) == 0)
  {
    keys->Remove(vtkOpenGLRenderPass::RenderPasses());
  }
}
} // namespace shadowmaps
