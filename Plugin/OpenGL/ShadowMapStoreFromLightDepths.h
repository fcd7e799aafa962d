// Value maps rebuilt from combined light depths (vtkShadowMapExchange): moments
// do not combine across processes, the nearest caster's light depth does. While
// a process renders a value map's layers, its casters also write their light
// depth to the layers' second output, which Keep copies per layer; once the
// depths are combined (the nearest over the processes), Store writes each
// layer's values from them with the storage's own store code, as if the
// nearest caster of every process had drawn there. The blur and the mipmaps
// follow as usual. Not a VTK class: it holds no VTK state.
#ifndef ShadowMapStoreFromLightDepths_h
#define ShadowMapStoreFromLightDepths_h

#include "ShadowMapFloatUniforms.h" // For FloatUniforms

#include <memory>
#include <string>
#include <vector>

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkWindow;

namespace shadowmaps
{
class TextureArray;

class StoreFromLightDepths
{
public:
  StoreFromLightDepths();
  ~StoreFromLightDepths();
  StoreFromLightDepths(const StoreFromLightDepths&) = delete;
  StoreFromLightDepths& operator=(const StoreFromLightDepths&) = delete;

  /// Room for `layers` layers of the maps' light depths, all far (1).
  void Reset(const TextureArray& maps, int layers);

  /// Copies the light depths `layer`'s casters just wrote to the maps' second
  /// output. False, with `error`, on a GL failure.
  bool Keep(vtkOpenGLState* state, const TextureArray& maps, int layer, std::string& error);

  /// Every kept layer's light depths, layer after layer, row after row.
  std::vector<float>& GetDepths() { return this->Depths; }

  /// Writes `layer` of `maps` from its light depths: `storeCode` (which reads
  /// `float vtkShadowCasterDepth` and writes gl_FragData[0]) after
  /// `storeFunctions`, whose uniforms are `storeUniforms`, once per texel.
  /// False, with `error`, on a GL failure.
  bool Store(vtkOpenGLRenderWindow* window, TextureArray& maps, int layer,
    const std::string& storeFunctions, const std::string& storeCode,
    const FloatUniforms& storeUniforms, std::string& error);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  /// The quad's program for this store code, ready to draw; nullptr when it does not compile.
  bool ReadyProgram(vtkOpenGLRenderWindow* window, const std::string& storeFunctions,
    const std::string& storeCode);
  /// Uploads `layer`'s depths into Source, made or resized on demand.
  bool UploadLayer(vtkOpenGLState* state, int layer, int resolution);

  std::vector<float> Depths;
  unsigned int Source = 0;
  int SourceResolution = 0;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::string QuadShader;
};
} // namespace shadowmaps

#endif
