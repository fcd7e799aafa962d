// vtkDualDepthShadowMapPass: second-depth, midpoint and dual maps, each made by
// minimum blending or depth peeling, rendered with every bias parameter at 0.
#include "ShadowMapClosedSurfaces.h"
#include "ShadowTestUtilities.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkWarpedShadowMapViews.h"

#include "vtkActor.h"
#include "vtkContourFilter.h"
#include "vtkCubeSource.h"
#include "vtkElevationFilter.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkLineSource.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "ShadowMapVTKCompat.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSphereSource.h"
#include "vtkStripper.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

using namespace shadowtest;

namespace
{
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(-0.4, 0.3, -1.0));

const char* ModeName(int mode)
{
  return mode == vtkDualDepthShadowMapPass::SECOND_DEPTH ? "SecondDepth"
    : mode == vtkDualDepthShadowMapPass::MIDPOINT        ? "Midpoint"
                                                          : "Dual";
}

const char* MethodName(int method)
{
  return method == vtkDualDepthShadowMapPass::MINIMUM_BLENDING ? "MinimumBlending"
    : method == vtkDualDepthShadowMapPass::DEPTH_PEELING       ? "DepthPeeling"
                                                               : "Auto";
}

/// In shadow at `world`, which must be on the image (LuminanceAt is -1 off it).
::testing::AssertionResult ShadowedAt(vtkRenderer* renderer, vtkImageData* image, const glm::dvec3& world)
{
  const double luminance = LuminanceAt(renderer, image, world);
  if (luminance >= 0.0 && luminance < ShadowedBelow)
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "luminance " << luminance << " at " << world.x << ", "
                                       << world.y << ", " << world.z;
}

vtkSmartPointer<vtkDualDepthShadowMapPass> MakeUnbiasedPass(int mode, int method)
{
  auto pass = vtkSmartPointer<vtkDualDepthShadowMapPass>::New();
  pass->SetMode(mode);
  pass->SetLayerMethod(method);
  pass->SetResolution(512);
  // Every bias parameter at zero, whatever the defaults.
  pass->SetNormalOffset(0.0);
  pass->SetConstantBias(0.0);
  pass->SetSlopeScaledBias(0.0);
  return pass;
}
} // namespace

class DualDepthModes : public ::testing::TestWithParam<std::tuple<int, int>>
{
};

// The standard scene: the sphere's shadow on the ground, and the sunlit faces
// of the sphere, the box and the ground lit although nothing is biased.
TEST_P(DualDepthModes, ShadowsWithoutBias)
{
  const int mode = std::get<0>(GetParam());
  const int method = std::get<1>(GetParam());
  TestScene scene;
  scene.SetSun(SunDirection);
  auto pass = MakeUnbiasedPass(mode, method);
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_TRUE(ShadowedAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)));
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { -5, -4, 0 }), LitAbove);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, glm::dvec3(0, 0, 1.5) - SunDirection), LitAbove);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { 4, 2, 1.5 }), LitAbove);
  const std::string difference =
    CompareWithBaseline(image, std::string("DualDepth") + ModeName(mode) + MethodName(method));
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(Modes, DualDepthModes,
  ::testing::Combine(::testing::Values(vtkDualDepthShadowMapPass::SECOND_DEPTH,
                       vtkDualDepthShadowMapPass::MIDPOINT, vtkDualDepthShadowMapPass::DUAL),
    ::testing::Values(vtkDualDepthShadowMapPass::MINIMUM_BLENDING,
      vtkDualDepthShadowMapPass::DEPTH_PEELING)),
  [](const ::testing::TestParamInfo<std::tuple<int, int>>& info) {
    return std::string(ModeName(std::get<0>(info.param))) + MethodName(std::get<1>(info.param));
  });

// AUTO peels when a caster is open (the ground plane), and makes both depths
// in one pass when every caster is closed (the sphere and the box).
TEST(DualDepth, AutoPeelsOnlyForOpenCasters)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  auto pass = MakeUnbiasedPass(vtkDualDepthShadowMapPass::DUAL, vtkDualDepthShadowMapPass::AUTO);
  scene.Renderer->SetPass(pass);
  RenderAndCapture(scene.Window);
  EXPECT_EQ(pass->GetNumberOfCasterPassesPerLayer(), 2);
  EXPECT_EQ(pass->GetNumberOfCasterDraws(), 2 * 3) << "the ground, the sphere and the box, twice";
  scene.Ground->GetPropertyKeys()->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  scene.Ground->Modified();
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(pass->GetNumberOfCasterPassesPerLayer(), 1);
  EXPECT_EQ(pass->GetNumberOfCasterDraws(), 2);
  EXPECT_TRUE(ShadowedAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)));
  // The decision follows the casters' data: a wedge cut out of the sphere opens it.
  scene.SphereSource->SetEndTheta(300.0);
  RenderAndCapture(scene.Window);
  EXPECT_EQ(pass->GetNumberOfCasterPassesPerLayer(), 2);
  scene.SphereSource->SetEndTheta(360.0);
  RenderAndCapture(scene.Window);
  EXPECT_EQ(pass->GetNumberOfCasterPassesPerLayer(), 1);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

class DualDepthFilters : public ::testing::TestWithParam<int>
{
};

// Every filter of the depth maps compares each of its taps with the virtual
// surface: shadows with soft edges, lit caps without acne, no bias.
TEST_P(DualDepthFilters, EachTapUsesTheVirtualSurface)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  auto pass = MakeUnbiasedPass(vtkDualDepthShadowMapPass::DUAL, vtkDualDepthShadowMapPass::AUTO);
  pass->SetFilter(GetParam());
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_TRUE(ShadowedAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)));
  EXPECT_GT(DarkestAround(scene.Renderer, image, glm::dvec3(0, 0, 1.5) - SunDirection), LitAbove);
  EXPECT_GT(DarkestAround(scene.Renderer, image, { 4, 2, 1.5 }), LitAbove);
  EXPECT_GT(DarkestAround(scene.Renderer, image, { -5, -4, 0 }), LitAbove);
  const std::string difference =
    CompareWithBaseline(image, "DualDepthFilter" + std::to_string(GetParam()));
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(Filters, DualDepthFilters,
  ::testing::Values(vtkDualDepthShadowMapPass::HARD, vtkDualDepthShadowMapPass::PCF_NXN,
    vtkDualDepthShadowMapPass::POISSON),
  [](const ::testing::TestParamInfo<int>& info) {
    return info.param == vtkDualDepthShadowMapPass::HARD ? std::string("Hard")
      : info.param == vtkDualDepthShadowMapPass::PCF_NXN ? std::string("PCFNxN")
                                                          : std::string("Poisson");
  });

namespace
{
/// A scene of the spec's list on the test ground (the standard sphere and box
/// hidden), with where its probes are.
struct DualDepthScene
{
  std::string Name;
  std::function<void(TestScene&)> Build;
  /// Points the sun reaches: lit, with no acne.
  std::vector<glm::dvec3> Lit;
  /// Points in a shadow, contact shadows among them.
  std::vector<glm::dvec3> Shadowed;
};

glm::dvec3 GroundShadowOf(const glm::dvec3& point)
{
  return point + SunDirection * (point.z / -SunDirection.z);
}

std::vector<DualDepthScene> DualDepthScenes()
{
  std::vector<DualDepthScene> scenes;
  // An open plane casting on the ground: one surface per texel.
  scenes.push_back({ "OpenPlane",
    [](TestScene& scene) {
      vtkNew<vtkPlaneSource> plane;
      plane->SetOrigin(-1.5, -1.5, 1.5);
      plane->SetPoint1(1.5, -1.5, 1.5);
      plane->SetPoint2(-1.5, 1.5, 1.5);
      AddSourceActor(scene.Renderer, plane);
    },
    { { 0.0, -1.0, 1.5 }, { -5.0, -4.0, 0.0 } }, { GroundShadowOf({ 0.0, -1.0, 1.5 }) } });
  // An isosurface cut open by the volume's boundary (the bottom of its extent).
  scenes.push_back({ "Isosurface",
    [](TestScene& scene) {
      vtkNew<vtkRTAnalyticSource> field;
      field->SetWholeExtent(-10, 10, -10, 10, 0, 10);
      vtkNew<vtkContourFilter> contour;
      contour->SetInputConnection(field->GetOutputPort());
      contour->SetValue(0, 160.0);
      auto actor = AddSourceActor(scene.Renderer, contour);
      actor->GetMapper()->ScalarVisibilityOff();
      actor->SetScale(0.1);
      actor->SetPosition(0.0, 0.0, 1.5);
    },
    { { -5.0, -4.0, 0.0 } }, { GroundShadowOf({ 0.0, 0.0, 1.9 }) } });
  // Two boxes touching along a face, on the ground: contact shadows at their
  // feet, lit tops.
  scenes.push_back({ "TouchingBoxes",
    [](TestScene& scene) {
      AddBox(scene.Renderer, { -1.0, 0.0, 0.75 }, { 1.5, 1.5, 1.5 });
      AddBox(scene.Renderer, { 0.5, 0.0, 0.5 }, { 1.5, 1.5, 1.0 });
    },
    { { -1.0, -0.2, 1.5 }, { 0.5, -0.2, 1.0 }, { -5.0, -4.0, 0.0 } },
    { { -1.8, -0.5, 0.0 }, { -1.8, 0.5, 0.0 } } });
  // A sheet thinner than a texel, floating.
  scenes.push_back({ "ThinSheet",
    [](TestScene& scene) { AddBox(scene.Renderer, { 0.0, 0.0, 1.2 }, { 3.0, 3.0, 0.01 }); },
    { { 0.0, -1.0, 1.205 }, { -5.0, -4.0, 0.0 } }, { GroundShadowOf({ 0.0, -1.0, 1.2 }) } });
  return scenes;
}
} // namespace

class DualDepthScenesAndModes
  : public ::testing::TestWithParam<std::tuple<std::string, int>>
{
};

TEST_P(DualDepthScenesAndModes, LitFacesAndContactShadowsWithoutBias)
{
  const std::string name = std::get<0>(GetParam());
  const int mode = std::get<1>(GetParam());
  DualDepthScene spec;
  for (const auto& candidate : DualDepthScenes())
  {
    if (candidate.Name == name)
    {
      spec = candidate;
    }
  }
  TestScene scene;
  scene.SetSun(SunDirection);
  scene.Sphere->SetVisibility(false);
  scene.Box->SetVisibility(false);
  spec.Build(scene);
  auto pass = MakeUnbiasedPass(mode, vtkDualDepthShadowMapPass::AUTO);
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  for (const auto& point : spec.Lit)
  {
    EXPECT_GT(DarkestAround(scene.Renderer, image, point), LitAbove)
      << "lit, without acne, at " << point.x << ", " << point.y << ", " << point.z;
  }
  for (const auto& point : spec.Shadowed)
  {
    EXPECT_TRUE(ShadowedAt(scene.Renderer, image, point));
  }
  const std::string difference =
    CompareWithBaseline(image, "DualDepth" + name + ModeName(mode));
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(Scenes, DualDepthScenesAndModes,
  ::testing::Combine(::testing::Values("OpenPlane", "Isosurface", "TouchingBoxes", "ThinSheet"),
    ::testing::Values(vtkDualDepthShadowMapPass::SECOND_DEPTH, vtkDualDepthShadowMapPass::MIDPOINT,
      vtkDualDepthShadowMapPass::DUAL)),
  [](const ::testing::TestParamInfo<std::tuple<std::string, int>>& info) {
    return std::get<0>(info.param) + ModeName(std::get<1>(info.param));
  });

namespace
{
/// vtkShadowVirtualSurface of Shaders/vtkShadowMapsDualDepthLookupFS.glsl,
/// compiled as the receivers get it and evaluated on the GPU for each case
/// (stored x, stored y, offset).
std::vector<float> VirtualSurfaces(int mode, const std::vector<glm::vec3>& cases)
{
  const std::string functions = "uniform float vtkShadowMapResolution;\n"
                                "float vtkShadowDepthPerTexel = 0.0;\n"
                                "vec2 vtkShadowReceiverSlope = vec2(0.0);\n"
                                "#define VTK_SHADOW_FILTER 0\n#define VTK_SHADOW_DUAL_MODE " +
    std::to_string(mode) + "\n" + ShaderFile("vtkShadowMapsDualDepthLookupFS");
  std::vector<glm::vec4> inputs;
  for (const glm::vec3& c : cases)
  {
    inputs.emplace_back(c, 0.0f);
  }
  std::vector<float> surfaces;
  for (const glm::vec4& result : EvaluateGLSL(functions, "vec4(vtkShadowVirtualSurface(c.xy, c.z))", inputs))
  {
    surfaces.push_back(result.x);
  }
  return surfaces;
}
} // namespace

// The virtual surface of each mode against its closed form, with the first
// and second depth in either order (a one-pass map holds the nearest front face
// in x, the nearest back face in y), Z2 missing (the far value 1), and Z2 - Z1
// below the depth precision.
TEST(DualDepth, VirtualSurfacesMatchTheirFormulas)
{
  const float precision = 4.0f / 16777216.0f;
  const float offset = 0.01f;
  const std::vector<glm::vec3> cases = {
    { 0.3f, 0.5f, offset },         // gap 0.2: half of it above the offset
    { 0.5f, 0.3f, offset },         // the same, back face nearer
    { 0.3f, 0.31f, offset },        // gap 0.01: half of it below the offset
    { 0.3f, 1.0f, offset },         // no second surface
    { 1.0f, 0.3f, offset },         // an open surface seen from behind
    { 0.6f, 0.6f, offset },         // both surfaces at one depth
    { 0.6f, std::nextafter(0.6f, 1.0f), offset }, // closer than the precision
    { 0.6f, 1.0f, 0.0f },           // one surface, no offset
  };
  for (int mode : { vtkDualDepthShadowMapPass::SECOND_DEPTH, vtkDualDepthShadowMapPass::MIDPOINT,
         vtkDualDepthShadowMapPass::DUAL })
  {
    SCOPED_TRACE(ModeName(mode));
    const std::vector<float> surfaces = VirtualSurfaces(mode, cases);
    const float secondDepth = mode == vtkDualDepthShadowMapPass::SECOND_DEPTH ? 1.0f : 0.5f;
    // Z1 + behind, behind = gap (second depth), gap / 2 (midpoint), min(gap / 2, offset) (dual).
    auto expected = [&](float gap) {
      return mode == vtkDualDepthShadowMapPass::DUAL ? std::min(0.5f * gap, offset) : secondDepth * gap;
    };
    EXPECT_FLOAT_EQ(surfaces[0], 0.3f + expected(0.2f));
    EXPECT_FLOAT_EQ(surfaces[1], 0.3f + expected(0.2f));
    EXPECT_NEAR(surfaces[2], 0.3f + expected(0.01f), 1e-7f);
    EXPECT_FLOAT_EQ(surfaces[3], 0.3f + offset);
    EXPECT_FLOAT_EQ(surfaces[4], 0.3f + offset);
    // A receiver at Z1 stays in front of its own surface however thin it is.
    EXPECT_FLOAT_EQ(surfaces[5], 0.6f + precision);
    EXPECT_FLOAT_EQ(surfaces[6], 0.6f + precision);
    EXPECT_FLOAT_EQ(surfaces[7], 0.6f + precision);
  }
}

// What AUTO decides from: a surface is closed when every edge has two faces,
// corners repeated per face counting as one point.
TEST(DualDepth, ClosedSurfacesAreToldFromOpenOnes)
{
  auto output = [](vtkAlgorithm* source) {
    source->Update();
    return vtkPolyData::SafeDownCast(source->GetOutputDataObject(0));
  };
  vtkNew<vtkSphereSource> sphere;
  EXPECT_TRUE(shadowmaps::IsClosedSurface(output(sphere)));
  vtkNew<vtkCubeSource> cube;
  EXPECT_TRUE(shadowmaps::IsClosedSurface(output(cube)));
  vtkNew<vtkStripper> strips;
  strips->SetInputConnection(sphere->GetOutputPort());
  ASSERT_GT(output(strips)->GetNumberOfStrips(), 0);
  EXPECT_TRUE(shadowmaps::IsClosedSurface(output(strips)));
  vtkNew<vtkPlaneSource> plane;
  EXPECT_FALSE(shadowmaps::IsClosedSurface(output(plane)));
  // A sphere with a wedge cut out is open along the cut.
  vtkNew<vtkSphereSource> cut;
  cut->SetEndTheta(300.0);
  EXPECT_FALSE(shadowmaps::IsClosedSurface(output(cut)));
  // An isosurface cut by the boundary of its volume.
  vtkNew<vtkRTAnalyticSource> field;
  field->SetWholeExtent(-10, 10, -10, 10, 0, 10);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(field->GetOutputPort());
  contour->SetValue(0, 160.0);
  EXPECT_FALSE(shadowmaps::IsClosedSurface(output(contour)));
  // A higher isosurface of the whole volume stays inside it: closed.
  field->SetWholeExtent(-10, 10, -10, 10, -10, 10);
  contour->SetValue(0, 240.0);
  EXPECT_TRUE(shadowmaps::IsClosedSurface(output(contour)));
  vtkNew<vtkLineSource> line;
  EXPECT_FALSE(shadowmaps::IsClosedSurface(output(line)));
  // A closed surface with one face wound the wrong way: minimum blending would
  // take that face's entry for an exit.
  vtkNew<vtkPolyData> flipped;
  flipped->DeepCopy(output(cube));
  flipped->GetPolys()->ReverseCellAtId(0);
  EXPECT_FALSE(shadowmaps::IsClosedSurface(flipped));
  EXPECT_FALSE(shadowmaps::IsClosedData(nullptr));
}

// The cases that take the other ways through the edge pairing: corners merged
// that still leave an edge alone, a face given twice, faces that bound nothing.
TEST(DualDepth, OpenSurfacesStayOpenWhateverPointsMerge)
{
  vtkNew<vtkCubeSource> cube;
  cube->Update();
  vtkNew<vtkPolyData> lidless;
  lidless->DeepCopy(cube->GetOutput());
  vtkNew<vtkCellArray> fiveFaces;
  for (vtkIdType face = 1; face < 6; ++face)
  {
    vtkNew<vtkIdList> ids;
    lidless->GetPolys()->GetCellAtId(face, ids);
    fiveFaces->InsertNextCell(ids);
  }
  lidless->SetPolys(fiveFaces);
  EXPECT_FALSE(shadowmaps::IsClosedSurface(lidless));

  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  vtkNew<vtkPolyData> doubled;
  doubled->DeepCopy(sphere->GetOutput());
  vtkNew<vtkIdList> first;
  doubled->GetPolys()->GetCellAtId(0, first);
  doubled->GetPolys()->InsertNextCell(first);
  EXPECT_FALSE(shadowmaps::IsClosedSurface(doubled));

  vtkNew<vtkPolyData> flat;
  flat->SetPoints(sphere->GetOutput()->GetPoints());
  vtkNew<vtkCellArray> degenerate;
  const vtkIdType samePoint[3] = { 0, 0, 0 };
  degenerate->InsertNextCell(3, samePoint);
  flat->SetPolys(degenerate);
  EXPECT_FALSE(shadowmaps::IsClosedSurface(flat));
}

// The analysis reads VTK's cell arrays directly in either width of ids, and
// VTK 9.6's other storage through the cell iterator.
TEST(DualDepth, ClosednessReadsEveryStorageOfCellArrays)
{
  std::vector<std::pair<std::string, std::function<bool(vtkCellArray*)>>> storages = {
    { "32-bit ids", [](vtkCellArray* cells) { return cells->ConvertTo32BitStorage(); } },
    { "64-bit ids", [](vtkCellArray* cells) { return cells->ConvertTo64BitStorage(); } },
  };
#if VTK_SHADOW_FIXED_SIZE_CELL_ARRAYS
  storages.emplace_back("fixed-size cells, 32-bit ids",
    [](vtkCellArray* cells) { return cells->ConvertToFixedSize32BitStorage(); });
  storages.emplace_back("fixed-size cells, 64-bit ids",
    [](vtkCellArray* cells) { return cells->ConvertToFixedSize64BitStorage(); });
#endif
  for (const auto& storage : storages)
  {
    for (const double endTheta : { 360.0, 300.0 })
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetEndTheta(endTheta);
      sphere->Update();
      vtkNew<vtkPolyData> surface;
      surface->DeepCopy(sphere->GetOutput());
      ASSERT_TRUE(storage.second(surface->GetPolys())) << storage.first;
      EXPECT_EQ(shadowmaps::IsClosedSurface(surface), endTheta == 360.0)
        << storage.first << ", sphere to " << endTheta << " degrees";
    }
  }
}

// Faces naming points the surface does not have (negative, past the end, or
// past 32 bits) are bad data: a warning, and open (peeling is right for any
// casters), never a read or write outside the points.
TEST(DualDepth, FacesNamingMissingPointsCountAsOpen)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  for (const vtkIdType missing : { vtkIdType(-1), sphere->GetOutput()->GetNumberOfPoints(),
         (vtkIdType(1) << 32) + 1 })
  {
    vtkNew<vtkPolyData> surface;
    surface->DeepCopy(sphere->GetOutput());
    ASSERT_TRUE(surface->GetPolys()->ConvertTo64BitStorage()); // holds ids past 32 bits
    const vtkIdType face[3] = { 0, 1, missing };
    surface->GetPolys()->InsertNextCell(3, face);
    ErrorCounter messages;
    EXPECT_FALSE(shadowmaps::IsClosedSurface(surface)) << missing;
    EXPECT_EQ(messages.Warnings(), 1) << missing;
  }
}

// A time series changes an isosurface every frame over an open ground: the
// ground's known answer must spare the isosurface its analysis.
TEST(DualDepth, OneOpenCasterSparesTheOthersTheirAnalysis)
{
  auto actorOf = [](vtkPolyDataAlgorithm* source) {
    source->Update();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
  };
  vtkNew<vtkPlaneSource> plane;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkCubeSource> cube;
  auto ground = actorOf(plane);
  auto ball = actorOf(sphere);
  auto box = actorOf(cube);
  shadowmaps::ClosedCasters closed;
  // The smallest caster first: the plane's one cell before the cube's six.
  EXPECT_FALSE(closed.AllClosed({ { ball, 1 }, { box, 1 }, { ground, 1 } }));
  EXPECT_EQ(closed.GetNumberOfAnalyses(), 1u);
  EXPECT_FALSE(closed.AllClosed({ { ball, 2 }, { box, 2 }, { ground, 1 } }));
  EXPECT_EQ(closed.GetNumberOfAnalyses(), 1u);
  // Without the ground, both closed casters are analysed once per version.
  EXPECT_TRUE(closed.AllClosed({ { ball, 2 }, { box, 2 } }));
  EXPECT_EQ(closed.GetNumberOfAnalyses(), 3u);
  EXPECT_TRUE(closed.AllClosed({ { ball, 2 }, { box, 2 } }));
  EXPECT_EQ(closed.GetNumberOfAnalyses(), 3u);
  EXPECT_TRUE(closed.AllClosed({ { ball, 3 }, { box, 2 } }));
  EXPECT_EQ(closed.GetNumberOfAnalyses(), 4u);
  // The ground back: analysed again, its answer having been let go.
  EXPECT_FALSE(closed.AllClosed({ { ball, 3 }, { box, 2 }, { ground, 1 } }));
  EXPECT_EQ(closed.GetNumberOfAnalyses(), 5u);
}

// Every edge's sums cancel when a surface is given with its reverse (as
// vtkReverseSense and vtkAppendPolyData make two-sided geometry), yet minimum
// blending would then store each near face as its own exit: an edge of more
// than two faces leaves the surface open, whichever way they are wound.
TEST(DualDepth, EdgesOfMoreThanTwoFacesLeaveSurfacesOpen)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  vtkNew<vtkPolyData> twice;
  twice->DeepCopy(sphere->GetOutput());
  vtkNew<vtkCellArray> allTwice;
  allTwice->DeepCopy(twice->GetPolys());
  allTwice->Append(twice->GetPolys());
  twice->SetPolys(allTwice);
  EXPECT_FALSE(shadowmaps::IsClosedSurface(twice));
  vtkNew<vtkPolyData> withReverse;
  withReverse->DeepCopy(twice);
  for (vtkIdType face = sphere->GetOutput()->GetNumberOfPolys(); face < withReverse->GetNumberOfPolys();
       ++face)
  {
    withReverse->GetPolys()->ReverseCellAtId(face);
  }
  EXPECT_FALSE(shadowmaps::IsClosedSurface(withReverse));

  // Two tetrahedra sharing the edge (0, 1): four faces meet there.
  vtkNew<vtkPoints> corners;
  corners->InsertNextPoint(0.0, 0.0, 0.0);
  corners->InsertNextPoint(1.0, 0.0, 0.0);
  corners->InsertNextPoint(0.5, 1.0, 0.2);
  corners->InsertNextPoint(0.5, 0.3, 1.0);
  corners->InsertNextPoint(0.5, -1.0, 0.2);
  corners->InsertNextPoint(0.5, -0.3, -1.0);
  vtkNew<vtkCellArray> faces;
  auto tetrahedron = [&faces](vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d) {
    const vtkIdType outward[4][3] = { { a, c, b }, { a, b, d }, { a, d, c }, { b, c, d } };
    for (const auto& face : outward)
    {
      faces->InsertNextCell(3, face);
    }
  };
  tetrahedron(0, 1, 2, 3);
  tetrahedron(0, 1, 4, 5);
  vtkNew<vtkPolyData> pair;
  pair->SetPoints(corners);
  pair->SetPolys(faces);
  EXPECT_FALSE(shadowmaps::IsClosedSurface(pair));
  // Either tetrahedron alone is closed.
  vtkNew<vtkCellArray> fourFaces;
  for (vtkIdType face = 0; face < 4; ++face)
  {
    vtkNew<vtkIdList> ids;
    faces->GetCellAtId(face, ids);
    fourFaces->InsertNextCell(ids);
  }
  pair->SetPolys(fourFaces);
  EXPECT_TRUE(shadowmaps::IsClosedSurface(pair));
}

class DualDepthViewsAndModes : public ::testing::TestWithParam<std::tuple<std::string, int>>
{
};

// Each mode with cascades (stable, and tight with a LiSPSM warp per cascade), a
// LiSPSM and a TSM warp, a spot light and a point light's
// cube faces: the sphere's shadow, and the lit caps with no bias.
TEST_P(DualDepthViewsAndModes, ShadowsWithoutBias)
{
  const std::string views = std::get<0>(GetParam());
  const int mode = std::get<1>(GetParam());
  TestScene scene;
  auto pass = MakeUnbiasedPass(mode, vtkDualDepthShadowMapPass::AUTO);
  glm::dvec3 shadow = GroundShadowOfSphereCenter(SunDirection);
  glm::dvec3 sphereCap = glm::dvec3(0, 0, 1.5) - SunDirection;
  if (views == "Spot" || views == "Point")
  {
    const glm::dvec3 position(3.0, -2.0, 6.0);
    views == "Spot" ? scene.SetSpot(position, 45.0) : scene.SetPoint(position);
    shadow = GroundShadowOfSphereCenterFrom(position);
    sphereCap = glm::dvec3(0, 0, 1.5) + glm::normalize(position - glm::dvec3(0, 0, 1.5));
  }
  else
  {
    scene.SetSun(SunDirection);
  }
  if (views == "Cascaded" || views == "CascadedLiSPSM")
  {
    auto cascades = vtkSmartPointer<vtkCascadedShadowMapViews>::New();
    if (views == "CascadedLiSPSM")
    {
      cascades->SetFitModeToTight();
      cascades->SetCascadeWarpToLiSPSM();
    }
    pass->SetViews(cascades);
  }
  else if (views == "LiSPSM" || views == "TSM")
  {
    // TSM maps store depth linear in light space: the casters write it, and
    // the receivers' plane and offset are taken in it.
    auto warped = vtkSmartPointer<vtkWarpedShadowMapViews>::New();
    warped->SetWarpMode(views == "TSM" ? vtkWarpedShadowMapViews::TSM : vtkWarpedShadowMapViews::LISPSM);
    pass->SetViews(warped);
  }
  ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_TRUE(ShadowedAt(scene.Renderer, image, shadow));
  EXPECT_GT(LuminanceAt(scene.Renderer, image, sphereCap), LitAbove);
  // The open ground (under the positional lights, where they shine most) and,
  // for the sun, the box's top.
  const bool positional = views == "Spot" || views == "Point";
  EXPECT_GT(LuminanceAt(scene.Renderer, image, positional ? glm::dvec3(2, -3, 0) : glm::dvec3(-5, -4, 0)),
    LitAbove);
  if (!positional)
  {
    EXPECT_GT(LuminanceAt(scene.Renderer, image, { 4, 2, 1.5 }), LitAbove);
  }
  const std::string difference = CompareWithBaseline(image, "DualDepth" + views + ModeName(mode));
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

INSTANTIATE_TEST_SUITE_P(Views, DualDepthViewsAndModes,
  ::testing::Combine(::testing::Values("Cascaded", "CascadedLiSPSM", "LiSPSM", "TSM", "Spot", "Point"),
    ::testing::Values(vtkDualDepthShadowMapPass::SECOND_DEPTH, vtkDualDepthShadowMapPass::MIDPOINT,
      vtkDualDepthShadowMapPass::DUAL)),
  [](const ::testing::TestParamInfo<std::tuple<std::string, int>>& info) {
    return std::get<0>(info.param) + ModeName(std::get<1>(info.param));
  });

namespace
{
/// A closed L-shaped prism: a tall part (x in [0, 2], z in [0, 4]) and a step
/// (x in [2, 5], z in [0, 3]), y in [-1.5, 1.5]: a concave step in one thick
/// caster, Woo's failure case for midpoint maps.
vtkSmartPointer<vtkPolyData> StepPrism()
{
  const double profile[8][2] = { { 0, 0 }, { 2, 0 }, { 5, 0 }, { 5, 3 }, { 2, 3 }, { 2, 4 }, { 0, 4 },
    { 0, 3 } };
  vtkNew<vtkPoints> points;
  for (double y : { -1.5, 1.5 })
  {
    for (const auto& p : profile)
    {
      points->InsertNextPoint(p[0], y, p[1]);
    }
  }
  vtkNew<vtkCellArray> faces;
  for (vtkIdType i = 0; i < 8; ++i)
  {
    const vtkIdType j = (i + 1) % 8;
    const vtkIdType side[4] = { i, j, j + 8, i + 8 };
    faces->InsertNextCell(4, side);
  }
  // Each cap in three rectangles meeting at profile points.
  const vtkIdType rectangles[3][4] = { { 0, 1, 4, 7 }, { 7, 4, 5, 6 }, { 1, 2, 3, 4 } };
  for (const auto& r : rectangles)
  {
    const vtkIdType front[4] = { r[3], r[2], r[1], r[0] };
    const vtkIdType back[4] = { r[0] + 8, r[1] + 8, r[2] + 8, r[3] + 8 };
    faces->InsertNextCell(4, front);
    faces->InsertNextCell(4, back);
  }
  auto prism = vtkSmartPointer<vtkPolyData>::New();
  prism->SetPoints(points);
  prism->SetPolys(faces);
  return prism;
}
} // namespace

TEST(DualDepth, StepPrismIsClosed)
{
  EXPECT_TRUE(shadowmaps::IsClosedSurface(StepPrism()));
}

// Woo's failure case: next to the step's wall, the wall's shadow on the step
// is thinner than a texel, whose rays beside it run through the whole tall
// part: their midpoint lies below the step, which midpoint maps then light.
// Dual maps keep the virtual surface within DualOffset texels of the top.
TEST(DualDepth, ConcaveStepKeepsItsShadowInDualMode)
{
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.4, 0.0, -1.0));
  std::map<int, double> band;
  for (int mode : { vtkDualDepthShadowMapPass::MIDPOINT, vtkDualDepthShadowMapPass::DUAL })
  {
    TestScene scene;
    scene.SetSun(sun);
    scene.Sphere->SetVisibility(false);
    scene.Box->SetVisibility(false);
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(StepPrism());
    normals->AutoOrientNormalsOn();
    normals->SplittingOn();
    auto step = AddSourceActor(scene.Renderer, normals);
    step->SetPosition(-2.5, 0.0, 0.0);
    // Only closed casters: one caster pass.
    vtkNew<vtkInformation> keys;
    keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
    scene.Ground->SetPropertyKeys(keys);
    auto pass = MakeUnbiasedPass(mode, vtkDualDepthShadowMapPass::AUTO);
    pass->SetResolution(64);
    scene.Renderer->SetPass(pass);
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(pass->GetNumberOfCasterPassesPerLayer(), 1) << "the step is closed";
    // On the step, at the foot of the wall, in its shadow.
    band[mode] = LuminanceAt(scene.Renderer, image, { -0.45, -1.0, 3.0 });
    const std::string difference = CompareWithBaseline(image, std::string("DualDepthStep") + ModeName(mode));
    EXPECT_TRUE(difference.empty()) << difference;
    scene.Renderer->SetPass(nullptr);
    pass->ReleaseGraphicsResources(scene.Window);
  }
  EXPECT_GE(band[vtkDualDepthShadowMapPass::DUAL], 0.0) << "the probe is on the image";
  EXPECT_LT(band[vtkDualDepthShadowMapPass::DUAL], ShadowedBelow);
  // The scene is the failure case: midpoint maps light the wall's foot.
  EXPECT_GT(band[vtkDualDepthShadowMapPass::MIDPOINT], band[vtkDualDepthShadowMapPass::DUAL] + 40.0);
}

// The SHADOW_MAP view shows both surfaces of the map side by side: the nearest
// on the left, the next on the right, everywhere at least as far.
TEST(DualDepth, ShadowMapViewShowsBothSurfaces)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  auto pass = MakeUnbiasedPass(vtkDualDepthShadowMapPass::DUAL, vtkDualDepthShadowMapPass::AUTO);
  pass->SetAnalysisView(vtkAbstractShadowMapPass::SHADOW_MAP);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  int dims[3];
  image->GetDimensions(dims);
  const int half = dims[0] / 2;
  int nearer = 0;
  int farther = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < half; ++x)
    {
      // The same map texel in both halves (the halves have the same width).
      const auto* first = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      const auto* second = static_cast<unsigned char*>(image->GetScalarPointer(x + half, y, 0));
      nearer += second[0] + 1 < first[0] ? 1 : 0;
      farther += second[0] > first[0] + 1 ? 1 : 0;
    }
  }
  EXPECT_EQ(nearer, 0) << "a second surface nearer than the first";
  EXPECT_GT(farther, dims[1] * half / 100) << "the casters' second surfaces (and the far value) show";
  const std::string difference = CompareWithBaseline(image, "DualDepthShadowMapView");
  EXPECT_TRUE(difference.empty()) << difference;
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

// Depth peeling with a caster that draws with a texture of its own (scalars
// interpolated before mapping): the second pass reads the first pass's depths,
// not the caster's colours, so the sphere's texels keep its back as Z2.
TEST(DualDepth, PeelingKeepsTheSecondSurfaceOfATexturedCaster)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(scene.SphereSource->GetOutputPort());
  elevation->SetLowPoint(0.0, 0.0, 0.5);
  elevation->SetHighPoint(0.0, 0.0, 2.5);
  scene.Sphere->GetMapper()->SetInputConnection(elevation->GetOutputPort());
  scene.Sphere->GetMapper()->ScalarVisibilityOn();
  scene.Sphere->GetMapper()->InterpolateScalarsBeforeMappingOn();
  auto pass =
    MakeUnbiasedPass(vtkDualDepthShadowMapPass::DUAL, vtkDualDepthShadowMapPass::DEPTH_PEELING);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_TRUE(ShadowedAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)));
  std::string difference = CompareWithBaseline(image, "DualDepthPeeledTexturedCaster");
  EXPECT_TRUE(difference.empty()) << difference;
  pass->SetAnalysisView(vtkAbstractShadowMapPass::SHADOW_MAP);
  image = RenderAndCapture(scene.Window);
  difference = CompareWithBaseline(image, "DualDepthPeeledTexturedCasterMaps");
  EXPECT_TRUE(difference.empty()) << difference;
  // The casters' backs show as second surfaces behind the first, and no
  // second surface is nearer than the first.
  int dims[3];
  image->GetDimensions(dims);
  const int half = dims[0] / 2;
  int behind = 0;
  int nearer = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < half; ++x)
    {
      const int first = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0))[0];
      const int second = static_cast<unsigned char*>(image->GetScalarPointer(x + half, y, 0))[0];
      behind += second < 255 && second > first ? 1 : 0;
      nearer += second < first ? 1 : 0;
    }
  }
  EXPECT_GT(behind, 300) << "the casters' backs";
  EXPECT_EQ(nearer, 0);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

TEST(DualDepth, ParametersClamp)
{
  vtkNew<vtkDualDepthShadowMapPass> pass;
  EXPECT_EQ(pass->GetMode(), vtkDualDepthShadowMapPass::DUAL);
  EXPECT_EQ(pass->GetLayerMethod(), vtkDualDepthShadowMapPass::AUTO);
  EXPECT_EQ(pass->GetNormalOffset(), 0.0);
  EXPECT_EQ(pass->GetConstantBias(), 0.0);
  EXPECT_EQ(pass->GetSlopeScaledBias(), 0.0);
  pass->SetMode(7);
  EXPECT_EQ(pass->GetMode(), vtkDualDepthShadowMapPass::DUAL);
  pass->SetMode(-1);
  EXPECT_EQ(pass->GetMode(), vtkDualDepthShadowMapPass::SECOND_DEPTH);
  pass->SetLayerMethod(9);
  EXPECT_EQ(pass->GetLayerMethod(), vtkDualDepthShadowMapPass::DEPTH_PEELING);
  pass->SetDualOffset(-3.0);
  EXPECT_EQ(pass->GetDualOffset(), 0.0);
  pass->SetDualOffset(1e9);
  EXPECT_EQ(pass->GetDualOffset(), 64.0);
}
