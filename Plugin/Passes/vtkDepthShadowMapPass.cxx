#include "vtkDepthShadowMapPass.h"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkUniformShadowMapViews.h"

vtkStandardNewMacro(vtkDepthShadowMapPass);

//------------------------------------------------------------------------------
vtkDepthShadowMapPass::vtkDepthShadowMapPass()
  : vtkDepthShadowMapPass(vtkSmartPointer<vtkUniformShadowMapViews>::New())
{
}

//------------------------------------------------------------------------------
vtkDepthShadowMapPass::vtkDepthShadowMapPass(vtkShadowMapViews* views)
  : vtkAbstractShadowMapPass(views, vtkSmartPointer<vtkDepthShadowMapRepresentation>::New())
  // The preset representation, which the pass holds until it is destroyed.
  , Depth(vtkDepthShadowMapRepresentation::SafeDownCast(this->GetRepresentation()))
{
}

//------------------------------------------------------------------------------
vtkDepthShadowMapPass::~vtkDepthShadowMapPass() = default;

//------------------------------------------------------------------------------
void vtkDepthShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
