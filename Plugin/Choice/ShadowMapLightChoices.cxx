#include "ShadowMapLightChoices.h"

#include <algorithm>

namespace shadowmaps
{
//------------------------------------------------------------------------------
bool LightChoices::Update(vtkRenderer* renderer, const std::vector<SituatedLight>& lights,
  bool interactive, const std::vector<ViewsRule>& rules, double budget)
{
  this->Known.erase(std::remove_if(this->Known.begin(), this->Known.end(),
                      [](const Choice& choice) { return !choice.Light; }),
    this->Known.end());
  this->Current.clear();
  bool changed = false;
  for (const SituatedLight& light : lights)
  {
    auto known = std::find_if(this->Known.begin(), this->Known.end(),
      [&](const Choice& choice) { return choice.Light == light.Light; });
    if (known == this->Known.end())
    {
      Choice fresh;
      fresh.Light = light.Light;
      fresh.Chooser = renderer;
      fresh.Rule = ChooseViewsRule(rules, light.Situation, -1, budget);
      known = this->Known.insert(this->Known.end(), fresh);
      changed = true;
    }
    else if (!interactive && (!known->Chooser || known->Chooser == renderer))
    {
      known->Chooser = renderer;
      const int rule = ChooseViewsRule(rules, light.Situation, known->Rule, budget);
      changed = changed || rule != known->Rule;
      known->Rule = rule;
    }
    known->Situation = light.Situation;
    this->Current.push_back(*known);
  }
  return changed;
}
} // namespace shadowmaps
