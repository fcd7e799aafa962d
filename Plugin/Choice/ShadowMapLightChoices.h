// What the automatic pass chose for each light, and when a choice may change:
// a light seen for the first time is given its row at once; a light already
// chosen for changes its row only in still frames, so that the receivers'
// shaders (which follow a light's views) are never rebuilt while the camera
// moves, and only past the rules' margin (ChooseViewsRule). Not a VTK class.
#ifndef ShadowMapLightChoices_h
#define ShadowMapLightChoices_h

#include "ShadowMapViewsRules.h" // For ViewsRule

#include "vtkLight.h"       // For vtkWeakPointer<vtkLight>
#include "vtkWeakPointer.h"

#include <vector>


namespace shadowmaps
{
class LightChoices
{
public:
  struct Choice
  {
    vtkWeakPointer<vtkLight> Light;
    LightSituation Situation;
    /// Row of the rules (-1: none held).
    int Rule = -1;
  };

  /// Chooses for this frame's shadowed lights, in their order, among the rows
  /// within `budget` (ChooseViewsRule); lights no longer shadowed are
  /// forgotten. Returns whether any light's row changed.
  bool Update(const std::vector<vtkLight*>& lights, const std::vector<LightSituation>& situations,
    bool interactive, const std::vector<ViewsRule>& rules, double budget = 1.0);

  /// This frame's lights and what they got, in the order given to Update.
  const std::vector<Choice>& Choices() const { return this->Current; }

  /// Forgets every choice: the next frame chooses anew.
  void Clear() { this->Current.clear(); }

private:
  std::vector<Choice> Current;
};
} // namespace shadowmaps

#endif
