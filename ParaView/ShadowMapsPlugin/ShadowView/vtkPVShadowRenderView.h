/**
 * @class   vtkPVShadowRenderView
 * @brief   ParaView's render view with rasterised shadows.
 *
 * A vtkPVRenderView whose geometry is rendered through one of the module's
 * shadow passes, put where ParaView renders geometry
 * (vtkPVSynchronizedRenderer::SetRenderPass), so that with IceT each rank
 * shades its own geometry, and the image passes (FXAA, tone mapping) still
 * follow. The passes render the scene through vtkPVDefaultPass, so SSAO,
 * hidden-line removal and the translucent and volume steps of the renderer
 * keep working.
 *
 * Two independent choices, as in the module: where each light's views go
 * (ShadowViews: chosen per light by vtkAutomaticShadowMapPass, the default; a
 * uniform or warped map; or cascades) and what a texel stores (ShadowStorage:
 * two depths without bias, the default; depth with PCF; or filterable
 * moments). Lights: the light kit's key light casts shadows (KeyLightShadows),
 * its fill, back and head lights do not; every light added to the view casts.
 *
 * Per representation, Casts Shadows and Receives Shadows (properties the plugin
 * adds to the surface representations, vtkSIShadowRoleProperty) give each
 * representation's prop the module's keys before every render.
 *
 * On several ranks (pvbatch, pvserver under MPI) every rank fits its views to
 * the view's global geometry bounds, renders its own casters into its maps, and
 * the maps are combined into the nearest surfaces over the ranks
 * (vtkPVShadowMapExchange): depths, the two nearest surfaces of dual-depth
 * maps, the nearest light depth of moment maps (each rank then stores, blurs
 * and mipmaps its moments), so a caster on one rank shadows receivers on
 * another; ranks without geometry still render and take part.
 */
#ifndef vtkPVShadowRenderView_h
#define vtkPVShadowRenderView_h

#include "vtkPVRenderView.h"
#include "vtkParaViewShadowViewModule.h" // For export macro

#include <array> // For AllPasses
#include <limits> // For RenderedViewTime

class vtkAbstractShadowMapPass;
class vtkAutomaticShadowMapPass;
class vtkCascadedShadowMapViews;
class vtkPVDefaultPass;
class vtkDepthShadowMapPass;
class vtkInformationIntegerKey;
class vtkPVShadowMapExchange;
class vtkVarianceShadowMapPass;
class vtkWarpedShadowMapViews;

class VTKPARAVIEWSHADOWVIEW_EXPORT vtkPVShadowRenderView : public vtkPVRenderView
{
public:
  static vtkPVShadowRenderView* New();
  vtkTypeMacro(vtkPVShadowRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ShadowViewsType
  {
    UNIFORM = 0,
    LISPSM = 1,
    TSM = 2,
    PSM = 3,
    GMNPR = 4,
    CASCADES = 5,
    AUTOMATIC = 6
  };

  ///@{
  /**
   * Where each light's views go: chosen per light from its situation
   * (AUTOMATIC, vtkAutomaticShadowMapPass, default), a focused uniform map, a
   * warped map, or cascades.
   */
  void SetShadowViews(int views);
  vtkGetMacro(ShadowViews, int);
  ///@}

  enum ShadowStorageType
  {
    DEPTH = 0,
    DUAL_DEPTH = 1,
    MOMENTS = 2
  };

  ///@{
  /**
   * What a texel stores: depth with 2 x 2 PCF, two depths and no bias
   * (vtkDualDepthShadowMapPass, default), or EVSM4 moments
   * (vtkVarianceShadowMapPass). Under AUTOMATIC views the automatic pass
   * stores what this says (its own dual-depth maps, or the other passes'
   * representations).
   */
  void SetShadowStorage(int storage);
  vtkGetMacro(ShadowStorage, int);
  ///@}

  ///@{
  /** Map width and height in texels, [64, 16384], default 2048 (each cascade is one such map). */
  void SetShadowMapResolution(int resolution);
  vtkGetMacro(ShadowMapResolution, int);
  ///@}

  ///@{
  /** Cascades when ShadowViews is CASCADES, [1, 8], default 4. */
  void SetNumberOfCascades(int count);
  int GetNumberOfCascades();
  ///@}

  ///@{
  /** vtkAbstractShadowMapPass's AnalysisView (0 none, 1 shadow factor, 2 texel density, 3 map, 4 partition, 5 chosen views). */
  void SetShadowAnalysisView(int view);
  vtkGetMacro(ShadowAnalysisView, int);
  ///@}

  ///@{
  /**
   * The filter of depth and dual-depth maps (vtkDepthShadowMapPass::FilterType:
   * 0 hard, 1 2 x 2 PCF (default), 2 N x N PCF, 3 Poisson) and the Poisson
   * disc's radius in texels ([0.5, 16], default 2). Moment maps are filtered
   * by their blur (MomentsBlurRadius).
   */
  void SetShadowFilter(int filter);
  int GetShadowFilter();
  void SetShadowFilterRadius(double texels);
  double GetShadowFilterRadius();
  ///@}

  ///@{
  /**
   * The depth maps' bias: constant (polygon-offset units, [0, 10000], default
   * 4) and slope-scaled ([0, 100], default 2). Dual-depth and moment maps need none.
   */
  void SetShadowConstantBias(double bias);
  double GetShadowConstantBias();
  void SetShadowSlopeScaledBias(double bias);
  double GetShadowSlopeScaledBias();
  ///@}

  ///@{
  /** The moment maps' Gaussian blur, texels of a light's finest view, [0, 16], default 1. */
  void SetMomentsBlurRadius(double texels);
  double GetMomentsBlurRadius();
  ///@}

  ///@{
  /**
   * Sizes for soft shadows (vtkAbstractShadowMapPass::LIGHT_SIZE) of the
   * view's lights: SunDiameter, directional lights' angular diameter in
   * degrees, [0, 30]; LampRadius, positional lights' radius in world units,
   * [0, inf). 0 (default): hard shadows. A light with a Radius of its own
   * (vtkOSPRayLightNode's, which the Light Inspector sets where ParaView has
   * ray tracing) keeps it, and so does one a script gave a LIGHT_SIZE.
   */
  void SetSunDiameter(double degrees);
  vtkGetMacro(SunDiameter, double);
  void SetLampRadius(double radius);
  vtkGetMacro(LampRadius, double);
  ///@}

  ///@{
  /** Whether the light kit's key light casts shadows (default on). */
  void SetKeyLightShadows(bool on);
  vtkGetMacro(KeyLightShadows, bool);
  ///@}

  /** The pass that renders this view's geometry now. */
  vtkAbstractShadowMapPass* GetShadowPass();

  /** Lights the last frame rendered shadows of (an information property). */
  int GetNumberOfShadowedLights();

  /**
   * Whether the last frame was an animation's: a still render from the first
   * at a new view time (ParaView's animation gives each frame one) until the
   * next interactive render. Such frames keep warped and cascaded views as a
   * drag does (vtkAbstractShadowMapPass::AnimationKeepsViews); the still
   * render that ends a drag fits anew. An information property.
   */
  bool GetAnimationFrame();

  ///@{
  /**
   * What combining the maps across ranks has cost this rank so far: bytes it
   * all-reduced, and seconds in those reductions (waiting for the other ranks
   * included). Information properties.
   */
  double GetBytesCombined();
  double GetSecondsCombining();
  ///@}

protected:
  vtkPVShadowRenderView();
  ~vtkPVShadowRenderView() override;

  /** Every rank renders, even one with no geometry: the maps' combination needs all. */
  void Update() override;
  /**
   * Gives each representation's prop its Casts/Receives Shadows values, and
   * on several ranks fits the pass's views to the global geometry bounds.
   */
  void Render(bool interactive, bool skip_rendering) override;

private:
  vtkPVShadowRenderView(const vtkPVShadowRenderView&) = delete;
  void operator=(const vtkPVShadowRenderView&) = delete;

  /** Puts the pass for the current choices in the geometry slot. */
  void UsePass();
  /** The storage passes and the automatic pass. */
  std::array<vtkAbstractShadowMapPass*, 4> AllPasses();
  /** Marks which of the light kit's lights cast shadows. */
  void MarkLightKitLights();
  /** Frees a pass's GL objects, if the window ever rendered. */
  void ReleasePass(vtkAbstractShadowMapPass* pass);
  /** The passes whose maps hold depths (depth and dual depth), which share their filters and bias. */
  vtkDepthShadowMapPass* DepthPass(int storage);
  vtkVarianceShadowMapPass* MomentsPass();
  /** Several ranks render pieces of this view's data through one camera. */
  bool CombinesAcrossRanks();
  /**
   * Copies the shadow roles vtkSIShadowRoleProperty keeps on each
   * representation to the prop its active surface representation renders.
   */
  void ApplyShadowRoles();
  /**
   * Gives the renderer's lights the view's sizes (SunDiameter, LampRadius),
   * but those with a LIGHT_SIZE the view did not set, or a Radius of their own.
   */
  void ApplyLightSizes();
  /** Marks the lights whose LIGHT_SIZE the view set. */
  static vtkInformationIntegerKey* SIZED_BY_VIEW();

  double SunDiameter = 0.0;
  double LampRadius = 0.0;
  int ShadowViews = AUTOMATIC;
  int ShadowStorage = DUAL_DEPTH;
  int ShadowMapResolution = 2048;
  int ShadowAnalysisView = 0;
  bool KeyLightShadows = true;
  bool AnimationFrame = false;
  /** The view time of the last render, NaN before the first. */
  double RenderedViewTime = std::numeric_limits<double>::quiet_NaN();

  /** One pass per ShadowStorage, in its order: depth, dual depth, moments. */
  vtkAbstractShadowMapPass* Passes[3];
  /** The pass of AUTOMATIC views, with the representation ShadowStorage says. */
  vtkAutomaticShadowMapPass* AutomaticPass;
  vtkWarpedShadowMapViews* WarpedViews;
  vtkCascadedShadowMapViews* CascadedViews;
  vtkPVDefaultPass* ScenePass;
  vtkPVShadowMapExchange* Exchange;
};

#endif
