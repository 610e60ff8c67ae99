#!/usr/bin/env python3
"""The samplers as every chart, table and script shows them: the library's registry
(include/vrlis/method.hpp) with the samplers' roles in the lab (bench/sampler_roles.hpp),
read through the lab's `vrlis_samplers`, so that no script names a sampler. Shared by
bench/plot.py, bench/accuracy_scenes.py, bench/compare/plot.py, bench/compare/thesis.py,
bench/compare/effort.py and tools/speed.sh.

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
    """{"segment": [entry...], "vrl": [entry...]}, each entry {name, own, policy, thesis, baseline}."""
    build = build or os.environ.get("VRLIS_BUILD", os.path.join(_ROOT, "build"))
    listing = subprocess.run([os.path.join(build, "bench", "vrlis_samplers")], check=True,
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
    return [e["name"] for e in registry()["segment"] if e["thesis"]]


def baseline():
    """The sampler every efficiency ratio is to."""
    return next(e["name"] for e in registry()["segment"] if e["baseline"])


def label(name):
    """The label of a registry name, as the library spells its types ("full-product" -> "FullProduct")."""
    return "".join(word[:1].upper() + word[1:] for word in name.split("-"))


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
