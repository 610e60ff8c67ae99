#!/usr/bin/env python3
"""Fails when a number the README's prose quotes disagrees with the generated page it comes
from (docs/stability.md, docs/bench.md) or with the library's defaults (node counts).

Run by ctest (readme_numbers) and by hand: tools/check_readme_numbers.py [repository root].
Each check names the README sentence and the source value, so a regenerated table that moves
a number makes this fail until the prose is updated.
"""
import re
import sys
from pathlib import Path

root = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent)
readme = re.sub(r"\s+", " ", (root / "README.md").read_text())  # prose wraps anywhere
bench = (root / "docs/bench.md").read_text()
stability = (root / "docs/stability.md").read_text()
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def prose(pattern, text=readme, name="README.md"):
    m = re.search(pattern, text, re.S)
    if not m:
        failures.append(f"{name}: sentence not found: /{pattern}/")
    return m


def table(text, heading):
    """The Markdown table after `heading`: header cells and a dict from first cell to row cells."""
    lines = text[text.index(heading):].splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.startswith("|"))
    rows = []
    for ln in lines[start:]:
        if not ln.startswith("|"):
            break
        rows.append([c.strip() for c in ln.strip().strip("|").split("|")])
    header, body = rows[0], rows[2:]
    return header, {r[0]: r for r in body}


def near(quoted, actual, factor=1.25):
    """A '~' number: within the factor of the source value."""
    return actual / factor <= quoted <= actual * factor


# 1. Largest weights at g = 0.999 (docs/stability.md, double table).
header, rows = table(stability, "### Largest weight f / (pdf * integral), double")
cell = dict(zip(header, rows["g=+0.999"]))
weight = {k: float(cell[k].split()[0]) for k in ["equiangular", "novak", "cauchy-sum", "cauchy-mixture", "full-product"]}
m = prose(r"At `g = 0.999` the largest weight is ~(\S+) for\s+equiangular, ~(\S+) for both Cauchy samplers, "
          r"~(\S+) for Novák and ~(\S+) for FullProduct")
if m:
    eq, cauchy, novak, full = (float(x) for x in m.groups())
    check(near(eq, weight["equiangular"]), f"largest weight, equiangular: README ~{eq:g}, docs/stability.md {weight['equiangular']:g}")
    for k in ["cauchy-sum", "cauchy-mixture"]:
        check(near(cauchy, weight[k]), f"largest weight, {k}: README ~{cauchy:g}, docs/stability.md {weight[k]:g}")
    check(near(novak, weight["novak"]), f"largest weight, novak: README ~{novak:g}, docs/stability.md {weight['novak']:g}")
    check(near(full, weight["full-product"]), f"largest weight, full-product: README ~{full:g}, docs/stability.md {weight['full-product']:g}")

# 2. Where FullProduct has the lowest camera-step variance (docs/bench.md, mean relative variance).
header, rows = table(bench, "## Camera step (fixed VRL point)")
samplers = ["Equiangular", "Novak", "CauchySum", "CauchyMixture", "FullProduct"]
lowest_not_full = []
for g, r in rows.items():
    cells = dict(zip(header, r))
    mean = {s: float(cells[f"{s} median / mean"].split("/")[1]) for s in samplers}
    if min(mean, key=mean.get) != "FullProduct":
        lowest_not_full.append(g)
m = prose(r"`FullProduct` \(transmittance in the fit\) has the lowest (?:mean )?camera-step variance at every `g`"
          r"(?: except (?P<except>-?\d+(?:\.\d+)?(?:(?:, | and )-?\d+(?:\.\d+)?)*))?")
if m:
    quoted = re.findall(r"-?\d+(?:\.\d+)?", m.group("except") or "")
    check(sorted(map(float, quoted)) == sorted(map(float, lowest_not_full)),
          f"lowest camera-step variance: README exceptions {quoted}, docs/bench.md {lowest_not_full}")

# 3. The g range where FullProduct with VrlMarginal is the most efficient combination by more
#    than a tie (the README treats ratios within 20% as ties).
header, rows = table(bench, "## Whole estimator, either step one")
wins = []
for g, r in rows.items():
    best = dict(zip(header, r))["most efficient overall (margin)"]
    mm = re.match(r"\*\*(\S+)\*\* \(x([\d.]+) over", best)
    if mm and mm.group(1) == "FullProduct+M" and float(mm.group(2)) > 1.2:
        wins.append(float(g))
m = prose(r"most efficient combination\s+for `g` from (\S+) to (\S+);")
if m and wins:
    lo, hi = float(m.group(1)), float(m.group(2))
    check((lo, hi) == (min(wins), max(wins)),
          f"FullProduct+M most efficient: README g from {lo:g} to {hi:g}, docs/bench.md {min(wins):g} to {max(wins):g}")
    all_g = [float(g) for g in rows]
    inside = [g for g in all_g if min(wins) <= g <= max(wins)]
    check(inside == sorted(wins), f"FullProduct+M does not win at every g in its range: wins {wins}")

# 4. VrlMarginal's cost per sample.
m = prose(r"about ([\d.]+) us per sample")
vm = re.search(r"VrlMarginal alone \(fit \+ sample_pdf; (\d+) nodes.*?\): (\d+) ns", bench)
if m and vm:
    check(near(float(m.group(1)) * 1000, float(vm.group(2)), 1.15),
          f"VrlMarginal cost: README {m.group(1)} us, docs/bench.md {vm.group(2)} ns")

# 5. The speed goal.
# The README names the g where both Cauchy samplers meet it; docs/bench.md lists each one's.
m = prose(r"Our goal of a ratio below 0.35 is met (?:only at `g = (\S+)`|at no `g`) by CauchySum and by CauchyMixture")
goal = re.search(r"the 0.35 goal is met by CauchySum at g in \{([^}]*)\} and by CauchyMixture at g in \{([^}]*)\}", bench)
if m and goal:
    quoted = [m.group(1)] if m.group(1) else ["none"]
    for k, name in ((1, "CauchySum"), (2, "CauchyMixture")):
        check(quoted == [x.strip() for x in goal.group(k).split(",")],
              f"0.35 goal for {name}: README g = {quoted}, docs/bench.md {{{goal.group(k)}}}")

# 6. Node counts quoted anywhere against the defaults in the headers.
def default_nodes(header_path, alias):
    text = (root / header_path).read_text()
    mm = re.search(r"template <typename Real = float, int kNodes = (\d+)>\s*using " + alias, text)
    return int(mm.group(1)) if mm else None


novak_nodes = default_nodes("include/vrlis/samplers/novak.hpp", "Novak")
full_nodes = default_nodes("include/vrlis/samplers/full_product.hpp", "FullProduct")
marginal = re.search(r"template <typename R = float, int kNodes = (\d+)", (root / "include/vrlis/samplers/vrl_marginal.hpp").read_text())
check(novak_nodes is not None and full_nodes is not None and marginal is not None, "node defaults not found in the headers")
for text, name in [(readme, "README.md"), (bench, "docs/bench.md")]:
    for mm in re.finditer(r"Novák's piecewise-linear fit of the phase product \((\d+) nodes\)|`Novak<Real, Nodes = (\d+)>`", text):
        n = int(mm.group(1) or mm.group(2))
        check(n == novak_nodes, f"{name}: Novak with {n} nodes, novak.hpp {novak_nodes}")
    for mm in re.finditer(r"FullProduct[^.\n]{0,120}?(\d+) nodes|`FullProduct<Real, Nodes = (\d+)>`", text):
        n = int(mm.group(1) or mm.group(2))
        check(n == full_nodes, f"{name}: FullProduct with {n} nodes, full_product.hpp {full_nodes}")
if vm and marginal:
    check(int(vm.group(1)) == int(marginal.group(1)), f"docs/bench.md: VrlMarginal {vm.group(1)} nodes, vrl_marginal.hpp {marginal.group(1)}")

for f in failures:
    print(f"README numbers: {f}", file=sys.stderr)
print(f"README numbers: {len(failures)} disagreement(s)")
sys.exit(1 if failures else 0)
