// What a representation of a light's own costs (SetLightRepresentation): a
// sun and a spot over 25 spheres (327k triangles) and a ground, at 960 x 540,
// drawn with no shadows, with VTK's vtkShadowMapPass, with depth maps for
// both lights, dual-depth maps for both, and the sun in dual depth beside the
// spot in depth maps (two groups
// of maps, both representations' code in every shader). Per configuration:
// the first frame (shaders built), the median of 24 frames of an orbit drawn
// as a drag (coarser maps redrawn) and of 24 still frames of it, each over
// the frame without shadows, and the reading step (the scene read once per
// group). One run, the ratios from it:
//   build/bin/light_representations_timing
#include "ShadowTechniques.h"
#include "vtkAbstractShadowMapPass.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDepthShadowMapRepresentation.h"
#include "vtkDualDepthShadowMapRepresentation.h"

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
#include <functional>
#include <string>
#include <vector>

namespace
{
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkLight> Sun;
  vtkNew<vtkLight> Spot;

  Scene()
  {
    this->Window->SetSize(960, 540);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    vtkNew<vtkPlaneSource> ground;
    ground->SetOrigin(-12, -12, 0);
    ground->SetPoint1(12, -12, 0);
    ground->SetPoint2(-12, 12, 0);
    this->Add(ground);
    for (int i = 0; i < 25; ++i)
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter(-8.0 + 4.0 * (i % 5), -8.0 + 4.0 * (i / 5), 1.2);
      sphere->SetThetaResolution(128);
      sphere->SetPhiResolution(52);
      this->Add(sphere);
    }
    this->Renderer->AutomaticLightCreationOff();
    this->Sun->SetPositional(false);
    this->Sun->SetPosition(1.0, -0.5, 1.5);
    this->Sun->SetFocalPoint(0.0, 0.0, 0.0);
    this->Sun->SetIntensity(0.6);
    this->Spot->SetPositional(true);
    this->Spot->SetPosition(-4.0, 3.0, 12.0);
    this->Spot->SetFocalPoint(0.0, 0.0, 0.0);
    this->Spot->SetConeAngle(40.0);
    this->Spot->SetIntensity(0.6);
    this->Renderer->AddLight(this->Sun);
    this->Renderer->AddLight(this->Spot);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.0, -26.0, 14.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    this->Renderer->ResetCameraClippingRange();
  }

  void Add(vtkPolyDataAlgorithm* source)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    this->Renderer->AddActor(actor);
  }
};

double Milliseconds(vtkRenderWindow* window)
{
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

struct Timing
{
  double First = 0.0;
  double Drag = 0.0;
  double Still = 0.0;
  double Reading = 0.0;
  int Groups = 0;
};

using MakePass = std::function<vtkSmartPointer<vtkRenderPass>(Scene&)>;

Timing Measure(const MakePass& make)
{
  Scene scene;
  vtkSmartPointer<vtkRenderPass> drawing = make ? make(scene) : nullptr;
  auto* pass = vtkAbstractShadowMapPass::SafeDownCast(drawing);
  scene.Renderer->SetPass(drawing);
  Timing timing;
  scene.Window->SetDesiredUpdateRate(0.0001);
  timing.First = Milliseconds(scene.Window);
  std::vector<double> drag;
  std::vector<double> still;
  std::vector<double> reading;
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  for (int i = 0; i < 24; ++i)
  {
    camera->Azimuth(2.0);
    scene.Renderer->ResetCameraClippingRange();
    scene.Window->SetDesiredUpdateRate(15.0);
    drag.push_back(Milliseconds(scene.Window));
    camera->Azimuth(2.0);
    scene.Renderer->ResetCameraClippingRange();
    scene.Window->SetDesiredUpdateRate(0.0001);
    still.push_back(Milliseconds(scene.Window));
    if (pass)
    {
      reading.push_back(pass->GetFrameStepMilliseconds(vtkAbstractShadowMapPass::READING_STEP));
    }
  }
  timing.Drag = Median(drag);
  timing.Still = Median(still);
  timing.Reading = reading.empty() ? 0.0 : Median(reading);
  timing.Groups = pass ? pass->GetNumberOfRepresentationsInUse() : 0;
  scene.Renderer->SetPass(nullptr);
  if (drawing)
  {
    drawing->ReleaseGraphicsResources(scene.Window);
  }
  return timing;
}
} // namespace

vtkSmartPointer<vtkDepthShadowMapPass> PassOf(vtkShadowMapRepresentation* representation)
{
  auto pass = vtkSmartPointer<vtkDepthShadowMapPass>::New();
  pass->SetRepresentation(representation);
  return pass;
}

int main()
{
  const Timing none = Measure(nullptr);
  std::printf("| maps | groups | first ms | drag / none | still / none | reading ms |\n"
              "|---|---:|---:|---:|---:|---:|\n");
  std::printf("| no shadows | 0 | %.0f | 1.00 (%.0f ms) | 1.00 (%.0f ms) | |\n", none.First,
    none.Drag, none.Still);
  const auto row = [&none](const char* name, const MakePass& make) {
    const Timing t = Measure(make);
    std::printf("| %s | %d | %.0f | %.2f | %.2f | %.2f |\n", name, t.Groups, t.First,
      t.Drag / none.Drag, t.Still / none.Still, t.Reading);
  };
  row("VTK's vtkShadowMapPass (1024^2)",
    [](Scene&) { return shadowbench::MakeVTKShadowMapPass(1024); });
  row("depth maps, both lights",
    [](Scene&) { return PassOf(vtkNew<vtkDepthShadowMapRepresentation>()); });
  row("dual depth, both lights",
    [](Scene&) { return PassOf(vtkNew<vtkDualDepthShadowMapRepresentation>()); });
  row("sun in dual depth, spot in depth maps", [](Scene& scene) {
    auto pass = PassOf(vtkNew<vtkDualDepthShadowMapRepresentation>());
    pass->SetLightRepresentation(scene.Spot, vtkNew<vtkDepthShadowMapRepresentation>());
    return pass;
  });
  return 0;
}
