#include "vtkUniformShadowMapViews.h"

#include "ShadowMapLight.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkUniformShadowMapViews);

//------------------------------------------------------------------------------
void vtkUniformShadowMapViews::FitLight(
  const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light)
{
  light.PossibleFeatures = 0;
  vtkShadowMapViews::FitUniformViews(frame, light);
}
