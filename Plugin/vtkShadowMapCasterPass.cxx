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
} // namespace

bool vtkShadowMapCasterPass::PostReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  if (ShapesItsOwnFragments(fragmentShader))
  {
    ++this->NumberOfOwnFragmentShaders;
    return true;
  }
  ++this->NumberOfDepthOnlyShaders;
  std::string caster = vtkShadowMapsCasterFS;
  const char* faces = this->CasterFaces == 0 ? "#define VTK_SHADOW_CAST_FRONT_ONLY\n"
    : this->CasterFaces == 1                 ? "#define VTK_SHADOW_CAST_BACK_ONLY\n"
                                             : "";
  vtkShaderProgram::Substitute(caster, "//VTK::ShadowMaps::Dec", faces);
  fragmentShader = caster;
  return true;
}

void vtkShadowMapCasterPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CasterFaces: " << this->CasterFaces << "\n";
}
