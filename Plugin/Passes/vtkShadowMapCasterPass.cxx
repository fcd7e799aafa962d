#include "vtkShadowMapCasterPass.h"

#include "vtkObjectFactory.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsCasterFS.h"
#include "vtkShadowMapsLinearDepthFS.h"

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

// The statements that end a caster's main(): depth (the rasterizer's, or the one
// the shader wrote) made linear when asked, then the store code.
std::string CasterEpilogue(const std::string& rawDepth, bool linear, const std::string& storeCode)
{
  std::string code = "  {\n  float vtkShadowCasterDepth = ";
  code += linear ? "vtkShadowLinearDepth(" + rawDepth + ");\n  gl_FragDepth = vtkShadowCasterDepth;\n"
                 : rawDepth + ";\n";
  code += storeCode.empty() ? "  gl_FragData[0] = vec4(1.0);" : storeCode;
  code += "\n  }\n";
  return code;
}

// Shaders that shape their own fragments keep their code; the epilogue goes at the
// end of main(), the last function of VTK's fragment shaders, and reads the depth
// the shader wrote if it writes one.
void AppendEpilogue(std::string& fragmentShader, bool linear, const std::string& storeCode)
{
  const size_t end = fragmentShader.rfind('}');
  const size_t main = fragmentShader.find("void main");
  if (end == std::string::npos || main == std::string::npos)
  {
    return;
  }
  const bool writesDepth =
    WithoutLineComments(fragmentShader).find("gl_FragDepth") != std::string::npos;
  fragmentShader.insert(
    end, CasterEpilogue(writesDepth ? "gl_FragDepth" : "gl_FragCoord.z", linear, storeCode));
  if (linear)
  {
    fragmentShader.insert(main, std::string(vtkShadowMapsLinearDepthFS) + "\n");
  }
}
} // namespace

void vtkShadowMapCasterPass::SetLinearDepth(bool linear)
{
  if (linear != this->LinearDepth)
  {
    this->LinearDepth = linear;
    this->Modified();
  }
}

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
    if (this->LinearDepth || !this->StoreCode.empty())
    {
      AppendEpilogue(fragmentShader, this->LinearDepth, this->StoreCode);
    }
    return true;
  }
  ++this->NumberOfDepthOnlyShaders;
  std::string caster = vtkShadowMapsCasterFS;
  std::string defines = this->CasterFaces == 0 ? "#define VTK_SHADOW_CAST_FRONT_ONLY\n"
    : this->CasterFaces == 1                   ? "#define VTK_SHADOW_CAST_BACK_ONLY\n"
                                               : "";
  if (this->LinearDepth)
  {
    defines += vtkShadowMapsLinearDepthFS;
  }
  vtkShaderProgram::Substitute(caster, "//VTK::ShadowMaps::Dec", defines);
  vtkShaderProgram::Substitute(
    caster, "//VTK::ShadowMaps::Impl", CasterEpilogue("gl_FragCoord.z", this->LinearDepth, this->StoreCode));
  fragmentShader = caster;
  return true;
}

bool vtkShadowMapCasterPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  if (this->LinearDepth && program->IsUniformUsed("vtkShadowWindowToInverseW"))
  {
    program->SetUniform3f("vtkShadowWindowToInverseW", this->WindowToInverseW.data());
    program->SetUniform3f("vtkShadowLinearDepthBias", this->LinearDepthBias.data());
  }
  return true;
}

void vtkShadowMapCasterPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CasterFaces: " << this->CasterFaces << "\n";
  os << indent << "LinearDepth: " << this->LinearDepth << "\n";
}
