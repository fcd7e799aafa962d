"""Every numeric setter of every wrapped class, found by introspection (a new
setter is covered without editing this test), given NaN, +-infinity, +-1e30, -1,
0 and 1e-30 (integer setters: -1 and 0), each followed by a render of a sun and a
spot over a sphere and a ground. Fails on a crash, a GL error, a VTK error, a
shader that does not compile, a value that is stored though not finite, a
non-finite value that changes the parameter, or one refused without a warning
naming the parameter.

  PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
    Testing/Python/test_setters.py
"""
import ctypes
import math
import re
import sys

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkCommonCore import vtkLogger, vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow)

import vtkshadowmaps

FLOAT_VALUES = [math.nan, math.inf, -math.inf, 1e30, -1e30, -1.0, 0.0, 1e-30]
INT_VALUES = [-1, 0]
GL = ctypes.CDLL("libGL.so.1")


def scene():
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(160, 120)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    for source in (vtkPlaneSource(), vtkSphereSource()):
        if isinstance(source, vtkPlaneSource):
            source.SetOrigin(-5, -5, 0); source.SetPoint1(5, -5, 0); source.SetPoint2(-5, 5, 0)
        else:
            source.SetCenter(0, 0, 1.5)
        mapper = vtkPolyDataMapper(); mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor(); actor.SetMapper(mapper); renderer.AddActor(actor)
    renderer.AutomaticLightCreationOff()
    sun = vtkLight(); sun.SetLightTypeToSceneLight(); sun.SetPositional(False)
    sun.SetPosition(1, -1, 4); sun.SetFocalPoint(0, 0, 0); renderer.AddLight(sun)
    spot = vtkLight(); spot.SetLightTypeToSceneLight(); spot.SetPositional(True)
    spot.SetPosition(-3, -2, 6); spot.SetFocalPoint(0, 0, 0); spot.SetConeAngle(40)
    renderer.AddLight(spot)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -12, 7); camera.SetFocalPoint(0, 0, 0); camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    return window, renderer


def signatures(method):
    """The Python signatures of a wrapped method: lists of parameter types."""
    text = re.sub(r"\n\s+", " ", method.__doc__ or "")
    found = []
    for params in re.findall(r"^\w+\(self(?:, )?(.*?)\) -> None", text, re.M):
        found.append(re.findall(r"_?\w+:(\([^)]*\)|\w+)", params))
    return found


def declared_here(cls, name):
    """Whether this module's classes declare `name` (not VTK's base classes)."""
    owner = next(c for c in cls.__mro__ if name in c.__dict__)
    return getattr(vtkshadowmaps, owner.__name__, None) is owner


def numeric_setters(obj):
    """(name, kind, arity) for every Set method taking only numbers; kind is
    'float' or 'int' (bools cannot be out of range), arity how many numbers
    (a tuple parameter counts as one argument of that many numbers)."""
    setters = []
    for name in sorted(dir(obj)):
        if not name.startswith("Set") or not declared_here(type(obj), name):
            continue
        for types in signatures(getattr(obj, name)):
            if types and all(t == "float" for t in types):
                setters.append((name, "float", [None] * len(types)))
                break
            if len(types) == 1 and re.fullmatch(r"\((float, )*float\)", types[0]):
                setters.append((name, "float", [types[0].count("float")]))
                break
            if types and all(t == "int" for t in types):
                setters.append((name, "int", [None] * len(types)))
                break
    return setters


def arguments(value, shape):
    return [value if n is None else (value,) * n for n in shape]


def values_of(getter):
    if getter is None:
        return None
    got = getter()
    return tuple(got) if isinstance(got, (tuple, list)) else (got,)


def switch_options_on(obj):
    """Turns on every boolean option the module declares (UseSceneBounds,
    LloydFalloff, Mipmaps...), so that the parameters they enable are used."""
    for name in dir(obj):
        if name.endswith("On") and declared_here(type(obj), name):
            getattr(obj, name)()


def pass_for(cls, obj):
    """A pass that renders with `obj`: the pass itself, or one that uses it."""
    if isinstance(obj, vtkshadowmaps.vtkAbstractShadowMapPass):
        shadow_pass = obj
    elif isinstance(obj, vtkshadowmaps.vtkShadowMapViews):
        shadow_pass = vtkshadowmaps.vtkDepthShadowMapPass(); shadow_pass.SetViews(obj)
    elif isinstance(obj, vtkshadowmaps.vtkShadowMapRepresentation):
        shadow_pass = vtkshadowmaps.vtkDepthShadowMapPass(); shadow_pass.SetRepresentation(obj)
    else:
        return None
    shadow_pass.SetResolution(256)
    return shadow_pass


def gl_errors(window):
    window.MakeCurrent()
    codes = []
    while len(codes) < 16:
        code = GL.glGetError()
        if code == 0:
            break
        codes.append(hex(code))
    return codes


def main():
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    log = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(log)
    window, renderer = scene()
    failures = []
    renders = 0
    classes = [getattr(vtkshadowmaps, n) for n in sorted(dir(vtkshadowmaps)) if n.startswith("vtk")]
    covered = set()
    for cls in classes:
        try:
            probe = cls()
        except TypeError:
            continue  # abstract: its setters are its subclasses'
        for name, kind, shape in numeric_setters(probe):
            for value in FLOAT_VALUES if kind == "float" else INT_VALUES:
                obj = cls()
                switch_options_on(obj)
                shadow_pass = pass_for(cls, obj)
                if shadow_pass is None:
                    failures.append(f"{cls.__name__}: no pass renders it; {name} untested")
                    break
                renderer.SetPass(shadow_pass)
                window.Render()
                getter = getattr(obj, "Get" + name[3:], None)
                before = values_of(getter)
                start = len(log.GetOutput())
                getattr(obj, name)(*arguments(value, shape))
                window.Render()
                renders += 1
                after = values_of(getter)
                text = log.GetOutput()[start:]
                what = f"{cls.__name__}.{name}({value})"
                if "ERROR" in text or "does not compile" in text:
                    failures.append(f"{what}: {text.strip()[:400]}")
                errors = gl_errors(window)
                if errors:
                    failures.append(f"{what}: GL errors {errors}")
                if after is not None and not all(math.isfinite(v) for v in after):
                    failures.append(f"{what}: stores {after}")
                if kind == "float" and not math.isfinite(value):
                    if after is not None and after != before:
                        failures.append(f"{what}: changed {before} to {after}")
                    if name[3:] not in text or "not a finite number" not in text:
                        failures.append(f"{what}: refused without a warning naming it: {text[:200]!r}")
                covered.add(f"{cls.__name__}.{name}")
        renderer.SetPass(None)
        window.Render()
    print(f"{len(covered)} setters of {len(classes)} classes, {renders} renders")
    for failure in failures:
        print("FAIL", failure)
    return 1 if failures or not covered else 0


if __name__ == "__main__":
    sys.exit(main())
