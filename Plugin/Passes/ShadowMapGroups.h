// The groups of maps of a pass: one per representation its shadowed lights
// use (vtkAbstractShadowMapPass::SetLightRepresentation), in the order they
// were first used, each rendered by a FrameUpdate of its own. A group stays
// while its representation is the pass's or a light's, so that renderers
// whose lights use different ones share the groups (a group without lights
// in a renderer's frame draws nothing there).
// Every group's shadow code goes into the same mapper programs under names of
// its own (ShaderGroup); this sets each program's uniforms for every group,
// and puts each group's samplers on units of their own while another group's
// casters draw. With one representation in use there is one group, group 0,
// whose code and frames are those of a pass of one representation. The pass
// keeps the VTK side and asks this what the frame has. Not a VTK class.
#ifndef ShadowMapGroups_h
#define ShadowMapGroups_h

#include "ShadowMapBuiltCode.h"   // For BuiltCode
#include "ShadowMapFrameUpdate.h" // For FrameSettings, FrameStatistics, FrameUpdate

#include "vtkSmartPointer.h"
#include "vtkTimeStamp.h"
#include "vtkType.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

class vtkAbstractMapper;
class vtkLight;
class vtkOpenGLRenderWindow;
class vtkOpenGLRenderer;
class vtkProp;
class vtkRenderState;
class vtkRenderer;
class vtkShaderProgram;
class vtkShadowMapExchange;
class vtkShadowMapRepresentation;
class vtkWindow;

namespace shadowmaps
{
class MapGroups
{
public:
  /// Each light's representation: its own or the pass's.
  using RepresentationOf = std::function<vtkShadowMapRepresentation*(vtkLight*)>;

  /// Makes `renderer`'s maps (and its camera's eye's) the current ones in every group.
  void SelectRenderer(vtkOpenGLRenderer* renderer);

  /// The frame's shadows for the current renderer: a group added for each
  /// representation its shadowed lights use that has none, the groups of
  /// representations no longer `assigned` (the pass's, the lights' own)
  /// dropped, then each group's maps prepared and, once every group's texture
  /// units are reserved, rendered (FrameUpdate). Whether the frame has
  /// shadows (false: no shadowed light, or a failure, warned).
  bool Prepare(vtkOpenGLRenderer* renderer, const vtkRenderState* s, const FrameSettings& settings,
    const RepresentationOf& representationOf,
    const std::vector<vtkShadowMapRepresentation*>& assigned);

  /// Binds every group's maps for the receivers of the frame just prepared.
  void BindForReceivers(vtkOpenGLRenderer* renderer);

  /// The frame goes on without shadows; `error` is warned (once until another).
  void Fail(const std::string& error, vtkWindow* context);

  /// The warnings every group found since the last call.
  std::vector<std::string> TakeWarnings();

  /// The groups' statistics together: counts summed, the resolution and
  /// caster passes per layer the largest.
  FrameStatistics Statistics() const;
  void ClearFrameStatistics();
  /// How many groups of maps (representations) shadowed lights of the last
  /// frame (the last renderer's) used.
  int Count() const;

  /// Every group's share of the mappers' shaders, in group order.
  std::vector<GroupCode> ShaderCode() const;
  /// When the current renderer's mappers must last have built their shaders:
  /// the groups changed, or its code did, or a prop of it is drawn with
  /// another renderer's code (BuiltCode).
  vtkMTimeType ShaderKeyTime() const;
  /// `mapper` just built its shaders with the current renderer's code, to draw `prop`.
  void ShadersBuilt(vtkAbstractMapper* mapper, vtkProp* prop) { this->Built.Built(mapper, prop); }

  /// Sets `program`'s uniforms for its next draw: casting into the group whose
  /// casters draw, else receiving every group's shadows (`active`: the frame
  /// has shadows), else drawn without the pass (another renderer's draw).
  void SetProgramUniforms(vtkShaderProgram* program, vtkProp* prop, bool active, double normalOffset);

  /// The group whose lights hold the analysed light, and that light's index
  /// among them; null when no group's does.
  FrameUpdate* AnalysedGroup(int& light) const;

  /// A frame of the pass ended (ProgramUniforms::EndFrame).
  void EndFrame();
  /// Frees every group's texture units.
  void ReleaseTextureUnits(vtkOpenGLRenderWindow* window);

  bool HoldsMapsOf(vtkRenderer* renderer) const;
  bool HoldsNoMaps() const;
  std::size_t MemoryBytes() const;
  void ReleaseMapsOf(vtkRenderer* renderer, vtkOpenGLRenderWindow* window);
  /// `renderer` stopped drawing through the pass: its shader code no longer
  /// counts (BuiltCode).
  void ForgetCodeOf(vtkRenderer* renderer) { this->Built.Forget(renderer); }
  /// Releases every GL object the groups hold in `window`'s (current) context.
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  struct Group
  {
    vtkSmartPointer<vtkShadowMapRepresentation> Representation;
    std::unique_ptr<FrameUpdate> Update;
    FrameSettings Settings;
    bool Ready = false;
  };

  /// The representations the renderer's shadowed lights use, in the order of
  /// each one's first light (the pass's alone where no light shadows).
  static std::vector<vtkShadowMapRepresentation*> RepresentationsInUse(vtkOpenGLRenderer* renderer,
    const FrameSettings& settings, const RepresentationOf& representationOf);
  /// Releases the groups whose representation is not `assigned`, and adds
  /// one for each of `used` that has none, after the others.
  void FormGroups(const std::vector<vtkShadowMapRepresentation*>& used,
    const std::vector<vtkShadowMapRepresentation*>& assigned, vtkOpenGLRenderWindow* window);
  void Release(Group& group, vtkWindow* window);
  /// Whether the groups' code for the current renderer, of key `key`
  /// (CodeKey), compiles (together), tried once per key; with several groups,
  /// on every process alike.
  bool CodeCompiles(
    const std::string& key, vtkOpenGLRenderWindow* window, vtkShadowMapExchange* exchange);
  /// The keys of every group's code for the current renderer, in group order.
  std::string CodeKey() const;

  std::vector<Group> Groups;
  vtkTimeStamp GroupsTime;
  /// Whether the groups' code compiles, by CodeKey: renderers whose lights
  /// differ hold different code, each tried once.
  std::map<std::string, bool> CheckedCodes;
  BuiltCode Built;
};
} // namespace shadowmaps

#endif
