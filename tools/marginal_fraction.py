#!/usr/bin/env python3
"""Variance against time of VrlMarginal's fits given to a share of the gathers.

    /usr/bin/python3 tools/marginal_fraction.py SCENE G [--pairs N=3] [--spp N=16] [--size N=48]
        [--build DIR=build] METHOD[:FRACTION] ...

Renders SCENE's medium-to-medium gathers (vrl_render --gather m2m --effort off, one thread,
pinned to CPU 1 when taskset exists) with each METHOD and --marginal-fraction FRACTION (default
1), in pairs of seeds: the RMSE of seed 2k against seed 2k - 1 (--reference) squared over two
is an estimate of the image's per-pixel variance. Prints, per method, that variance, the median
render time, and both over the first method's, with the efficiency 1 / (variance x time).
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile


def render(args, method, fraction, seed, out, reference=None):
    cmd = [os.path.join(args.build, "examples", "vrl_render"), "--scene", args.scene, "--g", str(args.g),
           "--gather", "m2m", "--sampler", method, "--marginal-fraction", str(fraction), "--effort", "off",
           "--threads", "1", "--spp", str(args.spp), "--width", str(args.size), "--height", str(args.size),
           "--seed", str(seed), "--json", "--out", out]
    if reference:
        cmd += ["--reference", reference]
    if shutil.which("taskset"):
        cmd = ["taskset", "-c", "1"] + cmd
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"marginal_fraction.py: {' '.join(cmd)} failed: {run.stderr.strip()}")
    return json.loads(run.stdout)


def measure(args, method, fraction, work):
    variances, times = [], []
    for k in range(args.pairs):
        first = os.path.join(work, f"a{k}")
        a = render(args, method, fraction, 2 * k + 1, first)
        b = render(args, method, fraction, 2 * k + 2, os.path.join(work, f"b{k}"), reference=first + ".exr")
        variances.append(b["rmse"] ** 2 / 2)
        times += [a["render_time_s"], b["render_time_s"]]
    return statistics.mean(variances), statistics.median(times)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene")
    p.add_argument("g", type=float)
    p.add_argument("methods", nargs="+", help="METHOD[:FRACTION], e.g. novak full-product+marginal:0.2")
    p.add_argument("--pairs", type=int, default=3)
    p.add_argument("--spp", type=int, default=16)
    p.add_argument("--size", type=int, default=48)
    p.add_argument("--build", default="build")
    args = p.parse_args()
    if args.pairs < 1 or args.spp < 1 or args.size < 1:
        sys.exit("marginal_fraction.py: --pairs, --spp and --size must be positive")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for m in args.methods:
            method, _, fraction = m.partition(":")
            fraction = float(fraction) if fraction else 1.0
            rows.append((m, *measure(args, method, fraction, work)))
    base_var, base_time = rows[0][1], rows[0][2]
    print(f"| {args.scene}, g {args.g} | variance | seconds | variance / first | time / first | efficiency / first |")
    print("|---|---|---|---|---|---|")
    for name, var, time in rows:
        print(f"| {name} | {var:.3g} | {time:.3f} | {var / base_var:.2f} | {time / base_time:.2f} | "
              f"{base_var * base_time / (var * time):.2f} |")


if __name__ == "__main__":
    main()
