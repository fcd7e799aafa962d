#include "vtkShadowMapRepresentation.h"

//------------------------------------------------------------------------------
void vtkShadowMapRepresentation::GetMapStorage(shadowmaps::MapStorage& storage) const
{
  storage = shadowmaps::MapStorage();
}

//------------------------------------------------------------------------------
std::string vtkShadowMapRepresentation::GetReceiverDefinitions() const
{
  return std::string();
}

//------------------------------------------------------------------------------
double vtkShadowMapRepresentation::GetFilterReachTexels() const
{
  return 1.0;
}

//------------------------------------------------------------------------------
bool vtkShadowMapRepresentation::GetLinearFiltering() const
{
  return true;
}

//------------------------------------------------------------------------------
shadowmaps::DepthOffset vtkShadowMapRepresentation::GetCasterDepthOffset() const
{
  return shadowmaps::DepthOffset();
}

//------------------------------------------------------------------------------
bool vtkShadowMapRepresentation::PostProcessMaps(
  vtkOpenGLRenderer*, shadowmaps::TextureArray&, const std::vector<shadowmaps::RenderedLayer>&)
{
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowMapRepresentation::GetPostProcessingFollowsFilterScale() const
{
  return true;
}

//------------------------------------------------------------------------------
std::string vtkShadowMapRepresentation::GetSoftShadowCode() const
{
  return std::string();
}

//------------------------------------------------------------------------------
bool vtkShadowMapRepresentation::GetSupportsSizedLights() const
{
  return !this->GetSoftShadowCode().empty();
}

//------------------------------------------------------------------------------
void vtkShadowMapRepresentation::ActivateReceiverResources(vtkOpenGLRenderWindow*) {}

//------------------------------------------------------------------------------
void vtkShadowMapRepresentation::SetReceiverUniforms(vtkShaderProgram*, const std::string&) {}

//------------------------------------------------------------------------------
void vtkShadowMapRepresentation::DeactivateReceiverResources() {}

//------------------------------------------------------------------------------
void vtkShadowMapRepresentation::ReleaseGraphicsResources(vtkWindow*) {}

//------------------------------------------------------------------------------
void vtkShadowMapRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
