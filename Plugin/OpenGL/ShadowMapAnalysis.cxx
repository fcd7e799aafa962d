#include "ShadowMapAnalysis.h"

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

namespace shadowmaps
{
//------------------------------------------------------------------------------
void AddAnalysisReceiverCode(
  int view, int light, const std::vector<ShadowLight>& lights, ReceiverCode& code)
{
  code.AnalysisFunctions.clear();
  code.AnalysisStatement.clear();
  if (view <= 0 || light >= static_cast<int>(lights.size()))
  {
    return;
  }
  code.AnalysisFunctions =
    "#define VTK_SHADOW_ANALYSIS " + std::to_string(view) + "\n" + vtkShadowMapsAnalysisFS;
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
