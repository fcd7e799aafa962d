"""The Python package imports, turns shadows on in one line and renders them."""
import os
import sys

import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)

import vtkshadowmaps


def add(renderer, source):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetAmbient(0.15)
    renderer.AddActor(actor)


def luminance(renderer, image, world):
    renderer.SetWorldPoint(*world, 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    scalars = image.GetPointData().GetScalars()
    width = image.GetDimensions()[0]
    r, g, b = scalars.GetTuple3(int(y) * width + int(x))
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def render_with(renderer, window, grab, shadow_pass, *points):
    """Renders with `shadow_pass`; the frame and the luminance at each point."""
    renderer.SetPass(shadow_pass)
    window.Render()
    grab.Modified()
    grab.Update()
    image = grab.GetOutput()
    return image, [luminance(renderer, image, point) for point in points]


UNDER_THE_SPHERE = (0.0, 0.0, 0.0)
OPEN_GROUND = (3.0, -3.0, 0.0)
SPHERE_TOP = (0.0, 0.0, 2.5)
SHADOW_RIM = (0.5, 0.0, 0.0)  # the sphere's radius: the hard shadow's edge


def main(output_dir):
    renderer = vtkRenderer()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(320, 240)
    window.AddRenderer(renderer)
    plane = vtkPlaneSource()
    plane.SetOrigin(-5, -5, 0)
    plane.SetPoint1(5, -5, 0)
    plane.SetPoint2(-5, 5, 0)
    add(renderer, plane)
    sphere = vtkSphereSource()
    sphere.SetCenter(0, 0, 1.5)
    sphere.SetThetaResolution(32)
    sphere.SetPhiResolution(32)
    add(renderer, sphere)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(False)
    light.SetPosition(0, 0, 1)
    light.SetFocalPoint(0, 0, 0)
    renderer.AutomaticLightCreationOff()
    renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -10, 8)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    image, (under, open_ground) = render_with(
        renderer, window, grab, vtkshadowmaps.vtkWarpedShadowMapPass(), UNDER_THE_SPHERE, OPEN_GROUND)
    os.makedirs(output_dir, exist_ok=True)
    writer = vtkPNGWriter()
    writer.SetInputData(image)
    writer.SetFileName(os.path.join(output_dir, "python_shadow.png"))
    writer.Write()
    print(f"under the sphere {under:.1f}, open ground {open_ground:.1f}")
    assert under < 80, "the sun straight above puts the ground under the sphere in shadow"
    assert open_ground > 120, "open ground is lit"

    # A sun with a size (LIGHT_SIZE: 10 degrees across): the ground under the
    # sphere stays in its umbra, the rim of its shadow is a penumbra.
    size_key = vtkshadowmaps.vtkAbstractShadowMapPass.LIGHT_SIZE()
    light.GetInformation().Set(size_key, 10.0)
    assert vtkshadowmaps.vtkAbstractShadowMapPass.GetLightSize(light) == 10.0
    _, (under, open_ground, rim) = render_with(
        renderer, window, grab, vtkshadowmaps.vtkWarpedShadowMapPass(), UNDER_THE_SPHERE,
        OPEN_GROUND, SHADOW_RIM)
    print(f"sized sun: under the sphere {under:.1f}, open ground {open_ground:.1f}, rim {rim:.1f}")
    assert under < 80 and open_ground > 120
    assert under + 15 < rim < open_ground - 15, "the shadow's rim is half lit"
    light.GetInformation().Remove(size_key)

    # The two strategies from Python: depth maps with cascaded views.
    cascades = vtkshadowmaps.vtkCascadedShadowMapViews()
    cascades.SetNumberOfCascades(2)
    cascades.SetFitModeToTight()
    depth = vtkshadowmaps.vtkDepthShadowMapPass()
    depth.SetViews(cascades)
    depth.SetFilterToPoisson()
    _, (under, open_ground) = render_with(renderer, window, grab, depth, UNDER_THE_SPHERE, OPEN_GROUND)
    print(f"cascaded views: under the sphere {under:.1f}, open ground {open_ground:.1f}")
    assert depth.GetViews() is cascades
    assert depth.GetNumberOfShadowMapLayers() == 2
    assert under < 80 and open_ground > 120

    # Dual-depth maps, no bias at all: the sphere's shadow and its lit top.
    dual = vtkshadowmaps.vtkDualDepthShadowMapPass()
    dual.SetModeToDual()
    assert dual.GetNormalOffset() == 0.0 and dual.GetConstantBias() == 0.0
    _, (under, open_ground, sphere_top) = render_with(
        renderer, window, grab, dual, UNDER_THE_SPHERE, OPEN_GROUND, SPHERE_TOP)
    print(f"dual depth: under the sphere {under:.1f}, open ground {open_ground:.1f}, "
          f"sphere top {sphere_top:.1f}")
    assert under < 80 and open_ground > 120 and sphere_top > 120
    assert dual.GetNumberOfCasterPassesPerLayer() == 2, "the ground is open: peeled"

    # The automatic pass: its choice for the sun, read back from Python, and
    # pinned to one views for every light.
    automatic = vtkshadowmaps.make_pass()
    assert isinstance(automatic, vtkshadowmaps.vtkAutomaticShadowMapPass), "make_pass()'s default"
    _, (under, open_ground) = render_with(renderer, window, grab, automatic, UNDER_THE_SPHERE,
                                          OPEN_GROUND)
    chosen = automatic.GetChosenViewsName(0)
    print(f"automatic ({chosen} views, {automatic.GetChosenRepresentationName(0)}): "
          f"under the sphere {under:.1f}, open ground {open_ground:.1f}")
    assert chosen in ("uniform", "lispsm", "tsm", "psm", "cascades")
    assert automatic.GetChosenRepresentationName(0) == "dual depth"
    assert automatic.GetChosenViews(1) == -2, "one light"
    assert under < 80 and open_ground > 120
    automatic.SetViewsChoiceToLiSPSM()
    render_with(renderer, window, grab, automatic, UNDER_THE_SPHERE)
    assert automatic.GetChosenViews(0) == vtkshadowmaps.vtkAutomaticShadowMapPass.LISPSM_VIEWS
    # A light's own representation, from Python: the sun's maps in moments.
    automatic.SetLightRepresentation(light, vtkshadowmaps.vtkVarianceShadowMapRepresentation())
    _, (under, open_ground) = render_with(renderer, window, grab, automatic, UNDER_THE_SPHERE,
                                          OPEN_GROUND)
    assert automatic.GetChosenRepresentationName(0) == "moments"
    assert automatic.GetNumberOfRepresentationsInUse() == 1, "the only light's"
    assert under < 80 and open_ground > 120
    automatic.SetLightRepresentation(light, None)
    renderer.SetPass(None)
    automatic.ReleaseGraphicsResources(window)

    # Filterable moments with cascades: the shadow, the lit ground and top.
    variance = vtkshadowmaps.vtkVarianceShadowMapPass()
    variance.SetMomentsToMSM()
    variance.SetBlurRadius(2.0)
    variance.SetViews(cascades)
    _, (under, open_ground, sphere_top) = render_with(
        renderer, window, grab, variance, UNDER_THE_SPHERE, OPEN_GROUND, SPHERE_TOP)
    print(f"variance (MSM): under the sphere {under:.1f}, open ground {open_ground:.1f}, "
          f"sphere top {sphere_top:.1f}")
    assert under < 80 and open_ground > 120 and sphere_top > 120
    assert variance.GetMoments() == vtkshadowmaps.vtkVarianceShadowMapPass.MSM
    every_technique_light_and_shading(renderer, window, grab, sphere, light)
    try:
        vtkshadowmaps.make_pass("uniform", no_such_setting=1)
        raise AssertionError("make_pass took a setting its pass has no setter for")
    except ValueError as error:
        assert "SetNoSuchSetting" in str(error), error
    print(f"imported {vtkshadowmaps.__file__}")
    print("5 passed, 0 failed")


LAMP = (-1.0, 0.5, 6.0)
# Where the sphere's centre (0, 0, 1.5) casts its shadow from the lamp.
UNDER_THE_SPHERE_FROM_LAMP = (1.0 / 3.0, -0.5 / 3.0, 0.0)


# make_pass's techniques, and PSM's post-perspective cube map for every light.
TECHNIQUES_AND_THE_CUBE = list(vtkshadowmaps.TECHNIQUES) + ["psm-cube"]


def every_technique_light_and_shading(renderer, window, grab, sphere, light):
    """vtkshadowmaps.make_pass's every technique shades its shadow with a sun,
    a spot and a point light, on Phong and on PBR surfaces."""
    actors = renderer.GetActors()
    failures = []
    for pbr in (False, True):
        actors.InitTraversal()
        for _ in range(actors.GetNumberOfItems()):
            prop = actors.GetNextActor().GetProperty()
            if pbr:
                prop.SetInterpolationToPBR()
                prop.SetRoughness(0.8)
                prop.SetMetallic(0.0)
            else:
                prop.SetInterpolationToGouraud()
        for kind in ("sun", "spot", "point"):
            light.SetPositional(kind != "sun")
            light.SetPosition(*((0, 0, 1) if kind == "sun" else LAMP))
            light.SetConeAngle(45.0 if kind == "spot" else 180.0)
            shadowed = UNDER_THE_SPHERE if kind == "sun" else UNDER_THE_SPHERE_FROM_LAMP
            for technique in TECHNIQUES_AND_THE_CUBE:
                # psm-cube: the sun's and the spot's cube too (PSM_CUBE_ALWAYS),
                # set by the snake_case name of a setter with an acronym.
                settings = {"psm_cube_map": 1} if technique == "psm-cube" else {}
                shadow_pass = vtkshadowmaps.make_pass(technique.replace("-cube", ""), **settings)
                assert technique != "psm-cube" or shadow_pass.GetPSMCubeMap() == 1
                _, (under, open_ground) = render_with(
                    renderer, window, grab, shadow_pass, shadowed, OPEN_GROUND)
                renderer.SetPass(None)
                shadow_pass.ReleaseGraphicsResources(window)
                if not (open_ground > 60 and under < 0.5 * open_ground):
                    failures.append(f"{technique}, {kind}, {'PBR' if pbr else 'Phong'}: "
                                    f"under the sphere {under:.0f}, open ground {open_ground:.0f}")
    light.SetPositional(False)
    light.SetPosition(0, 0, 1)
    count = 2 * 3 * len(TECHNIQUES_AND_THE_CUBE)
    print(f"{count - len(failures)} of {count} technique x light x shading cases shade their shadow")
    assert not failures, "\n".join(failures)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
