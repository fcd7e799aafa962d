#include "ShadowMapCasterShader.h"

#include "ShadowMapShaderGroup.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsCasterFS.h"
#include "vtkShadowMapsLightDepthFS.h"
#include "vtkShadowMapsTransmittedFS.h"
#include "vtkShadowMapsLinearDepthFS.h"

#include <functional>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

namespace shadowmaps
{
namespace
{
const char* const EarlyMarker = "//VTK::ShadowMaps::CastEarly";
const char* const LateMarker = "//VTK::ShadowMaps::CastLate";
const char* const TransmitMarker = "//VTK::ShadowMaps::Transmit";

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
bool ShapesItsOwnFragments(const std::string& code)
{
  return code.find("gl_FragDepth") != std::string::npos || CountOccurrences(code, "discard") > 1;
}

// The impostors whose depth the casters' branches compute: shapes that cut
// their own fragments, sized by ImpostorShader::Size.
Impostors CastingImpostors(const std::string& mapperCode, Impostors sized)
{
  return ShapesItsOwnFragments(mapperCode) && !ImpostorShader::CasterDepth(sized).empty()
    ? sized
    : Impostors::None;
}

// A group's declarations (the shared ones are CasterShader::DeclareShared's).
std::string Declarations(const CasterCode& code, const ShaderGroup& group)
{
  std::string dec = code.Faces == 0 ? "#define VTK_SHADOW_CAST_FRONT_ONLY\n"
    : code.Faces == 1               ? "#define VTK_SHADOW_CAST_BACK_ONLY\n"
                                    : "";
  if (code.SecondDepth == SecondDepthMethod::Peeling)
  {
    dec += "#define VTK_SHADOW_PEEL\n";
  }
  if (code.LightDepth || code.Transmittance)
  {
    dec += "#define VTK_SHADOW_LIGHT_DEPTH\n";
    dec += vtkShadowMapsLightDepthFS;
  }
  if (code.Transmittance)
  {
    dec += "#define VTK_SHADOW_TRANSMITTANCE\n";
    dec += vtkShadowMapsTransmittedFS;
  }
  dec += vtkShadowMapsCasterFS;
  if (code.LinearDepth)
  {
    dec += vtkShadowMapsLinearDepthFS;
  }
  return group.Rename(dec + code.StoreFunctions) + "\n";
}

// What the branch writes once it has vtkShadowCasterDepth (and, for an
// impostor, vtkShadowCasterBackDepth: where its ray leaves it).
std::string StoreCode(const CasterCode& code, bool backDepth)
{
  switch (code.SecondDepth)
  {
    case SecondDepthMethod::FrontAndBackFaces:
      if (backDepth)
      {
        return "    gl_FragData[0] = vec4(vtkShadowCasterDepth, vtkShadowCasterBackDepth, 0.0, 1.0);";
      }
      return "    gl_FragData[0] = gl_FrontFacing ? vec4(vtkShadowCasterDepth, 1.0, 0.0, 1.0)\n"
             "                                    : vec4(1.0, vtkShadowCasterDepth, 0.0, 1.0);";
    case SecondDepthMethod::Peeling:
      return "    if (vtkShadowPeeledAway(vtkShadowCasterDepth))\n    {\n      discard;\n    }\n"
             "    gl_FragData[0] = vec4(vtkShadowCasterDepth);\n"
             "    gl_FragData[1] = vec4(vtkShadowCasterDepth);";
    default:
      break;
  }
  const std::string depthOutput = "    gl_FragData[1] = vec4(vtkShadowCasterDepth);";
  if (!code.StoreCode.empty())
  {
    return code.KeepsLightDepth ? code.StoreCode + "\n" + depthOutput : code.StoreCode;
  }
  return code.LinearDepth ? depthOutput : "    gl_FragData[0] = vec4(1.0);";
}

// The stored depth of window depth `raw`: made linear, or the light depth, when asked.
std::string StoredDepth(const CasterCode& code, const std::string& raw)
{
  return code.LightDepth ? "vtkShadowLightDepthAt(" + raw + ")"
    : code.LinearDepth   ? "vtkShadowLinearDepth(" + raw + ")"
                         : raw;
}

// The branch: depth (the rasterizer's, or the one the shader wrote) made linear
// when asked, written back when the shader writes depth on its other path, then
// the store code, or for linear depth in depth maps the depth as colour
// (ShadowMapLinearDepthResolve.h says why not gl_FragDepth) in a second output:
// the first, the mapper's colour, has no buffer while casting, so a software
// rasteriser drops the work that makes it. An impostor also has a back depth
// (`rawBackDepth`, the window depth where each texel's ray leaves it): its
// second depth, one surface for front and back faces, and the surface behind
// the peeled one in the second peeling pass.
std::string Branch(const CasterCode& code, const std::string& rawDepth,
  const std::string& rawBackDepth, bool writeDepth, bool selectFaces, const ShaderGroup& group)
{
  std::ostringstream branch;
  branch << "  if (vtkShadowCasting == " << group.CastingValue() << ")\n  {\n";
  if (selectFaces)
  {
    branch << "    if (!vtkShadowCastsThisFace())\n    {\n      discard;\n    }\n";
  }
  branch << "    float vtkShadowCasterRawDepth = " << rawDepth << ";\n";
  const bool backDepth = !rawBackDepth.empty();
  if (backDepth && code.SecondDepth == SecondDepthMethod::Peeling)
  {
    branch << "    if (vtkShadowPeeledAway(" << StoredDepth(code, "vtkShadowCasterRawDepth")
           << "))\n    {\n      vtkShadowCasterRawDepth = " << rawBackDepth << ";\n    }\n";
  }
  branch << "    float vtkShadowCasterDepth = " << StoredDepth(code, "vtkShadowCasterRawDepth") << ";\n";
  if (backDepth)
  {
    branch << "    float vtkShadowCasterBackDepth = " << StoredDepth(code, rawBackDepth) << ";\n";
  }
  if (writeDepth)
  {
    // The depth test keeps the nearest fragment by window depth, as the
    // rasteriser gives it to other casters: not the light depth or the
    // linear depth stored.
    branch << "    gl_FragDepth = "
           << (code.LightDepth || code.LinearDepth ? "vtkShadowCasterRawDepth" : "vtkShadowCasterDepth")
           << ";\n";
  }
  branch << StoreCode(code, backDepth) << "\n    return;\n  }\n";
  return group.Rename(branch.str());
}

// The branch that draws a translucent caster into the transmittance maps,
// where the mapper has its colour and opacity (right after its colour code,
// before edges and lighting): what the surface lets through and its light
// depth. A shader without them draws nothing there.
std::string TransmittanceBranch(const std::string& mapperCode, const ShaderGroup& group)
{
  const std::string transmitted = CasterShader::TransmittedLight(mapperCode);
  std::ostringstream branch;
  branch << "  if (vtkShadowCasting == " << group.TransmittingValue() << ")\n  {\n";
  if (transmitted.empty())
  {
    branch << "    discard;\n  }\n";
    return branch.str();
  }
  branch << "    gl_FragData[0] = vec4(" << transmitted
         << ", vtkShadowTransmittedDepth(gl_FragCoord.z));\n    return;\n  }\n";
  return group.Rename(branch.str());
}

// Inserts `text` at the start of main()'s body.
void PutAtMainStart(std::string& shader, const std::string& text)
{
  const size_t main = shader.find("void main");
  const size_t body = main == std::string::npos ? main : shader.find('{', main);
  if (body != std::string::npos)
  {
    shader.insert(body + 1, "\n" + text);
  }
}

// Puts `text` before `marker`, which stays for the next group's code, or
// before the end of main() (the last function of VTK's fragment shaders) if a
// mapper's template had no such marker.
void PutAtMarker(std::string& fragmentShader, const char* marker, const std::string& text)
{
  if (fragmentShader.find(marker) != std::string::npos)
  {
    vtkShaderProgram::Substitute(fragmentShader, marker, text + marker);
    return;
  }
  const size_t end = fragmentShader.rfind('}');
  if (end != std::string::npos)
  {
    fragmentShader.insert(end, text);
  }
}
} // namespace

//------------------------------------------------------------------------------
std::string CasterCode::Key() const
{
  std::ostringstream key;
  key << this->Faces << ':' << this->LinearDepth << ':' << this->LightDepth << ':'
      << this->KeepsLightDepth << ':' << this->Transmittance << ':'
      << static_cast<int>(this->SecondDepth) << ':'
      << std::hash<std::string>{}(this->StoreCode + '\n' + this->StoreFunctions);
  return key.str();
}

//------------------------------------------------------------------------------
void CasterShader::MarkInjectionPoints(std::string& fragmentShader)
{
  PutAtMainStart(fragmentShader, std::string(EarlyMarker) + "\n");
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Color::Impl",
    std::string("//VTK::Color::Impl\n") + TransmitMarker, false);
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Impl", std::string(LateMarker) + "\n//VTK::Light::Impl", false);
}

//------------------------------------------------------------------------------
CasterBranch CasterShader::Inject(std::string& fragmentShader, const std::string& mapperShader,
  const CasterCode& code, Impostors sized, const ShaderGroup& group)
{
  const std::string mapperCode = WithoutLineComments(mapperShader);
  const bool writesDepth = mapperCode.find("gl_FragDepth") != std::string::npos;
  const bool ownFragments = ShapesItsOwnFragments(mapperCode);
  // An impostor's depth as the mapper writes it follows the scene camera's
  // sizes: the branch computes its own.
  const std::string impostorDepth =
    ImpostorShader::CasterDepth(CastingImpostors(mapperCode, sized));
  // Shapes that cut their own fragments (impostors, splats) draw nothing into
  // the transmittance maps: their cuts come after the colour code.
  PutAtMarker(fragmentShader, TransmitMarker,
    code.Transmittance ? TransmittanceBranch(ownFragments ? std::string() : mapperCode, group)
                       : std::string());
  if (code.Transmittance && !ownFragments)
  {
    // Where control flow is uniform, before any of the mapper's discards.
    PutAtMainStart(fragmentShader,
      group.Rename("  vtkShadowCasterDepthDx = dFdx(gl_FragCoord.z);\n"
                   "  vtkShadowCasterDepthDy = dFdy(gl_FragCoord.z);\n"));
  }

  if (ownFragments)
  {
    // An impostor's branch finds its shape itself, after VTK's clipping
    // planes; VTK's cut of a point's square to its inscribed circle, about its
    // centre, is lifted while casting (the casters' square may have left the
    // centre: vtkShadowDrawPartInView). Where it cannot be lifted, the branch
    // runs first. Casting back faces only, an impostor casts where the ray
    // leaves it (GLSL's comma: the call sets the back depth, then it is read).
    const std::string backDepth =
      impostorDepth.empty() ? "" : ImpostorShader::CasterBackDepth(sized);
    const std::string depth = impostorDepth.empty() ? (writesDepth ? "gl_FragDepth" : "gl_FragCoord.z")
      : code.Faces == 1 ? "(" + impostorDepth + ", " + backDepth + ")"
                        : impostorDepth;
    const bool first =
      !impostorDepth.empty() && !ImpostorShader::LiftOwnCutWhileCasting(fragmentShader, sized);
    PutAtMarker(fragmentShader, first ? EarlyMarker : LateMarker,
      Branch(code, depth, backDepth, !impostorDepth.empty(), false, group));
  }
  else
  {
    // A shader that writes gl_FragDepth on one path must on every path.
    PutAtMarker(
      fragmentShader, EarlyMarker, Branch(code, "gl_FragCoord.z", "", writesDepth, true, group));
  }
  const size_t main = fragmentShader.find("void main");
  if (main != std::string::npos)
  {
    fragmentShader.insert(main, Declarations(code, group));
  }
  return ownFragments ? CasterBranch::AfterOwnFragments : CasterBranch::DepthOnly;
}

//------------------------------------------------------------------------------
void CasterShader::DeclareShared(
  std::string& fragmentShader, const std::string& mapperShader, Impostors sized)
{
  const size_t main = fragmentShader.find("void main");
  if (main != std::string::npos)
  {
    fragmentShader.insert(main,
      "uniform int vtkShadowCasting;\n" +
        ImpostorShader::CasterDeclarations(
          CastingImpostors(WithoutLineComments(mapperShader), sized)));
  }
}

//------------------------------------------------------------------------------
void CasterShader::ClearMarkers(std::string& fragmentShader)
{
  for (const char* marker : { EarlyMarker, LateMarker, TransmitMarker })
  {
    vtkShaderProgram::Substitute(fragmentShader, marker, "");
  }
}

//------------------------------------------------------------------------------
std::string CasterShader::TransmittedLight(const std::string& mapperCode)
{
  if (mapperCode.find("vec3 diffuseColor") == std::string::npos ||
    mapperCode.find("float opacity") == std::string::npos)
  {
    return {};
  }
  // VTK's diffuse colour is the drawn colour times the property's Diffuse
  // coefficient, taken out again.
  const std::string color = mapperCode.find("diffuseIntensity") != std::string::npos
    ? "vtkShadowCasterColor(diffuseColor, diffuseIntensity)"
    : "diffuseColor";
  return "vtkShadowTransmitted(" + color + ", opacity)";
}

//------------------------------------------------------------------------------
void CasterShader::RouteCameraParallel(std::string& shader)
{
  const std::string declaration = "uniform int cameraParallel;";
  if (shader.find(declaration) == std::string::npos)
  {
    return;
  }
  const bool declaresCasting = shader.find("uniform int vtkShadowCasting;") != std::string::npos;
  vtkShaderProgram::Substitute(shader, "cameraParallel", "vtkShadowParallel");
  vtkShaderProgram::Substitute(shader, "uniform int vtkShadowParallel;",
    declaration + (declaresCasting ? "" : "\nuniform int vtkShadowCasting;") +
      "\nuniform int vtkShadowCasterParallel;\nint vtkShadowParallel;");
  PutAtMainStart(shader,
    "  vtkShadowParallel = vtkShadowCasting != 0 ? vtkShadowCasterParallel : cameraParallel;\n");
}

//------------------------------------------------------------------------------
void CasterUniforms::SetView(const std::array<float, 3>& windowToInverseW,
  const std::array<float, 3>& linearDepthBias, bool parallel)
{
  this->WindowToInverseW = windowToInverseW;
  this->LinearDepthBias = linearDepthBias;
  this->Parallel = parallel;
}

//------------------------------------------------------------------------------
void CasterUniforms::SetLightDepth(
  const glm::mat4& windowToLight, const glm::vec4& plane, float perDistance)
{
  this->WindowToLight = windowToLight;
  this->LightDepthPlane = plane;
  this->LightDepthPerDistance = perDistance;
}

//------------------------------------------------------------------------------
void CasterUniforms::SetPeeling(bool secondPass, int peelUnit)
{
  this->SecondPass = secondPass;
  this->PeelUnit = peelUnit;
}

//------------------------------------------------------------------------------
CasterUniforms::Names CasterUniforms::NamesOf(const ShaderGroup& g)
{
  return { g.Name("vtkShadowPeelDepths"), g.Name("vtkShadowPeelSecondPass"),
    g.Name("vtkShadowWindowToLight"), g.Name("vtkShadowLightDepthPlane"),
    g.Name("vtkShadowLightDepthPerDistance"), g.Name("vtkShadowWindowToInverseW"),
    g.Name("vtkShadowLinearDepthBias") };
}

//------------------------------------------------------------------------------
void CasterUniforms::SetGroup(int index)
{
  this->Group = ShaderGroup(index);
  this->GroupNames = NamesOf(this->Group);
}

//------------------------------------------------------------------------------
void CasterUniforms::ApplyPeelUnit(vtkShaderProgram* program) const
{
  const char* name = this->GroupNames.PeelDepths.c_str();
  if (program->IsUniformUsed(name))
  {
    program->SetUniformi(name, this->PeelUnit);
  }
}

//------------------------------------------------------------------------------
void CasterUniforms::ApplyCasting(vtkShaderProgram* program) const
{
  program->SetUniformi("vtkShadowCasting",
    this->Transmitting ? this->Group.TransmittingValue() : this->Group.CastingValue());
  this->ApplyPeelUnit(program);
  const Names& names = this->GroupNames;
  if (program->IsUniformUsed(names.PeelSecondPass.c_str()))
  {
    program->SetUniformi(names.PeelSecondPass.c_str(), this->SecondPass ? 1 : 0);
  }
  if (program->IsUniformUsed("vtkShadowCasterParallel"))
  {
    program->SetUniformi("vtkShadowCasterParallel", this->Parallel ? 1 : 0);
  }
  if (program->IsUniformUsed(names.WindowToLight.c_str()))
  {
    glm::mat4 windowToLight = this->WindowToLight; // VTK 9.1 takes a mutable pointer
    program->SetUniformMatrix4x4(names.WindowToLight.c_str(), glm::value_ptr(windowToLight));
    program->SetUniform4f(names.LightDepthPlane.c_str(), glm::value_ptr(this->LightDepthPlane));
    program->SetUniformf(names.LightDepthPerDistance.c_str(), this->LightDepthPerDistance);
  }
  if (program->IsUniformUsed(names.WindowToInverseW.c_str()))
  {
    program->SetUniform3f(names.WindowToInverseW.c_str(), this->WindowToInverseW.data());
    program->SetUniform3f(names.LinearDepthBias.c_str(), this->LinearDepthBias.data());
  }
  if (ImpostorShader::IsSized(program))
  {
    this->ImpostorSizes.Apply(program);
  }
}

//------------------------------------------------------------------------------
void CasterUniforms::ApplyReceiving(vtkShaderProgram* program) const
{
  if (program->IsUniformUsed("vtkShadowCasting"))
  {
    program->SetUniformi("vtkShadowCasting", 0);
  }
  this->ApplyPeelUnit(program);
  this->ImpostorSizes.ApplyReceiving(program);
}
} // namespace shadowmaps
