// What the pass sets on the mappers' programs, and when. Programs keep their
// uniforms and many draws share one, so each program takes the casters'
// uniforms once per view it draws into, and the receivers' once per frame
// (ProgramStamps): the per-draw cost does not grow with lights or views.
// Programs are shared by the renderers (and eyes) that draw through the pass,
// whose maps differ. Not a VTK class.
#ifndef ShadowMapProgramUniforms_h
#define ShadowMapProgramUniforms_h

#include "ShadowMapCasterShader.h" // For CasterUniforms
#include "ShadowMapFloatUniforms.h" // For FloatUniforms
#include "ShadowMapLight.h"        // For ShadowFrame
#include "ShadowMapProgramStamps.h"
#include "ShadowMapReceiverShader.h" // For ReceiverTextureUnits

#include <unordered_map>
#include <unordered_set>

class vtkShaderProgram;
class vtkShadowMapRepresentation;

namespace shadowmaps
{
struct RendererMaps;

/// What a view's casters draw with besides the view.
struct CastingSettings
{
  int Resolution = 1;
  /// Window depth in 16 bits (TexelFormat::Depth16): the polygon offset's
  /// unit for impostors, which write their own depth.
  bool Depth16 = false;
  /// The casters store the light depth (CasterCode::LightDepth), or
  /// translucent ones keep it in the transmittance maps.
  bool LightDepth = false;
  double SlopeScaledOffset = 0.0;
  double ConstantOffset = 0.0;
  /// The context's largest point size (impostors' sprites).
  float LargestPointSize = 1.0f;
  bool SceneCameraParallel = false;
  /// What the storage's store code reads (MapStorage::StoreUniforms).
  FloatUniforms StoreUniforms;
};

class ProgramUniforms
{
public:
  /// The group of maps whose shadow code these uniforms are for (ShaderGroup).
  void SetGroup(int index);

  /// The casters' uniforms, and the GL polygon offset, for drawing into
  /// `view` of `light`: every program takes them on its next caster draw.
  void SetCastingView(const ShadowLight& light, const LightView& view, const ShadowFrame& frame,
    const CastingSettings& settings);

  /// Depth peeling's pass (CasterUniforms::SetPeeling), for the next caster draws.
  void SetPeeling(bool secondPass, int peelUnit);

  /// Whether the next caster draws go into the transmittance maps.
  void SetTransmitting(bool transmitting);

  /// Impostors' drawn size over the whole image's (SceneCamera::DrawnRadius).
  void SetDrawnRadius(float radius);

  /// Before a caster draw with `program`.
  void Casting(vtkShaderProgram* program, const ReceiverTextureUnits& units,
    vtkShadowMapRepresentation* representation);

  /// Before a caster draw with `program` into another group's maps: this
  /// group's samplers on units of their own (a sampler sharing a unit with
  /// one of another type fails the draw). Once per program and frame.
  void WhileOthersCast(vtkShaderProgram* program, const ReceiverTextureUnits& units,
    vtkShadowMapRepresentation* representation);

  /// Before a scene draw with `program`, shaded with `maps`.
  void Receiving(vtkShaderProgram* program, RendererMaps& maps, const ReceiverTextureUnits& units,
    int resolution,
    double normalOffset, vtkShadowMapRepresentation* representation);

  /// Before another renderer's draw with `program` of a prop the pass keeps
  /// joined past its frame (PropJoining): no cast, no shadow, its samplers on
  /// the units the pass keeps, its renderer's lights sent again; once per
  /// program until the pass's next frame (EndFrame).
  void DrawnWithoutThePass(vtkShaderProgram* program, const ReceiverTextureUnits& units,
    vtkShadowMapRepresentation* representation);

  /// A frame of the pass's ended: the programs it drew with hold its uniforms.
  void EndFrame()
  {
    this->ElsewherePrograms.Invalidate();
    this->OthersCastingPrograms.Invalidate();
  }

  /// `maps` are going: no program was last drawn for them.
  void Forget(const RendererMaps* maps);

  /// Every program is forgotten (their GL objects released).
  void Clear();

private:
  /// The group's samplers on `units` and the representation's uniforms, if
  /// `program` receives the group's shadows (whether it does).
  bool ApplyReceiverSamplers(vtkShaderProgram* program, const ReceiverTextureUnits& units,
    vtkShadowMapRepresentation* representation) const;

  CasterUniforms Casters;
  FloatUniforms StoreUniforms;
  ProgramStamps CasterPrograms;
  /// Programs set up for other renderers' draws since the pass's last frame.
  ProgramStamps ElsewherePrograms;
  /// Programs set up for other groups' caster draws in this frame.
  ProgramStamps OthersCastingPrograms;
  ShaderGroup Group;
  /// Programs the casters drew with since the scene last did.
  std::unordered_set<vtkShaderProgram*> CastSinceSceneDraw;
  /// The maps each program last shaded with.
  std::unordered_map<vtkShaderProgram*, const RendererMaps*> LastDrawnFor;
};
} // namespace shadowmaps

#endif
