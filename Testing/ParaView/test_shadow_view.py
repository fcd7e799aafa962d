"""The ParaView plugin's Render View (Shadows), in pvpython: a sphere over a plane
lit by a sun. Each choice of views and storage darkens the ground where the
sphere's shadow falls and keeps it lit elsewhere; the default and cascaded views
equal their baselines; ParaView's plain render view (no plugin pass) leaves the
shadow point lit, so the probes can fail; the light kit's key light is the only
kit light that casts, and only while KeyLightShadows is on; a representation's
Casts Shadows and Receives Shadows turn its part off; SunDiameter softens the
sun's shadow; translucent and volume representations cast partial shadows; the
axes grid and data axes grid cast none; the frames of an animation (each at a new
view time) are the ones that keep views.

  xvfb-run -a pvpython Testing/ParaView/test_shadow_view.py PLUGIN OUTDIR
  (SHADOWMAPS_UPDATE_BASELINES=1 writes the baselines; look at them.)
"""
import os
import subprocess
import sys

from paraview import servermanager
from paraview.simple import (AddLight, ClearSelection, ColorBy, Delete, ExtractSelection, GetDisplayProperties,
                             Hide, LoadPlugin, SelectSurfaceCells, SetActiveSource, SetActiveView, Show,
                             Sphere, Tessellate, Text, Transform, Wavelet)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shadow_view_testing as testing  # noqa: E402
from shadow_view_testing import (LIT, SHADOWED, SUN, check, check_same_image,  # noqa: E402
                                 compare_with_baseline, failures, in_frame, luminance_at,
                                 make_view, render, rgb_at, shadow_probes, show_scene, show_volume)

PLUGIN = sys.argv[1]
OUT = testing.OUT = sys.argv[2]
os.makedirs(OUT, exist_ok=True)
LoadPlugin(PLUGIN, remote=False, ns=globals())

# ParaView's own render view: no shadow where the probes expect one.
plain = make_view("RenderView")
show_scene(plain)
png = render(plain, "ParaViewPlainView")
check(luminance_at(plain, png, SHADOWED) > 0.8 * luminance_at(plain, png, LIT),
      "the plain render view leaves the shadow point lit")
Delete(plain)

views = ["Automatic", "Uniform", "LiSPSM", "TSM", "PSM", "GMNPR", "Cascades"]
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

# The default: each light's views chosen by the automatic pass, in dual-depth maps.
view = make_view("ShadowRenderView")
check(view.ShadowViews == "Automatic" and view.ShadowStorage == "Dual depth (no bias)",
      f"the default views and storage are Automatic and Dual depth ({view.ShadowViews}, {view.ShadowStorage})")
show_scene(view)
check_same_image(os.path.join(OUT, "ParaViewShadowView_Automatic_Dual.png"), render(view, "ParaViewShadowViewDefault"),
                 "the default view's frame equals Automatic / Dual depth's")
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
                              ("Automatic", "Depth (PCF)"), ("Uniform", "Depth (PCF)"),
                              ("Automatic", "Dual depth (no bias)"), ("Cascades", "Depth (PCF)")):
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
# Chosen views: the legend's colour of the sun's views (vtkAbstractShadowMapPass.h), in
# the even or odd (a quarter darker) map: blue cascades, green LiSPSM (the automatic pass's).
view.ShadowAnalysisView = "Chosen views"
for views_choice, legend in (("Cascades", (0.2, 0.4, 1.0)), ("Automatic", (0.2, 0.8, 0.2))):
    view.ShadowViews = views_choice
    lit = rgb_at(view, render(view, "ParaViewShadowViewChosen" + views_choice), LIT)
    check(any(all(abs(c - 255 * shade * l) <= 1 for c, l in zip(lit, legend)) for shade in (1.0, 0.75)),
          f"the chosen-views analysis view colours {views_choice} as its legend says {tuple(lit)}")
Delete(view)

# The filter, the bias and the moments' blur reach the passes: each changes the
# frame, and the shadow stays.
view = make_view("ShadowRenderView")
show_scene(view)
previous = render(view, "ParaViewShadowViewFilter_default")
for storage, name, value in (("Depth (PCF)", "ShadowFilter", "Hard"),
                             ("Depth (PCF)", "ShadowFilter", "Poisson"),
                             ("Depth (PCF)", "ShadowFilterRadius", 6.0),
                             ("Depth (PCF)", "ShadowConstantBias", 3000.0),
                             ("Dual depth (no bias)", "ShadowFilter", "Hard"),
                             ("Moments (EVSM4)", "MomentsBlurRadius", 0.0),
                             ("Moments (EVSM4)", "MomentsBlurRadius", 6.0)):
    what = f"{storage}: {name} {value}"
    if view.ShadowStorage != storage:
        view.ShadowStorage = storage
        previous = render(view, "ParaViewShadowViewFilter_" + storage.split(" ")[0])
    setattr(view, name, value)
    png = render(view, f"ParaViewShadowViewFilter_{name}_{value}")
    check(mean_difference(previous, png) > 0.0, what + " changes the frame")
    shadow_probes(view, png, what)
    previous = png
Delete(view)

# Volumes, translucency, scalar colouring and annotations: with no light that
# casts (the light kit's key light's shadows off), the shadow view draws exactly
# what ParaView's plain view draws; with the key light casting, shadows appear
# and the volume is still drawn.
def show_rich_scene(view):
    ground, sphere = show_scene(view, sun=False)
    sphere_display = GetDisplayProperties(sphere, view)
    ColorBy(sphere_display, ("POINTS", "Normals", "Z"))
    glass = Sphere(Center=[-3.0, 2.0, 1.0], Radius=0.8)
    glass_display = Show(glass, view)
    glass_display.Opacity = 0.4
    wavelet = Wavelet(WholeExtent=[2, 5, -5, -2, 0, 3])
    volume = Show(wavelet, view)
    volume.Representation = "Volume"
    ColorBy(volume, ("POINTS", "RTData"))
    Show(Text(Text="Render View (Shadows)"), view)
    return wavelet


plain = make_view("RenderView")
show_rich_scene(plain)
plain_png = render(plain, "ParaViewRichPlain")
view = make_view("ShadowRenderView", KeyLightShadows=0)
wavelet = show_rich_scene(view)
unshadowed = render(view, "ParaViewRichNoShadows")
check_same_image(plain_png, unshadowed,
                 "volume, translucency, colouring and text without shadows equal the plain view")
view.KeyLightShadows = 1
shadowed = render(view, "ParaViewRichShadows")
check(mean_difference(unshadowed, shadowed) > 0.0, "the key light's shadows appear among them")
Hide(wavelet, view)
without_volume = render(view, "ParaViewRichShadowsNoVolume")
# Inside the volume's box (x 2..5, y -5..-2, z 0..3) it changes the pixels.
inside = [[x, y, z] for x in (2.5, 3.5, 4.5) for y in (-4.5, -3.5, -2.5) for z in (0.5, 1.5, 2.5)]
inside = [p for p in inside if in_frame(view, p)]  # the box runs off the frame's edge
check(len(inside) >= 9, f"{len(inside)} of the volume's probe points are in the frame (at least 9)")
change = max(abs(luminance_at(view, shadowed, p) - luminance_at(view, without_volume, p)) for p in inside)
check(change > 20, f"the volume is still drawn with shadows (up to {change:.0f} grey levels)")
Delete(view)
Delete(plain)

# Selection renders ids through the view: the shadow pass steps aside and the
# cells of the sphere under the rectangle are selected.
view = make_view("ShadowRenderView")
_, sphere = show_scene(view)
render(view, "ParaViewShadowViewBeforeSelection")
SetActiveView(view)
SetActiveSource(sphere)
SelectSurfaceCells(Rectangle=[150, 150, 250, 220], View=view)
selected = servermanager.Fetch(ExtractSelection(Input=sphere))
check(selected is not None and selected.GetNumberOfCells() > 0,
      f"surface selection in the shadow view selects the sphere's cells "
      f"({selected.GetNumberOfCells() if selected else 0})")
ClearSelection(sphere)
shadow_probes(view, render(view, "ParaViewShadowViewAfterSelection"), "after a selection")
Delete(view)

# Per representation: a sphere that does not cast leaves the ground lit, a
# ground that does not receive stays lit under it; both back on, the shadow
# returns. An unstructured grid's surface (UnstructuredGridRepresentation)
# takes the roles too.
view = make_view("ShadowRenderView")
ground, sphere = show_scene(view)
sphere_display = GetDisplayProperties(sphere, view)
ground_display = GetDisplayProperties(ground, view)
check(sphere_display.CastsShadows == 1 and ground_display.ReceivesShadows == 1,
      "representations cast and receive shadows by default")


def shadow_is_dark(png):
    return luminance_at(view, png, SHADOWED) < 0.45 * luminance_at(view, png, LIT)


sphere_display.CastsShadows = 0
check(not shadow_is_dark(render(view, "ParaViewShadowViewSphereCastsNot")),
      "a sphere with Casts Shadows off leaves the ground lit")
sphere_display.CastsShadows = 1
ground_display.ReceivesShadows = 0
check(not shadow_is_dark(render(view, "ParaViewShadowViewGroundReceivesNot")),
      "a ground with Receives Shadows off stays lit under the sphere")
ground_display.ReceivesShadows = 1
shadow_probes(view, render(view, "ParaViewShadowViewRolesBack"), "roles back on")
Hide(sphere, view)
grid = Tessellate(Input=sphere)
grid_display = Show(grid, view)
check(grid.GetDataInformation().GetDataSetTypeAsString() == "vtkUnstructuredGrid",
      "the tessellated sphere is an unstructured grid")
shadow_probes(view, render(view, "ParaViewShadowViewGridCasts"), "an unstructured grid casts")
grid_display.CastsShadows = 0
check(not shadow_is_dark(render(view, "ParaViewShadowViewGridCastsNot")),
      "an unstructured grid with Casts Shadows off leaves the ground lit")
# A 2 x 2 x 2 box of image data above the ground, and the same as a structured
# grid: each casts the shadow, and with Casts Shadows off does not.
Hide(grid, view)
box = Wavelet(WholeExtent=[-1, 1, -1, 1, 1, 3])
for kind, source, proxy in (("image data", box, "UniformGridRepresentation"),
                            ("a structured grid", Transform(Input=box), "StructuredGridRepresentation")):
    display = Show(source, view)
    display.Representation = "Surface"
    check(display.GetXMLName() == proxy, f"{kind} is shown by {proxy} ({display.GetXMLName()})")
    check(shadow_is_dark(render(view, "ParaViewShadowViewRoles" + proxy)), f"{kind} casts")
    display.CastsShadows = 0
    check(not shadow_is_dark(render(view, "ParaViewShadowViewRoles" + proxy + "Off")),
          f"{kind} with Casts Shadows off leaves the ground lit")
    Hide(source, view)
Delete(view)

# Soft shadows: SunDiameter sizes the sun. Across the sphere's shadow (at right
# angles to the sun's horizontal direction its half width is the sphere's
# radius), the hard edge falls from lit to dark within a few pixels; an 8 degree
# sun's penumbra, about 0.22 wide, leaves its middle half lit and lightens the
# umbra's rim, while the umbra's centre stays dark and the lit ground lit.
# LampRadius sizes positional lights only: under the sun it changes nothing.
across = [-1.0 / 5 ** 0.5, 2.0 / 5 ** 0.5, 0.0]
def across_shadow(distance):
    return [SHADOWED[i] + distance * across[i] for i in range(3)]
view = make_view("ShadowRenderView")
show_scene(view)
hard = render(view, "ParaViewShadowViewHardSun")
view.LampRadius = 0.5
check_same_image(hard, render(view, "ParaViewShadowViewLampRadius"),
                 "LampRadius leaves a sun's shadow as it was")
view.SunDiameter = 8.0
soft = render(view, "ParaViewShadowViewSoftSun")
check(mean_difference(hard, soft) > 0.0, "SunDiameter 8 changes the frame")
lit = luminance_at(view, soft, LIT)
dark = luminance_at(view, soft, SHADOWED)
check(dark < 0.2 * lit, f"the umbra stays dark under the 8 degree sun ({dark:.0f} of {lit:.0f})")
edge = (luminance_at(view, soft, across_shadow(1.0)) - dark) / (lit - dark)
check(0.25 < edge < 0.75, f"the shadow's edge is half lit under the 8 degree sun ({edge:.2f})")
rim_soft = luminance_at(view, soft, across_shadow(0.95))
rim_hard = luminance_at(view, hard, across_shadow(0.95))
check(rim_soft > rim_hard + 10, f"the umbra's rim is lighter under the 8 degree sun "
      f"({rim_soft:.0f} against {rim_hard:.0f})")
view.SunDiameter = 0.0
check_same_image(hard, render(view, "ParaViewShadowViewHardSunAgain"),
                 "SunDiameter 0 gives the hard frame back")
Delete(view)

# LampRadius sizes a positional light; SunDiameter leaves it as it was.
view = make_view("ShadowRenderView")
show_scene(view, sun=False)
view.UseLight = 0
lamp = AddLight(view=view)
lamp.Coords = "Scene"
lamp.Type = "Positional"
lamp.Position = [2 * c for c in SUN]
lamp.FocalPoint = [0, 0, 0]
lamp.ConeAngle = 60
hard = render(view, "ParaViewShadowViewHardLamp")
view.SunDiameter = 8.0
check_same_image(hard, render(view, "ParaViewShadowViewLampSunDiameter"),
                 "SunDiameter leaves a lamp's shadow as it was")
view.LampRadius = 0.5
check(mean_difference(hard, render(view, "ParaViewShadowViewSoftLamp")) > 0.0,
      "LampRadius 0.5 softens the lamp's shadow")
view.UpdatePropertyInformation()
check(view.GetPropertyValue("NumberOfShadowedLights") == 1, "the sized lamp casts")
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

# Translucent representations cast partial shadows tinted by their colour
# (docs/TRANSLUCENT.md), with ParaView's depth peeling on (its default) or off.
view = make_view("ShadowRenderView")
ground, sphere = show_scene(view)
display = GetDisplayProperties(sphere, view)
display.AmbientColor = display.DiffuseColor = [1.0, 0.2, 0.2]
opaque_png = render(view, "ParaViewShadowViewOpaqueRed")
opaque, lit = rgb_at(view, opaque_png, SHADOWED), rgb_at(view, opaque_png, LIT)
display.Opacity = 0.5
for peeling in (1, 0):
    if view.GetProperty("DepthPeeling") is not None:
        view.DepthPeeling = peeling
    tinted = rgb_at(view, render(view, f"ParaViewShadowViewTranslucentRed{peeling}"), SHADOWED)
    check(opaque[0] + 20 < tinted[0] < lit[0] - 20,
          f"depth peeling {peeling}: the half-transparent sphere's shadow is partial "
          f"(red {tinted[0]:.0f} between {opaque[0]:.0f} and {lit[0]:.0f})")
    check(tinted[0] > tinted[2] + 20,
          f"depth peeling {peeling}: and red ({tinted[0]:.0f} {tinted[1]:.0f} {tinted[2]:.0f})")
display.Opacity = 1.0
check(rgb_at(view, render(view, "ParaViewShadowViewOpaqueRedAgain"), SHADOWED) == opaque,
      "opacity 1 again: the opaque shadow as it was")
Delete(view)

# A volume representation casts (docs/TRANSLUCENT.md): a wavelet shown as a
# volume where the sphere was shades the ground under it, partly; opted out
# of casting (its Casts Shadows), it shades nothing.
view = make_view("ShadowRenderView")
ground, sphere = show_scene(view)
Hide(sphere, view)
lit_png = render(view, "ParaViewShadowViewNoVolume")
open_ground = luminance_at(view, lit_png, SHADOWED)
volume = show_volume(view)
under_volume = luminance_at(view, render(view, "ParaViewShadowViewVolume"), SHADOWED)
check(0.1 * open_ground < under_volume < 0.9 * open_ground,
      f"the volume's shadow is partial (luminance {under_volume:.0f}, open ground {open_ground:.0f})")
volume.CastsShadows = 0
opted_out = luminance_at(view, render(view, "ParaViewShadowViewVolumeOptedOut"), SHADOWED)
check(abs(opted_out - open_ground) < 2,
      f"opted out, the volume shades nothing (luminance {opted_out:.0f}, open ground {open_ground:.0f})")
Delete(view)

# Annotations: the view's axes grid and the sphere's data axes grid, their grid
# lines on, cast no shadow: with the sphere opted out of casting, nothing else
# could, and the shadow view draws what ParaView's plain view draws; the sphere
# casting again, its shadow is dark among them.
def show_grid(grid):
    """Shows an axes grid with its grid lines (the name of its visibility
    differs between ParaView versions: the data axes grid of 5.13 has none
    called Visibility)."""
    shown = [name for name in ("GridAxesVisibility", "Visibility", "ShowGrid")
             if grid.GetProperty(name) is not None]
    for name in shown:
        setattr(grid, name, 1)
    check("ShowGrid" in shown and len(shown) > 1,
          f"{grid.GetXMLName()} is shown with its grid lines ({', '.join(shown)})")


frames = {}
for kind in ("RenderView", "ShadowRenderView"):
    view = make_view(kind)
    ground, sphere = show_scene(view)
    sphere_display = GetDisplayProperties(sphere, view)
    show_grid(view.AxesGrid)
    show_grid(sphere_display.DataAxesGrid)
    if kind == "ShadowRenderView":
        sphere_display.CastsShadows = 0
    frames[kind] = render(view, "ParaViewGrids" + kind)
    if kind == "ShadowRenderView":
        sphere_display.CastsShadows = 1
        shadow_probes(view, render(view, "ParaViewGridsSphereCasts"), "among the axes grids")
    Delete(view)
check_same_image(frames["RenderView"], frames["ShadowRenderView"],
                 "the axes grid and the data axes grid cast no shadow (the plain view's frame)")

# An animation: ParaView gives each frame a new view time; still renders from
# then on (the screenshot's too) keep warped and cascaded views as a drag does,
# until a drag, whose closing still render fits anew. The camera moves along
# the way, as a camera track moves it.
view = make_view("ShadowRenderView", ShadowViews="Cascades")
show_scene(view)
kept = []
for frame, time in enumerate((0.0, 0.0, 1.0, 2.0, 2.0, "drag")):
    if time == "drag":
        view.InteractiveRender()
    else:
        view.ViewTime = time
    view.CameraPosition = [0.1 * frame, -12, 7]
    png = render(view, f"ParaViewAnimationFrame{frame}")
    view.UpdatePropertyInformation()
    kept.append(view.GetPropertyValue("AnimationFrame"))
    shadow_probes(view, png, f"animation frame {frame} ({time})")
check(kept == [0, 0, 1, 1, 1, 0], f"frames from a new view time to a drag are animation frames ({kept})")
Delete(view)

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
