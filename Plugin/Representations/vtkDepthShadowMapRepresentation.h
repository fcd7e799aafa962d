/**
 * @class   vtkDepthShadowMapRepresentation
 * @brief   Depth shadow maps with the PCF filter family and caster depth offsets.
 *
 * Each texel stores the depth of the nearest caster (32 bits, or 16 where every
 * view's depth steps stay well below its texels). Receivers compare their
 * depth with it (vtkShadowMapsDepthLookupFS.glsl, filtered by
 * vtkShadowMapsFilterFS.glsl): hard (1 tap), hardware 2x2
 * bilinear PCF, N x N PCF of bilinear taps, or Poisson-disc PCF rotated per
 * texel by a noise texture addressed in light space, so the pattern stays put
 * while the camera moves (thesis 000, jittered PCF; docs/REFERENCES.md).
 *
 * Bias (thesis 000 §3.2, text 001): constant and slope-scaled depth offsets
 * applied when the casters are rendered (m = max(|dz/dx|, |dz/dy|)); the pass's
 * NormalOffset moves receivers along their normals.
 *
 * The representation of vtkDepthShadowMapPass, vtkWarpedShadowMapPass and
 * vtkCascadedShadowMapPass, which forward its parameters.
 */
#ifndef vtkDepthShadowMapRepresentation_h
#define vtkDepthShadowMapRepresentation_h

#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkShadowMapRepresentation.h"
#include "vtkShadowMapSetMacros.h" // For vtkSetFiniteClampMacro

#include <memory> // For std::unique_ptr

namespace shadowmaps
{
class RotationNoise;
}

class VTKRENDERINGSHADOWMAPS_EXPORT vtkDepthShadowMapRepresentation
  : public vtkShadowMapRepresentation
{
public:
  static vtkDepthShadowMapRepresentation* New();
  vtkTypeMacro(vtkDepthShadowMapRepresentation, vtkShadowMapRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FilterType
  {
    HARD = 0,
    PCF_2X2 = 1,
    PCF_NXN = 2,
    POISSON = 3
  };

  ///@{
  /**
   * Shadow filter. HARD: one nearest tap. PCF_2X2: one hardware bilinear
   * comparison. PCF_NXN: N x N bilinear comparisons (KernelSize). POISSON: a
   * rotated Poisson disc of PoissonSamples taps within FilterRadius texels.
   * Clamped to [HARD, POISSON]; default PCF_2X2.
   */
  vtkSetClampMacro(Filter, int, HARD, POISSON);
  vtkGetMacro(Filter, int);
  void SetFilterToHard() { this->SetFilter(HARD); }
  void SetFilterToPCF2x2() { this->SetFilter(PCF_2X2); }
  void SetFilterToPCFNxN() { this->SetFilter(PCF_NXN); }
  void SetFilterToPoisson() { this->SetFilter(POISSON); }
  ///@}

  ///@{
  /** N of the N x N PCF filter. Clamped to [2, 7]; default 3. */
  vtkSetClampMacro(KernelSize, int, 2, 7);
  vtkGetMacro(KernelSize, int);
  ///@}

  ///@{
  /** Radius of the Poisson filter, in texels. Clamped to [0.5, 16]; default 2. */
  vtkSetFiniteClampMacro(FilterRadius, double, 0.5, 16.0);
  vtkGetMacro(FilterRadius, double);
  ///@}

  ///@{
  /** Taps of the Poisson filter. Clamped to [4, 32]; default 16. */
  vtkSetClampMacro(PoissonSamples, int, 4, 32);
  vtkGetMacro(PoissonSamples, int);
  ///@}

  ///@{
  /**
   * Constant depth offset applied to casters, in units of the smallest
   * resolvable depth difference of the maps (glPolygonOffset units): about 2^-24
   * of the light's depth range in 32-bit maps, 1/65535 in 16-bit ones, so a unit
   * weighs 256 times more there; the default stays below a quarter texel either
   * way. Views that store linear depth (the TSM, LiSPSM and GMNPR warps) are
   * always 32-bit and add it, as 2^-24 per unit, to the depth they store.
   * Clamped to [0, 10000]; default 4.
   */
  vtkSetFiniteClampMacro(ConstantBias, double, 0.0, 10000.0);
  vtkGetMacro(ConstantBias, double);
  ///@}

  ///@{
  /**
   * Slope-scaled depth offset applied to casters: the depth offset grows by
   * this factor times m = max(|dz/dx|, |dz/dy|). Views that store linear depth
   * take m on the depth they store; for directional lights this term is capped
   * at SlopeScaledBias / Resolution (a 45 degree surface in a uniform map), as a
   * warp's far texels are many times the mean. Clamped to [0, 100]; default 2.
   */
  vtkSetFiniteClampMacro(SlopeScaledBias, double, 0.0, 100.0);
  vtkGetMacro(SlopeScaledBias, double);
  ///@}

  std::string GetReceiverLookupCode() const override;
  std::string GetReceiverDefinitions() const override;
  double GetFilterReachTexels() const override;
  /** Percentage-closer soft shadows of sized lights (vtkShadowMapsSoftFS). */
  std::string GetSoftShadowCode() const override;
  bool GetLinearFiltering() const override;
  /** False: depth maps are not post-processed. */
  bool GetPostProcessingFollowsFilterScale() const override;
  VTK_WRAPEXCLUDE shadowmaps::DepthOffset GetCasterDepthOffset() const override;
  VTK_WRAPEXCLUDE void ActivateReceiverResources(vtkOpenGLRenderWindow* window) override;
  VTK_WRAPEXCLUDE void SetReceiverUniforms(
    vtkShaderProgram* program, const std::string& nameSuffix) override;
  VTK_WRAPEXCLUDE void DeactivateReceiverResources() override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkDepthShadowMapRepresentation();
  ~vtkDepthShadowMapRepresentation() override;

  int Filter = PCF_2X2;
  int KernelSize = 3;
  double FilterRadius = 2.0;
  int PoissonSamples = 16;
  double ConstantBias = 4.0;
  double SlopeScaledBias = 2.0;

  /** Per-texel rotations of the Poisson disc and the soft shadows' kernels. */
  std::unique_ptr<shadowmaps::RotationNoise> Noise;

private:
  vtkDepthShadowMapRepresentation(const vtkDepthShadowMapRepresentation&) = delete;
  void operator=(const vtkDepthShadowMapRepresentation&) = delete;
};

#endif
