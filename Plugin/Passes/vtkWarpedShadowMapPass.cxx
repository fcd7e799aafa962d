#include "vtkWarpedShadowMapPass.h"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

vtkStandardNewMacro(vtkWarpedShadowMapPass);

//------------------------------------------------------------------------------
vtkWarpedShadowMapPass::vtkWarpedShadowMapPass()
  : vtkDepthShadowMapPass(vtkSmartPointer<vtkWarpedShadowMapViews>::New())
  // The preset views, which the pass holds until it is destroyed.
  , Warped(vtkWarpedShadowMapViews::SafeDownCast(this->GetViews()))
{
}

//------------------------------------------------------------------------------
vtkWarpedShadowMapPass::~vtkWarpedShadowMapPass() = default;

//------------------------------------------------------------------------------
void vtkWarpedShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
