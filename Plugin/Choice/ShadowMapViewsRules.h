// The automatic pass's rules: which views a light gets in its situation
// (ShadowMapLightSituation.h). The rules are a table measured on the
// robustness sweep (docs/AUTOMATIC.md gives the figures behind each row); the
// first row that holds is chosen. A light keeps the row it had while its
// situation stays within a margin of that row's range, so that a camera
// orbiting through a boundary does not switch back and forth. Pure functions.
#ifndef ShadowMapViewsRules_h
#define ShadowMapViewsRules_h

#include "ShadowMapLightSituation.h" // For LightSituation

#include <vector>

namespace shadowmaps
{
/// The views the automatic pass chooses among (vtkAutomaticShadowMapPass's
/// ChosenViewsType has the same values).
enum class ViewsKind
{
  Uniform = 0,
  LiSPSM = 1,
  TSM = 2,
  /// PSM with Kozlov's cube for point lights and wide spots only.
  PSM = 3,
  Cascades = 4,
  /// PSM in Kozlov's post-perspective cube for every light.
  PSMCube = 5
};

/// "uniform", "lispsm", "tsm", "psm", "cascades" or "psm-cube".
const char* ViewsKindName(ViewsKind kind);

/// One row of the table: the situations it holds, and what they get.
struct ViewsRule
{
  LightKind Kind = LightKind::Directional;
  /// The range of LightSituation::CosLightView the row holds.
  double MinimumCos = -1.0;
  double MaximumCos = 1.0;
  /// -1: either; 0: only lights in front of the camera's eye plane; 1: only behind.
  int Behind = -1;
  /// -1: either; 0: perspective cameras only; 1: parallel only.
  int Parallel = -1;
  ViewsKind Views = ViewsKind::Uniform;
  /// The maps the row's views render for a light, in maps of the pass's
  /// resolution over what the light's uniform views render (one map; a point
  /// light's six faces): Kozlov's cube for a sun, up to six.
  double Cost = 1.0;
};

/// The measured table, most preferred rows first; its last row of each kind
/// holds every situation of that kind at a cost of 1.
const std::vector<ViewsRule>& ViewsRules();

/// How far past its range's ends (in CosLightView) a light keeps its row.
constexpr double ViewsRuleMargin = 0.05;

/// The row of `rules` for `situation` among those whose Cost is at most
/// `budget`, given the light's `previous` row (-1: none): an earlier row than
/// `previous` once it holds the situation by more than `margin`, else
/// `previous` while it holds the situation within `margin`, else the first
/// row that holds it; -1 if none does.
int ChooseViewsRule(const std::vector<ViewsRule>& rules, const LightSituation& situation,
  int previous, double budget = 1.0, double margin = ViewsRuleMargin);
} // namespace shadowmaps

#endif
