"""A time series played in ParaView's views (issue 61): the wavelet's isosurface at
STEPS values (about 780,000 triangles each), written as a file series and read back
by ParaView's XML PolyData reader, over a ground under a sun, each step shown in
ParaView's own render view (no shadows) and in the plugin's Render View (Shadows),
frames interleaved in one process.

  pvpython Measurement/paraview_time_series.py PLUGIN [--steps 6] [--rounds 2]
      [--resolution 2048] [--size 960x540] [--techniques none,uniform,csm,dual,evsm4,auto]
  mpiexec -n 3 pvbatch Measurement/paraview_time_series.py PLUGIN ...

Each frame is one view's still render at a new view time, as ParaView's animation
renders it; the reader is brought to that time before the clock starts (the file's
reading is not the view's cost), so a frame holds the view's update (the new step's
data delivered to the representations) and its render, the GL finished. It prints
per view the median frame and its ratio to ParaView's own view's frame of the same
step (median over steps and rounds), and the plugin's AnimationFrame (1: the pass
keeps its views through the animation's frames). Run it through scripts/paraview.sh
--run, which installs ParaView and builds the plugin:

  bash scripts/paraview.sh --run pvpython Measurement/paraview_time_series.py @PLUGIN@
  bash scripts/paraview.sh --run mpiexec --allow-run-as-root --oversubscribe -n 3 \\
      pvbatch Measurement/paraview_time_series.py @PLUGIN@
"""
import argparse
import math
import os
import statistics
import tempfile

from paraview.simple import LoadPlugin, Plane, SetActiveView, XMLPolyDataReader
from vtkmodules.vtkFiltersCore import vtkContourFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

import paraview_views

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("--steps", type=int, default=6)
parser.add_argument("--rounds", type=int, default=2)
parser.add_argument("--resolution", type=int, default=2048)
parser.add_argument("--size", default="960x540")
parser.add_argument("--techniques", default="none,uniform,csm,dual,evsm4,auto")
arguments = parser.parse_args()
LoadPlugin(arguments.plugin, remote=False, ns=globals())
SIZE = [int(v) for v in arguments.size.split("x")]
HALF = 110  # the wavelet's half extent, as Measurement/ShadowScenes.cxx's contour scene

def write_series(folder, steps):
    """The isosurface at the contour scene's values (160 + 12 sin(0.7 step)), a file a step."""
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-HALF, HALF, -HALF, HALF, -HALF, HALF)
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(contour.GetOutputPort())
    writer.SetDataModeToAppended()
    writer.EncodeAppendedDataOff()
    files = []
    for step in range(steps):
        contour.SetValue(0, 160.0 + 12.0 * math.sin(0.7 * step))
        files.append(os.path.join(folder, "surface_%02d.vtp" % step))
        writer.SetFileName(files[-1])
        writer.Write()
    return files


def make_view(technique, shown):
    view = paraview_views.make_view(technique, shown, SIZE, arguments.resolution)
    view.CameraPosition = [-3.2 * HALF, -3.0 * HALF, 1.8 * HALF]
    view.CameraFocalPoint = [0, 0, -0.2 * HALF]
    view.CameraViewUp = [0, 0, 1]
    return view


def timed(view, step_time):
    """Wall-clock seconds of one still render at a new view time, the GL finished."""
    def frame():
        view.ViewTime = step_time
        view.StillRender()
    return paraview_views.timed(view, frame)[0]


folder = tempfile.mkdtemp(prefix="paraview-time-series-")
files = write_series(folder, arguments.steps)
reader = XMLPolyDataReader(FileName=files)
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
ground = Plane(Origin=[-4 * HALF, -4 * HALF, -1.3 * HALF], Point1=[4 * HALF, -4 * HALF, -1.3 * HALF],
               Point2=[-4 * HALF, 4 * HALF, -1.3 * HALF])
techniques = arguments.techniques.split(",")
views = {technique: make_view(technique, (reader, ground)) for technique in techniques}
for view in views.values():
    timed(view, times[0])
    timed(view, times[-1])
reader.UpdatePipeline(times[0])
cells = reader.GetDataInformation().GetNumberOfCells()
print(f"a series of {len(times)} steps of about {cells:,} triangles, {SIZE[0]} x {SIZE[1]}, "
      f"{arguments.resolution}^2 maps, {arguments.rounds} rounds")
frames = {technique: [] for technique in techniques}
for _ in range(arguments.rounds):
    for step_time in times:
        reader.UpdatePipeline(step_time)  # the file read before the clocks start
        for technique, view in views.items():
            SetActiveView(view)
            frames[technique].append(timed(view, step_time))
print("| view | frame ms | / ParaView's view | animation keeps views |")
print("|---|---:|---:|---:|")
for technique in techniques:
    line = f"| {technique} | {1000.0 * statistics.median(frames[technique]):.0f}"
    if "none" in frames:
        ratios = [f / n for f, n in zip(frames[technique], frames["none"])]
        line += f" | {statistics.median(ratios):.2f}"
    else:
        line += " | -"
    view = views[technique]
    if view.GetProperty("AnimationFrame") is not None:
        view.UpdatePropertyInformation()
        line += f" | {view.GetPropertyValue('AnimationFrame')} |"
    else:
        line += " | - |"
    print(line)
for name in files:
    os.remove(name)
os.rmdir(folder)
