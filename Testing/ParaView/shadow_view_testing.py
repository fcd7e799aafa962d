"""What the ParaView plugin's pvpython and pvbatch tests share: the scene (a
sphere over a plane under a sun), the view's camera, probes at world points,
strict baseline comparison (idiff) and a failure list."""
import os
import subprocess

from paraview.simple import (AddLight, ColorBy, CreateView, Plane, Render, SaveScreenshot, Show,
                             Sphere, Wavelet)
from vtkmodules.vtkIOImage import vtkPNGReader

HERE = os.path.dirname(os.path.abspath(__file__))
BASELINES = os.path.join(HERE, "..", "Data", "Baseline")
SIZE = [400, 300]
SUN = [2.0, 1.0, 6.0]             # from the focal point (origin) toward the sun
SPHERE_CENTER = [0.0, 0.0, 1.5]
# Where the sun's ray through the sphere's centre meets the ground, and a point
# no shadow reaches.
SHADOWED = [SPHERE_CENTER[i] - SUN[i] * SPHERE_CENTER[2] / SUN[2] for i in range(3)]
LIT = [3.0, 3.0, 0.0]
failures = []
OUT = None  # set by the test: where frames go


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def make_view(kind, **properties):
    view = CreateView(kind)
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    # ParaView 6 draws the colour palette's background unless told not to.
    if view.GetProperty("UseColorPaletteForBackground") is not None:
        view.UseColorPaletteForBackground = 0
    view.Background = [0.32, 0.34, 0.43]
    view.CameraPosition = [0, -12, 7]
    view.CameraFocalPoint = [0, 0, 0.5]
    view.CameraViewUp = [0, 0, 1]
    for name, value in properties.items():
        setattr(view, name, value)
    return view


def add_sun(view):
    """Turns the light kit off and lights the view with the sun alone."""
    view.UseLight = 0
    light = AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Directional"
    light.Position = SUN
    light.FocalPoint = [0, 0, 0]


def show_scene(view, sun=True):
    """Shows the ground and the sphere in `view` (and the sun); returns both sources."""
    ground = Plane(Origin=[-5, -5, 0], Point1=[5, -5, 0], Point2=[-5, 5, 0])
    sphere = Sphere(Center=SPHERE_CENTER, Radius=1.0, ThetaResolution=48, PhiResolution=48)
    Show(ground, view)
    Show(sphere, view)
    if sun:
        add_sun(view)
    return ground, sphere


def show_volume(view):
    """A wavelet shown as a volume (ParaView's default transfer functions) in the
    place of the sphere: a box of 2 units centred 1.5 above the ground."""
    volume = Show(Wavelet(WholeExtent=[-10, 10, -10, 10, -10, 10]), view)
    volume.Representation = "Volume"
    ColorBy(volume, ("POINTS", "RTData"))
    volume.Scale = [0.1, 0.1, 0.1]
    # ParaView 5.13 renamed Position Translation.
    setattr(volume, "Translation" if volume.GetProperty("Translation") is not None else "Position",
            SPHERE_CENTER)
    volume.ScalarOpacityUnitDistance = 20.0  # data lengths: the wavelet is 20 across
    return volume


def pixel_of(view, world):
    """The pixel (x, y from the bottom) where `world` is seen."""
    renderer = view.GetRenderer()
    renderer.SetWorldPoint(world[0], world[1], world[2], 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    return int(round(x)), int(round(y))


def in_frame(view, world):
    x, y = pixel_of(view, world)
    return 0 <= x < SIZE[0] and 0 <= y < SIZE[1]


def rgb_at(view, png, world):
    """RGB (0-255) where `world` is seen; a probe outside the frame fails."""
    x, y = pixel_of(view, world)
    if not in_frame(view, world):
        check(False, f"probe {world} falls outside the frame, at pixel ({x}, {y})")
        return [float("nan")] * 3
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    pixel = image.GetScalarComponentAsDouble  # (x, y from the bottom, z, component)
    return [pixel(x, y, 0, c) for c in range(3)]


def luminance_at(view, png, world):
    """Luminance (0-255) where `world` is seen; a probe outside the frame fails."""
    rgb = rgb_at(view, png, world)
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]


def render(view, name):
    Render(view)
    png = os.path.join(OUT, name + ".png")
    SaveScreenshot(png, view, ImageResolution=SIZE)
    return png


def baseline_variant():
    """The folder of this ParaView version's own baselines, for the frames it
    draws differently from ParaView 5.11 (whose baselines are the root's)."""
    from paraview import servermanager
    manager = servermanager.vtkSMProxyManager
    version = (manager.GetVersionMajor(), manager.GetVersionMinor())
    return "" if version <= (5, 11) else "paraview-%d.%d" % version


def compare_with_baseline(png, name):
    host = os.path.join(BASELINES, name + ".png")
    variant = baseline_variant()
    own = os.path.join(BASELINES, variant, name + ".png") if variant else None
    if os.environ.get("SHADOWMAPS_UPDATE_BASELINES") == "1":
        if own and same_image(host, png):
            if os.path.exists(own):
                os.remove(own)
            print("equals the ParaView 5.11 baseline " + host + ": no variant kept")
            return
        target = own or host
        os.makedirs(os.path.dirname(target), exist_ok=True)
        subprocess.run(["cp", png, target], check=True)
        print("baseline written: " + target + " (look at it, then rerun)")
        return
    baseline = own if own and os.path.exists(own) else host
    check_same_image(baseline, png, name + " equals its baseline " + baseline)


def same_image(expected, actual):
    return idiff(expected, actual).returncode == 0


def idiff(expected, actual):
    return subprocess.run(["idiff", "-fail", "0.0059", "-warn", "0.0059", expected, actual],
                          capture_output=True, text=True)


def check_same_image(expected, actual, what):
    """As the C++ image tests: any pixel off by more than 1.5/255 fails."""
    result = idiff(expected, actual)
    check(result.returncode == 0, what + ("" if result.returncode == 0 else ":\n" + result.stdout))


def check_nearly_same_image(expected, actual, percent, what):
    """At most `percent` % of the pixels off by more than 1.5/255."""
    result = subprocess.run(["idiff", "-fail", "0.0059", "-failpercent", str(percent), "-warn", "0.0059",
                             expected, actual], capture_output=True, text=True)
    check(result.returncode in (0, 1), what + ("" if result.returncode in (0, 1) else ":\n" + result.stdout))


def shadow_probes(view, png, what):
    dark = luminance_at(view, png, SHADOWED)
    lit = luminance_at(view, png, LIT)
    check(dark < 0.45 * lit, f"{what}: the shadow is dark ({dark:.0f} against lit {lit:.0f})")
    check(lit > 150, f"{what}: the lit ground is lit ({lit:.0f})")


