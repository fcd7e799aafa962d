/**
 * @class   vtkWarpedShadowMapViews
 * @brief   Warped shadow-map views: focused uniform, PSM, LiSPSM, TSM and GMNPR.
 *
 * WarpMode chooses how a directional light's map is parameterised:
 * - UNIFORM (default): an orthographic map fitted to the focus body B;
 * - LISPSM (Wimmer et al.; thesis 000, survey 003 §4.2): a perspective warp in
 *   light space whose axis is the view direction projected perpendicular to the
 *   light, with n = (z_n + sqrt(z_f z_n)) / sin(gamma), optionally Lloyd-style
 *   faster falloff, or a user-set free parameter n;
 * - GMNPR (Zhang et al., seed 002 Eq. 8): the same warp with the
 *   direction-adaptive lambda that equalises the aliasing at the near and far
 *   planes;
 * - PSM (Stamminger and Drettakis, with Kozlov's fixes, seed 001): the map is
 *   rendered in the camera's post-perspective space, focused on the receivers
 *   there (unit-cube clipping); a light behind the viewer uses the inverse
 *   projection; PSMSlideBack moves the virtual camera back to trade near for
 *   far quality (automatic by default). Bias is the normal offset scaled by the world-space texel size
 *   at the receiver, taken from the map's local gradient;
 * - TSM (Martin and Tan; thesis 000): the trapezoid around the focus body's
 *   light-space hull mapped to the square, with the point TSMFocusDistance
 *   beyond the near plane on the TSMFocusFraction line; depth stays linear in
 *   light space, so one bias serves the whole map.
 * As the view direction approaches the light direction every mode fades
 * continuously into the uniform map (PSM over 2 to 20 degrees, the others by
 * 12 or 15); parallel-projection cameras get the uniform map. Spot lights are
 * warped by LISPSM, GMNPR and TSM inside their own post-perspective space, where
 * they are directional (the angle, depths and half angle that choose n are
 * measured in the world at B; a spot's TSM map stores z / w, so its depth is not
 * linear), and by PSM as a point light in the camera's post-perspective space.
 * In PSM mode, point lights and spots wider than one map holds get Kozlov's
 * cube map in post-perspective space (PSMCubeMap, ShadowMapPerspectiveCube.h):
 * up to six faces on the sides of the receivers' box there, looking away from
 * the light's post-perspective position, so that texels follow screen area
 * wherever the light is; the other modes give them the uniform cube faces.
 *
 * UNIFORM is vtkUniformShadowMapViews' fit. The views of
 * vtkWarpedShadowMapPass; any pass takes them:
 *
 * @code
 * vtkNew<vtkWarpedShadowMapViews> views;
 * views->SetWarpModeToLiSPSM();
 * pass->SetViews(views);
 * @endcode
 */
#ifndef vtkWarpedShadowMapViews_h
#define vtkWarpedShadowMapViews_h

#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkShadowMapSetMacros.h" // For vtkSetFiniteClampMacro
#include "vtkShadowMapViews.h"

#include <vector> // For FitCubeFor

namespace shadowmaps
{
enum class DirectionalWarp;
struct LightView;
struct PerspectiveCube;
struct Plane;
struct WarpOptions;
}

class VTKRENDERINGSHADOWMAPS_EXPORT vtkWarpedShadowMapViews : public vtkShadowMapViews
{
public:
  static vtkWarpedShadowMapViews* New();
  vtkTypeMacro(vtkWarpedShadowMapViews, vtkShadowMapViews);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum WarpModeType
  {
    UNIFORM = 0,
    LISPSM = 1,
    GMNPR = 2,
    PSM = 3,
    TSM = 4
  };

  ///@{
  /** How directional and spot maps are warped. Clamped to [UNIFORM, TSM]; default UNIFORM. */
  vtkSetClampMacro(WarpMode, int, UNIFORM, TSM);
  vtkGetMacro(WarpMode, int);
  void SetWarpModeToUniform() { this->SetWarpMode(UNIFORM); }
  void SetWarpModeToLiSPSM() { this->SetWarpMode(LISPSM); }
  void SetWarpModeToGMNPR() { this->SetWarpMode(GMNPR); }
  void SetWarpModeToPSM() { this->SetWarpMode(PSM); }
  void SetWarpModeToTSM() { this->SetWarpMode(TSM); }
  ///@}

  ///@{
  /**
   * LiSPSM's free parameter n (distance of the warp's apex before the focus
   * body, world units). 0 (default) chooses n_opt automatically; clamped to
   * [0, 1e30].
   */
  vtkSetFiniteClampMacro(LiSPSMFreeParameter, double, 0.0, 1e30);
  vtkGetMacro(LiSPSMFreeParameter, double);
  ///@}

  ///@{
  /**
   * LiSPSM and GMNPR: the fraction of the focus body's far view depth below
   * which the near depth their n is chosen from is not taken (a pseudo near
   * plane): a camera's near plane a hair in front of it would otherwise spend
   * the map on the empty space there. Default 0.003 (measured, docs/WARPS.md);
   * 0 takes the near depth as it is. Clamped to [0, 1].
   */
  vtkSetFiniteClampMacro(PseudoNearFraction, double, 0.0, 1.0);
  vtkGetMacro(PseudoNearFraction, double);
  ///@}

  ///@{
  /** LiSPSM: fall off faster than 1/sin(gamma) below the frustum's half angle. Default off. */
  vtkSetMacro(LloydFalloff, bool);
  vtkGetMacro(LloydFalloff, bool);
  vtkBooleanMacro(LloydFalloff, bool);
  ///@}

  ///@{
  /**
   * PSM: Kozlov's virtual slide-back, how far (world units) the virtual camera
   * is moved back behind the real one; more trades near for far quality.
   * Negative (default -1): automatic, sqrt(z_n z_f) of the visible depth range,
   * which puts the virtual near plane at LiSPSM's n_opt = z_n + sqrt(z_n z_f)
   * where near and far aliasing balance. 0: the original PSM, which gives most
   * of the map to the first few depth units. Clamped to [-1, 1e30].
   */
  vtkSetFiniteClampMacro(PSMSlideBack, double, -1.0, 1e30);
  vtkGetMacro(PSMSlideBack, double);
  ///@}

  enum PSMCubeMapType
  {
    PSM_CUBE_AUTOMATIC = 0,
    PSM_CUBE_ALWAYS = 1,
    PSM_CUBE_NEVER = 2
  };

  ///@{
  /**
   * PSM: which lights get Kozlov's post-perspective cube map instead of one
   * map. AUTOMATIC (default): point lights and spots wider than one map holds
   * (suns and narrow spots keep the single focused PSM); ALWAYS: every light;
   * NEVER: none (point lights and wide spots get the uniform cube faces).
   * The cube's virtual camera slides back by PSMSlideBack as the single
   * map's does. docs/WARPS.md compares them. Clamped to [AUTOMATIC, NEVER].
   */
  vtkSetClampMacro(PSMCubeMap, int, PSM_CUBE_AUTOMATIC, PSM_CUBE_NEVER);
  vtkGetMacro(PSMCubeMap, int);
  void SetPSMCubeMapToAutomatic() { this->SetPSMCubeMap(PSM_CUBE_AUTOMATIC); }
  void SetPSMCubeMapToAlways() { this->SetPSMCubeMap(PSM_CUBE_ALWAYS); }
  void SetPSMCubeMapToNever() { this->SetPSMCubeMap(PSM_CUBE_NEVER); }
  ///@}

  ///@{
  /**
   * TSM: the focus distance delta beyond the camera's near plane (world units)
   * whose shadows get TSMFocusFraction of the map. 0 (default): a fifth of the
   * depth the focus body reaches. Clamped to [0, 1e30].
   */
  vtkSetFiniteClampMacro(TSMFocusDistance, double, 0.0, 1e30);
  vtkGetMacro(TSMFocusDistance, double);
  ///@}

  ///@{
  /** TSM: the share of the map given to the focus region (the paper's 80% line). Clamped to [0.05, 0.95]; default 0.8. */
  vtkSetFiniteClampMacro(TSMFocusFraction, double, 0.05, 0.95);
  vtkGetMacro(TSMFocusFraction, double);
  ///@}

  VTK_WRAPEXCLUDE void FitLight(
    const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light) override;

  /** The light-space warp of a mode: GMNPR for GMNPR, LiSPSM for the others. */
  VTK_WRAPEXCLUDE static shadowmaps::DirectionalWarp LightSpaceWarpOf(int warpMode);

protected:
  /** The warp mode, or "uniform" where the fit fell back to the focused uniform map. */
  VTK_WRAPEXCLUDE const char* GetSingleMapKindName(
    const shadowmaps::ShadowLight& light) const override;
  vtkWarpedShadowMapViews();
  ~vtkWarpedShadowMapViews() override = default;

  shadowmaps::LightView FitDirectionalLight(
    const shadowmaps::ShadowFrame& frame, const shadowmaps::ShadowLight& light) const;
  shadowmaps::LightView FitSpotLight(
    const shadowmaps::ShadowFrame& frame, const shadowmaps::ShadowLight& light) const;
  /** The frame's own warped view of a directional or spot light. */
  shadowmaps::LightView FitWarpedView(
    const shadowmaps::ShadowFrame& frame, const shadowmaps::ShadowLight& light) const;
  /** Whether the light gets the post-perspective cube map (PSMCubeMap). */
  bool UsesPerspectiveCube(const shadowmaps::ShadowLight& light) const;
  /**
   * Gives the light its post-perspective cube faces (in interactive frames the
   * last ones while they serve, else a cube fitted to a widened camera where
   * one serves); false, leaving the light, when none can be built.
   */
  bool AssignPerspectiveCube(
    const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light) const;
  /** The frame's cube of the light, and in `receivers` the world planes around its receivers. */
  shadowmaps::PerspectiveCube FitCubeFor(const shadowmaps::ShadowFrame& frame,
    const shadowmaps::ShadowLight& light, std::vector<shadowmaps::Plane>& receivers) const;
  /** LiSPSM and GMNPR settings (free parameter, falloff). */
  shadowmaps::WarpOptions LightSpaceWarpOptions() const;

  int WarpMode = UNIFORM;
  double LiSPSMFreeParameter = 0.0;
  bool LloydFalloff = false;
  double PseudoNearFraction; // WarpOptions' default
  double PSMSlideBack = -1.0;
  int PSMCubeMap = PSM_CUBE_AUTOMATIC;
  double TSMFocusDistance = 0.0;
  double TSMFocusFraction = 0.8;

private:
  vtkWarpedShadowMapViews(const vtkWarpedShadowMapViews&) = delete;
  void operator=(const vtkWarpedShadowMapViews&) = delete;
};

#endif
