/**
 * @class   vtkVarianceShadowMapRepresentation
 * @brief   Filterable shadow maps: moments of the casters' light depth,
 *          blurred and mipmapped, compared by a moment reconstruction.
 *
 * Each texel stores moments of the depth of the casters it sees, along the
 * light's rays (shadowmaps::LightDepth: linear in light space, the same in
 * every view of a light, so an exponent or a blur means the same in cascades,
 * warped, spot and cube views). Moments average: the maps can be blurred
 * (BlurRadius, once per re-rendered layer), mipmapped and sampled with linear
 * filtering, and a receiver reads one filtered sample instead of a PCF kernel.
 * The receiver bounds the fraction of occluders in front of it from the
 * moments (thesis 000 on [DL06], [Lau06]; text 003):
 * - VSM: depth and depth^2; Chebyshev's inequality p = s^2 / (s^2 + (t - m)^2).
 * - EVSM2: the same on exp(c+ d) (d the depth moved to [-1, 1]), which
 *   makes the bound much tighter where occluders are far from the receiver.
 * - EVSM4: EVSM2 and the same on -exp(-c- d), the smaller of the two bounds.
 * - MSM: four powers of depth and the Hamburger reconstruction (Peters and
 *   Klein's moment shadow maps), biased toward a safe moment vector; in
 *   16-bit storage, the moments in a basis that keeps their differences
 *   (normalized integers holding shifted Chebyshev polynomials of depth).
 * - ESM: exp(c d) alone, visibility exp(c (m - t)), c the largest exponent the
 *   storage holds (the sane version of vtkShadowMapPass's exponential map, for
 *   comparison).
 *
 * Light bleeding (a receiver lit through two occluders at different depths)
 * is cut by LightBleedingReduction (off by default); acne on surfaces that slope away from the
 * light by a variance floor taken from the receiver's own depth slope over the
 * filter (plus MinimumVariance). No depth offset is needed.
 *
 * The representation of vtkVarianceShadowMapPass, which forwards its
 * parameters; it works with every views strategy.
 */
#ifndef vtkVarianceShadowMapRepresentation_h
#define vtkVarianceShadowMapRepresentation_h

#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkShadowMapRepresentation.h"
#include "vtkShadowMapSetMacros.h" // For vtkSetFiniteClampMacro

#include <map>    // For the blur per window
#include <memory> // For the blur per window

namespace shadowmaps
{
class MapBlur;
class RotationNoise;
}

class VTKRENDERINGSHADOWMAPS_EXPORT vtkVarianceShadowMapRepresentation
  : public vtkShadowMapRepresentation
{
public:
  static vtkVarianceShadowMapRepresentation* New();
  vtkTypeMacro(vtkVarianceShadowMapRepresentation, vtkShadowMapRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum MomentsType
  {
    VSM = 0,
    EVSM2 = 1,
    EVSM4 = 2,
    MSM = 3,
    ESM = 4
  };

  enum StorageType
  {
    HALF_FLOAT = 16,
    FLOAT = 32
  };

  ///@{
  /** What a texel stores and how it is compared. Clamped to [VSM, ESM]; default EVSM4. */
  void SetMoments(int moments);
  vtkGetMacro(Moments, int);
  void SetMomentsToVSM() { this->SetMoments(VSM); }
  void SetMomentsToEVSM2() { this->SetMoments(EVSM2); }
  void SetMomentsToEVSM4() { this->SetMoments(EVSM4); }
  void SetMomentsToMSM() { this->SetMoments(MSM); }
  void SetMomentsToESM() { this->SetMoments(ESM); }
  ///@}

  ///@{
  /**
   * Bits per stored value: HALF_FLOAT (16) or FLOAT (32, default). 16 bits
   * halve the memory. Half floats hold exponents up to GetMaximumExponent()
   * only (about 5.5 for EVSM instead of 42). MSM stores 16-bit normalized
   * integers instead of half floats: its four moments in a shifted Chebyshev
   * basis, where rounding costs the reconstruction little (Peters and Klein
   * quantize for the same reason with a basis of their own; this one is
   * derived in Shaders/vtkShadowMapsMomentsFS.glsl). Other values snap to the
   * nearer one.
   */
  void SetStorage(int bits);
  vtkGetMacro(Storage, int);
  void SetStorageToHalfFloat() { this->SetStorage(HALF_FLOAT); }
  void SetStorageToFloat() { this->SetStorage(FLOAT); }
  ///@}

  ///@{
  /**
   * Exponents of EVSM's positive and negative warps (EVSM2 uses the positive
   * one), applied to depth in [-1, 1]. Larger means less light bleeding and
   * less room for filtering; clamped to [0, GetMaximumExponent()] for the
   * storage and moments, with a warning when a value had to be reduced.
   * Defaults 40 and 5 (32-bit storage). ESM uses the largest exponent its
   * storage holds (GetWarpExponent), as its shadows lighten with a smaller one.
   */
  void SetPositiveExponent(double exponent);
  vtkGetMacro(PositiveExponent, double);
  void SetNegativeExponent(double exponent);
  vtkGetMacro(NegativeExponent, double);
  ///@}

  /**
   * The largest exponent whose stored values (and their squares, for EVSM)
   * the storage holds: 42 (EVSM) or 88 (ESM) for 32-bit floats, 5.54 or 11
   * for 16-bit ones.
   */
  double GetMaximumExponent() const;

  /** The exponent of the positive warp the maps use: PositiveExponent, or for ESM GetMaximumExponent(). */
  double GetWarpExponent() const;

  ///@{
  /**
   * Gaussian blur of every re-rendered map layer, in texels of a light's first
   * (finest) view: coarser cascades blur by fewer of their own texels, so the
   * penumbra keeps its world width. 0 turns the blur off. Clamped to [0, 16];
   * default 1.
   */
  vtkSetFiniteClampMacro(BlurRadius, double, 0.0, 16.0);
  vtkGetMacro(BlurRadius, double);
  ///@}

  ///@{
  /** Mipmapped maps, sampled trilinearly over the pixel's footprint. Default on. */
  vtkSetMacro(Mipmaps, bool);
  vtkGetMacro(Mipmaps, bool);
  vtkBooleanMacro(Mipmaps, bool);
  ///@}

  ///@{
  /**
   * Samples per map texel the casters are rendered with (multisampling),
   * averaged into the texel's moments: a caster covering part of a texel
   * contributes that part, which smooths the maps' edges before any blur.
   * Costs the multisample buffers' memory and their resolve per re-rendered
   * layer; limited to what GL offers, and off while a pass combines its maps
   * across processes (vtkAbstractShadowMapPass::SetExchange). Clamped to
   * [1, 8]; default 1 (off).
   */
  vtkSetClampMacro(CasterSamples, int, 1, 8);
  vtkGetMacro(CasterSamples, int);
  ///@}

  ///@{
  /**
   * Mipmaps: how elongated a pixel's footprint in the map may be before its
   * long axis picks the mipmap level. Where receivers are seen at a grazing
   * angle, the level of the long axis blurs their shadows across the short one
   * too; the level is that of the short axis, or of the long one over this
   * ratio if coarser (sharper, at the cost of some aliasing along the long
   * axis). 1: the long axis's level. Clamped to [1, 16]; default 8.
   */
  vtkSetFiniteClampMacro(Anisotropy, double, 1.0, 16.0);
  vtkGetMacro(Anisotropy, double);
  ///@}

  ///@{
  /**
   * Light-bleeding reduction: visibilities below this are cut to 0 and the
   * rest stretched over [0, 1] (a linear step). It also darkens penumbrae,
   * which widens shadows: on the benchmark scenes, where occluders rarely
   * stack within a filter's reach, 0.2 raised EVSM4's mean error from 0.59% to
   * 0.69% (docs/VARIANCE.md). Raise it for VSM where occluders stack. Clamped
   * to [0, 0.95]; default 0.
   */
  vtkSetFiniteClampMacro(LightBleedingReduction, double, 0.0, 0.95);
  vtkGetMacro(LightBleedingReduction, double);
  ///@}

  ///@{
  /**
   * Least variance of the stored depth distribution, in squared light depth
   * (the scene's depth along the light is 1), added to the variance that the
   * receiver's own slope over the filter has. Clamped to [0, 0.01]; default 1e-6.
   */
  vtkSetFiniteClampMacro(MinimumVariance, double, 0.0, 0.01);
  vtkGetMacro(MinimumVariance, double);
  ///@}

  ///@{
  /**
   * MSM: how far the stored moments are pulled toward those of a safe
   * distribution before the reconstruction, against rounding. Clamped to
   * [0, 0.01]; default 3e-5.
   */
  vtkSetFiniteClampMacro(MomentBias, double, 0.0, 0.01);
  vtkGetMacro(MomentBias, double);
  ///@}

  /**
   * The moments of light depth `depth` as the casters store them (a texel
   * with one caster surface), x to w; the values of a texel without casters
   * are those of depth 1.
   */
  void GetMomentsOfDepth(double depth, double moments[4]) const;

  VTK_WRAPEXCLUDE void GetMapStorage(shadowmaps::MapStorage& storage) const override;
  std::string GetReceiverLookupCode() const override;
  /**
   * Soft shadows of sized lights from the moments themselves
   * (vtkShadowMapsSoftMomentsFS), at a cost that does not grow with the
   * penumbra; none (hard shadows, with a warning) for ESM, which keeps no
   * variance, EVSM2, whose one warp loses the blockers' mean depth, and
   * without Mipmaps, which the filter needs.
   */
  std::string GetSoftShadowCode() const override;
  std::string GetReceiverDefinitions() const override;
  double GetFilterReachTexels() const override;
  VTK_WRAPEXCLUDE bool PostProcessMaps(vtkOpenGLRenderer* renderer, shadowmaps::TextureArray& maps,
    const std::vector<shadowmaps::RenderedLayer>& layers) override;
  /** True while BlurRadius > 0: the blur keeps one world size in every cascade. */
  bool GetPostProcessingFollowsFilterScale() const override;
  VTK_WRAPEXCLUDE void ActivateReceiverResources(vtkOpenGLRenderWindow* window) override;
  VTK_WRAPEXCLUDE void SetReceiverUniforms(
    vtkShaderProgram* program, const std::string& nameSuffix) override;
  void DeactivateReceiverResources() override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkVarianceShadowMapRepresentation();
  ~vtkVarianceShadowMapRepresentation() override;

  /** MSM in 16-bit storage: moments in the Chebyshev basis, normalized integers. */
  bool StoresChebyshevMoments() const;
  /** Exponents reduced to what the storage holds, warning when one was. */
  void ClampExponents();
  /** The shared GLSL definitions of casters and receivers. */
  std::string MomentDefinitions() const;
  /** The warps' exponents, as the uniforms of Shaders/vtkShadowMapsMomentsFS.glsl. */
  std::vector<std::pair<std::string, float>> ExponentUniforms() const;

  int Moments = EVSM4;
  int Storage = FLOAT;
  double PositiveExponent = 40.0;
  double NegativeExponent = 5.0;
  double BlurRadius = 1.0;
  bool Mipmaps = true;
  double Anisotropy = 8.0;
  int CasterSamples = 1;
  double LightBleedingReduction = 0.0;
  double MinimumVariance = 1e-6;
  double MomentBias = 3e-5;

  /** The blur's GL objects, per window (GL context) the representation serves. */
  std::map<vtkWindow*, std::unique_ptr<shadowmaps::MapBlur>> BlurPerWindow;
  /** Per-texel rotations of the soft shadows' kernels. */
  std::unique_ptr<shadowmaps::RotationNoise> Noise;

private:
  vtkVarianceShadowMapRepresentation(const vtkVarianceShadowMapRepresentation&) = delete;
  void operator=(const vtkVarianceShadowMapRepresentation&) = delete;
};

#endif
