#include "vtkWarpedShadowMapPass.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkWarpedShadowMapPass);

void vtkWarpedShadowMapPass::ComputeLightViews(Internals& internals, int lightIndex)
{
  this->FitLightViewsUniform(internals, lightIndex);
}

void vtkWarpedShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
