#include "vtkCascadedShadowMapPass.h"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

vtkStandardNewMacro(vtkCascadedShadowMapPass);

//------------------------------------------------------------------------------
vtkCascadedShadowMapPass::vtkCascadedShadowMapPass()
  : vtkDepthShadowMapPass(vtkSmartPointer<vtkCascadedShadowMapViews>::New())
  // The preset views, which the pass holds until it is destroyed.
  , Cascaded(vtkCascadedShadowMapViews::SafeDownCast(this->GetViews()))
{
  this->Resolution = 1024;
}

//------------------------------------------------------------------------------
vtkCascadedShadowMapPass::~vtkCascadedShadowMapPass() = default;

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
