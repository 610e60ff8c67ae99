#!/usr/bin/python3
"""Charts for vrl_compare's output: for every study, RMSE against wall time (log-log, one line
per sampler) and an equal-time image strip with each sampler's RMSE under its image.
With --publish DIR, also copies the charts and the summary table into DIR and writes
DIR/README.md stating the date, the machine and the command."""
import argparse
import csv
import datetime
import json
import os
import platform
import shutil
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {
    "equiangular": ("tab:gray", "o"),
    "novak": ("tab:blue", "s"),
    "cauchy-sum": ("tab:orange", "^"),
    "cauchy-mixture": ("tab:red", "v"),
    "full-product": ("tab:green", "D"),
}


def read_curves(study_dir):
    curves = {}
    with open(os.path.join(study_dir, "curve.csv")) as f:
        for row in csv.DictReader(f):
            c = curves.setdefault(row["method"], ([], []))
            c[0].append(float(row["seconds"]) * 1000)
            c[1].append(float(row["rmse"]))
    return curves


def plot_curves(study_dir, result, name):
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for method, (ms, rmse) in read_curves(study_dir).items():
        color, marker = STYLE.get(method, ("black", "x"))
        ax.loglog(ms, [max(r, 1e-12) for r in rmse], color=color, label=method, marker=marker, markevery=0.2, ms=4)
    ax.set_xlabel("wall time per sampler (ms)")
    ax.set_ylabel("RMSE (reference noise subtracted)")
    ax.set_title(f"{result['scene']}, g = {result['g']:g}, {result['width']}x{result['height']}")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(study_dir, f"{name}_rmse.{ext}"), dpi=120)
    plt.close(fig)


def plot_strip(study_dir, result, name):
    methods = result["methods"]
    fig, axes = plt.subplots(1, len(methods) + 1, figsize=(2 * (len(methods) + 1), 2.5))
    panels = [("reference", "reference.png", "")] + [
        (m["method"], m["method"] + ".png", f"RMSE {m['rmse_at_budget']:.3g}") for m in methods
    ]
    for ax, (title, image, caption) in zip(axes, panels):
        ax.imshow(mpimg.imread(os.path.join(study_dir, image)), interpolation="nearest")
        ax.set_title(title, fontsize=8)
        ax.set_xlabel(caption, fontsize=8)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.suptitle(f"{result['scene']}, g = {result['g']:g}: equal time, {result['budget']:g} s each", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(study_dir, f"{name}_strip.png"), dpi=120)
    plt.close(fig)


def machine():
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        model = next(line.split(":", 1)[1].strip() for line in out.splitlines() if line.startswith("Model name"))
    except (OSError, StopIteration):
        model = platform.processor() or "unknown CPU"
    return f"{model}, {os.cpu_count()} cores, {platform.system()} {platform.release()}"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("out", help="vrl_compare's output folder")
    parser.add_argument("--publish", help="folder to copy the charts and summary into")
    parser.add_argument("--command", default="tools/main.sh", help="the command that produced the output")
    args = parser.parse_args()
    with open(os.path.join(args.out, "studies.json")) as f:
        studies = json.load(f)
    for name in studies:
        study_dir = os.path.join(args.out, name)
        with open(os.path.join(study_dir, "result.json")) as f:
            result = json.load(f)
        plot_curves(study_dir, result, name)
        plot_strip(study_dir, result, name)
    if not args.publish:
        return 0
    os.makedirs(args.publish, exist_ok=True)
    lines = [
        "# Equal-time comparison",
        "",
        f"Generated {datetime.date.today().isoformat()} on {machine()} by `{args.command}`.",
        "",
    ]
    for name in studies:
        study_dir = os.path.join(args.out, name)
        for suffix in ("_rmse.png", "_rmse.svg", "_strip.png"):
            shutil.copy(os.path.join(study_dir, name + suffix), args.publish)
        lines += [f"## {name}", "", f"![{name} RMSE]({name}_rmse.png) ![{name} strip]({name}_strip.png)", ""]
    with open(os.path.join(args.out, "summary.md")) as f:
        lines += ["## Summary", "", f.read()]
    with open(os.path.join(args.publish, "README.md"), "w") as f:
        f.write("\n".join(lines))
    update_readme(lines[2], os.path.join(args.out, "summary.md"))
    return 0


def update_readme(provenance, summary_path, readme="README.md"):
    """Replaces the block between the compare-summary markers of the project README with the
    summary table just measured, so the README never quotes a table no command made."""
    begin, end = "<!-- compare-summary -->", "<!-- /compare-summary -->"
    if not os.path.exists(readme):
        return
    with open(readme) as f:
        text = f.read()
    if begin not in text or end not in text:
        return
    with open(summary_path) as f:
        table = f.read()
    block = f"{begin}\n{provenance}\n\n{table}{end}"
    text = text[: text.index(begin)] + block + text[text.index(end) + len(end):]
    with open(readme, "w") as f:
        f.write(text)


if __name__ == "__main__":
    sys.exit(main())
