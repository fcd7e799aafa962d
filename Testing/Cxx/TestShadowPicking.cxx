// Picking through a shadow pass: VTK's pickers that draw the scene with a
// hardware selector (vtkPropPicker, vtkHardwareSelector, vtkRenderedAreaPicker)
// pick exactly what they pick without the pass, under every preset and light
// kind, and the frame after a pick is the frame before it.
#include "ShadowTestUtilities.h"

#include "vtkAbstractShadowMapPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkProp3DCollection.h"
#include "vtkPropCollection.h"
#include "vtkPropPicker.h"
#include "vtkRenderedAreaPicker.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace shadowtest;

namespace
{
// What the pickers found on the test scene, in a form that compares.
struct Picks
{
  /// vtkPropPicker at each probed pixel (nullptr: nothing).
  std::vector<vtkProp*> Props;
  /// vtkPropPicker with a pick list that holds the ground only.
  std::vector<vtkProp*> FromList;
  /// The hardware selector's cells per prop over the whole window.
  std::map<vtkProp*, std::set<vtkIdType>> Cells;
  /// vtkRenderedAreaPicker's props in a rectangle around the sphere.
  std::set<vtkProp*> InArea;
};

using LightSetter = std::function<void(TestScene&)>;

std::vector<std::pair<std::string, LightSetter>> EveryLightKind()
{
  return { { "sun", [](TestScene& scene) { scene.SetSun({ -0.3, 0.2, -1.0 }); } },
    { "spot", [](TestScene& scene) { scene.SetSpot({ -2.0, 1.0, 8.0 }, 40.0); } },
    { "point light", [](TestScene& scene) { scene.SetPoint({ -2.0, 1.0, 6.0 }); } } };
}

// Display coordinates of `world` in `renderer`.
glm::dvec2 PixelOf(vtkRenderer* renderer, const glm::dvec3& world)
{
  renderer->SetWorldPoint(world.x, world.y, world.z, 1.0);
  renderer->WorldToDisplay();
  const double* display = renderer->GetDisplayPoint();
  return { display[0], display[1] };
}

std::map<vtkProp*, std::set<vtkIdType>> SelectedCells(vtkRenderer* renderer)
{
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  const int* size = renderer->GetSize();
  selector->SetArea(0, 0, size[0] - 1, size[1] - 1);
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  std::map<vtkProp*, std::set<vtkIdType>> cells;
  for (unsigned int n = 0; selection && n < selection->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = selection->GetNode(n);
    vtkProp* prop =
      selector->GetPropFromID(node->GetProperties()->Get(vtkSelectionNode::PROP_ID()));
    auto* ids = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
    for (vtkIdType i = 0; ids && i < ids->GetNumberOfTuples(); ++i)
    {
      cells[prop].insert(ids->GetValue(i));
    }
  }
  return cells;
}

Picks PickTheScene(TestScene& scene)
{
  vtkRenderer* renderer = scene.Renderer;
  Picks picks;
  // The sphere, the box, the ground in the open and under the sphere, the sky.
  const std::vector<glm::dvec2> pixels = { PixelOf(renderer, { 0.0, 0.0, 1.5 }),
    PixelOf(renderer, { 4.0, 2.0, 0.75 }), PixelOf(renderer, { -4.0, -3.0, 0.0 }),
    PixelOf(renderer, { 0.0, 0.0, 0.0 }), { 2.0, scene.Window->GetSize()[1] - 3.0 } };
  vtkNew<vtkPropPicker> picker;
  for (const glm::dvec2& pixel : pixels)
  {
    picker->Pick(pixel.x, pixel.y, 0.0, renderer);
    picks.Props.push_back(picker->GetViewProp());
  }
  picks.Cells = SelectedCells(renderer);
  vtkNew<vtkRenderedAreaPicker> areaPicker;
  const glm::dvec2 sphere = pixels.front();
  areaPicker->AreaPick(sphere.x - 20.0, sphere.y - 20.0, sphere.x + 20.0, sphere.y + 20.0, renderer);
  vtkProp3DCollection* inArea = areaPicker->GetProp3Ds();
  inArea->InitTraversal();
  while (vtkProp* prop = inArea->GetNextProp3D())
  {
    picks.InArea.insert(prop);
  }
  // VTK's renderer keeps the pick list after the pick (vtkViewport::
  // PickPropFrom does not reset it): every later selection would draw only its
  // props, and none once the picker is deleted. A pick from no list resets it.
  vtkNew<vtkPropPicker> listPicker;
  listPicker->PickFromListOn();
  listPicker->AddPickList(scene.Ground);
  for (const glm::dvec2& pixel : pixels)
  {
    listPicker->Pick(pixel.x, pixel.y, 0.0, renderer);
    picks.FromList.push_back(listPicker->GetViewProp());
  }
  renderer->PickPropFrom(0.0, 0.0, nullptr);
  return picks;
}
} // namespace

// Every preset, under a sun, a spot and a point light: the props at five
// pixels (the sphere, the box, the ground, the sky), the same from a pick list
// of the ground alone, the hardware selector's cells over the whole window and
// the area picker's props are those picked without the pass; the frame after
// the picks equals the one before them.
TEST(ShadowPicking, PickersPickAsWithoutThePass)
{
  for (const auto& light : EveryLightKind())
  {
    TestScene scene(240, 180);
    light.second(scene);
    scene.Window->Render();
    const Picks expected = PickTheScene(scene);
    ASSERT_EQ(expected.Props[0], scene.Sphere.Get()) << "the scene is not what this test expects";
    ASSERT_EQ(expected.FromList[0], scene.Ground.Get());
    ASSERT_EQ(expected.Cells.size(), 3u);
    for (const auto& kind : EveryPassKind())
    {
      const std::string what = kind.first + " under a " + light.first;
      vtkSmartPointer<vtkAbstractShadowMapPass> pass = kind.second();
      pass->SetResolution(512);
      scene.Renderer->SetPass(pass);
      const auto before = RgbBytes(RenderAndCapture(scene.Window));
      const Picks picked = PickTheScene(scene);
      EXPECT_EQ(picked.Props, expected.Props) << what << ": vtkPropPicker";
      EXPECT_EQ(picked.FromList, expected.FromList) << what << ": vtkPropPicker from a list";
      EXPECT_EQ(picked.Cells, expected.Cells) << what << ": vtkHardwareSelector's cells";
      EXPECT_EQ(picked.InArea, expected.InArea) << what << ": vtkRenderedAreaPicker";
      EXPECT_TRUE(RgbBytes(RenderAndCapture(scene.Window)) == before)
        << what << ": the frame after the picks differs from the one before";
      EXPECT_GT(pass->GetNumberOfShadowedLights(), 0) << what;
      scene.Renderer->SetPass(nullptr);
    }
  }
}
