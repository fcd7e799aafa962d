// A separable Gaussian blur of value map layers (filterable representations):
// a horizontal pass from the layer into a scratch layer, a vertical pass back.
// The cost is per map texel, paid when a layer is re-rendered, not per pixel.
#ifndef ShadowMapBlur_h
#define ShadowMapBlur_h

#include "vtkOpenGLQuadHelper.h" // For the quad

#include <memory>
#include <string>

class vtkOpenGLRenderWindow;
class vtkWindow;

namespace shadowmaps
{
class TextureArray;

/// The Gaussian's standard deviation for a blur of `radius` texels: the kernel
/// spans +-2 sigma, where its weights fall below a seventh of the centre's.
inline double BlurSigma(double radius)
{
  return 0.5 * radius;
}

class MapBlur
{
public:
  MapBlur();
  ~MapBlur(); // GL names need a current context: call ReleaseGraphicsResources().
  MapBlur(const MapBlur&) = delete;
  MapBlur& operator=(const MapBlur&) = delete;

  /// Blurs level 0 of `layer` of the value maps `maps` by a Gaussian `radius`
  /// texels wide (nothing below half a texel). False on GL failure, with
  /// `error` filled.
  bool Blur(vtkOpenGLRenderWindow* window, TextureArray& maps, int layer, double radius,
    std::string& error);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  bool ReserveScratch(const TextureArray& maps, std::string& error);
  /// The horizontal pass from `layer` into the scratch layer, then the vertical one back.
  bool DrawBothPasses(vtkOpenGLRenderWindow* window, TextureArray& maps, int layer, int unit,
    double radius, std::string& error);
  void DrawPass(vtkOpenGLRenderWindow* window, unsigned int source, int layer, int unit,
    int dx, int dy, double radius);

  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  unsigned int Scratch = 0;
  unsigned int ScratchFramebuffer = 0;
  int ScratchResolution = 0;
  int ScratchFormat = -1;
};
} // namespace shadowmaps

#endif
