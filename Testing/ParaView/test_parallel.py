"""The ParaView plugin in parallel: under `mpiexec -np 3 pvbatch`, rank 0 holds the
ground, rank 1 the sphere and rank 2 nothing (a programmable source gives each
rank its piece). The sphere's shadow falls on rank 0's ground only if the ranks'
depth maps are combined, and rank 2 must still take part. The composited frame
is compared with the same scene on one rank (both pieces, as two sources),
written first by the `serial` run, for the uniform map, cascades and LiSPSM of depths,
the uniform map of dual depths and of moments, and the automatic views (the default)
of dual depths. The representation's Casts Shadows
and Receives Shadows reach every rank. A translucent sphere on rank 1 and a
volume split over the ranks shade rank 0's ground as on one rank (their
transmittance maps multiplied over the ranks; the sphere with uniform depth maps
exactly, with the default views and storage all but 0.01 % of the pixels). The same holds with the pieces on three
pvserver ranks behind a pvpython client (mode pvserver, port in argv[4]).

  xvfb-run -a pvbatch Testing/ParaView/test_parallel.py PLUGIN OUTDIR serial
  xvfb-run -a mpiexec -np 3 pvbatch Testing/ParaView/test_parallel.py PLUGIN OUTDIR parallel
  xvfb-run -a scripts/paraview_pvserver.sh PLUGIN OUTDIR   (pvserver mode: a client of 3 pvserver ranks)
"""
import os
import sys
import time
from statistics import median

from paraview.simple import (Connect, Delete, GetSettingsProxy, LoadPlugin, ProgrammableSource,
                             Render, Show)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shadow_view_testing as testing  # noqa: E402
from shadow_view_testing import (LIT, SHADOWED, SUN, add_sun, check, check_nearly_same_image, check_same_image,  # noqa: E402
                                 failures, luminance_at, make_view, render, rgb_at, shadow_probes,
                                 show_volume)

PLUGIN, MODE = sys.argv[1], sys.argv[3]
# Pieces on several ranks: pvbatch's, or a pvserver's behind this client.
SPLIT = MODE in ("parallel", "pvserver")
RANKS = "3 server ranks" if MODE == "pvserver" else "3 ranks" if SPLIT else "1 rank"


def combination_totals(view):
    """Bytes the first rank all-reduced so far, and seconds it spent doing so."""
    view.UpdatePropertyInformation()
    return view.GetPropertyValue("BytesCombined"), view.GetPropertyValue("SecondsCombining")


def timed_frames(view, count=5):
    times = []
    for _ in range(count):
        started = time.perf_counter()
        Render(view)
        times.append(time.perf_counter() - started)
    return times


OUT = testing.OUT = sys.argv[2]
os.makedirs(OUT, exist_ok=True)
if MODE == "pvserver":
    Connect("localhost", int(sys.argv[4]))
    LoadPlugin(PLUGIN, remote=True, ns=globals())
    # Render on the server ranks (each shades its piece, IceT composites),
    # however small the data, instead of delivering the geometry to the client.
    GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 0.0
LoadPlugin(PLUGIN, remote=False, ns=globals())

# A programmable source whose piece on rank GROUND is the ground and on rank
# SPHERE the sphere (-1: none).
PIECES = """
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkParallelCore import vtkMultiProcessController
controller = vtkMultiProcessController.GetGlobalController()
rank = controller.GetLocalProcessId() if controller else 0
pieces = vtkAppendPolyData()
if rank == GROUND:
    ground = vtkPlaneSource()
    ground.SetOrigin(-5, -5, 0); ground.SetPoint1(5, -5, 0); ground.SetPoint2(-5, 5, 0)
    ground.SetResolution(GROUND_CELLS, GROUND_CELLS)
    pieces.AddInputConnection(ground.GetOutputPort())
if rank == SPHERE:
    sphere = vtkSphereSource()
    sphere.SetCenter(0, 0, 1.5); sphere.SetRadius(1.0)
    sphere.SetThetaResolution(48); sphere.SetPhiResolution(48)
    pieces.AddInputConnection(sphere.GetOutputPort())
if pieces.GetNumberOfInputConnections(0) > 0:
    pieces.Update()
    self.GetOutput().ShallowCopy(pieces.GetOutput())
"""


def pieces_script(ground_rank, sphere_rank, cells=1):
    return (PIECES.replace("GROUND_CELLS", str(cells)).replace("GROUND", str(ground_rank))
            .replace("SPHERE", str(sphere_rank)))


def show_pieces(view):
    """In parallel one source, the ground on rank 0 and the sphere on rank 1;
    on one rank the same two pieces as two sources, so that both runs' fits see
    the ground's and the sphere's boxes. Returns the (parallel) display."""
    pieces = [(0, 1)] if SPLIT else [(0, -1), (-1, 0)]
    displays = [Show(ProgrammableSource(OutputDataSetType="vtkPolyData",
                                        Script=pieces_script(g, s)), view) for g, s in pieces]
    return displays[0]


# Every storage combines: depths, two surfaces' depths (peeled), moments (from
# the nearest light depth); cascades and a warp (whose fit follows every rank's
# props) with depths.
CASES = (("Uniform", "Depth (PCF)"), ("Cascades", "Depth (PCF)"), ("LiSPSM", "Depth (PCF)"),
         ("Uniform", "Dual depth (no bias)"), ("Uniform", "Moments (EVSM4)"),
         ("Automatic", "Dual depth (no bias)"))
for views_choice, storage in CASES:
    view = make_view("ShadowRenderView", ShadowViews=views_choice, ShadowStorage=storage)
    display = show_pieces(view)
    add_sun(view)
    what = views_choice + " / " + storage
    name = "ParaViewParallel" + views_choice + ("" if storage == CASES[0][1] else storage.split(" ")[0])
    png = render(view, name + "_" + MODE)  # the first frame compiles shaders
    # Frame cost (printed, not tested): steady frames keep the maps; a frame
    # whose sun moved re-renders them, and on several ranks combines them.
    steady_before = combination_totals(view)
    steady = timed_frames(view)
    steady_bytes = combination_totals(view)[0] - steady_before[0]
    sun = view.AdditionalLights[0]
    moved = []
    combined_before = combination_totals(view)
    for step in range(4):
        sun.Position = [SUN[0] + 0.01 * (step + 1), SUN[1], SUN[2]]
        moved += timed_frames(view, 1)
    combined = [(after - before) / len(moved)
                for after, before in zip(combination_totals(view), combined_before)]
    sun.Position = SUN
    render(view, name + "_" + MODE)
    if MODE == "pvserver":
        check(view.GetClientSideObject().GetUseDistributedRenderingForRender(),
              what + ": the server ranks rendered the frame, not the client")
    if SPLIT:
        shadow_probes(view, png, f"{what} on {RANKS} (caster on rank 1, ground on rank 0)")
        serial = os.path.join(OUT, name + "_serial.png")
        check_same_image(serial, png, f"{what}: the frame of {RANKS} equals the 1-rank frame")
    else:
        shadow_probes(view, png, what + " on 1 rank")
    if SPLIT and (views_choice, storage) == CASES[0]:
        # The representation's roles reach every rank: the caster's (rank 1)
        # and the receiver's (rank 0).
        for role in ("CastsShadows", "ReceivesShadows"):
            setattr(display, role, 0)
            off = render(view, name + "_" + role + "Off")
            check(luminance_at(view, off, SHADOWED) > 0.8 * luminance_at(view, off, LIT),
                  f"{role} off on {RANKS}: the ground under the sphere is lit")
            setattr(display, role, 1)
    layers = view.NumberOfCascades if views_choice == "Cascades" else 1
    # Floats all-reduced per texel: a depth; the nearest depth, then the one
    # behind it (two reductions); a light depth.
    floats = 2 if storage.startswith("Dual") else 1
    mebibytes = 4 * floats * view.ShadowMapResolution ** 2 * layers / 2 ** 20
    print(f"{what}, {RANKS}: steady frame "
          f"{1000 * median(steady):.0f} ms, frame whose sun moved {1000 * median(moved):.0f} ms "
          f"({layers} map(s) of {view.ShadowMapResolution}^2"
          + (f", {mebibytes:.0f} MiB combined per rank; measured per frame whose sun moved: "
             f"{combined[0] / 2 ** 20:.0f} MiB all-reduced in {1000 * combined[1]:.0f} ms)"
             if MODE == "parallel" else f", {mebibytes:.0f} MiB combined per rank)" if SPLIT else ")"))
    # (The information properties come from pvbatch's first rank; a pvserver
    # client reads its own view's, which combines nothing.)
    if MODE == "parallel":
        check(steady_bytes == 0, f"{what}: steady frames combine nothing ({steady_bytes:.0f} bytes)")
        check(abs(combined[0] - mebibytes * 2 ** 20) < 1024,  # and the maps' shape
              f"{what}: each frame whose sun moved all-reduces the maps once ({mebibytes:.0f} MiB)")
    Delete(view)


# Translucent casters and volumes on other ranks shade rank 0's ground: the
# transmittance maps multiply over the ranks (docs/TRANSLUCENT.md). A
# half-transparent red sphere on rank 1 (rank 0 in the serial run), as a
# source of its own; then a wavelet volume that every rank holds a piece of.
def show_ground_and(view, sphere=True):
    """The ground (rank 0) and, if `sphere`, the sphere as a source of its own
    (rank 1 in parallel); returns the sphere's display."""
    sphere_rank = 1 if SPLIT else 0
    pieces = [(0, -1)] + ([(-1, sphere_rank)] if sphere else [])
    # A ground of many cells: with translucent geometry or volumes, ParaView
    # 5.13 and later redistribute the data over the ranks for ordered
    # compositing, and a single quad is drawn by one rank inside its region only.
    displays = [Show(ProgrammableSource(OutputDataSetType="vtkPolyData",
                                        Script=pieces_script(g, s, cells=32)), view) for g, s in pieces]
    return displays[-1]


# Exact with the uniform depth map; with the default (automatic views on dual
# depth) one pixel of 120,000 at the sphere's edge came out 2/255 apart on 3 ranks
# (ParaView 6.1), so there at most 0.01 % of the pixels may differ.
for config, exact in (({"ShadowViews": "Uniform", "ShadowStorage": "Depth (PCF)"}, True), ({}, False)):
    view = make_view("ShadowRenderView", **config)
    sphere_display = show_ground_and(view)
    sphere_display.AmbientColor = sphere_display.DiffuseColor = [1.0, 0.2, 0.2]
    sphere_display.Opacity = 0.5
    add_sun(view)
    what = "translucent red sphere" + ("" if exact else " (default views and storage)")
    name = "ParaViewParallelTranslucent" + ("" if exact else "Default")
    png = render(view, name + "_" + MODE)
    tinted, lit = rgb_at(view, png, SHADOWED), rgb_at(view, png, LIT)
    check(0.2 * lit[0] < tinted[0] < 0.9 * lit[0] and tinted[0] > tinted[2] + 20,
          f"{what} on {RANKS}: a partial red shadow on the ground "
          f"({tinted[0]:.0f} {tinted[1]:.0f} {tinted[2]:.0f}, lit {lit[0]:.0f})")
    if SPLIT:
        serial = os.path.join(OUT, name + "_serial.png")
        if exact:
            check_same_image(serial, png, f"{what}: the frame of {RANKS} equals the 1-rank frame")
        else:
            check_nearly_same_image(serial, png, 0.01,
                                    f"{what}: the frame of {RANKS} nearly equals the 1-rank frame")
    Delete(view)

view = make_view("ShadowRenderView")
show_ground_and(view, sphere=False)
show_volume(view)
add_sun(view)
png = render(view, "ParaViewParallelVolume_" + MODE)
under, open_ground = luminance_at(view, png, SHADOWED), luminance_at(view, png, LIT)
check(0.1 * open_ground < under < 0.9 * open_ground,
      f"volume on {RANKS}: its shadow is partial ({under:.0f}, open ground {open_ground:.0f})")
if SPLIT:
    serial = luminance_at(view, os.path.join(OUT, "ParaViewParallelVolume_serial.png"), SHADOWED)
    check(abs(under - serial) < 4,
          f"volume in pieces on {RANKS}: the shadow of the whole ({under:.0f} against {serial:.0f} on 1 rank)")
Delete(view)

print(f"{len(failures)} failures")
if failures:
    sys.exit(1)  # pvbatch's other ranks are then killed: a failing exit status either way
