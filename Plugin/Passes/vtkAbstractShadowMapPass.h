/**
 * @class   vtkAbstractShadowMapPass
 * @brief   The shadow-map pass: coordinates lights, casters, views, maps and receivers.
 *
 * A shadow-map pass renders the scene through a delegate (by default a
 * vtkRenderStepsPass, so opaque, translucent, volume and overlay geometry all
 * draw) after rendering the shadow maps of every shadowed light. It makes two
 * independent choices, each a strategy object:
 * - where a light's views go: a vtkShadowMapViews (SetViews): focused uniform
 *   maps, warped maps (vtkWarpedShadowMapViews) or cascades
 *   (vtkCascadedShadowMapViews);
 * - what a texel stores: a vtkShadowMapRepresentation (SetRepresentation): one
 *   depth with the PCF filters (vtkDepthShadowMapRepresentation), or values a
 *   subclass chooses.
 * The concrete passes are presets: vtkDepthShadowMapPass (depth maps, any
 * views), vtkWarpedShadowMapPass and vtkCascadedShadowMapPass. One line turns
 * shadows on:
 *
 * @code
 * renderer->SetPass(vtkNew< vtkWarpedShadowMapPass >());
 * @endcode
 *
 * Every frame: collect the shadowed lights and the casters; if anything the
 * maps depend on changed (camera, a light, a caster, a caster's input data, the
 * window size, a parameter of the pass or of its strategies), fit each light's
 * views and re-render the layers of one texture array (one per view) whose view
 * or casters changed, and let the representation post-process those; then bind
 * the maps and render the scene through the delegate, with the shadow test
 * injected into the receivers' shaders (shadowmaps::ReceiverShader). The fits
 * that follow the camera change in steps (stable cascades, focused maps snapped
 * to a grid), so a small camera move often re-renders no layer at all.
 *
 * Lights: every switched-on light that is not a headlight casts shadows:
 * directional lights (scene or camera lights), spot lights (cone angle below 90
 * degrees; cones wider than 60 degrees use six cube faces) and point lights
 * (positional with a cone of 90 degrees or more: six cube faces). At most
 * VTK_MAX_SHADOWED_LIGHTS lights are shadowed; further lights still light the
 * scene, unshadowed, and a warning says so. A light opts out with
 * light->GetInformation()->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
 * its ShadowAttenuation scales how dark its shadows are.
 *
 * Casters are drawn with the same programs as the scene, through a casters'
 * branch that writes depth only (shadowmaps::CasterShader): a moving camera
 * rebuilds no mapper's shader. Casters nearer the light than a view's near
 * plane are clamped onto it (depth clamping) rather than clipped, so they
 * still occlude what lies behind them.
 *
 * Receivers: the shadow test is injected into the fragment shaders of
 * vtkOpenGLPolyDataMapper and its subclasses, per light, scaling that light's
 * diffuse and specular (Phong) or radiance (PBR) terms. Unlit draws compile
 * unchanged and render without shadows. Props opt out through their property
 * keys: CASTS_SHADOWS() = 0 (not a caster), RECEIVES_SHADOWS() = 0;
 * annotations (axes, labels, widgets) opt in through the same keys.
 *
 * If the GL context cannot provide the maps (allocation or framebuffer
 * failure) the pass warns once and renders the frame without shadows.
 */
#ifndef vtkAbstractShadowMapPass_h
#define vtkAbstractShadowMapPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkShadowMapSetMacros.h" // For vtkSetFiniteClampMacro

#include <memory> // For std::unique_ptr
#include <string> // For the shader hooks

class vtkInformationDoubleKey;
class vtkInformationIntegerKey;
class vtkLight;
class vtkOpenGLRenderer;
class vtkProp;
class vtkRenderer;
class vtkRenderPass;
class vtkShadowMapExchange;
class vtkShadowMapRepresentation;
class vtkShadowMapViews;

#define VTK_MAX_SHADOWED_LIGHTS 8

class VTKRENDERINGSHADOWMAPS_EXPORT vtkAbstractShadowMapPass : public vtkOpenGLRenderPass
{
public:
  vtkTypeMacro(vtkAbstractShadowMapPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Set on a prop's property keys (or a light's information) with value 0 to
   * keep it from casting shadows, or 1 to make it cast. Absent means 1 for
   * lights and props but annotations: axes (vtkCubeAxesActor,
   * vtkPolarAxesActor, vtkAxesActor, ParaView's axes grids), labels and 3D
   * text (vtkTextActor3D, vtkBillboardTextActor3D, vtkAxisFollower), 2D
   * actors and widgets' representations neither cast nor receive unless
   * their keys say so.
   */
  static vtkInformationIntegerKey* CASTS_SHADOWS();

  /**
   * Set on a prop's property keys with value 0 to keep it from receiving
   * shadows, or 1 to make it receive. Absent means 1, but for annotations
   * (see CASTS_SHADOWS).
   */
  static vtkInformationIntegerKey* RECEIVES_SHADOWS();

  /**
   * Set on a light's information to give the light a size and its shadows
   * penumbrae: a sun's (directional light's) angular diameter in degrees (the
   * real sun's is about 0.53), a positional light's radius in world units
   * (spots and point lights are spheres). Absent or 0: a point source, hard
   * shadows. OSPRay's light node calls the same quantities RADIUS, in the same
   * units (ParaView's light Radius): where VTK's ray tracing module is loaded, a
   * light with an OSPRay radius and no LIGHT_SIZE takes that radius.
   */
  static vtkInformationDoubleKey* LIGHT_SIZE();

  /**
   * The light's LIGHT_SIZE as the passes use it: 0 when absent, not finite or
   * negative; a sun's clamped to 30 degrees (wider "suns" are lamps: give them
   * a position). Sets `clamped` (when given) to whether the stored value was
   * changed.
   */
  static double GetLightSize(vtkLight* light, bool* clamped = nullptr);

  /**
   * What a translucent caster of `color` (RGB in [0, 1]) and `opacity` a
   * lets through of the light that crosses it, per channel c:
   * (1 - a) (1 - a + a c). A white caster lets 1 - a through, what VTK's
   * blending shows of what lies behind it; a coloured one also filters that
   * light toward its colour in proportion to its opacity; an opaque one lets
   * nothing through. Several crossings multiply, in any order. Out-of-range
   * values are clamped. The passes' transmittance maps and the benchmark's
   * ray-traced truth use this model (docs/TRANSLUCENT.md).
   */
  static void GetTransmittance(const double color[3], double opacity, double transmitted[3]);

  ///@{
  /**
   * Whether lights with a LIGHT_SIZE get contact-hardening soft shadows
   * (blocker search, penumbra estimate, a filter of the penumbra's width, in
   * world units). Off: every light's shadow is hard, filtered by the
   * representation's own filter. Default on.
   */
  vtkSetMacro(SoftShadows, vtkTypeBool);
  vtkGetMacro(SoftShadows, vtkTypeBool);
  vtkBooleanMacro(SoftShadows, vtkTypeBool);
  ///@}

  /**
   * The pass that renders the scene with shadows applied. Defaults to a
   * vtkRenderStepsPass. Setting nullptr restores the default.
   */
  virtual void SetDelegatePass(vtkRenderPass* delegate);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);

  ///@{
  /**
   * Where each light's views go. A pass's preset keeps its own views object;
   * setting nullptr restores it. Its parameters' changes re-render the maps.
   */
  void SetViews(vtkShadowMapViews* views);
  vtkShadowMapViews* GetViews();

  /**
   * The views of one light, instead of the pass's (GetViews()): a sun in
   * cascades and a point light in Kozlov's cube in the same frame. Each
   * light's receivers get the code of its own views, so that mixing them
   * builds no shader while the camera moves. nullptr gives the light the
   * pass's views again. The pass does not keep the light alive; a light
   * deleted is forgotten. Changes of these views' parameters re-render the
   * maps. The pass's own parameters that forward to its views (a preset's
   * NumberOfCascades or WarpMode, InteractiveTexelRatio, ParaView's views
   * property) set the pass's views only: a light's own keep theirs. One views
   * object may serve several lights and passes; what it reports of its last
   * fit (a cascades' splits) is then the last light's. In parallel rendering
   * every process must give a light the same views.
   */
  void SetLightViews(vtkLight* light, vtkShadowMapViews* views);
  /** The views `light` gets: its own (SetLightViews), else the pass's. */
  vtkShadowMapViews* GetLightViews(vtkLight* light);
  ///@}

  ///@{
  /**
   * What a texel of the maps stores and how receivers read it. A pass's preset
   * keeps its own representation; setting nullptr restores it. Its parameters'
   * changes re-render the maps and rebuild the receivers' shaders as needed.
   */
  void SetRepresentation(vtkShadowMapRepresentation* representation);
  vtkShadowMapRepresentation* GetRepresentation();
  ///@}

  ///@{
  /**
   * The representation of one light, instead of the pass's
   * (GetRepresentation()): a sun in dual-depth maps and a lamp in depth maps
   * in the same frame. The lights of each representation have maps of their
   * own (one texture array per representation in use), and the receivers'
   * shaders hold every representation's code, under names of its own
   * (shadowmaps::ShaderGroup), so that no shader is built while the camera
   * moves. nullptr gives the light the pass's representation again. The pass
   * does not keep the light alive; a light deleted is forgotten. One
   * representation object may serve several lights (they then share its
   * maps) and passes. In parallel rendering every process must give a light
   * the same representation.
   */
  void SetLightRepresentation(vtkLight* light, vtkShadowMapRepresentation* representation);
  /** The representation `light` gets: its own (SetLightRepresentation), else the pass's. */
  vtkShadowMapRepresentation* GetLightRepresentation(vtkLight* light);
  /**
   * How many representations the shadowed lights of the last frame (the last
   * renderer's) used, each with a texture array of its own.
   */
  int GetNumberOfRepresentationsInUse();
  ///@}

  ///@{
  /**
   * Parallel rendering: the collectives with which the processes that each
   * render a piece of the data combine their maps into the nearest surfaces
   * over all of them (vtkShadowMapExchange): depth maps and front-and-back-face
   * maps texel by texel, peeled two-surface maps as the nearest two, maps of
   * values of the light depth (moments) through the nearest light depth, from
   * which each process stores its values. With an exchange, two-surface maps
   * whose representation leaves the layer method to the pass (AUTO) are
   * always peeled (every process must make its maps alike), and the casters
   * of combined light-depth maps are not multisampled (the nearest light
   * depth is combined, not samples). Values that are no light depth are not
   * combined (a warning says so). nullptr (default): one process.
   */
  void SetExchange(vtkShadowMapExchange* exchange);
  vtkGetObjectMacro(Exchange, vtkShadowMapExchange);
  ///@}

  ///@{
  /**
   * The bounds the views are fitted to, instead of the visible props': the
   * global bounds of a parallel renderer, so that every process fits the same
   * views. Used while UseSceneBounds is on (default off). Without an
   * exchange, the fits that follow props (tight cascades, warps) then see
   * this one box; with one, they see every process's props' boxes
   * (vtkShadowMapExchange::AllBoxes), whose union is the scene's bounds when
   * none are given. Bounds with a value that is not finite are refused.
   */
  virtual void SetSceneBounds(
    double xMin, double xMax, double yMin, double yMax, double zMin, double zMax);
  virtual void SetSceneBounds(const double bounds[6]);
  vtkGetVector6Macro(SceneBounds, double);
  vtkSetMacro(UseSceneBounds, bool);
  vtkGetMacro(UseSceneBounds, bool);
  vtkBooleanMacro(UseSceneBounds, bool);
  ///@}

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
  void SetCasterFacesToFront() { this->SetCasterFaces(FRONT_FACES); }
  void SetCasterFacesToBack() { this->SetCasterFaces(BACK_FACES); }
  void SetCasterFacesToBoth() { this->SetCasterFaces(BOTH_FACES); }
  ///@}

  ///@{
  /**
   * Whether a view's casters are culled to those whose shadows can reach what
   * the camera sees (the casters' footprints in the view against the focus
   * body's: Plugin/Math/ShadowMapCasterReach.h); the view's frustum culls
   * either way. A layer re-rendered while the user drags takes every caster in
   * its view (but for mipmapped maps), so that casters the turning camera
   * brings into reach do not re-render it. Default on.
   */
  vtkSetMacro(ShadowReachCulling, bool);
  vtkGetMacro(ShadowReachCulling, bool);
  vtkBooleanMacro(ShadowReachCulling, bool);
  ///@}

  ///@{
  /**
   * A render is interactive when its render window's DesiredUpdateRate is at
   * least this (as for vtkSmartVolumeMapper): VTK's interactor styles set the
   * interactor's DesiredUpdateRate (15) while the user drags and its
   * StillUpdateRate (0.0001) for the render that ends the drag; ParaView sets
   * 5 and 0.002. In interactive renders, views that follow the camera (warped
   * maps, directional lights' cascades) may keep a light's last views while
   * they still serve, so that its maps are re-rendered only every few frames
   * (InteractiveTexelRatio); still renders always fit anew. VTK_DOUBLE_MAX
   * makes every render a still one, 0 every render an
   * interactive one (whose images then depend on the camera's path). With an
   * exchange, a render is interactive only if it is on every process.
   * Clamped to [0, VTK_DOUBLE_MAX]; default 1.
   */
  vtkSetFiniteClampMacro(InteractiveUpdateRate, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(InteractiveUpdateRate, double);
  ///@}

  ///@{
  /**
   * Whether still renders (a scripted camera path, a movie, a time series
   * played) keep a light's views while they still serve the frame, under the
   * rule interactive renders follow (InteractiveTexelRatio), with maps of the
   * full Resolution: a camera path then re-renders warped and cascaded maps
   * only every few frames. Off by default: every still render fits its views
   * anew, so that a frame does not depend on the camera's path and image
   * tests repeat exactly. Every process of a parallel renderer must set it
   * alike.
   */
  vtkSetMacro(AnimationKeepsViews, bool);
  vtkGetMacro(AnimationKeepsViews, bool);
  vtkBooleanMacro(AnimationKeepsViews, bool);
  ///@}

  ///@{
  /**
   * InteractiveTexelRatio (vtkShadowMapViews) of the views the pass uses now
   * (GetViews(); a views object set later keeps its own), [1, 16], default
   * 1.5: how much coarser a view kept while the user drags the camera may get
   * (1: none kept).
   */
  void SetInteractiveTexelRatio(double ratio);
  double GetInteractiveTexelRatio();
  ///@}

  ///@{
  /**
   * The share of the maps' resolution (Resolution, or the GL's largest) at
   * which maps are drawn in interactive renders (InteractiveUpdateRate) that
   * must draw any of them: the drag then draws all its maps at this share,
   * and the first still render draws them at the full resolution again. The
   * maps a still render left serve a drag until a layer must be drawn. A map's
   * cost is its texels on a fill-bound GPU or a software rasteriser: 0.5 draws
   * a quarter of them. Not below 64 texels. Clamped to [0.0625, 1]; default 1
   * (drags draw full maps), vtkAutomaticShadowMapPass's 0.5.
   */
  vtkSetFiniteClampMacro(InteractiveResolutionScale, double, 0.0625, 1.0);
  vtkGetMacro(InteractiveResolutionScale, double);
  ///@}

  ///@{
  /**
   * Receiver offset along its normal, in shadow-map texels (scaled by the
   * world-space size of a texel at the receiver). Clamped to [0, 10]; default 1.
   */
  vtkSetFiniteClampMacro(NormalOffset, double, 0.0, 10.0);
  vtkGetMacro(NormalOffset, double);
  ///@}

  enum AnalysisViewType
  {
    NO_ANALYSIS = 0,
    SHADOW_FACTOR = 1,
    TEXEL_DENSITY = 2,
    SHADOW_MAP = 3,
    PARTITION = 4,
    CHOSEN_VIEWS = 5
  };

  ///@{
  /**
   * Analysis view of light AnalysisLight (an index among the shadowed lights,
   * in the renderer's order): receivers show instead of their shading
   * - SHADOW_FACTOR: the light's visibility, white lit, black shadowed (per
   *   colour channel where translucent casters tint it);
   * - TEXEL_DENSITY: a heat map of how many screen pixels one map texel
   *   covers (log scale): blue dense, green 1.5 pixels, orange to red
   *   undersampled (red channel 255 exactly when over 1.5 pixels);
   * - PARTITION: a colour per map view (cascade, cube face) that shaded the
   *   pixel, darker in shadow;
   * - CHOSEN_VIEWS: a colour per kind of views the light got (what the
   *   automatic pass chose for it): grey uniform map, cyan uniform cube
   *   faces, green LiSPSM, olive GMNPR, yellow TSM, red PSM, violet
   *   Kozlov's post-perspective cube, blue cascades, orange tiles
   *   (shadowmaps::ViewsKindColor); its odd maps (cascades, faces) a quarter
   *   darker, and darker in shadow.
   * SHADOW_MAP replaces the frame by the light's maps, tiled, depth as grey.
   * Clamped; default NO_ANALYSIS.
   */
  vtkSetClampMacro(AnalysisView, int, NO_ANALYSIS, CHOSEN_VIEWS);
  vtkGetMacro(AnalysisView, int);
  void SetAnalysisViewToNone() { this->SetAnalysisView(NO_ANALYSIS); }
  void SetAnalysisViewToShadowFactor() { this->SetAnalysisView(SHADOW_FACTOR); }
  void SetAnalysisViewToTexelDensity() { this->SetAnalysisView(TEXEL_DENSITY); }
  void SetAnalysisViewToShadowMap() { this->SetAnalysisView(SHADOW_MAP); }
  void SetAnalysisViewToPartition() { this->SetAnalysisView(PARTITION); }
  void SetAnalysisViewToChosenViews() { this->SetAnalysisView(CHOSEN_VIEWS); }
  vtkSetClampMacro(AnalysisLight, int, 0, VTK_MAX_SHADOWED_LIGHTS - 1);
  vtkGetMacro(AnalysisLight, int);
  ///@}

  /** Number of lights that received shadow maps in the last frame. */
  int GetNumberOfShadowedLights() const;

  /** Number of map layers (light views) in use in the last frame. */
  int GetNumberOfShadowMapLayers() const;

  /**
   * Width and height in texels of the map layers the last frame read:
   * Resolution (at most the GL's largest texture), or its
   * InteractiveResolutionScale share in a drag that drew them; the automatic
   * pass's lights in cascades halve it. 0 before any map.
   */
  int GetShadowMapResolution() const;

  /**
   * Light views of the last map update whose matrices were not finite (a
   * degenerate scene or camera). Their lights cast no shadow in that frame, and
   * a warning says so once until every view is finite again. 0 in a healthy frame.
   */
  int GetNumberOfNonFiniteViews() const;

  /** How many times the shadow maps were (re-)rendered since creation. */
  int GetNumberOfShadowMapUpdates() const;

  /**
   * Caster draws (prop renders into maps, transmittance maps included) in the
   * last frame that rendered map layers.
   */
  int GetNumberOfCasterDraws() const;

  /**
   * Map layers rendered in the last frame: 0 when nothing the maps depend on
   * changed; after a camera move, only the views whose matrices changed, that
   * now need a caster they did not draw, or one of whose casters changed (a
   * stable cascade that did not move keeps its layer).
   */
  int GetNumberOfRenderedLayers() const;

  /**
   * Where the last frame's shadow work went: milliseconds of the thread that
   * renders in each step (FrameStepType), in the order they run. A GPU driver
   * defers most GL work, which the drawing then leaves out; llvmpipe shades the
   * casters' vertices on this thread. 0 for a step out of range.
   */
  enum FrameStepType
  {
    READING_STEP = 0, ///< lights, casters and camera collected
    FITTING_STEP,     ///< the lights' views fitted
    STORAGE_STEP,     ///< the storage chosen (casters' closedness) and the maps reserved
    SHADERS_STEP,     ///< the receivers' shadow code made
    DRAWING_STEP,     ///< the changed layers drawn
    FINISHING_STEP,   ///< the maps combined across processes and post-processed
    NUMBER_OF_FRAME_STEPS
  };
  double GetFrameStepMilliseconds(int step) const;
  /** The name of a FrameStepType ("reading", ...), "" out of range. */
  static const char* GetFrameStepName(int step);

  /**
   * Shader sources the mappers generated with this pass so far. Casters and
   * receivers share one program per mapper primitive (see
   * Shaders/vtkShadowMapsCasterFS.glsl), so an orbiting camera, with the scene,
   * the lights and the parameters unchanged, adds none after its first frame.
   */
  vtkGetMacro(NumberOfShaderBuilds, int);

  ///@{
  /**
   * Of those, the ones whose casters' branch draws depth only (most), and the
   * ones whose branch runs after the mapper's own fragment code (impostors,
   * point splats, which cut their own silhouettes).
   */
  vtkGetMacro(NumberOfDepthOnlyCasterShaders, int);
  vtkGetMacro(NumberOfOwnFragmentCasterShaders, int);
  ///@}

  /**
   * Lights in receivers' shaders built so far that the mapper lit in code the
   * pass could not patch (a VTK version whose lighting code it does not know):
   * those lights cast no shadow on those props, and the pass warns once. 0 on
   * every VTK this module is tested with.
   */
  vtkGetMacro(NumberOfUnpatchedReceiverLights, int);

  /**
   * Caster passes per map layer in the last map update: 2 when the
   * representation stores two surfaces' depths made by depth peeling (chosen,
   * or picked by SecondDepthMethod::Auto because a caster is open), else 1;
   * one more while translucent casters are drawn into transmittance maps
   * (docs/TRANSLUCENT.md).
   */
  int GetNumberOfCasterPassesPerLayer() const;

  /**
   * Memory held by the shadow maps, in bytes (depth maps: 2 or 4 per texel;
   * transmittance maps, while a caster is translucent: 16), the maps of a
   * drag's coarser resolution kept beside them included
   * (InteractiveResolutionScale).
   */
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

  /** Includes the views' and the representation's modification times. */
  vtkMTimeType GetMTime() override;

protected:
  /**
   * A pass of the given default views and representation (the preset that
   * SetViews(nullptr) and SetRepresentation(nullptr) restore).
   */
  vtkAbstractShadowMapPass(
    vtkShadowMapViews* defaultViews, vtkShadowMapRepresentation* defaultRepresentation);
  ~vtkAbstractShadowMapPass() override;

  /**
   * Called at the start of each frame that may have shadows (not while a
   * selector picks), before the lights' views are fitted: a subclass may
   * choose each light's views (SetLightViews) from the frame. Does nothing here.
   */
  virtual void ChooseForFrame(vtkOpenGLRenderer* renderer);

  /** The width and height of the maps' layers this frame: Resolution here. */
  virtual int GetLayerResolution();

  vtkRenderPass* DelegatePass = nullptr;
  vtkShadowMapExchange* Exchange = nullptr;
  double SceneBounds[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };
  bool UseSceneBounds = false;
  vtkTypeBool SoftShadows = 1;
  int Resolution = 2048;
  int CasterFaces = BOTH_FACES;
  double NormalOffset = 1.0;
  bool ShadowReachCulling = true;
  double InteractiveUpdateRate = 1.0;
  bool AnimationKeepsViews = false;
  double InteractiveResolutionScale = 1.0;
  int AnalysisView = NO_ANALYSIS;
  int AnalysisLight = 0;

  int NumberOfShaderBuilds = 0;
  int NumberOfDepthOnlyCasterShaders = 0;
  int NumberOfOwnFragmentCasterShaders = 0;
  int NumberOfUnpatchedReceiverLights = 0;

private:
  /**
   * The strategies, the scene's delegates and what the pass's frames left
   * (shadowmaps::FrameUpdate renders each renderer's maps).
   */
  struct Internals;
  std::unique_ptr<Internals> Internal;

  /** A hardware selector's frame (picking): the props drawn as the renderer draws them without a pass. */
  void RenderForSelection(vtkOpenGLRenderer* renderer);
  /** The frame's maps (shadowmaps::FrameUpdate): whether the frame has shadows. */
  bool PrepareShadows(vtkOpenGLRenderer* renderer, const vtkRenderState* s);
  /** Warns what the frame's update found to warn about. */
  void WarnAboutUpdate();
  /** Records the window `renderer` draws in and that it draws through the pass. */
  void UseContextOf(vtkOpenGLRenderer* renderer);
  /** Makes the maps of `renderer` (and its camera's eye) the current ones. */
  void SelectRendererMaps(vtkOpenGLRenderer* renderer);
  /** Releases the maps of a renderer that no longer draws through the pass. */
  void ReleaseMapsOf(vtkRenderer* renderer);
  /**
   * Releases the GL objects held in the recorded window's context, while it can
   * still be made current, and forgets that window.
   */
  void ForgetContext();
  void JoinRenderPasses(vtkProp* const* props, int count);
  void LeaveRenderPasses();
  /**
   * Leaves the props' render passes but those another renderer of the window
   * draws too, and frees the texture units unless such props stay joined.
   */
  void EndFrame(vtkOpenGLRenderer* renderer);
  void ReleaseTextureUnits(vtkOpenGLRenderer* renderer);
  void RenderShadowMapView(vtkOpenGLRenderer* renderer);

  vtkAbstractShadowMapPass(const vtkAbstractShadowMapPass&) = delete;
  void operator=(const vtkAbstractShadowMapPass&) = delete;
};

#endif
