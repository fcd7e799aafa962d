/**
 * @class   vtkShadowMapViews
 * @brief   Where a light's shadow-map views go: one strategy of a shadow-map pass.
 *
 * A shadow-map pass (vtkAbstractShadowMapPass) makes two independent choices:
 * where each light's views go (this class) and what a texel of their maps
 * stores (vtkShadowMapRepresentation). A views strategy fits, once per map
 * update and per shadowed light, the light's view layout and its list of views
 * (shadowmaps::ShadowLight, ShadowMapLight.h) to the frame
 * (shadowmaps::ShadowFrame: camera, scene bounds, map resolution).
 *
 * Subclasses: vtkUniformShadowMapViews (focused uniform maps and cube faces),
 * vtkWarpedShadowMapViews (PSM, LiSPSM, TSM, GMNPR) and
 * vtkCascadedShadowMapViews (cascades and tiles). Any strategy gives point
 * lights and spots wider than one map holds the uniform cube faces
 * (FitUniformViews). A change of a strategy's parameters re-renders the maps of
 * every pass that uses it.
 */
#ifndef vtkShadowMapViews_h
#define vtkShadowMapViews_h

#include "vtkObject.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkWrappingHints.h"             // For VTK_WRAPEXCLUDE

namespace shadowmaps
{
struct ShadowFrame;
struct ShadowLight;
}

class VTKRENDERINGSHADOWMAPS_EXPORT vtkShadowMapViews : public vtkObject
{
public:
  vtkTypeMacro(vtkShadowMapViews, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Fits the views of `light` for `frame`: sets its Layout, Views (one per map
   * layer), PossibleFeatures and what the layout needs (Tiles, CascadeDepths,
   * CoverageBlendFraction, Fade). Views may come out non-finite on a
   * degenerate frame; the pass then drops the light for the frame. In
   * interactive frames (frame.Interactive) a strategy whose views follow the
   * camera may give light.LastViews again while they serve; still frames must
   * get the frame's own fit.
   */
  VTK_WRAPEXCLUDE virtual void FitLight(
    const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light) = 0;

  /** The focused uniform views of any light: cube faces, a spot's cone or a directional map. */
  VTK_WRAPEXCLUDE static void FitUniformViews(
    const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light);

protected:
  vtkShadowMapViews() = default;
  ~vtkShadowMapViews() override = default;

private:
  vtkShadowMapViews(const vtkShadowMapViews&) = delete;
  void operator=(const vtkShadowMapViews&) = delete;
};

#endif
