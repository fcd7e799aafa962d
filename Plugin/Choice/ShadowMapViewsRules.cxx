#include "ShadowMapViewsRules.h"

namespace shadowmaps
{
namespace
{
/// Whether `rule` holds `situation` with its range of CosLightView widened by
/// `margin` (narrowed where negative) at the ends that are boundaries (not
/// -1, 1), and is within `budget`.
bool Holds(const ViewsRule& rule, const LightSituation& situation, double budget, double margin)
{
  if (rule.Cost > budget)
  {
    return false;
  }
  const double lowest = rule.MinimumCos > -1.0 ? rule.MinimumCos - margin : -1.0;
  const double highest = rule.MaximumCos < 1.0 ? rule.MaximumCos + margin : 1.0;
  return rule.Kind == situation.Kind && situation.CosLightView >= lowest &&
    situation.CosLightView <= highest &&
    (rule.Behind < 0 || rule.Behind == (situation.LightBehindCamera ? 1 : 0)) &&
    (rule.Parallel < 0 || rule.Parallel == (situation.ParallelCamera ? 1 : 0));
}
} // namespace

//------------------------------------------------------------------------------
const char* ViewsKindName(ViewsKind kind)
{
  switch (kind)
  {
    case ViewsKind::LiSPSM:
      return "lispsm";
    case ViewsKind::TSM:
      return "tsm";
    case ViewsKind::PSM:
      return "psm";
    case ViewsKind::Cascades:
      return "cascades";
    case ViewsKind::PSMCube:
      return "psm-cube";
    default:
      return "uniform";
  }
}

//------------------------------------------------------------------------------
const std::vector<ViewsRule>& ViewsRules()
{
  // docs/AUTOMATIC.md, "The rules": the classes of the sweep (seed 1, 160
  // cases, checked on seed 2) and the candidates' figures behind each row.
  static const std::vector<ViewsRule> rules = {
    // Suns: Kozlov's post-perspective cube had the lowest error of all, with
    // up to six maps; LiSPSM the lowest of the one-map views, in every class.
    { LightKind::Directional, -1.0, 1.0, -1, -1, ViewsKind::PSMCube, 6.0 },
    { LightKind::Directional, -1.0, 1.0, -1, -1, ViewsKind::LiSPSM, 1.0 },
    // Spots: the focused map; no warp was lower over the spots' classes.
    { LightKind::Spot, -1.0, 1.0, -1, -1, ViewsKind::Uniform, 1.0 },
    // Point lights seen side-on, in front of the camera: Kozlov's cube (six
    // faces, as the uniform ones); otherwise the uniform cube faces.
    // (For a perspective camera a cosine below 0 is a light in front of it.)
    { LightKind::Point, -0.5, 0.0, -1, -1, ViewsKind::PSM, 1.0 },
    { LightKind::Point, -1.0, 1.0, -1, -1, ViewsKind::Uniform, 1.0 },
  };
  return rules;
}

//------------------------------------------------------------------------------
int ChooseViewsRule(const std::vector<ViewsRule>& rules, const LightSituation& situation,
  int previous, double budget, double margin)
{
  const int count = static_cast<int>(rules.size());
  if (previous >= 0 && previous < count)
  {
    // An earlier (more specific) row takes the light once it holds it by
    // more than the margin; else the light keeps its row within the margin.
    for (int i = 0; i < previous; ++i)
    {
      if (Holds(rules[i], situation, budget, -margin))
      {
        return i;
      }
    }
    if (Holds(rules[previous], situation, budget, margin))
    {
      return previous;
    }
  }
  for (int i = 0; i < count; ++i)
  {
    if (Holds(rules[i], situation, budget, 0.0))
    {
      return i;
    }
  }
  return -1;
}
} // namespace shadowmaps
