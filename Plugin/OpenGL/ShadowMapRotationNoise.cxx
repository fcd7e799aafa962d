#include "ShadowMapRotationNoise.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"

#include <cmath>
#include <random>
#include <vector>

namespace shadowmaps
{
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
void RotationNoise::Activate(vtkOpenGLRenderWindow* window)
{
  vtkSmartPointer<vtkTextureObject>& noise = this->PerWindow[window];
  if (!noise)
  {
    noise = CreateRotationNoise(window);
  }
  this->Active = noise;
  this->Active->Activate();
}

//------------------------------------------------------------------------------
void RotationNoise::SetUniform(vtkShaderProgram* program, const std::string& nameSuffix) const
{
  if (this->Active)
  {
    program->SetUniformi(("vtkShadowNoise" + nameSuffix).c_str(), this->Active->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void RotationNoise::Deactivate()
{
  if (this->Active)
  {
    this->Active->Deactivate();
    this->Active = nullptr;
  }
}

//------------------------------------------------------------------------------
void RotationNoise::ReleaseGraphicsResources(vtkWindow* window)
{
  const auto found = this->PerWindow.find(window);
  if (found != this->PerWindow.end())
  {
    found->second->ReleaseGraphicsResources(window);
    this->PerWindow.erase(found);
  }
}
} // namespace shadowmaps
