#!/usr/bin/python3
"""Whether two runs of the default study (different seeds) give the same verdicts: per study,
the "best" sampler or the samplers tied with the winner, from each run's result.json, and
both runs' tables (summary.md) and resolution lines. Writes Markdown to stdout.
Usage: bench/compare/two_runs.py RUN1_DIR RUN2_DIR"""
import json
import os
import sys


def studies(run):
    """The studies of a run: the directories its resolution.txt names."""
    with open(os.path.join(run, "resolution.txt")) as f:
        return [line.split(":", 1)[0] for line in f if ":" in line]


def verdict(run, study):
    with open(os.path.join(run, study, "result.json")) as f:
        r = json.load(f)
    return r["seed"], r["verdict"], sorted(s["sampler"] for s in r["samplers"] if s["verdict"])


def read(path):
    with open(path) as f:
        return f.read().rstrip("\n")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: bench/compare/two_runs.py RUN1_DIR RUN2_DIR")
    runs = sys.argv[1:]
    names = studies(runs[0])
    if names != studies(runs[1]):
        sys.exit("the two runs hold different studies")
    rows, same = [], 0
    for study in names:
        (s1, v1, w1), (s2, v2, w2) = verdict(runs[0], study), verdict(runs[1], study)
        agree = (v1, w1) == (v2, w2)
        same += agree
        rows.append(f"| {study} | {v1}: {', '.join(w1)} | {v2}: {', '.join(w2)} | {'same' if agree else '**different**'} |")
    seeds = [verdict(run, names[0])[0] for run in runs]
    print(f"Verdicts agree in {same} of {len(names)} studies (seeds {seeds[0]} and {seeds[1]}).\n")
    print(f"| study | seed {seeds[0]} | seed {seeds[1]} | |\n|---|---|---|---|")
    print("\n".join(rows))
    for seed, run in zip(seeds, runs):
        print(f"\n### Seed {seed}\n")
        print(read(os.path.join(run, "summary.md")))
        print("\n```\n" + read(os.path.join(run, "resolution.txt")) + "\n```")


if __name__ == "__main__":
    main()
