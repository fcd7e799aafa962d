#!/usr/bin/env python3
"""The automatic pass's rules from a robustness sweep (`vtkshadows sweep`'s
results.csv, run with the candidate pairs): per class of situation (the light's
kind, the cosine between its direction and the view's, a positional light behind
the camera), each candidate's median and 95th percentile of misclassified %, the
candidate with the lowest of (median + p95) / 2, and how a technique (the
automatic pass, by default) compares with the per-case best and with the old
default (csm).

  automatic_rules.py results.csv [more.csv ...] [--best-of T,T,...]
      [--technique auto] [--default csm] [--candidates dual,dual+csm,...]
      [--in-sample-rule] [--rule-from other.csv[,more.csv]]

Several results.csv of the same sweep seed (the same cases, other techniques)
are read as one; a technique measured in a later file replaces the earlier's.
"""
import argparse
import csv
import statistics
from collections import defaultdict

COS_EDGES = [-1.0, -0.5, 0.0, 0.5, 1.0001]


def percentile(values, fraction):
    ordered = sorted(values)
    if not ordered:
        return float("nan")
    position = fraction * (len(ordered) - 1)
    low = int(position)
    high = min(low + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (position - low)


def class_of(row):
    cosine = float(row["cos_light_view"])
    band = next(i for i in range(len(COS_EDGES) - 1) if cosine < COS_EDGES[i + 1])
    behind = " behind" if row["light_behind_camera"] == "1" else ""
    return f"{row['light_kind']}{behind} cos [{COS_EDGES[band]:+.1f}, {min(COS_EDGES[band + 1], 1.0):+.1f}]"


def read_cases(paths, minimum_counted):
    cases = defaultdict(dict)
    classes = {}
    for path in paths:
        for row in csv.DictReader(open(path)):
            if int(row["counted"]) < minimum_counted:
                continue
            cases[row["seed"]][row["technique"]] = float(row["misclassified"])
            classes[row["seed"]] = class_of(row)
    return cases, classes


def summary(values):
    return statistics.median(values), percentile(values, 0.95)


def seeds_by_class(classes):
    """The case seeds of each class."""
    by_class = defaultdict(list)
    for seed, name in classes.items():
        by_class[name].append(seed)
    return by_class


def rule_of(cases, by_class, candidates):
    """Each class's candidate of the lowest mean misclassified % over its cases."""
    def mean_of(seeds, candidate):
        values = [cases[s][candidate] for s in seeds if candidate in cases[s]]
        return statistics.mean(values) if values else float("inf")
    return {name: min(candidates, key=lambda c: mean_of(seeds, c))
            for name, seeds in by_class.items()}


def rule_summary(cases, classes, chosen):
    """Median, 95th percentile and count of the figures the rule `chosen` gets."""
    values = [cases[s][chosen[classes[s]]] for s in cases
              if classes[s] in chosen and chosen[classes[s]] in cases[s]]
    median, p95 = summary(values) if values else (float("nan"), float("nan"))
    return median, p95, len(values)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("csv", nargs="+")
    parser.add_argument("--candidates", default="dual,dual+csm,dual+tsm,dual+lispsm,dual+psm")
    parser.add_argument("--best-of", default="")
    parser.add_argument("--technique", default="auto")
    parser.add_argument("--default", default="csm")
    parser.add_argument("--min-counted", type=int, default=300)
    parser.add_argument("--in-sample-rule", action="store_true",
                        help="also the distribution of the rule that gives each class its "
                             "candidate of the lowest mean there (the best any rule of the "
                             "classes can do on these cases)")
    parser.add_argument("--rule-from", default="",
                        help="comma-separated results.csv of other cases: the rule that gives "
                             "each class the candidate of the lowest mean over those cases, "
                             "measured on these (a rule checked out of sample)")
    args = parser.parse_args()
    cases, classes = read_cases(args.csv, args.min_counted)
    candidates = args.candidates.split(",")
    best_of = args.best_of.split(",") if args.best_of else None

    by_class = seeds_by_class(classes)

    print("| class | cases | " + " | ".join(candidates) + " | lowest |")
    print("|---|---:|" + "---:|" * len(candidates) + "---|")
    for name in sorted(by_class):
        seeds = by_class[name]
        cells = []
        scores = {}
        for candidate in candidates:
            values = [cases[s][candidate] for s in seeds if candidate in cases[s]]
            if not values:
                cells.append("–")
                continue
            median, p95 = summary(values)
            scores[candidate] = (median + p95) / 2.0
            cells.append(f"{median:.3f} / {p95:.3f}")
        lowest = min(scores, key=scores.get) if scores else "–"
        print(f"| {name} | {len(seeds)} | " + " | ".join(cells) + f" | {lowest} |")

    if args.in_sample_rule:
        chosen = rule_of(cases, by_class, candidates)
        median, p95, count = rule_summary(cases, classes, chosen)
        print(f"\nThe in-sample rule (each class's lowest mean among the candidates): "
              f"median {median:.3f}, p95 {p95:.3f} over {count} cases")
    if args.rule_from:
        other_cases, other_classes = read_cases(args.rule_from.split(","), args.min_counted)
        other_by_class = seeds_by_class(other_classes)
        chosen = rule_of(other_cases, other_by_class, candidates)
        print(f"\nThe rule read off {args.rule_from} ({len(other_cases)} cases):\n")
        print("| class | cases there | candidate |\n|---|---:|---|")
        for name in sorted(chosen):
            print(f"| {name} | {len(other_by_class[name])} | {chosen[name]} |")
        median, p95, count = rule_summary(cases, classes, chosen)
        print(f"\nThat rule on these cases (classes it has not seen: skipped): "
              f"median {median:.3f}, p95 {p95:.3f} over {count} cases")

    technique = args.technique
    measured = [s for s in cases if technique in cases[s]]
    if not measured:
        return
    print(f"\n{technique} against the per-case best"
          f" ({', '.join(best_of) if best_of else 'every technique measured'})"
          f" and the old default ({args.default}), misclassified %:\n")
    print("| class | cases | best median / p95 | " + technique + " median / p95 | "
          + args.default + " median / p95 | cases where " + technique + " > 1.05 × "
          + args.default + " |")
    print("|---|---:|---:|---:|---:|---:|")
    rows = sorted(by_class.items()) + [("all", measured)]
    for name, seeds in rows:
        seeds = [s for s in seeds if technique in cases[s]]
        best = [min(v for t, v in cases[s].items() if best_of is None or t in best_of)
                for s in seeds]
        ours = [cases[s][technique] for s in seeds]
        old = [cases[s].get(args.default, float("nan")) for s in seeds]
        worse = sum(1 for o, d in zip(ours, old) if o > 1.05 * d + 1e-9)
        b, o, d = summary(best), summary(ours), summary(old)
        print(f"| {name} | {len(seeds)} | {b[0]:.3f} / {b[1]:.3f} | {o[0]:.3f} / {o[1]:.3f} | "
              f"{d[0]:.3f} / {d[1]:.3f} | {worse} |")


if __name__ == "__main__":
    main()
