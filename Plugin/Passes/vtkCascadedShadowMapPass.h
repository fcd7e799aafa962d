/**
 * @class   vtkCascadedShadowMapPass
 * @brief   Cascaded depth shadow maps for directional lights; tiled maps for spots.
 *
 * vtkDepthShadowMapPass with vtkCascadedShadowMapViews, whose parameters are
 * forwarded here; see vtkCascadedShadowMapViews for the splits, fitting,
 * blending and selection. Resolution is per cascade (default 1024: four
 * cascades hold the memory of one 2048² map).
 *
 * The forwarded parameters are those of the pass's own views object
 * (GetCascadedViews()); after SetViews() with another views object they
 * change that unused one.
 *
 * @code
 * vtkNew< vtkCascadedShadowMapPass > shadows;
 * shadows->SetMaximumShadowDistance(200.0);
 * renderer->SetPass(shadows);
 * @endcode
 *
 * Main settings: SetNumberOfCascades(), SetSplitLambda() (PSSM's blend of
 * logarithmic and uniform splits), SetMaximumShadowDistance(), SetFitMode()
 * (SetFitModeToStable(): no shimmer as the camera moves; SetFitModeToTight()),
 * SetBlendFraction(), SetCascadeWarp(), SetResolution() (per cascade). In
 * Python: vtkshadowmaps.make_pass("cascaded", number_of_cascades=3).
 */
#ifndef vtkCascadedShadowMapPass_h
#define vtkCascadedShadowMapPass_h

#include "vtkCascadedShadowMapViews.h" // For the enums
#include "vtkDepthShadowMapPass.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro

class VTKRENDERINGSHADOWMAPS_EXPORT vtkCascadedShadowMapPass : public vtkDepthShadowMapPass
{
public:
  static vtkCascadedShadowMapPass* New();
  vtkTypeMacro(vtkCascadedShadowMapPass, vtkDepthShadowMapPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FitModeType
  {
    STABLE = vtkCascadedShadowMapViews::STABLE,
    TIGHT = vtkCascadedShadowMapViews::TIGHT
  };
  enum CascadeWarpType
  {
    NO_WARP = vtkCascadedShadowMapViews::NO_WARP,
    LISPSM_WARP = vtkCascadedShadowMapViews::LISPSM_WARP,
    GMNPR_WARP = vtkCascadedShadowMapViews::GMNPR_WARP
  };
  enum SelectionType
  {
    BY_DEPTH = vtkCascadedShadowMapViews::BY_DEPTH,
    BY_COVERAGE = vtkCascadedShadowMapViews::BY_COVERAGE
  };

  /** The cascaded views whose parameters the pass forwards. */
  vtkCascadedShadowMapViews* GetCascadedViews() { return this->Cascaded; }

  ///@{
  /** vtkCascadedShadowMapViews' NumberOfCascades, 1 to 8 (default 4). */
  void SetNumberOfCascades(int count) { this->Cascaded->SetNumberOfCascades(count); }
  int GetNumberOfCascades() { return this->Cascaded->GetNumberOfCascades(); }
  ///@}

  ///@{
  /** vtkCascadedShadowMapViews' SplitLambda, [0, 1] (default 0.75). */
  void SetSplitLambda(double lambda) { this->Cascaded->SetSplitLambda(lambda); }
  double GetSplitLambda() { return this->Cascaded->GetSplitLambda(); }
  ///@}

  ///@{
  /** vtkCascadedShadowMapViews' explicit split depths. */
  void AddSplitDistance(double distance) { this->Cascaded->AddSplitDistance(distance); }
  void RemoveAllSplitDistances() { this->Cascaded->RemoveAllSplitDistances(); }
  int GetNumberOfSplitDistances() { return this->Cascaded->GetNumberOfSplitDistances(); }
  ///@}

  ///@{
  /** vtkCascadedShadowMapViews' MaximumShadowDistance (0: the visible depth). */
  void SetMaximumShadowDistance(double distance) { this->Cascaded->SetMaximumShadowDistance(distance); }
  double GetMaximumShadowDistance() { return this->Cascaded->GetMaximumShadowDistance(); }
  ///@}

  ///@{
  /** vtkCascadedShadowMapViews' FadeFraction, [0, 1] (default 0.1). */
  void SetFadeFraction(double fraction) { this->Cascaded->SetFadeFraction(fraction); }
  double GetFadeFraction() { return this->Cascaded->GetFadeFraction(); }
  ///@}

  ///@{
  /** vtkCascadedShadowMapViews' BlendFraction, [0, 1] (default 0.1). */
  void SetBlendFraction(double fraction) { this->Cascaded->SetBlendFraction(fraction); }
  double GetBlendFraction() { return this->Cascaded->GetBlendFraction(); }
  ///@}

  ///@{
  /** vtkCascadedShadowMapViews' FitMode (STABLE default, TIGHT). */
  void SetFitMode(int mode) { this->Cascaded->SetFitMode(mode); }
  int GetFitMode() { return this->Cascaded->GetFitMode(); }
  void SetFitModeToStable() { this->SetFitMode(STABLE); }
  void SetFitModeToTight() { this->SetFitMode(TIGHT); }
  ///@}

  ///@{
  /** vtkCascadedShadowMapViews' CascadeWarp (NO_WARP default, LISPSM_WARP, GMNPR_WARP). */
  void SetCascadeWarp(int warp) { this->Cascaded->SetCascadeWarp(warp); }
  int GetCascadeWarp() { return this->Cascaded->GetCascadeWarp(); }
  void SetCascadeWarpToNoWarp() { this->SetCascadeWarp(NO_WARP); }
  void SetCascadeWarpToLiSPSM() { this->SetCascadeWarp(LISPSM_WARP); }
  void SetCascadeWarpToGMNPR() { this->SetCascadeWarp(GMNPR_WARP); }
  ///@}

  ///@{
  /** vtkCascadedShadowMapViews' Selection (BY_DEPTH default, BY_COVERAGE). */
  void SetSelection(int selection) { this->Cascaded->SetSelection(selection); }
  int GetSelection() { return this->Cascaded->GetSelection(); }
  void SetSelectionToByDepth() { this->SetSelection(BY_DEPTH); }
  void SetSelectionToByCoverage() { this->SetSelection(BY_COVERAGE); }
  ///@}

  ///@{
  /** The split depths the last frame used (vtkCascadedShadowMapViews::GetSplit). */
  int GetNumberOfSplits() { return this->Cascaded->GetNumberOfSplits(); }
  double GetSplit(int i) { return this->Cascaded->GetSplit(i); }
  ///@}

protected:
  vtkCascadedShadowMapPass();
  ~vtkCascadedShadowMapPass() override;

  vtkCascadedShadowMapViews* Cascaded;

private:
  vtkCascadedShadowMapPass(const vtkCascadedShadowMapPass&) = delete;
  void operator=(const vtkCascadedShadowMapPass&) = delete;
};

#endif
