// A user's model the right way up (Measurement/ShadowModelUp.h): the choice of
// up axis, the rotation, and a model rendered upright whichever axis it was
// made with.
#include "ShadowModelUp.h"
#include "ShadowScenes.h"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkAppendPolyData.h>
#include <vtkCamera.h>
#include <vtkCubeSource.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPropPicker.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>

namespace
{
using shadowscenes::ChooseModelUp;
using shadowscenes::UpAxis;

TEST(ShadowModelUp, ParsesTheSixAxesAndNothingElse)
{
  UpAxis axis = UpAxis::Auto;
  const std::pair<const char*, UpAxis> good[] = { { "x", UpAxis::PlusX }, { "+Y", UpAxis::PlusY },
    { "z", UpAxis::PlusZ }, { "-x", UpAxis::MinusX }, { "-y", UpAxis::MinusY }, { "-Z", UpAxis::MinusZ } };
  for (const auto& entry : good)
  {
    ASSERT_TRUE(shadowscenes::ParseUpAxis(entry.first, axis)) << entry.first;
    EXPECT_EQ(axis, entry.second) << entry.first;
  }
  for (const char* bad : { "", "w", "up", "--x", "+-x", "xy", "auto" })
  {
    EXPECT_FALSE(shadowscenes::ParseUpAxis(bad, axis)) << bad;
  }
}

TEST(ShadowModelUp, ChoosesFromTheFormatAndWhereTheModelStands)
{
  const std::array<double, 6> centred = { -1, 1, -1, 1, -1, 1 };
  const std::array<double, 6> onY = { -0.46, 0.46, -0.0006, 1.52, -1.62, 1.62 }; // Wuson.ply
  const std::array<double, 6> onZ = { -194, 1442, -205, 968, 0, 338 }; // OBJ/regr01.obj
  const std::array<double, 6> underZ = { -1, 1, -2, 2, -3, 0.001 }; // a pit, a sea floor
  const std::array<double, 6> offCentre = { -1, 1, 0, 2, 0.3, 4 }; // y at 0 by chance
  const std::array<double, 6> corner = { 0, 1, 0, 1, 0, 1 }; // every axis at 0
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".glb", onY).Axis, UpAxis::PlusY);
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".gltf", onZ).Axis, UpAxis::PlusY)
    << "glTF's specification first";
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".ply", onY).Axis, UpAxis::PlusY);
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".stl", onY).Axis, UpAxis::PlusY);
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".obj", onZ).Axis, UpAxis::PlusZ);
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".stl", underZ).Axis, UpAxis::PlusZ)
    << "not turned over: a maximum at 0 says nothing";
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".stl", offCentre).Axis, UpAxis::PlusZ)
    << "a minimum at 0 over a model not centred is no ground";
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".obj", centred).Axis, UpAxis::PlusY);
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".ply", corner).Axis, UpAxis::PlusY);
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".stl", centred).Axis, UpAxis::PlusZ);
  EXPECT_EQ(ChooseModelUp(UpAxis::Auto, ".vtp", corner).Axis, UpAxis::PlusZ);
  EXPECT_EQ(ChooseModelUp(UpAxis::MinusX, ".glb", onY).Axis, UpAxis::MinusX) << "asked for";
  const std::string line = shadowscenes::DescribeModelUp(ChooseModelUp(UpAxis::Auto, ".glb", onY));
  EXPECT_NE(line.find("+y"), std::string::npos) << line;
  EXPECT_NE(line.find("--up"), std::string::npos) << line;
}

TEST(ShadowModelUp, TheRotationTurnsTheAxisToZ)
{
  const std::pair<UpAxis, std::array<double, 3>> axes[] = { { UpAxis::PlusX, { 1, 0, 0 } },
    { UpAxis::MinusX, { -1, 0, 0 } }, { UpAxis::PlusY, { 0, 1, 0 } }, { UpAxis::MinusY, { 0, -1, 0 } },
    { UpAxis::PlusZ, { 0, 0, 1 } }, { UpAxis::MinusZ, { 0, 0, -1 } } };
  for (const auto& entry : axes)
  {
    const std::array<double, 9> m = shadowscenes::RotationToZUp(entry.first);
    for (int row = 0; row < 3; ++row)
    {
      double turned = 0.0;
      for (int column = 0; column < 3; ++column)
      {
        turned += m[3 * row + column] * entry.second[column];
      }
      EXPECT_EQ(turned, row == 2 ? 1.0 : 0.0) << shadowscenes::UpAxisName(entry.first);
    }
    const double determinant = m[0] * (m[4] * m[8] - m[5] * m[7]) -
      m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
    EXPECT_EQ(determinant, 1.0) << "a rotation, not a mirror";
  }
}

// --- rendered ---------------------------------------------------------------------

// A column 0.5 wide and 4 tall standing on a 3 x 3 plate 0.2 thick, made
// with `up` as its up axis (written out axis by axis, not through
// RotationToZUp, so that a wrong rotation shows) as PLY: upright, the plate is
// at the bottom.
std::string WriteColumnOnPlate(const std::string& name, UpAxis up)
{
  const std::string axisName = shadowscenes::UpAxisName(up);
  const int axis = axisName[1] - 'x';
  const double sign = axisName[0] == '-' ? -1.0 : 1.0;
  // Bounds of a box `width` across and from 0 to `height` along the up axis.
  const auto box = [&](double width, double height) {
    std::array<double, 6> bounds = { -width / 2, width / 2, -width / 2, width / 2, -width / 2,
      width / 2 };
    bounds[2 * axis] = std::min(0.0, sign * height);
    bounds[2 * axis + 1] = std::max(0.0, sign * height);
    return bounds;
  };
  vtkNew<vtkCubeSource> column;
  column->SetBounds(box(0.5, 4.0).data());
  vtkNew<vtkCubeSource> plate;
  plate->SetBounds(box(3.0, 0.2).data());
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(column->GetOutputPort());
  both->AddInputConnection(plate->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(both->GetOutputPort());
  const std::string path =
    (std::filesystem::temp_directory_path() / ("vtkshadows-up-" + name + ".ply")).string();
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputConnection(triangles->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
  return path;
}

// Renders the model file as `vtkshadows render` does and probes the frame:
// whether the model is what the pixel of a world point (in the scene's
// coordinates, relative to the model's ground centre) shows.
class RenderedModel
{
public:
  RenderedModel(const std::string& path, UpAxis up)
  {
    std::string error;
    this->Built = shadowscenes::BuildFileScene(this->Renderer, path, up, this->Chosen, error);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetSize(400, 300);
    this->Window->AddRenderer(this->Renderer);
    this->Window->Render();
    vtkActorCollection* actors = this->Renderer->GetActors();
    this->Model = vtkActor::SafeDownCast(actors->GetItemAsObject(actors->GetNumberOfItems() - 1));
    this->Model->GetBounds(this->Bounds.data());
  }

  bool ShowsModelAt(double dx, double dy, double height)
  {
    const double centre[2] = { 0.5 * (this->Bounds[0] + this->Bounds[1]),
      0.5 * (this->Bounds[2] + this->Bounds[3]) };
    this->Renderer->SetWorldPoint(centre[0] + dx, centre[1] + dy, this->Bounds[4] + height, 1.0);
    this->Renderer->WorldToDisplay();
    const double* display = this->Renderer->GetDisplayPoint();
    vtkNew<vtkPropPicker> picker;
    picker->Pick(display[0], display[1], 0.0, this->Renderer);
    return picker->GetViewProp() == this->Model;
  }

  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  shadowscenes::ModelUp Chosen;
  bool Built = false;
  vtkActor* Model = nullptr;
  std::array<double, 6> Bounds{};
};

// Upright: the column's top and the plate's rim near the ground are the model,
// and where an upside-down model would have its plate, at the column's height,
// there is none.
void ExpectUpright(RenderedModel& model, const std::string& what)
{
  ASSERT_TRUE(model.Built) << what;
  EXPECT_NEAR(model.Bounds[5] - model.Bounds[4], 4.0, 1e-6) << what << ": standing, not lying";
  EXPECT_TRUE(model.ShowsModelAt(0.0, 0.0, 3.8)) << what << ": the column's top";
  EXPECT_TRUE(model.ShowsModelAt(1.2, -1.2, 0.1)) << what << ": the plate, at the bottom";
  EXPECT_FALSE(model.ShowsModelAt(1.2, -1.2, 3.9)) << what << ": no plate at the top";
}

TEST(ShadowModelUpRendered, AZUpModelLandsUpright)
{
  RenderedModel model(WriteColumnOnPlate("z", UpAxis::PlusZ), UpAxis::Auto);
  EXPECT_EQ(model.Chosen.Axis, UpAxis::PlusZ) << model.Chosen.Reason;
  ExpectUpright(model, "z-up, automatic");
}

TEST(ShadowModelUpRendered, EveryAxisLandsUprightWhenNamed)
{
  for (const UpAxis up : { UpAxis::PlusX, UpAxis::MinusX, UpAxis::PlusY, UpAxis::MinusY,
         UpAxis::PlusZ, UpAxis::MinusZ })
  {
    const std::string name = shadowscenes::UpAxisName(up);
    RenderedModel model(WriteColumnOnPlate(name.substr(1) + (name[0] == '-' ? "-minus" : ""), up), up);
    ExpectUpright(model, name + ", named");
  }
}

// The probe can fail: the z-up model given as y-up lies on its side, and as
// -z-up stands on its head.
TEST(ShadowModelUpRendered, AWrongAxisIsSeen)
{
  const std::string path = WriteColumnOnPlate("z-wrong", UpAxis::PlusZ);
  RenderedModel lying(path, UpAxis::PlusY);
  ASSERT_TRUE(lying.Built);
  EXPECT_LT(lying.Bounds[5] - lying.Bounds[4], 3.5) << "lying";
  RenderedModel headfirst(path, UpAxis::MinusZ);
  ASSERT_TRUE(headfirst.Built);
  EXPECT_TRUE(headfirst.ShowsModelAt(1.2, -1.2, 3.9)) << "the plate on top";
  EXPECT_FALSE(headfirst.ShowsModelAt(1.2, -1.2, 0.1)) << "no plate at the bottom";
}
} // namespace
