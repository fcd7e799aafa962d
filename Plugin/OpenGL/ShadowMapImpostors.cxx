#include "ShadowMapImpostors.h"

#include "vtkShaderProgram.h"
#include "vtkShadowMapsImpostorDepthFS.h"
#include "vtkShadowMapsImpostorSizes.h"
#include "vtkShadowMapsSpriteFS.h"
#include "vtkShadowMapsSpriteVS.h"
#include "vtkShadowMapsTubeFS.h"
#include "vtkShadowMapsTubeGS.h"

#include <glm/gtc/type_ptr.hpp>

namespace shadowmaps
{
namespace
{
const char* const CastingUniform = "uniform int vtkShadowCasting;";

bool Contains(const std::string& text, const char* word)
{
  return text.find(word) != std::string::npos;
}

// VTK's round impostors read ZCalcR, the radius per eye depth: spheres are
// rounded points, tubes have basis vectors from the wide lines' geometry shader.
bool DrawsSpheres(const std::string& fragmentShader)
{
  return Contains(fragmentShader, "gl_PointCoord") && Contains(fragmentShader, "ZCalcR");
}

bool DrawsTubes(const std::string& fragmentShader)
{
  return Contains(fragmentShader, "tubeBasis1") && Contains(fragmentShader, "ZCalcR");
}

// The declarations `stage` needs before main() for the impostors' code.
void DeclareBeforeMain(std::string& stage, size_t main, const char* code)
{
  std::string declarations;
  for (const char* uniform : { CastingUniform, "uniform float ZCalcR;" })
  {
    if (!Contains(stage, uniform))
    {
      declarations += std::string(uniform) + "\n";
    }
  }
  stage.insert(main, declarations + vtkShadowMapsImpostorSizes + "\n" + code + "\n");
}

bool SizeSpheres(std::string& vertexShader)
{
  const size_t main = vertexShader.find("void main");
  const size_t end = vertexShader.rfind('}');
  if (main == std::string::npos || end == std::string::npos || end < main)
  {
    return false;
  }
  vertexShader.insert(end, "  if (vtkShadowCasting != 0)\n  {\n    vtkShadowSizeSprite();\n  }\n");
  DeclareBeforeMain(vertexShader, main, vtkShadowMapsSpriteVS);
  return true;
}

const char* const CornerLoop = "for (int j = 0; j < 4; j++)";

// Writes the loop over the corners at `loop` as four blocks, each with its
// corner j a constant: VTK's loop reads its inputs (gl_in, the clipping
// planes' clipVertexMC) at j / 2, and llvmpipe in Mesa 25.0 drew nothing of
// such a shader with the casters' code and clipping planes in it (an index
// chosen at run time, as in vtkShadowMapsTubeGS). A user's replacement of a
// marker inside the loop made after this (ReplaceAll off) reaches the first
// corner only. False if the loop's body has no closing brace.
bool UnrollCornerLoop(std::string& geometryShader, size_t loop)
{
  const size_t open = geometryShader.find('{', loop);
  if (open == std::string::npos)
  {
    return false;
  }
  int depth = 0;
  size_t close = open;
  for (; close < geometryShader.size(); ++close)
  {
    depth += geometryShader[close] == '{' ? 1 : geometryShader[close] == '}' ? -1 : 0;
    if (depth == 0)
    {
      break;
    }
  }
  if (close == geometryShader.size())
  {
    return false;
  }
  const std::string body = geometryShader.substr(open + 1, close - open - 1);
  std::string unrolled;
  for (int corner = 0; corner < 4; ++corner)
  {
    unrolled += "{\n    const int j = " + std::to_string(corner) + ";" + body + "}\n  ";
  }
  geometryShader.replace(loop, close + 1 - loop, unrolled);
  return true;
}

// VTK's tubes come from its wide-line geometry shaders, which (9.1 to 9.6)
// emit the quad's corners in a loop over j, one EmitVertex each: the corner is
// replaced just before it.
bool SizeTubes(std::string& geometryShader)
{
  const size_t main = geometryShader.find("void main");
  const size_t emit = geometryShader.find("EmitVertex();");
  const size_t loop = main == std::string::npos ? main : geometryShader.find(CornerLoop, main);
  if (!Contains(geometryShader, "layout(lines) in") || main == std::string::npos ||
    emit == std::string::npos || emit < main || loop > emit ||
    geometryShader.find("EmitVertex();", emit + 1) != std::string::npos)
  {
    return false;
  }
  std::string sized = geometryShader;
  sized.insert(
    emit, "if (vtkShadowCasting != 0)\n    {\n      gl_Position = vtkShadowTubeCorner(j);\n    }\n    ");
  if (!UnrollCornerLoop(sized, loop))
  {
    return false;
  }
  DeclareBeforeMain(sized, main, vtkShadowMapsTubeGS);
  geometryShader = sized;
  return true;
}
} // namespace

//------------------------------------------------------------------------------
Impostors ImpostorShader::Size(
  std::string& vertexShader, std::string& geometryShader, const std::string& fragmentShader)
{
  if (DrawsSpheres(fragmentShader))
  {
    return SizeSpheres(vertexShader) ? Impostors::Spheres : Impostors::None;
  }
  // Flat wide lines are a screen-space decoration (drawn by the GL's own wide
  // lines where it has them, with no geometry shader): they keep their width
  // in texels.
  if (DrawsTubes(fragmentShader))
  {
    return SizeTubes(geometryShader) ? Impostors::Tubes : Impostors::None;
  }
  return Impostors::None;
}

//------------------------------------------------------------------------------
std::string ImpostorShader::CasterDepth(Impostors sized)
{
  switch (sized)
  {
    case Impostors::Spheres:
      return "vtkShadowSpriteDepth()";
    case Impostors::Tubes:
      return "vtkShadowTubeDepth()";
    default:
      return "";
  }
}

//------------------------------------------------------------------------------
std::string ImpostorShader::CasterBackDepth(Impostors sized)
{
  return sized == Impostors::None ? "" : "vtkShadowImpostorBackDepth";
}

//------------------------------------------------------------------------------
bool ImpostorShader::LiftOwnCutWhileCasting(std::string& fragmentShader, Impostors sized)
{
  if (sized != Impostors::Spheres)
  {
    return true;
  }
  // VTK 9.1 to 9.6 write it so (vtkOpenGLPolyDataMapper::ReplaceShaderDepth).
  // Lifted once for every group's branch.
  const std::string cut = "if (len2 > 1.0) { discard; }";
  const std::string lifted = "if (len2 > 1.0 && vtkShadowCasting == 0) { discard; }";
  const size_t at = fragmentShader.find(cut);
  if (at == std::string::npos)
  {
    return fragmentShader.find(lifted) != std::string::npos;
  }
  fragmentShader.replace(at, cut.size(), lifted);
  return true;
}

//------------------------------------------------------------------------------
std::string ImpostorShader::CasterDeclarations(Impostors sized)
{
  switch (sized)
  {
    case Impostors::Spheres:
      return std::string(vtkShadowMapsImpostorDepthFS) + vtkShadowMapsSpriteFS;
    case Impostors::Tubes:
      return std::string(vtkShadowMapsImpostorDepthFS) + vtkShadowMapsTubeFS;
    default:
      return "";
  }
}

//------------------------------------------------------------------------------
std::string ImpostorShader::ReceiverPositionVC(const std::string& fragmentShader)
{
  // The drawn radius, ZCalcR times the eye depth (times the tile scale in a
  // tile, see ReceiverDeclarations), along the impostor's normal from its
  // centre (sphere) or centre line (tube), where all its fragments are.
  if (DrawsSpheres(fragmentShader) || DrawsTubes(fragmentShader))
  {
    return "vertexVC.xyz + normalVCVSOutput * ZCalcR * vtkShadowImpostorDrawnRadius * "
           "(cameraParallel != 0 ? 1.0 : -vertexVC.z)";
  }
  return "vertexVC.xyz";
}

//------------------------------------------------------------------------------
std::string ImpostorShader::ReceiverDeclarations(const std::string& fragmentShader)
{
  // While a tile of a larger image renders, VTK's ZCalcR divides the point
  // size by the whole image's width but the tile's P00: it is the drawn
  // radius over the tile scale.
  return DrawsSpheres(fragmentShader) || DrawsTubes(fragmentShader)
    ? "uniform float vtkShadowImpostorDrawnRadius;\n"
    : "";
}

//------------------------------------------------------------------------------
bool ImpostorShader::IsSized(vtkShaderProgram* program)
{
  return program->IsUniformUsed("vtkShadowImpostorScale");
}

//------------------------------------------------------------------------------
void ImpostorUniforms::Set(const glm::dmat4& worldToClip, const glm::vec4& light,
  const glm::vec4& sceneDepth, const glm::vec4& scale)
{
  this->WorldToClip = glm::mat4(worldToClip);
  this->ClipToWorld = glm::mat4(glm::inverse(worldToClip));
  this->Light = light;
  this->SceneDepth = sceneDepth;
  this->Scale = scale;
}

//------------------------------------------------------------------------------
void ImpostorUniforms::Apply(vtkShaderProgram* program) const
{
  glm::mat4 worldToClip = this->WorldToClip; // VTK 9.1 takes mutable pointers
  glm::mat4 clipToWorld = this->ClipToWorld;
  program->SetUniformMatrix4x4("vtkShadowImpostorWorldToClip", glm::value_ptr(worldToClip));
  program->SetUniformMatrix4x4("vtkShadowImpostorClipToWorld", glm::value_ptr(clipToWorld));
  program->SetUniform4f("vtkShadowImpostorLight", glm::value_ptr(this->Light));
  program->SetUniform4f("vtkShadowImpostorSceneDepth", glm::value_ptr(this->SceneDepth));
  program->SetUniform4f("vtkShadowImpostorScale", glm::value_ptr(this->Scale));
  if (program->IsUniformUsed("vtkShadowImpostorDepthOffset"))
  {
    program->SetUniform2f("vtkShadowImpostorDepthOffset", glm::value_ptr(this->DepthOffset));
  }
}

//------------------------------------------------------------------------------
void ImpostorUniforms::ApplyReceiving(vtkShaderProgram* program) const
{
  if (program->IsUniformUsed("vtkShadowImpostorDrawnRadius"))
  {
    program->SetUniformf("vtkShadowImpostorDrawnRadius", this->DrawnRadius);
  }
}
} // namespace shadowmaps
