/**
 * @class   vtkAbstractShadowMapPass
 * @brief   Shared base of the shadow-map passes: lights, casters, receivers, filters, bias.
 *
 * A shadow-map pass renders the scene through a delegate (by default a
 * vtkRenderStepsPass, so opaque, translucent, volume and overlay geometry all
 * draw) after rendering one depth map per view of every shadowed light. One
 * line turns shadows on:
 *
 * @code
 * renderer->SetPass(vtkNew<vtkWarpedShadowMapPass>());
 * @endcode
 *
 * Every switched-on light that is not a headlight casts shadows: directional
 * lights (scene or camera lights), spot lights (cone angle below 90 degrees;
 * cones wider than 60 degrees use six cube faces) and point lights (positional
 * with a cone of 90 degrees or more: six cube faces). At most
 * VTK_MAX_SHADOWED_LIGHTS lights are shadowed; further lights still light the
 * scene, unshadowed, and a warning says so. A light opts out with
 * light->GetInformation()->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
 * its ShadowAttenuation scales how dark its shadows are.
 *
 * Maps are rendered with a minimal caster fragment shader into one texture
 * array, one layer per light view. Casters nearer the light than a view's near
 * plane are clamped onto it (depth clamping) rather than clipped, so they still
 * occlude what lies behind them. What a light's views are (ComputeLightViews)
 * and what a texel stores (GetMapStorage, GetReceiverLookupCode: one depth by
 * default, or two float values such as two depth layers or moments) are the
 * subclass's choice.
 *
 * Receivers: the shadow test is injected into the fragment shaders of
 * vtkOpenGLPolyDataMapper and its subclasses, per light, scaling that light's
 * diffuse and specular (Phong) or radiance (PBR) terms. Unlit draws compile
 * unchanged and render without shadows. Actors opt out through their property
 * keys: CASTS_SHADOWS() = 0 (not a caster), RECEIVES_SHADOWS() = 0.
 *
 * Bias (thesis 000 §3.2, Kozlov 001): constant and slope-scaled depth offset
 * applied when the casters are rendered (m = max(|dz/dx|, |dz/dy|)), and a
 * normal offset measured in texels and scaled by the world-space texel size at
 * the receiver.
 *
 * Filtering: hard (1 tap), hardware 2x2 bilinear PCF, N x N PCF of bilinear
 * taps, and Poisson-disc PCF rotated per texel by a noise texture addressed in
 * light space, so the pattern stays put while the camera moves.
 *
 * The maps are re-rendered only when the camera, a light, a caster, a caster's
 * input data (including upstream pipeline changes), the window size or a pass
 * parameter changed.
 *
 * If the GL context cannot provide the maps (allocation or framebuffer
 * failure) the pass warns once and renders the frame without shadows.
 */
#ifndef vtkAbstractShadowMapPass_h
#define vtkAbstractShadowMapPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro

#include <memory> // For std::unique_ptr
#include <string> // For GetReceiverLookupCode

class vtkCamera;
class vtkInformationIntegerKey;
class vtkLight;
class vtkOpenGLRenderer;
class vtkRenderPass;
namespace shadowmaps
{
struct LightView;
struct ShadowLight;
struct MapStorage;
class TextureArray;
}

#define VTK_MAX_SHADOWED_LIGHTS 8

class VTKRENDERINGSHADOWMAPS_EXPORT vtkAbstractShadowMapPass : public vtkOpenGLRenderPass
{
public:
  vtkTypeMacro(vtkAbstractShadowMapPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Set on an actor's property keys (or a light's information) with value 0 to
   * keep it from casting shadows. Absent means 1.
   */
  static vtkInformationIntegerKey* CASTS_SHADOWS();

  /**
   * Set on an actor's property keys with value 0 to keep it from receiving
   * shadows. Absent means 1.
   */
  static vtkInformationIntegerKey* RECEIVES_SHADOWS();

  /**
   * The pass that renders the scene with shadows applied. Defaults to a
   * vtkRenderStepsPass. Setting nullptr restores the default.
   */
  virtual void SetDelegatePass(vtkRenderPass* delegate);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);

  ///@{
  /**
   * Width and height of each shadow map in texels. Default 2048, clamped to
   * [64, 16384] here and to the GL maximum texture size at render time.
   */
  vtkSetClampMacro(Resolution, int, 64, 16384);
  vtkGetMacro(Resolution, int);
  ///@}

  enum CasterFacesType
  {
    FRONT_FACES = 0,
    BACK_FACES = 1,
    BOTH_FACES = 2
  };

  ///@{
  /**
   * Which faces of the casters are rendered into the maps. Back faces alone
   * (second-depth shadow mapping) need almost no bias on closed objects; both
   * (the default) suits open surfaces. Clamped to [FRONT_FACES, BOTH_FACES].
   */
  vtkSetClampMacro(CasterFaces, int, FRONT_FACES, BOTH_FACES);
  vtkGetMacro(CasterFaces, int);
  ///@}

  enum FilterType
  {
    HARD = 0,
    PCF_2X2 = 1,
    PCF_NXN = 2,
    POISSON = 3
  };

  ///@{
  /**
   * Shadow filter. HARD: one nearest tap. PCF_2X2: one hardware bilinear
   * comparison. PCF_NXN: N x N bilinear comparisons (KernelSize). POISSON: a
   * rotated Poisson disc of PoissonSamples taps within FilterRadius texels.
   * Clamped to [HARD, POISSON]; default PCF_2X2.
   */
  vtkSetClampMacro(Filter, int, HARD, POISSON);
  vtkGetMacro(Filter, int);
  ///@}

  ///@{
  /** N of the N x N PCF filter. Clamped to [2, 7]; default 3. */
  vtkSetClampMacro(KernelSize, int, 2, 7);
  vtkGetMacro(KernelSize, int);
  ///@}

  ///@{
  /** Radius of the Poisson filter, in texels. Clamped to [0.5, 16]; default 2. */
  vtkSetClampMacro(FilterRadius, double, 0.5, 16.0);
  vtkGetMacro(FilterRadius, double);
  ///@}

  ///@{
  /** Taps of the Poisson filter. Clamped to [4, 32]; default 16. */
  vtkSetClampMacro(PoissonSamples, int, 4, 32);
  vtkGetMacro(PoissonSamples, int);
  ///@}

  ///@{
  /**
   * Constant depth offset applied to casters, in units of the smallest
   * resolvable depth difference of the maps (glPolygonOffset units): about 2^-24
   * of the light's depth range in 32-bit maps, 1/65535 in 16-bit ones, so a unit
   * weighs 256 times more there (see GetMapStorage); the default stays below a
   * quarter texel either way. Views that store linear depth (the TSM, LiSPSM and
   * GMNPR warps) are always 32-bit and add it, as 2^-24 per unit, to the depth
   * they store. Clamped to [0, 10000]; default 4.
   */
  vtkSetClampMacro(ConstantBias, double, 0.0, 10000.0);
  vtkGetMacro(ConstantBias, double);
  ///@}

  ///@{
  /**
   * Slope-scaled depth offset applied to casters: the depth offset grows by
   * this factor times m = max(|dz/dx|, |dz/dy|). Views that store linear depth
   * take m on the depth they store; for directional lights this term is capped
   * at SlopeScaledBias / Resolution (a 45 degree surface in a uniform map), as a
   * warp's far texels are many times the mean. Clamped to [0, 100]; default 2.
   */
  vtkSetClampMacro(SlopeScaledBias, double, 0.0, 100.0);
  vtkGetMacro(SlopeScaledBias, double);
  ///@}

  ///@{
  /**
   * Receiver offset along its normal, in shadow-map texels (scaled by the
   * world-space size of a texel at the receiver). Clamped to [0, 10]; default 1.
   */
  vtkSetClampMacro(NormalOffset, double, 0.0, 10.0);
  vtkGetMacro(NormalOffset, double);
  ///@}

  enum AnalysisViewType
  {
    NO_ANALYSIS = 0,
    SHADOW_FACTOR = 1,
    TEXEL_DENSITY = 2,
    SHADOW_MAP = 3,
    PARTITION = 4
  };

  ///@{
  /**
   * Analysis view of light AnalysisLight (an index among the shadowed lights,
   * in the renderer's order): receivers show instead of their shading
   * - SHADOW_FACTOR: the light's visibility, white lit, black shadowed;
   * - TEXEL_DENSITY: a heat map of how many screen pixels one map texel
   *   covers (log scale): blue dense, green 1.5 pixels, orange to red
   *   undersampled (red channel 255 exactly when over 1.5 pixels);
   * - PARTITION: a colour per map view (cascade, cube face) that shaded the
   *   pixel, darker in shadow.
   * SHADOW_MAP replaces the frame by the light's maps, tiled, depth as grey.
   * Clamped; default NO_ANALYSIS.
   */
  vtkSetClampMacro(AnalysisView, int, NO_ANALYSIS, PARTITION);
  vtkGetMacro(AnalysisView, int);
  vtkSetClampMacro(AnalysisLight, int, 0, VTK_MAX_SHADOWED_LIGHTS - 1);
  vtkGetMacro(AnalysisLight, int);
  ///@}

  /** Number of lights that received shadow maps in the last frame. */
  vtkGetMacro(NumberOfShadowedLights, int);

  /** Number of map layers (light views) in use in the last frame. */
  vtkGetMacro(NumberOfShadowMapLayers, int);

  /**
   * Light views of the last map update whose matrices were not finite (a
   * degenerate scene or camera). Their lights cast no shadow in that frame, and
   * a warning says so once until every view is finite again. 0 in a healthy frame.
   */
  vtkGetMacro(NumberOfNonFiniteViews, int);

  /** How many times the shadow maps were (re-)rendered since creation. */
  vtkGetMacro(NumberOfShadowMapUpdates, int);

  /** Caster draws (prop renders into maps) in the last map update. */
  vtkGetMacro(NumberOfCasterDraws, int);

  ///@{
  /**
   * Caster shaders built so far: depth-only (minimal fragment shader) and
   * keeping the mapper's fragment shader (impostors, splats).
   */
  int GetNumberOfDepthOnlyCasterShaders() const;
  int GetNumberOfOwnFragmentCasterShaders() const;
  ///@}

  /** Memory held by the shadow maps, in bytes (depth maps: 2 or 4 per texel). */
  size_t GetShadowMapMemory() const;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;

protected:
  /** Per-frame state: shadowed lights and their views (vtkShadowMapInternals.h). */
  struct Internals;

  vtkAbstractShadowMapPass();
  ~vtkAbstractShadowMapPass() override;

  /**
   * Fill `views` with the views of `light` for this frame. The base class
   * provides the focused uniform fits (see FitLightViewsUniform).
   */
  virtual void ComputeLightViews(Internals& internals, int lightIndex) = 0;

  /** The focused uniform fit for light lightIndex (directional, spot or cube). */
  void FitLightViewsUniform(Internals& internals, int lightIndex);

  /**
   * What a texel of the maps holds and how casters write it (see
   * shadowmaps::MapStorage). Default: one depth, written depth-only; the pass
   * stores it in 16 bits instead of 32 where every view allows
   * (shadowmaps::SixteenBitDepthSuffices).
   */
  virtual void GetMapStorage(shadowmaps::MapStorage& storage) const;

  /**
   * GLSL appended to the receivers' shadow code. It declares the sampler
   * `vtkShadowMaps` (a sampler2DArrayShadow for depth storage, a sampler2DArray
   * for value storage) and defines `float vtkShadowLookup(vec3 mapCoord, int
   * layer)`: the visibility in [0, 1] of a receiver at depth mapCoord.z seen at
   * texture coordinates mapCoord.xy of map layer `layer`. The filter settings
   * arrive as the VTK_SHADOW_* macros and uniforms of vtkShadowMapsReceiverFS.
   * Default: the PCF family over depth maps (vtkShadowMapsDepthLookupFS).
   */
  virtual std::string GetReceiverLookupCode() const;

  /**
   * Called after the casters were rendered into all layers (and mipmaps
   * built), before receivers sample them: blur or other map filtering goes
   * here. Returning false reports a GL failure: the frame renders unshadowed.
   */
  virtual bool PostProcessShadowMaps(vtkOpenGLRenderer* renderer, shadowmaps::TextureArray& maps);

  vtkRenderPass* DelegatePass = nullptr;
  int Resolution = 2048;
  int CasterFaces = BOTH_FACES;
  int Filter = PCF_2X2;
  int KernelSize = 3;
  double FilterRadius = 2.0;
  int PoissonSamples = 16;
  double ConstantBias = 4.0;
  double SlopeScaledBias = 2.0;
  double NormalOffset = 1.0;
  int AnalysisView = NO_ANALYSIS;
  int AnalysisLight = 0;

  int NumberOfShadowedLights = 0;
  int NumberOfShadowMapLayers = 0;
  int NumberOfShadowMapUpdates = 0;
  int NumberOfCasterDraws = 0;
  int NumberOfNonFiniteViews = 0;

  std::unique_ptr<Internals> Internal;

private:
  /** GL objects, helper passes and the state of the last map update. */
  struct Resources;
  std::unique_ptr<Resources> Resource;

  bool PrepareShadows(const vtkRenderState* s, vtkOpenGLRenderer* renderer);
  void CollectLights(vtkOpenGLRenderer* renderer);
  void CollectPropsAndBounds(vtkOpenGLRenderer* renderer);
  void DropLightsWithNonFiniteViews();
  bool UpdateShadowMaps(vtkOpenGLRenderer* renderer);
  bool RenderShadowMaps(vtkOpenGLRenderer* renderer);
  void RenderCastersIntoView(vtkOpenGLRenderer* renderer, const shadowmaps::LightView& view);
  void ApplyDepthBias(const shadowmaps::ShadowLight& light, const shadowmaps::LightView& view);
  void ClearLayer(vtkOpenGLRenderer* renderer);
  void StoreReceiverUniforms();
  void UpdateReceiverShaderKey(const vtkRenderState* s);
  void BindShadowTextures(vtkOpenGLRenderer* renderer);
  void UnbindShadowTextures(vtkOpenGLRenderer* renderer);
  void ReportGLFailure(const std::string& error);
  void RenderShadowMapView(vtkOpenGLRenderer* renderer);
  std::string AnalysisCode() const;

  vtkAbstractShadowMapPass(const vtkAbstractShadowMapPass&) = delete;
  void operator=(const vtkAbstractShadowMapPass&) = delete;
};

#endif
