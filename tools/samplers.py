#!/usr/bin/env python3
"""The samplers as every chart, table and script shows them: names, labels and properties
read from the library's registry (include/vrlis/method.hpp) through
`vrl_render --list-samplers`, so that the registry stays the one table of samplers. Shared
by bench/plot.py, bench/accuracy_scenes.py, bench/compare/plot.py, tools/speed.sh and
tools/stability.sh.

    tools/samplers.py BUILD_DIR [--per-sample]
prints the segment samplers' names, one a line (--per-sample: without the policies, which
only the equal-time study judges).
"""
import functools
import json
import os
import subprocess
import sys

# Colours and markers in registry order: a sampler keeps its look while others are added.
_PALETTE = [("tab:gray", "o"), ("tab:blue", "s"), ("tab:orange", "^"), ("tab:red", "v"), ("tab:green", "D"),
            ("tab:brown", "P"), ("tab:purple", "X"), ("tab:pink", "*"), ("tab:olive", "h"), ("tab:cyan", "p")]
_ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


@functools.lru_cache(maxsize=None)
def registry(build=None):
    """{"segment": [entry...], "vrl": [entry...]}, each entry {name, label, own, policy, round_trip, thesis,
    baseline}."""
    build = build or os.environ.get("VRLIS_BUILD", os.path.join(_ROOT, "build"))
    listing = subprocess.run([os.path.join(build, "examples", "vrl_render"), "--list-samplers"], check=True,
                             capture_output=True, text=True).stdout
    return json.loads(listing)


def _segment():
    return {e["name"]: e for e in registry()["segment"]}


def own():
    """This project's samplers; the others are the published methods the README cites."""
    return {e["name"] for kind in ("segment", "vrl") for e in registry()[kind] if e["own"]}


def policies():
    """Samplers that choose among the others per query: judged by the equal-time study, left
    out of the per-sample speed and accuracy tables."""
    return {e["name"] for e in registry()["segment"] if e["policy"]}


def thesis():
    """The thesis's samplers, in registry order: the ones its claims are tested on."""
    return [e["name"] for e in registry()["segment"] if e.get("thesis")]  # (listings before the property: none)


def baseline():
    """The sampler every efficiency ratio is to."""
    found = [e["name"] for e in registry()["segment"] if e.get("baseline")]
    if not found:
        sys.exit("tools/samplers.py: the registry's listing marks no baseline (a build older than the property?)")
    return found[0]


def label(name):
    """The label of a registry name ("full-product" -> "FullProduct")."""
    entry = _segment().get(name) or {e["name"]: e for e in registry()["vrl"]}.get(name)
    return entry["label"] if entry else name


def style(name):
    """(colour, marker) of a sampler in every chart."""
    names = list(_segment())
    return _PALETTE[names.index(name) % len(_PALETTE)] if name in names else ("black", "x")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: tools/samplers.py BUILD_DIR [--per-sample]")
    for entry in registry(sys.argv[1])["segment"]:
        if "--per-sample" not in sys.argv or not entry["policy"]:
            print(entry["name"])
