// A sphere over a plane lit by a directional light, with shadows.
// Usage: MinimalShadows [out.png]   (without a file name it renders once and exits)
#include "vtkWarpedShadowMapPass.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkWindowToImageFilter.h>

static void AddActor(vtkRenderer* renderer, vtkAlgorithm* source)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
}

int main(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkSphereSource> sphere; // radius 0.5 at the origin
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  AddActor(renderer, sphere);
  vtkNew<vtkPlaneSource> plane; // 4 x 4, normal +z, 0.5 below the sphere
  plane->SetOrigin(-2.0, -2.0, -1.0);
  plane->SetPoint1(2.0, -2.0, -1.0);
  plane->SetPoint2(-2.0, 2.0, -1.0);
  AddActor(renderer, plane);

  vtkNew<vtkLight> sun;
  sun->SetPositional(false);
  sun->SetPosition(1.0, 1.0, 2.0); // shines from (1, 1, 2) towards the origin
  renderer->AddLight(sun);
  renderer->GetActiveCamera()->SetPosition(0.0, -6.0, 3.0);
  renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.5);

  renderer->SetPass(vtkNew<vtkWarpedShadowMapPass>());

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->Render();
  if (argc > 1)
  {
    vtkNew<vtkWindowToImageFilter> capture;
    capture->SetInput(window);
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(capture->GetOutputPort());
    writer->SetFileName(argv[1]);
    writer->Write();
  }
  return 0;
}
