"""vtkshadows: renders the default scene to a PNG, runs a small speed benchmark
(a table row per technique, no shader built in a moving frame), rejects bad
input with one line on stderr and exit status 2, and keeps --help to one screen
with each command's options a "COMMAND --help" away."""
import csv
import os
import subprocess
import sys


def run(program, *args):
    return subprocess.run([program, *args], capture_output=True, text=True, timeout=240)


def main(program, output_dir):
    os.makedirs(output_dir, exist_ok=True)
    failures = []
    out = os.path.join(output_dir, "cli_default.png")
    if os.path.exists(out):
        os.remove(out)
    result = run(program, "render", "--size", "320x240", "--resolution", "1024", "-o", out)
    printed = result.stdout.strip()
    if result.returncode != 0 or not os.path.isfile(out) or os.path.getsize(out) == 0:
        failures.append(f"render: rc={result.returncode} stderr={result.stderr!r}")
    elif os.path.realpath(printed) != os.path.realpath(out):
        failures.append(f"render printed {printed!r}, expected the output path")
    with open(out, "rb") as png:
        if png.read(8) != b"\x89PNG\r\n\x1a\n":
            failures.append("render: output is not a PNG")

    speed_dir = os.path.join(output_dir, "speed")
    result = run(program, "speed", "--scenes", "street", "--setups", "spot", "--techniques",
                 "uniform,csm", "--timed-frames", "1", "--size", "160x90", "--out", speed_dir)
    lines = result.stdout.splitlines()
    header = [cell.strip() for cell in lines[0].split("|")] if lines else []
    shaders = header.index("shaders built in 8 moving frames") if "shaders built in 8 moving frames" in header else -1
    rows = [line.split("|") for line in lines if line.startswith("| street")]
    if result.returncode != 0 or not os.path.isfile(os.path.join(speed_dir, "speed.csv")):
        failures.append(f"speed: rc={result.returncode} stderr={result.stderr!r}")
    elif sorted(r[4].strip() for r in rows) != sorted(["none", "vtk", "uniform", "csm"] * 2):
        failures.append(f"speed: rows {[r[1:5] for r in rows]}")
    elif shaders < 0 or any(r[4].strip() in ("uniform", "csm") and r[shaders].strip() != "0" for r in rows):
        failures.append(f"speed: shaders built in a moving frame: {result.stdout}")
    else:
        # Each of our techniques says where its frames' shadow work went, in
        # six steps that add up to a part of the frame; the references have none.
        with open(os.path.join(speed_dir, "speed.csv")) as table:
            records = list(csv.DictReader(table))
        # Each of our techniques' first frame says the same of its steps.
        names = list(records[0]) if records else []
        for frame, seconds in (("moving_", "moving_s"), ("first_", "first_s")):
            step_columns = [name for name in names if name.startswith(frame) and name.endswith("_ms")]
            for record in records:
                steps = [float(record[name]) for name in step_columns]
                ours = record["technique"] in ("uniform", "csm")
                frame_ms = 1000.0 * float(record[seconds])
                if len(steps) != 6 or (ours and not all(0.0 <= step for step in steps)) or \
                        (ours and sum(steps) > 2.0 * frame_ms) or (not ours and steps != [-1.0] * 6):
                    failures.append(f"speed: {frame}frame steps of {record['technique']}: {steps} "
                                    f"({frame_ms:.1f} ms)")

    bad_inputs = [
        [],
        ["explode"],
        ["render", "--bogus"],
        ["render", "--resolution"],
        ["render", "--resolution", "abc"],
        ["render", "--resolution", "5"],
        ["render", "--filter", "pcf:9"],
        ["render", "--filter", "blur"],
        ["render", "--size", "100"],
        ["render", "--light", "moon"],
        ["render", "--scene", "/nonexistent/model.obj"],
        ["render", "--scene", __file__],
        ["speed", "--scenes", "city"],
        ["speed", "--techniques", "magic"],
        ["speed", "--moving", "fast"],
        ["speed", "--scenes", "street", "--moving", "data"],
        ["speed", "--scenes", "contour,street", "--moving", "data"],
        ["speed", "--flicker-yaw", "30"],
        ["bench", "--flicker-yaw", "270"],
        ["bench", "--flicker-yaw", "nan"],
    ]
    for args in bad_inputs:
        result = run(program, *args)
        lines = [line for line in result.stderr.splitlines() if line.strip()]
        if result.returncode != 2:
            failures.append(f"{args}: exit {result.returncode}, expected 2")
        elif args and (len(lines) != 1 or "error" not in lines[0]):
            failures.append(f"{args}: stderr should be one error line, got {result.stderr!r}")

    # The overview fits one screen (24 lines) and names every command; each
    # command's help has its options.
    commands = ["render", "gallery", "bench", "analyze", "sweep", "speed"]
    result = run(program, "--help")
    overview = result.stdout.splitlines()
    if result.returncode != 0 or len(overview) > 24 or \
            not all(any(line.startswith("  " + c + " ") for line in overview) for c in commands) or \
            "COMMAND --help" not in result.stdout:
        failures.append(f"--help: {len(overview)} lines, rc={result.returncode}: {result.stdout!r}")
    result = run(program, "help", "gallery")
    if result.returncode != 0 or not result.stdout.startswith("usage: vtkshadows gallery"):
        failures.append(f"help gallery: rc={result.returncode}: {result.stdout[:200]!r}")
    for command in commands:
        result = run(program, command, "--help") if command != "analyze" else run(program, "analyze", "--help")
        if result.returncode != 0 or f"vtkshadows {command}" not in result.stdout or \
                "--out" not in result.stdout and command != "render" or "options of" not in result.stdout:
            failures.append(f"{command} --help: rc={result.returncode}: {result.stdout[:300]!r}")

    for failure in failures:
        print("FAIL:", failure)
    checks = 5 + len(commands) + len(bad_inputs)
    print(f"{checks - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
