// The last step of rendering a linear-depth view into a depth map: its casters
// wrote their linear depth as colour (TextureArray::BindLayer's secondOutput),
// since a cast that wrote gl_FragDepth would make the scene's draws of the same
// programs (ShadowMapCasterShader.h) lose their early depth test; this copies
// that colour into the layer's depth with one full-screen draw.
#ifndef ShadowMapLinearDepthResolve_h
#define ShadowMapLinearDepthResolve_h

#include <memory>
#include <string>

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkWindow;

namespace shadowmaps
{
class TextureArray;

class LinearDepthResolve
{
public:
  LinearDepthResolve();
  ~LinearDepthResolve();
  LinearDepthResolve(const LinearDepthResolve&) = delete;
  LinearDepthResolve& operator=(const LinearDepthResolve&) = delete;

  /// Copies the linear depths into `layer` of `maps`; leaves the layer bound
  /// without its colour buffer. False, with `error`, on a GL failure.
  bool Render(vtkOpenGLRenderWindow* window, TextureArray& maps, int layer, std::string& error);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
};
} // namespace shadowmaps

#endif
