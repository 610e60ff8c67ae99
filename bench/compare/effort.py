#!/usr/bin/python3
"""The effort control's tables, from runs of `vrl_compare --with-effort` (tools/effort.sh).

Per run and study: the best fixed published sampler at fixed effort (equiangular, Novák,
CauchySum, CauchyMixture: every gather taken once), and against it, with a 95% interval,
each of our own methods and every method with the effort control on (NAME+effort); the
error against the reference over the noise (about 1 when unbiased) of every method.

    effort.py RUN... [--publish FILE] [--command CMD] [--previous PAGE]

With --publish, also the README's sentence between its effort-summary markers. With --previous
(the page this one replaces, e.g. from `git show`), every method's cells against that page's,
cell by cell.

A method's gains over the cells are far from normal (room's and the cloud's near 4-5, the
bidirectional scene's and the cube's near 1-2), so their median can sit in the gap between the
groups: its interval (a bootstrap over the cells) says how far it moves when a few cells do, and
the cell-by-cell ratio against an earlier run is the comparison that does not move so."""
import argparse
import math
import os
import random
import re
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot import load, provenance, update_readme  # noqa: E402
import samplers  # noqa: E402  (tools/samplers.py, on the path through plot)

SUFFIX = "+effort"


def interval(j):
    """(point, low, high) of a ratio the study wrote (bench/compare/efficiency.hpp)."""
    return j["point"], j["low"], j["high"]


def median_interval(values, resamples=2000):
    """The median and a 95% bootstrap interval of it over the cells (seeded: the page is a function of its runs)."""
    rng = random.Random(1)
    medians = sorted(statistics.median(rng.choices(values, k=len(values))) for _ in range(resamples))
    return statistics.median(values), medians[int(0.025 * resamples)], medians[int(0.975 * resamples) - 1]


def geomean(values):
    return math.exp(statistics.fmean(math.log(v) for v in values))


def outside(sampler):
    """Whether a method's error² / noise² lies outside the range it keeps 95% of the time when
    unbiased (bench/compare/error_to_noise.hpp)."""
    low, high = sampler.get("error_range", (0, math.inf))
    return not low <= sampler["error_to_noise"] <= high


def error_cell(sampler):
    x = f"{sampler['error_to_noise']:.2f}"
    return f"**{x}**" if outside(sampler) else x


def error_range(samplers):
    """The median over a study's methods of their ranges (they differ by the noise's shape)."""
    ranges = [s["error_range"] for s in samplers if "error_range" in s]
    if not ranges:
        return ""
    return f"{statistics.median(r[0] for r in ranges):.2f}-{statistics.median(r[1] for r in ranges):.2f}"


def cell(r):
    return f"{r[0]:.2f} ({r[1]:.2f}-{r[2]:.2f})"


def studies(run):
    return [load(os.path.join(run, name, "result.json")) for name in load(os.path.join(run, "studies.json"))]


def by_name(result):
    return {s["sampler"]: s for s in result["samplers"]}


def tables(runs):
    """(against-best table, error table, summary lines)"""
    names = []
    for run in runs:
        for r in run:
            names += [s["sampler"] for s in r["samplers"] if s["sampler"] not in names]
    fixed = [n for n in names if not n.endswith(SUFFIX)]
    header = "| study | seed | best fixed published | " + " | ".join(f"`{n}`" for n in names) + " |"
    rule = "|---|---|---|" + "---|" * len(names)
    rows, errors, medians = [header, rule], [], {n: [] for n in names}
    flagged, checked = 0, 0
    for run in runs:
        for r in run:
            seed = r["seed"]
            s, best = by_name(r), r["best_published"]
            cells = []
            for n in names:
                if n not in s:
                    cells.append("")
                    continue
                x = interval(s[n]["to_best_published"])
                medians[n].append(x[0])
                cells.append(("**" if x[2] < 1 else "") + cell(x) + ("**" if x[2] < 1 else ""))
                flagged += outside(s[n])
                checked += 1
            rows.append(f"| {r['scene']} g = {round(r['g'], 4)} | {seed} | `{best}` | " + " | ".join(cells) + " |")
            errors.append(f"| {r['scene']} g = {round(r['g'], 4)} | {seed} | " +
                          " | ".join(error_cell(s[n]) if n in s else "" for n in names) +
                          f" | {error_range(s.values())} |")
    error_table = ["| study | seed | " + " | ".join(f"`{n}`" for n in names) + " | range if unbiased |",
                   "|---|---|" + "---|" * (len(names) + 1)]
    summary = []
    for n in names:
        below = sum(1 for run in runs for r in run
                    if n in by_name(r) and by_name(r)[n]["to_best_published"]["high"] < 1)
        summary.append(f"| `{n}` | {statistics.median(medians[n]):.2f} | {below} of {len(medians[n])} |")
    gains = []
    for n in fixed:
        if n + SUFFIX in names:
            g = [by_name(r)[n + SUFFIX]["to_without_effort"]["point"] for run in runs for r in run
                 if n in by_name(r) and n + SUFFIX in by_name(r)]
            if not g:
                continue
            gains.append(f"| `{n}` | {cell(median_interval(g))} | {geomean(g):.2f} | {min(g):.2f}-{max(g):.2f} |")
    cells = {n: v for n, v in medians.items() if v}
    ranked = sorted((n for n in cells if n.endswith(SUFFIX)), key=lambda n: -statistics.median(cells[n]))
    all_gains = [by_name(r)[n + SUFFIX]["to_without_effort"]["point"] for run in runs for r in run for n in fixed
                 if n in by_name(r) and n + SUFFIX in by_name(r)]
    policies = [n + SUFFIX for n in samplers.policies()]
    sentence = ""
    if ranked and all_gains:
        best = ", ".join(f"`{n}` {statistics.median(cells[n]):.2f}" for n in ranked[:3])
        sentence = (f"Against each study's best fixed published sampler, median over {len(cells[ranked[0]])} cells: "
                    f"{best}" + "".join(f"; `{n}` {statistics.median(cells[n]):.2f}" for n in policies
                                        if n in cells and n not in ranked[:3]) +
                    f". The control alone, each method over itself without it: median {statistics.median(all_gains):.2f} "
                    f"(range {min(all_gains):.2f}-{max(all_gains):.2f}; [docs/compare/effort.md](docs/compare/effort.md)).\n")
    return rows, error_table + errors, summary, gains, (flagged, checked), sentence


def published_cells(page):
    """{(study, seed): {method: point}} from a published page's per-study table."""
    out, names = {}, []
    for line in page.splitlines():
        if line.startswith("| study |"):
            names = re.findall(r"`([^`]+)`", line)
        elif names and re.match(r"\| \S+ g = ", line):
            parts = [p.strip() for p in line.strip("|").split("|")]
            points = [float(m.group(1)) for p in parts if (m := re.match(r"\**([\d.]+) \(", p))]
            if len(points) == len(names):
                out[(parts[0], parts[1])] = dict(zip(names, points))
    return out


def against_previous(runs, page):
    """Every method's cells over the previous page's, cell by cell: median and geometric mean of the ratio."""
    before = published_cells(page)
    ratios = {}
    for run in runs:
        for r in run:
            old = before.get((f"{r['scene']} g = {round(r['g'], 4)}", str(r["seed"])), {})
            for n, s in by_name(r).items():
                if old.get(n):
                    ratios.setdefault(n, []).append(s["to_best_published"]["point"] / old[n])
    return [f"| `{n}` | {cell(median_interval(v))} | {geomean(v):.2f} | {len(v)} |" for n, v in ratios.items()]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--publish")
    ap.add_argument("--command", default="tools/effort.sh")
    ap.add_argument("--previous", help="the published page this run replaces")
    a = ap.parse_args()
    runs = [studies(r) for r in a.runs]
    rows, errors, summary, gains, (flagged, checked), sentence = tables(runs)
    previous = []
    if a.previous:
        with open(a.previous) as f:
            previous = [
                "Against the page this one replaced, cell by cell (each method's efficiency over its cell's best fixed "
                "published sampler here, over the same on that page; the best fixed published sampler itself may "
                "have changed between the two):",
                "",
                "| method | median ratio (95% interval) | geometric mean | cells |",
                "|---|---|---|---|",
                *against_previous(runs, f.read()),
                "",
            ]
    page = "\n".join([
        "# The effort control against the best fixed sampler",
        "",
        provenance(a.command),
        "",
        "Every method of the equal-time study, each also with the effort control on (`NAME+effort`: "
        "Russian roulette and splitting of every VRL gather by a price of variance learned from earlier "
        "passes, [../maths.md](../maths.md#effort); `auto+effort` also chooses both steps' models by it, "
        "[../maths.md](../maths.md#effort-models)): the default study (bidirectional scene and room, "
        "g in {-0.9, 0.5, 0.9}) with seeds 1 and 2, and every scene at every g in {-0.9, -0.5, 0, 0.5, 0.9} with seed 1. "
        "Each cell is the method's efficiency over that study's best "
        "fixed published sampler (equiangular, Novák, CauchySum, CauchyMixture, every gather taken once) "
        "with its 95% interval; **bold**: the interval lies below 1.",
        "",
        "| method | median over the cells | cells whose interval lies below 1 |",
        "|---|---|---|",
        *summary,
        "",
        "The effort control's own gain, `NAME+effort` over `NAME` over the cells: the median with a 95% "
        "bootstrap interval over the cells, the geometric mean and the range:",
        "",
        "| method | median (95% interval) | geometric mean | range |",
        "|---|---|---|---|",
        *gains,
        "",
        *previous,
        "## Per study",
        "",
        *rows,
        "",
        "## error² / noise²",
        "",
        "The squared error of each method's image against the reference over the noise expected of both: "
        "about 1 when unbiased, but with the spread of a chi-square on as few degrees of freedom as the "
        "image's noise has independent directions (a light path lights many pixels at once). The last "
        "column is the range it keeps 95% of the time when unbiased, from the replicates' and the reference's own spread "
        "([README.md](README.md#the-reference-and-the-bias-check)); **bold**: outside it "
        f"({flagged} of {checked}; a row's methods share its seeds and reference, so they leave it together).",
        "",
        *errors,
        "",
    ])
    print(page)
    if a.publish:
        with open(a.publish + ".tmp", "w") as f:
            f.write(page)
        os.replace(a.publish + ".tmp", a.publish)
        update_readme(provenance(a.command), sentence, marker="effort-summary")


if __name__ == "__main__":
    main()
