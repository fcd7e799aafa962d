#!/usr/bin/env python3
"""VTK's own frame of the time-varying scene's surface (the wavelet's contour at
160 over 221^3 points, 814,728 triangles), without shadows, in a 64 x 64 window:
the mapper's draw path a caster draw also takes (docs/notes/time-varying.md).
Median of seven frames with the actor shown, then hidden. One run:

  xvfb-run -a /usr/bin/python3 Measurement/vtk_draw_timing.py   (Debian's python3-vtk9)
"""
import statistics
import time

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkContourFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow


def median_frame_ms(window, frames=7):
    times = []
    for _ in range(frames):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(time.perf_counter() - start)
    return 1000.0 * statistics.median(times)


def main():
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-110, 110, -110, 110, -110, 110)
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 160.0)
    contour.Update()
    surface = vtkPolyData()
    surface.ShallowCopy(contour.GetOutput())
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(surface)
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(64, 64)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    window.Render()
    print(f"{surface.GetNumberOfCells()} triangles")
    print(f"shown: {median_frame_ms(window):.1f} ms")
    actor.VisibilityOff()
    print(f"hidden: {median_frame_ms(window):.1f} ms")


if __name__ == "__main__":
    main()
