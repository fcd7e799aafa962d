/**
 * @class   vtkUniformShadowMapViews
 * @brief   Focused uniform shadow-map views: one map per light, six for point lights.
 *
 * Directional lights get an orthographic map fitted to the focus body B (view
 * frustum ∩ scene bounds; survey 003 §4.1 in docs/REFERENCES.md) with its near
 * plane pulled back to the nearest caster inside the map's side planes (text
 * 004); spot lights get their cone's frustum cropped to B; point lights, and
 * spots wider than one map holds, get six 90 degree cube faces, each cropped to
 * what the camera sees. The default views of vtkDepthShadowMapPass.
 */
#ifndef vtkUniformShadowMapViews_h
#define vtkUniformShadowMapViews_h

#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkShadowMapViews.h"

class VTKRENDERINGSHADOWMAPS_EXPORT vtkUniformShadowMapViews : public vtkShadowMapViews
{
public:
  static vtkUniformShadowMapViews* New();
  vtkTypeMacro(vtkUniformShadowMapViews, vtkShadowMapViews);

  VTK_WRAPEXCLUDE void FitLight(
    const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light) override;

protected:
  vtkUniformShadowMapViews() = default;
  ~vtkUniformShadowMapViews() override = default;

private:
  vtkUniformShadowMapViews(const vtkUniformShadowMapViews&) = delete;
  void operator=(const vtkUniformShadowMapViews&) = delete;
};

#endif
