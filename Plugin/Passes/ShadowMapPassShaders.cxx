#include "ShadowMapPassShaders.h"

#include "ShadowMapAnalysis.h"
#include "ShadowMapImpostors.h"
#include "ShadowMapStorageChoice.h"
#include "ShadowMapTextureArray.h"
#include "vtkShadowMapRepresentation.h"
#include "vtkShadowMapsTransmittanceFS.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"

#include <algorithm>

#include <utility>

namespace shadowmaps
{
//------------------------------------------------------------------------------
bool PassShaders::Update(const MapStorage& storage, vtkShadowMapRepresentation* representation,
  const std::vector<ShadowLight>& lights, int layers, const ShaderChoices& choices)
{
  const bool sized = std::any_of(lights.begin(), lights.end(),
    [](const ShadowLight& light) { return light.Size > 0.0; });
  this->Receivers.Definitions =
    std::string(storage.LightDepth ? "#define VTK_SHADOW_LIGHT_DEPTH\n" : "") +
    (sized ? "#define VTK_SHADOW_SIZED_LIGHTS\n" : "") +
    (storage.Transmittance ? "#define VTK_SHADOW_TRANSMITTANCE\n" : "") +
    representation->GetReceiverDefinitions();
  this->Receivers.Lookup = representation->GetReceiverLookupCode() +
    (sized ? representation->GetSoftShadowCode() : "") +
    (storage.Transmittance ? vtkShadowMapsTransmittanceFS : "");
  this->Receivers.Transmittance = storage.Transmittance;
  AddAnalysisReceiverCode(
    choices.AnalysisView, choices.AnalysisLight, choices.AnalysisViewsKind, lights, this->Receivers);
  this->Receivers.Rehash();

  CasterCode& casters = this->Casters;
  casters.SecondDepth = storage.SecondDepth;
  // Two surfaces' depths need both faces of the casters.
  casters.Faces = storage.SecondDepth == SecondDepthMethod::None
    ? choices.CasterFaces
    : static_cast<int>(vtkAbstractShadowMapPass::BOTH_FACES);
  const bool values = !IsDepth(storage.Format);
  casters.StoreCode = values ? storage.StoreCode : std::string();
  casters.KeepsLightDepth = choices.KeepsLightDepths;
  casters.StoreFunctions = values ? storage.StoreFunctions : std::string();
  casters.LightDepth = values && storage.LightDepth;
  casters.LinearDepth = AnyLinearDepthView(lights);
  casters.Transmittance = storage.Transmittance;

  std::string key = ReceiverShader::Key(lights, layers, this->Receivers) + '|' + casters.Key();
  if (key == this->Key)
  {
    return false;
  }
  this->Key = std::move(key);
  this->KeyTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
void PassShaders::MarkInjectionPoints(std::string& fragmentShader)
{
  CasterShader::MarkInjectionPoints(fragmentShader);
  ReceiverShader::MarkInjectionPoints(fragmentShader);
  ReceiverShader::MarkVolumeInjectionPoints(fragmentShader);
}

//------------------------------------------------------------------------------
CasterBranch PassShaders::Inject(std::string& vertexShader, std::string& geometryShader,
  std::string& fragmentShader, const std::vector<ShadowLight>& lights, int layers, bool receives,
  int& unpatched, bool ownShare) const
{
  const Impostors sized = ImpostorShader::Size(vertexShader, geometryShader, fragmentShader);
  const CasterBranch branch = CasterShader::Inject(fragmentShader, this->Casters, sized);
  for (std::string* stage : { &vertexShader, &geometryShader, &fragmentShader })
  {
    CasterShader::RouteCameraParallel(*stage);
  }
  unpatched += ReceiverShader::Inject(fragmentShader, lights, layers, this->Receivers, receives,
    branch == CasterBranch::DepthOnly, ownShare);
  return branch;
}

//------------------------------------------------------------------------------
bool PassShaders::Compiles(
  vtkOpenGLRenderWindow* window, const std::vector<ShadowLight>& lights, int layers) const
{
  ProbeShaders probe = MakeProbeShaders(lights);
  std::string geometryShader;
  MarkInjectionPoints(probe.Fragment);
  int unpatched = 0;
  this->Inject(probe.Vertex, geometryShader, probe.Fragment, lights, layers, true, unpatched);
  return window->GetShaderCache()->ReadyShaderProgram(
           probe.Vertex.c_str(), probe.Fragment.c_str(), "") != nullptr;
}
} // namespace shadowmaps
