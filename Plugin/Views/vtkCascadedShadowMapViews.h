/**
 * @class   vtkCascadedShadowMapViews
 * @brief   Cascaded shadow-map views for directional lights; tiled maps for spots.
 *
 * The camera's view depth up to MaximumShadowDistance is split into
 * NumberOfCascades partitions (survey 003 §4.3.1, PSSM's practical scheme, or
 * explicit split depths), each with its own map, one layer of a 2D texture
 * array. A cascade is fitted either STABLE (default: a sphere around its
 * sub-frustum in a light frame fixed in the world, moved in steps of whole
 * texels, so that shadow edges do not shimmer and a small camera move keeps the
 * map; seed 004) or TIGHT
 * (sub-frustum ∩ scene, the sharpest texels). While the user drags the camera, a
 * cascade keeps its last view while that still serves its sub-frustum
 * (vtkShadowMapViews::InteractiveTexelRatio). Each cascade's depth range reaches
 * the casters between its sub-frustum and the light. Optionally each cascade is
 * warped with LiSPSM or GMNPR (vtkWarpedShadowMapPass's warps).
 *
 * Receivers pick their cascade by view depth (or by map coverage: the finest
 * cascade whose map contains them, better when the light is near the view
 * direction), blend into the next cascade over the last BlendFraction of each
 * cascade, and fade out over the last FadeFraction before MaximumShadowDistance
 * when that distance cuts the visible scene. Filter kernels keep their world
 * size in every cascade. A spot light gets one map of its cone cropped to the
 * lit part of the view, stored as tiles in the cascades' layers (columns x rows
 * with rows = floor(sqrt(NumberOfCascades)): 2 x 2 tiles, one 2048² map, for four
 * cascades of 1024²) and picked by where the receiver falls in that map: a spot's texels spread with the
 * distance to the light, not to the camera, and one such map misclassified fewer
 * pixels than depth cascades in every benchmark scene. Splits, blending and
 * STABLE fitting apply to directional lights; CascadeWarp, with TIGHT fitting,
 * to directional and spot lights (a spot's whole map is warped before tiling);
 * MaximumShadowDistance's fade applies to all. Point lights, and spots wider than one map holds, keep the
 * uniform cube faces. Each cascade (and each tile) is a map of the pass's
 * Resolution: vtkCascadedShadowMapPass defaults it to 1024 so that four
 * cascades hold the memory of one 2048² map; another pass keeps its own.
 *
 * The views of vtkCascadedShadowMapPass; any pass takes them:
 *
 * @code
 * vtkNew<vtkCascadedShadowMapViews> cascades;
 * cascades->SetNumberOfCascades(3);
 * pass->SetViews(cascades);
 * @endcode
 */
#ifndef vtkCascadedShadowMapViews_h
#define vtkCascadedShadowMapViews_h

#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkShadowMapSetMacros.h" // For vtkSetFiniteClampMacro
#include "vtkShadowMapViews.h"
#include "vtkWarpedShadowMapViews.h" // For the warp modes

#include <vector> // For SplitDistances

namespace shadowmaps
{
struct LightView;
}

class VTKRENDERINGSHADOWMAPS_EXPORT vtkCascadedShadowMapViews : public vtkShadowMapViews
{
public:
  static vtkCascadedShadowMapViews* New();
  vtkTypeMacro(vtkCascadedShadowMapViews, vtkShadowMapViews);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Number of cascades, 1 to 8 (default 4); out-of-range values clamp with a warning. */
  void SetNumberOfCascades(int count);
  vtkGetMacro(NumberOfCascades, int);
  ///@}

  ///@{
  /**
   * Practical split weight: 0 uniform splits, 1 logarithmic (default 0.75).
   * Values outside [0, 1] clamp with a warning. Ignored while explicit split
   * distances are set.
   */
  void SetSplitLambda(double lambda);
  vtkGetMacro(SplitLambda, double);
  ///@}

  ///@{
  /**
   * Explicit split depths (view-space distances): the boundaries between
   * cascades, one fewer than the cascades wanted. Unsorted, negative, duplicate
   * or out-of-range values are repaired with a warning at render time. With
   * none (default) the splits follow SplitLambda and NumberOfCascades.
   */
  void AddSplitDistance(double distance);
  void RemoveAllSplitDistances();
  int GetNumberOfSplitDistances() const { return static_cast<int>(this->SplitDistances.size()); }
  ///@}

  ///@{
  /**
   * Depth up to which shadows are drawn. 0 (default): the camera's far plane,
   * tightened to the farthest visible prop. Values below the near plane clamp to
   * it with a warning at render time; negative values clamp to 0 with a warning.
   */
  void SetMaximumShadowDistance(double distance);
  vtkGetMacro(MaximumShadowDistance, double);
  ///@}

  ///@{
  /** Share of MaximumShadowDistance over which shadows fade out, [0, 1], default 0.1. */
  vtkSetFiniteClampMacro(FadeFraction, double, 0.0, 1.0);
  vtkGetMacro(FadeFraction, double);
  ///@}

  ///@{
  /**
   * Share of each cascade blended into the next, [0, 1], default 0.1: of its
   * depth range when cascades are selected BY_DEPTH, of its map's half-width
   * (along the border) BY_COVERAGE. Receivers in a band look up two cascades;
   * with 0 the second lookup is compiled out, which on a software rasteriser
   * (that runs it at every pixel) saves about a tenth of a cascaded frame.
   */
  vtkSetFiniteClampMacro(BlendFraction, double, 0.0, 1.0);
  vtkGetMacro(BlendFraction, double);
  ///@}

  enum FitModeType
  {
    STABLE = 0,
    TIGHT = 1
  };

  ///@{
  /**
   * STABLE (default) or TIGHT cascade fitting. Stable cascades also split the
   * visible depth range rounded out to levels 2^(1/4) apart (possibly beyond
   * the camera's planes, which interactors reset every frame), so that small
   * camera moves do not move the splits.
   */
  vtkSetClampMacro(FitMode, int, STABLE, TIGHT);
  vtkGetMacro(FitMode, int);
  void SetFitModeToStable() { this->SetFitMode(STABLE); }
  void SetFitModeToTight() { this->SetFitMode(TIGHT); }
  ///@}

  /** The warped views' modes, so that vtkWarpedShadowMapViews::LightSpaceWarpOf reads them. */
  enum CascadeWarpType
  {
    NO_WARP = vtkWarpedShadowMapViews::UNIFORM,
    LISPSM_WARP = vtkWarpedShadowMapViews::LISPSM,
    GMNPR_WARP = vtkWarpedShadowMapViews::GMNPR
  };

  ///@{
  /**
   * Warp inside each cascade, and of a spot light's tiled map (TIGHT fitting only;
   * stable cascades stay uniform). Default NO_WARP.
   */
  vtkSetClampMacro(CascadeWarp, int, NO_WARP, GMNPR_WARP);
  vtkGetMacro(CascadeWarp, int);
  void SetCascadeWarpToNoWarp() { this->SetCascadeWarp(NO_WARP); }
  void SetCascadeWarpToLiSPSM() { this->SetCascadeWarp(LISPSM_WARP); }
  void SetCascadeWarpToGMNPR() { this->SetCascadeWarp(GMNPR_WARP); }
  ///@}

  enum SelectionType
  {
    BY_DEPTH = 0,
    BY_COVERAGE = 1
  };

  ///@{
  /** How receivers pick their cascade. Default BY_DEPTH. */
  vtkSetClampMacro(Selection, int, BY_DEPTH, BY_COVERAGE);
  vtkGetMacro(Selection, int);
  void SetSelectionToByDepth() { this->SetSelection(BY_DEPTH); }
  void SetSelectionToByCoverage() { this->SetSelection(BY_COVERAGE); }
  ///@}

  ///@{
  /**
   * Split depths the last frame used (the same for every cascaded light):
   * cascade i shades view depths from GetSplit(i) to GetSplit(i + 1).
   */
  int GetNumberOfSplits() const { return static_cast<int>(this->LastSplits.size()); }
  double GetSplit(int i) const;
  ///@}

  VTK_WRAPEXCLUDE void FitLight(
    const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light) override;

protected:
  vtkCascadedShadowMapViews() = default;
  ~vtkCascadedShadowMapViews() override = default;

  /** This frame's split depths; fade receives the depths shadows fade over ({0, 0}: none). */
  std::vector<double> ComputeSplits(const shadowmaps::ShadowFrame& frame, double fade[2]);
  /** A directional light's views: one per depth partition. */
  void FitCascades(const shadowmaps::ShadowFrame& frame, const std::vector<double>& splits,
    shadowmaps::ShadowLight& light) const;
  /** A spot light's views: one cone map, in tiles of the cascades' layers. */
  void TileSpotLight(const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light) const;
  /** A spot's whole map before tiling, warped by CascadeWarp when the light may warp. */
  shadowmaps::LightView FitSpotMap(
    const shadowmaps::ShadowFrame& frame, const shadowmaps::ShadowLight& light) const;
  /** Whether this light's cascades (or tiles) may be warped. */
  bool MayWarp() const;

  int NumberOfCascades = 4;
  double SplitLambda = 0.75;
  std::vector<double> SplitDistances;
  double MaximumShadowDistance = 0.0;
  double FadeFraction = 0.1;
  double BlendFraction = 0.1;
  int FitMode = STABLE;
  int CascadeWarp = NO_WARP;
  int Selection = BY_DEPTH;
  std::vector<double> LastSplits;
  bool SplitProblemReported = false;

private:
  vtkCascadedShadowMapViews(const vtkCascadedShadowMapViews&) = delete;
  void operator=(const vtkCascadedShadowMapViews&) = delete;
};

#endif
