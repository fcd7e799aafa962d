// When a renderer's mappers must build their shaders again: VTK's mappers ask
// a render pass one time for all of them (GetShaderStageMTime), not whether
// its code changed for them. A renderer's code (every group's, for its lights)
// is known by a number: its mappers build again when that number changes, when
// a mapper one of its props draws with was last built with another code (a
// mapper drawn for another renderer too, which may since have stopped), or,
// where renderers drawing through the pass hold different code, when one of
// its props is also another's. A renderer without shadowed lights draws with
// whatever code its programs hold, the receiving turned off. The eyes of a
// stereo camera hold the same code. Not a VTK class.
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
  /// Whether a prop of `s` is drawn by a renderer of another code.
  bool SharedWithAnother(const vtkRenderState* s) const;
  /// Whether a prop of `s` draws with a mapper last built with another code.
  bool BuiltWithAnother(const vtkRenderState* s) const;
  /// Whether any mapper alive was last built with another code than the
  /// current one (forgets the deleted ones).
  bool AnyBuiltWithAnother();
  void Record(vtkAbstractMapper* mapper);
  /// Adds `change` to the records of `code` (0: none).
  void Count(int code, int change);
  void Purge();

  std::map<std::string, int> Numbers;
  int NextNumber = 1;
  std::map<vtkRenderer*, RendererCode> Renderers;
  RendererCode* Current = nullptr;
  /// The code each mapper last built its shaders with: the mapper that built
  /// them, and the actor's or volume's own mapper where that one delegates
  /// (composite and glyph mappers, vtkSmartVolumeMapper).
  std::unordered_map<vtkObject*, std::pair<vtkWeakPointer<vtkObject>, int>> Mappers;
  std::size_t MappersAtLastPurge = 0;
  /// How many records hold each code, deleted mappers' included until purged.
  std::map<int, long> RecordsOfCode;
};
} // namespace shadowmaps

#endif
