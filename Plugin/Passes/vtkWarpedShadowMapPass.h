/**
 * @class   vtkWarpedShadowMapPass
 * @brief   Warped depth shadow maps: focused uniform, PSM, LiSPSM, TSM and GMNPR.
 *
 * vtkDepthShadowMapPass with vtkWarpedShadowMapViews, whose parameters are
 * forwarded here; see vtkWarpedShadowMapViews for what each warp does.
 *
 * The forwarded parameters are those of the pass's own views object
 * (GetWarpedViews()); after SetViews() with another views object they
 * change that unused one.
 *
 * @code
 * vtkNew< vtkWarpedShadowMapPass > shadows;
 * shadows->SetWarpModeToLiSPSM();
 * renderer->SetPass(shadows);
 * @endcode
 *
 * Main settings: SetWarpMode() (SetWarpModeToUniform(), SetWarpModeToPSM(),
 * SetWarpModeToLiSPSM(), SetWarpModeToTSM(), SetWarpModeToGMNPR()),
 * SetResolution(), SetPSMCubeMap() (Kozlov's cube), SetLiSPSMFreeParameter(),
 * and the depth filters (SetFilterToPoisson(), ...). In Python:
 * vtkshadowmaps.make_pass("lispsm", resolution=4096).
 */
#ifndef vtkWarpedShadowMapPass_h
#define vtkWarpedShadowMapPass_h

#include "vtkDepthShadowMapPass.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkWarpedShadowMapViews.h"      // For WarpModeType

class VTKRENDERINGSHADOWMAPS_EXPORT vtkWarpedShadowMapPass : public vtkDepthShadowMapPass
{
public:
  static vtkWarpedShadowMapPass* New();
  vtkTypeMacro(vtkWarpedShadowMapPass, vtkDepthShadowMapPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum WarpModeType
  {
    UNIFORM = vtkWarpedShadowMapViews::UNIFORM,
    LISPSM = vtkWarpedShadowMapViews::LISPSM,
    GMNPR = vtkWarpedShadowMapViews::GMNPR,
    PSM = vtkWarpedShadowMapViews::PSM,
    TSM = vtkWarpedShadowMapViews::TSM
  };

  /** The warped views whose parameters the pass forwards. */
  vtkWarpedShadowMapViews* GetWarpedViews() { return this->Warped; }

  ///@{
  /** vtkWarpedShadowMapViews' WarpMode (UNIFORM default, LISPSM, GMNPR, PSM, TSM). */
  void SetWarpMode(int mode) { this->Warped->SetWarpMode(mode); }
  int GetWarpMode() { return this->Warped->GetWarpMode(); }
  void SetWarpModeToUniform() { this->SetWarpMode(UNIFORM); }
  void SetWarpModeToLiSPSM() { this->SetWarpMode(LISPSM); }
  void SetWarpModeToGMNPR() { this->SetWarpMode(GMNPR); }
  void SetWarpModeToPSM() { this->SetWarpMode(PSM); }
  void SetWarpModeToTSM() { this->SetWarpMode(TSM); }
  ///@}

  ///@{
  /** vtkWarpedShadowMapViews' LiSPSMFreeParameter (0: automatic n_opt). */
  void SetLiSPSMFreeParameter(double n) { this->Warped->SetLiSPSMFreeParameter(n); }
  double GetLiSPSMFreeParameter() { return this->Warped->GetLiSPSMFreeParameter(); }
  ///@}

  ///@{
  /** vtkWarpedShadowMapViews' PseudoNearFraction (0: the near depth as it is). */
  void SetPseudoNearFraction(double fraction) { this->Warped->SetPseudoNearFraction(fraction); }
  double GetPseudoNearFraction() { return this->Warped->GetPseudoNearFraction(); }
  ///@}

  ///@{
  /** vtkWarpedShadowMapViews' LloydFalloff. */
  void SetLloydFalloff(bool on) { this->Warped->SetLloydFalloff(on); }
  bool GetLloydFalloff() { return this->Warped->GetLloydFalloff(); }
  void LloydFalloffOn() { this->SetLloydFalloff(true); }
  void LloydFalloffOff() { this->SetLloydFalloff(false); }
  ///@}

  ///@{
  /** vtkWarpedShadowMapViews' PSMSlideBack (negative: automatic). */
  void SetPSMSlideBack(double distance) { this->Warped->SetPSMSlideBack(distance); }
  double GetPSMSlideBack() { return this->Warped->GetPSMSlideBack(); }
  ///@}

  ///@{
  /** vtkWarpedShadowMapViews' PSMCubeMap (AUTOMATIC default: point lights and wide spots). */
  void SetPSMCubeMap(int choice) { this->Warped->SetPSMCubeMap(choice); }
  int GetPSMCubeMap() { return this->Warped->GetPSMCubeMap(); }
  void SetPSMCubeMapToAutomatic() { this->Warped->SetPSMCubeMapToAutomatic(); }
  void SetPSMCubeMapToAlways() { this->Warped->SetPSMCubeMapToAlways(); }
  void SetPSMCubeMapToNever() { this->Warped->SetPSMCubeMapToNever(); }
  ///@}

  ///@{
  /** vtkWarpedShadowMapViews' TSMFocusDistance (0: a fifth of the focus body's depth). */
  void SetTSMFocusDistance(double distance) { this->Warped->SetTSMFocusDistance(distance); }
  double GetTSMFocusDistance() { return this->Warped->GetTSMFocusDistance(); }
  ///@}

  ///@{
  /** vtkWarpedShadowMapViews' TSMFocusFraction, [0.05, 0.95], default 0.8. */
  void SetTSMFocusFraction(double fraction) { this->Warped->SetTSMFocusFraction(fraction); }
  double GetTSMFocusFraction() { return this->Warped->GetTSMFocusFraction(); }
  ///@}

protected:
  vtkWarpedShadowMapPass();
  ~vtkWarpedShadowMapPass() override;

  vtkWarpedShadowMapViews* Warped;

private:
  vtkWarpedShadowMapPass(const vtkWarpedShadowMapPass&) = delete;
  void operator=(const vtkWarpedShadowMapPass&) = delete;
};

#endif
