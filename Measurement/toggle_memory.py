"""Resident memory over 200 on/off toggles of each pass given on the command line
(a new pass each time, as `renderer.SetPass(pass)` then `SetPass(None)`), a ground
and a sphere under a sun at 160 x 120, one process per run: the resident MiB after every tenth
toggle, once the GL has finished and glibc has trimmed its free pages (freed
blocks of 1 MiB or more are unmapped at once).

  PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
    Measurement/toggle_memory.py vtkDepthShadowMapPass
"""
import ctypes
import sys

import vtkshadowmaps
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

LIBC = ctypes.CDLL("libc.so.6")
LIBC.mallopt(-3, 1 << 20)  # M_MMAP_THRESHOLD


def resident_mib():
    LIBC.malloc_trim(0)
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096 / 2**20


window = vtkRenderWindow(); window.SetSize(160, 120); window.SetOffScreenRendering(1)
renderer = vtkRenderer(); window.AddRenderer(renderer)
for source in (vtkPlaneSource(), vtkSphereSource()):
    mapper = vtkPolyDataMapper(); mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor(); actor.SetMapper(mapper); renderer.AddActor(actor)
renderer.AutomaticLightCreationOff()
sun = vtkLight(); sun.SetLightTypeToSceneLight(); sun.SetPositional(False)
sun.SetPosition(1, -1, 4); sun.SetFocalPoint(0, 0, 0); renderer.AddLight(sun)
for name in [a for a in sys.argv[1:] if a != "-v"]:
    samples = []
    for i in range(200):
        shadow_pass = getattr(vtkshadowmaps, name)()
        renderer.SetPass(shadow_pass); window.Render()
        if i == 0:
            layers = shadow_pass.GetNumberOfShadowMapLayers()
        renderer.SetPass(None); window.Render()
        del shadow_pass
        window.WaitForCompletion()
        if i % 10 == 9:
            samples.append(resident_mib())
    print(" ".join(f"{v:.1f}" for v in samples)) if "-v" in sys.argv else None
    print(f"{name} ({layers} layer(s)): MiB after toggle 10 {samples[0]:.1f}, after 200 {samples[-1]:.1f}, "
          f"least {min(samples):.1f}, most {max(samples):.1f}")
