// A representation of a light's own (vtkAbstractShadowMapPass::
// SetLightRepresentation): two spots whose cones do not meet, each in its own
// representation, shadow their halves of the ground exactly as a pass of that
// representation alone does; the same frame whichever representation is the
// pass's; no shader built while the camera moves; every kind of prop draws;
// the groups come and go with the pinning; a light deleted is forgotten.
#include "ShadowTestUtilities.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDepthShadowMapRepresentation.h"
#include "vtkDualDepthShadowMapRepresentation.h"
#include "vtkVarianceShadowMapRepresentation.h"

#include "vtkActor.h"
#include "vtkAxesActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLODActor.h"
#include "vtkLODProp3D.h"
#include "vtkLineSource.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPointSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using namespace shadowtest;

namespace
{
// Straight down over the sphere, and over the box: 14 degree cones, 2 units
// wide on the ground, 4.5 units apart.
const glm::dvec3 OverSphere(0.0, 0.0, 8.0);
const glm::dvec3 OverBox(4.0, 2.0, 8.0);
// Ground points in each spot's shadow, seen by the camera: beside the sphere,
// in front of the box.
const glm::dvec3 InSphereShadow(0.9, -0.5, 0.0);
const glm::dvec3 InBoxShadow(4.0, 1.15, 0.0);

struct TwoSpots
{
  TestScene Scene;
  vtkLight* Left = nullptr;
  vtkNew<vtkLight> Right;

  TwoSpots()
  {
    this->Left = this->Scene.SetSpot(OverSphere, 14.0);
    this->Right->SetLightTypeToSceneLight();
    this->Right->SetPositional(true);
    this->Right->SetPosition(OverBox.x, OverBox.y, OverBox.z);
    this->Right->SetFocalPoint(OverBox.x, OverBox.y, 0.0);
    this->Right->SetConeAngle(14.0);
    this->Right->SetAttenuationValues(1.0, 0.0, 0.0);
    this->Scene.Renderer->AddLight(this->Right);
  }
};

using MakeRepresentation = std::function<vtkSmartPointer<vtkShadowMapRepresentation>()>;

vtkSmartPointer<vtkShadowMapRepresentation> Made(const std::string& kind)
{
  if (kind == "DualDepth")
  {
    return vtkSmartPointer<vtkDualDepthShadowMapRepresentation>::New();
  }
  if (kind == "Moments")
  {
    return vtkSmartPointer<vtkVarianceShadowMapRepresentation>::New();
  }
  return vtkSmartPointer<vtkDepthShadowMapRepresentation>::New();
}

// A frame of `scene` with a pass of `representation` for every light, and,
// when `right` is given, that one for the right spot.
vtkSmartPointer<vtkImageData> FrameOf(TwoSpots& scene, vtkShadowMapRepresentation* representation,
  vtkShadowMapRepresentation* right = nullptr, int* groups = nullptr)
{
  vtkNew<vtkDepthShadowMapPass> pass;
  pass->SetRepresentation(representation);
  pass->SetLightRepresentation(scene.Right, right);
  scene.Scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  auto frame = RenderAndCapture(scene.Scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_EQ(pass->GetNumberOfShadowedLights(), 2);
  if (groups)
  {
    *groups = pass->GetNumberOfRepresentationsInUse();
  }
  scene.Scene.Renderer->SetPass(nullptr);
  return frame;
}

// The pixels `light` lights (without shadows), as a mask: where the frame
// changes when it is switched off (the other light stays on, so that VTK's
// mapper lights the same way).
std::vector<bool> LitBy(TwoSpots& scene, vtkLight* light)
{
  const std::vector<unsigned char> lit = RgbBytes(RenderAndCapture(scene.Scene.Window));
  light->SwitchOff();
  const std::vector<unsigned char> dark = RgbBytes(RenderAndCapture(scene.Scene.Window));
  light->SwitchOn();
  std::vector<bool> mask(lit.size() / 3);
  for (std::size_t p = 0; p < mask.size(); ++p)
  {
    mask[p] = lit[3 * p] != dark[3 * p] || lit[3 * p + 1] != dark[3 * p + 1] ||
      lit[3 * p + 2] != dark[3 * p + 2];
  }
  return mask;
}

bool SamePixel(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b, std::size_t p)
{
  return a[3 * p] == b[3 * p] && a[3 * p + 1] == b[3 * p + 1] && a[3 * p + 2] == b[3 * p + 2];
}

using RepresentationPair = std::tuple<std::string, std::string>;
class LightRepresentationPairs : public testing::TestWithParam<RepresentationPair>
{
};
} // namespace

// The left spot in the pass's representation, the right in its own: where
// only the left lights, the frame is the left's representation's pass's,
// where only the right does, the right's; elsewhere all three agree. Each
// spot's shadow is there.
TEST_P(LightRepresentationPairs, EachSpotIsShadowedAsItsRepresentationAloneShadowsIt)
{
  const std::string leftKind = std::get<0>(GetParam());
  const std::string rightKind = std::get<1>(GetParam());
  TwoSpots scene;
  const std::vector<bool> left = LitBy(scene, scene.Left);
  const std::vector<bool> right = LitBy(scene, scene.Right);
  auto withoutShadows = RenderAndCapture(scene.Scene.Window);

  int groups = 0;
  auto mixed = FrameOf(scene, Made(leftKind), Made(rightKind), &groups);
  EXPECT_EQ(groups, 2);
  const std::vector<unsigned char> mixedBytes = RgbBytes(mixed);
  const std::vector<unsigned char> leftAlone = RgbBytes(FrameOf(scene, Made(leftKind)));
  const std::vector<unsigned char> rightAlone = RgbBytes(FrameOf(scene, Made(rightKind)));

  int wrongLeft = 0;
  int wrongRight = 0;
  int wrongElsewhere = 0;
  int distinctLeft = 0;
  int distinctRight = 0;
  for (std::size_t p = 0; p < left.size(); ++p)
  {
    const bool alike = SamePixel(leftAlone, rightAlone, p);
    if (left[p] && right[p])
    {
      continue; // none by design
    }
    if (left[p])
    {
      wrongLeft += SamePixel(mixedBytes, leftAlone, p) ? 0 : 1;
      distinctLeft += alike ? 0 : 1;
    }
    else if (right[p])
    {
      wrongRight += SamePixel(mixedBytes, rightAlone, p) ? 0 : 1;
      distinctRight += alike ? 0 : 1;
    }
    else
    {
      wrongElsewhere += SamePixel(mixedBytes, leftAlone, p) && alike ? 0 : 1;
    }
  }
  EXPECT_EQ(wrongLeft, 0);
  EXPECT_EQ(wrongRight, 0);
  EXPECT_EQ(wrongElsewhere, 0);
  // Each light lights its cone, and the comparison tells the
  // representations apart (depth and dual-depth maps agree here).
  EXPECT_GT(std::count(left.begin(), left.end(), true), 1000);
  EXPECT_GT(std::count(right.begin(), right.end(), true), 1000);
  if (leftKind == "Moments" || rightKind == "Moments")
  {
    EXPECT_GT(distinctLeft, 0);
    EXPECT_GT(distinctRight, 0);
  }

  for (const glm::dvec3& shadow : { InSphereShadow, InBoxShadow })
  {
    const double lit = LuminanceAt(scene.Scene.Renderer, withoutShadows, shadow);
    EXPECT_GT(lit, 30.0);
    EXPECT_LT(LuminanceAt(scene.Scene.Renderer, mixed, shadow), 0.5 * lit);
  }
}

// Which representation is the pass's and which the light's own changes nothing.
TEST_P(LightRepresentationPairs, TheSameFrameWhicheverRepresentationIsThePasses)
{
  const std::string leftKind = std::get<0>(GetParam());
  const std::string rightKind = std::get<1>(GetParam());
  TwoSpots scene;
  auto first = FrameOf(scene, Made(leftKind), Made(rightKind));

  vtkNew<vtkDepthShadowMapPass> pass;
  pass->SetRepresentation(Made(rightKind));
  pass->SetLightRepresentation(scene.Left, Made(leftKind));
  scene.Scene.Renderer->SetPass(pass);
  auto second = RenderAndCapture(scene.Scene.Window);
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 2);
  EXPECT_EQ(RgbBytes(first), RgbBytes(second));
  scene.Scene.Renderer->SetPass(nullptr);
}

INSTANTIATE_TEST_SUITE_P(ShadowLightRepresentations, LightRepresentationPairs,
  testing::Values(RepresentationPair{ "Depth", "DualDepth" },
    RepresentationPair{ "DualDepth", "Moments" }, RepresentationPair{ "Moments", "Depth" }),
  [](const testing::TestParamInfo<RepresentationPair>& info) {
    return std::get<0>(info.param) + "And" + std::get<1>(info.param);
  });

// A light given the pass's own representation, or given none again, leaves
// one group, and the frame of the pass alone.
TEST(ShadowLightRepresentations, OneRepresentationIsOneGroupAsWithoutPinning)
{
  TwoSpots scene;
  vtkNew<vtkDepthShadowMapPass> pass;
  scene.Scene.Renderer->SetPass(pass);
  auto alone = RenderAndCapture(scene.Scene.Window);
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 1);

  pass->SetLightRepresentation(scene.Right, pass->GetRepresentation());
  auto pinnedToItsOwn = RenderAndCapture(scene.Scene.Window);
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 1);
  EXPECT_EQ(RgbBytes(alone), RgbBytes(pinnedToItsOwn));

  vtkSmartPointer<vtkShadowMapRepresentation> moments = Made("Moments");
  pass->SetLightRepresentation(scene.Right, moments);
  auto mixed = RenderAndCapture(scene.Scene.Window);
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 2);
  EXPECT_EQ(pass->GetLightRepresentation(scene.Right), moments.Get());
  EXPECT_EQ(pass->GetLightRepresentation(scene.Left), pass->GetRepresentation());
  EXPECT_NE(RgbBytes(alone), RgbBytes(mixed));

  pass->SetLightRepresentation(scene.Right, nullptr);
  auto again = RenderAndCapture(scene.Scene.Window);
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 1);
  EXPECT_EQ(RgbBytes(alone), RgbBytes(again));
  scene.Scene.Renderer->SetPass(nullptr);
}

// A light of one group switched off and on again, the camera still: the
// other group's spot keeps its shadow, and the frames are those of a pass
// made for them.
TEST(ShadowLightRepresentations, SwitchingALightOfOneGroupKeepsTheOthersShadow)
{
  TwoSpots scene;
  const auto mixedPass = [&scene]() {
    auto pass = vtkSmartPointer<vtkDepthShadowMapPass>::New();
    pass->SetRepresentation(Made("DualDepth"));
    pass->SetLightRepresentation(scene.Right, Made("Moments"));
    return vtkSmartPointer<vtkAbstractShadowMapPass>(pass);
  };
  vtkSmartPointer<vtkAbstractShadowMapPass> pass = mixedPass();
  ErrorCounter errors;
  const std::string off = ChangeShownAsFresh(
    scene.Scene, pass, [&scene]() { scene.Left->SwitchOff(); }, mixedPass, "the left spot off");
  EXPECT_TRUE(off.empty()) << off;
  EXPECT_EQ(pass->GetNumberOfShadowedLights(), 1);
  auto rightOnly = RenderAndCapture(scene.Scene.Window);
  const std::string on = ChangeShownAsFresh(
    scene.Scene, pass, [&scene]() { scene.Left->SwitchOn(); }, mixedPass, "the left spot on again");
  EXPECT_TRUE(on.empty()) << on;
  EXPECT_EQ(pass->GetNumberOfShadowedLights(), 2);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();

  scene.Scene.Renderer->SetPass(nullptr);
  scene.Left->SwitchOff();
  auto unshadowed = RenderAndCapture(scene.Scene.Window);
  const double lit = LuminanceAt(scene.Scene.Renderer, unshadowed, InBoxShadow);
  EXPECT_LT(LuminanceAt(scene.Scene.Renderer, rightOnly, InBoxShadow), 0.5 * lit);
}

// A group's only light stops casting (its CASTS_SHADOWS key: VTK builds no
// shader for it) and starts again: meanwhile the programs hold nothing of the
// group, and once it casts again its shadow is back, as before, without an
// error.
TEST(ShadowLightRepresentations, AGroupsLightThatStopsCastingShadowsAgainWhenItStarts)
{
  TwoSpots scene;
  vtkNew<vtkDepthShadowMapPass> pass;
  vtkNew<vtkDualDepthShadowMapRepresentation> dual;
  pass->SetRepresentation(dual);
  pass->SetLightRepresentation(scene.Right, Made("Moments"));
  scene.Scene.Renderer->SetPass(pass);
  ErrorCounter errors;
  auto before = RenderAndCapture(scene.Scene.Window);
  scene.Right->GetInformation()->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  auto stopped = RenderAndCapture(scene.Scene.Window);
  EXPECT_EQ(pass->GetNumberOfShadowedLights(), 1);
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 1);
  // Meanwhile the other group's code changes, and back: the programs are
  // built again while the right spot does not cast.
  dual->SetModeToMidpoint();
  RenderAndCapture(scene.Scene.Window);
  dual->SetModeToDual();
  RenderAndCapture(scene.Scene.Window);
  scene.Right->GetInformation()->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 1);
  auto again = RenderAndCapture(scene.Scene.Window);
  EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 2);
  EXPECT_EQ(RgbBytes(before), RgbBytes(again));
  const double shadowed = LuminanceAt(scene.Scene.Renderer, before, InBoxShadow);
  EXPECT_GT(LuminanceAt(scene.Scene.Renderer, stopped, InBoxShadow), 2.0 * shadowed + 10.0)
    << "the box's shadow went with its light's casting";
  scene.Scene.Renderer->SetPass(nullptr);
}

// Two renderers of one window share a pass. Their spots are alike, but the
// left one's left spot is pinned to moments: each renderer has shadow code of
// its own, with the same lights for VTK's own code. A still frame renders no
// map; where no mapper draws in both renderers it builds no shader (each
// renderer's mappers keep the code they were built with); where one does (the
// same actors, mappers, level-of-detail or glyph actors in both), each
// renderer's pixels are those it draws alone, its own code's.
namespace
{
enum class Sharing
{
  Nothing,
  Property,
  Actors,
  Mappers,
  LevelOfDetail,
  LevelOfDetailProp,
  Glyphs
};

struct TwoRenderers
{
  TwoSpots Left;
  vtkNew<vtkRenderer> Other;
  vtkNew<vtkDepthShadowMapPass> Pass;
  std::vector<vtkSmartPointer<vtkProp>> Props;

  TwoRenderers(Sharing sharing, bool pinned)
  {
    vtkRenderer* left = this->Left.Scene.Renderer;
    left->SetViewport(0.0, 0.0, 0.5, 1.0);
    this->Other->SetViewport(0.5, 0.0, 1.0, 1.0);
    this->Left.Scene.Window->AddRenderer(this->Other);
    // A camera of its own: one camera shared by renderers of different props
    // gets the clipping range of each in turn, which changes the maps' fit.
    this->Other->GetActiveCamera()->DeepCopy(left->GetActiveCamera());
    this->Other->AutomaticLightCreationOff();
    for (vtkLight* spot : { this->Left.Left, static_cast<vtkLight*>(this->Left.Right) })
    {
      vtkNew<vtkLight> alike;
      alike->DeepCopy(spot);
      this->Other->AddLight(alike);
    }
    for (vtkActor* actor : { this->Left.Scene.Ground.Get(), this->Left.Scene.Sphere.Get(),
           this->Left.Scene.Box.Get() })
    {
      this->Other->AddViewProp(this->OtherOf(actor, sharing));
    }
    if (sharing == Sharing::LevelOfDetail || sharing == Sharing::LevelOfDetailProp ||
      sharing == Sharing::Glyphs)
    {
      vtkSmartPointer<vtkProp> both = this->Shared(sharing);
      left->AddViewProp(both);
      this->Other->AddViewProp(both);
    }
    if (pinned)
    {
      this->Pass->SetLightRepresentation(this->Left.Left, Made("Moments"));
    }
    left->SetPass(this->Pass);
    this->Other->SetPass(this->Pass);
  }

  ~TwoRenderers()
  {
    this->Left.Scene.Renderer->SetPass(nullptr);
    this->Other->SetPass(nullptr);
  }

  vtkSmartPointer<vtkProp> OtherOf(vtkActor* actor, Sharing sharing)
  {
    if (sharing == Sharing::Actors)
    {
      return actor;
    }
    if (sharing == Sharing::Property)
    {
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(actor->GetMapper()->GetInputConnection(0, 0));
      vtkNew<vtkActor> other;
      other->SetMapper(mapper);
      other->SetProperty(actor->GetProperty());
      this->Props.emplace_back(other);
      return other.Get();
    }
    vtkSmartPointer<vtkMapper> mapper = actor->GetMapper();
    if (sharing != Sharing::Mappers)
    {
      mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
      mapper->SetInputConnection(actor->GetMapper()->GetInputConnection(0, 0));
    }
    vtkNew<vtkActor> other;
    other->SetMapper(mapper);
    other->GetProperty()->DeepCopy(actor->GetProperty());
    this->Props.emplace_back(other);
    return other.Get();
  }

  // Beside the sphere, in the left spot's cone.
  vtkSmartPointer<vtkProp> Shared(Sharing sharing)
  {
    vtkNew<vtkCubeSource> cube;
    cube->SetCenter(-0.9, 0.4, 0.3);
    cube->SetXLength(0.6);
    cube->SetYLength(0.6);
    cube->SetZLength(0.6);
    if (sharing == Sharing::LevelOfDetail)
    {
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(cube->GetOutputPort());
      vtkNew<vtkLODActor> lod;
      lod->SetMapper(mapper);
      this->Props.emplace_back(lod);
      return lod.Get();
    }
    if (sharing == Sharing::LevelOfDetailProp)
    {
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(cube->GetOutputPort());
      vtkNew<vtkLODProp3D> lod;
      lod->AddLOD(mapper, 0.0);
      this->Props.emplace_back(lod);
      return lod.Get();
    }
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(-0.9, 0.4, 0.3);
    points->InsertNextPoint(-0.9, -1.0, 0.3);
    vtkNew<vtkPolyData> centres;
    centres->SetPoints(points);
    vtkNew<vtkGlyph3DMapper> glyphs;
    glyphs->SetInputData(centres);
    cube->SetCenter(0.0, 0.0, 0.0);
    glyphs->SetSourceConnection(cube->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(glyphs);
    this->Props.emplace_back(actor);
    return actor.Get();
  }

  /// The RGB bytes of `renderer`'s viewport in `frame`.
  static std::vector<unsigned char> ViewportBytes(vtkImageData* frame, vtkRenderer* renderer)
  {
    int size[2];
    int origin[2];
    renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
    std::vector<unsigned char> bytes;
    auto* rgb = static_cast<unsigned char*>(frame->GetScalarPointer());
    const int width = frame->GetDimensions()[0];
    for (int y = origin[1]; y < origin[1] + size[1]; ++y)
    {
      const unsigned char* row = rgb + 3 * (y * width + origin[0]);
      bytes.insert(bytes.end(), row, row + 3 * size[0]);
    }
    return bytes;
  }
};

struct FrameCost
{
  int Updates = 0;
  int Builds = 0;
};

FrameCost StillFrameCost(TwoRenderers& two)
{
  vtkRenderWindow* window = two.Left.Scene.Window;
  window->Render();
  window->Render();
  FrameCost cost;
  cost.Updates = -two.Pass->GetNumberOfShadowMapUpdates();
  cost.Builds = -two.Pass->GetNumberOfShaderBuilds();
  window->Render();
  cost.Updates += two.Pass->GetNumberOfShadowMapUpdates();
  cost.Builds += two.Pass->GetNumberOfShaderBuilds();
  return cost;
}
} // namespace

TEST(ShadowLightRepresentations, RenderersWhoseCodeDiffersBuildNoShaderInAStillFrame)
{
  for (bool pinned : { false, true })
  {
    TwoRenderers two(pinned ? Sharing::Property : Sharing::Nothing, pinned);
    ErrorCounter errors;
    const FrameCost cost = StillFrameCost(two);
    EXPECT_EQ(cost.Updates, 0) << "pinned " << pinned;
    EXPECT_EQ(cost.Builds, 0) << "pinned " << pinned;
    auto drawn = RenderAndCapture(two.Left.Scene.Window);
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
    two.Left.Scene.Renderer->SetPass(nullptr);
    two.Other->SetPass(nullptr);
    auto unshadowed = RenderAndCapture(two.Left.Scene.Window);
    for (vtkRenderer* renderer : { two.Left.Scene.Renderer.Get(), two.Other.Get() })
    {
      const double lit = LuminanceAt(renderer, unshadowed, InSphereShadow);
      EXPECT_LT(LuminanceAt(renderer, drawn, InSphereShadow), 0.5 * lit) << "pinned " << pinned;
    }
  }
}

// A renderer without shadowed lights, or that stops drawing, leaves the other's
// shaders as they are, a prop that draws through actors of its own (an axes
// actor) in it too.
TEST(ShadowLightRepresentations, ARendererWithoutShadowsOrDrawingBuildsNoOthersShaders)
{
  for (bool drawing : { true, false })
  {
    TwoRenderers two(Sharing::Nothing, true);
    vtkNew<vtkAxesActor> axes;
    axes->SetPosition(-3.0, 0.0, 0.0);
    two.Left.Scene.Renderer->AddViewProp(axes);
    StillFrameCost(two);
    if (drawing)
    {
      vtkCollectionSimpleIterator it;
      vtkLightCollection* lights = two.Other->GetLights();
      lights->InitTraversal(it);
      while (vtkLight* light = lights->GetNextLight(it))
      {
        light->SwitchOff();
      }
    }
    else
    {
      two.Other->DrawOff();
    }
    ErrorCounter errors;
    const FrameCost cost = StillFrameCost(two);
    EXPECT_EQ(cost.Builds, 0) << (drawing ? "without shadowed lights" : "not drawing");
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << errors.Text();
  }
}

// Mappers last built for the other renderer, which then stops drawing or is
// taken off the window, build again for this one: its pixels are its own
// code's.
TEST(ShadowLightRepresentations, ARendererThatStopsLeavesTheOtherItsOwnCode)
{
  TwoRenderers alone(Sharing::Mappers, true);
  alone.Other->DrawOff();
  const auto own =
    TwoRenderers::ViewportBytes(RenderAndCapture(alone.Left.Scene.Window), alone.Left.Scene.Renderer);
  for (bool removed : { false, true })
  {
    for (Sharing sharing : { Sharing::Mappers, Sharing::Actors })
    {
      TwoRenderers two(sharing, true);
      vtkRenderWindow* window = two.Left.Scene.Window;
      window->Render();
      window->Render();
      if (removed)
      {
        two.Other->SetPass(nullptr);
        window->RemoveRenderer(two.Other);
      }
      else
      {
        two.Other->DrawOff();
      }
      EXPECT_TRUE(TwoRenderers::ViewportBytes(RenderAndCapture(window), two.Left.Scene.Renderer) == own)
        << (sharing == Sharing::Mappers ? "mappers" : "actors") << " shared with a renderer "
        << (removed ? "removed" : "no longer drawing") << ": the left renderer drew another's code";
    }
  }
}

TEST(ShadowLightRepresentations, WhatBothRenderersDrawDrawsWithEachRenderersCode)
{
  const std::pair<Sharing, const char*> kinds[] = { { Sharing::Actors, "actors" },
    { Sharing::Mappers, "mappers" }, { Sharing::LevelOfDetail, "level-of-detail actor" },
    { Sharing::LevelOfDetailProp, "level-of-detail prop" }, { Sharing::Glyphs, "glyph mapper" } };
  for (const auto& kind : kinds)
  {
    TwoRenderers two(kind.first, true);
    vtkRenderWindow* window = two.Left.Scene.Window;
    ErrorCounter errors;
    const FrameCost cost = StillFrameCost(two);
    EXPECT_EQ(cost.Updates, 0) << kind.second;
    auto both = RenderAndCapture(window);
    for (bool right : { false, true })
    {
      // Drawn alone from the first frame, with nothing built for the other.
      TwoRenderers alone(kind.first, true);
      (right ? alone.Left.Scene.Renderer.Get() : alone.Other.Get())->DrawOff();
      auto frame = RenderAndCapture(alone.Left.Scene.Window);
      vtkRenderer* drawn = right ? two.Other.Get() : two.Left.Scene.Renderer.Get();
      EXPECT_TRUE(TwoRenderers::ViewportBytes(both, drawn) ==
        TwoRenderers::ViewportBytes(frame, drawn))
        << kind.second << ": the " << (right ? "right" : "left")
        << " renderer's pixels differ from its own code's";
    }
    // VTK 9.1's vtkLODActor copies its mapper through calls it deprecated, and warns.
    const bool lodWarns = kind.first == Sharing::LevelOfDetail &&
      errors.Text().find("deprecated") != std::string::npos;
    EXPECT_EQ(errors.Errors() + (lodWarns ? 0 : errors.Warnings()), 0)
      << kind.second << ": " << errors.Text();
  }
}

// Mixed representations build each receiver's shader once: an orbit, still
// and interactive frames, builds none.
TEST(ShadowLightRepresentations, AnOrbitWithMixedRepresentationsBuildsNoShader)
{
  TwoSpots scene;
  vtkNew<vtkDepthShadowMapPass> pass;
  pass->SetLightRepresentation(scene.Right, Made("Moments"));
  scene.Scene.Renderer->SetPass(pass);
  RenderAndCapture(scene.Scene.Window);
  const int builds = pass->GetNumberOfShaderBuilds();
  OrbitDraggedThenStill(scene.Scene);
  EXPECT_EQ(pass->GetNumberOfShaderBuilds(), builds);
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 2);
  scene.Scene.Renderer->SetPass(nullptr);
}

// Translucent casters, a volume, points as spheres and lines as tubes draw
// with two representations' code in their shaders, without a warning, and
// the spots' shadows stay.
TEST(ShadowLightRepresentations, EveryKindOfPropDrawsWithTwoRepresentations)
{
  TwoSpots scene;
  vtkRenderer* renderer = scene.Scene.Renderer;
  scene.Scene.Box->GetProperty()->SetOpacity(0.5);

  vtkNew<vtkPointSource> points;
  points->SetCenter(-3.0, 1.0, 1.0);
  points->SetRadius(0.8);
  points->SetNumberOfPoints(30);
  vtkSmartPointer<vtkActor> spheres = AddSourceActor(renderer, points);
  spheres->GetProperty()->SetRenderPointsAsSpheres(true);
  spheres->GetProperty()->SetPointSize(12.0);

  vtkNew<vtkLineSource> line;
  line->SetPoint1(-4.0, -2.0, 0.8);
  line->SetPoint2(-1.5, -3.0, 0.8);
  vtkSmartPointer<vtkActor> tube = AddSourceActor(renderer, line);
  tube->GetProperty()->SetRenderLinesAsTubes(true);
  tube->GetProperty()->SetLineWidth(10.0);

  vtkNew<vtkImageData> image;
  image->SetDimensions(6, 6, 6);
  image->SetOrigin(1.5, -3.5, 0.5);
  image->SetSpacing(0.2, 0.2, 0.2);
  image->AllocateScalars(VTK_FLOAT, 1);
  vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars())->FillValue(1.0f);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.3);
  opacity->AddPoint(2.0, 0.3);
  vtkNew<vtkVolumeProperty> volumeProperty;
  volumeProperty->SetScalarOpacity(opacity);
  vtkNew<vtkSmartVolumeMapper> volumeMapper;
  volumeMapper->SetInputData(image);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(volumeMapper);
  volume->SetProperty(volumeProperty);
  renderer->AddVolume(volume);
  auto withoutShadows = RenderAndCapture(scene.Scene.Window);

  for (const std::string& kind : { "Depth", "DualDepth", "Moments" })
  {
    vtkNew<vtkDepthShadowMapPass> pass;
    pass->SetRepresentation(Made(kind == "Depth" ? "Moments" : "Depth"));
    pass->SetLightRepresentation(scene.Right, Made(kind));
    renderer->SetPass(pass);
    ErrorCounter errors;
    auto frame = RenderAndCapture(scene.Scene.Window);
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << kind << ": " << errors.Text();
    EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 2) << kind;
    const double lit = LuminanceAt(renderer, withoutShadows, InSphereShadow);
    EXPECT_LT(LuminanceAt(renderer, frame, InSphereShadow), 0.5 * lit) << kind;
    renderer->SetPass(nullptr);
  }
}

// A parameter of a light's own representation re-renders the maps; once the
// light is deleted, its representation is forgotten and changes nothing.
TEST(ShadowLightRepresentations, TheLightsRepresentationRendersAndADeletedLightIsForgotten)
{
  TwoSpots scene;
  vtkNew<vtkDepthShadowMapPass> pass;
  vtkNew<vtkDualDepthShadowMapRepresentation> dual;
  pass->SetLightRepresentation(scene.Right, dual);
  scene.Scene.Renderer->SetPass(pass);
  scene.Scene.Window->Render();
  int updates = pass->GetNumberOfShadowMapUpdates();
  dual->SetDualOffset(0.5 * dual->GetDualOffset() + 0.01);
  scene.Scene.Window->Render();
  EXPECT_GT(pass->GetNumberOfShadowMapUpdates(), updates);

  scene.Scene.Renderer->RemoveLight(scene.Right);
  scene.Right.Reset();
  scene.Scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowedLights(), 1);
  EXPECT_EQ(pass->GetNumberOfRepresentationsInUse(), 1);
  const vtkMTimeType before = pass->GetMTime();
  dual->SetDualOffset(0.5 * dual->GetDualOffset());
  EXPECT_EQ(pass->GetMTime(), before) << "a deleted light's representation still counts";
  updates = pass->GetNumberOfShadowMapUpdates();
  scene.Scene.Window->Render();
  EXPECT_EQ(pass->GetNumberOfShadowMapUpdates(), updates);
  scene.Scene.Renderer->SetPass(nullptr);
}

// No light: a warning, and nothing changes.
TEST(ShadowLightRepresentations, NoLightIsRefused)
{
  vtkNew<vtkDepthShadowMapPass> pass;
  vtkNew<vtkDualDepthShadowMapRepresentation> dual;
  ErrorCounter errors;
  pass->SetLightRepresentation(nullptr, dual);
  EXPECT_EQ(errors.Warnings(), 1);
  EXPECT_EQ(pass->GetLightRepresentation(nullptr), pass->GetRepresentation());
}
