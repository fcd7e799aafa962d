/**
 * @class   vtkDepthShadowMapPass
 * @brief   Depth shadow maps with the PCF filters, for any views.
 *
 * The preset of vtkAbstractShadowMapPass whose representation is a
 * vtkDepthShadowMapRepresentation; its filter and bias parameters are
 * forwarded here. Its views default to vtkUniformShadowMapViews and take any
 * other strategy:
 *
 * @code
 * vtkNew< vtkDepthShadowMapPass > shadows;
 * vtkNew< vtkCascadedShadowMapViews > cascades;
 * shadows->SetViews(cascades);
 * shadows->SetFilterToPoisson();
 * renderer->SetPass(shadows);
 * @endcode
 *
 * Main settings: SetViews(), SetResolution(), SetFilter() (SetFilterToHard(),
 * SetFilterToPCF2x2(), SetFilterToPCFNxN() with SetKernelSize(),
 * SetFilterToPoisson() with SetFilterRadius()), SetConstantBias(),
 * SetSlopeScaledBias(), SetNormalOffset(). In Python:
 * vtkshadowmaps.make_pass("depth", resolution=2048).
 *
 * vtkWarpedShadowMapPass and vtkCascadedShadowMapPass are this pass with
 * warped and cascaded views. After SetRepresentation() with another
 * representation, the forwarded parameters below change the depth
 * representation, which is then unused.
 */
#ifndef vtkDepthShadowMapPass_h
#define vtkDepthShadowMapPass_h

#include "vtkAbstractShadowMapPass.h"
#include "vtkDepthShadowMapRepresentation.h" // For FilterType
#include "vtkRenderingShadowMapsModule.h"    // For export macro

class vtkShadowMapViews;

class VTKRENDERINGSHADOWMAPS_EXPORT vtkDepthShadowMapPass : public vtkAbstractShadowMapPass
{
public:
  static vtkDepthShadowMapPass* New();
  vtkTypeMacro(vtkDepthShadowMapPass, vtkAbstractShadowMapPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FilterType
  {
    HARD = vtkDepthShadowMapRepresentation::HARD,
    PCF_2X2 = vtkDepthShadowMapRepresentation::PCF_2X2,
    PCF_NXN = vtkDepthShadowMapRepresentation::PCF_NXN,
    POISSON = vtkDepthShadowMapRepresentation::POISSON
  };

  /** The depth representation whose parameters the pass forwards. */
  vtkDepthShadowMapRepresentation* GetDepthRepresentation() { return this->Depth; }

  ///@{
  /** vtkDepthShadowMapRepresentation's Filter (HARD, PCF_2X2 default, PCF_NXN, POISSON). */
  void SetFilter(int filter) { this->Depth->SetFilter(filter); }
  int GetFilter() { return this->Depth->GetFilter(); }
  void SetFilterToHard() { this->SetFilter(HARD); }
  void SetFilterToPCF2x2() { this->SetFilter(PCF_2X2); }
  void SetFilterToPCFNxN() { this->SetFilter(PCF_NXN); }
  void SetFilterToPoisson() { this->SetFilter(POISSON); }
  ///@}

  ///@{
  /** vtkDepthShadowMapRepresentation's KernelSize: N of the N x N PCF, [2, 7], default 3. */
  void SetKernelSize(int size) { this->Depth->SetKernelSize(size); }
  int GetKernelSize() { return this->Depth->GetKernelSize(); }
  ///@}

  ///@{
  /** vtkDepthShadowMapRepresentation's FilterRadius: the Poisson disc's, in texels, [0.5, 16], default 2. */
  void SetFilterRadius(double radius) { this->Depth->SetFilterRadius(radius); }
  double GetFilterRadius() { return this->Depth->GetFilterRadius(); }
  ///@}

  ///@{
  /** vtkDepthShadowMapRepresentation's PoissonSamples: taps of the Poisson disc, [4, 32], default 16. */
  void SetPoissonSamples(int samples) { this->Depth->SetPoissonSamples(samples); }
  int GetPoissonSamples() { return this->Depth->GetPoissonSamples(); }
  ///@}

  ///@{
  /** vtkDepthShadowMapRepresentation's ConstantBias (polygon-offset units), [0, 10000], default 4. */
  void SetConstantBias(double bias) { this->Depth->SetConstantBias(bias); }
  double GetConstantBias() { return this->Depth->GetConstantBias(); }
  ///@}

  ///@{
  /** vtkDepthShadowMapRepresentation's SlopeScaledBias, [0, 100], default 2. */
  void SetSlopeScaledBias(double bias) { this->Depth->SetSlopeScaledBias(bias); }
  double GetSlopeScaledBias() { return this->Depth->GetSlopeScaledBias(); }
  ///@}

protected:
  vtkDepthShadowMapPass();
  /** A depth pass whose preset views are `views`. */
  explicit vtkDepthShadowMapPass(vtkShadowMapViews* views);
  /** A pass whose preset views are `views` and representation `depth` (a kind of depth map). */
  vtkDepthShadowMapPass(vtkShadowMapViews* views, vtkDepthShadowMapRepresentation* depth);
  ~vtkDepthShadowMapPass() override;

  vtkDepthShadowMapRepresentation* Depth;

private:
  vtkDepthShadowMapPass(const vtkDepthShadowMapPass&) = delete;
  void operator=(const vtkDepthShadowMapPass&) = delete;
};

#endif
