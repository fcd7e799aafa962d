#include "vtkDualDepthShadowMapPass.h"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkUniformShadowMapViews.h"

vtkStandardNewMacro(vtkDualDepthShadowMapPass);

//------------------------------------------------------------------------------
vtkDualDepthShadowMapPass::vtkDualDepthShadowMapPass()
  : vtkDepthShadowMapPass(vtkSmartPointer<vtkUniformShadowMapViews>::New(),
      vtkSmartPointer<vtkDualDepthShadowMapRepresentation>::New())
  , DualDepth(vtkDualDepthShadowMapRepresentation::SafeDownCast(this->GetDepthRepresentation()))
{
  this->NormalOffset = 0.0;
}

//------------------------------------------------------------------------------
vtkDualDepthShadowMapPass::~vtkDualDepthShadowMapPass() = default;

//------------------------------------------------------------------------------
void vtkDualDepthShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
