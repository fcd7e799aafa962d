#include "ShadowMapAnalysis.h"

#include "ShadowMapGlslLiteral.h"
#include "ShadowMapLight.h"
#include "ShadowMapReceiverShader.h"
#include "ShadowMapTextureArray.h"
#include "ShadowMapQuad.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsAnalysisFS.h"
#include "vtkShadowMapsViewFS.h"
#include "ShadowMapVTKCompat.h"

#include <map>

namespace shadowmaps
{
//------------------------------------------------------------------------------
std::array<float, 3> ViewsKindColor(const std::string& viewsKind)
{
  static const std::map<std::string, std::array<float, 3>> legend = {
    { "uniform", { 0.6f, 0.6f, 0.6f } },
    { "cube faces", { 0.2f, 0.85f, 0.85f } },
    { "lispsm", { 0.2f, 0.8f, 0.2f } },
    { "gmnpr", { 0.55f, 0.65f, 0.1f } },
    { "tsm", { 0.95f, 0.85f, 0.2f } },
    { "psm", { 0.9f, 0.2f, 0.2f } },
    { "psm-cube", { 0.8f, 0.3f, 0.9f } },
    { "cascades", { 0.2f, 0.4f, 1.0f } },
    { "tiles", { 1.0f, 0.55f, 0.1f } },
  };
  const auto found = legend.find(viewsKind);
  return found != legend.end() ? found->second : std::array<float, 3>{ 1.0f, 1.0f, 1.0f };
}

//------------------------------------------------------------------------------
void AddAnalysisReceiverCode(int view, int light, const std::string& viewsKind,
  const std::vector<ShadowLight>& lights, ReceiverCode& code)
{
  code.AnalysisFunctions.clear();
  code.AnalysisStatement.clear();
  if (view <= 0 || light >= static_cast<int>(lights.size()))
  {
    return;
  }
  // Only the view that shows it holds the colour: a change of the light's views
  // rebuilds no other view's shaders.
  std::string viewsColour;
  if (view == ChosenViewsAnalysis)
  {
    const std::array<float, 3> colour = ViewsKindColor(viewsKind);
    viewsColour = "#define VTK_SHADOW_VIEWS_COLOR vec3(" + GlslFloat(colour[0]) + ", " +
      GlslFloat(colour[1]) + ", " + GlslFloat(colour[2]) + ")\n";
  }
  code.AnalysisFunctions = "#define VTK_SHADOW_ANALYSIS " + std::to_string(view) + "\n" +
    viewsColour + vtkShadowMapsAnalysisFS;
  code.AnalysisStatement = "  gl_FragData[0] = vtkShadowAnalysisColor(" +
    ReceiverCallArguments(lights[light], light) + ");\n";
}

//------------------------------------------------------------------------------
MapView::MapView() = default;

//------------------------------------------------------------------------------
MapView::~MapView() = default;

//------------------------------------------------------------------------------
bool MapView::Render(vtkOpenGLRenderWindow* window, TextureArray& maps, int mapUnit,
  const ShadowLight& light, bool twoSurfaces, double warpExponent)
{
  vtkShaderProgram* program = ReadyQuadProgram(this->Quad, window, vtkShadowMapsViewFS);
  if (!program)
  {
    return false;
  }
  program->SetUniformi("vtkShadowMaps", mapUnit);
  program->SetUniformi("vtkShadowFirstView", light.FirstLayer);
  program->SetUniformi("vtkShadowViewCount", static_cast<int>(light.Views.size()));
  program->SetUniformi("vtkShadowSurfaces", twoSurfaces ? 2 : 1);
  program->SetUniformf("vtkShadowWarpExponent", static_cast<float>(warpExponent));
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  maps.SetDepthComparison(false);
  this->Quad->Render();
  maps.SetDepthComparison(true);
  return true;
}

//------------------------------------------------------------------------------
void MapView::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
}
} // namespace shadowmaps
