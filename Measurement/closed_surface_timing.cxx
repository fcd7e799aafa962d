// Times the casters' closedness analysis (shadowmaps::IsClosedSurface) on the
// surfaces a time series and a big mesh bring, with its answer: the first call
// (as a renderer makes it, once per version of the data) and the best of three:
//   build/bin/closed_surface_timing
#include "ShadowMapClosedSurfaces.h"

#include <vtkContourFilter.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRTAnalyticSource.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace
{
void Time(const char* name, vtkPolyDataAlgorithm* source)
{
  source->Update();
  vtkPolyData* surface = source->GetOutput();
  double first = 0.0;
  double best = 1e300;
  bool closed = false;
  for (int run = 0; run < 3; ++run)
  {
    const auto start = std::chrono::steady_clock::now();
    closed = shadowmaps::IsClosedSurface(surface);
    const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
    first = run == 0 ? took.count() : first;
    best = std::min(best, took.count());
  }
  std::printf("| %s | %lld | %s | %.1f | %.1f |\n", name,
    static_cast<long long>(surface->GetNumberOfCells()), closed ? "closed" : "open", first, best);
}
}

int main()
{
  std::printf("| surface | triangles | answer | first ms | best ms |\n|---|---:|---|---:|---:|\n");
  vtkNew<vtkRTAnalyticSource> wavelet; // the contour scenes' 221^3 wavelet
  wavelet->SetWholeExtent(-110, 110, -110, 110, -110, 110);
  vtkNew<vtkContourFilter> open;
  open->SetInputConnection(wavelet->GetOutputPort());
  open->SetValue(0, 160.0);
  Time("221^3 wavelet at 160 (the contour scene's first step)", open);
  vtkNew<vtkLinearSubdivisionFilter> finer;
  finer->SetInputConnection(open->GetOutputPort());
  finer->SetNumberOfSubdivisions(1);
  Time("the same, each triangle split in four (bigmesh)", finer);
  vtkNew<vtkContourFilter> closed;
  closed->SetInputConnection(wavelet->GetOutputPort());
  closed->SetValue(0, 210.0);
  Time("221^3 wavelet at 210", closed);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(1000);
  sphere->SetPhiResolution(800);
  Time("vtkSphereSource 1000 x 800", sphere);
  return 0;
}
