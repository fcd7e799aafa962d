#include "ShadowMapPassShaders.h"

#include "ShadowMapShaderGroup.h"

#include "ShadowMapAnalysis.h"
#include "ShadowMapImpostors.h"
#include "ShadowMapStorageChoice.h"
#include "ShadowMapTextureArray.h"
#include "vtkShadowMapRepresentation.h"
#include "vtkShadowMapsTransmittanceFS.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"

#include <algorithm>
#include <set>

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
  return true;
}

//------------------------------------------------------------------------------
void PassShaders::Clear()
{
  if (!this->Key.empty())
  {
    *this = PassShaders();
  }
}

//------------------------------------------------------------------------------
void PassShaders::MarkInjectionPoints(std::string& fragmentShader)
{
  CasterShader::MarkInjectionPoints(fragmentShader);
  ReceiverShader::MarkInjectionPoints(fragmentShader);
  ReceiverShader::MarkVolumeInjectionPoints(fragmentShader);
}

//------------------------------------------------------------------------------
std::vector<ShaderGroup> PassShaders::Groups(
  const std::vector<GroupCode>& groups, const std::string& fragmentShader, Impostors sized)
{
  // What the mapper's shader holds before any group's code, and the
  // impostors' declarations group 0 makes, are every group's.
  std::set<std::string> shared = ShadowNamesIn(fragmentShader);
  for (const std::string& code :
    { ImpostorShader::CasterDeclarations(sized), ImpostorShader::ReceiverDeclarations(fragmentShader) })
  {
    const std::set<std::string> names = ShadowNamesIn(code);
    shared.insert(names.begin(), names.end());
  }
  std::vector<ShaderGroup> named;
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    named.emplace_back(static_cast<int>(g));
    named.back().ShareNames(shared);
  }
  return named;
}

//------------------------------------------------------------------------------
CasterBranch PassShaders::Inject(std::string& vertexShader, std::string& geometryShader,
  std::string& fragmentShader, const std::vector<GroupCode>& groups, bool receives,
  int& unpatched, bool ownShare)
{
  const Impostors sized = ImpostorShader::Size(vertexShader, geometryShader, fragmentShader);
  const std::vector<ShaderGroup> named = Groups(groups, fragmentShader, sized);
  const std::string mapperShader = fragmentShader;
  CasterShader::DeclareShared(fragmentShader, mapperShader, sized);
  CasterBranch branch = CasterBranch::DepthOnly;
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    // An emptied group keeps its place (its names) and puts nothing in.
    if (!groups[g].Code->Empty() || groups.size() == 1)
    {
      branch = CasterShader::Inject(
        fragmentShader, mapperShader, groups[g].Code->Casters, sized, named[g]);
    }
  }
  CasterShader::ClearMarkers(fragmentShader);
  for (std::string* stage : { &vertexShader, &geometryShader, &fragmentShader })
  {
    CasterShader::RouteCameraParallel(*stage);
  }
  const std::string withoutReceivers = fragmentShader;
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    unpatched += ReceiverShader::Inject(fragmentShader, *groups[g].Lights, groups[g].Layers,
      groups[g].Code->Receivers, receives, branch == CasterBranch::DepthOnly, ownShare, named[g]);
  }
  if (fragmentShader != withoutReceivers)
  {
    ReceiverShader::DeclareShared(fragmentShader);
  }
  ReceiverShader::ClearMarkers(fragmentShader);
  return branch;
}

//------------------------------------------------------------------------------
bool PassShaders::InjectVolume(
  std::string& fragmentShader, const std::vector<GroupCode>& groups, bool receives)
{
  const std::vector<ShaderGroup> named = Groups(groups, fragmentShader, Impostors::None);
  bool injected = false;
  std::string factors;
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    injected = ReceiverShader::InjectVolume(fragmentShader, *groups[g].Lights, groups[g].Layers,
                 groups[g].Code->Receivers, receives, named[g], factors) ||
      injected;
  }
  ReceiverShader::ClearMarkers(fragmentShader);
  return injected;
}

//------------------------------------------------------------------------------
bool PassShaders::Compiles(vtkOpenGLRenderWindow* window, const std::vector<GroupCode>& groups)
{
  std::vector<ShadowLight> lights;
  for (const GroupCode& group : groups)
  {
    lights.insert(lights.end(), group.Lights->begin(), group.Lights->end());
  }
  ProbeShaders probe = MakeProbeShaders(lights);
  std::string geometryShader;
  MarkInjectionPoints(probe.Fragment);
  int unpatched = 0;
  Inject(probe.Vertex, geometryShader, probe.Fragment, groups, true, unpatched);
  return window->GetShaderCache()->ReadyShaderProgram(
           probe.Vertex.c_str(), probe.Fragment.c_str(), "") != nullptr;
}
} // namespace shadowmaps
