#include "ShadowMapLightChoices.h"

#include <algorithm>

namespace shadowmaps
{
//------------------------------------------------------------------------------
bool LightChoices::Update(vtkRenderer* renderer, const std::vector<vtkLight*>& lights,
  const std::vector<LightSituation>& situations, bool interactive, const std::vector<ViewsRule>& rules,
  double budget)
{
  this->Known.erase(std::remove_if(this->Known.begin(), this->Known.end(),
                      [](const Choice& choice) { return !choice.Light; }),
    this->Known.end());
  this->Current.clear();
  bool changed = false;
  for (std::size_t i = 0; i < lights.size() && i < situations.size(); ++i)
  {
    auto known = std::find_if(this->Known.begin(), this->Known.end(),
      [&](const Choice& choice) { return choice.Light == lights[i]; });
    if (known == this->Known.end())
    {
      Choice fresh;
      fresh.Light = lights[i];
      fresh.Chooser = renderer;
      fresh.Rule = ChooseViewsRule(rules, situations[i], -1, budget);
      known = this->Known.insert(this->Known.end(), fresh);
      changed = true;
    }
    else if (!interactive && (!known->Chooser || known->Chooser == renderer))
    {
      known->Chooser = renderer;
      const int rule = ChooseViewsRule(rules, situations[i], known->Rule, budget);
      changed = changed || rule != known->Rule;
      known->Rule = rule;
    }
    known->Situation = situations[i];
    this->Current.push_back(*known);
  }
  return changed;
}
} // namespace shadowmaps
