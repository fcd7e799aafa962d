/**
 * @class   vtkDualDepthShadowMapPass
 * @brief   Second-depth, midpoint and dual shadow maps: shadows without a
 *          hand-tuned bias, for any views.
 *
 * The preset of vtkAbstractShadowMapPass whose representation is a
 * vtkDualDepthShadowMapRepresentation (its docs say how each mode works);
 * its parameters, and the depth representation's filters, are forwarded here.
 * Every depth offset, the normal offset included, defaults to 0. Its views
 * default to vtkUniformShadowMapViews and take any other strategy:
 *
 * @code
 * vtkNew< vtkDualDepthShadowMapPass > shadows;
 * shadows->SetModeToDual();            // or SetModeToMidpoint(), SetModeToSecondDepth()
 * renderer->SetPass(shadows);
 * vtkNew< vtkCascadedShadowMapViews > cascades;
 * shadows->SetViews(cascades);         // dual-depth cascades
 * @endcode
 *
 * Main settings: SetMode() (SetModeToDual(), SetModeToMidpoint(),
 * SetModeToSecondDepth()), SetDualOffset(), SetLayerMethod(), SetViews(),
 * SetResolution(). In Python: vtkshadowmaps.make_pass("dual-depth").
 */
#ifndef vtkDualDepthShadowMapPass_h
#define vtkDualDepthShadowMapPass_h

#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapRepresentation.h" // For ModeType
#include "vtkRenderingShadowMapsModule.h"        // For export macro

class VTKRENDERINGSHADOWMAPS_EXPORT vtkDualDepthShadowMapPass : public vtkDepthShadowMapPass
{
public:
  static vtkDualDepthShadowMapPass* New();
  vtkTypeMacro(vtkDualDepthShadowMapPass, vtkDepthShadowMapPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ModeType
  {
    SECOND_DEPTH = vtkDualDepthShadowMapRepresentation::SECOND_DEPTH,
    MIDPOINT = vtkDualDepthShadowMapRepresentation::MIDPOINT,
    DUAL = vtkDualDepthShadowMapRepresentation::DUAL
  };

  enum LayerMethodType
  {
    AUTO = vtkDualDepthShadowMapRepresentation::AUTO,
    MINIMUM_BLENDING = vtkDualDepthShadowMapRepresentation::MINIMUM_BLENDING,
    DEPTH_PEELING = vtkDualDepthShadowMapRepresentation::DEPTH_PEELING
  };

  /** The dual-depth representation whose parameters the pass forwards. */
  vtkDualDepthShadowMapRepresentation* GetDualDepthRepresentation() { return this->DualDepth; }

  ///@{
  /** vtkDualDepthShadowMapRepresentation's Mode: SECOND_DEPTH, MIDPOINT, DUAL (default). */
  void SetMode(int mode) { this->DualDepth->SetMode(mode); }
  int GetMode() { return this->DualDepth->GetMode(); }
  void SetModeToSecondDepth() { this->SetMode(SECOND_DEPTH); }
  void SetModeToMidpoint() { this->SetMode(MIDPOINT); }
  void SetModeToDual() { this->SetMode(DUAL); }
  ///@}

  ///@{
  /** vtkDualDepthShadowMapRepresentation's LayerMethod: AUTO (default), MINIMUM_BLENDING, DEPTH_PEELING. */
  void SetLayerMethod(int method) { this->DualDepth->SetLayerMethod(method); }
  int GetLayerMethod() { return this->DualDepth->GetLayerMethod(); }
  void SetLayerMethodToAuto() { this->SetLayerMethod(AUTO); }
  void SetLayerMethodToMinimumBlending() { this->SetLayerMethod(MINIMUM_BLENDING); }
  void SetLayerMethodToDepthPeeling() { this->SetLayerMethod(DEPTH_PEELING); }
  ///@}

  ///@{
  /** vtkDualDepthShadowMapRepresentation's DualOffset, in texels, [0, 64], default 2. */
  void SetDualOffset(double offset) { this->DualDepth->SetDualOffset(offset); }
  double GetDualOffset() { return this->DualDepth->GetDualOffset(); }
  ///@}

protected:
  vtkDualDepthShadowMapPass();
  ~vtkDualDepthShadowMapPass() override;

  vtkDualDepthShadowMapRepresentation* DualDepth;

private:
  vtkDualDepthShadowMapPass(const vtkDualDepthShadowMapPass&) = delete;
  void operator=(const vtkDualDepthShadowMapPass&) = delete;
};

#endif
