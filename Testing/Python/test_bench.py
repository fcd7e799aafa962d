"""vtkshadows bench and analyze, end to end on a small image.

usage: test_bench.py VTKSHADOWS OUTPUT_DIR

Checks the outputs exist and the measured numbers mean what they should: no
shadows misclassifies exactly the truly shadowed pixels (all leaks), VTK's pass
misses point-light shadows entirely, the focused map beats VTK's pass.
"""
import csv
import os
import sys

from clitools import check, check_usage_error, run

MODEL = "/usr/share/assimp/models/STL/Spider_binary.stl"
SMALL = ["--size", "192x108", "--timed-frames", "1"]



def rows_by_case(path):
    with open(path, newline="") as stream:
        return {(r["scene"], r["light"], r["technique"]): r for r in csv.DictReader(stream)}



def test_bench(program, output):
    directory = os.path.join(output, "bench")
    result = run(program, "bench", "--scenes", "model", "--setups", "perpendicular,point",
                 "--flicker-frames", "3", "--out", directory, *SMALL)
    check(result.returncode == 0, "bench failed: " + result.stderr[-2000:])
    table = [line for line in result.stdout.splitlines() if line.startswith("| model")]
    check(len(table) == 30, "expected 30 table rows (2 set-ups x 15 techniques), got %d" % len(table))
    rows = rows_by_case(os.path.join(directory, "results.csv"))
    for setup in ("perpendicular", "point"):
        none = rows[("model", setup, "none")]
        check(float(none["false_shadow"]) == 0.0, setup + ": no shadows cannot shadow falsely")
        check(float(none["misclassified"]) > 0.5, setup + ": the scene has shadows to find")
        check(float(none["misclassified"]) == float(none["leak"]), setup + ": all leaks")
        for technique in ("uniform", "psm", "lispsm", "tsm", "gmnpr", "csm", "csm-tight", "csm-lispsm",
                          "second-depth", "midpoint", "dual", "evsm4"):
            focused = rows[("model", setup, technique)]
            check(float(focused["misclassified"]) < 0.5 * float(none["misclassified"]),
                  setup + ": " + technique + " finds the shadows")
        for technique in ("none", "vtk", "vtk-equal", "uniform", "psm", "lispsm", "tsm", "gmnpr", "csm",
                          "csm-tight", "csm-lispsm", "second-depth", "midpoint", "dual", "evsm4"):
            name = "model-%s-%s-errors.png" % (setup, technique)
            check(os.path.getsize(os.path.join(directory, name)) > 0, name + " written")
        check(os.path.getsize(os.path.join(directory, "model-%s-chart.png" % setup)) > 0, "chart")
    point_vtk = rows[("model", "point", "vtk")]
    check(point_vtk["misclassified"] == rows[("model", "point", "none")]["misclassified"],
          "VTK's pass casts no point-light shadows")
    sun_vtk = rows[("model", "perpendicular", "vtk")]
    check(float(rows[("model", "perpendicular", "uniform")]["misclassified"])
          < float(sun_vtk["misclassified"]), "the focused map beats VTK's pass")
    check(rows[("model", "perpendicular", "uniform")]["flicker"] != "nan", "flicker measured")
    check(float(rows[("model", "perpendicular", "uniform")]["changes"])
          >= float(rows[("model", "perpendicular", "uniform")]["flicker"]),
          "a technique changes at least where it flickers")
    check(rows[("model", "point", "uniform")]["flicker"] == "nan", "flicker only where asked")
    check(float(rows[("model", "perpendicular", "uniform")]["memory_mib"]) == 8.0,
          "one 2048^2 map of 16-bit depth is 8 MiB")
    check(float(rows[("model", "perpendicular", "second-depth")]["memory_mib"]) == 48.0,
          "two floats per texel and a shared 32-bit depth: 48 MiB at 2048^2")
    check(float(rows[("model", "perpendicular", "dual")]["memory_mib"]) == 64.0,
          "the ground is open, so the dual map is peeled: one float per texel more")
    check(abs(float(rows[("model", "perpendicular", "evsm4")]["memory_mib"]) - (64.0 * 4 / 3 + 16.0)) < 0.01,
          "four 32-bit floats per texel, a third more for mipmaps, a shared 32-bit depth")
    check(rows[("model", "perpendicular", "uniform")]["bleeding"] != "",
          "the bleeding column is written")
    check(int(rows[("model", "perpendicular", "vtk-equal")]["resolution"]) == 1448,
          "VTK at the memory of a 32-bit 2048^2 map: 1448^2 colour + depth = 16 MiB")


def test_analyze(program, output):
    directory = os.path.join(output, "analyze")
    result = run(program, "analyze", MODEL, "--setups", "overhead", "--technique", "uniform",
                 "--flicker-frames", "0", "--out", directory, *SMALL)
    check(result.returncode == 0, "analyze failed: " + result.stderr[-2000:])
    rows = rows_by_case(os.path.join(directory, "results.csv"))
    check(("file", "overhead", "uniform") in rows, "analyze measures the file")
    check(("file", "overhead", "vtk") in rows, "VTK's pass is always the reference")


def test_errors(program):
    for arguments, expected in [
        (["bench", "--techniques", "magic"], "unknown technique"),
        (["bench", "--scenes", "moon"], "unknown scene"),
        (["bench", "--setups", "sideways"], "unknown light set-up"),
        (["bench", "--flicker-frames", "1"], "flicker frames"),
        (["analyze"], "needs a model FILE"),
        (["analyze", "/nonexistent.stl", "--flicker-frames", "0"], "error"),
    ]:
        check_usage_error(program, arguments, expected)


def main():
    program, output = sys.argv[1], sys.argv[2]
    os.makedirs(output, exist_ok=True)
    test_errors(program)
    test_bench(program, output)
    test_analyze(program, output)
    print("ok")


if __name__ == "__main__":
    main()
