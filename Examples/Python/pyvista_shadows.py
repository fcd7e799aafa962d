#!/usr/bin/env python3
"""PyVista with this module's cascaded shadows instead of plotter.enable_shadows():
a sphere and a box over a ground under a sun, with PyVista's SSAO and SSAA on.

Usage: pyvista_shadows.py [out.png]   (without a file name it opens a window)
"""
import sys

import pyvista as pv

from vtkshadowmaps.pyvista import enable_shadows


def main():
    off_screen = len(sys.argv) > 1
    plotter = pv.Plotter(lighting="none", off_screen=off_screen, window_size=(800, 600))
    plotter.add_mesh(pv.Plane(i_size=12, j_size=12), color="white")
    plotter.add_mesh(pv.Sphere(radius=1.0, center=(0, 0, 1.5)), color="orange", smooth_shading=True)
    plotter.add_mesh(pv.Cube(center=(3, 1.5, 0.75), x_length=1.5, y_length=1.5, z_length=1.5),
                     color="lightblue")
    sun = pv.Light(position=(3, 2, 8), focal_point=(0, 0, 0), light_type="scene light")
    sun.positional = False
    plotter.add_light(sun)
    plotter.camera_position = [(0, -14, 9), (0, 0, 0.5), (0, 0, 1)]
    plotter.enable_ssao()
    plotter.enable_anti_aliasing("ssaa")
    enable_shadows(plotter, "cascaded", number_of_cascades=3)
    if off_screen:
        plotter.screenshot(sys.argv[1])
        print(sys.argv[1])
    else:
        plotter.show()


if __name__ == "__main__":
    main()
