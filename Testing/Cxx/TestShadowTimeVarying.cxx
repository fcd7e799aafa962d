// Time-varying casters (issue 61): a caster whose data change between frames,
// with nothing else touched, as a time series or a dragged contour value
// changes them, is never missed by any pass, whatever its views and
// representation. VTK's own vtkShadowMapPass misses exactly this: its baker
// renders the map again only when a light or a prop changes.
#include "ShadowTestUtilities.h"
#include "ShadowMapVTKCompat.h" // the GL loader first
#include "vtkAbstractShadowMapPass.h"
#include "vtkAutomaticShadowMapPass.h"
#include "vtkCamera.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkWarpedShadowMapPass.h"
#include "vtkActor.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace shadowtest;

namespace
{
// The wavelet's isosurface at 240 is a closed blob around the volume's centre;
// at 160 it reaches the volume's sides and is cut open there, so that dual
// depth's automatic layer method switches between its two ways.
constexpr double ClosedValue = 240.0;
constexpr double OpenValue = 160.0;

struct TimeVaryingScene
{
  TestScene Scene;
  vtkNew<vtkRTAnalyticSource> Wavelet;
  vtkNew<vtkFlyingEdges3D> Contour;
  vtkSmartPointer<vtkActor> Surface;

  TimeVaryingScene()
  {
    this->Scene.Renderer->RemoveActor(this->Scene.Sphere);
    this->Wavelet->SetWholeExtent(-10, 10, -10, 10, -10, 10);
    this->Contour->SetInputConnection(this->Wavelet->GetOutputPort());
    this->Contour->SetValue(0, ClosedValue);
    this->Surface = AddSourceActor(this->Scene.Renderer, this->Contour);
    // The wavelet's 21 samples a side become 2 units, centred 1.5 above the ground.
    this->Surface->SetScale(0.1);
    this->Surface->SetPosition(0.0, 0.0, 1.5);
  }

  vtkPolyDataMapper* Mapper() const
  {
    return vtkPolyDataMapper::SafeDownCast(this->Surface->GetMapper());
  }
};

struct DataChange
{
  std::string Name;
  std::function<void(TimeVaryingScene&)> Apply;
};

// Each changes the surface's data only: the actor, its mapper's settings and
// the lights stay as they were, so no prop's modification time moves.
std::vector<DataChange> DataChanges(vtkPolyData* replacement)
{
  return {
    { "re-contoured open", [](TimeVaryingScene& s) { s.Contour->SetValue(0, OpenValue); } },
    { "re-contoured closed", [](TimeVaryingScene& s) { s.Contour->SetValue(0, ClosedValue); } },
    { "upstream source changed",
      [](TimeVaryingScene& s) { s.Wavelet->SetCenter(4.0, 0.0, 0.0); } },
    { "input replaced by data of its own",
      [replacement](TimeVaryingScene& s) { s.Mapper()->SetInputData(replacement); } },
    { "points edited in place",
      [replacement](TimeVaryingScene&) {
        vtkPoints* points = replacement->GetPoints();
        for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
        {
          double p[3];
          points->GetPoint(i, p);
          points->SetPoint(i, p[0] + 30.0, p[1], p[2]);
        }
        points->Modified();
      } },
  };
}

// A sphere of radius 10 in the wavelet's coordinates, about the origin.
vtkSmartPointer<vtkPolyData> SphereData()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(10.0);
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(24);
  sphere->Update();
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->DeepCopy(sphere->GetOutput());
  return data;
}

struct LightSetUp
{
  std::string Name;
  std::function<void(TestScene&)> Apply;
};

std::vector<LightSetUp> LightSetUps()
{
  return { { "sun", [](TestScene& s) { s.SetSun({ 0.0, 0.0, -1.0 }); } },
    { "point light", [](TestScene& s) { s.SetPoint({ 0.5, -0.5, 6.0 }); } } };
}
} // namespace

// Under every pass kind and both light kinds (cube faces for the point light),
// each change of the data alone shows in the next frame exactly as a fresh
// pass draws it.
TEST(ShadowTimeVarying, ChangedCasterDataIsNeverMissed)
{
  for (const auto& kind : EveryPassKind())
  {
    for (const LightSetUp& light : LightSetUps())
    {
      TimeVaryingScene scene;
      light.Apply(scene.Scene);
      vtkSmartPointer<vtkAbstractShadowMapPass> pass = kind.second();
      pass->SetResolution(512);
      const auto fresh = [&kind] {
        vtkSmartPointer<vtkAbstractShadowMapPass> made = kind.second();
        made->SetResolution(512);
        return made;
      };
      const vtkSmartPointer<vtkPolyData> replacement = SphereData();
      for (const DataChange& change : DataChanges(replacement))
      {
        const std::string what = kind.first + ", " + light.Name + ", " + change.Name;
        const auto applyAlone = [&] {
          const vtkMTimeType actorTime = scene.Surface->GetMTime();
          change.Apply(scene);
          EXPECT_EQ(scene.Surface->GetMTime(), actorTime) << what << ": the actor is left alone";
        };
        EXPECT_EQ(ChangeShownAsFresh(scene.Scene, pass, applyAlone, fresh, what), "");
      }
    }
  }
}

// What the changes above draw, checked by meaning on one pass: the shadow
// under a sun straight above follows the surface as its data move it.
TEST(ShadowTimeVarying, ShadowFollowsTheDataUnderASun)
{
  TimeVaryingScene scene;
  scene.Scene.SetSun({ 0.0, 0.0, -1.0 });
  vtkSmartPointer<vtkAbstractShadowMapPass> pass = NewPass<vtkAutomaticShadowMapPass>();
  scene.Scene.Renderer->SetPass(pass);
  // The wavelet's centre moved 40 samples along x: 4 units once scaled.
  const glm::dvec3 underCentre(0.0, 0.0, 0.0);
  const glm::dvec3 underMoved(4.0, 0.0, 0.0);
  auto image = RenderAndCapture(scene.Scene.Window);
  EXPECT_LT(LuminanceAt(scene.Scene.Renderer, image, underCentre), ShadowedBelow);
  EXPECT_GT(LuminanceAt(scene.Scene.Renderer, image, underMoved), LitAbove);
  scene.Wavelet->SetWholeExtent(30, 50, -10, 10, -10, 10);
  scene.Wavelet->SetCenter(40.0, 0.0, 0.0);
  image = RenderAndCapture(scene.Scene.Window);
  EXPECT_GT(LuminanceAt(scene.Scene.Renderer, image, underCentre), LitAbove) << "moved away";
  EXPECT_LT(LuminanceAt(scene.Scene.Renderer, image, underMoved), ShadowedBelow) << "moved there";
}

// A scripted camera path (still renders, as a movie is made: a turn of 6
// degrees and a step of 3.6 aside over 12 frames) with
// AnimationKeepsViews on keeps warped and cascaded views as a drag does, at
// the full resolution; off, the default, it fits every frame anew.
TEST(ShadowTimeVarying, AnimationKeepsViewsAlongAScriptedOrbit)
{
  const auto lispsm = [] {
    auto pass = vtkSmartPointer<vtkWarpedShadowMapPass>::New();
    pass->SetWarpModeToLiSPSM();
    return vtkSmartPointer<vtkAbstractShadowMapPass>(pass);
  };
  const PassKinds kinds = { { "LiSPSM", lispsm }, { "cascades", NewPass<vtkCascadedShadowMapPass> } };
  constexpr int Frames = 12;
  for (const auto& kind : kinds)
  {
    int renderedLayers[2] = { 0, 0 };
    for (const bool keeps : { false, true })
    {
      TestScene scene;
      scene.SetSun(glm::normalize(glm::dvec3(-0.4, 0.3, -1.0)));
      vtkSmartPointer<vtkAbstractShadowMapPass> pass = kind.second();
      pass->SetAnimationKeepsViews(keeps);
      scene.Renderer->SetPass(pass);
      scene.Window->Render();
      for (int frame = 0; frame < Frames; ++frame)
      {
        // A turn and a step aside: stable cascades keep their layers through
        // a turn alone.
        vtkCamera* camera = scene.Renderer->GetActiveCamera();
        camera->Azimuth(0.5);
        const double* position = camera->GetPosition();
        const double* focus = camera->GetFocalPoint();
        camera->SetPosition(position[0] + 0.3, position[1], position[2]);
        camera->SetFocalPoint(focus[0] + 0.3, focus[1], focus[2]);
        scene.Renderer->ResetCameraClippingRange();
        scene.Window->Render();
        renderedLayers[keeps] += pass->GetNumberOfRenderedLayers();
        auto image = CaptureAsRendered(scene.Window);
        EXPECT_EQ(pass->GetShadowMapResolution(), kind.first == "cascades" ? 1024 : 2048)
          << kind.first << ": full maps";
        EXPECT_LT(LuminanceAt(scene.Renderer, image,
                    GroundShadowOfSphereCenter(glm::normalize(glm::dvec3(-0.4, 0.3, -1.0)))),
          ShadowedBelow)
          << kind.first << ", keeps " << keeps << ", frame " << frame;
      }
    }
    EXPECT_LT(2 * renderedLayers[1], renderedLayers[0])
      << kind.first << ": layers re-rendered along the path, kept " << renderedLayers[1]
      << " against " << renderedLayers[0];
  }
}

// A time series of 200 steps, each new geometry (its size changes with the
// value), under the automatic pass (dual-depth maps, whose layer method follows
// each step's closedness) and cascades: memory stays flat once the first steps
// have sized the maps and buffers (measured: 2.4 and 3.6 MiB over the 160
// steps after the warm-up; a 512² depth layer lost per step would be 160).
TEST(ShadowTimeVarying, TwoHundredStepsKeepMemoryFlat)
{
  constexpr int Steps = 200;
  constexpr int WarmUp = 40;
  const PassKinds kinds = { { "automatic", NewPass<vtkAutomaticShadowMapPass> },
    { "cascades", NewPass<vtkCascadedShadowMapPass> } };
  for (const auto& kind : kinds)
  {
    TimeVaryingScene scene;
    scene.Scene.SetSun(glm::normalize(glm::dvec3(-0.4, 0.3, -1.0)));
    vtkSmartPointer<vtkAbstractShadowMapPass> pass = kind.second();
    pass->SetResolution(512);
    scene.Scene.Renderer->SetPass(pass);
    double warm = 0.0;
    for (int step = 0; step < Steps; ++step)
    {
      // Between open (160) and closed (240) surfaces.
      scene.Contour->SetValue(0, 200.0 + 45.0 * std::sin(0.37 * step));
      scene.Scene.Window->Render();
      if (step == WarmUp)
      {
        warm = ResidentMiB();
      }
    }
    const double grown = ResidentMiB() - warm;
    EXPECT_LT(grown, 16.0) << kind.first << ": resident memory grew " << grown << " MiB over "
                           << Steps - WarmUp << " steps";
    scene.Scene.Renderer->SetPass(nullptr);
  }
}
