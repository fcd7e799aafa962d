/**
 * @class   vtkWarpedShadowMapPass
 * @brief   Warped shadow maps; for now the focused uniform member of the family.
 *
 * Directional lights get an orthographic map fitted to the focus body B
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

protected:
  vtkWarpedShadowMapPass() = default;
  ~vtkWarpedShadowMapPass() override = default;

  void ComputeLightViews(Internals& internals, int lightIndex) override;

private:
  vtkWarpedShadowMapPass(const vtkWarpedShadowMapPass&) = delete;
  void operator=(const vtkWarpedShadowMapPass&) = delete;
};

#endif
