#include "vtkDepthShadowMapRepresentation.h"

#include "ShadowMapRotationNoise.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsDepthLookupFS.h"
#include "vtkShadowMapsFilterFS.h"
#include "vtkShadowMapsSoftFS.h"
#include "vtkShadowMapsSoftKernelFS.h"

#include <sstream>

vtkStandardNewMacro(vtkDepthShadowMapRepresentation);


//------------------------------------------------------------------------------
vtkDepthShadowMapRepresentation::vtkDepthShadowMapRepresentation()
  : Noise(new shadowmaps::RotationNoise())
{
}

//------------------------------------------------------------------------------
vtkDepthShadowMapRepresentation::~vtkDepthShadowMapRepresentation() = default;

//------------------------------------------------------------------------------
std::string vtkDepthShadowMapRepresentation::GetReceiverLookupCode() const
{
  return std::string(vtkShadowMapsDepthLookupFS) + vtkShadowMapsFilterFS;
}

//------------------------------------------------------------------------------
std::string vtkDepthShadowMapRepresentation::GetReceiverDefinitions() const
{
  std::ostringstream definitions;
  definitions << "#define VTK_SHADOW_FILTER " << this->Filter << "\n"
              << "#define VTK_SHADOW_KERNEL " << this->KernelSize << "\n"
              << "#define VTK_SHADOW_POISSON_SAMPLES " << this->PoissonSamples << "\n";
  return definitions.str();
}

//------------------------------------------------------------------------------
double vtkDepthShadowMapRepresentation::GetFilterReachTexels() const
{
  switch (this->Filter)
  {
    case PCF_NXN:
      return 0.5 * this->KernelSize + 1.0;
    case POISSON:
      return this->FilterRadius + 1.0;
    default:
      return 1.0;
  }
}

//------------------------------------------------------------------------------
std::string vtkDepthShadowMapRepresentation::GetSoftShadowCode() const
{
  return std::string(vtkShadowMapsSoftKernelFS) + vtkShadowMapsSoftFS;
}

//------------------------------------------------------------------------------
bool vtkDepthShadowMapRepresentation::GetLinearFiltering() const
{
  return this->Filter != HARD;
}

//------------------------------------------------------------------------------
bool vtkDepthShadowMapRepresentation::GetPostProcessingFollowsFilterScale() const
{
  return false;
}

//------------------------------------------------------------------------------
shadowmaps::DepthOffset vtkDepthShadowMapRepresentation::GetCasterDepthOffset() const
{
  shadowmaps::DepthOffset offset;
  offset.SlopeScaled = this->SlopeScaledBias;
  offset.Constant = this->ConstantBias;
  return offset;
}

//------------------------------------------------------------------------------
void vtkDepthShadowMapRepresentation::ActivateReceiverResources(vtkOpenGLRenderWindow* window)
{
  this->Noise->Activate(window);
}

//------------------------------------------------------------------------------
void vtkDepthShadowMapRepresentation::SetReceiverUniforms(
  vtkShaderProgram* program, const std::string& nameSuffix)
{
  this->Noise->SetUniform(program, nameSuffix);
  program->SetUniformf(("vtkShadowFilterRadius" + nameSuffix).c_str(), static_cast<float>(this->FilterRadius));
}

//------------------------------------------------------------------------------
void vtkDepthShadowMapRepresentation::DeactivateReceiverResources()
{
  this->Noise->Deactivate();
}

//------------------------------------------------------------------------------
void vtkDepthShadowMapRepresentation::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Noise->ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkDepthShadowMapRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Filter: " << this->Filter << "\n";
  os << indent << "KernelSize: " << this->KernelSize << "\n";
  os << indent << "FilterRadius: " << this->FilterRadius << "\n";
  os << indent << "PoissonSamples: " << this->PoissonSamples << "\n";
  os << indent << "ConstantBias: " << this->ConstantBias << "\n";
  os << indent << "SlopeScaledBias: " << this->SlopeScaledBias << "\n";
}
