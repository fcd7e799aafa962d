// What the automatic pass chose for each light, and when a choice may change:
// a light seen for the first time is given its row at once; a light already
// chosen for changes its row only in still frames, so that the receivers'
// shaders (which follow a light's views) are never rebuilt while the camera
// moves, and only past the rules' margin (ChooseViewsRule). Not a VTK class.
#ifndef ShadowMapLightChoices_h
#define ShadowMapLightChoices_h

#include "ShadowMapViewsRules.h" // For ViewsRule

#include "vtkLight.h"       // For vtkWeakPointer<vtkLight>
#include "vtkRenderer.h"    // For vtkWeakPointer<vtkRenderer>
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
    /// The renderer whose camera chose the row: only it changes the row
    /// while it lives, so that a light two renderers see differently does
    /// not switch at every frame.
    vtkWeakPointer<vtkRenderer> Chooser;
  };

  /// Chooses for `renderer`'s frame's shadowed lights, in their order, among
  /// the rows within `budget` (ChooseViewsRule). Lights not in this frame keep
  /// their rows (another renderer of the pass may shadow them), as do lights
  /// another living renderer chose for; deleted lights are forgotten. Returns
  /// whether any light's row changed or is new.
  bool Update(vtkRenderer* renderer, const std::vector<SituatedLight>& lights, bool interactive,
    const std::vector<ViewsRule>& rules, double budget = 1.0);

  /// This frame's lights and what they got, in the order given to Update.
  const std::vector<Choice>& Choices() const { return this->Current; }

private:
  /// Every light chosen for and not deleted since.
  std::vector<Choice> Known;
  /// This frame's lights, in their order.
  std::vector<Choice> Current;
};
} // namespace shadowmaps

#endif
