// The benchmark's time-varying scene (Measurement/ShadowScenes.h): each time
// step gives the isosurface new geometry of about the same size, and only
// scenes with such data can be played.
#include "ShadowScenes.h"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>

#include <set>
#include <string>

namespace
{
/// The first actor whose mapper has input: the contour's (the ground comes first
/// but its plane holds one cell).
vtkPolyData* LargestInput(vtkRenderer* renderer)
{
  vtkPolyData* largest = nullptr;
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    auto* data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput());
    if (data && (!largest || data->GetNumberOfCells() > largest->GetNumberOfCells()))
    {
      largest = data;
    }
  }
  return largest;
}
} // namespace

TEST(ShadowScenes, TimeVaryingScenesGetNewGeometryEveryStep)
{
  // A contour re-run at each step's value, and a series of steps made once.
  for (const char* name : { "contour", "timesteps" })
  {
    SCOPED_TRACE(name);
    vtkNew<vtkRenderer> renderer;
    std::string error;
    ASSERT_TRUE(shadowscenes::BuildSceneByName(renderer, name, error)) << error;
    EXPECT_TRUE(shadowscenes::HasTimeVaryingData(name));
    std::set<vtkIdType> pointCounts;
    vtkActor* contour = renderer->GetActors()->GetLastActor();
    for (int step = 0; step < 4; ++step)
    {
      const vtkMTimeType actorBefore = contour->GetMTime();
      ASSERT_EQ(shadowscenes::AdvanceTimeVaryingData(renderer, step), 1) << "step " << step;
      EXPECT_GT(contour->GetMTime(), actorBefore)
        << "step " << step << ": the actor is touched, for VTK's pass to render its map again";
      vtkPolyData* surface = LargestInput(renderer);
      ASSERT_NE(surface, nullptr);
      const vtkMTimeType advanced = surface->GetMTime();
      EXPECT_GT(surface->GetNumberOfCells(), 650000) << "step " << step;
      EXPECT_LT(surface->GetNumberOfCells(), 900000) << "step " << step;
      pointCounts.insert(surface->GetNumberOfPoints());
      // Advanced before the render: the update a render asks of the mapper's
      // input runs no filter.
      renderer->GetActors()->GetLastActor()->GetMapper()->GetInputAlgorithm()->Update();
      EXPECT_EQ(LargestInput(renderer)->GetMTime(), advanced) << "step " << step;
    }
    EXPECT_EQ(pointCounts.size(), 4u) << "each step's surface differs";
  }
}

TEST(ShadowScenes, ScenesWithoutTimeVaryingDataPlayNothing)
{
  for (const char* name : { "street", "paraview", "default", "bigmesh" })
  {
    vtkNew<vtkRenderer> renderer;
    std::string error;
    ASSERT_TRUE(shadowscenes::BuildSceneByName(renderer, name, error)) << error;
    EXPECT_EQ(shadowscenes::AdvanceTimeVaryingData(renderer, 1), 0) << name;
    EXPECT_FALSE(shadowscenes::HasTimeVaryingData(name)) << name;
  }
}

TEST(ShadowScenes, BigMeshHoldsMillionsOfTriangles)
{
  vtkNew<vtkRenderer> renderer;
  std::string error;
  ASSERT_TRUE(shadowscenes::BuildSceneByName(renderer, "bigmesh", error)) << error;
  vtkMapper* mapper = renderer->GetActors()->GetLastActor()->GetMapper();
  mapper->GetInputAlgorithm()->Update();
  const vtkIdType triangles = LargestInput(renderer)->GetNumberOfCells();
  EXPECT_GT(triangles, 2500000);
  EXPECT_LT(triangles, 4000000);
}

TEST(ShadowScenes, EverySceneNameBuildsAndAnUnknownOneIsNamed)
{
  const std::vector<std::string> names = shadowscenes::SceneNames();
  EXPECT_GE(names.size(), 16u);
  for (const std::string& name : names)
  {
    vtkNew<vtkRenderer> renderer;
    std::string error;
    EXPECT_TRUE(shadowscenes::BuildSceneByName(renderer, name, error)) << name << ": " << error;
    EXPECT_GT(renderer->GetViewProps()->GetNumberOfItems(), 0) << name;
  }
  vtkNew<vtkRenderer> renderer;
  std::string error;
  EXPECT_FALSE(shadowscenes::BuildSceneByName(renderer, "nowhere", error));
  EXPECT_NE(error.find("'nowhere'"), std::string::npos) << error;
  EXPECT_NE(error.find("timesteps"), std::string::npos) << error;
}
