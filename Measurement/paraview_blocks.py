"""The many-block scene in ParaView's views (issue 38): the 2,025 boxes and ground
of Measurement/many_actors.py under a sun, as one multiblock dataset of 2,026 blocks
(one representation, drawn block by block by ParaView's composite mapper: how
ParaView shows a dataset of many parts), timed in ParaView's own render view (no
shadows) and in the plugin's Render View (Shadows), frames interleaved in one process.

  pvpython Measurement/paraview_blocks.py PLUGIN [--resolution 2048] [--frames 8]
      [--rounds 3] [--size 960x540] [--techniques none,uniform,csm,second-depth,evsm4]

Per view and kind of frame it prints the median frame (wall clock, the GL finished)
and the rendering thread's CPU time per frame, and each over the plain view's in the
same round (median over rounds). Steady frames render an unchanged view; moving frames
orbit the camera a degree a frame through the view's interactive render, as a drag
does (ParaView raises the window's desired update rate for them). Run it through
scripts/paraview.sh --run, which installs ParaView and builds the plugin:

  bash scripts/paraview.sh --run pvpython Measurement/paraview_blocks.py @PLUGIN@
"""
import argparse
import statistics

from paraview.simple import LoadPlugin, ProgrammableSource, Render, SetActiveView

import paraview_views
from paraview_views import timed

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("--resolution", type=int, default=2048)
parser.add_argument("--frames", type=int, default=8)
parser.add_argument("--rounds", type=int, default=3)
parser.add_argument("--size", default="960x540")
parser.add_argument("--techniques", default="none,uniform,csm,second-depth,evsm4")
arguments = parser.parse_args()
LoadPlugin(arguments.plugin, remote=False, ns=globals())
SIZE = [int(v) for v in arguments.size.split("x")]
GRID = 45

# The boxes of Measurement/many_actors.py: a 45 x 45 grid on a 100 x 100 ground.
MULTIBLOCK_SCRIPT = """
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource
output = self.GetOutput()
ground = vtkPlaneSource(); ground.SetOrigin(-50, -50, 0); ground.SetPoint1(50, -50, 0)
ground.SetPoint2(-50, 50, 0); ground.Update()
output.SetBlock(0, ground.GetOutput())
for i in range({grid}):
    for j in range({grid}):
        height = 0.5 + 3.0 * ((i * 7 + j * 13) % 10) / 10.0
        cube = vtkCubeSource(); cube.SetCenter(-44 + 2 * i, -44 + 2 * j, height / 2)
        cube.SetXLength(1.2); cube.SetYLength(1.2); cube.SetZLength(height); cube.Update()
        output.SetBlock(1 + i * {grid} + j, cube.GetOutput())
""".format(grid=GRID)


def make_source():
    source = ProgrammableSource(OutputDataSetType="vtkMultiblockDataSet", Script=MULTIBLOCK_SCRIPT)
    source.UpdatePipeline()  # the blocks made once, before any view shows them
    return source


def make_view(technique, source):
    view = paraview_views.make_view(technique, [source], SIZE, arguments.resolution)
    place_camera(view)
    return view


def place_camera(view):
    view.CameraPosition = [-65, -70, 35]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]


def steady_frames(view):
    Render(view)
    return [timed(view, lambda: view.StillRender()) for _ in range(arguments.frames)]


def moving_frames(view):
    place_camera(view)
    Render(view)
    camera = view.GetActiveCamera()

    def orbit():
        camera.Azimuth(1.0)
        view.InteractiveRender()

    frames = [timed(view, orbit) for _ in range(arguments.frames)]
    place_camera(view)
    return frames


source = make_source()
techniques = arguments.techniques.split(",")
views = {technique: make_view(technique, source) for technique in techniques}
for view in views.values():
    Render(view)
    Render(view)
print(f"{GRID * GRID} boxes and a ground in one multiblock, {SIZE[0]} x {SIZE[1]}, "
      f"{arguments.resolution}^2 maps, {arguments.frames} frames x {arguments.rounds} rounds")
rates = {}
samples = {(t, kind): [] for t in techniques for kind in ("steady", "moving")}
for _ in range(arguments.rounds):
    for technique, view in views.items():
        SetActiveView(view)
        samples[(technique, "steady")].append(steady_frames(view))
        still = view.GetRenderWindow().GetDesiredUpdateRate()
        samples[(technique, "moving")].append(moving_frames(view))
        rates[technique] = (still, view.GetRenderWindow().GetDesiredUpdateRate())


def median_ms(frames, column):
    return 1000.0 * statistics.median(f[column] for f in frames)


print("| technique | frame | ms | thread CPU ms | / none | CPU / none | CPU µs per prop over none |")
print("|---|---|---:|---:|---:|---:|---:|")
props = GRID * GRID + 1
for kind in ("steady", "moving"):
    for technique in techniques:
        rounds = samples[(technique, kind)]
        walls = [median_ms(r, 0) for r in rounds]
        cpus = [median_ms(r, 1) for r in rounds]
        line = f"| {technique} | {kind} | {statistics.median(walls):.1f} | {statistics.median(cpus):.1f}"
        if "none" in techniques and technique != "none":
            none = samples[("none", kind)]
            ratio = statistics.median(w / median_ms(n, 0) for w, n in zip(walls, none))
            cpu_ratio = statistics.median(c / median_ms(n, 1) for c, n in zip(cpus, none))
            per_prop = statistics.median(1000.0 * (c - median_ms(n, 1)) / props
                                         for c, n in zip(cpus, none))
            line += f" | {ratio:.2f} | {cpu_ratio:.2f} | {per_prop:.2f} |"
        else:
            line += " | 1.00 | 1.00 | 0 |"
        print(line)
print("the window's desired update rate in steady / moving frames (the pass's frames are "
      "interactive from 1): " + ", ".join(f"{t} {s:g} / {m:g}" for t, (s, m) in rates.items()))
