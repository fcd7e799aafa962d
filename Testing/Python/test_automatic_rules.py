"""Measurement/automatic_rules.py on made-up sweep results, whose answers are
known: each class's lowest candidate, the in-sample rule, a rule read off other
cases and measured on these (--rule-from, unseen classes skipped), and the
comparison of a technique with the per-case best and the old default.

usage: test_automatic_rules.py AUTOMATIC_RULES_PY OUTPUT_DIR
"""
import csv
import os
import subprocess
import sys

from clitools import check

COLUMNS = ["seed", "counted", "technique", "misclassified", "light_kind", "cos_light_view",
           "light_behind_camera"]


def write_results(path, cases):
    """cases: (seed, kind, cosine, {technique: misclassified}), 1000 counted pixels each."""
    with open(path, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=COLUMNS)
        writer.writeheader()
        for seed, kind, cosine, figures in cases:
            for technique, value in figures.items():
                writer.writerow({"seed": seed, "counted": 1000, "technique": technique,
                                 "misclassified": value, "light_kind": kind,
                                 "cos_light_view": cosine, "light_behind_camera": 0})


def rules(script, *arguments):
    result = subprocess.run([sys.executable, script, *arguments], capture_output=True, text=True)
    check(result.returncode == 0, "automatic_rules.py failed: " + result.stderr[-2000:])
    return result.stdout


def main():
    script, output = sys.argv[1], sys.argv[2]
    os.makedirs(output, exist_ok=True)
    # Suns facing the camera favour "a", spots side-on favour "b"; "auto"
    # takes "a" everywhere and the old default ("csm") is worse but once.
    here = os.path.join(output, "rules-here.csv")
    write_results(here, [
        ("1", "sun", -0.9, {"a": 0.1, "b": 0.5, "auto": 0.1, "csm": 0.4}),
        ("2", "sun", -0.8, {"a": 0.3, "b": 0.9, "auto": 0.3, "csm": 0.2}),
        ("3", "spot", 0.2, {"a": 0.8, "b": 0.2, "auto": 0.8, "csm": 1.0}),
        ("4", "spot", 0.3, {"a": 0.6, "b": 0.0, "auto": 0.6, "csm": 0.9}),
    ])
    # Other cases whose spots favour "a": the rule read there gives spots "a";
    # their point light's class is not here, their suns' is.
    there = os.path.join(output, "rules-there.csv")
    write_results(there, [
        ("5", "sun", -0.7, {"a": 0.1, "b": 0.2}),
        ("6", "spot", 0.4, {"a": 0.1, "b": 0.7}),
        ("7", "point", 0.9, {"a": 0.1, "b": 0.0}),
    ])

    out = rules(script, here, "--candidates", "a,b", "--in-sample-rule", "--rule-from", there)
    check("| sun cos [-1.0, -0.5] | 2 | 0.200 / 0.290 | 0.700 / 0.880 | a |" in out,
          "the suns' medians, 95th percentiles and lowest candidate:\n" + out)
    check("| spot cos [+0.0, +0.5] | 2 | 0.700 / 0.790 | 0.100 / 0.190 | b |" in out,
          "the spots' lowest candidate is b:\n" + out)
    check("median 0.150, p95 0.285 over 4 cases" in out,
          "the in-sample rule takes a for suns and b for spots:\n" + out)
    check("| spot cos [+0.0, +0.5] | 1 | a |" in out and "| point cos [+0.5, +1.0] | 1 | b |" in out,
          "the rule read off the other cases lists its classes:\n" + out)
    check("median 0.450, p95 0.770 over 4 cases" in out,
          "the other cases' rule (a for suns and spots) measured here:\n" + out)

    out = rules(script, here, "--candidates", "a,b", "--technique", "auto", "--best-of", "a,b")
    check("| all | 4 | 0.150 / 0.285 | 0.450 / 0.770 | 0.650 / 0.985 | 1 |" in out,
          "auto against the per-case best and csm, one case above csm by more than 5 %:\n" + out)
    print("ok")


if __name__ == "__main__":
    main()
