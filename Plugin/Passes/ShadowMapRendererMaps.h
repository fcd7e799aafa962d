// The maps of each renderer that draws through a pass, and of each eye of a
// stereo camera: views sharing one set would fit and render it anew for each
// other. A renderer's maps hold their GL objects, their receivers' uniforms,
// the shader code made for them, and what they were last rendered for
// (MapUpdates). Not a VTK class.
#ifndef ShadowMapRendererMaps_h
#define ShadowMapRendererMaps_h

#include "ShadowMapLinearDepthResolve.h"
#include "ShadowMapPassShaders.h"
#include "ShadowMapPropRecords.h"
#include "ShadowMapReceiverShader.h"
#include "ShadowMapStoreFromLightDepths.h"
#include "ShadowMapTextureArray.h"
#include "ShadowMapTransmittance.h"
#include "ShadowMapUpdates.h"
#include "ShadowMapVolumeCasting.h"
#include "vtkShadowMapRepresentation.h" // For MapStorage

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <utility>

class vtkRenderer;
class vtkWindow;

namespace shadowmaps
{
/// One renderer's (one eye's) maps, what renders them, their receivers'
/// uniforms and shader code, and what the maps were last rendered for.
struct RendererMaps
{
  TextureArray Maps;
  /// The maps of the other of a drag's two resolutions (still and coarse,
  /// InteractiveResolutionScale), kept so that switching allocates nothing.
  TextureArray SpareMaps;
  /// Beside the maps while some caster is translucent (MapStorage::Transmittance).
  TransmittanceMaps Transmittances;
  /// The casting volumes' data, marched into the transmittance maps.
  VolumeCasters Volumes;
  MapStorage Storage;
  ReceiverUniforms Uniforms;
  LinearDepthResolve LinearDepths;
  /// Light depths of value maps, while the processes' maps are combined.
  StoreFromLightDepths LightDepths;
  MapUpdates Updates;
  /// The props' bounds and versions, read again only when they change.
  PropRecords Props;
  int Layers = 0;
  /// The shadow code for these maps' lights, layers and storage. Each
  /// renderer's is its own, so that renderers whose lights differ do not
  /// change the code of each other's mappers (MapGroups::ShaderKeyTime).
  PassShaders Code;

  /// Makes Maps those held at `resolution` if SpareMaps holds them, and keeps
  /// as SpareMaps only maps of resolution `spare` (0: none), released else.
  void SwitchMaps(int resolution, int spare);

  /// Frees the GL objects (`window`'s context current); the maps are then
  /// rendered anew.
  void ReleaseGraphicsResources(vtkWindow* window);
};

class MapsByRenderer
{
public:
  /// The maps of `renderer` for the eye its camera renders now, made on first
  /// use; they become the current ones.
  RendererMaps& Select(vtkRenderer* renderer);

  /// The maps of the frame being rendered; null before Select or once released.
  RendererMaps* Current() const { return this->CurrentMaps; }

  bool Holds(vtkRenderer* renderer) const;

  /// Frees and forgets the maps of `renderer` (both eyes), `window`'s
  /// context current; `forgetting` is told of each first.
  void Release(vtkRenderer* renderer, vtkWindow* window,
    const std::function<void(const RendererMaps*)>& forgetting);

  /// Frees and forgets every renderer's maps.
  void ReleaseAll(vtkWindow* window);

  bool Empty() const { return this->Maps.empty(); }

  /// Bytes the maps of every renderer hold.
  std::size_t MemoryBytes() const;

private:
  std::map<std::pair<vtkRenderer*, int>, std::unique_ptr<RendererMaps>> Maps;
  RendererMaps* CurrentMaps = nullptr;
};
} // namespace shadowmaps

#endif
