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
  : vtkDepthShadowMapPass(views, vtkSmartPointer<vtkDepthShadowMapRepresentation>::New())
{
}

//------------------------------------------------------------------------------
vtkDepthShadowMapPass::vtkDepthShadowMapPass(
  vtkShadowMapViews* views, vtkDepthShadowMapRepresentation* depth)
  : vtkAbstractShadowMapPass(views, depth)
  // The preset representation, which the pass holds until it is destroyed.
  , Depth(depth)
{
}

//------------------------------------------------------------------------------
vtkDepthShadowMapPass::~vtkDepthShadowMapPass() = default;

//------------------------------------------------------------------------------
void vtkDepthShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
