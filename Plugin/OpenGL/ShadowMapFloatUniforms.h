// Float uniforms by name, set on a program together: the values a
// representation's GLSL reads that a user may drag (MapStorage::StoreUniforms),
// which as uniforms change no shader.
#ifndef ShadowMapFloatUniforms_h
#define ShadowMapFloatUniforms_h

#include "vtkShaderProgram.h"

#include <string>
#include <utility>
#include <vector>

namespace shadowmaps
{
using FloatUniforms = std::vector<std::pair<std::string, float>>;

/// Sets each uniform, its name followed by `suffix` (ShaderGroup::Suffix).
inline void SetFloatUniforms(
  vtkShaderProgram* program, const FloatUniforms& uniforms, const std::string& suffix = {})
{
  for (const auto& uniform : uniforms)
  {
    program->SetUniformf((uniform.first + suffix).c_str(), uniform.second);
  }
}
} // namespace shadowmaps

#endif
