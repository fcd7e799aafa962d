// Image tests: passes that each render a piece of the scene combine their maps
// (depths, two surfaces' depths, moments through light depths) and fit their
// views to each other's props through a vtkShadowMapExchange (Plugin/Passes),
// as ParaView's ranks do.
// Two "processes" are two test scenes in this process: A holds the sphere, B the
// ground. Their exchanges stand for the collectives: A's MinimumOf keeps what A
// sends, B's combines with it, as if both had called it together.
#include "ShadowTestUtilities.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkShadowMapRepresentation.h"
#include "vtkShadowMapExchange.h"
#include "vtkVarianceShadowMapPass.h"
#include "vtkWarpedShadowMapViews.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace
{
using namespace shadowtest;

// What process A has sent, call by call; B answers each call with A's.
struct Wire
{
  enum Kind
  {
    ANY_OF,
    MINIMUM_OF,
    PRODUCT_OF,
    ALL_BOXES
  };
  struct Call
  {
    bool Flag = false;
    std::vector<float> Values;
    Kind Made = ANY_OF;
  };
  std::vector<Call> Sent;
  std::size_t Received = 0;
  bool Mismatch = false; // B called something A did not, or with another size
};

class TestExchange : public vtkShadowMapExchange
{
public:
  static TestExchange* New();
  vtkTypeMacro(TestExchange, vtkShadowMapExchange);

  Wire* Shared = nullptr;
  bool Sends = true; // A sends what it has; B combines with what A sent
  int Calls = 0;
  // The other process's props' boxes, known to the test beforehand (the one
  // direction of the wire cannot give A what B gathers).
  std::vector<double> OtherBoxes;

  bool AnyOf(bool local) override
  {
    ++this->Calls;
    if (this->Sends)
    {
      this->Shared->Sent.push_back({ local, {}, Wire::ANY_OF });
      return local;
    }
    const Wire::Call* call = this->Next(Wire::ANY_OF);
    return local || (call && call->Flag);
  }

  bool MinimumOf(std::vector<float>& values) override
  {
    return this->Reduce(
      values, Wire::MINIMUM_OF, [](float mine, float theirs) { return std::min(mine, theirs); });
  }

  // An exchange that does not override ProductOf multiplies nothing (vtkShadowMapExchange's default).
  bool Multiplies = true;

  bool ProductOf(std::vector<float>& values) override
  {
    if (!this->Multiplies)
    {
      return this->Superclass::ProductOf(values);
    }
    return this->Reduce(
      values, Wire::PRODUCT_OF, [](float mine, float theirs) { return mine * theirs; });
  }

  // A's boxes come first, then B's.
  bool AllBoxes(std::vector<double>& boxes) override
  {
    ++this->Calls;
    if (this->Sends)
    {
      this->Shared->Sent.push_back({ false, {}, Wire::ALL_BOXES });
      boxes.insert(boxes.end(), this->OtherBoxes.begin(), this->OtherBoxes.end());
      return true;
    }
    if (!this->Next(Wire::ALL_BOXES))
    {
      return false;
    }
    boxes.insert(boxes.begin(), this->OtherBoxes.begin(), this->OtherBoxes.end());
    return true;
  }

private:
  // A sends its values; B combines its own with A's by `combine`, element by element.
  bool Reduce(std::vector<float>& values, Wire::Kind kind, float (*combine)(float, float))
  {
    ++this->Calls;
    if (this->Sends)
    {
      this->Shared->Sent.push_back({ false, values, kind });
      return true;
    }
    const Wire::Call* call = this->Next(kind);
    if (!call || call->Values.size() != values.size())
    {
      this->Shared->Mismatch = true;
      return false;
    }
    std::transform(values.begin(), values.end(), call->Values.begin(), values.begin(), combine);
    return true;
  }

  const Wire::Call* Next(Wire::Kind kind)
  {
    Wire& wire = *this->Shared;
    if (wire.Received >= wire.Sent.size() || wire.Sent[wire.Received].Made != kind)
    {
      wire.Mismatch = true;
      return nullptr;
    }
    return &wire.Sent[wire.Received++];
  }
};
vtkStandardNewMacro(TestExchange);

const glm::dvec3 SunDirection(-0.3, 0.2, -1.0);

// Both processes fit their views to the whole scene's bounds, as ParaView's
// synchronised geometry bounds give them.
void ShareBounds(vtkAbstractShadowMapPass* pass, const TestScene& whole)
{
  double bounds[6];
  whole.Renderer->ComputeVisiblePropBounds(bounds);
  pass->SetSceneBounds(bounds);
  pass->UseSceneBoundsOn();
}

struct TwoProcesses
{
  TestScene Whole;
  TestScene A; // the sphere only
  TestScene B; // the ground only
  Wire Shared;
  vtkNew<TestExchange> ExchangeA;
  vtkNew<TestExchange> ExchangeB;

  TwoProcesses()
  {
    for (TestScene* scene : { &Whole, &A, &B })
    {
      scene->SetSun(SunDirection);
      scene->Box->SetVisibility(false);
    }
    A.Ground->SetVisibility(false);
    B.Sphere->SetVisibility(false);
    ExchangeA->Shared = &Shared;
    ExchangeB->Shared = &Shared;
    ExchangeB->Sends = false;
  }

  // The visible props' boxes of a scene, as a pass gathers them.
  static std::vector<double> PropBoxes(TestScene& scene)
  {
    std::vector<double> boxes;
    vtkPropCollection* props = scene.Renderer->GetViewProps();
    props->InitTraversal();
    while (vtkProp* prop = props->GetNextProp())
    {
      const double* bounds = prop->GetVisibility() ? prop->GetBounds() : nullptr;
      if (bounds && bounds[0] <= bounds[1])
      {
        boxes.insert(boxes.end(), bounds, bounds + 6);
      }
    }
    return boxes;
  }

  void Use(vtkAbstractShadowMapPass* a, vtkAbstractShadowMapPass* b, bool exchange)
  {
    ShareBounds(a, Whole);
    ShareBounds(b, Whole);
    a->SetExchange(exchange ? ExchangeA.Get() : nullptr);
    b->SetExchange(exchange ? ExchangeB.Get() : nullptr);
    A.Renderer->SetPass(a);
    B.Renderer->SetPass(b);
  }

  // A renders first and leaves its calls for B's, which must be the same ones.
  vtkSmartPointer<vtkImageData> RenderBoth()
  {
    Shared.Sent.clear();
    Shared.Received = 0;
    ExchangeA->OtherBoxes = PropBoxes(B);
    ExchangeB->OtherBoxes = PropBoxes(A);
    A.Window->Render();
    B.Window->Render();
    EXPECT_FALSE(Shared.Mismatch) << "the processes called different collectives";
    EXPECT_EQ(Shared.Received, Shared.Sent.size()) << "B made fewer calls than A";
    return CaptureAsRendered(B.Window);
  }

  void Release()
  {
    for (TestScene* scene : { &A, &B })
    {
      vtkRenderPass* pass = scene->Renderer->GetPass();
      scene->Renderer->SetPass(nullptr);
      pass->ReleaseGraphicsResources(scene->Window);
    }
  }
};

TEST(ShadowExchange, ACasterOnAnotherProcessShadowsThisOnesGround)
{
  const glm::dvec3 shadowed = GroundShadowOfSphereCenter(SunDirection);
  const glm::dvec3 lit(-5.0, -4.0, 0.0);
  for (const bool exchange : { false, true })
  {
    TwoProcesses processes;
    vtkNew<vtkDepthShadowMapPass> a;
    vtkNew<vtkDepthShadowMapPass> b;
    processes.Use(a, b, exchange);
    vtkSmartPointer<vtkImageData> image = processes.RenderBoth();
    const double dark = LuminanceAt(processes.B.Renderer, image, shadowed);
    const double bright = LuminanceAt(processes.B.Renderer, image, lit);
    EXPECT_GT(bright, 150.0);
    if (exchange)
    {
      EXPECT_LT(dark, 0.45 * bright) << "the sphere lives on the other process";
      EXPECT_EQ(processes.ExchangeB->Calls, 8)
        << "the props' boxes, all interactive, any translucent, any changed, any failed, the "
           "maps' shape, the maps' shape and readability, the depths";
    }
    else
    {
      EXPECT_GT(dark, 0.9 * bright) << "without the exchange, B's maps hold no caster";
    }
    processes.Release();
  }
}

/// Stands for the other processes with what they contribute to each MinimumOf call.
class ScriptedExchange : public vtkShadowMapExchange
{
public:
  static ScriptedExchange* New();
  vtkTypeMacro(ScriptedExchange, vtkShadowMapExchange);
  std::vector<std::vector<float>> Others;
  std::size_t Call = 0;
  bool AnyOf(bool local) override { return local; }
  bool MinimumOf(std::vector<float>& values) override
  {
    if (this->Call >= this->Others.size() || this->Others[this->Call].size() != values.size())
    {
      return false;
    }
    const std::vector<float>& others = this->Others[this->Call++];
    std::transform(values.begin(), values.end(), others.begin(), values.begin(),
      [](float mine, float theirs) { return std::min(mine, theirs); });
    return true;
  }
};
vtkStandardNewMacro(ScriptedExchange);

// NearestTwoOf: this process's texels (x nearest, y next) and another's make
// the nearest two surfaces of both, whichever process holds them.
TEST(ShadowExchange, NearestTwoOfKeepsTheNearestTwoSurfacesOfAllProcesses)
{
  // Texel by texel: both of this process's surfaces nearest; this one's, then
  // the other's; the other's, then this one's; both of the other's; this one
  // alone; neither has any; both nearest at one depth (which counts once).
  const std::vector<float> mine = { 0.2f, 0.3f, 0.2f, 0.6f, 0.5f, 0.6f, 0.7f, 0.8f, 0.4f, 1.0f,
    1.0f, 1.0f, 0.3f, 0.6f };
  const std::vector<float> theirs = { 0.5f, 0.6f, 0.4f, 0.5f, 0.1f, 0.9f, 0.1f, 0.2f, 1.0f, 1.0f,
    1.0f, 1.0f, 0.3f, 0.5f };
  vtkNew<ScriptedExchange> exchange;
  // What the other process sends: its x, then its nearest behind the nearest of all.
  std::vector<float> theirNearest;
  std::vector<float> theirBehind;
  for (std::size_t i = 0; i < mine.size(); i += 2)
  {
    const float nearest = std::min(mine[i], theirs[i]);
    theirNearest.push_back(theirs[i]);
    theirBehind.push_back(theirs[i] > nearest ? theirs[i] : theirs[i + 1]);
  }
  exchange->Others = { theirNearest, theirBehind };
  std::vector<float> pairs = mine;
  ASSERT_TRUE(exchange->NearestTwoOf(pairs));
  EXPECT_EQ(exchange->Call, 2u);
  for (std::size_t i = 0; i < mine.size(); i += 2)
  {
    // The nearest two distinct depths (far, 1, where there are fewer).
    std::vector<float> surfaces = { mine[i], mine[i + 1], theirs[i], theirs[i + 1], 1.0f };
    std::sort(surfaces.begin(), surfaces.end());
    surfaces.erase(std::unique(surfaces.begin(), surfaces.end()), surfaces.end());
    EXPECT_EQ(pairs[i], surfaces[0]) << "texel " << i / 2;
    EXPECT_EQ(pairs[i + 1], surfaces.size() > 1 ? surfaces[1] : 1.0f) << "texel " << i / 2;
  }
}

// A pass of each storage that combines, by name.
vtkSmartPointer<vtkAbstractShadowMapPass> MakeCombiningPass(const std::string& name)
{
  if (name.rfind("Dual", 0) == 0)
  {
    auto dual = vtkSmartPointer<vtkDualDepthShadowMapPass>::New();
    dual->SetLayerMethod(name == "DualPeeling" ? vtkDualDepthShadowMapPass::DEPTH_PEELING
        : name == "DualMinimumBlending"         ? vtkDualDepthShadowMapPass::MINIMUM_BLENDING
                                                : vtkDualDepthShadowMapPass::AUTO);
    return dual;
  }
  if (name == "TightCascades" || name == "LiSPSM")
  {
    // Fits that follow the props: each process must see the other's.
    auto depth = vtkSmartPointer<vtkDepthShadowMapPass>::New();
    if (name == "LiSPSM")
    {
      vtkNew<vtkWarpedShadowMapViews> warped;
      warped->SetWarpModeToLiSPSM();
      depth->SetViews(warped);
    }
    else
    {
      vtkNew<vtkCascadedShadowMapViews> cascades;
      cascades->SetFitMode(vtkCascadedShadowMapViews::TIGHT);
      depth->SetViews(cascades);
    }
    return depth;
  }
  if (name == "EVSM4" || name == "MSM16")
  {
    auto variance = vtkSmartPointer<vtkVarianceShadowMapPass>::New();
    if (name == "MSM16")
    {
      variance->SetMomentsToMSM();
      variance->SetStorageToHalfFloat();
    }
    return variance;
  }
  return vtkSmartPointer<vtkDepthShadowMapPass>::New();
}

class ShadowExchangeStorage : public ::testing::TestWithParam<std::string>
{
};

// The combined maps equal the maps of the whole scene: B's ground shades as the
// whole scene's ground does wherever the whole scene's sphere does not hide it.
// Depth maps and front and back faces combine texel by texel, peeled surfaces
// as the nearest two, moments through the nearest light depth; tight cascades
// and warps fit to both processes' props.
TEST_P(ShadowExchangeStorage, CombinedMapsShadeLikeTheWholeScenesMaps)
{
  TwoProcesses processes;
  auto a = MakeCombiningPass(GetParam());
  auto b = MakeCombiningPass(GetParam());
  processes.Use(a, b, true);
  ErrorCounter messages;
  vtkSmartPointer<vtkImageData> combined = processes.RenderBoth();
  EXPECT_EQ(messages.Errors() + messages.Warnings(), 0) << messages.Text();

  TestScene& whole = processes.Whole;
  vtkSmartPointer<vtkImageData> withSphere = RenderAndCapture(whole.Window);
  whole.Sphere->SetVisibility(false);
  vtkSmartPointer<vtkImageData> withoutSphere = RenderAndCapture(whole.Window);
  whole.Sphere->SetVisibility(true);
  // One process: the fits see its props.
  auto wholePass = MakeCombiningPass(GetParam());
  whole.Renderer->SetPass(wholePass);
  vtkSmartPointer<vtkImageData> reference = RenderAndCapture(whole.Window);

  int compared = 0;
  int shadowed = 0;
  int differing = 0;
  for (double x = -8.0; x <= 8.0; x += 0.5)
  {
    for (double y = -8.0; y <= 8.0; y += 0.5)
    {
      const glm::dvec3 p(x, y, 0.0);
      if (LuminanceAt(whole.Renderer, withSphere, p) != LuminanceAt(whole.Renderer, withoutSphere, p))
      {
        continue; // the sphere hides the ground there
      }
      const double expected = LuminanceAt(whole.Renderer, reference, p);
      ++compared;
      shadowed += expected < 0.5 * LuminanceAt(whole.Renderer, withoutSphere, p);
      differing += std::abs(LuminanceAt(processes.B.Renderer, combined, p) - expected) > 1.5;
    }
  }
  EXPECT_GT(compared, 900);
  EXPECT_GT(shadowed, 5) << "the comparison covers the shadow";
  EXPECT_EQ(differing, 0);
  whole.Renderer->SetPass(nullptr);
  wholePass->ReleaseGraphicsResources(whole.Window);
  processes.Release();
}

INSTANTIATE_TEST_SUITE_P(ShadowExchange, ShadowExchangeStorage,
  ::testing::Values("Depth", "DualPeeling", "DualMinimumBlending", "DualAuto", "EVSM4", "MSM16",
    "TightCascades", "LiSPSM"));

// A change on one process re-renders every process's maps: B's own scene did
// not change, A's sphere moved, and B's shadow follows it.
TEST(ShadowExchange, AChangeOnAnyProcessReRendersAll)
{
  TwoProcesses processes;
  vtkNew<vtkDepthShadowMapPass> a;
  vtkNew<vtkDepthShadowMapPass> b;
  processes.Use(a, b, true);
  processes.RenderBoth();
  processes.RenderBoth();
  processes.RenderBoth();
  EXPECT_EQ(b->GetNumberOfRenderedLayers(), 0) << "nothing changed anywhere";
  processes.A.Sphere->AddPosition(3.0, 0.0, 0.0);
  vtkSmartPointer<vtkImageData> image = processes.RenderBoth();
  EXPECT_GT(b->GetNumberOfRenderedLayers(), 0) << "A's change re-renders B's maps";
  const glm::dvec3 moved = GroundShadowOfSphereCenter(SunDirection) + glm::dvec3(3.0, 0.0, 0.0);
  const glm::dvec3 left = GroundShadowOfSphereCenter(SunDirection);
  EXPECT_LT(LuminanceAt(processes.B.Renderer, image, moved), 0.45 * LuminanceAt(processes.B.Renderer, image, left))
    << "the shadow moved with the sphere, and left its old place";
  processes.Release();
}

// A drag draws the maps coarser on every process alike
// (InteractiveResolutionScale), even where one process lost its maps on its
// own (a failure, its context released): the processes still make the same
// collective calls, and both draw at the coarse resolution.
TEST(ShadowExchange, ADragIsCoarserOnEveryProcessEvenOneThatLostItsMaps)
{
  for (bool oneLost : { false, true })
  {
    TwoProcesses processes;
    vtkNew<vtkDualDepthShadowMapPass> a;
    vtkNew<vtkDualDepthShadowMapPass> b;
    for (vtkAbstractShadowMapPass* pass : { a.Get(), b.Get() })
    {
      pass->SetResolution(512);
      pass->SetInteractiveResolutionScale(0.5);
    }
    processes.Use(a, b, true);
    processes.RenderBoth();
    EXPECT_EQ(b->GetShadowMapResolution(), 512);
    if (oneLost)
    {
      b->ReleaseGraphicsResources(processes.B.Window);
    }
    for (TestScene* scene : { &processes.A, &processes.B })
    {
      scene->Window->SetDesiredUpdateRate(15.0);
      scene->Renderer->GetActiveCamera()->Azimuth(10.0);
    }
    processes.RenderBoth();
    EXPECT_EQ(a->GetShadowMapResolution(), 256) << (oneLost ? "B lost its maps" : "");
    EXPECT_EQ(b->GetShadowMapResolution(), 256) << (oneLost ? "B lost its maps" : "");
    processes.Release();
  }
}

// Translucent casters on one process tint another's receivers: the
// transmittance maps multiply their colours over the processes and keep the
// nearest depth, every process making them once any has a translucent caster.
TEST(ShadowExchange, TranslucentCastersOnAnotherProcessTintThisOnesGround)
{
  const glm::dvec3 shadowed = GroundShadowOfSphereCenter(SunDirection);
  const glm::dvec3 color(1.0, 0.3, 0.2);
  double transmitted[3];
  const double c[3] = { color.x, color.y, color.z };
  vtkAbstractShadowMapPass::GetTransmittance(c, 0.5, transmitted);
  for (const bool multiplies : { true, false })
  {
    TwoProcesses processes;
    processes.A.Sphere->GetProperty()->SetColor(color.x, color.y, color.z);
    processes.A.Sphere->GetProperty()->SetOpacity(0.5);
    processes.ExchangeA->Multiplies = multiplies;
    processes.ExchangeB->Multiplies = multiplies;
    vtkNew<vtkDepthShadowMapPass> a;
    vtkNew<vtkDepthShadowMapPass> b;
    b->SetAnalysisViewToShadowFactor();
    processes.Use(a, b, true);
    ErrorCounter errors;
    vtkSmartPointer<vtkImageData> image = processes.RenderBoth();
    const glm::ivec3 factor = ColorAt(processes.B.Renderer, image, shadowed);
    if (multiplies)
    {
      // The light crosses the sphere twice.
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_NEAR(factor[k] / 255.0, transmitted[k] * transmitted[k], 0.03) << "channel " << k;
      }
      EXPECT_EQ(errors.Warnings(), 0) << errors.Text();
    }
    else
    {
      EXPECT_EQ(factor, glm::ivec3(255)) << "each process keeps its own transmittance maps";
      EXPECT_EQ(errors.Warnings(), 2) << "once on each process: " << errors.Text();
    }
    processes.Release();
  }
}

// A receiver that casts no shadow moves on one process: the fits that follow
// every process's props change, so every process re-renders its maps, though
// its own scene, its casters and the given scene bounds stayed the same.
TEST(ShadowExchange, AReceiverMovingOnAnyProcessReFitsEveryProcess)
{
  TwoProcesses processes;
  auto a = MakeCombiningPass("TightCascades");
  auto b = MakeCombiningPass("TightCascades");
  vtkNew<vtkInformation> receiverOnly;
  receiverOnly->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  processes.A.Box->SetPropertyKeys(receiverOnly);
  processes.A.Box->SetVisibility(true);
  processes.Use(a, b, true);
  processes.RenderBoth();
  processes.RenderBoth();
  EXPECT_EQ(b->GetNumberOfRenderedLayers(), 0) << "nothing changed anywhere";
  processes.A.Box->AddPosition(0.0, 0.0, 0.5);
  processes.RenderBoth();
  EXPECT_GT(a->GetNumberOfRenderedLayers(), 0) << "A's receiver moved";
  EXPECT_GT(b->GetNumberOfRenderedLayers(), 0) << "B fits to A's props too";
  processes.Release();
}

/// Values that are no light depth: (depth, depth^2) of the window depth.
class vtkTestWindowMomentsRepresentation : public vtkShadowMapRepresentation
{
public:
  static vtkTestWindowMomentsRepresentation* New();
  vtkTypeMacro(vtkTestWindowMomentsRepresentation, vtkShadowMapRepresentation);
  void GetMapStorage(shadowmaps::MapStorage& storage) const override
  {
    storage = shadowmaps::MapStorage();
    storage.Format = shadowmaps::TexelFormat::TwoFloats;
    storage.StoreCode = "  gl_FragData[0] = vec4(vtkShadowCasterDepth, "
                        "vtkShadowCasterDepth * vtkShadowCasterDepth, 0.0, 1.0);";
  }
  std::string GetReceiverLookupCode() const override
  {
    return "uniform sampler2DArray vtkShadowMaps;\n"
           "float vtkShadowLookup(vec3 mapCoord, int layer)\n"
           "{\n"
           "  float nearest = texture(vtkShadowMaps, vec3(mapCoord.xy, float(layer))).x;\n"
           "  return mapCoord.z <= nearest + 0.002 ? 1.0 : 0.0;\n"
           "}\n";
  }
};
vtkStandardNewMacro(vtkTestWindowMomentsRepresentation);

// Values the pass cannot combine (not light depths): a warning says so, once
// per pass, and each process keeps its own casters.
TEST(ShadowExchange, OtherValuesAreNotCombinedAndSaySo)
{
  TwoProcesses processes;
  vtkNew<vtkDepthShadowMapPass> a;
  vtkNew<vtkDepthShadowMapPass> b;
  vtkNew<vtkTestWindowMomentsRepresentation> representationA;
  vtkNew<vtkTestWindowMomentsRepresentation> representationB;
  a->SetRepresentation(representationA);
  b->SetRepresentation(representationB);
  processes.Use(a, b, true);
  ErrorCounter warnings;
  processes.RenderBoth();
  vtkSmartPointer<vtkImageData> image = processes.RenderBoth();
  EXPECT_EQ(warnings.Warnings(), 2) << "once per pass: " << warnings.Text();
  EXPECT_NE(warnings.Text().find("are not combined"), std::string::npos) << warnings.Text();
  const glm::dvec3 shadowed = GroundShadowOfSphereCenter(SunDirection);
  const double lit = LuminanceAt(processes.B.Renderer, image, glm::dvec3(-5.0, -4.0, 0.0));
  EXPECT_GT(LuminanceAt(processes.B.Renderer, image, shadowed), 0.9 * lit)
    << "B's maps hold its own casters only";
  processes.Release();
}

// Values the pass cannot combine keep their layers while nothing changes on
// this process; their transmittance maps, which are combined, cannot: a layer
// kept would multiply the other process's share in once more at each update.
TEST(ShadowExchange, TransmittanceIsCombinedOnceWhateverTheMapsKeep)
{
  TwoProcesses processes;
  processes.A.Sphere->GetProperty()->SetOpacity(0.5);
  vtkNew<vtkDepthShadowMapPass> a;
  vtkNew<vtkDepthShadowMapPass> b;
  vtkNew<vtkTestWindowMomentsRepresentation> representationA;
  vtkNew<vtkTestWindowMomentsRepresentation> representationB;
  a->SetRepresentation(representationA);
  b->SetRepresentation(representationB);
  b->SetAnalysisViewToShadowFactor();
  processes.Use(a, b, true);
  const glm::dvec3 shadowed = GroundShadowOfSphereCenter(SunDirection);
  const glm::ivec3 first = ColorAt(processes.B.Renderer, processes.RenderBoth(), shadowed);
  EXPECT_LT(first.x, 200) << "A's translucent sphere tints B's ground";
  // A receiver on B that casts nothing moves: both processes update.
  vtkNew<vtkInformation> receiverOnly;
  receiverOnly->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  processes.B.Box->SetPropertyKeys(receiverOnly);
  processes.B.Box->SetVisibility(true);
  for (int update = 0; update < 3; ++update)
  {
    processes.B.Box->AddPosition(0.0, 0.0, 0.1);
    const glm::ivec3 again = ColorAt(processes.B.Renderer, processes.RenderBoth(), shadowed);
    EXPECT_EQ(again, first) << "update " << update;
  }
  processes.Release();
}
} // namespace
