/**
 * @class   vtkWarpedShadowMapPass
 * @brief   Warped shadow maps: focused uniform, LiSPSM and GMNPR.
 *
 * WarpMode chooses how a directional light's map is parameterised:
 * - UNIFORM (default): an orthographic map fitted to the focus body B;
 * - LISPSM (Wimmer et al.; thesis 000, survey 003 §4.2): a perspective warp in
 *   light space whose axis is the view direction projected perpendicular to the
 *   light, with n = (z_n + sqrt(z_f z_n)) / sin(gamma), optionally Lloyd-style
 *   faster falloff, or a user-set free parameter n;
 * - GMNPR (Zhang et al., seed 002 Eq. 8): the same warp with the
 *   direction-adaptive lambda that equalises the aliasing at the near and far
 *   planes.
 * As the view direction approaches the light direction the warps fade
 * continuously into the uniform map; parallel-projection cameras get the
 * uniform map. Spot and point lights use the uniform fits below. PSM and TSM
 * are not implemented yet (the math is in ShadowMapPerspective/Trapezoid).
 *
 * Uniform fit: directional lights get an orthographic map fitted to the focus body B
 * (view frustum ∩ scene bounds, survey 003 §4.1) with its near plane pulled back
 * to the nearest caster inside the map's side planes (ComputeNearAndFar, text
 * 004); spot lights get their cone's frustum cropped to B; point lights get six
 * 90 degree faces. Filtering, bias and resource handling come from
 * vtkAbstractShadowMapPass.
 *
 * @code
 * renderer->SetPass(vtkNew<vtkWarpedShadowMapPass>());
 * @endcode
 */
#ifndef vtkWarpedShadowMapPass_h
#define vtkWarpedShadowMapPass_h

#include "vtkAbstractShadowMapPass.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro

class VTKRENDERINGSHADOWMAPS_EXPORT vtkWarpedShadowMapPass : public vtkAbstractShadowMapPass
{
public:
  static vtkWarpedShadowMapPass* New();
  vtkTypeMacro(vtkWarpedShadowMapPass, vtkAbstractShadowMapPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum WarpModeType
  {
    UNIFORM = 0,
    LISPSM = 1,
    GMNPR = 2
  };

  ///@{
  /** How directional maps are warped. Clamped to [UNIFORM, GMNPR]; default UNIFORM. */
  vtkSetClampMacro(WarpMode, int, UNIFORM, GMNPR);
  vtkGetMacro(WarpMode, int);
  ///@}

  ///@{
  /**
   * LiSPSM's free parameter n (distance of the warp's apex before the focus
   * body, world units). 0 (default) chooses n_opt automatically; clamped to
   * [0, 1e30].
   */
  vtkSetClampMacro(LiSPSMFreeParameter, double, 0.0, 1e30);
  vtkGetMacro(LiSPSMFreeParameter, double);
  ///@}

  ///@{
  /** LiSPSM: fall off faster than 1/sin(gamma) below the frustum's half angle. Default off. */
  vtkSetMacro(LloydFalloff, bool);
  vtkGetMacro(LloydFalloff, bool);
  vtkBooleanMacro(LloydFalloff, bool);
  ///@}

protected:
  vtkWarpedShadowMapPass() = default;
  ~vtkWarpedShadowMapPass() override = default;

  void ComputeLightViews(Internals& internals, int lightIndex) override;

  int WarpMode = UNIFORM;
  double LiSPSMFreeParameter = 0.0;
  bool LloydFalloff = false;

private:
  vtkWarpedShadowMapPass(const vtkWarpedShadowMapPass&) = delete;
  void operator=(const vtkWarpedShadowMapPass&) = delete;
};

#endif
