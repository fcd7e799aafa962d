#include "ShadowMapLightChoices.h"

#include <algorithm>

namespace shadowmaps
{
//------------------------------------------------------------------------------
bool LightChoices::Update(const std::vector<vtkLight*>& lights,
  const std::vector<LightSituation>& situations, bool interactive, const std::vector<ViewsRule>& rules,
  double budget)
{
  std::vector<Choice> next;
  next.reserve(lights.size());
  bool changed = lights.size() != this->Current.size();
  for (std::size_t i = 0; i < lights.size() && i < situations.size(); ++i)
  {
    const auto known = std::find_if(this->Current.begin(), this->Current.end(),
      [&](const Choice& choice) { return choice.Light == lights[i]; });
    Choice choice;
    choice.Light = lights[i];
    choice.Situation = situations[i];
    if (known != this->Current.end() && interactive)
    {
      choice.Rule = known->Rule;
    }
    else
    {
      const int previous = known != this->Current.end() ? known->Rule : -1;
      choice.Rule = ChooseViewsRule(rules, situations[i], previous, budget);
    }
    changed = changed || known == this->Current.end() || known->Rule != choice.Rule;
    next.push_back(choice);
  }
  this->Current = std::move(next);
  return changed;
}
} // namespace shadowmaps
