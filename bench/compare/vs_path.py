#!/usr/bin/env python3
"""The VRL renderer against its own path tracer at equal time (tools/vs_path.sh).

Renders every scene with a medium and surfaces twice per seed pair with `vrl_render` (its
defaults) and with `--integrator path`, each for the same wall time on one thread, and
estimates each integrator's per-pixel variance at that time from the pairs' differences
(RMSE^2 / 2 of the second render against the first, pooled over pairs). Efficiency of the VRL
renderer over the path tracer = variance of the path tracer / variance of the VRL renderer;
its 95% interval from the pairs' spread (delta method on the log ratio).

  vs_path.py VRL_RENDER OUT_DIR [--scenes a,b] [--seconds S] [--pairs P] [--size N] [--markdown FILE]
             [--vrl-args "--vrl-bound scene ..."]   (further arguments of the VRL renders)
"""
import argparse
import json
import math
import statistics
import subprocess
import sys
from pathlib import Path

SCENES = ("room", "cube", "corner", "cloud", "fog")


def render(binary, scene, integrator, seed, args, out, reference=None):
    cmd = [binary, "--scene", scene, "--integrator", integrator, "--seed", str(seed), "--threads", "1", "--quiet",
           "--json", "--width", str(args.size), "--height", str(args.size), "--time", str(args.seconds),
           "--out", str(out)] + (["--reference", str(reference)] if reference else [])
    if integrator == "vrl":
        cmd += args.vrl_args.split()
    return json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("vrl_render")
    ap.add_argument("out", type=Path)
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--seconds", type=float, default=4)
    ap.add_argument("--pairs", type=int, default=4)
    ap.add_argument("--size", type=int, default=48)
    ap.add_argument("--markdown", type=Path)
    ap.add_argument("--vrl-args", default="")
    args = ap.parse_args()
    if args.pairs < 2 or args.seconds <= 0 or args.size < 1:
        sys.exit("vs_path.py: --pairs >= 2, --seconds > 0 and --size >= 1")
    args.out.mkdir(parents=True, exist_ok=True)
    rows = []
    for scene in args.scenes.split(","):
        per = {"vrl": [], "path": []}
        bounds, passes = [], {"vrl": [], "path": []}
        for k in range(args.pairs):
            # The two integrators alternate, so that the machine's load falls on both alike; the
            # second render of a pair reports its RMSE against the first: 2 x the variance.
            for seed in (2 * k + 1, 2 * k + 2):
                for integrator in ("vrl", "path"):
                    first = args.out / f"{scene}_{integrator}_{2 * k + 1}.exr"
                    exr = args.out / f"{scene}_{integrator}_{seed}.exr"
                    s = render(args.vrl_render, scene, integrator, seed, args, exr, first if seed != 2 * k + 1 else None)
                    passes[integrator].append(s["passes"])
                    if integrator == "vrl":
                        b = s["vrl_bound"]
                        bounds.append(b if isinstance(b, str) else f"{b:g}")
                    if "rmse" in s:
                        per[integrator].append(s["rmse"] ** 2 / 2)
        mv, mp = statistics.fmean(per["vrl"]), statistics.fmean(per["path"])
        ratio = mp / mv
        se = math.sqrt(statistics.variance(per["vrl"]) / (args.pairs * mv * mv)
                       + statistics.variance(per["path"]) / (args.pairs * mp * mp))
        rows.append({"scene": scene, "ratio": ratio, "low": ratio * math.exp(-1.96 * se),
                     "high": ratio * math.exp(1.96 * se), "bounds": sorted(set(bounds)),
                     "passes_vrl": statistics.median(passes["vrl"]), "passes_path": statistics.median(passes["path"])})
        print(f"{scene:8s} VRL / path {ratio:6.2f} ({rows[-1]['low']:.2f}-{rows[-1]['high']:.2f})  "
              f"bound {','.join(rows[-1]['bounds'])}  passes {rows[-1]['passes_vrl']:.0f} vs {rows[-1]['passes_path']:.0f}",
              flush=True)
    (args.out / "vs_path.json").write_text(json.dumps(rows, indent=1) + "\n")
    if args.markdown:
        ratios = sorted(r["ratio"] for r in rows)
        lines = ["| scene | VRL renderer / path tracer (95% interval) | VRL bound chosen | passes, VRL / path |",
                 "|---|---|---|---|"]
        for r in rows:
            lines.append(f"| {r['scene']} | {r['ratio']:.2f} ({r['low']:.2f}-{r['high']:.2f}) | {', '.join(r['bounds'])} "
                         f"| {r['passes_vrl']:.0f} / {r['passes_path']:.0f} |")
        lines.append(f"\nMedian over the scenes: {statistics.median(ratios):.2f}.")
        args.markdown.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
