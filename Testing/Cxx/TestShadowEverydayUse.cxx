// The ways VTK and ParaView applications really draw: a clipping plane moved
// in place, assemblies, glyph sources, followers, levels of detail, passes
// toggled on and off, several renderers and non-receivers entering the view.
// Each change must show in the next frame exactly as a fresh pass draws it.
#include "ShadowTestUtilities.h"

#include "ShadowMapVTKCompat.h" // the GL loader first

#include "ShadowMapCasting.h"

#include "vtkCascadedShadowMapPass.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkVarianceShadowMapPass.h"
#include "vtkWarpedShadowMapPass.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkCellArray.h"
#include "vtkMatrix4x4.h"
#include "vtkProperty.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkFollower.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkLODProp3D.h"
#include "vtkPlane.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropAssembly.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <limits>
#include <malloc.h>
#include <map>
#include <functional>
#include <string>

using namespace shadowtest;

namespace
{
const glm::dvec3 Down(0.0, 0.0, -1.0);
const glm::dvec3 Origin(0.0, 0.0, 0.0);

// The sphere's shadow under a sun straight above: its centre, and a point
// beside it that the sphere never shades.
const glm::dvec3 UnderSphere(0.0, 0.0, 0.0);
const glm::dvec3 AwayFromEverything(-4.0, -3.0, 0.0);

// Uniform views (vtkDepthShadowMapPass) are fitted to the scene's bounds, which
// a caster changing inside the scene leaves as they are: only its version
// tells the pass to render the maps again.

// Every pass kind, the warps the focused map's default (uniform) leaves out
// (LiSPSM, TSM with its linear depth, PSM), and casting back faces only.
PassKinds EveryPassKindAndWarp()
{
  PassKinds kinds = EveryPassKind();
  for (const int mode : { vtkWarpedShadowMapPass::LISPSM, vtkWarpedShadowMapPass::TSM,
         vtkWarpedShadowMapPass::PSM })
  {
    kinds.emplace_back("warp mode " + std::to_string(mode), [mode] {
      vtkSmartPointer<vtkWarpedShadowMapPass> pass = vtkSmartPointer<vtkWarpedShadowMapPass>::New();
      pass->SetWarpMode(mode);
      return vtkSmartPointer<vtkAbstractShadowMapPass>(pass);
    });
  }
  kinds.emplace_back("back faces", [] {
    vtkSmartPointer<vtkAbstractShadowMapPass> pass = NewPass<vtkDepthShadowMapPass>();
    pass->SetCasterFacesToBack();
    return pass;
  });
  return kinds;
}

} // namespace

// A clipping plane moved in place (as plane widgets do) moves the shadow.
TEST(ShadowEverydayUse, ClippingPlaneMovedInPlace)
{
  TestScene scene;
  scene.SetSun(Down);
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetNormal(1.0, 0.0, 0.0);
  scene.Sphere->GetMapper()->AddClippingPlane(plane);
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { -0.5, 0.0, 0.0 }), LitAbove) << "clipped half";
  EXPECT_LT(LuminanceAt(scene.Renderer, image, { 0.5, 0.0, 0.0 }), ShadowedBelow) << "kept half";
  // Clip the whole sphere away.
  plane->SetOrigin(2.0, 0.0, 0.0);
  image = RenderAndCapture(scene.Window);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { 0.5, 0.0, 0.0 }), LitAbove) << "after the move";
  EXPECT_TRUE(RgbBytes(image) == FreshPassFrame(scene, NewPass<vtkWarpedShadowMapPass>()));
  // And turn it round: the other half comes back.
  EXPECT_EQ(ChangeShownAsFresh(
    scene, pass, [&] { plane->SetNormal(-1.0, 0.0, 0.0); plane->SetOrigin(0.0, 0.0, 0.0); },
    NewPass<vtkWarpedShadowMapPass>, "normal turned"), "");
}

// A part of an assembly, its transform or its input, moves the shadow.
TEST(ShadowEverydayUse, AssemblyParts)
{
  TestScene scene;
  scene.SetSun(Down);
  scene.Renderer->RemoveActor(scene.Sphere);
  vtkNew<vtkAssembly> assembly;
  assembly->AddPart(scene.Sphere);
  scene.Renderer->AddViewProp(assembly);
  vtkNew<vtkDepthShadowMapPass> pass;
  vtkNew<vtkCubeSource> cube; // the sphere's bounds: the same fits, another shadow
  cube->SetBounds(-1.0, 1.0, -1.0, 1.0, 0.5, 2.5);
  EXPECT_EQ(ChangeShownAsFresh(
    scene, pass,
    [&] { vtkPolyDataMapper::SafeDownCast(scene.Sphere->GetMapper())->SetInputConnection(cube->GetOutputPort()); },
    NewPass<vtkDepthShadowMapPass>, "part's mapper input"), "");
  auto image = CaptureAsRendered(scene.Window);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, { 0.9, 0.9, 0.0 }), ShadowedBelow) << "cube's corner";
  EXPECT_EQ(ChangeShownAsFresh(
    scene, pass, [&] { scene.Sphere->SetPosition(3.0, -1.0, 0.0); },
    NewPass<vtkDepthShadowMapPass>, "part's position"), "");
  // Assemblies modify their parts at every draw (PokeMatrix): still frames
  // must still keep the maps.
  scene.Window->Render();
  scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfRenderedLayers(), 0) << "a still frame re-rendered the assembly";
}

// A vtkPropAssembly's part's input moves the shadow.
TEST(ShadowEverydayUse, PropAssemblyParts)
{
  TestScene scene;
  scene.SetSun(Down);
  scene.Renderer->RemoveActor(scene.Sphere);
  vtkNew<vtkPropAssembly> assembly;
  assembly->AddPart(scene.Sphere);
  scene.Renderer->AddViewProp(assembly);
  vtkNew<vtkDepthShadowMapPass> pass;
  // Half the sphere's facets, in the same bounds.
  EXPECT_EQ(ChangeShownAsFresh(
    scene, pass, [&] { scene.SphereSource->SetThetaResolution(4); },
    NewPass<vtkDepthShadowMapPass>, "part's input"), "");
  auto image = CaptureAsRendered(scene.Window);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, UnderSphere), ShadowedBelow);
  EXPECT_GT(LuminanceAt(scene.Renderer, image, { 0.75, 0.75, 0.0 }), LitAbove) << "cut away by the facets";
  scene.Window->Render();
  scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfRenderedLayers(), 0) << "a still frame re-rendered the assembly";
}

// A glyph mapper's source (its input port 1) changed upstream.
TEST(ShadowEverydayUse, GlyphSourceChanged)
{
  TestScene scene;
  scene.SetSun(Down);
  scene.Renderer->RemoveActor(scene.Sphere);
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 2.0);
  vtkNew<vtkPolyData> centers;
  centers->SetPoints(points);
  vtkNew<vtkCubeSource> shape;
  shape->SetXLength(0.5);
  shape->SetYLength(0.5);
  vtkNew<vtkGlyph3DMapper> mapper;
  mapper->SetInputData(centers);
  mapper->SetSourceConnection(shape->GetOutputPort());
  vtkNew<vtkActor> glyphs;
  glyphs->SetMapper(mapper);
  scene.Renderer->AddActor(glyphs);
  vtkNew<vtkDepthShadowMapPass> pass;
  EXPECT_EQ(ChangeShownAsFresh(
    scene, pass, [&] { shape->SetXLength(3.0); }, NewPass<vtkDepthShadowMapPass>, "glyph source"), "");
  auto image = CaptureAsRendered(scene.Window);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, { 1.2, 0.0, 0.0 }), ShadowedBelow);
}

// A follower turns with the camera: its shadow turns with it.
TEST(ShadowEverydayUse, FollowerTurnsWithTheCamera)
{
  TestScene scene;
  scene.SetSun(Down);
  scene.Renderer->RemoveActor(scene.Sphere);
  vtkNew<vtkPlaneSource> card;
  card->SetOrigin(-2.0, 0.0, -0.3);
  card->SetPoint1(2.0, 0.0, -0.3);
  card->SetPoint2(-2.0, 0.0, 0.3);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(card->GetOutputPort());
  vtkNew<vtkFollower> follower;
  follower->SetMapper(mapper);
  follower->SetPosition(0.0, 0.0, 2.0);
  follower->SetCamera(scene.Renderer->GetActiveCamera());
  scene.Renderer->AddActor(follower);
  vtkNew<vtkDepthShadowMapPass> pass;
  EXPECT_EQ(ChangeShownAsFresh(
    scene, pass, [&] { scene.Renderer->GetActiveCamera()->Azimuth(60.0); },
    NewPass<vtkDepthShadowMapPass>, "camera turned"), "");
}

// A level-of-detail prop switched to another level draws that level into
// the maps of the next frame.
TEST(ShadowEverydayUse, LevelOfDetailSwitch)
{
  TestScene scene;
  scene.SetSun(Down);
  scene.Renderer->RemoveActor(scene.Sphere);
  vtkNew<vtkCubeSource> cube; // the sphere's bounds: the same fits, another shadow
  const double* bounds = scene.Sphere->GetBounds();
  cube->SetBounds(bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]);
  vtkNew<vtkPolyDataMapper> coarse;
  coarse->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkLODProp3D> lod;
  const int fine = lod->AddLOD(scene.Sphere->GetMapper(), 0.0);
  const int boxed = lod->AddLOD(coarse, 0.0);
  lod->AutomaticLODSelectionOff();
  lod->SetSelectedLODID(fine);
  scene.Renderer->AddViewProp(lod);
  vtkNew<vtkDepthShadowMapPass> pass;
  EXPECT_EQ(ChangeShownAsFresh(
    scene, pass, [&] { lod->SetSelectedLODID(boxed); }, NewPass<vtkDepthShadowMapPass>, "level switched"), "");
  auto image = CaptureAsRendered(scene.Window);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, { 0.9, 0.9, 0.0 }), ShadowedBelow) << "box's corner";
}

// Layers rendered while the user drags (where vtkLODActor and ParaView draw
// coarse levels chosen by time) are rendered again for the still frame.
TEST(ShadowEverydayUse, StillFrameAfterADragRendersItsLayers)
{
  TestScene scene;
  scene.SetSun(Down);
  vtkNew<vtkDepthShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  scene.Window->SetDesiredUpdateRate(1.0e6);
  scene.Window->Render();
  const int layers = pass->GetNumberOfShadowMapLayers();
  scene.Window->SetDesiredUpdateRate(0.0001);
  scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfRenderedLayers(), layers);
  scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfRenderedLayers(), 0) << "a still camera re-rendered a layer";
}

// Replacing or deleting a pass leaves no maps behind: 40 toggles of each
// pass, each time a new one (the README's one line), keep memory flat
// (before passes released their maps when replaced: 8 MiB per toggle of
// cascades, 64 MiB per toggle of dual depth).
TEST(ShadowEverydayUse, TogglingPassesKeepsMemoryFlat)
{
  const PassKinds kinds = EveryPassKind();
  // Freed blocks of 1 MiB or more go back to the system at once: otherwise
  // glibc raises its mmap threshold after the first map is freed and keeps
  // later maps in a heap that resident memory never shrinks from.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  TestScene scene(160, 120);
  scene.SetSun(Down);
  for (const auto& kind : kinds)
  {
    auto toggle = [&] {
      vtkSmartPointer<vtkAbstractShadowMapPass> pass = kind.second();
      scene.Renderer->SetPass(pass);
      scene.Window->Render();
      scene.Renderer->SetPass(nullptr);
      scene.Window->Render();
    };
    // Resident memory after a toggle, once the GL has finished with it; a map
    // freed a frame late (the GL's or the allocator's timing) shows as a
    // transient step of one map, so each side takes its least of ten toggles.
    auto leastOfTenToggles = [&] {
      double least = std::numeric_limits<double>::max();
      for (int i = 0; i < 10; ++i)
      {
        toggle();
        scene.Window->WaitForCompletion();
        least = std::min(least, ResidentMiB());
      }
      return least;
    };
    leastOfTenToggles(); // what the first frames allocate once
    const double before = leastOfTenToggles();
    for (int i = 0; i < 10; ++i)
    {
      toggle();
    }
    const double grown = leastOfTenToggles() - before;
    // One toggle's maps are 8 MiB (16-bit depth) to 64 MiB (two floats and a
    // second output): a leak of any of them grows memory by 160 MiB or more.
    // Memory takes single steps of one map (8 MiB after depth's loop here,
    // returned when the next kind runs; 16 MiB once within 200 toggles of dual
    // depth in Measurement/toggle_memory.py, flat before and after it), not
    // one per toggle.
    EXPECT_LT(grown, 32.0) << kind.first << ": MiB grown over 40 toggles";
    std::cout << kind.first << ": " << grown << " MiB grown over 40 toggles\n";
  }
}

// A pass kept by the user and taken off the renderer releases its maps; put
// back, it renders them again.
TEST(ShadowEverydayUse, PassTakenOffReleasesItsMaps)
{
  TestScene scene;
  scene.SetSun(Down);
  vtkNew<vtkCascadedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  RenderAndCapture(scene.Window);
  EXPECT_GT(pass->GetShadowMapMemory(), 0u);
  scene.Renderer->SetPass(nullptr);
  RenderAndCapture(scene.Window);
  EXPECT_EQ(pass->GetShadowMapMemory(), 0u) << "maps held by a pass no renderer uses";
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, UnderSphere), ShadowedBelow);
}

// A prop that receives no shadow entering or leaving the view changes no
// other prop's shader.
TEST(ShadowEverydayUse, NonReceiverEnteringBuildsNoShader)
{
  TestScene scene;
  scene.SetSun(Down);
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  vtkSmartPointer<vtkActor> marker = AddBox(scene.Renderer, { -4.0, 3.0, 0.5 }, { 1.0, 1.0, 1.0 });
  vtkNew<vtkInformation> keys;
  keys->Set(vtkAbstractShadowMapPass::RECEIVES_SHADOWS(), 0);
  marker->SetPropertyKeys(keys);
  RenderAndCapture(scene.Window);
  marker->SetVisibility(false);
  RenderAndCapture(scene.Window);
  marker->SetVisibility(true);
  RenderAndCapture(scene.Window);
  const int builds = pass->GetNumberOfShaderBuilds();
  marker->SetVisibility(false);
  RenderAndCapture(scene.Window);
  marker->SetVisibility(true);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_EQ(pass->GetNumberOfShaderBuilds(), builds);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, UnderSphere), ShadowedBelow);
}

namespace
{
const glm::dvec3 SideSun = glm::normalize(glm::dvec3(-0.3, 0.2, -1.0));

// `scene`'s renderer on the left half of its window, `right` on the right
// half with the same actors and the scene's light.
void ShareSceneWithRightHalf(TestScene& scene, vtkRenderer* right)
{
  scene.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  right->SetBackground(0.2, 0.3, 0.4);
  for (vtkActor* actor : { scene.Ground.Get(), scene.Sphere.Get(), scene.Box.Get() })
  {
    right->AddActor(actor);
  }
  right->SetLightFollowCamera(false);
  right->AutomaticLightCreationOff();
  scene.Renderer->GetLights()->InitTraversal();
  right->AddLight(scene.Renderer->GetLights()->GetNextItem());
  scene.Window->AddRenderer(right);
}

// `renderer`'s camera looks at the scene from another side than the test scene's.
void LookFromAnotherSide(vtkRenderer* renderer)
{
  renderer->GetActiveCamera()->SetPosition(12.0, 6.0, 14.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCameraClippingRange();
}

// A spot over the scene, lighting it besides its sun (another light count and
// kind than the sun's alone: other shader code).
vtkSmartPointer<vtkLight> SpotOverTheScene()
{
  auto spot = vtkSmartPointer<vtkLight>::New();
  spot->SetLightTypeToSceneLight();
  spot->SetPositional(true);
  spot->SetPosition(-1.0, 0.5, 5.0);
  spot->SetFocalPoint(0.0, 0.0, 0.0);
  spot->SetConeAngle(40.0);
  spot->SetAttenuationValues(1.0, 0.0, 0.0);
  return spot;
}

// The test scene on the left half, seen from another side on the right, both
// drawn through one cascaded pass.
struct TwoSidesOneCascadedPass
{
  TestScene Scene{ 480, 240 };
  vtkNew<vtkRenderer> Right;
  vtkNew<vtkCascadedShadowMapPass> Pass;

  TwoSidesOneCascadedPass()
  {
    this->Scene.SetSun(SideSun);
    ShareSceneWithRightHalf(this->Scene, this->Right);
    LookFromAnotherSide(this->Right);
    this->Scene.Renderer->SetPass(this->Pass);
    this->Right->SetPass(this->Pass);
  }
};
} // namespace

// One pass shared by two renderers side by side: each shows its own view's
// shadows, as a fresh pass would, and still cameras re-render no layer.
TEST(ShadowEverydayUse, TwoRenderersShareAPass)
{
  TwoSidesOneCascadedPass two;
  TestScene& scene = two.Scene;
  vtkRenderer* right = two.Right;
  vtkCascadedShadowMapPass* pass = two.Pass;
  scene.Window->Render();
  const int updates = pass->GetNumberOfShadowMapUpdates();
  scene.Window->Render();
  const auto shared = RgbBytes(CaptureAsRendered(scene.Window));
  EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates) << "still cameras re-rendered the maps";
  vtkNew<vtkCascadedShadowMapPass> leftFresh;
  vtkNew<vtkCascadedShadowMapPass> rightFresh;
  scene.Renderer->SetPass(leftFresh);
  right->SetPass(rightFresh);
  scene.Window->Render();
  const auto separate = RgbBytes(CaptureAsRendered(scene.Window));
  EXPECT_TRUE(shared == separate) << "a shared pass draws other shadows than a pass per renderer";
  auto image = CaptureAsRendered(scene.Window);
  EXPECT_LT(LuminanceAt(right, image, GroundShadowOfSphereCenter(SideSun)), ShadowedBelow);
}

// A window of two renderers captured by vtkWindowToImageFilter, whose own
// render derives each renderer's projection by another path (about 5e-9
// apart): no map is rendered for the capture, nor for the plain frame after
// it, and the capture is the plain frame.
TEST(ShadowEverydayUse, CapturingTwoRenderersRendersNoMap)
{
  TwoSidesOneCascadedPass two;
  TestScene& scene = two.Scene;
  vtkCascadedShadowMapPass* pass = two.Pass;
  scene.Window->Render();
  scene.Window->Render();
  const int updates = pass->GetNumberOfShadowMapUpdates();
  const auto plain = RgbBytes(CaptureAsRendered(scene.Window));
  const auto captured = RgbBytes(RenderAndCapture(scene.Window));
  EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates) << "the capture rendered maps";
  scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates) << "the frame after it rendered maps";
  EXPECT_TRUE(plain == captured) << "the capture differs from the plain frame";
  scene.Renderer->SetPass(nullptr);
  two.Right->SetPass(nullptr);
}

namespace
{
// Counts the shader sources a mapper builds.
class CountingMapper : public vtkOpenGLPolyDataMapper
{
public:
  static CountingMapper* New();
  vtkTypeMacro(CountingMapper, vtkOpenGLPolyDataMapper);
  int Builds = 0;

protected:
  CountingMapper() = default;
  void BuildShaders(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    ++this->Builds;
    this->Superclass::BuildShaders(shaders, ren, act);
  }
};
vtkStandardNewMacro(CountingMapper);

// The scene's actors drawn by counting mappers of their inputs; their builds.
std::function<int()> CountBuilds(TestScene& scene)
{
  std::vector<vtkSmartPointer<CountingMapper>> mappers;
  for (vtkActor* actor : { scene.Ground.Get(), scene.Sphere.Get(), scene.Box.Get() })
  {
    auto counting = vtkSmartPointer<CountingMapper>::New();
    counting->SetInputConnection(actor->GetMapper()->GetInputConnection(0, 0));
    actor->SetMapper(counting);
    mappers.push_back(counting);
  }
  return [mappers] {
    int builds = 0;
    for (const auto& mapper : mappers)
    {
      builds += mapper->Builds;
    }
    return builds;
  };
}
} // namespace

// Actors shown in two renderers of one window, one drawing through the pass
// and the other not: still frames build no shader in either (a mapper keeps
// one program per primitive for both), a moving camera neither; the frames
// are those of the other renderer showing copies of the actors: shadows in the
// pass's renderer, none in the other.
TEST(ShadowEverydayUse, ActorsSharedWithARendererWithoutThePass)
{
  for (const auto& kind : EveryPassKind())
  {
    TestScene scene(480, 240);
    scene.SetSun(SideSun);
    const auto builds = CountBuilds(scene);
    vtkNew<vtkRenderer> right;
    ShareSceneWithRightHalf(scene, right);
    LookFromAnotherSide(right);
    vtkSmartPointer<vtkAbstractShadowMapPass> pass = kind.second();
    scene.Renderer->SetPass(pass);
    scene.Window->Render();
    scene.Window->Render();
    const int before = builds();
    for (int frame = 0; frame < 5; ++frame)
    {
      scene.Window->Render();
    }
    EXPECT_EQ(builds(), before) << kind.first << ": shaders built in 5 still frames";
    const auto shared = RgbBytes(CaptureAsRendered(scene.Window));
    scene.Renderer->GetActiveCamera()->Azimuth(10.0);
    scene.Window->Render();
    EXPECT_EQ(builds(), before) << kind.first << ": shaders built as the camera moved";
    scene.Renderer->GetActiveCamera()->Azimuth(-10.0);

    // Copies in the right renderer: its own actors, mappers and programs.
    right->RemoveAllViewProps();
    for (vtkActor* actor : { scene.Ground.Get(), scene.Sphere.Get(), scene.Box.Get() })
    {
      vtkNew<vtkActor> copy;
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(actor->GetMapper()->GetInputConnection(0, 0));
      copy->SetMapper(mapper);
      copy->SetProperty(actor->GetProperty());
      right->AddActor(copy);
    }
    scene.Window->Render();
    const auto copies = RgbBytes(CaptureAsRendered(scene.Window));
    EXPECT_TRUE(shared == copies) << kind.first << ": the shared actors draw other frames";
    auto image = CaptureAsRendered(scene.Window);
    EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(SideSun)), ShadowedBelow)
      << kind.first;
  }
}

// Three renderers of one window sharing the actors: one through a pass, one
// through no pass, one through another pass. The first keeps its place on the
// actors for the second, whose draws stay unshadowed; the third takes the
// actors over in its frames (one pass's code per program): no shader fails,
// each pass renderer shows its shadow, and giving the second renderer a pass
// later shadows it too.
TEST(ShadowEverydayUse, ActorsSharedWithRenderersWithAndWithoutPasses)
{
  ErrorCounter errors;
  TestScene scene(600, 200);
  scene.SetSun(SideSun);
  scene.Renderer->SetViewport(0.0, 0.0, 1.0 / 3.0, 1.0);
  vtkNew<vtkRenderer> middle;
  vtkNew<vtkRenderer> right;
  for (vtkRenderer* other : { middle.Get(), right.Get() })
  {
    for (vtkActor* actor : { scene.Ground.Get(), scene.Sphere.Get(), scene.Box.Get() })
    {
      other->AddActor(actor);
    }
    other->SetActiveCamera(scene.Renderer->GetActiveCamera());
    other->AutomaticLightCreationOff();
    scene.Renderer->GetLights()->InitTraversal();
    other->AddLight(scene.Renderer->GetLights()->GetNextItem());
    scene.Window->AddRenderer(other);
  }
  middle->SetViewport(1.0 / 3.0, 0.0, 2.0 / 3.0, 1.0);
  right->SetViewport(2.0 / 3.0, 0.0, 1.0, 1.0);
  vtkNew<vtkCascadedShadowMapPass> first;
  vtkNew<vtkVarianceShadowMapPass> other;
  scene.Renderer->SetPass(first);
  right->SetPass(other);
  for (int frame = 0; frame < 3; ++frame)
  {
    scene.Window->Render();
  }
  auto image = CaptureAsRendered(scene.Window);
  const glm::dvec3 shadow = GroundShadowOfSphereCenter(SideSun);
  EXPECT_LT(LuminanceAt(scene.Renderer, image, shadow), ShadowedBelow);
  EXPECT_GT(LuminanceAt(middle, image, shadow), LitAbove) << "the renderer without a pass";
  EXPECT_LT(LuminanceAt(right, image, shadow), ShadowedBelow);
  vtkNew<vtkDepthShadowMapPass> third;
  middle->SetPass(third);
  scene.Window->Render();
  image = CaptureAsRendered(scene.Window);
  EXPECT_LT(LuminanceAt(middle, image, shadow), ShadowedBelow) << "given a pass later";
  EXPECT_EQ(errors.Errors(), 0) << errors.Text();
}

// Two renderers sharing a pass and its shaders, with other lights each: each
// renderer's frame is the one a pass of its own draws.
TEST(ShadowEverydayUse, TwoRenderersWithOtherLights)
{
  TestScene scene(480, 240);
  scene.SetSun(SideSun);
  vtkNew<vtkRenderer> right;
  ShareSceneWithRightHalf(scene, right);
  right->AddLight(SpotOverTheScene());
  right->SetActiveCamera(scene.Renderer->GetActiveCamera());
  vtkNew<vtkWarpedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  right->SetPass(pass);
  scene.Window->Render();
  scene.Window->Render();
  const auto shared = RgbBytes(CaptureAsRendered(scene.Window));
  vtkNew<vtkWarpedShadowMapPass> leftFresh;
  vtkNew<vtkWarpedShadowMapPass> rightFresh;
  scene.Renderer->SetPass(leftFresh);
  right->SetPass(rightFresh);
  scene.Window->Render();
  EXPECT_TRUE(shared == RgbBytes(CaptureAsRendered(scene.Window)))
    << "a renderer drew with the other's lights' shader code";
}

// A stereo camera: each eye keeps maps of its own, a still camera re-renders
// neither, and the frame is a fresh pass's.
TEST(ShadowEverydayUse, StereoEyesKeepTheirMaps)
{
  TestScene scene(480, 240);
  scene.SetSun(SideSun);
  scene.Window->SetStereoTypeToSplitViewportHorizontal();
  scene.Window->SetStereoRender(1);
  vtkNew<vtkCascadedShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  scene.Window->Render();
  const int updates = pass->GetNumberOfShadowMapUpdates();
  EXPECT_EQ(updates, 2) << "one update per eye";
  scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates) << "a still stereo camera re-rendered the maps";
  const auto kept = RgbBytes(CaptureAsRendered(scene.Window));
  EXPECT_TRUE(kept == FreshPassFrame(scene, NewPass<vtkCascadedShadowMapPass>()));
  scene.Renderer->GetActiveCamera()->Azimuth(10.0);
  scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates + 2) << "each eye fits the moved camera";
}

// The eyes of a stereo camera hold the same shader code: a change of it (a
// second light switched on and off) builds each mapper's shaders once, as
// without stereo.
TEST(ShadowEverydayUse, StereoEyesBuildShadersOnceForACodeChange)
{
  std::vector<int> builds[2];
  for (int stereo : { 0, 1 })
  {
    TestScene scene(480, 240);
    scene.SetSun(SideSun);
    vtkSmartPointer<vtkLight> spot = SpotOverTheScene();
    scene.Renderer->AddLight(spot);
    scene.Window->SetStereoTypeToSplitViewportHorizontal();
    scene.Window->SetStereoRender(stereo);
    vtkNew<vtkDepthShadowMapPass> pass;
    scene.Renderer->SetPass(pass);
    const auto frame = [&] {
      const int before = pass->GetNumberOfShaderBuilds();
      scene.Window->Render();
      builds[stereo].push_back(pass->GetNumberOfShaderBuilds() - before);
    };
    frame();
    frame();
    spot->SwitchOff();
    frame();
    frame();
    spot->SwitchOn();
    frame();
    frame();
    scene.Renderer->SetPass(nullptr);
  }
  EXPECT_EQ(builds[1], builds[0]) << "stereo built more than mono";
  EXPECT_GT(builds[0][2], 0) << "the switch changed no code";
  EXPECT_EQ(builds[0][3] + builds[0][5], 0) << "a still frame built shaders";
}

// The casters' GL state is set for their draws and restored after, as the
// application (or another pass) had it, not reset to fixed values.
TEST(ShadowEverydayUse, CastingRestoresTheGLState)
{
  TestScene scene(64, 48);
  scene.Window->Render();
  scene.Window->MakeCurrent();
  vtkOpenGLState* state = vtkOpenGLRenderWindow::SafeDownCast(scene.Window)->GetState();
  for (bool minimumBlending : { false, true })
  {
    state->vtkglDepthFunc(GL_GREATER);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    state->vtkglActiveTexture(GL_TEXTURE3);
    state->vtkglBlendEquation(GL_MAX);
    glPolygonOffset(2.0f, 3.0f);
    {
      const shadowmaps::CasterGLState casting(state, minimumBlending);
      state->vtkglDepthFunc(GL_LESS);
      state->vtkglClearColor(1.0f, 1.0f, 1.0f, 1.0f);
      state->vtkglActiveTexture(GL_TEXTURE5);
      glPolygonOffset(1.0f, 1.0f);
    }
    GLint depthFunc = 0;
    GLboolean depthMask = GL_TRUE;
    GLfloat clear[4] = { 0, 0, 0, 0 };
    GLint unit = 0;
    GLint equation = 0;
    GLfloat offset[2] = { 0, 0 };
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &unit);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &equation);
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &offset[0]);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &offset[1]);
    EXPECT_EQ(depthFunc, GL_GREATER) << minimumBlending;
    EXPECT_EQ(depthMask, GL_FALSE) << minimumBlending;
    EXPECT_EQ(clear[2], 0.75f) << minimumBlending;
    EXPECT_EQ(unit, GL_TEXTURE3) << minimumBlending;
    EXPECT_EQ(equation, GL_MAX) << minimumBlending;
    EXPECT_EQ(offset[0], 2.0f) << minimumBlending;
    EXPECT_EQ(offset[1], 3.0f) << minimumBlending;
  }
  // Back to what VTK expects of a frame's start.
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglActiveTexture(GL_TEXTURE0);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  glPolygonOffset(0.0f, 0.0f);
}

namespace
{
// The camera's eye depth of `p`.
double EyeDepth(vtkRenderer* renderer, const glm::dvec3& p)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  double eye[3];
  camera->GetPosition(eye);
  double direction[3];
  camera->GetDirectionOfProjection(direction);
  return glm::dot(p - glm::dvec3(eye[0], eye[1], eye[2]),
    glm::dvec3(direction[0], direction[1], direction[2]));
}

// The point size (or line width) in pixels that VTK's impostors draw as a
// sphere (tube) of `radius` world units at `center`, seen by the renderer's
// camera: VTK sizes them as radius = size / (width * P00) * eye depth.
double PixelsForRadius(vtkRenderer* renderer, const glm::dvec3& center, double radius)
{
  int width = 0;
  int height = 0;
  int origin[2];
  renderer->GetTiledSizeAndOrigin(&width, &height, origin, origin + 1);
  vtkMatrix4x4* projection = renderer->GetActiveCamera()->GetProjectionTransformMatrix(
    renderer->GetTiledAspectRatio(), -1.0, 1.0);
  return radius * width * projection->GetElement(0, 0) / EyeDepth(renderer, center);
}

// An actor drawing `data` with a vtkPolyDataMapper, added to the scene.
vtkSmartPointer<vtkActor> AddDataActor(TestScene& scene, vtkPolyData* data)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  scene.Renderer->AddActor(actor);
  return actor;
}

vtkSmartPointer<vtkActor> PointsAsSpheres(
  TestScene& scene, const std::vector<glm::dvec3>& centers, double radius)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  for (const auto& c : centers)
  {
    vertices->InsertNextCell(1);
    vertices->InsertCellPoint(points->InsertNextPoint(c.x, c.y, c.z));
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetVerts(vertices);
  vtkSmartPointer<vtkActor> actor = AddDataActor(scene, data);
  actor->GetProperty()->SetRenderPointsAsSpheres(true);
  actor->GetProperty()->SetPointSize(
    static_cast<float>(PixelsForRadius(scene.Renderer, centers.front(), radius)));
  return actor;
}

vtkSmartPointer<vtkActor> LineAsTube(
  TestScene& scene, const glm::dvec3& from, const glm::dvec3& to, double radius)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(from.x, from.y, from.z);
  points->InsertNextPoint(to.x, to.y, to.z);
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(2);
  lines->InsertCellPoint(0);
  lines->InsertCellPoint(1);
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetLines(lines);
  vtkSmartPointer<vtkActor> actor = AddDataActor(scene, data);
  actor->GetProperty()->SetRenderLinesAsTubes(true);
  actor->GetProperty()->SetLineWidth(
    static_cast<float>(PixelsForRadius(scene.Renderer, 0.5 * (from + to), radius)));
  return actor;
}

// Each pass kind (uniform, warped, cascaded; dual depth and moments in uniform
// views) under a sun straight down, then a
// spot and a point light at (0, 0, 6), drawing the scene without its sphere
// and with what `add` puts in it; `expect` probes the frame (an `analysis`
// view of it). Shadows of what lies at height 1.5 are `scale` times as far from
// the z axis as their casters.
void ForEachPassAndLight(const std::function<void(TestScene&)>& add,
  const std::function<void(TestScene&, vtkImageData*, double scale, const std::string&)>& expect,
  int analysis = vtkAbstractShadowMapPass::NO_ANALYSIS)
{
  const PassKinds kinds = EveryPassKind();
  const glm::dvec3 position(0.0, 0.0, 6.0);
  for (const auto& kind : kinds)
  {
    for (int light = 0; light < 3; ++light)
    {
      TestScene scene;
      scene.Renderer->RemoveActor(scene.Sphere);
      light == 0 ? scene.SetSun(Down)
        : light == 1 ? scene.SetSpot(position, 60.0)
                     : scene.SetPoint(position);
      add(scene);
      vtkSmartPointer<vtkAbstractShadowMapPass> pass = kind.second();
      // A sprite's size in the map is limited to the GL's largest point size
      // (255 on llvmpipe): at 1024 texels the point light's cube face needs 232.
      pass->SetResolution(1024);
      pass->SetAnalysisView(analysis);
      scene.Renderer->SetPass(pass);
      auto image = RenderAndCapture(scene.Window);
      const char* lights[] = { ", sun", ", spot", ", point" };
      expect(scene, image, light == 0 ? 1.0 : 6.0 / 4.5, kind.first + lights[light]);
    }
  }
}
} // namespace

// Points drawn as spheres cast the shadow of the sphere they show, under every
// view layout: its centre dark, its rim's shadow dark, beyond it lit.
TEST(ShadowEverydayUse, PointsAsSpheresCastTheirSpheresShadows)
{
  GLfloat range[2] = { 0.0f, 0.0f };
  ForEachPassAndLight([](TestScene& scene) { PointsAsSpheres(scene, { { 0.0, 0.0, 1.5 } }, 1.0); },
    [&](TestScene& scene, vtkImageData* image, double rim, const std::string& what) {
      if (range[1] == 0.0f)
      {
        glGetFloatv(GL_POINT_SIZE_RANGE, range);
        std::cout << "[ measured ] largest point size " << range[1] << "\n";
      }
      EXPECT_LT(LuminanceAt(scene.Renderer, image, Origin), ShadowedBelow) << what << ": centre";
      // Sides the sphere does not hide from the camera (it looks along +y).
      for (const glm::dvec3 side : { glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(-1, 0, 0) })
      {
        EXPECT_LT(LuminanceAt(scene.Renderer, image, 0.75 * rim * side), ShadowedBelow)
          << what << ": inside the rim";
        EXPECT_GT(LuminanceAt(scene.Renderer, image, 1.35 * rim * side), LitAbove)
          << what << ": beyond the rim";
      }
    });
}

// Points drawn as spheres cast into PSM's post-perspective cube faces, whose
// matrices are no rigid light camera (VTK sizes the sprites by the light
// camera's projection). At 256 texels: the cube's faces are cropped to the
// receivers, so the sphere under the light covers more of a face than of a
// uniform cube face, and at 1024 its sprite would pass the GL's largest point
// size (255 on llvmpipe) and be cut.
TEST(ShadowEverydayUse, PointsAsSpheresCastIntoThePostPerspectiveCube)
{
  const glm::dvec3 position(0.0, 0.0, 6.0);
  for (const bool spot : { false, true })
  {
    const std::string what = spot ? "wide spot" : "point light";
    TestScene scene;
    scene.Renderer->RemoveActor(scene.Sphere);
    spot ? scene.SetSpot(position, 75.0) : scene.SetPoint(position);
    PointsAsSpheres(scene, { { 0.0, 0.0, 1.5 } }, 1.0);
    vtkNew<vtkWarpedShadowMapPass> pass;
    pass->SetWarpModeToPSM();
    pass->SetResolution(256);
    scene.Renderer->SetPass(pass);
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << what << ": " << errors.Text();
    const double rim = 6.0 / 4.5;
    EXPECT_LT(LuminanceAt(scene.Renderer, image, Origin), ShadowedBelow) << what << ": centre";
    for (const glm::dvec3 side : { glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(-1, 0, 0) })
    {
      EXPECT_LT(LuminanceAt(scene.Renderer, image, 0.75 * rim * side), ShadowedBelow)
        << what << ": inside the rim " << side.x << "," << side.y;
      EXPECT_GT(LuminanceAt(scene.Renderer, image, 1.35 * rim * side), LitAbove)
        << what << ": beyond the rim " << side.x << "," << side.y;
    }
    scene.Renderer->SetPass(nullptr);
    pass->ReleaseGraphicsResources(scene.Window);
  }
}

// Points drawn as spheres and lines drawn as tubes shadow themselves as
// spheres and tubes do: where the surface faces the light, its points are lit
// (the shadow factor's analysis view), at the default resolution, under a sun
// and under a spot and a point light near them. Depths mixed linearly in
// window depth between the centre's and the nearest point's, exact for
// orthographic maps only, once put a perspective map's sphere nearer the light
// than the one the receivers see, and shadowed a patch of its lit side.
TEST(ShadowEverydayUse, ImpostorsLightTheirLitSide)
{
  const PassKinds kinds = EveryPassKindAndWarp();
  const glm::dvec3 center(-2.0, 1.0, 1.5);
  const glm::dvec3 lamp = center + glm::dvec3(2.0, -5.0, 4.5);
  for (const auto& kind : kinds)
  {
    for (const std::string light : { "sun", "spot", "point" })
    {
      for (const bool tube : { false, true })
      {
      TestScene scene(800, 600);
      scene.Renderer->RemoveActor(scene.Sphere);
      // A tube along x: its surface's normals lie across x.
      const glm::dvec3 axis(tube ? 1.0 : 0.0, 0.0, 0.0);
      tube ? LineAsTube(scene, center - 1.5 * axis, center + 1.5 * axis, 0.5)
           : PointsAsSpheres(scene, { center }, 0.5);
      glm::dvec3 toLight = glm::normalize(lamp - center);
      if (light == "sun")
      {
        scene.SetSun(SideSun);
        toLight = -SideSun;
      }
      else if (light == "spot")
      {
        scene.SetSpot(lamp, 60.0)->SetFocalPoint(center.x, center.y, 0.0);
      }
      else
      {
        scene.SetPoint(lamp);
      }
      vtkSmartPointer<vtkAbstractShadowMapPass> pass = kind.second();
      pass->SetAnalysisViewToShadowFactor();
      scene.Renderer->SetPass(pass);
      auto image = RenderAndCapture(scene.Window);
      double eye[3];
      scene.Renderer->GetActiveCamera()->GetPosition(eye);
      const glm::dvec3 toCamera = glm::normalize(glm::dvec3(eye[0], eye[1], eye[2]) - center);
      const glm::dvec3 halfway = glm::normalize(toLight + toCamera);
      const glm::dvec3 facing = glm::normalize(halfway - glm::dot(halfway, axis) * axis);
      const glm::dvec3 across = tube ? axis : glm::normalize(glm::cross(facing, toLight - toCamera));
      for (const double turn : { -0.4, 0.0, 0.4 })
      {
        // Around the sphere, or along the tube.
        const glm::dvec3 point = tube ? center + 0.5 * facing + 2.0 * turn * across
                                      : center + 0.5 * (facing * std::cos(turn) + across * std::sin(turn));
        EXPECT_GT(DarkestAround(scene.Renderer, image, point), LitAbove)
          << kind.first << ", " << light << (tube ? ", tube" : ", sphere") << ": the lit side, at "
          << turn;
      }
      }
    }
  }
}

// Dual depth maps take an impostor's two surfaces, where each texel's ray
// enters it and where it leaves it, whatever the layer method: a sphere is one
// front face to the GL, and peeling took the ground behind it as its second
// surface, which striped the shadow in second-depth mode.
TEST(ShadowEverydayUse, ImpostorsGiveDualDepthMapsTheirBackSurface)
{
  for (const int mode : { vtkDualDepthShadowMapPass::SECOND_DEPTH,
         vtkDualDepthShadowMapPass::MIDPOINT, vtkDualDepthShadowMapPass::DUAL })
  {
    for (const int method :
      { vtkDualDepthShadowMapPass::MINIMUM_BLENDING, vtkDualDepthShadowMapPass::DEPTH_PEELING })
    {
      for (const bool tube : { false, true })
      {
        TestScene scene;
        scene.Renderer->RemoveActor(scene.Sphere);
        scene.SetSun(Down);
        tube ? LineAsTube(scene, { -2.0, 0.0, 1.5 }, { 2.0, 0.0, 1.5 }, 1.0)
             : PointsAsSpheres(scene, { { 0.0, 0.0, 1.5 } }, 1.0);
        vtkNew<vtkDualDepthShadowMapPass> pass;
        pass->SetMode(mode);
        pass->SetLayerMethod(method);
        scene.Renderer->SetPass(pass);
        auto image = RenderAndCapture(scene.Window);
        const std::string what = "mode " + std::to_string(mode) + ", method " +
          std::to_string(method) + (tube ? ", tube" : ", sphere");
        for (double x = -0.6; x <= 0.61; x += 0.2)
        {
          for (double y = -0.6; y <= 0.61; y += 0.2)
          {
            EXPECT_LT(LuminanceAt(scene.Renderer, image, glm::dvec3(x, y, 0.0)), ShadowedBelow)
              << what << ": the ground at " << x << ", " << y;
          }
        }
        EXPECT_GT(LuminanceAt(scene.Renderer, image, glm::dvec3(0.0, -1.4, 0.0)), LitAbove) << what;
      }
    }
  }
}

// Lines drawn as tubes cast the shadow of the tube they show: a band as wide as
// the tube (scaled by the light), dark inside, lit beyond its sides and ends.
TEST(ShadowEverydayUse, LinesAsTubesCastTheirTubesShadows)
{
  const double radius = 0.4;
  ForEachPassAndLight(
    [&](TestScene& scene) { LineAsTube(scene, { -2.0, 0.0, 1.5 }, { 2.0, 0.0, 1.5 }, radius); },
    [&](TestScene& scene, vtkImageData* image, double scale, const std::string& what) {
      // The side of the band the tube does not hide from the camera (-y).
      for (const double x : { -1.0, 0.0, 1.0 })
      {
        const glm::dvec3 under(scale * x, 0.0, 0.0);
        const glm::dvec3 side(0.0, -radius * scale, 0.0);
        EXPECT_LT(LuminanceAt(scene.Renderer, image, under), ShadowedBelow)
          << what << ": under the line at x " << x;
        EXPECT_LT(LuminanceAt(scene.Renderer, image, under + 0.7 * side), ShadowedBelow)
          << what << ": inside the band at x " << x;
        EXPECT_GT(LuminanceAt(scene.Renderer, image, under + 1.4 * side), LitAbove)
          << what << ": beside the band at x " << x;
        // The tube's top, facing the camera, lit: no shadow of its own.
        const glm::dvec3 top(x, -0.5 * radius, 1.5 + 0.85 * radius);
        EXPECT_GT(LuminanceAt(scene.Renderer, image, top), LitAbove)
          << what << ": the tube's top at x " << x;
      }
      // The tube is solid: under a light at height 6 its end cap, whose top
      // is a radius above the line, casts farther out than the line's end.
      const double capScale = scale == 1.0 ? 1.0 : 6.0 / (6.0 - 1.5 - radius);
      for (const double end : { -1.0, 1.0 })
      {
        EXPECT_GT(
          LuminanceAt(scene.Renderer, image, glm::dvec3(end * (2.0 * capScale + 0.3), -0.1, 0.0)),
          LitAbove)
          << what << ": beyond the end";
        EXPECT_LT(LuminanceAt(scene.Renderer, image, glm::dvec3(end * (2.0 * scale - 0.1), 0.0, 0.0)),
          ShadowedBelow)
          << what << ": under the end";
      }
    });
}

// A tube the light sees end-on (a vertical line under a sun straight above)
// casts a spot as wide as the tube, not a sliver.
TEST(ShadowEverydayUse, TubesSeenEndOnCastTheirWidth)
{
  const double radius = 0.4;
  const glm::dvec3 foot(2.0, 2.0, 0.0);
  TestScene scene;
  scene.Renderer->RemoveActor(scene.Sphere);
  scene.SetSun(Down);
  LineAsTube(scene, foot + glm::dvec3(0.0, 0.0, 0.5), foot + glm::dvec3(0.0, 0.0, 2.5), radius);
  vtkSmartPointer<vtkAbstractShadowMapPass> pass = NewPass<vtkDepthShadowMapPass>();
  pass->SetResolution(1024);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  for (const glm::dvec3 side : { glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(-1, 0, 0) })
  {
    EXPECT_LT(LuminanceAt(scene.Renderer, image, foot + 0.5 * radius * side), ShadowedBelow);
    EXPECT_GT(LuminanceAt(scene.Renderer, image, foot + 2.0 * radius * side), LitAbove);
  }
}

// A capture larger than the window (vtkWindowToImageFilter with a scale, as
// PyVista's and ParaView's screenshots take) renders the image in tiles: each
// shows the shadows of the whole image, as a window of that size draws them,
// impostors' too (points as spheres, tubes: sized in the image's pixels),
// from maps rendered once rather than once per tile.
TEST(ShadowEverydayUse, TiledCapturesShowTheWholeImagesShadows)
{
  const PassKinds kinds = { { "uniform", NewPass<vtkDepthShadowMapPass> },
    { "warped", NewPass<vtkWarpedShadowMapPass> },
    { "cascaded", NewPass<vtkCascadedShadowMapPass> },
    { "moments", NewPass<vtkVarianceShadowMapPass> } };
  for (const auto& kind : kinds)
  {
    // Impostors are sized in pixels of the image: the same sizes in both.
    TestScene whole(800, 600);
    whole.SetSun(SideSun);
    vtkProperty* sphere = PointsAsSpheres(whole, { { -3.5, -4.5, 1.2 } }, 0.8)->GetProperty();
    vtkProperty* tube = LineAsTube(whole, { -5.0, 2.0, 1.2 }, { -1.0, 4.0, 1.2 }, 0.3)->GetProperty();
    whole.Renderer->SetPass(kind.second());
    const auto expected = RgbBytes(RenderAndCapture(whole.Window));

    TestScene tiled(400, 300);
    tiled.SetSun(SideSun);
    PointsAsSpheres(tiled, { { -3.5, -4.5, 1.2 } }, 0.8)->GetProperty()->SetPointSize(sphere->GetPointSize());
    LineAsTube(tiled, { -5.0, 2.0, 1.2 }, { -1.0, 4.0, 1.2 }, 0.3)->GetProperty()->SetLineWidth(tube->GetLineWidth());
    vtkSmartPointer<vtkAbstractShadowMapPass> pass = kind.second();
    tiled.Renderer->SetPass(pass);
    tiled.Window->Render();
    const int updates = pass->GetNumberOfShadowMapUpdates();
    vtkNew<vtkWindowToImageFilter> capture;
    capture->SetInput(tiled.Window);
    capture->SetInputBufferTypeToRGB();
    capture->ReadFrontBufferOff();
    capture->SetScale(2);
    capture->Update();
    const auto tiles = RgbBytes(capture->GetOutput());
    ASSERT_EQ(tiles.size(), expected.size()) << kind.first;
    int differing = 0;
    for (std::size_t i = 0; i < tiles.size(); ++i)
    {
      differing += std::abs(int(tiles[i]) - int(expected[i])) > 32 ? 1 : 0;
    }
    EXPECT_EQ(differing, 0) << kind.first << ": channels differing by more than 32";
    // The first tile's projection, turned back into the whole image's, may
    // differ from the last frame's by rounding: at most one update.
    EXPECT_LE(pass->GetNumberOfShadowMapUpdates() - updates, 1) << kind.first;
  }
}

namespace
{
// A point drawn as a sphere (From == To) or a line drawn as a tube, of
// Radius at its middle (PointsAsSpheres, LineAsTube): VTK sizes it in pixels,
// so its world radius grows with the eye depth along a tube.
struct Impostor
{
  glm::dvec3 From;
  glm::dvec3 To;
  double Radius;
};

// How near the segment from `from` along the unit `direction` for `length`
// passes to `impostor`'s centre or axis, in its radii there, and whether the
// nearest axis point lies between the ends (where a capped tube is its capsule).
std::pair<double, bool> Nearness(vtkRenderer* renderer, const Impostor& impostor,
  const glm::dvec3& from, const glm::dvec3& direction, double length)
{
  const double middle = EyeDepth(renderer, 0.5 * (impostor.From + impostor.To));
  double nearest = std::numeric_limits<double>::max();
  bool between = false;
  const int steps = impostor.From == impostor.To ? 0 : 200;
  for (int i = 0; i <= steps; ++i)
  {
    const double f = steps == 0 ? 0.0 : double(i) / steps;
    const glm::dvec3 axis = glm::mix(impostor.From, impostor.To, f);
    const double radius = impostor.Radius * EyeDepth(renderer, axis) / middle;
    const double along = glm::clamp(glm::dot(axis - from, direction), 0.0, length);
    const double distance = glm::length(from + along * direction - axis) / radius;
    if (distance < nearest)
    {
      nearest = distance;
      between = steps == 0 || (i > 0 && i < steps);
    }
  }
  return { nearest, between };
}

// What GroundShadowsDisagreeing probed: the probes that disagree, and how many
// probes it judged in each impostor's shadow and beside the shadows.
struct GroundProbes
{
  std::vector<std::string> Disagreeing;
  std::vector<int> InShadowOf;
  int Beside = 0;
};

// Probes the ground the camera sees, on a grid, where `impostors` are the only
// casters: dark where the light's ray (towards `light`: a direction with w 0,
// a position with w 1) passes well inside one, lit where it passes well
// outside all of them but near one.
GroundProbes GroundShadowsDisagreeing(vtkRenderer* renderer, vtkImageData* image,
  const std::vector<Impostor>& impostors, const glm::dvec4& light)
{
  GroundProbes probes;
  probes.InShadowOf.assign(impostors.size(), 0);
  double eye[3];
  renderer->GetActiveCamera()->GetPosition(eye);
  for (double x = -10.0; x <= 10.0; x += 0.25)
  {
    for (double y = -10.0; y <= 10.0; y += 0.25)
    {
      const glm::dvec3 ground(x, y, 0.0);
      const glm::dvec3 toEye = glm::dvec3(eye[0], eye[1], eye[2]) - ground;
      const glm::dvec3 toLight = light.w != 0.0 ? glm::dvec3(light) - ground : glm::dvec3(light) * 1e4;
      int inside = -1;
      double nearest = std::numeric_limits<double>::max();
      bool hidden = false;
      for (std::size_t i = 0; i < impostors.size(); ++i)
      {
        const Impostor& impostor = impostors[i];
        const auto [distance, between] =
          Nearness(renderer, impostor, ground, glm::normalize(toLight), glm::length(toLight));
        inside = distance < 0.75 && between ? static_cast<int>(i) : inside;
        nearest = std::min(nearest, distance);
        hidden = hidden ||
          Nearness(renderer, impostor, ground, glm::normalize(toEye), glm::length(toEye)).first < 1.1;
      }
      const double luminance = LuminanceAt(renderer, image, ground);
      if (hidden || luminance < 0.0 || (inside < 0 && (nearest < 1.3 || nearest > 2.0)))
      {
        continue;
      }
      inside >= 0 ? ++probes.InShadowOf[inside] : ++probes.Beside;
      if (inside >= 0 ? luminance >= ShadowedBelow : luminance <= LitAbove)
      {
        probes.Disagreeing.push_back("(" + std::to_string(x) + ", " + std::to_string(y) +
          "): " + std::to_string(luminance) + (inside >= 0 ? " in the shadow" : " beside it"));
      }
    }
  }
  return probes;
}
} // namespace

// A sphere or a tube across the edge between two layers casts into both: a
// point light's cube faces, cascades, a focused view's edge. The GL drops a
// point whose centre is outside the view, VTK's sphere code rounded the square
// about the centre, and the layers' casters were culled by their points'
// bounds: a sphere's shadow was cut at the face's edge (43 probes under a
// point light before, with every pass).
TEST(ShadowEverydayUse, ImpostorsAcrossALayersEdgeCastInBoth)
{
  // Under the point light at (0, 0, 6): across the -z and +x faces, -z and -y,
  // near the corner of -z, +y and -x; a tube across -z and +x.
  const std::vector<Impostor> underThePoint = { { { 4.3, 0.0, 1.5 }, { 4.3, 0.0, 1.5 }, 0.6 },
    { { -1.0, -4.4, 1.5 }, { -1.0, -4.4, 1.5 }, 0.6 },
    { { -3.0, 3.2, 2.8 }, { -3.0, 3.2, 2.8 }, 0.6 },
    { { 3.0, -2.5, 1.5 }, { 6.0, -2.0, 1.5 }, 0.3 } };
  std::vector<Impostor> underTheSun;
  for (double y = -6.0; y <= 9.0; y += 1.5)
  {
    const glm::dvec3 center(-3.0 + 0.4 * y, y, 1.5);
    underTheSun.push_back({ center, center, 0.5 });
  }
  underTheSun.push_back({ { -9.0, 1.0, 2.0 }, { -9.0, 1.0, 2.0 }, 0.7 });
  underTheSun.push_back({ { 3.0, -7.0, 1.2 }, { 4.0, 8.0, 1.2 }, 0.5 });
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.8, 0.3, -1.0));
  for (const auto& kind : EveryPassKind())
  {
    for (const bool point : { true, false })
    {
      TestScene scene(800, 600);
      scene.Renderer->RemoveActor(scene.Sphere);
      scene.Renderer->RemoveActor(scene.Box);
      const std::vector<Impostor>& impostors = point ? underThePoint : underTheSun;
      for (const Impostor& impostor : impostors)
      {
        impostor.From == impostor.To
          ? PointsAsSpheres(scene, { impostor.From }, impostor.Radius)
          : LineAsTube(scene, impostor.From, impostor.To, impostor.Radius);
      }
      const glm::dvec4 light = point ? glm::dvec4(0.0, 0.0, 6.0, 1.0) : glm::dvec4(-sun, 0.0);
      point ? scene.SetPoint(glm::dvec3(light)) : scene.SetSun(sun);
      vtkSmartPointer<vtkAbstractShadowMapPass> pass = kind.second();
      // The largest point size (255 texels on llvmpipe) holds these spheres'
      // images at this resolution.
      pass->SetResolution(512);
      pass->SetAnalysisViewToShadowFactor();
      scene.Renderer->SetPass(pass);
      auto image = RenderAndCapture(scene.Window);
      const std::string what = kind.first + (point ? ", point light" : ", sun");
      const GroundProbes probes = GroundShadowsDisagreeing(scene.Renderer, image, impostors, light);
      EXPECT_TRUE(probes.Disagreeing.empty())
        << what << ": " << probes.Disagreeing.size() << " probes, the first "
        << (probes.Disagreeing.empty() ? "" : probes.Disagreeing.front());
      // Not passed for want of probes: each shadow and its surroundings seen.
      for (std::size_t i = 0; i < impostors.size(); ++i)
      {
        EXPECT_GE(probes.InShadowOf[i], 4) << what << ": probes in the shadow of impostor " << i;
      }
      EXPECT_GE(probes.Beside, 100) << what << ": probes beside the shadows";
    }
  }
}

// A clipping plane cuts the shadows of points drawn as spheres and lines drawn
// as tubes as it cuts the shapes, in every pass kind: the casters' branch of
// impostors runs after VTK's clipping (run before it, it cast them whole).
TEST(ShadowEverydayUse, ClippingPlanesClipImpostorsShadows)
{
  for (const auto& kind : EveryPassKind())
  {
    TestScene scene;
    scene.Renderer->RemoveActor(scene.Sphere);
    scene.Renderer->RemoveActor(scene.Box);
    scene.SetSun(Down);
    vtkNew<vtkPlane> plane; // keeps x > 0
    plane->SetOrigin(0.0, 0.0, 0.0);
    plane->SetNormal(1.0, 0.0, 0.0);
    PointsAsSpheres(scene, { { -2.0, 1.0, 1.5 }, { 2.0, 1.0, 1.5 } }, 0.8)
      ->GetMapper()
      ->AddClippingPlane(plane);
    vtkSmartPointer<vtkActor> tube = LineAsTube(scene, { -3.0, -4.0, 1.5 }, { 3.0, -4.0, 1.5 }, 0.5);
    tube->GetMapper()->AddClippingPlane(plane);
    tube->GetProperty()->SetColor(1.0, 0.0, 0.0);
    scene.Renderer->SetPass(kind.second());
    auto image = RenderAndCapture(scene.Window);
    // The kept half of the tube is drawn (Mesa 25.0 once drew nothing of it).
    const glm::ivec3 tubeTop = ColorAt(scene.Renderer, image, { 1.5, -4.0, 2.0 });
    EXPECT_GT(tubeTop.r, 2 * tubeTop.g + 40) << kind.first << ": the kept half of the tube, drawn";
    EXPECT_LT(LuminanceAt(scene.Renderer, image, { 2.0, 1.0, 0.0 }), ShadowedBelow)
      << kind.first << ": the kept sphere";
    EXPECT_GT(LuminanceAt(scene.Renderer, image, { -2.0, 1.0, 0.0 }), LitAbove)
      << kind.first << ": the clipped sphere";
    EXPECT_LT(LuminanceAt(scene.Renderer, image, { 1.5, -4.0, 0.0 }), ShadowedBelow)
      << kind.first << ": the kept half of the tube";
    EXPECT_GT(LuminanceAt(scene.Renderer, image, { -1.5, -4.0, 0.0 }), LitAbove)
      << kind.first << ": the clipped half of the tube";
  }
}

// An impostor's world size follows the scene camera (its size is in pixels):
// an orbit changes the depths it casts, so the layers that see it are
// rendered again, while a scene without impostors keeps its layers (a point
// light's faces fit the scene as the light sees it, whatever the camera).
TEST(ShadowEverydayUse, ImpostorsShadowsFollowTheCamera)
{
  for (const bool impostors : { true, false })
  {
    TestScene scene;
    scene.SetPoint(glm::dvec3(1.0, -1.0, 4.0));
    if (impostors)
    {
      PointsAsSpheres(scene, { { -2.5, -3.5, 1.2 } }, 0.5);
      LineAsTube(scene, { -5.0, 2.0, 1.2 }, { -1.0, 4.0, 1.2 }, 0.3);
    }
    vtkSmartPointer<vtkAbstractShadowMapPass> pass = NewPass<vtkDepthShadowMapPass>();
    scene.Renderer->SetPass(pass);
    scene.Window->Render();
    scene.Renderer->GetActiveCamera()->Azimuth(4.0);
    scene.Renderer->ResetCameraClippingRange();
    const auto after = RgbBytes(RenderAndCapture(scene.Window));
    if (impostors)
    {
      EXPECT_GE(pass->GetNumberOfRenderedLayers(), 1) << "the faces that see the impostors";
      EXPECT_LT(pass->GetNumberOfRenderedLayers(), 6) << "the faces that do not see them stay";
    }
    else
    {
      EXPECT_EQ(pass->GetNumberOfRenderedLayers(), 0) << "the faces stayed put";
    }
    EXPECT_TRUE(after == FreshPassFrame(scene, NewPass<vtkDepthShadowMapPass>())) << impostors;
  }
}
