"""Run by scripts/paraview_gui_screenshot.sh inside ParaView's GUI
(paraview --script=...): loads the plugin from SHADOWMAPS_PLUGIN and replaces the
default render view by a Render View (Shadows) of a contour over a ground, lit by a
sun and the light kit."""
import os
from paraview.simple import (AddLight, AssignViewToLayout, ColorBy, Contour, CreateView, Delete,
                             GetActiveView, GetLayout, LoadPlugin, Plane, Render, SetActiveView,
                             Show, Wavelet)

LoadPlugin(os.environ["SHADOWMAPS_PLUGIN"], remote=False, ns=globals())
layout = GetLayout()
Delete(GetActiveView())
view = CreateView("ShadowRenderView")
AssignViewToLayout(view=view, layout=layout, hint=0)
SetActiveView(view)
view.OrientationAxesVisibility = 0
view.ShadowViews = "Cascades"

wavelet = Wavelet(WholeExtent=[-10, 10, -10, 10, -10, 10])
contour = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[160.0])
shown = Show(contour, view)
ColorBy(shown, ("POINTS", "RTData"))
Show(Plane(Origin=[-25, -25, -12], Point1=[25, -25, -12], Point2=[-25, 25, -12]), view)
sun = AddLight(view=view)
sun.Coords = "Scene"
sun.Type = "Directional"
sun.Position = [-14, -4, 20]
sun.FocalPoint = [0, 0, 0]
sun.Intensity = 0.8
view.CameraPosition = [30, -70, 60]
view.CameraFocalPoint = [4, 0, -8]
view.CameraViewUp = [0, 0, 1]
Render(view)
