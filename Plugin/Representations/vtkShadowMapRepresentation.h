/**
 * @class   vtkShadowMapRepresentation
 * @brief   What a texel of the shadow maps stores: one strategy of a shadow-map pass.
 *
 * A shadow-map pass (vtkAbstractShadowMapPass) makes two independent choices:
 * where each light's views go (vtkShadowMapViews) and what a texel of their maps
 * stores (this class). A representation says
 * - what the casters write (GetMapStorage: one depth, or two float values
 *   written by a GLSL snippet, optionally with minimum blending, or the depths
 *   of the two nearest caster surfaces);
 * - how the maps are post-processed once rendered (PostProcessMaps: a blur;
 *   the pass builds the mipmaps MapStorage asks for after);
 * - how receivers read them (GetReceiverLookupCode: the GLSL that defines
 *   vtkShadowLookup, usually one file of Shaders/), with its own parameters
 *   (GetReceiverDefinitions, SetReceiverUniforms);
 * - the depth offset its casters need (GetCasterDepthOffset).
 *
 * Adding a representation is one subclass and one GLSL file; it then works with
 * every views strategy (uniform, warped, cascaded). vtkDepthShadowMapRepresentation
 * is the depth map with the PCF filter family. A change of a representation's
 * parameters re-renders the maps of every pass that uses it.
 */
#ifndef vtkShadowMapRepresentation_h
#define vtkShadowMapRepresentation_h

#include "ShadowMapTextureArray.h" // For TexelFormat, TextureArray
#include "vtkObject.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkWrappingHints.h"             // For VTK_WRAPEXCLUDE

#include <string>  // For the GLSL code
#include <utility> // For StoreUniforms
#include <vector>  // For PostProcessMaps

class vtkOpenGLRenderer;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

namespace shadowmaps
{
/// What a texel of the maps holds and how the casters write it.
struct MapStorage
{
  TexelFormat Format = TexelFormat::Depth;
  /// Value formats: GLSL statements that read `float vtkShadowCasterDepth` (the
  /// fragment's window depth, or its light depth; gl_FrontFacing is available
  /// too) and write gl_FragData[0]. Ignored for depth storage.
  std::string StoreCode;
  /// Value formats: GLSL functions StoreCode calls, put before main().
  std::string StoreFunctions;
  /// Value formats: the float uniforms StoreFunctions reads, by name. Every
  /// program that stores values (the casters', the values made again from
  /// the processes' combined light depths) gets them, so that a parameter a
  /// user drags builds no shader.
  std::vector<std::pair<std::string, float>> StoreUniforms;
  /// Value formats: vtkShadowCasterDepth, and the depth receivers pass to
  /// vtkShadowLookup, is the light depth (ShadowLight::Depth): linear in light
  /// space, the same for every view of a light, in [0, 1] over the scene.
  bool LightDepth = false;
  /// Value formats: each channel keeps the minimum over all fragments of a
  /// texel (blending with GL_MIN, no depth test), e.g. nearest front and back
  /// faces. Otherwise the nearest fragment's values are kept (depth test).
  bool MinimumBlending = false;
  /// Value formats: values of a texel no caster covers.
  float ClearValues[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
  /// Value formats: build a mipmap chain after rendering (filterable storage).
  bool Mipmaps = false;
  /// Value formats without a second depth: samples per texel the casters are
  /// rendered with, averaged into the texel (values that average, such as
  /// moments, then hold the texel's coverage). 1: none.
  int Samples = 1;
  /// Value formats: c > 0 when the first value is exp(c (2 d - 1)) of a depth
  /// d (exponential warps), for the SHADOW_MAP view to show d.
  double WarpExponent = 0.0;
  /// TwoFloats: store the depths of the two nearest caster surfaces (the far
  /// value 1 where there are fewer), made by this method; StoreCode,
  /// MinimumBlending and ClearValues are then the pass's
  /// (vtkAbstractShadowMapPass::ChooseSecondDepthMethod).
  SecondDepthMethod SecondDepth = SecondDepthMethod::None;
  /// Some caster is translucent: transmittance maps beside these
  /// (shadowmaps::TransmittanceMaps). Set by the pass, not the representation.
  bool Transmittance = false;
};

/// A map layer the casters were just rendered into (PostProcessMaps).
struct RenderedLayer
{
  int Layer = 0;
  /// Its light's first view's texel size over this layer's (1 but for
  /// cascades): a filter radius in texels times it keeps its world size.
  double FilterScale = 1.0;
};

/// Depth offset applied to the casters (glPolygonOffset's factor and units).
struct DepthOffset
{
  double SlopeScaled = 0.0;
  double Constant = 0.0;
};
} // namespace shadowmaps

class VTKRENDERINGSHADOWMAPS_EXPORT vtkShadowMapRepresentation : public vtkObject
{
public:
  vtkTypeMacro(vtkShadowMapRepresentation, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What a texel holds and how casters write it. Default: one depth, written
   * depth-only; the pass stores it in 16 bits instead of 32 where every view
   * allows (shadowmaps::SixteenBitDepthSuffices).
   */
  VTK_WRAPEXCLUDE virtual void GetMapStorage(shadowmaps::MapStorage& storage) const;

  /**
   * GLSL appended to the receivers' shadow code (vtkShadowMapsReceiverFS). It
   * declares the sampler `vtkShadowMaps` (a sampler2DArrayShadow for depth
   * storage, a sampler2DArray for value storage) and defines `float
   * vtkShadowLookup(vec3 mapCoord, int layer)`: the visibility in [0, 1] of a
   * receiver at depth mapCoord.z seen at texture coordinates mapCoord.xy of map
   * layer `layer`. `vtkShadowViews[layer].FilterScale` is its light's first
   * layer's texel size over this layer's (1 but for cascades): offsets in texels
   * multiplied by it keep a kernel's world size. Every global name it declares
   * starts with vtkShadow (macros VTK_SHADOW_): where lights of one pass use
   * two representations, each one's names get a suffix of their own.
   */
  virtual std::string GetReceiverLookupCode() const = 0;

  /** GLSL put before the receivers' shadow code, e.g. #defines of the parameters. Default none. */
  virtual std::string GetReceiverDefinitions() const;

  /** How far the lookup reaches from a receiver's texel, in texels. Default 1. */
  virtual double GetFilterReachTexels() const;

  /**
   * GLSL appended after the lookup code when a light has a size
   * (vtkAbstractShadowMapPass::LIGHT_SIZE; VTK_SHADOW_SIZED_LIGHTS is then
   * defined): it defines `float vtkShadowSoftVisibility(...)`, the soft
   * shadow's visibility (vtkShadowMapsSoftKernelFS.glsl says what the
   * techniques share). Maps of depths give vtkShadowMapsSoftFS (percentage-
   * closer soft shadows), whose lookup then also defines `vec2
   * vtkShadowBlockerDepth(vec2 uv, int layer)`: the depth in front of which a
   * receiver at uv is shadowed, and the nearest caster's depth there. Default
   * empty: sized lights cast hard shadows, with a warning.
   */
  virtual std::string GetSoftShadowCode() const;

  /** Whether sized lights get soft shadows here: GetSoftShadowCode is not empty. */
  bool GetSupportsSizedLights() const;

  /** Whether the maps are sampled with linear filtering. Default true. */
  virtual bool GetLinearFiltering() const;

  /** The depth offset of the casters. Default none. */
  VTK_WRAPEXCLUDE virtual shadowmaps::DepthOffset GetCasterDepthOffset() const;

  /**
   * Called after the casters were rendered into `layers`, before the mipmaps
   * MapStorage asks for are built and receivers sample the maps: blur or other
   * filtering of level 0 of those layers goes here. The other layers were not
   * re-rendered and keep what the last call left in them. Returning false
   * reports a GL failure: the frame renders unshadowed.
   */
  VTK_WRAPEXCLUDE virtual bool PostProcessMaps(vtkOpenGLRenderer* renderer,
    shadowmaps::TextureArray& maps, const std::vector<shadowmaps::RenderedLayer>& layers);

  /**
   * Whether what PostProcessMaps leaves in a layer depends on the layer's
   * RenderedLayer::FilterScale (a blur of one world size in every cascade): the
   * pass then re-renders a layer whose FilterScale changed although its own
   * view did not (a tight cascade's first cascade fitted again). Default true,
   * the safe answer for a representation that post-processes its layers.
   */
  virtual bool GetPostProcessingFollowsFilterScale() const;

  ///@{
  /**
   * Receiver resources: ActivateReceiverResources before the scene is drawn
   * (bind textures of the representation's own), SetReceiverUniforms per
   * receiver program, DeactivateReceiverResources after. Default: nothing.
   * The names of the uniforms SetReceiverUniforms sets end with `nameSuffix`:
   * where lights of a pass use several representations, each one's shadow
   * code has names of its own (shadowmaps::ShaderGroup); empty otherwise.
   */
  VTK_WRAPEXCLUDE virtual void ActivateReceiverResources(vtkOpenGLRenderWindow* window);
  VTK_WRAPEXCLUDE virtual void SetReceiverUniforms(
    vtkShaderProgram* program, const std::string& nameSuffix);
  VTK_WRAPEXCLUDE virtual void DeactivateReceiverResources();
  ///@}

  /** Releases the GL objects of the representation's own. */
  virtual void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkShadowMapRepresentation() = default;
  ~vtkShadowMapRepresentation() override = default;

private:
  vtkShadowMapRepresentation(const vtkShadowMapRepresentation&) = delete;
  void operator=(const vtkShadowMapRepresentation&) = delete;
};

#endif
