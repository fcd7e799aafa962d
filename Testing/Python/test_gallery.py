"""vtkshadows gallery: a tiny run, then the committed gallery against a fresh one.

usage: test_gallery.py VTKSHADOWS OUTPUT_DIR SOURCE_DIR

The tiny run checks what the command writes and that its pictures say what its
figures say: the red and the blue pixels of each error map are the light leaks
and false shadows gallery.csv counts, the page links only pictures that exist,
and VTK's pass misses more than the default. The second part remakes one
committed case at the size and resolution docs/GALLERY.md was made at and
compares its figures with docs/images/gallery/gallery.csv and its pictures with
the committed ones (idiff).
"""
import csv
import os
import re
import subprocess
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

from clitools import check, check_usage_error, run

LEAK = (230, 0, 0)  # shadowmetrics::ErrorMap's colours
FALSE_SHADOW = (0, 60, 230)


def read_png(path):
    """RGB rows of a PNG, top row first."""
    reader = vtkPNGReader()
    check(reader.CanReadFile(path), path + " is a PNG")
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)
    return pixels[::-1, :, :3]


def figures(path):
    with open(path, newline="") as stream:
        return {(r["scene"], r["light"], r["technique"]): r for r in csv.DictReader(stream)}


def headline(row):
    """What the page judges a case by: the misclassified %, or the light's error."""
    return float(row["misclassified"] if row["light_error"] == "nan" else row["light_error"])


def count(pixels, color):
    return int(numpy.all(pixels == numpy.array(color, dtype=pixels.dtype), axis=2).sum())


def test_tiny(program, output):
    directory = os.path.join(output, "gallery")
    page = os.path.join(output, "gallery-page", "GALLERY.md")
    os.makedirs(os.path.dirname(page), exist_ok=True)
    cases = [("outdoor", "perpendicular"), ("glass", "perpendicular")]
    techniques = ["vtk", "auto", "uniform"]
    width, height = 96, 54
    result = run(program, "gallery", "--out", directory, "--page", page,
                 "--cases", ",".join(s + ":" + l for s, l in cases),
                 "--techniques", ",".join(techniques), "--size", "%dx%d" % (width, height),
                 "--resolution", "512")
    check(result.returncode == 0, "gallery failed: " + result.stderr[-2000:])
    check(result.stdout.strip() == os.path.abspath(page), "prints the page's path")
    rows = figures(os.path.join(directory, "gallery.csv"))
    check(len(rows) == len(cases) * len(techniques),
          "one row per case and technique, got %d" % len(rows))
    for scene, light in cases:
        name = scene + "-" + light
        truth = read_png(os.path.join(directory, name + "-truth.png"))
        check(truth.shape == (height, width, 3), name + ": truth picture's size")
        for technique in techniques:
            picture = read_png(os.path.join(directory, "%s-%s.png" % (name, technique)))
            check(picture.shape == (height, 2 * width, 3), name + ", " + technique + ": frame|errors")
            errors = picture[:, width:]
            row = rows[(scene, light, technique)]
            if row["light_error"] != "nan":
                continue  # the map shows the light's error in proportion, not leaks and false shadows
            counted = int(row["counted_pixels"])
            for column, color in (("leak", LEAK), ("false_shadow", FALSE_SHADOW)):
                expected = float(row[column]) * counted / 100.0
                found = count(errors, color)
                check(abs(found - expected) < 0.5,
                      "%s, %s: %d %s pixels in the error map, the figures say %.1f"
                      % (name, technique, found, column, expected))
        vtk, default = (headline(rows[(scene, light, t)]) for t in ("vtk", "auto"))
        check(vtk > 2.0 * default, "%s: VTK's pass %.2f %% wrong, the default %.2f %%" % (name, vtk, default))
    check(rows[("outdoor", "perpendicular", "auto")]["choice"] != "", "the automatic pass's choice")
    check(all(rows[("glass", "perpendicular", t)]["light_error"] != "nan" for t in techniques),
          "the glass's light error measured")
    check(all(rows[("outdoor", "perpendicular", t)]["light_error"] == "nan" for t in techniques),
          "no light error without translucent casters")
    overview = read_png(os.path.join(directory, "overview.png"))
    check(overview.shape == (2 * height, 3 * width, 3), "overview: 2 cases of 3 pictures")
    first = os.path.join(directory, "outdoor-perpendicular-")
    check(numpy.array_equal(overview[:height, :width], read_png(first + "vtk.png")[:, :width]),
          "overview: the first case's VTK frame at the top left")
    check(numpy.array_equal(overview[:height, 2 * width:], read_png(first + "truth.png")),
          "overview: the first case's truth at the top right")
    text = open(page).read()
    links = re.findall(r"\]\(([^)#]+)\)", text)
    check(len(links) == 1 + len(cases) * (1 + len(techniques)), "page links every picture")
    for link in links:
        check(os.path.isfile(os.path.join(os.path.dirname(page), link)), "page link " + link)
    # Again without VTK's pass: no overview to make, and none of the last run's left.
    result = run(program, "gallery", "--out", directory, "--page", page, "--cases",
                 "outdoor:perpendicular", "--techniques", "uniform", "--size", "%dx%d" % (width, height),
                 "--resolution", "512")
    check(result.returncode == 0, "gallery without vtk failed: " + result.stderr[-2000:])
    check(not os.path.exists(os.path.join(directory, "overview.png")), "the last run's overview removed")
    check("overview.png" not in open(page).read(), "the page links no overview")
    check("--cases outdoor:perpendicular --techniques uniform" in open(page).read(),
          "the page's command makes this gallery again")
    for arguments, expected in (
            (["--cases", "outdoor"], "is not scene:set-up"),
            (["--cases", "outdoor:nowhere"], "is not scene:set-up"),
            (["--cases", "nowhere:perpendicular"], "is not scene:set-up"),
            (["--cases", "outdoor:spot,outdoor:spot"], "given twice"),
            (["--page", "/nonexistent/GALLERY.md"], "no such directory"),
            (["--techniques", "bogus"], "unknown technique"),
            (["--size", "0x0"], "size")):
        check_usage_error(program, ["gallery", "--out", directory] + arguments, expected)


def documented_run(source):
    """The size and resolution the committed page was made at."""
    text = open(os.path.join(source, "docs", "GALLERY.md")).read()
    made = re.search(r"Made by `vtkshadows gallery [^`]*--size (\d+)x(\d+) --resolution (\d+)`", text)
    check(made is not None, "docs/GALLERY.md names the command that made it")
    return made.group(1), made.group(2), made.group(3)


def idiff(committed, fresh):
    """The pictures agree: at most 0.5 % of the pixels differ by over 0.1."""
    result = subprocess.run(["idiff", "-fail", "0.1", "-failpercent", "0.5", "-warn", "0.02",
                             "-warnpercent", "0.5", committed, fresh],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    check(result.returncode in (0, 1), "idiff %s %s:\n%s" % (committed, fresh, result.stdout[-1500:]))


def test_committed(program, output, source):
    width, height, resolution = documented_run(source)
    committed = os.path.join(source, "docs", "images", "gallery")
    directory = os.path.join(output, "gallery-committed")
    scene, light = "outdoor", "perpendicular"
    techniques = ["vtk", "auto", "uniform"]
    result = run(program, "gallery", "--out", directory, "--cases", scene + ":" + light,
                 "--techniques", ",".join(techniques), "--size", width + "x" + height,
                 "--resolution", resolution)
    check(result.returncode == 0, "gallery failed: " + result.stderr[-2000:])
    before = figures(os.path.join(committed, "gallery.csv"))
    after = figures(os.path.join(directory, "gallery.csv"))
    for technique in techniques:
        for column in ("misclassified", "leak", "false_shadow"):
            a = float(before[(scene, light, technique)][column])
            b = float(after[(scene, light, technique)][column])
            check(abs(a - b) <= max(0.05, 0.1 * a),
                  "%s %s: committed %.3f %%, made now %.3f %%" % (technique, column, a, b))
    for picture in ["truth"] + techniques:
        name = "%s-%s-%s.png" % (scene, light, picture)
        idiff(os.path.join(committed, name), os.path.join(directory, name))


def main(program, output, source):
    os.makedirs(output, exist_ok=True)
    test_tiny(program, output)
    test_committed(program, output, source)
    print("gallery: all checks passed")


if __name__ == "__main__":
    main(*sys.argv[1:4])
