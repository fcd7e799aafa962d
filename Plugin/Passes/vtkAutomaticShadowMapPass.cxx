#include "vtkAutomaticShadowMapPass.h"

#include "ShadowMapLightChoices.h"
#include "ShadowMapSceneReading.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkDualDepthShadowMapRepresentation.h"
#include "vtkShadowMapExchange.h"
#include "vtkUniformShadowMapViews.h"
#include "vtkVarianceShadowMapRepresentation.h"
#include "vtkWarpedShadowMapViews.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderer.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>

vtkStandardNewMacro(vtkAutomaticShadowMapPass);

static_assert(static_cast<int>(shadowmaps::ViewsKind::Uniform) ==
      vtkAutomaticShadowMapPass::UNIFORM_VIEWS &&
    static_cast<int>(shadowmaps::ViewsKind::LiSPSM) == vtkAutomaticShadowMapPass::LISPSM_VIEWS &&
    static_cast<int>(shadowmaps::ViewsKind::TSM) == vtkAutomaticShadowMapPass::TSM_VIEWS &&
    static_cast<int>(shadowmaps::ViewsKind::PSM) == vtkAutomaticShadowMapPass::PSM_VIEWS &&
    static_cast<int>(shadowmaps::ViewsKind::Cascades) == vtkAutomaticShadowMapPass::CASCADED_VIEWS &&
    static_cast<int>(shadowmaps::ViewsKind::PSMCube) == vtkAutomaticShadowMapPass::PSM_CUBE_VIEWS,
  "the pass's views values are the rules'");

namespace
{
vtkSmartPointer<vtkShadowMapViews> WarpedViews(int mode, int cube = vtkWarpedShadowMapViews::PSM_CUBE_AUTOMATIC)
{
  auto views = vtkSmartPointer<vtkWarpedShadowMapViews>::New();
  views->SetWarpMode(mode);
  views->SetPSMCubeMap(cube);
  return views;
}

const char* ViewsName(int views)
{
  return views >= 0 ? shadowmaps::ViewsKindName(static_cast<shadowmaps::ViewsKind>(views))
    : views == vtkAutomaticShadowMapPass::USER_VIEWS ? "user"
                                                     : "none";
}
} // namespace

struct vtkAutomaticShadowMapPass::Internals
{
  // The views a light may get, indexed by ViewsChoiceType.
  std::array<vtkSmartPointer<vtkShadowMapViews>, 6> Candidates{
    vtkSmartPointer<vtkUniformShadowMapViews>::New(),
    WarpedViews(vtkWarpedShadowMapViews::LISPSM), WarpedViews(vtkWarpedShadowMapViews::TSM),
    WarpedViews(vtkWarpedShadowMapViews::PSM), vtkSmartPointer<vtkCascadedShadowMapViews>::New(),
    WarpedViews(vtkWarpedShadowMapViews::PSM, vtkWarpedShadowMapViews::PSM_CUBE_ALWAYS)
  };
  shadowmaps::LightChoices Choices;
  // Per light of the last frame, in the order of Choices: its ViewsChoiceType.
  std::vector<int> Chosen;

  bool IsCandidate(vtkShadowMapViews* views) const
  {
    return std::find(this->Candidates.begin(), this->Candidates.end(), views) !=
      this->Candidates.end();
  }
};

//------------------------------------------------------------------------------
vtkAutomaticShadowMapPass::vtkAutomaticShadowMapPass()
  : vtkDepthShadowMapPass(vtkSmartPointer<vtkUniformShadowMapViews>::New(),
      vtkSmartPointer<vtkDualDepthShadowMapRepresentation>::New())
  , Internal(new Internals)
{
  this->NormalOffset = 0.0; // the dual test needs no offset (vtkDualDepthShadowMapPass)
  // A dual-depth map costs several depth maps' texels to draw (docs/AUTOMATIC.md).
  this->InteractiveResolutionScale = 0.5;
}

//------------------------------------------------------------------------------
vtkAutomaticShadowMapPass::~vtkAutomaticShadowMapPass() = default;

//------------------------------------------------------------------------------
vtkDualDepthShadowMapRepresentation* vtkAutomaticShadowMapPass::GetDualDepthRepresentation()
{
  return vtkDualDepthShadowMapRepresentation::SafeDownCast(this->Depth);
}

//------------------------------------------------------------------------------
void vtkAutomaticShadowMapPass::ChooseForFrame(vtkOpenGLRenderer* renderer)
{
  Internals& r = *this->Internal;
  const std::vector<shadowmaps::SituatedLight> lights = shadowmaps::ReadLightSituations(
    renderer, CASTS_SHADOWS(), LIGHT_SIZE(), VTK_MAX_SHADOWED_LIGHTS);
  bool interactive = shadowmaps::IsInteractiveRender(renderer, this->InteractiveUpdateRate);
  if (this->Exchange)
  {
    // Every process changes a light's views in the same frame, or their maps
    // could not combine.
    interactive = !this->Exchange->AnyOf(!interactive);
  }
  const std::vector<shadowmaps::ViewsRule>& rules = shadowmaps::ViewsRules();
  r.Choices.Update(renderer, lights, interactive, rules, this->CostBudget);
  for (vtkShadowMapViews* candidate : r.Candidates)
  {
    // The pass's own parameter, which the base class forwards to its views.
    candidate->SetInteractiveTexelRatio(this->GetInteractiveTexelRatio());
  }

  r.Chosen.clear();
  for (const shadowmaps::LightChoices::Choice& choice : r.Choices.Choices())
  {
    vtkShadowMapViews* current = this->GetLightViews(choice.Light);
    if (current != this->GetViews() && !r.IsCandidate(current))
    {
      r.Chosen.push_back(USER_VIEWS); // pinned by the user
      continue;
    }
    const int views = this->ViewsChoice != AUTOMATIC_VIEWS ? this->ViewsChoice
      : choice.Rule >= 0 ? static_cast<int>(rules[choice.Rule].Views)
                         : static_cast<int>(UNIFORM_VIEWS);
    r.Chosen.push_back(views);
    this->SetLightViews(choice.Light, r.Candidates[views]);
  }
}

//------------------------------------------------------------------------------
int vtkAutomaticShadowMapPass::GetLayerResolution()
{
  const std::vector<int>& chosen = this->Internal->Chosen;
  const bool cascades = std::find(chosen.begin(), chosen.end(), CASCADED_VIEWS) != chosen.end();
  return cascades ? std::max(this->Resolution / 2, 64) : this->Resolution;
}

//------------------------------------------------------------------------------
int vtkAutomaticShadowMapPass::GetChosenViews(int index)
{
  const std::vector<int>& chosen = this->Internal->Chosen;
  return index >= 0 && index < static_cast<int>(chosen.size()) ? chosen[index] : -2;
}

//------------------------------------------------------------------------------
const char* vtkAutomaticShadowMapPass::GetChosenViewsName(int index)
{
  return ViewsName(this->GetChosenViews(index));
}

//------------------------------------------------------------------------------
int vtkAutomaticShadowMapPass::GetChosenRepresentation(int index)
{
  if (this->GetChosenViews(index) == -2)
  {
    return -2;
  }
  vtkShadowMapRepresentation* representation =
    this->GetLightRepresentation(this->Internal->Choices.Choices()[index].Light);
  if (vtkDualDepthShadowMapRepresentation::SafeDownCast(representation))
  {
    return DUAL_DEPTH_REPRESENTATION;
  }
  if (vtkVarianceShadowMapRepresentation::SafeDownCast(representation))
  {
    return MOMENTS_REPRESENTATION;
  }
  return vtkDepthShadowMapRepresentation::SafeDownCast(representation) ? DEPTH_REPRESENTATION
                                                                       : OTHER_REPRESENTATION;
}

//------------------------------------------------------------------------------
const char* vtkAutomaticShadowMapPass::GetChosenRepresentationName(int index)
{
  static const char* const names[] = { "depth", "dual depth", "moments", "other" };
  const int representation = this->GetChosenRepresentation(index);
  return representation >= 0 ? names[representation] : "none";
}

//------------------------------------------------------------------------------
void vtkAutomaticShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ViewsChoice: " << this->ViewsChoice << "\n";
  os << indent << "CostBudget: " << this->CostBudget << "\n";
  const std::vector<int>& chosen = this->Internal->Chosen;
  for (std::size_t i = 0; i < chosen.size(); ++i)
  {
    os << indent << "Light " << i << ": " << ViewsName(chosen[i]) << " views\n";
  }
}
