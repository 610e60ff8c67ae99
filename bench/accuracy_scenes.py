#!/usr/bin/env python3
"""docs/accuracy_scenes.md from the runs of tools/accuracy_scenes.sh.

    /usr/bin/python3 bench/accuracy_scenes.py --dir DIR --out FILE [--machine TEXT] [--command TEXT]
        [--date TEXT] [--seconds N] [--queries N]

Reads DIR/<scene>_g<g>.accuracy.json (vrlis_accuracy --queries) and DIR/<scene>_g<g>.json
(the render's summary) and writes one Markdown page.
"""
import argparse
import glob
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from samplers import baseline, own, policies  # noqa: E402

SCENES = ["bidirectional", "room", "cube", "corner"]


def fmt(x, digits=3):
    if x is None or not math.isfinite(x):
        return "-"
    return f"{x:.{digits}g}"


def tabled(acc):
    """The samplers of one vrlis_accuracy run that the tables show: registry names, in order."""
    return [n for n in acc["samplers"] if n not in policies()]


def load(directory):
    runs = []
    for path in glob.glob(os.path.join(directory, "*.accuracy.json")):
        m = re.match(r"(.+)_g(-?[0-9.]+)\.accuracy\.json$", os.path.basename(path))
        if not m:
            continue
        with open(path) as f:
            acc = json.load(f)
        with open(os.path.join(directory, f"{m.group(1)}_g{m.group(2)}.json")) as f:
            render = json.load(f)
        runs.append((m.group(1), float(m.group(2)), acc, render))
    order = {s: i for i, s in enumerate(SCENES)}
    runs.sort(key=lambda r: (order.get(r[0], len(SCENES)), r[1]))
    return runs


def relvar_table(L, runs, step, title):
    L.append(f"### {title}\n")
    L.append("Each cell: unweighted mean / **image-weighted mean** (median in brackets). "
             "Best image-weighted value of the row in bold italics; `+M`: step one by VrlMarginal.\n")
    samplers = tabled(runs[0][2])
    published = [s for s in samplers if s not in own()]
    L.append("| scene | g | " + " | ".join(samplers) + " | best weighted | best weighted, published |")
    L.append("|---" * (len(samplers) + 4) + "|")
    for scene, g, acc, _ in runs:
        r = acc["results"][0][step]
        # (JSON null: undefined, e.g. VrlMarginal on unbounded segments)
        weighted = {s: math.nan if r[s].get("weighted") is None else r[s]["weighted"] for s in samplers}
        best = min(samplers, key=lambda s: weighted[s] if math.isfinite(weighted[s]) else math.inf)
        best_pub = min(published, key=lambda s: weighted[s] if math.isfinite(weighted[s]) else math.inf)
        cells = []
        for s in samplers:
            w = fmt(weighted[s])
            w = f"***{w}***" if s == best else f"**{w}**"
            mean, median = (math.nan if r[s][k] is None else r[s][k] for k in ("mean", "median"))
            cells.append(f"{fmt(mean)} / {w} ({fmt(median)})")
        L.append(f"| {scene} | {g:g} | " + " | ".join(cells) + f" | {best} | {best_pub} |")
    L.append("")


def best_weighted(acc, step, samplers):
    r = acc["results"][0][step]
    vals = {s: r[s].get("weighted") for s in samplers}
    vals = {s: v for s, v in vals.items() if v is not None and math.isfinite(v)}
    return min(vals, key=vals.get) if vals else None


def summary(runs):
    """Sentences computed from the runs (so that they stay true when the page is regenerated)."""
    n = len(runs)
    few = [f"{scene} {g:g}" for scene, g, acc, _ in runs if acc["effective_queries"] < 5]
    lines = []
    lines.append(f"- The image's weights are concentrated: in {len(few)} of {n} runs fewer than 5 effective queries "
                 f"carry the image-weighted figures ({', '.join(few) or 'none'}): there they are decided by a handful "
                 f"of queries (a larger sample would pin them down better); the unweighted means and medians rest on all ~"
                 f"{round(sum(a['records'] for _, _, a, _ in runs) / n)} queries of each run.")
    hard = [(scene, g, acc["hard_class"]) for scene, g, acc, _ in runs if acc["hard_class"]["count"] > 0]
    if hard:
        parts = [f"{scene} {g:g}: {100 * h['fraction']:.1f}% of the queries, {100 * h['weight_fraction']:.0f}% of "
                 f"the weight" for scene, g, h in hard]
        lines.append("- Hard-class queries (long segments passing close to a VRL) occur in " +
                     ", ".join(sorted({s for s, _, _ in hard})) + " only, and carry much of its image: " +
                     "; ".join(parts) + ".")
    for step, label in [("whole", "whole estimator (VrlPoint)"), ("whole_marginal", "whole estimator (+M)"),
                        ("camera", "camera step")]:
        wins = {}
        for _, _, acc, _ in runs:
            b = best_weighted(acc, step, tabled(acc))
            wins[b] = wins.get(b, 0) + 1
        text = ", ".join(f"{s} in {c}" for s, c in sorted(wins.items(), key=lambda kv: -kv[1]))
        lines.append(f"- Lowest image-weighted relative variance of the {label}: {text} of {n} runs.")
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dir", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--machine", default="")
    ap.add_argument("--command", default="")
    ap.add_argument("--date", default="")
    ap.add_argument("--seconds", type=float, default=math.nan)
    ap.add_argument("--queries", type=int, default=0, help="the number of queries the script aimed to keep")
    args = ap.parse_args()
    runs = load(args.dir)
    if not runs:
        raise SystemExit(f"accuracy_scenes.py: error: no *.accuracy.json in {args.dir}")

    L = ["# The accuracy map on the scenes' own gather queries\n"]
    if args.date:
        L.append(f"- Date: {args.date}")
    if args.machine:
        L.append(f"- Machine: {args.machine}")
    if args.command:
        L.append(f"- Command: `{args.command}`" + (f" ({args.seconds / 60:.0f} min)" if math.isfinite(args.seconds) else ""))
    L.append("- Queries: `vrl_render --gather m2m --spp 4 --vrls 64 --seed 1 --dump-queries FILE --dump-every K` "
             "(64 x 64 pixels, the cube 128 x 128), K chosen so that about "
             f"{args.queries or '?'} of the render's medium-to-medium gather queries are kept; which ones is decided by a hash of the query, so the sample does not depend "
             "on the thread count (format: `integration/include/vrlis_integration/query_log.hpp`).")
    L.append("- Accuracy: `vrlis_accuracy --queries FILE`: relative variance `Int f^2/p / (Int f)^2 - 1` by "
             "quadrature (double) of the camera step (at a seeded VRL point per query) and of the whole two-step "
             "estimator (VRL point by VrlPoint, or by VrlMarginal: `+M`), per camera sampler.")
    L.append("- Image weighting: a query contributes `w I` to the image (`w` = camera-path throughput x VRL flux, "
             "RMS over RGB, stored in the log; `I` = the integral of its integrand) and `(w I)^2 relvar` to its "
             "variance, so the image-weighted relative variance is `sum (w I)^2 relvar / sum (w I)^2`. The "
             "unweighted mean is what a map over random configurations measures.")
    L.append("- Effective queries: `(sum a)^2 / sum a^2` with `a = (w I)^2` (Kish): how many of the sampled "
             "queries carry the image-weighted figures; where it is small, those figures rest on a few queries "
             "and are uncertain accordingly.")
    L.append("- Hard class: queries whose camera segment comes within 0.05 mean free paths (mfp) of the VRL "
             "(`sigma_t h < 0.05`, closest points of the two segments) and runs on more than 3 mfp beyond its "
             "closest point.\n")

    L.append("## The queries\n")
    L.append("| scene | g | gathers rendered | queries kept | effective queries | sigma_t | hard class: queries "
             f"| hard: weight | hard: second moment ({baseline()}) | largest 8: weight | largest query: share, sigma_t h, "
             "mfp beyond, camera / VRL length (mfp) |")
    L.append("|---" * 11 + "|")
    for scene, g, acc, render in runs:
        hc = acc["hard_class"]
        top = acc["largest"][0] if acc["largest"] else None
        sigma = sorted({round(q["sigma_t"], 4) for q in acc["largest"]})
        top_text = (f"{top['share']:.2f}, {fmt(top['h_mfp'], 2)}, {fmt(top['beyond_mfp'], 2)}, "
                    f"{fmt(top['camera_mfp'], 2)} / {fmt(top['vrl_mfp'], 2)}") if top else "-"
        L.append(f"| {scene} | {g:g} | {render['gathers']} | {acc['records']} | {acc['effective_queries']:.1f} | "
                 f"{', '.join(fmt(s) for s in sigma)} | {100 * hc['fraction']:.1f}% | "
                 f"{100 * hc['weight_fraction']:.1f}% | {100 * hc['second_moment_fraction'][baseline()]:.1f}% | "
                 f"{100 * acc['largest_share']:.0f}% | {top_text} |")
    L.append("")

    L.append("## In short\n")
    L.append(summary(runs))
    L.append("## Relative variance per sampler\n")
    relvar_table(L, runs, "whole", "Whole estimator (VRL point by VrlPoint, camera point by the sampler)")
    relvar_table(L, runs, "whole_marginal", "Whole estimator with VrlMarginal as step one (+M)")
    relvar_table(L, runs, "camera", "Camera step alone (fixed VRL point; weighted by the camera step's own integral)")

    unconverged = sum(acc["results"][0]["unconverged"] for _, _, acc, _ in runs)
    worst = max(acc["results"][0]["max_rel_error"] for _, _, acc, _ in runs)
    L.append(f"Quadrature: {unconverged} of {sum(acc['records'] for _, _, acc, _ in runs)} queries stopped at the "
             f"evaluation budget before the (pessimistic, G7-K15) error estimate met the tolerance; the largest "
             f"estimated relative error of any moment is {worst:.1e}.\n")
    L.append("Per-run tables with the best counts and the largest weights of each run: "
             "`<outdir>/<scene>_g<g>.accuracy.txt` after `tools/accuracy_scenes.sh`.")
    with open(args.out, "w") as f:
        f.write("\n".join(L) + "\n")


if __name__ == "__main__":
    main()
