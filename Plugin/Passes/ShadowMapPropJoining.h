// Which props draw through a shadow pass. A pass joins the render passes of
// the props it draws (their property keys' RenderPasses: the mapper then asks
// it for shader code and uniforms) for the length of a renderer's frame:
// casters before the scene's props, each once, since a mapper keeps one program
// per primitive and rebuilds it whenever the set of passes on its prop changes.
// A prop that another renderer of the window draws without any pass (an actor
// shown in two views) would then rebuild its shaders in both renderers every
// frame; such props stay joined past the frame, and the pass draws them there
// as without shadows (vtkAbstractShadowMapPass::SetShaderParameters outside its
// frames). Not a VTK class.
#ifndef ShadowMapPropJoining_h
#define ShadowMapPropJoining_h

#include "vtkWeakPointer.h"

#include <functional>
#include <vector>

class vtkObjectBase;
class vtkProp;
class vtkRenderer;

namespace shadowmaps
{
class PropJoining
{
public:
  /// `pass` is what joins the props' render passes.
  explicit PropJoining(vtkObjectBase* pass);
  ~PropJoining();
  PropJoining(const PropJoining&) = delete;
  PropJoining& operator=(const PropJoining&) = delete;

  /// Joins those of `props` that `takesPart` (cast or receive), once each.
  void Join(vtkProp* const* props, int count, const std::function<bool(vtkProp*)>& takesPart);

  /// At the end of `renderer`'s frame: leaves every prop joined, but those
  /// another renderer of its window draws too, through no pass at all, which
  /// stay joined until a frame of this pass's no longer draws them, LeaveAll,
  /// or another shadow pass's frame draws them (its Join takes them over).
  void EndFrame(vtkRenderer* renderer);

  /// Leaves every prop, those kept past their frame too.
  void LeaveAll();

  /// Whether some prop stays joined past its frame (the pass's samplers keep
  /// their texture units meanwhile).
  bool KeepsAny() const { return !this->Kept.empty(); }

private:
  void Leave(vtkProp* prop);

  vtkObjectBase* Pass;
  /// Joined in this frame.
  std::vector<vtkWeakPointer<vtkProp>> Joined;
  /// Joined past the last frame that drew them.
  std::vector<vtkWeakPointer<vtkProp>> Kept;
};
} // namespace shadowmaps

#endif
