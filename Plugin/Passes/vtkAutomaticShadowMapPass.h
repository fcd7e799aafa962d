/**
 * @class   vtkAutomaticShadowMapPass
 * @brief   Shadow maps whose views each light gets are chosen from its situation.
 *
 * The pass that chooses for the user: dual-depth maps (Weiskopf and Ertl's
 * dual test, no bias to tune) whose views are chosen per light from the
 * light's kind and where it shines relative to the camera
 * (shadowmaps::LightSituation), by a table measured on the robustness sweep
 * (shadowmaps::ViewsRules(); docs/AUTOMATIC.md gives the figures behind each
 * row) within a cost budget (CostBudget): LiSPSM for suns (Kozlov's
 * post-perspective cube, up to six maps, with a budget of 6), the focused
 * uniform map for spots, the uniform cube faces for point lights but those
 * seen side-on (Kozlov's cube); cascades and TSM are there to pin.
 *
 * @code
 * renderer->SetPass(vtkNew< vtkAutomaticShadowMapPass >());
 * @endcode
 *
 * Main settings: SetResolution() (each light's budget), SetCostBudget() (6
 * allows Kozlov's cube for suns), SetViewsChoice() (SetViewsChoiceToLiSPSM(),
 * ... pins every light), SetLightViews() (one light), SetSoftShadows(). In
 * Python: vtkshadowmaps.make_pass() or make_pass("auto", cost_budget=6).
 *
 * A light seen for the first time gets its views at once. After that its
 * views change only in still frames (InteractiveUpdateRate), so that no
 * shader is built while the camera moves, and only once its situation has
 * left the chosen row's range by a margin, so that a camera orbiting
 * through a boundary does not switch back and forth.
 *
 * Resolution is each light's budget: a light in cascades gets four maps of
 * half the resolution (the memory of one map), every other light maps of the
 * full resolution. All lights share one texture array, so while any light is
 * in cascades every map has half the resolution.
 *
 * Its dual-depth maps cost several depth maps' texels to draw, so a drag that
 * must draw them draws them at half the resolution (InteractiveResolutionScale
 * 0.5 here, 1 in the other passes); the still frame after draws them at full
 * resolution again.
 *
 * The views it chooses among take the pass's InteractiveTexelRatio. A light
 * that several renderers of the pass shadow gets the views the first of them
 * to choose for it chose, from that renderer's camera.
 *
 * Pinning: SetViewsChoice() gives every light the same views (SetViews()
 * does not: the pass gives each light views of its own); SetLightViews()
 * with a views object of the user's pins one light (the pass leaves it
 * alone); SetRepresentation() replaces the dual-depth maps of every light,
 * SetLightRepresentation() those of one light (its maps are then another
 * texture array, whose code the receivers' shaders also hold). The choices are
 * read from the light and the camera only, so every process of a parallel
 * renderer chooses the same, and with an exchange (SetExchange) a frame
 * counts as interactive only where it is on every process, so that a light's
 * views change in the same frame on all of them.
 */
#ifndef vtkAutomaticShadowMapPass_h
#define vtkAutomaticShadowMapPass_h

#include "vtkDepthShadowMapPass.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro

#include <memory> // For std::unique_ptr

class vtkDualDepthShadowMapRepresentation;

class VTKRENDERINGSHADOWMAPS_EXPORT vtkAutomaticShadowMapPass : public vtkDepthShadowMapPass
{
public:
  static vtkAutomaticShadowMapPass* New();
  vtkTypeMacro(vtkAutomaticShadowMapPass, vtkDepthShadowMapPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The views a light may get (shadowmaps::ViewsKind's values). */
  enum ViewsChoiceType
  {
    UNIFORM_VIEWS = 0,
    LISPSM_VIEWS = 1,
    TSM_VIEWS = 2,
    /** PSM; Kozlov's post-perspective cube for point lights and wide spots. */
    PSM_VIEWS = 3,
    CASCADED_VIEWS = 4,
    /** PSM in Kozlov's post-perspective cube for every light. */
    PSM_CUBE_VIEWS = 5,
    /** Each light's from its situation (default). */
    AUTOMATIC_VIEWS = 6,
    /** GetChosenViews: the light's views are the user's (SetLightViews). */
    USER_VIEWS = -1
  };

  ///@{
  /** Every light's views: AUTOMATIC_VIEWS (default) or one of the others for all. */
  vtkSetClampMacro(ViewsChoice, int, UNIFORM_VIEWS, AUTOMATIC_VIEWS);
  vtkGetMacro(ViewsChoice, int);
  void SetViewsChoiceToAutomatic() { this->SetViewsChoice(AUTOMATIC_VIEWS); }
  void SetViewsChoiceToUniform() { this->SetViewsChoice(UNIFORM_VIEWS); }
  void SetViewsChoiceToLiSPSM() { this->SetViewsChoice(LISPSM_VIEWS); }
  void SetViewsChoiceToTSM() { this->SetViewsChoice(TSM_VIEWS); }
  void SetViewsChoiceToPSM() { this->SetViewsChoice(PSM_VIEWS); }
  void SetViewsChoiceToCascaded() { this->SetViewsChoice(CASCADED_VIEWS); }
  void SetViewsChoiceToPSMCube() { this->SetViewsChoice(PSM_CUBE_VIEWS); }
  ///@}

  ///@{
  /**
   * The most maps a light's views may render, in maps of the pass's
   * resolution over what its uniform views render (one map; a point light's
   * six faces). 1 (default): every light's views cost what the uniform map
   * does (LiSPSM for suns); 6 or more lets suns have Kozlov's post-perspective
   * cube, the most accurate views measured, at up to six maps
   * (docs/AUTOMATIC.md). Clamped to [1, 16]. In still frames a light whose row
   * the budget no longer allows takes the next row that holds it.
   */
  vtkSetFiniteClampMacro(CostBudget, double, 1.0, 16.0);
  vtkGetMacro(CostBudget, double);
  ///@}

  /** The representations GetChosenRepresentation reports. */
  enum RepresentationType
  {
    DEPTH_REPRESENTATION = 0,
    DUAL_DEPTH_REPRESENTATION = 1,
    MOMENTS_REPRESENTATION = 2,
    OTHER_REPRESENTATION = 3
  };

  ///@{
  /**
   * What shadowed light `index` (in the order the pass shadows them: the
   * renderer's switched-on lights that cast shadows) got in the last frame
   * with shadows: its ViewsChoiceType (USER_VIEWS for a pinned light) and
   * RepresentationType; -2 for no such light. Names: "cascades", "lispsm",
   * "tsm", "psm", "psm-cube", "uniform", "user"; "depth", "dual depth",
   * "moments", "other".
   */
  int GetChosenViews(int index);
  const char* GetChosenViewsName(int index);
  int GetChosenRepresentation(int index);
  const char* GetChosenRepresentationName(int index);
  ///@}

  /** The dual-depth representation of the pass's preset. */
  vtkDualDepthShadowMapRepresentation* GetDualDepthRepresentation();

protected:
  vtkAutomaticShadowMapPass();
  ~vtkAutomaticShadowMapPass() override;

  void ChooseForFrame(vtkOpenGLRenderer* renderer) override;
  int GetLayerResolution() override;

  int ViewsChoice = AUTOMATIC_VIEWS;
  double CostBudget = 1.0;

private:
  struct Internals;
  std::unique_ptr<Internals> Internal;

  vtkAutomaticShadowMapPass(const vtkAutomaticShadowMapPass&) = delete;
  void operator=(const vtkAutomaticShadowMapPass&) = delete;
};

#endif
