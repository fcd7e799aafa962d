// Per-texel rotations (cos, sin) of the filters' tap patterns (the Poisson
// disc, the soft shadows' kernels): a small repeating texture of random
// angles, one per window (GL context) a representation serves.
#ifndef ShadowMapRotationNoise_h
#define ShadowMapRotationNoise_h

#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include <map>
#include <string>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

namespace shadowmaps
{
class RotationNoise
{
public:
  /// Binds `window`'s texture (made on first use) to a texture unit.
  void Activate(vtkOpenGLRenderWindow* window);
  /// Points the sampler `vtkShadowNoise` at the active texture's unit.
  void SetUniform(vtkShaderProgram* program, const std::string& nameSuffix) const;
  void Deactivate();
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  std::map<vtkWindow*, vtkSmartPointer<vtkTextureObject>> PerWindow;
  vtkTextureObject* Active = nullptr;
};
} // namespace shadowmaps

#endif
