// What the pass reads of each prop per frame (Plugin/Scene/ShadowMapPropRecords):
// read again exactly when something its bounds or depths depend on changed,
// and never stale. Without GL: the records ask props, mappers and pipelines.
#include "ShadowMapPropRecords.h"

#include "vtkActor.h"
#include "vtkCullerCollection.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <map>

namespace
{
struct Scene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkSphereSource> Source;
  vtkNew<vtkActor> Sphere;
  vtkNew<vtkActor> Other;

  Scene()
  {
    for (vtkActor* actor : { this->Sphere.Get(), this->Other.Get() })
    {
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(this->Source->GetOutputPort());
      actor->SetMapper(mapper);
      this->Renderer->AddActor(actor);
    }
    this->Other->SetPosition(5.0, 0.0, 0.0);
  }

  // One frame's reads, after what vtkRenderer::Render's cullers do: they ask
  // each prop its bounds (which updates its pipeline) before the passes run.
  int Frame(shadowmaps::PropRecords& records, bool cullers,
    const shadowmaps::ImpostorSizing& sizing = {})
  {
    records.BeginFrame(this->Renderer, sizing);
    for (vtkActor* actor : { this->Sphere.Get(), this->Other.Get() })
    {
      if (cullers)
      {
        actor->GetBounds();
      }
      this->Last[actor] = records.Read(actor);
    }
    records.EndFrame();
    return records.GetNumberOfReadAgain();
  }

  std::map<vtkActor*, shadowmaps::PropRecords::Record> Last;
};
} // namespace

TEST(ShadowPropRecords, ReadAgainOnlyWhatChanged)
{
  for (const bool cullers : { true, false })
  {
    Scene scene;
    if (!cullers)
    {
      scene.Renderer->GetCullers()->RemoveAllItems();
    }
    shadowmaps::PropRecords records;
    scene.Frame(records, cullers);
    scene.Frame(records, cullers);
    EXPECT_EQ(scene.Frame(records, cullers), 0) << "still: nothing read again, cullers " << cullers;

    scene.Sphere->SetPosition(0.0, 2.0, 0.0);
    EXPECT_EQ(scene.Frame(records, cullers), 1) << "moved, cullers " << cullers;
    EXPECT_NEAR(scene.Last[scene.Sphere].Bounds.Min.y, 1.5, 0.05); // a tessellated sphere

    // The source both mappers draw: both read again, their bounds grown.
    scene.Source->SetRadius(2.0);
    EXPECT_EQ(scene.Frame(records, cullers), 2) << "input changed, cullers " << cullers;
    EXPECT_GT(scene.Last[scene.Other].Bounds.Max.x, 6.5) << "cullers " << cullers;
    EXPECT_EQ(scene.Frame(records, cullers), 0) << "still again, cullers " << cullers;

    // Opacity decides whether a prop draws into the maps.
    EXPECT_TRUE(scene.Last[scene.Other].DrawsIntoDepthMaps);
    scene.Other->GetProperty()->SetOpacity(0.5);
    EXPECT_EQ(scene.Frame(records, cullers), 1) << "opacity, cullers " << cullers;
    EXPECT_FALSE(scene.Last[scene.Other].DrawsIntoDepthMaps);
  }
}

// The depths of points drawn as spheres and lines drawn as tubes follow what
// the scene camera sizes them by: only their props' versions change with it.
TEST(ShadowPropRecords, ImpostorsVersionsFollowTheirSizing)
{
  Scene scene;
  shadowmaps::PropRecords records;
  shadowmaps::ImpostorSizing sizing = { 400.0, 2.4, 0.0, 0.0, -1.0, 10.0, 0.0 };
  scene.Frame(records, true, sizing);
  EXPECT_EQ(scene.Frame(records, true, sizing), 0);
  sizing[0] = 800.0; // a tile of an image twice as wide
  EXPECT_EQ(scene.Frame(records, true, sizing), 0) << "no impostors";

  for (const bool spheres : { true, false })
  {
    spheres ? scene.Sphere->GetProperty()->RenderPointsAsSpheresOn()
            : scene.Sphere->GetProperty()->RenderLinesAsTubesOn();
    scene.Frame(records, true, sizing);
    const vtkMTimeType version = scene.Last[scene.Sphere].Version;
    EXPECT_EQ(scene.Frame(records, true, sizing), 0) << spheres;
    sizing[5] += 1.0; // the camera moved back
    EXPECT_EQ(scene.Frame(records, true, sizing), 1) << spheres;
    EXPECT_NE(scene.Last[scene.Sphere].Version, version) << spheres;
    scene.Sphere->GetProperty()->RenderPointsAsSpheresOff();
    scene.Sphere->GetProperty()->RenderLinesAsTubesOff();
  }
}

// A prop drawing impostors reaches their world radius beyond its points: its
// bounds as a caster grow by the largest one (at the farthest eye depth), so
// that every layer holding a part of one casts it; the bounds the views are
// fitted to stay its points' (they would follow the camera).
TEST(ShadowPropRecords, ImpostorsBoundsHoldTheirShapes)
{
  Scene scene;
  shadowmaps::PropRecords records;
  // 400 pixels wide, P00 2; the camera at z = 10 looking down -z (eye depth
  // 10 - z); the sphere's points reach z = 0.5 at most, eye depth 10.5 at z = -0.5.
  const shadowmaps::ImpostorSizing sizing = { 400.0, 2.0, 0.0, 0.0, 1.0, -10.0, 0.0 };
  scene.Frame(records, true, sizing);
  const shadowmaps::Aabb plain = scene.Last[scene.Sphere].Bounds;
  vtkProperty* property = scene.Sphere->GetProperty();
  property->SetPointSize(16.0f);
  property->SetLineWidth(8.0f);
  property->RenderPointsAsSpheresOn();
  scene.Frame(records, true, sizing);
  const double pointReach = 16.0 / (400.0 * 2.0) * 10.5;
  EXPECT_EQ(scene.Last[scene.Sphere].Bounds.Min, plain.Min);
  EXPECT_EQ(scene.Last[scene.Sphere].Bounds.Max, plain.Max);
  EXPECT_NEAR(scene.Last[scene.Sphere].CastingBounds.Min.x, plain.Min.x - pointReach, 1e-9);
  EXPECT_NEAR(scene.Last[scene.Sphere].CastingBounds.Max.z, plain.Max.z + pointReach, 1e-9);
  EXPECT_NEAR(scene.Last[scene.Other].CastingBounds.Min.x, 5.0 + plain.Min.x, 1e-9) << "no impostors";

  property->RenderPointsAsSpheresOff();
  property->RenderLinesAsTubesOn();
  scene.Frame(records, true, sizing);
  EXPECT_NEAR(scene.Last[scene.Sphere].CastingBounds.Max.y, plain.Max.y + pointReach / 2.0, 1e-9) << "tubes";

  shadowmaps::ImpostorSizing parallel = sizing;
  parallel[6] = 1.0;
  scene.Frame(records, true, parallel);
  EXPECT_NEAR(scene.Last[scene.Sphere].CastingBounds.Max.y, plain.Max.y + 8.0 / 800.0, 1e-9)
    << "a parallel camera's impostors do not grow with depth";
}
