"""The maps' memory of the automatic pass beside the presets, on a sphere over
a ground lit by a sun (docs/AUTOMATIC.md, "The rules"): what each light's
views cost.

usage (from build/): PYTHONPATH=lib/python3/dist-packages xvfb-run -a \
    /usr/bin/python3 ../Measurement/automatic_memory.py
"""
import vtkshadowmaps
from vtkmodules.vtkFiltersSources import vtkSphereSource
from timing_scene import add, add_ground_and_boxes, add_sun, window


def scene():
    renderer, render_window = window(300, 200)
    add_ground_and_boxes(renderer, 10, 0)
    sphere = vtkSphereSource()
    sphere.SetCenter(0, 0, 1.5)
    add(renderer, sphere)
    add_sun(renderer, (1, 0.3, 1))
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -14, 5)
    camera.SetFocalPoint(0, 0, 0.5)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    return renderer, render_window


def main():
    renderer, render_window = scene()
    print("| pass | sun's views | layers | MiB |\n|---|---|---:|---:|")
    for name, settings in (("auto", {}), ("auto", {"cost_budget": 6}), ("cascaded", {}),
                           ("uniform", {}), ("lispsm", {}), ("psm", {"psm_cube_map": 1})):
        shadow_pass = vtkshadowmaps.make_pass(name, **settings)
        renderer.SetPass(shadow_pass)
        render_window.Render()
        views = shadow_pass.GetChosenViewsName(0) if name == "auto" else "-"
        label = name + "".join(f", {k}={v}" for k, v in settings.items())
        print(f"| {label} | {views} | {shadow_pass.GetNumberOfShadowMapLayers()} | "
              f"{shadow_pass.GetShadowMapMemory() / 2**20:.0f} |")
        renderer.SetPass(None)
        shadow_pass.ReleaseGraphicsResources(render_window)


if __name__ == "__main__":
    main()
