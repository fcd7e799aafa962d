// When a renderer's mappers must build their shaders again: VTK's mappers ask
// a render pass one time for all of them (GetShaderStageMTime), not whether
// its code changed for them. A renderer's code (every group's, for its lights)
// is known by a number: its mappers build again when that number changes, or,
// where renderers sharing the pass hold different code, when one of its props
// is drawn by another renderer too, or its mapper was last built with another
// code (a mapper drawn for both). A renderer without shadowed lights draws
// with whatever code its programs hold, the receiving turned off. The eyes of
// a stereo camera hold the same code. Not a VTK class.
#ifndef ShadowMapBuiltCode_h
#define ShadowMapBuiltCode_h

#include "vtkTimeStamp.h"
#include "vtkType.h"
#include "vtkWeakPointer.h"

#include <map>
#include <string>
#include <unordered_map>
#include <utility>

class vtkAbstractMapper;
class vtkObject;
class vtkProp;
class vtkRenderState;
class vtkRenderer;

namespace shadowmaps
{
class BuiltCode
{
public:
  /// Makes `code` (the key of every group's code for `renderer`) the code its
  /// mappers build with, and decides whether they must build again
  /// (RebuildTime). `shadowed` false: the renderer has no shadowed light.
  void Select(vtkRenderer* renderer, const std::string& code, const vtkRenderState* s,
    bool shadowed);

  /// `mapper` just built its shaders with the current code, to draw `prop`.
  void Built(vtkAbstractMapper* mapper, vtkProp* prop);

  /// When the current renderer's mappers last had to build again; 0 for a
  /// renderer without shadowed lights.
  vtkMTimeType RebuildTime() const;

  void Forget(vtkRenderer* renderer);
  void Clear();

private:
  struct RendererCode
  {
    vtkWeakPointer<vtkRenderer> Renderer;
    int Code = 0;
    vtkTimeStamp Rebuild;
  };

  /// A number for each code key, never given to another.
  int NumberOf(const std::string& code);
  /// Whether renderers drawing now hold more than one code.
  bool RenderersDiffer();
  /// Whether a prop of `s` is drawn by a renderer of another code, or draws
  /// with a mapper last built with another.
  bool DrawnWithAnother(const vtkRenderState* s) const;
  void Record(vtkAbstractMapper* mapper);

  std::map<std::string, int> Numbers;
  int NextNumber = 1;
  std::map<vtkRenderer*, RendererCode> Renderers;
  RendererCode* Current = nullptr;
  /// The code each mapper last built its shaders with: the mapper that built
  /// them, and the actor's or volume's own mapper where that one delegates
  /// (composite and glyph mappers, vtkSmartVolumeMapper).
  std::unordered_map<vtkObject*, std::pair<vtkWeakPointer<vtkObject>, int>> Mappers;
  std::size_t MappersAtLastPurge = 0;
};
} // namespace shadowmaps

#endif
