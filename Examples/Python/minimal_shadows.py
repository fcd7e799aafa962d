#!/usr/bin/env python3
"""A sphere over a plane lit by a directional light, with shadows.

Usage: minimal_shadows.py [out.png]   (without a file name it renders once and exits)
"""
import sys

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL implementations of the classes below)
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkLight,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)

import vtkshadowmaps


def add_actor(renderer, source):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)


def main():
    renderer = vtkRenderer()
    sphere = vtkSphereSource()  # radius 0.5 at the origin
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    add_actor(renderer, sphere)
    plane = vtkPlaneSource()  # 4 x 4, normal +z, 0.5 below the sphere
    plane.SetOrigin(-2.0, -2.0, -1.0)
    plane.SetPoint1(2.0, -2.0, -1.0)
    plane.SetPoint2(-2.0, 2.0, -1.0)
    add_actor(renderer, plane)

    sun = vtkLight()
    sun.SetPositional(False)
    sun.SetPosition(1.0, 1.0, 2.0)  # shines from (1, 1, 2) towards the origin
    renderer.AddLight(sun)
    renderer.GetActiveCamera().SetPosition(0.0, -6.0, 3.0)
    renderer.GetActiveCamera().SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Zoom(1.5)

    renderer.SetPass(vtkshadowmaps.vtkWarpedShadowMapPass())

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.Render()
    if len(sys.argv) > 1:
        capture = vtkWindowToImageFilter()
        capture.SetInput(window)
        writer = vtkPNGWriter()
        writer.SetInputConnection(capture.GetOutputPort())
        writer.SetFileName(sys.argv[1])
        writer.Write()


if __name__ == "__main__":
    main()
