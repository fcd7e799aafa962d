// What a steady frame asks of the GL per prop (Measurement/ShadowGLCalls.h):
// with the maps kept, a pass adds no draw, and sets its receivers' uniforms
// once per program and frame, not per draw, so that its cost does not grow
// with the number of props.
#include "ShadowGLCalls.h"
#include "ShadowMapVTKCompat.h"

#include "vtkAbstractShadowMapPass.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkVarianceShadowMapPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <functional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace
{
// `boxes` boxes, each an actor with a mapper of its own, on a ground under a sun.
struct Boxes
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;

  explicit Boxes(int boxes)
  {
    this->Window->SetSize(320, 240);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    vtkNew<vtkPlaneSource> ground;
    ground->SetOrigin(-20, -20, 0);
    ground->SetPoint1(20, -20, 0);
    ground->SetPoint2(-20, 20, 0);
    this->Add(ground);
    for (int i = 0; i < boxes; ++i)
    {
      vtkNew<vtkCubeSource> box;
      box->SetCenter(-18.0 + 4.0 * (i % 10), -18.0 + 4.0 * (i / 10), 1.0);
      box->SetZLength(2.0);
      this->Add(box);
    }
    this->Renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> sun;
    sun->SetLightTypeToSceneLight();
    sun->SetPositional(false);
    sun->SetPosition(1.0, -1.0, 3.0);
    sun->SetFocalPoint(0.0, 0.0, 0.0);
    this->Renderer->AddLight(sun);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(-30.0, -35.0, 25.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    this->Renderer->ResetCameraClippingRange();
  }

  void Add(vtkAlgorithm* source)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    this->Renderer->AddActor(actor);
  }

  // The GL calls of a steady frame of `pass` (nullptr: no shadows).
  shadowbench::GLCallCounts SteadyFrame(vtkRenderPass* pass)
  {
    this->Renderer->SetPass(pass);
    for (int i = 0; i < 3; ++i)
    {
      this->Window->Render();
    }
    shadowbench::StartCountingGLCalls();
    this->Window->Render();
    return shadowbench::StopCountingGLCalls();
  }
};

template <typename Pass>
vtkSmartPointer<vtkRenderPass> Make()
{
  return vtkSmartPointer<Pass>::New();
}
} // namespace

TEST(ShadowGLCalls, SteadyFramesAddNoDrawAndNoUniformPerProp)
{
  const std::vector<std::pair<std::string, std::function<vtkSmartPointer<vtkRenderPass>()>>> kinds =
    { { "depth", Make<vtkDepthShadowMapPass> }, { "cascades", Make<vtkCascadedShadowMapPass> },
      { "dual depth", Make<vtkDualDepthShadowMapPass> },
      { "moments", Make<vtkVarianceShadowMapPass> } };
  for (const auto& kind : kinds)
  {
    long added[2] = { 0, 0 };
    const int counts[2] = { 20, 80 };
    for (int i = 0; i < 2; ++i)
    {
      Boxes scene(counts[i]);
      const shadowbench::GLCallCounts none = scene.SteadyFrame(nullptr);
      // The counters see the scene's draws: one per prop in view (VTK's
      // culler leaves out the boxes outside it).
      EXPECT_GE(none.Draws, counts[i] / 2) << kind.first;
      const vtkSmartPointer<vtkRenderPass> pass = kind.second();
      const shadowbench::GLCallCounts shadowed = scene.SteadyFrame(pass);
      // Not passed for want of shadows: the pass has maps and sets its uniforms,
      // which cost GL calls unless VTK skips the values a program already holds.
      EXPECT_GT(vtkAbstractShadowMapPass::SafeDownCast(pass)->GetNumberOfShadowMapLayers(), 0)
        << kind.first;
      EXPECT_GE(shadowed.UniformSets, none.UniformSets + (vtkShadowSkipsRepeatedUniforms ? 0 : 1))
        << kind.first;
      EXPECT_EQ(shadowed.Draws, none.Draws) << kind.first << ", " << counts[i]
                                            << " boxes: the kept maps draw nothing";
      added[i] = shadowed.UniformSets - none.UniformSets;
      std::cout << "[ measured ] " << kind.first << ", " << counts[i] << " boxes: "
                << none.UniformSets << " uniform sets without shadows, " << shadowed.UniformSets
                << " with\n";
    }
    EXPECT_EQ(added[1], added[0]) << kind.first
                                  << ": the uniform sets the pass adds grow with the props";
  }
}
