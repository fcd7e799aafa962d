#ifndef ShadowMapReceiverTextures_h
#define ShadowMapReceiverTextures_h

#include "ShadowMapReceiverShader.h" // For ReceiverTextureUnits

class vtkOpenGLRenderWindow;
class vtkShadowMapRepresentation;

namespace shadowmaps
{
struct MapStorage;
struct RendererMaps;

/// The texture units of a frame's shadow textures: the maps, the maps' depths
/// without comparison (soft shadows' blocker search), the transmittance maps,
/// depth peeling's first-pass depths, and the representation's own resources.
/// Casters and receivers share programs, so the receivers' samplers must point
/// at units of their own while the casters draw too (a sampler sharing a unit
/// with one of another type fails the draw): the units are reserved, with no
/// map bound, and the representation's resources activated before the casters
/// draw; the maps are bound to them for the scene's draw, and all is freed at
/// the end of the frame.
class ReceiverTextures
{
public:
  /// Reserves the units once per frame; true when this call reserved them.
  bool Reserve(vtkOpenGLRenderWindow* window, const MapStorage& storage, bool rawDepths,
    vtkShadowMapRepresentation* representation);

  /// Binds `maps` to the units Reserve reserved, for the scene's draw.
  void Bind(vtkOpenGLRenderWindow* window, RendererMaps& maps,
    vtkShadowMapRepresentation* representation);

  /// Unbinds and frees every unit; the representation's resources deactivated.
  void Release(vtkOpenGLRenderWindow* window, vtkShadowMapRepresentation* representation);

  /// The units the receivers' samplers read.
  ReceiverTextureUnits Units() const { return this->Receivers; }

  /// The unit of depth peeling's first-pass depths, -1 when the maps are not peeled.
  int GetPeelUnit() const { return this->PeelUnit; }

private:
  ReceiverTextureUnits Receivers;
  int PeelUnit = -1;
  bool Reserved = false;
};
} // namespace shadowmaps

#endif
