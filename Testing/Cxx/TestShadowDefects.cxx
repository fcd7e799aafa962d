// One test per defect of VTK's vtkShadowMapPass (GUIDE list), proving this
// project does not have it.
#include "ShadowTestUtilities.h"
#include "vtkCascadedShadowMapPass.h"
#include "ShadowMapLight.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkWarpedShadowMapViews.h"
#include "vtkWarpedShadowMapPass.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "ShadowMapVTKCompat.h"
#include "vtkGlyph3DMapper.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCubeSource.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkLineSource.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

using namespace shadowtest;

namespace
{
const glm::dvec3 SunDirection = glm::normalize(glm::dvec3(-0.4, 0.3, -1.0));

} // namespace

// Defect 1: the light camera must not take the window's aspect ratio.
TEST(ShadowDefects, NonSquareWindows)
{
  for (const auto& size : { glm::ivec2(640, 240), glm::ivec2(240, 520) })
  {
    TestScene scene(size.x, size.y);
    scene.SetSun(SunDirection);
    vtkNew<vtkWarpedShadowMapPass> pass;
    scene.Renderer->SetPass(pass);
    auto image = RenderAndCapture(scene.Window);
    const glm::dvec3 center = GroundShadowOfSphereCenter(SunDirection);
    // The shadow of a sphere is an ellipse around `center`; its extent along
    // the ground's x axis (perpendicular to the light's tilt in y) is the
    // sphere's radius, whatever the window's shape.
    EXPECT_LT(LuminanceAt(scene.Renderer, image, center + glm::dvec3(0.75, 0, 0)), ShadowedBelow);
    EXPECT_LT(LuminanceAt(scene.Renderer, image, center - glm::dvec3(0.75, 0, 0)), ShadowedBelow);
    EXPECT_GT(LuminanceAt(scene.Renderer, image, center + glm::dvec3(1.4, 0, 0)), LitAbove);
    EXPECT_GT(LuminanceAt(scene.Renderer, image, center - glm::dvec3(1.4, 0, 0)), LitAbove);
    const std::string name = "NonSquare" + std::to_string(size.x) + "x" + std::to_string(size.y);
    const std::string difference = CompareWithBaseline(image, name);
    EXPECT_TRUE(difference.empty()) << difference;
  }
}

// Defect 2: unlit draws (lighting off, lines without normals, point Gaussian
// splats) must compile and render.
TEST(ShadowDefects, UnlitActorsRender)
{
  ErrorCounter errors;
  TestScene scene;
  scene.SetSun(SunDirection);
  scene.Box->GetProperty()->LightingOff();
  scene.Box->GetProperty()->SetColor(0.0, 1.0, 0.0);
  scene.Box->GetProperty()->SetAmbient(0.0);

  vtkNew<vtkLineSource> line;
  line->SetPoint1(-6, -3, 0.2);
  line->SetPoint2(-2, -3, 3.0);
  auto lineActor = AddSourceActor(scene.Renderer, line);
  lineActor->GetProperty()->SetLineWidth(4.0);
  lineActor->GetProperty()->SetColor(1, 0, 0);

  vtkNew<vtkSphereSource> points;
  points->SetCenter(5, -3, 2);
  vtkNew<vtkPointGaussianMapper> splats;
  splats->SetInputConnection(points->GetOutputPort());
  splats->SetScaleFactor(0.2);
  vtkNew<vtkActor> splatActor;
  splatActor->SetMapper(splats);
  scene.Renderer->AddActor(splatActor);

  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors(), 0) << errors.Text();

  // The unlit box shows its flat colour: pure green, unshaded.
  const glm::ivec3 rgb = ColorAt(scene.Renderer, image, { 4.0, 1.25, 1.0 });
  EXPECT_LT(rgb[0], 10);
  EXPECT_GT(rgb[1], 245);
  // The lit geometry still has its shadow.
  EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SunDirection)), ShadowedBelow);
}

// Defect 3: PBR actors receive shadows from spot and point lights.
TEST(ShadowDefects, PbrReceivesFromSpotAndPoint)
{
  for (bool spot : { true, false })
  {
    ErrorCounter errors;
    TestScene scene;
    const glm::dvec3 position(-1.0, 0.5, 6.0);
    if (spot)
    {
      scene.SetSpot(position, 45.0);
    }
    else
    {
      scene.SetPoint(position);
    }
    scene.Ground->GetProperty()->SetInterpolationToPBR();
    scene.Ground->GetProperty()->SetRoughness(0.8);
    scene.Ground->GetProperty()->SetMetallic(0.0);
    vtkNew<vtkWarpedShadowMapPass> pass;
    scene.Renderer->SetPass(pass);
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Errors(), 0) << errors.Text();
    const double dark = LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenterFrom(position));
    const double lit = LuminanceAt(scene.Renderer, image, { 2.5, -2.5, 0.0 });
    EXPECT_LT(dark, 0.3 * lit) << (spot ? "spot" : "point");
  }
}

// Defect 4: several camera lights (a light kit) each get their own shadow map.
TEST(ShadowDefects, LightKitCameraLights)
{
  ErrorCounter errors;
  TestScene scene;
  scene.Renderer->RemoveAllLights();
  vtkNew<vtkLightKit> kit;
  kit->AddLightsToRenderer(scene.Renderer);
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors(), 0) << errors.Text();
  // Key, fill and two back lights are camera lights; the headlight casts none.
  EXPECT_EQ(pass->GetNumberOfShadowedLights(), 4);
  EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 4);

  // Each light's shadow darkens the ground: with shadows the frame is darker
  // on the ground below the sphere than without them.
  scene.Renderer->SetPass(nullptr);
  auto unshadowed = RenderAndCapture(scene.Window);
  const glm::dvec3 below(0.0, 0.3, 0.0);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, below) + 20.0,
    LuminanceAt(scene.Renderer, unshadowed, below));
  const std::string difference = CompareWithBaseline(image, "LightKit");
  EXPECT_TRUE(difference.empty()) << difference;
}

// Defect 5: translucent geometry is still drawn.
TEST(ShadowDefects, TranslucentGeometryKept)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkCubeSource> pane;
  pane->SetCenter(-4.0, -4.0, 1.0);
  pane->SetXLength(3.0);
  pane->SetYLength(0.1);
  pane->SetZLength(2.0);
  auto glass = AddSourceActor(scene.Renderer, pane);
  glass->GetProperty()->SetColor(1.0, 0.0, 0.0);
  glass->GetProperty()->SetOpacity(0.5);
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  const glm::ivec3 rgb = ColorAt(scene.Renderer, image, { -4.0, -4.1, 1.0 });
  // Its far side and the ground behind it lie in its own red-tinted shadow
  // (docs/TRANSLUCENT.md), which makes them darker: 94, 60, 60 here (111, 60,
  // 60 with the pane opted out of casting).
  EXPECT_GT(rgb[0], rgb[1] + 25) << "the red translucent pane tints what is behind it";
  EXPECT_GT(rgb[1], 20) << "and what is behind it still shows through";
}

// A renderer that asks for depth peeling gets it with the pass as without one:
// the pass's own steps pass peels overlapping translucent layers.
TEST(ShadowDefects, DepthPeelingStillPeels)
{
  auto frame = [](bool peel, bool shadows) {
    TestScene scene;
    scene.SetSun(SunDirection);
    const glm::dvec3 colors[] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    for (int i = 0; i < 3; ++i)
    {
      vtkNew<vtkSphereSource> ball;
      ball->SetCenter(-3.0 + 0.6 * i, -3.0, 1.0 + 0.4 * i);
      ball->SetRadius(1.2);
      auto actor = AddSourceActor(scene.Renderer, ball);
      actor->GetProperty()->SetColor(colors[i].x, colors[i].y, colors[i].z);
      actor->GetProperty()->SetOpacity(0.5);
      // Peeling, not their shadows on each other (which darken the layers it
      // composites), is what this compares.
      vtkNew<vtkInformation> keys;
      keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
      actor->SetPropertyKeys(keys);
    }
    scene.Renderer->SetUseDepthPeeling(peel);
    vtkNew<vtkWarpedShadowMapPass> pass;
    if (shadows)
    {
      scene.Renderer->SetPass(pass);
    }
    auto image = RenderAndCapture(scene.Window);
    scene.Renderer->SetPass(nullptr);
    pass->ReleaseGraphicsResources(scene.Window);
    return RgbBytes(image);
  };
  auto changed = [](const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    int count = 0;
    for (size_t i = 0; i + 2 < a.size(); i += 3)
    {
      count += std::abs(a[i] - b[i]) + std::abs(a[i + 1] - b[i + 1]) + std::abs(a[i + 2] - b[i + 2]) > 6;
    }
    return count;
  };
  const int withoutPass = changed(frame(false, false), frame(true, false));
  const int withPass = changed(frame(false, true), frame(true, true));
  EXPECT_GT(withoutPass, 100);
  EXPECT_GT(withPass, withoutPass / 2) << withPass << " pixels peeled with the pass, "
                                       << withoutPass << " without";
}

// Defect 6: empty texels are far, not occluders, whatever the background.
TEST(ShadowDefects, BackgroundIsNotAnOccluder)
{
  TestScene scene;
  scene.Renderer->SetBackground(0.0, 0.0, 0.0);
  scene.SetSun(glm::normalize(glm::dvec3(0.6, 0.0, -1.0)));
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  // Ground points near the map's rim where no caster is.
  for (const glm::dvec3 p :
    { glm::dvec3(-6, -3, 0), glm::dvec3(6, -3, 0), glm::dvec3(-8, 8, 0), glm::dvec3(8, 8, 0) })
  {
    EXPECT_GT(LuminanceAt(scene.Renderer, image, p), LitAbove) << p.x << "," << p.y;
  }
}

// Defect 7: a caster outside the view still casts into it.
TEST(ShadowDefects, CasterOutsideTheViewCastsIntoIt)
{
  TestScene scene;
  // A wall behind the camera, out of its view, lit at a grazing angle from behind.
  vtkNew<vtkCubeSource> wall;
  wall->SetCenter(0.0, -12.0, 1.0);
  wall->SetXLength(30.0);
  wall->SetYLength(0.5);
  wall->SetZLength(2.0);
  AddSourceActor(scene.Renderer, wall);
  scene.Renderer->GetActiveCamera()->SetPosition(0.0, -9.0, 6.0);
  scene.Renderer->ResetCameraClippingRange();
  const glm::dvec3 direction = glm::normalize(glm::dvec3(0.0, 1.0, -0.2));
  scene.SetSun(direction);
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);

  double wallDisplay[3];
  scene.Renderer->SetWorldPoint(0.0, -12.0, 1.0, 1.0);
  scene.Renderer->WorldToView();
  scene.Renderer->GetViewPoint(wallDisplay);
  EXPECT_LT(wallDisplay[1], -1.0) << "the wall is below the bottom of the view";
  // Wall top at z = 2, y = -11.75: its shadow reaches y = -11.75 + 2 / 0.2 = -1.75.
  const double shadowed = LuminanceAt(scene.Renderer, image, { -3.0, -2.5, 0.0 });
  const double lit = LuminanceAt(scene.Renderer, image, { -3.0, 1.0, 0.0 });
  EXPECT_GE(shadowed, 0.0) << "probe on screen";
  EXPECT_LT(shadowed + 25.0, lit);
}

// Defect 8: geometry changed upstream in the pipeline re-renders the maps.
TEST(ShadowDefects, UpstreamChangeMovesTheShadow)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  RenderAndCapture(scene.Window);
  const glm::dvec3 before = GroundShadowOfSphereCenter(SunDirection);
  scene.SphereSource->SetCenter(-4.0, 3.0, 1.5);
  auto image = RenderAndCapture(scene.Window);
  const glm::dvec3 after = before + glm::dvec3(-4.0, 3.0, 0.0);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, before), LitAbove);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, after), ShadowedBelow);
}

// Defect 9: point lights and spots of 90 degrees or wider cast shadows; so do
// wide spots below 90 (rendered as cube faces).
TEST(ShadowDefects, PointAndWideSpotLights)
{
  const glm::dvec3 position(-1.0, 0.5, 5.0);
  for (double cone : { 75.0, 90.0, 120.0 })
  {
    TestScene scene;
    scene.SetSpot(position, cone);
    vtkNew<vtkWarpedShadowMapPass> pass;
    scene.Renderer->SetPass(pass);
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(pass->GetNumberOfShadowMapLayers(), 6) << cone;
    EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenterFrom(position)), ShadowedBelow)
      << cone;
    if (cone >= 90.0)
    {
      EXPECT_GT(LuminanceAt(scene.Renderer, image, { 3.0, -3.0, 0.0 }), LitAbove) << cone;
    }
  }
}

// Every kind of polydata mapper casts and receives: composite data, glyphs and
// sphere impostors (whose fragment shader shapes the sphere).
TEST(ShadowDefects, CompositeGlyphAndImpostorMappers)
{
  ErrorCounter errors;
  TestScene scene;
  scene.SetSun({ 0.0, 0.0, -1.0 });
  scene.Renderer->RemoveActor(scene.Sphere);
  scene.Renderer->RemoveActor(scene.Box);

  // Composite: two blocks, a caster sphere over (-4, 0) and a small receiver
  // plate under it raised above the ground.
  vtkNew<vtkSphereSource> blockSphere;
  blockSphere->SetCenter(-4.0, 0.0, 2.0);
  blockSphere->Update();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(1);
  blocks->SetBlock(0, blockSphere->GetOutput());
  vtkNew<vtkShadowCompositeMapper> compositeMapper;
  compositeMapper->SetInputDataObject(blocks);
  vtkNew<vtkActor> composite;
  composite->SetMapper(compositeMapper);
  scene.Renderer->AddActor(composite);

  // Glyphs: cubes at two points above (0, 0).
  vtkNew<vtkPoints> glyphPoints;
  glyphPoints->InsertNextPoint(0.0, -0.3, 2.0);
  glyphPoints->InsertNextPoint(0.0, 0.3, 2.0);
  vtkNew<vtkPolyData> glyphCenters;
  glyphCenters->SetPoints(glyphPoints);
  vtkNew<vtkCubeSource> glyphShape;
  vtkNew<vtkGlyph3DMapper> glyphMapper;
  glyphMapper->SetInputData(glyphCenters);
  glyphMapper->SetSourceConnection(glyphShape->GetOutputPort());
  vtkNew<vtkActor> glyphs;
  glyphs->SetMapper(glyphMapper);
  scene.Renderer->AddActor(glyphs);

  // Sphere impostor of radius 1 above (4, 0).
  vtkNew<vtkPoints> impostorPoints;
  impostorPoints->InsertNextPoint(4.0, 0.0, 2.0);
  vtkNew<vtkPolyData> impostorCenters;
  impostorCenters->SetPoints(impostorPoints);
  vtkNew<vtkCellArray> impostorVertices;
  impostorVertices->InsertNextCell(1);
  impostorVertices->InsertCellPoint(0);
  impostorCenters->SetVerts(impostorVertices);
  vtkNew<vtkOpenGLSphereMapper> impostorMapper;
  impostorMapper->SetInputData(impostorCenters);
  impostorMapper->SetRadius(1.0);
  vtkNew<vtkActor> impostor;
  impostor->SetMapper(impostorMapper);
  scene.Renderer->AddActor(impostor);

  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(errors.Errors(), 0) << errors.Text();
  // Ground, composite block and glyphs render depth-only; the impostor keeps its
  // shader. (Counts are shader builds, not mappers.)
  EXPECT_GE(pass->GetNumberOfDepthOnlyCasterShaders(), 3);
  EXPECT_GE(pass->GetNumberOfOwnFragmentCasterShaders(), 1);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, { -4.0, -0.2, 0.0 }), ShadowedBelow) << "composite";
  EXPECT_LT(LuminanceAt(scene.Renderer, image, { 0.0, -0.3, 0.0 }), ShadowedBelow) << "glyph";
  EXPECT_LT(LuminanceAt(scene.Renderer, image, { 4.0, -0.2, 0.0 }), ShadowedBelow) << "impostor";
  // The impostor casts a disc, not its square proxy: the corner of the square
  // around its shadow stays lit.
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { 4.85, -0.85, 0.0 }), LitAbove) << "impostor corner";
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { 2.0, -3.0, 0.0 }), LitAbove);
  const std::string difference = CompareWithBaseline(image, "MapperKinds");
  EXPECT_TRUE(difference.empty()) << difference;
}

// Volumes are drawn by the delegate's volumetric step, after the shadowed
// opaque geometry and behind it where that geometry is nearer. They cast
// their absorption's shadow (docs/TRANSLUCENT.md), which follows an edit of
// their transfer functions.
TEST(ShadowDefects, VolumesRenderBehindOpaqueGeometryAndCastTheirShadows)
{
  TestScene scene;
  scene.SetSun(SunDirection);
  // A red block of constant density behind the box (seen from the camera) and
  // rising above it.
  vtkNew<vtkImageData> density;
  density->SetDimensions(13, 9, 11);
  density->SetOrigin(2.5, 3.0, 0.05);
  density->SetSpacing(0.25, 0.25, 0.25);
  density->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  std::fill_n(static_cast<unsigned char*>(density->GetScalarPointer()),
    density->GetNumberOfPoints(), 200);
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputData(density);
  vtkNew<vtkColorTransferFunction> red;
  red->AddRGBPoint(0.0, 1.0, 0.0, 0.0);
  red->AddRGBPoint(255.0, 1.0, 0.0, 0.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(255.0, 0.8);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(red);
  property->SetScalarOpacity(opacity);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  scene.Renderer->AddVolume(volume);

  const glm::dvec3 volumeAboveTheBox(4.0, 4.0, 2.4);
  const glm::dvec3 boxTop(4.0, 2.0, 1.5); // the volume lies behind it
  const glm::dvec3 groundWhereAVolumeShadowWouldBe(2.0, 5.2, 0.0);
  const glm::dvec3 sphereShadow = GroundShadowOfSphereCenter(SunDirection);
  auto plain = RenderAndCapture(scene.Window);
  const glm::ivec3 plainVolume = ColorAt(scene.Renderer, plain, volumeAboveTheBox);
  const glm::ivec3 plainBox = ColorAt(scene.Renderer, plain, boxTop);
  ASSERT_GT(plainVolume[0], plainVolume[1] + 60) << "without shadows the volume shows red";
  ASSERT_GT(plainBox[2], plainBox[0] + 40) << "and the box in front of it blue";

  vtkNew<vtkWarpedShadowMapPass> warped;
  vtkNew<vtkCascadedShadowMapPass> cascaded;
  const std::pair<vtkAbstractShadowMapPass*, std::string> passes[] = { { warped, "VolumeWarped" },
    { cascaded, "VolumeCascaded" } };
  for (const auto& [pass, name] : passes)
  {
    ErrorCounter errors;
    scene.Renderer->SetPass(pass);
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Errors(), 0) << name << ": " << errors.Text();
    const glm::ivec3 atVolume = ColorAt(scene.Renderer, image, volumeAboveTheBox);
    const glm::ivec3 atBox = ColorAt(scene.Renderer, image, boxTop);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(atVolume[c], plainVolume[c], 12) << name << ": volume, channel " << c;
      EXPECT_NEAR(atBox[c], plainBox[c], 12) << name << ": box, channel " << c;
    }
    EXPECT_LT(LuminanceAt(scene.Renderer, image, sphereShadow), ShadowedBelow)
      << name << ": the sphere still shadows the ground";
    const glm::ivec3 volumeShadow = ColorAt(scene.Renderer, image, groundWhereAVolumeShadowWouldBe);
    EXPECT_LT(LuminanceAt(scene.Renderer, image, groundWhereAVolumeShadowWouldBe), LitAbove)
      << name << ": the volume casts its shadow";
    EXPECT_GT(volumeShadow[0], volumeShadow[1] + 20) << name << ": red, its colour";
    const std::string difference = CompareWithBaseline(image, name);
    EXPECT_TRUE(difference.empty()) << difference;

    // The capture above re-rendered with a view angle off in its last bits
    // (vtkWindowToImageFilter sets it back through atan(tan())); this frame
    // renders the maps for the camera itself.
    scene.Window->Render();
    const int updates = pass->GetNumberOfShadowMapUpdates();
    opacity->AddPoint(255.0, 0.6);
    scene.Window->Render();
    EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates + 1)
      << name << ": a transfer function edit re-renders the maps";
    opacity->AddPoint(255.0, 0.8);
  }
  scene.Renderer->SetPass(nullptr);
}

namespace
{
/// Warped views with a NaN in their projection, as a degenerate scene could give.
class vtkTestNonFiniteViews : public vtkWarpedShadowMapViews
{
public:
  static vtkTestNonFiniteViews* New();
  vtkTypeMacro(vtkTestNonFiniteViews, vtkWarpedShadowMapViews);

  void FitLight(const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light) override
  {
    this->Superclass::FitLight(frame, light);
    light.Views.front().Projection[0][0] = std::nan("");
  }
};
vtkStandardNewMacro(vtkTestNonFiniteViews);

// Renders the test scene's sun through `pass` with `views`: one warning
// containing `warning`, no error, no shadowed light, and the frame is the
// unshadowed one where the sphere's shadow would fall.
void ExpectUnshadowedFrameWithOneWarning(
  vtkAbstractShadowMapPass* pass, vtkShadowMapViews* views, const std::string& warning)
{
  TestScene scene;
  scene.SetSun(glm::dvec3(-0.4, 0.3, -1.0));
  const glm::dvec3 shadowed = GroundShadowOfSphereCenter(glm::dvec3(-0.4, 0.3, -1.0));
  vtkSmartPointer<vtkImageData> unshadowed = RenderAndCapture(scene.Window);
  pass->SetViews(views);
  scene.Renderer->SetPass(pass);
  ErrorCounter counter;
  vtkSmartPointer<vtkImageData> frame = RenderAndCapture(scene.Window);
  RenderAndCapture(scene.Window);
  EXPECT_EQ(counter.Errors(), 0) << counter.Text();
  EXPECT_EQ(counter.Warnings(), 1) << counter.Text();
  EXPECT_NE(counter.Text().find(warning), std::string::npos) << counter.Text();
  EXPECT_EQ(pass->GetNumberOfShadowedLights(), 0);
  EXPECT_GT(LuminanceAt(scene.Renderer, frame, shadowed), LitAbove);
  EXPECT_NEAR(LuminanceAt(scene.Renderer, frame, shadowed),
    LuminanceAt(scene.Renderer, unshadowed, shadowed), 2.0);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}
} // namespace

// A light whose views come out non-finite casts no shadow, with one warning and
// no shader error, even when it is the only light (the receivers would otherwise
// be built for zero lights); the frame is the unshadowed one.
TEST(ShadowDefects, NonFiniteLightViewsRenderWithoutShadows)
{
  vtkNew<vtkWarpedShadowMapPass> pass;
  vtkNew<vtkTestNonFiniteViews> views;
  ExpectUnshadowedFrameWithOneWarning(pass, views, "non-finite");
  EXPECT_EQ(pass->GetNumberOfNonFiniteViews(), 1);
}

namespace
{
/// A views strategy of a user's that gives lights no view at all.
class vtkTestNoViews : public vtkWarpedShadowMapViews
{
public:
  static vtkTestNoViews* New();
  vtkTypeMacro(vtkTestNoViews, vtkWarpedShadowMapViews);

  void FitLight(const shadowmaps::ShadowFrame&, shadowmaps::ShadowLight& light) override
  {
    light.Views.clear();
  }
};
vtkStandardNewMacro(vtkTestNoViews);
} // namespace

// A light left without views casts no shadow, with one warning naming the views
// strategy and no GL or shader error; the frame is the unshadowed one.
TEST(ShadowDefects, LightsWithoutViewsRenderWithoutShadows)
{
  vtkNew<vtkDepthShadowMapPass> pass;
  vtkNew<vtkTestNoViews> views;
  ExpectUnshadowedFrameWithOneWarning(pass, views, "vtkTestNoViews");
}
