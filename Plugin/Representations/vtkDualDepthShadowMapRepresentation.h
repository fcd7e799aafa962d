/**
 * @class   vtkDualDepthShadowMapRepresentation
 * @brief   Shadow maps of the two nearest caster surfaces, compared through a
 *          virtual surface between them: no hand-tuned bias.
 *
 * Each texel stores the depth of the nearest caster surface along its light
 * ray, Z1, and of the next one, Z2. Receivers are compared with a virtual
 * surface behind Z1 (Shaders/vtkShadowMapsDualDepthLookupFS.glsl), so the
 * casters' lit faces are never behind it and take no acne without any depth
 * offset (thesis 000, sections on back-face, midpoint and dual shadow maps):
 * - SECOND_DEPTH (Wang and Molnar): Z2, the back of the first caster;
 * - MIDPOINT (Woo): (Z1 + Z2) / 2;
 * - DUAL (Weiskopf and Ertl): Z1 + min((Z2 - Z1) / 2, offset), which keeps
 *   the midpoint's freedom from acne without its light leaks where a thick
 *   caster's midpoint falls behind a receiver close to it.
 * The offset is DualOffset texels of world size at the receiver, converted to
 * depth along the light ray there, so that it scales with the map as the
 * pass's normal offset does. Where a texel holds a single surface (a lone
 * open surface, a silhouette) every mode compares with Z1 + offset.
 *
 * The two depths come from one caster pass with minimum blending (the nearest
 * front face and the nearest back face; right for closed casters only) or
 * from depth peeling (a second caster pass keeping the nearest surface behind
 * the first; right for any caster). LayerMethod AUTO picks the first when
 * every caster is closed (shadowmaps::IsClosedSurface, cached per caster),
 * else the second.
 *
 * The filters are the depth representation's, each tap comparing with the
 * virtual surface; its ConstantBias and SlopeScaledBias default to 0 here.
 * The representation of vtkDualDepthShadowMapPass.
 */
#ifndef vtkDualDepthShadowMapRepresentation_h
#define vtkDualDepthShadowMapRepresentation_h

#include "vtkDepthShadowMapRepresentation.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro
#include "vtkShadowMapSetMacros.h" // For vtkSetFiniteClampMacro

class VTKRENDERINGSHADOWMAPS_EXPORT vtkDualDepthShadowMapRepresentation
  : public vtkDepthShadowMapRepresentation
{
public:
  static vtkDualDepthShadowMapRepresentation* New();
  vtkTypeMacro(vtkDualDepthShadowMapRepresentation, vtkDepthShadowMapRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ModeType
  {
    SECOND_DEPTH = 0,
    MIDPOINT = 1,
    DUAL = 2
  };

  enum LayerMethodType
  {
    AUTO = 0,
    MINIMUM_BLENDING = 1,
    DEPTH_PEELING = 2
  };

  ///@{
  /** The virtual surface receivers are compared with. Clamped; default DUAL. */
  vtkSetClampMacro(Mode, int, SECOND_DEPTH, DUAL);
  vtkGetMacro(Mode, int);
  void SetModeToSecondDepth() { this->SetMode(SECOND_DEPTH); }
  void SetModeToMidpoint() { this->SetMode(MIDPOINT); }
  void SetModeToDual() { this->SetMode(DUAL); }
  ///@}

  ///@{
  /**
   * How the two depths are made: AUTO (default), MINIMUM_BLENDING (one caster
   * pass; casters that are not closed then get a wrong second depth where a
   * ray leaves them through no back face) or DEPTH_PEELING (two caster passes).
   */
  vtkSetClampMacro(LayerMethod, int, AUTO, DEPTH_PEELING);
  vtkGetMacro(LayerMethod, int);
  void SetLayerMethodToAuto() { this->SetLayerMethod(AUTO); }
  void SetLayerMethodToMinimumBlending() { this->SetLayerMethod(MINIMUM_BLENDING); }
  void SetLayerMethodToDepthPeeling() { this->SetLayerMethod(DEPTH_PEELING); }
  ///@}

  ///@{
  /**
   * The dual mode's largest distance of the virtual surface behind Z1, and
   * every mode's where a texel has one surface, in texels of world size at the
   * receiver. Clamped to [0, 64]; default 2.
   */
  vtkSetFiniteClampMacro(DualOffset, double, 0.0, 64.0);
  vtkGetMacro(DualOffset, double);
  ///@}

  VTK_WRAPEXCLUDE void GetMapStorage(shadowmaps::MapStorage& storage) const override;
  std::string GetReceiverLookupCode() const override;
  std::string GetReceiverDefinitions() const override;
  bool GetLinearFiltering() const override;
  VTK_WRAPEXCLUDE void SetReceiverUniforms(
    vtkShaderProgram* program, const std::string& nameSuffix) override;

protected:
  vtkDualDepthShadowMapRepresentation();
  ~vtkDualDepthShadowMapRepresentation() override;

  int Mode = DUAL;
  int LayerMethod = AUTO;
  double DualOffset = 2.0;

private:
  vtkDualDepthShadowMapRepresentation(const vtkDualDepthShadowMapRepresentation&) = delete;
  void operator=(const vtkDualDepthShadowMapRepresentation&) = delete;
};

#endif
