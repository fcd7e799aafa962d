/**
 * @class   vtkShadowMapCasterPass
 * @brief   Internal: turns the mappers' shaders into depth-only casters.
 *
 * vtkAbstractShadowMapPass appends this pass to the casters' render passes
 * while it renders the maps. Each mapper keeps its vertex (and geometry) shader,
 * so instancing, glyphs and clipping planes cast correctly, and gets a minimal
 * fragment shader. Mappers whose fragment shader shapes its own fragments
 * (sphere and stick impostors write gl_FragDepth, point Gaussians discard)
 * keep theirs so their silhouettes stay right.
 *
 * When the maps store values rather than depth (StoreCode set), the fragment
 * shader writes them: StoreCode is GLSL that reads `float vtkShadowCasterDepth`
 * (the fragment's window depth) and writes gl_FragData[0].
 *
 * With LinearDepth on, every caster writes gl_FragDepth = Z (linear light-space
 * depth) instead of Z / W, W taken from the window position through
 * SetWindowToInverseW; views whose W is 1 set (0, 0, 1) and keep their depth.
 */
#ifndef vtkShadowMapCasterPass_h
#define vtkShadowMapCasterPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro

#include <array>  // For WindowToInverseW
#include <string> // For StoreCode

class VTKRENDERINGSHADOWMAPS_NO_EXPORT vtkShadowMapCasterPass : public vtkOpenGLRenderPass
{
public:
  static vtkShadowMapCasterPass* New();
  vtkTypeMacro(vtkShadowMapCasterPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** vtkAbstractShadowMapPass::CasterFacesType. */
  vtkSetClampMacro(CasterFaces, int, 0, 2);
  vtkGetMacro(CasterFaces, int);

  ///@{
  /** GLSL storing the texel's values; empty: depth-only casters. */
  void SetStoreCode(const std::string& code);
  const std::string& GetStoreCode() const { return this->StoreCode; }
  ///@}

  ///@{
  /** Casters write linear depth (see the class description). Default off. */
  void SetLinearDepth(bool linear);
  bool GetLinearDepth() const { return this->LinearDepth; }
  ///@}

  /**
   * The row r with 1 / W = dot(r, (gl_FragCoord.xy, 1)) for the view being
   * rendered. A uniform: changing it rebuilds no shader.
   */
  void SetWindowToInverseW(const std::array<float, 3>& row) { this->WindowToInverseW = row; }

  /**
   * With LinearDepth on: the slope-scaled factor, the constant offset and the
   * cap of the slope-scaled term (depth units) added to the depth a
   * linear-depth view stores, in place of the rasterizer's polygon offset;
   * zeros for views that keep their depth.
   */
  void SetLinearDepthBias(const std::array<float, 3>& bias) { this->LinearDepthBias = bias; }

  ///@{
  /** Add this pass to (remove it from) the render passes of the state's props. */
  void AttachToProps(const vtkRenderState* s) { this->PreRender(s); }
  void DetachFromProps(const vtkRenderState* s) { this->PostRender(s); }
  ///@}

  ///@{
  /** Caster shaders built with the minimal fragment shader, and with the mapper's own. */
  vtkGetMacro(NumberOfDepthOnlyShaders, int);
  vtkGetMacro(NumberOfOwnFragmentShaders, int);
  ///@}

  /** Not used: the owning pass renders the casters itself. */
  void Render(const vtkRenderState*) override {}

  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO) override;
  vtkMTimeType GetShaderStageMTime() override { return this->GetMTime(); }

protected:
  vtkShadowMapCasterPass() = default;
  ~vtkShadowMapCasterPass() override = default;

  int CasterFaces = 2;
  std::string StoreCode;
  bool LinearDepth = false;
  std::array<float, 3> WindowToInverseW{ { 0.0f, 0.0f, 1.0f } };
  std::array<float, 3> LinearDepthBias{ { 0.0f, 0.0f, 0.0f } };
  int NumberOfDepthOnlyShaders = 0;
  int NumberOfOwnFragmentShaders = 0;

private:
  vtkShadowMapCasterPass(const vtkShadowMapCasterPass&) = delete;
  void operator=(const vtkShadowMapCasterPass&) = delete;
};

#endif
