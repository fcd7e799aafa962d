// The shadow code a pass puts into the mappers' shaders: the receivers' lookup
// and the casters' branch for the current maps, the key on which the mappers
// rebuild their shaders, and the injection itself. The receivers and casters
// share one program per mapper primitive (vtkShadowMapsCasterFS.glsl), so the
// key changes only with the lights' layouts, the layers and the storage, never
// with the camera. Where lights use several representations, each has its
// group of maps and its PassShaders, and every group's code goes into the
// same shaders under names of its own (ShaderGroup). Not a VTK class.
#ifndef ShadowMapPassShaders_h
#define ShadowMapPassShaders_h

#include "ShadowMapCasterShader.h"   // For CasterCode, CasterBranch
#include "ShadowMapReceiverShader.h" // For ReceiverCode
#include "ShadowMapShaderGroup.h"    // For ShaderGroup

#include "vtkAbstractShadowMapPass.h" // For CasterFacesType

#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkShadowMapRepresentation;

namespace shadowmaps
{
struct MapStorage;
struct ShadowLight;

/// What the code depends on besides the maps' storage and lights.
struct ShaderChoices
{
  /// vtkAbstractShadowMapPass::CasterFacesType, for one-depth maps.
  int CasterFaces = vtkAbstractShadowMapPass::BOTH_FACES;
  /// The analysis view that recolours receivers (0: none) and its light.
  int AnalysisView = 0;
  int AnalysisLight = 0;
  /// The analysed light's views (vtkShadowMapViews::GetKindName), which the
  /// CHOSEN_VIEWS view colours.
  std::string AnalysisViewsKind;
  /// The casters also write their light depth, for the processes' maps to be
  /// combined by it (Combination::NearestLightDepths).
  bool KeepsLightDepths = false;
};

class PassShaders;

/// One group's share of the mappers' shaders: its code, and the lights and
/// layers of its maps. The group's names are ShaderGroup(index in the list)'s.
struct GroupCode
{
  const PassShaders* Code = nullptr;
  const std::vector<ShadowLight>* Lights = nullptr;
  int Layers = 0;
};

class PassShaders
{
public:
  /// Makes the code for maps of `storage`, read as `representation` says, of
  /// `lights` in `layers` layers. True when the key changed: the mappers then
  /// rebuild their shaders (BuiltCode).
  bool Update(const MapStorage& storage, vtkShadowMapRepresentation* representation,
    const std::vector<ShadowLight>& lights, int layers, const ShaderChoices& choices);

  /// The key of the code.
  const std::string& GetKey() const { return this->Key; }

  /// No code: the group's lights are gone from this frame, so that the
  /// shaders hold nothing of it (its samplers would have no units). A change
  /// rebuilds the mappers' shaders.
  void Clear();
  bool Empty() const { return this->Key.empty(); }

  /// Puts every group's code into a mapper's shaders, which hold the
  /// injection points (MarkInjectionPoints). Adds to `unpatched` the
  /// receiving lights the mapper lit in code this module cannot patch.
  /// `receives` false: the casters' branches only. `ownShare`:
  /// ReceiverShader::Inject's.
  static CasterBranch Inject(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, const std::vector<GroupCode>& groups, bool receives,
    int& unpatched, bool ownShare = false);

  /// Puts every group's receivers' code into a volume mapper's ray caster
  /// (ReceiverShader::InjectVolume); volumes cast by being marched, not drawn.
  static bool InjectVolume(
    std::string& fragmentShader, const std::vector<GroupCode>& groups, bool receives);

  /// Marks where Inject and InjectVolume put their code, before the mapper's
  /// own replacements.
  static void MarkInjectionPoints(std::string& fragmentShader);

  /// Whether the groups' code compiles in `window`, tried on a probe
  /// program: VTK 9.1's mappers crash on a program that fails to build.
  static bool Compiles(vtkOpenGLRenderWindow* window, const std::vector<GroupCode>& groups);

  const CasterCode& GetCasterCode() const { return this->Casters; }

private:
  /// The groups' names in a mapper's fragment shader before their code goes in.
  static std::vector<ShaderGroup> Groups(
    const std::vector<GroupCode>& groups, const std::string& fragmentShader, Impostors sized);

  ReceiverCode Receivers;
  CasterCode Casters;
  std::string Key;
};
} // namespace shadowmaps

#endif
