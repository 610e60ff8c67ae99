#!/usr/bin/python3
"""Charts and pages for vrl_compare's output.

Study mode (default): an efficiency chart (efficiency / Novak's with 95% intervals, one
panel per scene), per study an image strip (the reference and every sampler after the same
passes), and the RMSE-against-time chart of bidirectional g = -0.9 (every study with
--rmse-all). With --publish DIR, also copies them into DIR and writes DIR/results.md (date,
machine, command, table, what each study resolved) and the README's table; for a VRL-only
study (vrl_compare --vrl-only), DIR/vrl_only.md, DIR/thesis_claims.md (thesis.py) and the
README's sentence on the thesis's claims instead. With --readme-from docs/compare/results.md
(from the repository root), only the README's table again, from the published page.

Decompose mode (--decompose): per scene, a stacked bar chart of the shares of per-pass
variance and of time per part of transport, and of the medium-to-medium gather's variance
between the light paths and pixel, step one and step two; with --publish DIR, writes
DIR/decomposition.md with the tables and, per scene, which term a better sampler would
have to improve."""
import argparse
import datetime
import json
import os
import platform
import re
import shutil
import subprocess
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker as ticker  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from samplers import label, style  # noqa: E402
import thesis  # noqa: E402

PART_COLOURS = {
    "medium-to-medium": "tab:blue",
    "medium-to-surface": "tab:orange",
    "single scattering": "tab:purple",
    "direct": "tab:olive",
    "surface-to-surface": "tab:brown",
    "surface-to-medium": "tab:pink",
    "remainder": "tab:gray",
    "light paths, camera rays": "lightgray",
    "light paths and pixel": "lightsteelblue",
    "step one (VRL point)": "tab:cyan",
    "step two (camera sampler)": "midnightblue",
}


def load(path):
    with open(path) as f:
        return json.load(f)


def machine():
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        model = next(line.split(":", 1)[1].strip() for line in out.splitlines() if line.startswith("Model name"))
    except (OSError, StopIteration):
        model = platform.processor() or "unknown CPU"
    return f"{model}, {os.cpu_count()} cores, {platform.system()} {platform.release()}"


def provenance(command):
    return f"Generated {datetime.date.today().isoformat()} on {machine()} by `{command}`."


def save(fig, folder, name, svg=True):
    fig.tight_layout()
    for ext in ("png", "svg") if svg else ("png",):
        fig.savefig(os.path.join(folder, f"{name}.{ext}"), dpi=120)
    plt.close(fig)


# ---------------------------------------------------------------- the equal-time study


def plot_efficiency(results, folder):
    """One panel per scene: efficiency / Novak's against g, one offset column per sampler."""
    scenes = list(dict.fromkeys(r["scene"] for r in results))
    cols = min(3, len(scenes))
    rows = (len(scenes) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.6 * cols, 3.8 * rows), squeeze=False)
    for ax in axes.flat[len(scenes):]:
        ax.axis("off")
    for ax, scene in zip(axes.flat, scenes):
        studies = [r for r in results if r["scene"] == scene]
        gs = [r["g"] for r in studies]
        samplers = [s["sampler"] for s in studies[0]["samplers"]]
        for k, name in enumerate(samplers):
            colour, marker = style(name)
            xs, ys, lo, hi = [], [], [], []
            for i, r in enumerate(studies):
                s = next(s for s in r["samplers"] if s["sampler"] == name)
                ratio = s["to_baseline"]
                xs.append(i + (k - (len(samplers) - 1) / 2) * 0.13)
                ys.append(ratio["point"])
                lo.append(ratio["point"] - ratio["low"])
                hi.append(min(ratio["high"], 1e6) - ratio["point"])
                if s["verdict"] == "best":
                    ax.annotate("best", (xs[-1], ratio["high"]), fontsize=7, ha="center", va="bottom")
            ax.errorbar(xs, ys, yerr=[lo, hi], fmt=marker, color=colour, label=name, ms=4, capsize=2, lw=1)
        ax.axhline(1, color="black", lw=0.6)
        ax.set_yscale("log")
        low, high = ax.get_ylim()
        ax.set_ylim(max(low, 1e-2), min(high, 30))  # intervals wider than that run off the panel
        ax.yaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
        if ax.get_ylim()[1] / ax.get_ylim()[0] < 30:  # minor labels only where they do not crowd
            ax.yaxis.set_minor_formatter(ticker.FormatStrFormatter("%g"))
            ax.tick_params(axis="y", which="minor", labelsize=7)
        ax.set_xticks(range(len(gs)))
        ax.set_xticklabels([f"g = {g:g}" for g in gs], fontsize=8)
        ax.set_ylabel(f"efficiency / {label(studies[0]['baseline'])}'s (95% interval)")
        ax.set_title(scene)
        ax.grid(True, which="both", axis="y", alpha=0.3)
    axes.flat[0].legend(fontsize=7)
    fig.tight_layout()
    save(fig, folder, "efficiency")


def plot_strip(study_dir, result, name):
    samplers = result["samplers"]
    fig, axes = plt.subplots(1, len(samplers) + 1, figsize=(2 * (len(samplers) + 1), 2.5))
    panels = [("reference (mixture)", "reference.png", f"{result['reference']['passes']} passes")]
    panels += [(s["sampler"], s["sampler"] + ".png", f"x{s['to_baseline']['point']:.2f} {label(result['baseline'])}") for s in samplers]
    for ax, (title, image, caption) in zip(axes, panels):
        ax.imshow(mpimg.imread(os.path.join(study_dir, image)), interpolation="nearest")
        ax.set_title(title, fontsize=8)
        ax.set_xlabel(caption, fontsize=8)
        ax.set_xticks([])
        ax.set_yticks([])
    passes = samplers[0]["passes"]
    fig.suptitle(f"{result['scene']}, g = {result['g']:g}: {passes} passes each (efficiency under each)", fontsize=9)
    save(fig, study_dir, f"{name}_strip", svg=False)


def publish_study(out, names, results, folder, command, vrl_only):
    """The whole-image study publishes results.md and the README's table; the VRL-only one
    (--vrl-only) publishes vrl_only.md beside it, thesis_claims.md, the RMSE-against-time
    chart and the README's sentence on the thesis's claims."""
    os.makedirs(folder, exist_ok=True)
    suffix = "_vrl" if vrl_only else ""
    for ext in ("png", "svg"):
        shutil.copy(os.path.join(out, f"efficiency.{ext}"), os.path.join(folder, f"efficiency{suffix}.{ext}"))
    with open(os.path.join(out, "summary.md")) as f:
        table = f.read()
    with open(os.path.join(out, "resolution.txt")) as f:
        resolution = f.read()
    r0 = results[0]
    what = ("the image of the two VRL gathers alone (medium-to-medium and medium-to-surface; no direct light, "
            "single scattering or path-traced remainder), with its own reference; the whole-image study is "
            "[results.md](results.md), the thesis's claims on this one [thesis_claims.md](thesis_claims.md)"
            if vrl_only else "whole images; the VRL gathers alone: [vrl_only.md](vrl_only.md)")
    lines = [
        "# Equal-time study, VRL gathers only: results" if vrl_only else "# Equal-time study: results",
        "",
        provenance(command),
        "",
        f"{r0['width']}x{r0['height']} pixels, {r0['vrls']} light paths per pass, {r0['replicates']} replicates "
        f"per study, at least {r0['budget']:g} s of passes per sampler; seed {r0['seed']}; {what}. How the "
        "numbers are made and how to read them: [README.md](README.md).",
        "",
        f"![efficiency](efficiency{suffix}.png)",
        "",
        table,
        "What each study could resolve:",
        "",
        "```",
        resolution.rstrip(),
        "```",
        "",
        "## Images after the same passes",
        "",
    ]
    for name in names:
        shutil.copy(os.path.join(out, name, name + "_strip.png"), os.path.join(folder, f"{name}{suffix}_strip.png"))
        lines += [f"![{name}]({name}{suffix}_strip.png)", ""]
    with open(os.path.join(folder, "vrl_only.md" if vrl_only else "results.md"), "w") as f:
        f.write("\n".join(lines))
    if not vrl_only:
        update_readme(provenance(command), verdict_table(table))
        return
    page, sentence = thesis.claims_page(results, provenance(command), r0["margin"])
    with open(os.path.join(folder, "thesis_claims.md"), "w") as f:
        f.write(page)
    for name in names:
        if os.path.exists(os.path.join(out, name, "rmse_time.png")):
            for ext in ("png", "svg"):
                shutil.copy(os.path.join(out, name, f"rmse_time.{ext}"), os.path.join(folder, f"rmse_time_{name}.{ext}"))
    update_readme(provenance(command), sentence + "\n", marker="thesis-claims")


# The scenes' media in a few words (docs/scenes.md), for the README's table.
SCENE_MEDIA = {
    "bidirectional": "thin, double scattering",
    "room": "thin, beams",
    "cube": "bounded box, caustics",
    "corner": "dense, short segments",
    "cloud": "dense, multiple scattering",
    "fog": "thick, multiple scattering",
}


def table_rows(table):
    """The rows of the first markdown table in `table` (a list of cell lists, the header
    first); lines after it are ignored."""
    rows, started = [], False
    for line in table.splitlines():
        if line.startswith("|"):
            started = True
            if not line.startswith("|---"):
                rows.append([c.strip() for c in line.strip().strip("|").split("|")])
        elif started:
            break
    return rows


def verdict_table(table, results_link="docs/compare/results.md"):
    """The README's "which sampler when", from the study's summary table: a row per scene
    (with its medium in a few words), a column per g, each cell the sampler called best
    (bold), or the samplers in the tie, most efficient first (at most 3, then "…"); no
    intervals: those are in results_link."""
    rows = table_rows(table)
    head, rows = rows[0], rows[1:]
    col = {name: i for i, name in enumerate(head)}
    efficiency = next(name for name in head if name.startswith("efficiency"))

    def ratio(cell):
        try:
            return float(cell.split()[0])
        except (IndexError, ValueError):
            return 0.0

    scenes, gs, cells = [], [], {}
    for r in rows:
        scene, g = r[col["scene"]], r[col["g"]]
        scenes += [scene] if scene not in scenes else []
        gs += [g] if g not in gs else []
        if r[col["verdict"]] in ("best", "tie"):
            cells.setdefault((scene, g), []).append((r[col["verdict"]], r[col["sampler"]], ratio(r[col[efficiency]])))

    def cell(found):
        if not found:
            return "none"
        if len(found) == 1 and found[0][0] == "best":
            return f"**{found[0][1]}**"
        names = [name for _, name, _ in sorted(found, key=lambda f: -f[2])]
        return ", ".join(names[:3]) + (", …" if len(names) > 3 else "")

    lines = ["| scene (medium) | " + " | ".join(f"g = {g}" for g in gs) + " |", "|---|" + "---|" * len(gs)]
    for scene in scenes:
        name = f"{scene} ({SCENE_MEDIA[scene]})" if scene in SCENE_MEDIA else scene
        lines.append(f"| {name} | " + " | ".join(cell(cells.get((scene, g))) for g in gs) + " |")
    return "\n".join(lines) + (
        "\n\n**Bold**: best at equal time, else the tie, best first; "
        f"full table with intervals: [results]({results_link}).\n")


def wrap_prose(text, width=120):
    """Lines of prose longer than `width` wrapped at spaces outside code spans (tables and
    code left alone), so the README keeps its line length whatever a generator writes."""
    out, code = [], False
    for line in text.split("\n"):
        if line.startswith("```"):
            code = not code
        if code or line.startswith(("|", "```", "    ")) or len(line) <= width:
            out.append(line)
        else:
            glued = re.sub(r"`[^`]*`", lambda m: m.group(0).replace(" ", "\0"), line)
            out += [w.replace("\0", " ") for w in
                    textwrap.wrap(glued, width, break_long_words=False, break_on_hyphens=False)]
    return "\n".join(out)


# Where generated blocks the README does not hold live: the results page it links.
RESULTS_PAGE = os.path.join("docs", "results.md")


def rebase_links(text, source, target):
    """Relative markdown links written for a page in folder `source` rewritten for one in `target`."""
    if os.path.normpath(source or ".") == os.path.normpath(target or "."):
        return text

    def rebase(m):
        label, path, rest = m.group(1), m.group(2), m.group(3) or ""
        if not path or re.match(r"[a-z]+:", path) or path.startswith("/"):
            return m.group(0)
        new = os.path.relpath(os.path.join(source or ".", path), target or ".").replace(os.sep, "/")
        return f"[{new if label == path else label}]({new}{rest})"

    return re.sub(r"\[([^\]]*)\]\(([^)\s#]*)(#[^)\s]*)?\)", rebase, text)


def update_readme(provenance_line, text_block, marker="compare-summary", readme="README.md"):
    """Replaces the block between the markers with what was just measured (the verdicts, or
    the sentence on the thesis's claims or on the effort control), so that no page quotes a
    figure no command made; docs/compare/ keeps the whole tables. The block is the README's,
    or, where the README does not hold the markers, the results page's (RESULTS_PAGE beside
    the README; links written for the README are rebased). Long prose lines are wrapped."""
    begin, end = f"<!-- {marker} -->", f"<!-- /{marker} -->"
    folder = os.path.dirname(readme)
    for page in (readme, os.path.join(folder, RESULTS_PAGE)):
        if not os.path.exists(page):
            continue
        with open(page) as f:
            text = f.read()
        if begin not in text or end not in text:
            continue
        block = rebase_links(f"{begin}\n{provenance_line}\n\n{text_block}{end}", folder, os.path.dirname(page))
        text = text[: text.index(begin)] + wrap_prose(block) + text[text.index(end) + len(end):]
        with open(page, "w") as f:
            f.write(text)
        return


def readme_from(results_page):
    """The README's table again from a published results.md (its provenance line and its
    summary table), without rerunning the study."""
    with open(results_page) as f:
        text = f.read()
    provenance_line = next(line for line in text.splitlines() if line.startswith("Generated "))
    update_readme(provenance_line, verdict_table(text, os.path.relpath(results_page).replace(os.sep, "/")))


def study_main(args):
    names = load(os.path.join(args.out, "studies.json"))
    results = [load(os.path.join(args.out, name, "result.json")) for name in names]
    vrl_only = results[0].get("vrl_only", False)
    plot_efficiency(results, args.out)
    for name, result in zip(names, results):
        plot_strip(os.path.join(args.out, name), result, name)
        # The thesis's figure: the bidirectional scene at g = -0.9; every study with --rmse-all.
        if args.rmse_all or (result["scene"] == "bidirectional" and thesis.g_of(result) == -0.9):
            thesis.plot_rmse_time(result, os.path.join(args.out, name, "rmse_time.png"), style)
    if args.publish:
        publish_study(args.out, names, results, args.publish, args.command, vrl_only)


# ---------------------------------------------------------------- the noise decomposition


def shares(d):
    """Per scene: variance and time shares of the parts, and the gather's step split."""
    parts = d["parts"]
    var = {p["part"]: max(p["variance"]["value"], 0.0) for p in parts}
    time = {"light paths, camera rays": max(d["base_seconds"], 0.0)}
    time.update({p["part"]: max(p["seconds_per_pass"], 0.0) for p in parts})
    steps = d["steps"]
    gather = next((g for g in steps["gathers"] if g["sampler"] == d["sampler"]), None)
    split = {}
    if gather and gather["variance"]["value"] > 0:
        full = gather["variance"]["value"]
        split = {
            "light paths and pixel": max(steps["paths_and_pixel_variance"]["value"], 0.0) / full,
            "step one (VRL point)": max(steps["step_one"]["value"], 0.0) / full,
            "step two (camera sampler)": max(gather["step_two"]["value"], 0.0) / full,
        }
    return var, time, split


def plot_decomposition(d, folder):
    var, time, split = shares(d)
    bars = [("per-pass variance", var), ("time per pass", time)]
    if split:
        bars.append((f"m2m gather variance\n({d['sampler']}, {d['steps']['pixels']} pixels)", split))
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    seen = set()
    for i, (label, values) in enumerate(bars):
        total = sum(values.values()) or 1
        bottom = 0
        for part, value in values.items():
            share = value / total
            ax.bar(i, share, bottom=bottom, color=PART_COLOURS.get(part, "black"), width=0.6,
                   label=part if part not in seen else None, edgecolor="white", lw=0.5)
            if share > 0.06:
                ax.text(i, bottom + share / 2, f"{100 * share:.0f}%", ha="center", va="center", fontsize=7)
            seen.add(part)
            bottom += share
    ax.set_xticks(range(len(bars)))
    ax.set_xticklabels([b[0] for b in bars], fontsize=8)
    ax.set_ylabel("share")
    ax.set_ylim(0, 1)
    ax.set_title(f"{d['scene']}, g = {d['g']:g}: where the noise and the time go ({d['sampler']})", fontsize=9)
    ax.legend(fontsize=7, bbox_to_anchor=(1.02, 1), loc="upper left")
    save(fig, folder, f"decompose_{d['scene']}")


def pct(x):
    return f"{100 * x:.1f}%" if x >= 0.001 else "<0.1%"


def signed_pct(x):
    return f"{100 * x:.1f}%"


def decomposition_page(decs, command):
    lines = [
        "# Where the noise lives",
        "",
        provenance(command),
        "",
        "Per scene (its default `g`), the image's per-pass variance (mean over pixels and channels, from the "
        "passes themselves, +- one standard error from the spread of 8 independent batches) and the time per "
        "pass of each part of light transport, every part rendered alone with the same seeds; the "
        "single-scattering part is the difference of the direct renders with and without it. Then, inside the "
        "medium-to-medium gather on a subset of pixels (the first camera segment, rays jittered as rendered): "
        "its variance as rendered, with step two replaced by quadrature (the midpoint rule on FullProduct's "
        "warp of the camera segment), and with both steps by quadrature; by the law of total variance the "
        "differences are what step two and step one add. How this is measured and what follows from it: "
        "[README.md](README.md).",
        "",
    ]
    for d in decs:
        var, time, split = shares(d)
        total_var = d["total_variance"]["value"]
        part_sum = sum(var.values())
        time_sum = sum(time.values())
        lines += [f"## {d['scene']} (g = {d['g']:g})", "", f"![{d['scene']}](decompose_{d['scene']}.png)", ""]
        lines += ["| part | variance per pass | share | ms per pass | share |", "|---|---|---|---|---|"]
        for p in d["parts"]:
            v = p["variance"]
            lines.append(
                f"| {p['part']} | {v['value']:.3g} +- {v['se']:.2g} | {pct(var[p['part']] / part_sum) if part_sum else '-'} "
                f"| {1000 * p['seconds_per_pass']:.3g} | {pct(time[p['part']] / time_sum)} |"
            )
        lines.append(
            f"| light paths, camera rays | | | {1000 * d['base_seconds']:.3g} | {pct(time['light paths, camera rays'] / time_sum)} |"
        )
        lines.append(
            f"| whole image | {total_var:.3g} +- {d['total_variance']['se']:.2g} | parts' covariance "
            f"{total_var - part_sum:+.2g} | {1000 * d['total_seconds']:.3g} | |"
        )
        lines += ["", f"{d['passes']} passes per part, {d['sampler']} as the camera sampler.", ""]
        steps = d["steps"]
        if steps["gathers"] and steps["pixels"] > 0:
            v0, v1 = steps["paths_and_pixel_variance"], steps["step_one"]
            lines += [
                f"Medium-to-medium gather on {steps['pixels']} pixels, {steps['passes']} passes (variances per pass, "
                "+- one standard error; the shares are of each sampler's gather variance):",
                "",
                "| camera sampler | gather variance | step two adds | share | step one adds | share | light paths and pixel | share |",
                "|---|---|---|---|---|---|---|---|",
            ]
            for g in steps["gathers"]:
                full, two = g["variance"]["value"], g["step_two"]
                if full <= 0:
                    continue
                lines.append(
                    f"| {g['sampler']} | {full:.3g} +- {g['variance']['se']:.2g} | {two['value']:.3g} +- {two['se']:.2g} "
                    f"| {signed_pct(two['value'] / full)} | {v1['value']:.3g} +- {v1['se']:.2g} | {signed_pct(v1['value'] / full)} "
                    f"| {v0['value']:.3g} +- {v0['se']:.2g} | {signed_pct(v0['value'] / full)} |"
                )
            lines.append("")
        lines += [conclusion(d, var, time, split), ""]
    return "\n".join(lines)


def conclusion(d, var, time, split):
    """The scene's verdict in words: which term a better sampler would have to improve."""
    part_sum = sum(var.values()) or 1
    time_sum = sum(time.values()) or 1
    whole = d["total_variance"]["value"] or part_sum
    top = max(var, key=var.get)
    sampler_parts = ("medium-to-medium", "medium-to-surface", "single scattering")
    step_two = split.get("step two (camera sampler)", 0.0)
    reach = var.get("medium-to-medium", 0) * step_two + var.get("medium-to-surface", 0) + var.get("single scattering", 0)
    gather_time = sum(time.get(p, 0) for p in ("medium-to-medium", "medium-to-surface"))
    words = (
        f"**{d['scene']}**: {top} carries {pct(var[top] / part_sum)} of the per-pass variance. "
        f"The parts the camera sampler touches (the medium-to-medium gather's step two, the medium-to-surface "
        f"gather, single scattering) hold at most {pct(reach / part_sum)} of it ({pct(reach / whole)} of the whole "
        f"image's), and the two VRL gathers take "
        f"{pct(gather_time / time_sum)} of the time. "
    )
    if top in sampler_parts and (top != "medium-to-medium" or step_two >= 0.5):
        words += (
            f"A better camera sampler changes this image's noise: {top} is the term to improve"
            + (f" (step two is {pct(step_two)} of the gather's variance)." if top == "medium-to-medium" else ".")
        )
    elif top == "medium-to-medium":
        words += (
            f"Inside the gather, step one and the light paths hold {pct(1 - step_two)} of its variance: a better "
            "VRL point (step one) would do more than a better camera sampler."
        )
    else:
        words += (
            f"No camera sampler can change much of this image's noise ({top} is outside its reach); between "
            "samplers, the image changes mainly through their cost per gather."
        )
    return words


def decompose_main(args):
    folder = os.path.join(args.out, "decompose")
    decs = [load(os.path.join(folder, f"{scene}.json")) for scene in load(os.path.join(folder, "scenes.json"))]
    for d in decs:
        plot_decomposition(d, folder)
    page = decomposition_page(decs, args.command)
    with open(os.path.join(folder, "decomposition.md"), "w") as f:
        f.write(page)
    if args.publish:
        os.makedirs(args.publish, exist_ok=True)
        for d in decs:
            for ext in ("png", "svg"):
                shutil.copy(os.path.join(folder, f"decompose_{d['scene']}.{ext}"), args.publish)
        shutil.copy(os.path.join(folder, "decomposition.md"), args.publish)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", nargs="?", help="vrl_compare's output folder")
    parser.add_argument("--decompose", action="store_true", help="the noise decomposition (vrl_compare --decompose)")
    parser.add_argument("--publish", help="folder to copy the charts and pages into (docs/compare)")
    parser.add_argument("--command", default="tools/main.sh", help="the command that produced the output")
    parser.add_argument("--rmse-all", action="store_true",
                        help="an RMSE-against-time chart for every study (default: bidirectional at g = -0.9)")
    parser.add_argument("--readme-from", metavar="RESULTS_MD",
                        help="only rewrite the README's table from a published results.md (docs/compare/results.md); "
                             "run from the repository root")
    args = parser.parse_args()
    if args.readme_from:
        readme_from(args.readme_from)
        return 0
    if not args.out:
        parser.error("the output folder is required")
    (decompose_main if args.decompose else study_main)(args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
