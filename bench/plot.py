#!/usr/bin/env python3
"""Charts and a Markdown table from one vrlis_bench run and one vrlis_accuracy run.

    /usr/bin/python3 bench/plot.py --bench bench.json --accuracy accuracy.json --out DIR \
        [--machine TEXT] [--command TEXT] [--date TEXT]

Writes DIR/table.md, DIR/speed_accuracy.{png,svg} and DIR/efficiency.{png,svg}.

Time per sample is the median CPU time over the benchmark's repetitions (CPU time, not
wall time: the machine may be shared). All ratios come from the one benchmark run given.
Efficiency is 1 / (relative variance x time per sample), with the mean relative variance
over the study's pairs (what the error of a whole image sees; the median is in the table).
"""
import argparse
import datetime
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from samplers import baseline, label, own, policies, style, thesis  # noqa: E402

STEPS = [("camera", "Camera", "camera step (fixed VRL point)"),
         ("whole", "Estimator", "whole estimator (VRL point + camera point)"),
         ("whole_marginal", "EstimatorMarginal", "whole estimator with VrlMarginal as step one")]
# The whole estimator with either step one: (step, prefix, label suffix).
WHOLE = [("whole", "Estimator", ""), ("whole_marginal", "EstimatorMarginal", "+M")]
UNIT = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def load_bench(path, names):
    """{run_name: median cpu time in ns} and the run's context; kind/<registry name>/g:<g>
    runs are renamed kind/<label>/g:<g>."""
    with open(path) as f:
        data = json.load(f)
    times, singles = {}, {}
    for b in data["benchmarks"]:
        name = b.get("run_name", b["name"])
        parts = name.split("/")
        if len(parts) == 3 and parts[1] in names:
            name = "/".join([parts[0], label(parts[1]), parts[2]])
        t = b["cpu_time"] * UNIT[b.get("time_unit", "ns")]
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == "median":
                times[name] = t
        else:
            singles.setdefault(name, []).append(t)
    for name, ts in singles.items():  # runs without repetitions
        if name not in times:
            ts = sorted(ts)
            times[name] = ts[len(ts) // 2]
    return times, data.get("context", {})


def gkey(g):
    return f"g:{g:.2f}"


def fmt(x, digits=3):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    return f"{x:.{digits}g}"


def geomean(xs):
    xs = [x for x in xs if x and x > 0]
    return math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else float("nan")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bench", required=True)
    ap.add_argument("--accuracy", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--machine", default="")
    ap.add_argument("--command", default="")
    ap.add_argument("--date", default=datetime.datetime.now().strftime("%Y-%m-%d %H:%M"))
    args = ap.parse_args()

    with open(args.accuracy) as f:
        acc = json.load(f)
    names = acc["samplers"]  # the registry's, in its order
    times, context = load_bench(args.bench, names)
    tabled = [n for n in names if n not in policies()]
    samplers = [label(n) for n in tabled]
    published = [label(n) for n in tabled if n not in own()]
    styles = {label(n): style(n) for n in tabled}

    def relabel(per_sampler):
        return {label(n): per_sampler[n] for n in tabled}

    for r in acc["results"]:
        for step in [st[0] for st in STEPS] + ["whole_bounded"]:
            if step in r:
                r[step] = relabel(r[step])
    gs = [r["g"] for r in acc["results"]]
    steps = [st for st in STEPS if all(st[0] in r for r in acc["results"])]
    # VrlMarginal needs a bounded camera segment: with unbounded ones in the study, VrlPoint is
    # compared with it on the bounded configurations only ("whole_bounded").
    bounded = all("whole_bounded" in r for r in acc["results"])
    whole_steps = [("whole_bounded" if bounded else "whole", "Estimator", ""), WHOLE[1]]
    relvar = {step: {(r["g"], s): r[step][s] for r in acc["results"] for s in samplers}
              for step in [st[0] for st in steps] + (["whole_bounded"] if bounded else [])}

    def time(prefix, s, g):
        return times.get(f"{prefix}/{s}/{gkey(g)}")

    eff = {}
    for step, prefix, _ in steps + ([("whole_bounded", "Estimator", "")] if bounded else []):
        for g in gs:
            for s in samplers:
                t, rv = time(prefix, s, g), relvar[step][(g, s)]
                eff[(step, g, s)] = 1e9 / (rv["mean"] * t) if t and rv["mean"] > 0 else float("nan")
                eff[(step, g, s, "median")] = 1e9 / (rv["median"] * t) if t and rv["median"] > 0 else float("nan")

    os.makedirs(args.out, exist_ok=True)
    L = []
    L.append("# vrlis: speed and accuracy of the camera samplers\n")
    L.append(f"- Date: {args.date}")
    if args.machine:
        L.append(f"- Machine: {args.machine}")
    if args.command:
        L.append(f"- Command: `{args.command}`")
    L.append(f"- Speed: `vrlis_bench`, float, one sample = fit + sample_pdf (sample and its density in one call, as renderers make it) over a pool of "
             f"{context.get('vrlis_pool', '1024')} random queries cycled in order; median CPU time of the repetitions "
             f"of one run (vrlis build: {context.get('vrlis_build', '?')}).")
    L.append(f"- Accuracy: `vrlis_accuracy`, relative variance `Int f^2/p / (Int f)^2 - 1` by quadrature (double), "
             f"{acc['pairs']} seeded configurations per g (seed {acc['seed']}), {acc['medium']}"
             + (f"; {100 * acc['hard_class']['fraction']:.0f}% of them in the scenes' hard class (a camera segment "
                f"within 0.05 mean free paths of the VRL and running on more than 3 beyond; "
                f"[accuracy_scenes.md](accuracy_scenes.md))" if "hard_class" in acc else "") + ".")
    L.append("- Efficiency: `1 / (mean relative variance x time per sample)`, in 1/s; "
             "the margin is the winner's efficiency over the runner-up's.\n")

    # Speed: the thesis's samplers and ours against the baseline (Novák's), as the lab lists them.
    base = label(baseline())
    claimed = [label(n) for n in thesis()]
    ours = [label(n) for n in tabled if n in own()]
    L.append(f"## Time per sample (ns) and ratios to {base}\n")
    L.append("| g | " + " | ".join(samplers) + " | " + " | ".join(f"**{c} / {base}**" for c in claimed) + " | "
             + " | ".join(f"{c} / {base}" for c in ours) + " | " + " | ".join(f"estimator: {s}" for s in samplers)
             + " | " + " | ".join(f"estimator {c} / {base}" for c in claimed) + " |")
    L.append("|---" * (2 * len(samplers) + 2 * len(claimed) + len(ours) + 1) + "|")
    camera_ratio = {c: [] for c in claimed + ours}
    estimator_ratio = {c: [] for c in claimed}
    for g in gs:
        c = {s: time("Camera", s, g) for s in samplers}
        e = {s: time("Estimator", s, g) for s in samplers}
        for k in camera_ratio:
            camera_ratio[k].append(c[k] / c[base])
        for k in estimator_ratio:
            estimator_ratio[k].append(e[k] / e[base])
        L.append(f"| {g:g} | " + " | ".join(fmt(c[s]) for s in samplers) + " | "
                 + " | ".join(f"**{camera_ratio[k][-1]:.2f}**" for k in claimed) + " | "
                 + " | ".join(f"{camera_ratio[k][-1]:.2f}" for k in ours) + " | "
                 + " | ".join(fmt(e[s]) for s in samplers) + " | "
                 + " | ".join(f"{estimator_ratio[k][-1]:.2f}" for k in claimed) + " |")
    vp = times.get("VrlPoint")
    L.append("")
    L.append("Geometric mean over g of the camera-step ratio: "
             + ", ".join(f"{k} / {base} = **{geomean(v):.2f}** (range over g {min(v):.2f}-{max(v):.2f})"
                         for k, v in camera_ratio.items() if k in claimed)
             + "; " + ", ".join(f"{k} / {base} = {geomean(camera_ratio[k]):.2f}" for k in ours)
             + ". Whole estimator step: " + ", ".join(f"{k} {geomean(v):.2f}" for k, v in estimator_ratio.items()) + "."
             + (f" VrlPoint alone: {vp:.0f} ns." if vp else ""))

    def where(rs, bound):
        return "{" + (", ".join(f"{g:g}" for g, x in zip(gs, rs) if x < bound) or "none") + "}"
    L.append(f"The thesis's claim (a sample costs less than {base}'s) holds for "
             + " and ".join(f"{k} at g in {where(camera_ratio[k], 1)}" for k in claimed) + ".")
    fits = [(s, [times.get(f"Fit/{s}/{gkey(g)}") for g in gs]) for s in samplers]
    if all(all(t for t in ts) for _, ts in fits):
        L.append("Of the camera-step time, the fit alone takes (geometric mean over g): "
                 + ", ".join(f"{s} {geomean(ts):.0f} ns" for s, ts in fits) + ".")
    L.append("")

    vm = [times.get(f"VrlMarginal/step/{gkey(g)}") for g in gs]
    if all(vm):
        L.append(f"VrlMarginal alone (fit + sample_pdf; 8 nodes, each a 2-point rule on 1-5 pieces cut at the lobes' peaks): {geomean(vm):.0f} ns "
                 f"(range over g {min(vm):.0f}-{max(vm):.0f}); the estimator with it as step one is timed as "
                 f"EstimatorMarginal/<camera sampler>.")
        L.append("")

    # Accuracy and efficiency.
    for step, prefix, title in steps:
        L.append(f"## {title[0].upper() + title[1:]}: relative variance and efficiency\n")
        L.append("| g | " + " | ".join(f"{s} median / mean" for s in samplers) + " | "
                 + " | ".join(f"{s} eff." for s in samplers) + " | most efficient (margin) | by median "
                 "| most efficient of the published samplers (margin) |")
        L.append("|---" * (2 * len(samplers) + 4) + "|")
        for g in gs:
            rv = [relvar[step][(g, s)] for s in samplers]
            ef = [eff[(step, g, s)] for s in samplers]
            efm = [eff[(step, g, s, "median")] for s in samplers]
            order = sorted(range(len(samplers)), key=lambda k: -ef[k])
            orderm = sorted(range(len(samplers)), key=lambda k: -efm[k])
            win = f"**{samplers[order[0]]}** (x{ef[order[0]] / ef[order[1]]:.2f} over {samplers[order[1]]})"
            winm = f"{samplers[orderm[0]]} (x{efm[orderm[0]] / efm[orderm[1]]:.2f})"
            pub = [k for k in order if samplers[k] in published]
            winp = f"{samplers[pub[0]]} (x{ef[pub[0]] / ef[pub[1]]:.2f} over {samplers[pub[1]]})"
            L.append(f"| {g:g} | " + " | ".join(f"{fmt(r['median'])} / {fmt(r['mean'])}" for r in rv) + " | "
                     + " | ".join(f"{x:.3g}" for x in ef) + f" | {win} | {winm} | {winp} |")
        L.append("")
    if "whole_marginal" in relvar:
        L.append("## Whole estimator, either step one: the most efficient combination\n")
        L.append("Step one by VrlPoint (no suffix) or VrlMarginal (+M), camera step by each sampler; "
                 "efficiency from the mean relative variance and the EstimatorMarginal / Estimator times"
                 + (", both over the configurations with a bounded camera segment (VrlMarginal needs one: "
                    f"{acc['results'][0]['whole_marginal']['Novak']['count']} of {acc['pairs']})" if bounded else "")
                 + ".\n")
        L.append("| g | best with VrlPoint (eff.) | best with VrlMarginal (eff.) | gain | "
                 "FullProduct: rel. var. VrlPoint -> +M (mean) | time (ns) | most efficient overall (margin) |")
        L.append("|---" * 7 + "|")
        for g in gs:
            combos = [(s + suffix, eff[(step, g, s)], step, prefix, s) for step, prefix, suffix in whole_steps
                      for s in samplers]
            combos = [c for c in combos if math.isfinite(c[1])]
            combos.sort(key=lambda c: -c[1])
            bp = max((c for c in combos if c[2] == whole_steps[0][0]), key=lambda c: c[1])
            bm = max((c for c in combos if c[2] == "whole_marginal"), key=lambda c: c[1])
            fp0, fp1 = relvar[whole_steps[0][0]][(g, "FullProduct")]["mean"], relvar["whole_marginal"][(g, "FullProduct")]["mean"]
            t0, t1 = time("Estimator", "FullProduct", g), time("EstimatorMarginal", "FullProduct", g)
            L.append(f"| {g:g} | {bp[0]} ({bp[1]:.3g}) | {bm[0]} ({bm[1]:.3g}) | x{bm[1] / bp[1]:.2f} | "
                     f"{fmt(fp0)} -> {fmt(fp1)} | {fmt(t0)} -> {fmt(t1)} | "
                     f"**{combos[0][0]}** (x{combos[0][1] / combos[1][1]:.2f} over {combos[1][0]}) |")
        L.append("")
    L.append("At g = 0 Novák and both Cauchy samplers draw the equiangular distribution (their relative variances are "
             "equal), so among them only cost differs there; FullProduct also follows transmittance. "
             "FullProduct is vrlis's own sampler (Novák's construction over phases x transmittance, 8 nodes), "
             "not one of the published ones. "
             "VrlMarginal (+M) is vrlis's own step one: VrlPoint's inverse-distance density times a piecewise-linear "
             "correction over VrlPoint's CDF, fitted at 8 nodes to an estimate of the marginal Int f du (transmittance "
             "along the VRL and to the camera segment's start times a 2-point Gauss rule of FullProductTarget over the "
             "camera step's angle interval, cut into pieces at both lobes' peaks); it is not one of the published ones "
             "either. Its relative variance is the whole estimator's with the same camera samplers, by the same "
             "quadrature (outer variable: VrlPoint's CDF, broken at VrlMarginal's nodes).")
    L.append("")
    L.append("![speed against accuracy](figures/speed_accuracy.png)\n")
    L.append("![efficiency against g](figures/efficiency.png)\n")
    table = "\n".join(L) + "\n"
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(table)

    def chart(name, suptitle, xlabel, ylabel, draw):
        """One panel per step; draw(ax, step, prefix, sampler, colour, marker) plots a sampler."""
        fig, axes = plt.subplots(1, len(steps), figsize=(6 * len(steps), 5))
        for ax, (step, prefix, title) in zip(axes, steps):
            for s in samplers:
                draw(ax, step, prefix, s, *styles[s])
            ax.set_yscale("log")
            ax.set_xlabel(xlabel)
            ax.set_ylabel(ylabel)
            ax.set_title(title)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
        fig.suptitle(suptitle)
        fig.tight_layout()
        for ext in ("png", "svg"):
            fig.savefig(os.path.join(args.out, f"{name}.{ext}"), dpi=130)
        plt.close(fig)

    def speed_accuracy(ax, step, prefix, s, colour, marker):
        xs = [time(prefix, s, g) for g in gs]
        ys = [relvar[step][(g, s)]["mean"] for g in gs]
        ax.scatter(xs, ys, color=colour, marker=marker, label=s, s=36, alpha=0.85)
        for x, y, g in zip(xs, ys, gs):
            ax.annotate(f"{g:g}", (x, y), textcoords="offset points", xytext=(4, 2), fontsize=6, color=colour)
        ax.set_xscale("log")

    def efficiency(ax, step, prefix, s, colour, marker):
        ax.plot(gs, [eff[(step, g, s)] for g in gs], color=colour, marker=marker, label=s)

    chart("speed_accuracy", "Speed against accuracy (labels: g); lower left is better", "time per sample (ns, float)",
          "mean relative variance", speed_accuracy)
    chart("efficiency", "Efficiency (higher is better)", "Henyey-Greenstein g",
          "efficiency 1 / (relative variance x time)  [1/s]", efficiency)
    print(table)


if __name__ == "__main__":
    main()
