"""vtkshadows sweep, end to end on a few small cases.

usage: test_sweep.py VTKSHADOWS OUTPUT_DIR

Checks that a sweep writes one row per case and technique, that its report
names the worst cases by seed, that replaying a seed renders that very case
(the same figures, with frames, error maps and maps) and that bad options
are refused with one error line and exit status 2.
"""
import csv
import os
import sys

from clitools import check, check_usage_error, run

SMALL = ["--size", "96x72", "--resolution", "512"]
TECHNIQUES = ["uniform", "lispsm", "csm"]




def read_rows(path):
    with open(path, newline="") as stream:
        return list(csv.DictReader(stream))


def test_sweep_and_replay(program, output):
    directory = os.path.join(output, "sweep")
    result = run(program, "sweep", "--cases", "6", "--seed", "4", "--techniques",
                 ",".join(TECHNIQUES), "--min-counted", "0", "--out", directory, *SMALL)
    check(result.returncode == 0, "sweep failed: " + result.stderr[-2000:])
    rows = read_rows(os.path.join(directory, "results.csv"))
    check(len(rows) == 6 * len(TECHNIQUES), "one row per case and technique, got %d" % len(rows))
    for technique in TECHNIQUES:
        check(("| " + technique + " | 6 |") in result.stdout, technique + " summarised over 6 cases")
    for row in rows:
        check(0.0 <= float(row["misclassified"]) <= 100.0, "misclassified is a percentage")
        check(row["gl_errors"] == "0" and row["nonfinite_views"] == "0", "no GL error, finite views")
    seeds = sorted({row["seed"] for row in rows})
    check(len(seeds) == 6, "six different case seeds")

    # The case with the most counted pixels, replayed alone, gives the same figures.
    seed = max(seeds, key=lambda s: int(next(r["counted"] for r in rows if r["seed"] == s)))
    replay_dir = os.path.join(output, "replay")
    result = run(program, "sweep", "--replay", seed, "--techniques", ",".join(TECHNIQUES),
                 "--out", replay_dir, *SMALL)
    check(result.returncode == 0, "replay failed: " + result.stderr[-2000:])
    check(("seed " + seed) in result.stdout, "replay describes the case")
    replayed = {row["technique"]: row for row in read_rows(os.path.join(replay_dir, "results.csv"))}
    for row in rows:
        if row["seed"] == seed:
            check(replayed[row["technique"]]["misclassified"] == row["misclassified"],
                  "replay of %s reproduces %s" % (seed, row["technique"]))
    for name in ["none"] + TECHNIQUES + [t + "-errors" for t in TECHNIQUES] + [t + "-maps" for t in TECHNIQUES]:
        path = os.path.join(replay_dir, "%s-%s.png" % (seed, name))
        check(os.path.isfile(path) and os.path.getsize(path) > 0, path + " written")
    return rows


def test_parts_and_counted_only(program, output, rows):
    """Cases 2..5 run alone are the full run's last four (its csv lists cases
    in order); with --counted-only the cases below --min-counted get no
    technique's row and the others the same figures."""
    counts = {row["seed"]: int(row["counted"]) for row in rows}
    in_order = list(dict.fromkeys(row["seed"] for row in rows))
    threshold = sorted(counts[seed] for seed in in_order[2:])[1] + 1
    directory = os.path.join(output, "sweep-part")
    result = run(program, "sweep", "--cases", "4", "--seed", "4", "--first-case", "2",
                 "--techniques", ",".join(TECHNIQUES), "--min-counted", str(threshold),
                 "--counted-only", "yes", "--out", directory, *SMALL)
    check(result.returncode == 0, "partial sweep failed: " + result.stderr[-2000:])
    check("(2 to 5)" in result.stdout and "the only ones measured" in result.stdout,
          "the report says which cases and that only counted ones were measured")
    part = read_rows(os.path.join(directory, "results.csv"))
    expected = {seed for seed in in_order[2:] if counts[seed] >= threshold}
    check({row["seed"] for row in part} == expected,
          "the measured cases are the full run's cases 2..5 with enough counted pixels")
    check(len(expected) == 2, "the threshold leaves two of the four cases out")
    full = {(row["seed"], row["technique"]): row["misclassified"] for row in rows}
    for row in part:
        check(full[(row["seed"], row["technique"])] == row["misclassified"],
              "case %s measured alone gives the full run's %s" % (row["seed"], row["technique"]))


def test_sized_lights(program, output):
    """--lights sized: the same cases with a size each, measured against the
    visibility; a replay reproduces it."""
    directory = os.path.join(output, "sweep-sized")
    result = run(program, "sweep", "--cases", "4", "--seed", "4", "--techniques", "uniform",
                 "--min-counted", "0", "--lights", "sized", "--out", directory, *SMALL)
    check(result.returncode == 0, "sized sweep failed: " + result.stderr[-2000:])
    check("Sized lights: the mean absolute difference" in result.stdout, "the visibility table")
    rows = read_rows(os.path.join(directory, "results.csv"))
    hard = {row["seed"]: row for row in read_rows(os.path.join(output, "sweep", "results.csv"))
            if row["technique"] == "uniform"}
    for row in rows:
        check(float(row["light_size"]) > 0.0, "every light has a size")
        check(0.0 <= float(row["visibility_mean_error"]) <= 1.0, "a visibility error")
        check(row["case"].split(";")[0] == hard[row["seed"]]["case"].split(";")[0],
              "the same scene and camera as without sizes")
        check(hard[row["seed"]]["visibility_mean_error"] == "nan", "hard lights: no visibility")
    seed = rows[0]["seed"]
    replay_dir = os.path.join(output, "replay-sized")
    result = run(program, "sweep", "--replay", seed, "--techniques", "uniform", "--lights",
                 "sized", "--out", replay_dir, *SMALL)
    check(result.returncode == 0, "sized replay failed: " + result.stderr[-2000:])
    replayed = read_rows(os.path.join(replay_dir, "results.csv"))[0]
    check(replayed["visibility_mean_error"] == rows[0]["visibility_mean_error"],
          "the replay reproduces the visibility error")


def test_errors(program):
    for arguments, expected in [
        (["sweep", "--cases", "0"], "cases"),
        (["sweep", "--seed", "-1"], "seed"),
        (["sweep", "--replay", "abc"], "replay seed"),
        (["sweep", "--techniques", "none"], "no shadows"),
        (["sweep", "--techniques", "magic"], "unknown technique"),
        (["sweep", "--bogus", "1"], "unknown option"),
        (["sweep", "--lights", "soft"], "neither hard nor sized"),
        (["sweep", "--first-case", "-2"], "first case"),
        (["sweep", "--counted-only", "maybe"], "neither yes nor no"),
    ]:
        lines = check_usage_error(program, arguments, expected)
        check(len(lines) == 1, "%s: one error line, got %r" % (arguments, lines))


def main():
    program, output = sys.argv[1], sys.argv[2]
    os.makedirs(output, exist_ok=True)
    test_errors(program)
    rows = test_sweep_and_replay(program, output)
    test_parts_and_counted_only(program, output, rows)
    test_sized_lights(program, output)
    print("ok")


if __name__ == "__main__":
    main()
