/**
 * @class   vtkVarianceShadowMapPass
 * @brief   Filterable shadow maps (VSM, EVSM2, EVSM4, MSM, ESM) with blur,
 *          mipmaps and light-bleeding control, for any views.
 *
 * The preset of vtkAbstractShadowMapPass whose representation is a
 * vtkVarianceShadowMapRepresentation (its docs say how each kind of moments
 * works); its parameters are forwarded here. No depth offset is involved, and
 * the normal offset defaults to 0. Its views default to
 * vtkUniformShadowMapViews and take any other strategy:
 *
 * @code
 * vtkNew< vtkVarianceShadowMapPass > shadows;
 * shadows->SetMomentsToEVSM4();        // VSM, EVSM2, EVSM4, MSM, ESM
 * shadows->SetBlurRadius(2.0);         // texels of the finest view
 * renderer->SetPass(shadows);
 * vtkNew< vtkCascadedShadowMapViews > cascades;
 * shadows->SetViews(cascades);         // filterable cascades
 * @endcode
 *
 * Main settings: SetMoments() (SetMomentsToVSM(), SetMomentsToEVSM4(),
 * SetMomentsToMSM(), SetMomentsToESM()), SetBlurRadius(),
 * SetLightBleedingReduction(), SetMipmaps(), SetStorage(), SetViews(),
 * SetResolution(). In Python: vtkshadowmaps.make_pass("variance",
 * blur_radius=2.0).
 */
#ifndef vtkVarianceShadowMapPass_h
#define vtkVarianceShadowMapPass_h

#include "vtkAbstractShadowMapPass.h"
#include "vtkRenderingShadowMapsModule.h"          // For export macro
#include "vtkVarianceShadowMapRepresentation.h"    // For MomentsType

class vtkShadowMapViews;

class VTKRENDERINGSHADOWMAPS_EXPORT vtkVarianceShadowMapPass : public vtkAbstractShadowMapPass
{
public:
  static vtkVarianceShadowMapPass* New();
  vtkTypeMacro(vtkVarianceShadowMapPass, vtkAbstractShadowMapPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum MomentsType
  {
    VSM = vtkVarianceShadowMapRepresentation::VSM,
    EVSM2 = vtkVarianceShadowMapRepresentation::EVSM2,
    EVSM4 = vtkVarianceShadowMapRepresentation::EVSM4,
    MSM = vtkVarianceShadowMapRepresentation::MSM,
    ESM = vtkVarianceShadowMapRepresentation::ESM
  };

  /** The variance representation whose parameters the pass forwards. */
  vtkVarianceShadowMapRepresentation* GetVarianceRepresentation() { return this->Variance; }

  ///@{
  /** vtkVarianceShadowMapRepresentation's Moments: VSM, EVSM2, EVSM4 (default), MSM, ESM. */
  void SetMoments(int moments) { this->Variance->SetMoments(moments); }
  int GetMoments() { return this->Variance->GetMoments(); }
  void SetMomentsToVSM() { this->SetMoments(VSM); }
  void SetMomentsToEVSM2() { this->SetMoments(EVSM2); }
  void SetMomentsToEVSM4() { this->SetMoments(EVSM4); }
  void SetMomentsToMSM() { this->SetMoments(MSM); }
  void SetMomentsToESM() { this->SetMoments(ESM); }
  ///@}

  ///@{
  /** vtkVarianceShadowMapRepresentation's Storage: 16 (half floats; MSM: normalized integers) or 32 bits (default). */
  void SetStorage(int bits) { this->Variance->SetStorage(bits); }
  int GetStorage() { return this->Variance->GetStorage(); }
  void SetStorageToHalfFloat() { this->Variance->SetStorageToHalfFloat(); }
  void SetStorageToFloat() { this->Variance->SetStorageToFloat(); }
  ///@}

  ///@{
  /** vtkVarianceShadowMapRepresentation's exponents, clamped to what the storage holds. */
  void SetPositiveExponent(double exponent) { this->Variance->SetPositiveExponent(exponent); }
  double GetPositiveExponent() { return this->Variance->GetPositiveExponent(); }
  void SetNegativeExponent(double exponent) { this->Variance->SetNegativeExponent(exponent); }
  double GetNegativeExponent() { return this->Variance->GetNegativeExponent(); }
  ///@}

  ///@{
  /** vtkVarianceShadowMapRepresentation's BlurRadius, texels of the finest view, [0, 16], default 1. */
  void SetBlurRadius(double radius) { this->Variance->SetBlurRadius(radius); }
  double GetBlurRadius() { return this->Variance->GetBlurRadius(); }
  ///@}

  ///@{
  /** vtkVarianceShadowMapRepresentation's Mipmaps, default on. */
  void SetMipmaps(bool mipmaps) { this->Variance->SetMipmaps(mipmaps); }
  bool GetMipmaps() { return this->Variance->GetMipmaps(); }
  ///@}

  ///@{
  /** vtkVarianceShadowMapRepresentation's CasterSamples (multisampled casters), [1, 8], default 1. */
  void SetCasterSamples(int samples) { this->Variance->SetCasterSamples(samples); }
  int GetCasterSamples() { return this->Variance->GetCasterSamples(); }
  ///@}

  ///@{
  /** vtkVarianceShadowMapRepresentation's Anisotropy, [1, 16], default 8. */
  void SetAnisotropy(double anisotropy) { this->Variance->SetAnisotropy(anisotropy); }
  double GetAnisotropy() { return this->Variance->GetAnisotropy(); }
  ///@}

  ///@{
  /** vtkVarianceShadowMapRepresentation's LightBleedingReduction, [0, 0.95], default 0. */
  void SetLightBleedingReduction(double amount) { this->Variance->SetLightBleedingReduction(amount); }
  double GetLightBleedingReduction() { return this->Variance->GetLightBleedingReduction(); }
  ///@}

  ///@{
  /** vtkVarianceShadowMapRepresentation's MinimumVariance, [0, 0.01], default 1e-6. */
  void SetMinimumVariance(double variance) { this->Variance->SetMinimumVariance(variance); }
  double GetMinimumVariance() { return this->Variance->GetMinimumVariance(); }
  ///@}

  ///@{
  /** vtkVarianceShadowMapRepresentation's MomentBias (MSM), [0, 0.01], default 3e-5. */
  void SetMomentBias(double bias) { this->Variance->SetMomentBias(bias); }
  double GetMomentBias() { return this->Variance->GetMomentBias(); }
  ///@}

protected:
  vtkVarianceShadowMapPass();
  vtkVarianceShadowMapPass(vtkShadowMapViews* views, vtkVarianceShadowMapRepresentation* variance);
  ~vtkVarianceShadowMapPass() override;

  vtkVarianceShadowMapRepresentation* Variance;

private:
  vtkVarianceShadowMapPass(const vtkVarianceShadowMapPass&) = delete;
  void operator=(const vtkVarianceShadowMapPass&) = delete;
};

#endif
