#include "vtkShadowMapCasterPass.h"

#include "vtkObjectFactory.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsCasterFS.h"

#include <sstream>

vtkStandardNewMacro(vtkShadowMapCasterPass);

namespace
{
size_t CountOccurrences(const std::string& text, const std::string& word)
{
  size_t count = 0;
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
  {
    ++count;
  }
  return count;
}

std::string WithoutLineComments(const std::string& source)
{
  std::string code;
  std::istringstream lines(source);
  for (std::string line; std::getline(lines, line);)
  {
    code += line.substr(0, line.find("//"));
    code += '\n';
  }
  return code;
}

// Every VTK polydata fragment shader discards fully transparent fragments once;
// more discards, or a written depth, mean the shader cuts its own silhouette.
bool ShapesItsOwnFragments(const std::string& fragmentShader)
{
  const std::string code = WithoutLineComments(fragmentShader);
  return code.find("gl_FragDepth") != std::string::npos || CountOccurrences(code, "discard") > 1;
}

// Appends the store code at the end of main(), the last function of VTK's
// fragment shaders, reading the depth the shader wrote if it writes one.
void AppendStoreCode(std::string& fragmentShader, const std::string& storeCode)
{
  const size_t end = fragmentShader.rfind('}');
  if (end == std::string::npos)
  {
    return;
  }
  const bool writesDepth =
    WithoutLineComments(fragmentShader).find("gl_FragDepth") != std::string::npos;
  fragmentShader.insert(end,
    std::string("  {\n  float vtkShadowCasterDepth = ") +
      (writesDepth ? "gl_FragDepth" : "gl_FragCoord.z") + ";\n" + storeCode + "\n  }\n");
}
} // namespace

void vtkShadowMapCasterPass::SetStoreCode(const std::string& code)
{
  if (code != this->StoreCode)
  {
    this->StoreCode = code;
    this->Modified();
  }
}

bool vtkShadowMapCasterPass::PostReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  if (ShapesItsOwnFragments(fragmentShader))
  {
    ++this->NumberOfOwnFragmentShaders;
    if (!this->StoreCode.empty())
    {
      AppendStoreCode(fragmentShader, this->StoreCode);
    }
    return true;
  }
  ++this->NumberOfDepthOnlyShaders;
  std::string caster = vtkShadowMapsCasterFS;
  std::string defines = this->CasterFaces == 0 ? "#define VTK_SHADOW_CAST_FRONT_ONLY\n"
    : this->CasterFaces == 1                   ? "#define VTK_SHADOW_CAST_BACK_ONLY\n"
                                               : "";
  std::string store = "  gl_FragData[0] = vec4(1.0);";
  if (!this->StoreCode.empty())
  {
    store = "  float vtkShadowCasterDepth = gl_FragCoord.z;\n" + this->StoreCode;
  }
  vtkShaderProgram::Substitute(caster, "//VTK::ShadowMaps::Dec", defines);
  vtkShaderProgram::Substitute(caster, "//VTK::ShadowMaps::Impl", store);
  fragmentShader = caster;
  return true;
}

void vtkShadowMapCasterPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CasterFaces: " << this->CasterFaces << "\n";
}
