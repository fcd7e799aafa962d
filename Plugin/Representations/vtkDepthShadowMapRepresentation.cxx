#include "vtkDepthShadowMapRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsDepthLookupFS.h"
#include "vtkShadowMapsFilterFS.h"
#include "vtkTextureObject.h"

#include <cmath>
#include <random>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkDepthShadowMapRepresentation);

namespace
{
constexpr int NoiseSize = 32;

vtkSmartPointer<vtkTextureObject> CreateRotationNoise(vtkOpenGLRenderWindow* window)
{
  std::mt19937 generator(20261122);
  std::uniform_real_distribution<float> angle(0.0f, 6.2831853f);
  std::vector<float> rotations(NoiseSize * NoiseSize * 2);
  for (size_t i = 0; i < rotations.size(); i += 2)
  {
    const float a = angle(generator);
    rotations[i] = std::cos(a);
    rotations[i + 1] = std::sin(a);
  }
  auto noise = vtkSmartPointer<vtkTextureObject>::New();
  noise->SetContext(window);
  noise->SetWrapS(vtkTextureObject::Repeat);
  noise->SetWrapT(vtkTextureObject::Repeat);
  noise->SetMinificationFilter(vtkTextureObject::Nearest);
  noise->SetMagnificationFilter(vtkTextureObject::Nearest);
  noise->Create2DFromRaw(NoiseSize, NoiseSize, 2, VTK_FLOAT, rotations.data());
  return noise;
}
} // namespace

//------------------------------------------------------------------------------
vtkDepthShadowMapRepresentation::vtkDepthShadowMapRepresentation() = default;

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
bool vtkDepthShadowMapRepresentation::GetSupportsSizedLights() const
{
  return true;
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
  // A representation may serve passes in several windows: each GL context
  // gets its own texture.
  vtkSmartPointer<vtkTextureObject>& noise = this->NoisePerWindow[window];
  if (!noise)
  {
    noise = CreateRotationNoise(window);
  }
  this->Noise = noise;
  this->Noise->Activate();
}

//------------------------------------------------------------------------------
void vtkDepthShadowMapRepresentation::SetReceiverUniforms(vtkShaderProgram* program)
{
  program->SetUniformi("vtkShadowNoise", this->Noise->GetTextureUnit());
  program->SetUniformf("vtkShadowFilterRadius", static_cast<float>(this->FilterRadius));
}

//------------------------------------------------------------------------------
void vtkDepthShadowMapRepresentation::DeactivateReceiverResources()
{
  if (this->Noise)
  {
    this->Noise->Deactivate();
    this->Noise = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkDepthShadowMapRepresentation::ReleaseGraphicsResources(vtkWindow* window)
{
  const auto found = this->NoisePerWindow.find(window);
  if (found != this->NoisePerWindow.end())
  {
    found->second->ReleaseGraphicsResources(window);
    this->NoisePerWindow.erase(found);
  }
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
