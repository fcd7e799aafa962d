// Which renderers draw through a pass. vtkRenderer::SetPass releases nothing
// of the pass it replaces, and a pass a renderer no longer draws with is never
// told: this watches each renderer's frames and reports one that ended without
// drawing through the pass (its context still current), or that is being
// deleted, so that the pass can release what it holds for it. Not a VTK class.
#ifndef ShadowMapRendererUse_h
#define ShadowMapRendererUse_h

#include "vtkWeakPointer.h" // For Watch

#include <functional>
#include <vector>

class vtkObject;
class vtkRenderer;

namespace shadowmaps
{
class RendererUse
{
public:
  /// `dropped` is called, at the end of its frame, for a renderer that drew
  /// without the pass (the renderer's context is current), and for a renderer
  /// being deleted.
  explicit RendererUse(std::function<void(vtkRenderer*)> dropped);
  ~RendererUse();
  RendererUse(const RendererUse&) = delete;
  RendererUse& operator=(const RendererUse&) = delete;

  /// The pass draws in `renderer`'s frame.
  void Drawn(vtkRenderer* renderer);

private:
  struct Watch
  {
    vtkWeakPointer<vtkRenderer> Renderer;
    unsigned long EndObserver = 0;
    unsigned long DeleteObserver = 0;
    bool DrawnThisFrame = false;
  };
  void FrameEnded(vtkObject* renderer, unsigned long, void*);
  void Deleted(vtkObject* renderer, unsigned long, void*);
  void Forget(std::vector<Watch>::iterator watch);

  std::function<void(vtkRenderer*)> Dropped;
  std::vector<Watch> Watches;
};
} // namespace shadowmaps

#endif
