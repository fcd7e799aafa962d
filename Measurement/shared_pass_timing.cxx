// What two renderers of one window cost when they share a pass and their
// lights differ (a sun on the left; a sun and a spot on the right), so that
// each has shadow code of its own: 2 x 200 small spheres and a ground at
// 960 x 540, still frames (the camera held), with no shadows and with the
// shared depth-map pass. Each renderer draws actors of its own, or the same
// actors (which must build their shaders again for each renderer, every
// frame). Per row: the median of 24 still frames, over the frame without
// shadows, and the shader builds per frame. One run, the ratios from it:
//   build/bin/shared_pass_timing
#include "vtkDepthShadowMapPass.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace
{
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Left;
  vtkNew<vtkRenderer> Right;

  explicit Scene(bool sameActors)
  {
    this->Window->SetSize(960, 540);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Left->SetViewport(0.0, 0.0, 0.5, 1.0);
    this->Right->SetViewport(0.5, 0.0, 1.0, 1.0);
    for (vtkRenderer* renderer : { this->Left.Get(), this->Right.Get() })
    {
      this->Window->AddRenderer(renderer);
      renderer->AutomaticLightCreationOff();
      vtkCamera* camera = renderer->GetActiveCamera();
      camera->SetPosition(0.0, -26.0, 14.0);
      camera->SetFocalPoint(0.0, 0.0, 0.0);
      camera->SetViewUp(0.0, 0.0, 1.0);
    }
    vtkNew<vtkPlaneSource> ground;
    ground->SetOrigin(-12, -12, 0);
    ground->SetPoint1(12, -12, 0);
    ground->SetPoint2(-12, 12, 0);
    std::vector<vtkSmartPointer<vtkPolyDataAlgorithm>> sources{ ground.Get() };
    for (int i = 0; i < 200; ++i)
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter(-10.0 + 1.5 * (i % 14), -10.0 + 1.5 * (i / 14), 0.5);
      sphere->SetRadius(0.4);
      sources.emplace_back(sphere);
    }
    for (vtkPolyDataAlgorithm* source : sources)
    {
      vtkSmartPointer<vtkActor> actor = Actor(source);
      this->Left->AddActor(actor);
      this->Right->AddActor(sameActors ? actor : Actor(source));
    }
    this->Left->AddLight(Sun());
    this->Right->AddLight(Sun());
    vtkNew<vtkLight> spot;
    spot->SetPositional(true);
    spot->SetPosition(-4.0, 3.0, 12.0);
    spot->SetFocalPoint(0.0, 0.0, 0.0);
    spot->SetConeAngle(40.0);
    spot->SetIntensity(0.5);
    this->Right->AddLight(spot);
    this->Left->ResetCameraClippingRange();
    this->Right->ResetCameraClippingRange();
  }

  static vtkSmartPointer<vtkActor> Actor(vtkPolyDataAlgorithm* source)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
  }

  static vtkSmartPointer<vtkLight> Sun()
  {
    auto sun = vtkSmartPointer<vtkLight>::New();
    sun->SetPositional(false);
    sun->SetPosition(1.0, -0.5, 1.5);
    sun->SetFocalPoint(0.0, 0.0, 0.0);
    sun->SetIntensity(0.6);
    return sun;
  }
};

double Milliseconds(vtkRenderWindow* window)
{
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

struct Timing
{
  double Still = 0.0;
  double BuildsPerFrame = 0.0;
};

Timing Measure(bool sameActors, bool shadows)
{
  Scene scene(sameActors);
  vtkNew<vtkDepthShadowMapPass> pass;
  if (shadows)
  {
    scene.Left->SetPass(pass);
    scene.Right->SetPass(pass);
  }
  scene.Window->Render();
  scene.Window->Render();
  const int builds = pass->GetNumberOfShaderBuilds();
  std::vector<double> still;
  for (int i = 0; i < 24; ++i)
  {
    still.push_back(Milliseconds(scene.Window));
  }
  std::sort(still.begin(), still.end());
  Timing timing;
  timing.Still = still[still.size() / 2];
  timing.BuildsPerFrame = (pass->GetNumberOfShaderBuilds() - builds) / 24.0;
  scene.Left->SetPass(nullptr);
  scene.Right->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
  return timing;
}
} // namespace

int main()
{
  std::printf("| each renderer draws | no shadows ms | shared pass ms | over no shadows | shader "
              "builds a frame |\n|---|---:|---:|---:|---:|\n");
  for (bool sameActors : { false, true })
  {
    const Timing none = Measure(sameActors, false);
    const Timing shadowed = Measure(sameActors, true);
    std::printf("| %s | %.1f | %.1f | %.2f | %.0f |\n",
      sameActors ? "the same 201 actors" : "201 actors of its own", none.Still, shadowed.Still,
      shadowed.Still / none.Still, shadowed.BuildsPerFrame);
  }
  return 0;
}
