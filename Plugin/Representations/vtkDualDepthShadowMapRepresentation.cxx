#include "vtkDualDepthShadowMapRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsDualDepthLookupFS.h"
#include "vtkShadowMapsFilterFS.h"

#include <sstream>

vtkStandardNewMacro(vtkDualDepthShadowMapRepresentation);

//------------------------------------------------------------------------------
vtkDualDepthShadowMapRepresentation::vtkDualDepthShadowMapRepresentation()
{
  this->ConstantBias = 0.0;
  this->SlopeScaledBias = 0.0;
}

//------------------------------------------------------------------------------
vtkDualDepthShadowMapRepresentation::~vtkDualDepthShadowMapRepresentation() = default;

//------------------------------------------------------------------------------
void vtkDualDepthShadowMapRepresentation::GetMapStorage(shadowmaps::MapStorage& storage) const
{
  storage = shadowmaps::MapStorage();
  storage.Format = shadowmaps::TexelFormat::TwoFloats;
  // The second depth is the nearest back face, for any casters.
  const int method = this->Mode == SECOND_DEPTH && this->LayerMethod == AUTO ? MINIMUM_BLENDING
                                                                              : this->LayerMethod;
  switch (method)
  {
    case MINIMUM_BLENDING:
      storage.SecondDepth = shadowmaps::SecondDepthMethod::FrontAndBackFaces;
      break;
    case DEPTH_PEELING:
      storage.SecondDepth = shadowmaps::SecondDepthMethod::Peeling;
      break;
    default:
      storage.SecondDepth = shadowmaps::SecondDepthMethod::Auto;
  }
}

//------------------------------------------------------------------------------
std::string vtkDualDepthShadowMapRepresentation::GetReceiverLookupCode() const
{
  return std::string(vtkShadowMapsDualDepthLookupFS) + vtkShadowMapsFilterFS;
}

//------------------------------------------------------------------------------
std::string vtkDualDepthShadowMapRepresentation::GetReceiverDefinitions() const
{
  std::ostringstream definitions;
  definitions << this->Superclass::GetReceiverDefinitions() << "#define VTK_SHADOW_DUAL_MODE "
              << this->Mode << "\n#define VTK_SHADOW_RECEIVER_PLANE\n";
  return definitions.str();
}

//------------------------------------------------------------------------------
bool vtkDualDepthShadowMapRepresentation::GetLinearFiltering() const
{
  // Texels are fetched one by one: each holds two depths, not a visibility.
  return false;
}

//------------------------------------------------------------------------------
void vtkDualDepthShadowMapRepresentation::SetReceiverUniforms(
  vtkShaderProgram* program, const std::string& nameSuffix)
{
  this->Superclass::SetReceiverUniforms(program, nameSuffix);
  program->SetUniformf(("vtkShadowDualOffset" + nameSuffix).c_str(), static_cast<float>(this->DualOffset));
}

//------------------------------------------------------------------------------
void vtkDualDepthShadowMapRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "LayerMethod: " << this->LayerMethod << "\n";
  os << indent << "DualOffset: " << this->DualOffset << "\n";
}
