#include "ShadowMapPropParts.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkMapper.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

namespace shadowmaps
{
//------------------------------------------------------------------------------
void ForEachPart(vtkProp* prop, const std::function<void(vtkProp*, vtkMatrix4x4*)>& visit)
{
  // An actor is its own only path, whose matrix is its own: vtkProp3D builds
  // that path anew at every traversal, which costs more than the rest of a
  // caster's version.
  if (auto* actor = vtkActor::SafeDownCast(prop))
  {
    visit(actor, actor->GetMatrix());
    return;
  }
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    vtkAssemblyNode* leaf = path->GetLastNode();
    visit(leaf->GetViewProp(), leaf->GetMatrix());
  }
}

//------------------------------------------------------------------------------
vtkAbstractMapper* MapperOf(vtkProp* prop)
{
  if (auto* actor = vtkActor::SafeDownCast(prop))
  {
    return actor->GetMapper();
  }
  if (auto* volume = vtkVolume::SafeDownCast(prop))
  {
    return volume->GetMapper();
  }
  return nullptr;
}

//------------------------------------------------------------------------------
void RebuildShaders(vtkProp* prop)
{
  ForEachPart(prop, [](vtkProp* part, vtkMatrix4x4*) {
    if (auto* actor = vtkActor::SafeDownCast(part))
    {
      actor->GetProperty()->Modified();
    }
    else if (auto* volume = vtkVolume::SafeDownCast(part))
    {
      // The ray caster rebuilds its shader when its volume property changes.
      if (vtkVolumeProperty* property = volume->GetProperty())
      {
        property->Modified();
      }
    }
  });
}
} // namespace shadowmaps
