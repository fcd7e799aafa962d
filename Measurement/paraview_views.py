"""What the ParaView measurements share: ParaView's own render view and the
plugin's Render View (Shadows) set up alike, one sun, and a timed frame.

make_view(technique, shown, size, resolution) makes the view of a TECHNIQUES name
showing the sources in `shown`; timed(view, frame) times frame(), the GL finished.
"""
import time

from paraview.simple import AddLight, CreateView, Show

# A technique's name -> (the view's kind, its shadow properties).
TECHNIQUES = {
    "none": ("RenderView", {}),
    "uniform": ("ShadowRenderView", {"ShadowViews": "Uniform", "ShadowStorage": "Depth (PCF)"}),
    "csm": ("ShadowRenderView", {"ShadowViews": "Cascades", "ShadowStorage": "Depth (PCF)"}),
    "second-depth": ("ShadowRenderView", {"ShadowViews": "Uniform",
                                          "ShadowStorage": "Dual depth (no bias)"}),
    "dual": ("ShadowRenderView", {"ShadowViews": "Uniform",
                                  "ShadowStorage": "Dual depth (no bias)"}),
    "evsm4": ("ShadowRenderView", {"ShadowViews": "Uniform", "ShadowStorage": "Moments (EVSM4)"}),
    "auto": ("ShadowRenderView", {"ShadowViews": "Automatic",
                                  "ShadowStorage": "Dual depth (no bias)"}),
}


def make_view(technique, shown, size, resolution):
    """A view of `technique` showing `shown`, lit by one scene sun from (1, -1, 3)."""
    kind, properties = TECHNIQUES[technique]
    view = CreateView(kind)
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    if view.GetProperty("UseColorPaletteForBackground") is not None:
        view.UseColorPaletteForBackground = 0
    if kind == "ShadowRenderView":
        view.ShadowMapResolution = resolution
    for name, value in properties.items():
        setattr(view, name, value)
    view.UseLight = 0
    sun = AddLight(view=view)
    sun.Coords = "Scene"
    sun.Type = "Directional"
    sun.Position = [1, -1, 3]
    sun.FocalPoint = [0, 0, 0]
    for source in shown:
        Show(source, view)
    return view


def timed(view, frame):
    """Wall-clock and rendering-thread CPU seconds of frame(), the GL finished."""
    window = view.GetRenderWindow()
    wall, cpu = time.perf_counter(), time.thread_time()
    frame()
    window.WaitForCompletion()
    return time.perf_counter() - wall, time.thread_time() - cpu
