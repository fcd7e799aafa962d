#include "vtkVarianceShadowMapPass.h"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkUniformShadowMapViews.h"

vtkStandardNewMacro(vtkVarianceShadowMapPass);

//------------------------------------------------------------------------------
vtkVarianceShadowMapPass::vtkVarianceShadowMapPass()
  : vtkVarianceShadowMapPass(vtkSmartPointer<vtkUniformShadowMapViews>::New(),
      vtkSmartPointer<vtkVarianceShadowMapRepresentation>::New())
{
}

//------------------------------------------------------------------------------
vtkVarianceShadowMapPass::vtkVarianceShadowMapPass(
  vtkShadowMapViews* views, vtkVarianceShadowMapRepresentation* variance)
  : vtkAbstractShadowMapPass(views, variance)
  // The preset representation, which the pass holds until it is destroyed.
  , Variance(variance)
{
  this->NormalOffset = 0.0;
}

//------------------------------------------------------------------------------
vtkVarianceShadowMapPass::~vtkVarianceShadowMapPass() = default;

//------------------------------------------------------------------------------
void vtkVarianceShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
