#include "ShadowMapViewsRules.h"

namespace shadowmaps
{
namespace
{
/// Whether `rule` holds `situation` with its range of CosLightView widened by
/// `margin` (narrowed where negative) at the ends that are boundaries (not -1, 1).
bool Holds(const ViewsRule& rule, const LightSituation& situation, double margin)
{
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
  // docs/AUTOMATIC.md, "The rules": each row's class of the sweep (seed 1,
  // 160 cases) and the candidates' median and 95th percentile there.
  static const std::vector<ViewsRule> rules = {
    // Suns: Kozlov's cube had the lowest error in three of the four classes
    // of the angle to the view, and the lowest overall.
    { LightKind::Directional, -1.0, 1.0, -1, -1, ViewsKind::PSMCube },
    // Spots: the focused map; no warp was lower over the spots' classes.
    { LightKind::Spot, -1.0, 1.0, -1, -1, ViewsKind::Uniform },
    // Point lights seen side-on, in front of the camera: Kozlov's cube;
    // otherwise the uniform cube faces.
    { LightKind::Point, -0.5, 0.0, 0, -1, ViewsKind::PSM },
    { LightKind::Point, -1.0, 1.0, -1, -1, ViewsKind::Uniform },
  };
  return rules;
}

//------------------------------------------------------------------------------
int ChooseViewsRule(
  const std::vector<ViewsRule>& rules, const LightSituation& situation, int previous, double margin)
{
  const int count = static_cast<int>(rules.size());
  if (previous >= 0 && previous < count)
  {
    // An earlier (more specific) row takes the light once it holds it by
    // more than the margin; else the light keeps its row within the margin.
    for (int i = 0; i < previous; ++i)
    {
      if (Holds(rules[i], situation, -margin))
      {
        return i;
      }
    }
    if (Holds(rules[previous], situation, margin))
    {
      return previous;
    }
  }
  for (int i = 0; i < count; ++i)
  {
    if (Holds(rules[i], situation, 0.0))
    {
      return i;
    }
  }
  return -1;
}
} // namespace shadowmaps
