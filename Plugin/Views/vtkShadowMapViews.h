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
 *
 * While the user drags the camera (vtkAbstractShadowMapPass's
 * InteractiveUpdateRate), the warped maps and the cascades of directional
 * lights give a light the views it was last rendered with again while they
 * still serve the frame (InteractiveView), so that its maps are re-rendered
 * only every few frames; InteractiveTexelRatio bounds how much coarser such a
 * view may be. vtkUniformShadowMapViews keeps none (its focused maps snap
 * outward to a grid instead).
 */
#ifndef vtkShadowMapViews_h
#define vtkShadowMapViews_h

#include "vtkObject.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkShadowMapSetMacros.h" // For vtkSetFiniteClampMacro
#include "vtkWrappingHints.h"             // For VTK_WRAPEXCLUDE

#include <functional> // For ViewFit
#include <vector>     // For WidenedFrames

namespace shadowmaps
{
struct LightView;
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
   * degenerate frame; the pass then drops the light for the frame. In frames
   * that may keep views (MayKeepViews) a strategy whose views follow the
   * camera may give light.LastViews again while they serve; other frames must
   * get the frame's own fit.
   */
  VTK_WRAPEXCLUDE virtual void FitLight(
    const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light) = 0;

  /** The focused uniform views of any light: cube faces, a spot's cone or a directional map. */
  VTK_WRAPEXCLUDE static void FitUniformViews(
    const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light);

  ///@{
  /**
   * In interactive renders (vtkAbstractShadowMapPass::InteractiveUpdateRate)
   * warped maps and directional lights' cascades keep a view the light was
   * last rendered with while it holds what the frame's own fit of that view
   * would hold, and its texels across the light are at most this many times
   * the fit's at every vertex of the visible part of the scene it holds. A
   * warped map or tight cascade that must be fitted again is fitted to a
   * slightly wider camera, so that it lasts several frames; a stable cascade
   * gets the frame's own fit, whose texel size depends on its depth range
   * alone. Still renders always get the frame's own fit. 1 fits every render
   * anew. No effect on vtkUniformShadowMapViews. Clamped to [1, 16]; default
   * 1.5.
   */
  vtkSetFiniteClampMacro(InteractiveTexelRatio, double, 1.0, 16.0);
  vtkGetMacro(InteractiveTexelRatio, double);
  ///@}

  /**
   * Whether views may be kept in `frame` (InteractiveView): an interactive
   * frame, or a still one of a pass whose AnimationKeepsViews is on
   * (frame.StillKeepsViews), with InteractiveTexelRatio above 1.
   */
  VTK_WRAPEXCLUDE bool MayKeepViews(const shadowmaps::ShadowFrame& frame) const;

  /**
   * The frame with its camera widened a few ways, widest first (eye moved
   * back, sides turned out), for a fit in an interactive frame that should
   * last several frames; none for a parallel projection or nothing visible.
   */
  VTK_WRAPEXCLUDE static std::vector<shadowmaps::ShadowFrame> WidenedFrames(
    const shadowmaps::ShadowFrame& frame);

  /**
   * What `light`, as this strategy last fitted it, got: "cube faces",
   * "psm-cube" (Kozlov's post-perspective cube), "cascades", "tiles", or for
   * one map its warp ("uniform", "lispsm", "gmnpr", "psm", "tsm").
   */
  VTK_WRAPEXCLUDE const char* GetKindName(const shadowmaps::ShadowLight& light) const;

protected:
  vtkShadowMapViews() = default;
  ~vtkShadowMapViews() override = default;

  /** GetKindName of a light given one map: how the strategy warped it. */
  VTK_WRAPEXCLUDE virtual const char* GetSingleMapKindName(
    const shadowmaps::ShadowLight& vtkNotUsed(light)) const
  {
    return "uniform";
  }

  /** Fits a view of a light to a frame (for a cascade: to its sub-frustum). */
  using ViewFit = std::function<shadowmaps::LightView(const shadowmaps::ShadowFrame&)>;

  /**
   * The view to render in `frame` for `fresh`, the frame's own fit by `fit`:
   * fresh when views may not be kept (MayKeepViews). Where they may,
   * `last` (the view the light was last rendered with, if any) while
   * it still serves as fresh would; else, unless `fit` is empty, the fit of
   * the widest of a few widened cameras whose texels stay within three
   * quarters of the ratio's margin, so that it lasts several frames; else
   * fresh.
   */
  shadowmaps::LightView InteractiveView(const shadowmaps::ShadowFrame& frame,
    const shadowmaps::ShadowLight& light, const shadowmaps::LightView& fresh,
    const shadowmaps::LightView* last, const ViewFit& fit) const;

  /**
   * The texel ratio a fit to a widened camera may have against the frame's own
   * fit: a share of InteractiveTexelRatio's margin, leaving the rest to the
   * camera's next moves.
   */
  double WidenedTexelRatio() const;

  double InteractiveTexelRatio = 1.5;

private:
  vtkShadowMapViews(const vtkShadowMapViews&) = delete;
  void operator=(const vtkShadowMapViews&) = delete;
};

#endif
