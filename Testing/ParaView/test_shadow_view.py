"""The ParaView plugin's Render View (Shadows), in pvpython: a sphere over a plane
lit by a sun. Each choice of views and storage darkens the ground where the
sphere's shadow falls and keeps it lit elsewhere; the default and cascaded views
equal their baselines; ParaView's plain render view (no plugin pass) leaves the
shadow point lit, so the probes can fail; the light kit's key light is the only
kit light that casts, and only while KeyLightShadows is on.

  xvfb-run -a pvpython Testing/ParaView/test_shadow_view.py PLUGIN OUTDIR
  (SHADOWMAPS_UPDATE_BASELINES=1 writes the baselines; look at them.)
"""
import os
import subprocess
import sys

from paraview.simple import (AddLight, CreateView, Delete, LoadPlugin, Plane, Render,
                             SaveScreenshot, Show, Sphere)
from vtkmodules.vtkIOImage import vtkPNGReader

PLUGIN, OUT = sys.argv[1], sys.argv[2]
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


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def make_view(kind, **properties):
    view = CreateView(kind)
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.Background = [0.32, 0.34, 0.43]
    view.CameraPosition = [0, -12, 7]
    view.CameraFocalPoint = [0, 0, 0.5]
    view.CameraViewUp = [0, 0, 1]
    for name, value in properties.items():
        setattr(view, name, value)
    return view


def show_scene(view, sun=True):
    Show(Plane(Origin=[-5, -5, 0], Point1=[5, -5, 0], Point2=[-5, 5, 0]), view)
    Show(Sphere(Center=SPHERE_CENTER, Radius=1.0, ThetaResolution=48, PhiResolution=48), view)
    if sun:
        view.UseLight = 0
        light = AddLight(view=view)
        light.Coords = "Scene"
        light.Type = "Directional"
        light.Position = SUN
        light.FocalPoint = [0, 0, 0]


def luminance_at(view, png, world):
    renderer = view.GetRenderer()
    renderer.SetWorldPoint(world[0], world[1], world[2], 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    pixel = image.GetScalarComponentAsDouble  # (x, y from the bottom, z, component)
    rgb = [pixel(int(round(x)), int(round(y)), 0, c) for c in range(3)]
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]


def render(view, name):
    Render(view)
    png = os.path.join(OUT, name + ".png")
    SaveScreenshot(png, view, ImageResolution=SIZE)
    return png


def compare_with_baseline(png, name):
    baseline = os.path.join(BASELINES, name + ".png")
    if os.environ.get("SHADOWMAPS_UPDATE_BASELINES") == "1":
        subprocess.run(["cp", png, baseline], check=True)
        print("baseline written: " + baseline + " (look at it, then rerun)")
        return
    # As the C++ image tests: any pixel off by more than 1.5/255 fails.
    result = subprocess.run(["idiff", "-fail", "0.0059", "-warn", "0.0059", baseline, png],
                            capture_output=True, text=True)
    check(result.returncode == 0, name + " equals its baseline " + baseline +
          ("" if result.returncode == 0 else ":\n" + result.stdout))


def shadow_probes(view, png, what):
    dark = luminance_at(view, png, SHADOWED)
    lit = luminance_at(view, png, LIT)
    check(dark < 0.45 * lit, f"{what}: the shadow is dark ({dark:.0f} against lit {lit:.0f})")
    check(lit > 150, f"{what}: the lit ground is lit ({lit:.0f})")


os.makedirs(OUT, exist_ok=True)
LoadPlugin(PLUGIN, remote=False, ns=globals())

# ParaView's own render view: no shadow where the probes expect one.
plain = make_view("RenderView")
show_scene(plain)
png = render(plain, "ParaViewPlainView")
check(luminance_at(plain, png, SHADOWED) > 0.8 * luminance_at(plain, png, LIT),
      "the plain render view leaves the shadow point lit")
Delete(plain)

views = ["Uniform", "LiSPSM", "TSM", "PSM", "GMNPR", "Cascades"]
storages = ["Depth (PCF)", "Dual depth (no bias)", "Moments (EVSM4)"]
for views_choice in views:
    for storage in storages:
        view = make_view("ShadowRenderView", ShadowViews=views_choice, ShadowStorage=storage)
        show_scene(view)
        name = "ParaViewShadowView_" + views_choice + "_" + storage.split(" ")[0]
        png = render(view, name)
        shadow_probes(view, png, views_choice + " / " + storage)
        view.UpdatePropertyInformation()
        check(view.GetPropertyValue("NumberOfShadowedLights") == 1,
              views_choice + " / " + storage + ": one shadowed light")
        if storage == storages[0] and views_choice in ("Uniform", "Cascades"):
            compare_with_baseline(png, "ParaViewShadowView" + ("" if views_choice == "Uniform" else "Cascades"))
        Delete(view)

# SSAO, FXAA and tone mapping keep working with the shadows, and do change the frame.
def mean_difference(first, second):
    result = subprocess.run(["idiff", "-abs", "-o", os.path.join(OUT, "difference.png"), first, second],
                            capture_output=True, text=True)
    for line in result.stdout.splitlines():
        if line.strip().startswith("Mean error"):
            return float(line.split("=")[1])
    return 0.0


plain_effects = make_view("ShadowRenderView")
show_scene(plain_effects)
without = render(plain_effects, "ParaViewShadowViewNoEffects")
Delete(plain_effects)
view = make_view("ShadowRenderView", UseAmbientOcclusion=1, UseFXAA=1, UseToneMapping=1)
show_scene(view)
with_effects = render(view, "ParaViewShadowViewSSAO")
shadow_probes(view, with_effects, "SSAO, FXAA and tone mapping")
difference = mean_difference(without, with_effects)
check(difference > 0.01, f"SSAO, FXAA and tone mapping change the frame (mean difference {difference:.3f})")
Delete(view)

# One view whose choices change between frames: each pass it switches to shadows,
# the one it leaves frees its maps, and the other settings reach the pass.
view = make_view("ShadowRenderView")
show_scene(view)
for views_choice, storage in (("Cascades", "Moments (EVSM4)"), ("LiSPSM", "Dual depth (no bias)"),
                              ("Uniform", "Depth (PCF)"), ("Cascades", "Depth (PCF)")):
    view.ShadowViews = views_choice
    view.ShadowStorage = storage
    png = render(view, "ParaViewShadowViewSwitched")
    shadow_probes(view, png, "switched to " + views_choice + " / " + storage)
view.NumberOfCascades = 2
view.ShadowMapResolution = 256
shadow_probes(view, render(view, "ParaViewShadowViewSmall"), "2 cascades of 256^2")
view.ShadowAnalysisView = "Shadow factor"
png = render(view, "ParaViewShadowViewFactor")
check(luminance_at(view, png, SHADOWED) < 10 and luminance_at(view, png, LIT) > 245,
      "the shadow-factor analysis view shows visibility as grey (0 in the shadow, 1 on the lit ground)")
Delete(view)

# The light kit: its key light casts, the others do not.
for key_light, expected in ((1, 1), (0, 0)):
    view = make_view("ShadowRenderView", KeyLightShadows=key_light)
    show_scene(view, sun=False)
    render(view, f"ParaViewShadowViewLightKit{key_light}")
    view.UpdatePropertyInformation()
    check(view.GetPropertyValue("NumberOfShadowedLights") == expected,
          f"light kit with KeyLightShadows {key_light}: {expected} shadowed lights")
    Delete(view)

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
