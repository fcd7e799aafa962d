// A representation of one's own, from the installed headers only: depth maps
// whose lookup bands the filtered visibility into three tones (a toon look).
// It plugs into any pass; here the LiSPSM-warped one. Renders a sphere over a
// ground, writes the frame to argv[1] and exits 1 unless the sphere's shadow is
// dark and the open ground lit.
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPNGWriter.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkWindowToImageFilter.h>

#include <vtkDepthShadowMapRepresentation.h>
#include <vtkWarpedShadowMapPass.h>

#include <iostream>

/// Depth maps with the 2x2 hardware PCF, banded into lit, half and full shadow.
class vtkToonShadowRepresentation : public vtkDepthShadowMapRepresentation
{
public:
  static vtkToonShadowRepresentation* New();
  vtkTypeMacro(vtkToonShadowRepresentation, vtkDepthShadowMapRepresentation);

  std::string GetReceiverLookupCode() const override
  {
    return R"(
uniform sampler2DArrayShadow vtkShadowMaps;
float vtkShadowLookup(vec3 mapCoord, int layer)
{
  float visibility = texture(vtkShadowMaps, vec4(mapCoord.xy, float(layer), mapCoord.z));
  return floor(visibility * 2.0 + 0.5) / 2.0;
}
)";
  }
};
vtkStandardNewMacro(vtkToonShadowRepresentation);

namespace
{
double LuminanceAt(vtkRenderer* renderer, vtkImageData* image, double x, double y, double z)
{
  renderer->SetWorldPoint(x, y, z, 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  int extent[6];
  image->GetExtent(extent);
  const int column = static_cast<int>(d[0]);
  const int row = static_cast<int>(d[1]);
  if (column < extent[0] || column > extent[1] || row < extent[2] || row > extent[3])
  {
    std::cerr << "the pixel (" << column << ", " << row << ") is not in the captured frame\n";
    return -1.0;
  }
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer(column, row, 0));
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}
} // namespace

int main(int argc, char* argv[])
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-10, -10, 0);
  plane->SetPoint1(10, -10, 0);
  plane->SetPoint2(-10, 10, 0);
  vtkNew<vtkPolyDataMapper> groundMapper;
  groundMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> ground;
  ground->SetMapper(groundMapper);
  ground->GetProperty()->SetAmbient(0.2);
  ground->GetProperty()->SetDiffuse(0.7);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 0, 2);
  sphere->SetRadius(1.5);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> ball;
  ball->SetMapper(sphereMapper);
  ball->GetProperty()->SetColor(0.9, 0.5, 0.2);
  ball->GetProperty()->SetAmbient(0.2);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(ground);
  renderer->AddActor(ball);
  renderer->SetBackground(0.2, 0.3, 0.4);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(0, 0, 10); // straight down: the shadow lies under the sphere
  sun->SetFocalPoint(0, 0, 0);
  renderer->AutomaticLightCreationOff();
  renderer->AddLight(sun);
  renderer->GetActiveCamera()->SetPosition(0, -18, 12);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);

  vtkNew<vtkWarpedShadowMapPass> shadows;
  shadows->SetWarpModeToLiSPSM();
  vtkNew<vtkToonShadowRepresentation> toon;
  shadows->SetRepresentation(toon);
  renderer->SetPass(shadows);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(true);
  window->SetSize(400, 300);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->ReadFrontBufferOff();
  capture->Update();
  vtkImageData* image = capture->GetOutput();
  if (argc > 1)
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(argv[1]);
    writer->SetInputData(image);
    writer->Write();
  }
  const double shadowed = LuminanceAt(renderer, image, 0.0, 0.0, 0.0);
  const double lit = LuminanceAt(renderer, image, 6.0, 4.0, 0.0);
  std::cout << "ground under the sphere " << shadowed << ", open ground " << lit << "\n";
  const bool ok = shadows->GetNumberOfShadowedLights() == 1 && shadowed >= 0.0 && shadowed < 0.5 * lit;
  renderer->SetPass(nullptr);
  shadows->ReleaseGraphicsResources(window);
  return ok ? 0 : 1;
}
