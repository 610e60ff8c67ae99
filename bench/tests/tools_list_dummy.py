#!/usr/bin/env python3
"""A dummy sampler added to the registry, with roles in the lab, reaches every tool:
tools/samplers.py (what tools/speed.sh and the charts read), bench/plot.py's and
bench/accuracy_scenes.py's sampler sets, and the charts' styles, all from the listing alone.
Usage: tools_list_dummy.py ROOT DUMMY_LISTER"""
import os
import subprocess
import sys
import tempfile

root, lister = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as build:
    os.makedirs(os.path.join(build, "bench"))
    os.symlink(os.path.abspath(lister), os.path.join(build, "bench", "vrlis_samplers"))
    os.environ["VRLIS_BUILD"] = build
    sys.path.insert(0, os.path.join(root, "tools"))
    import samplers

    failures = []
    listed = subprocess.run([sys.executable, os.path.join(root, "tools", "samplers.py"), build, "--per-sample"],
                            check=True, capture_output=True, text=True).stdout.split()
    if "dummy-sampler" not in listed:
        failures.append(f"tools/samplers.py (tools/speed.sh's sampler list) does not list it: {listed}")
    if samplers.label("dummy-sampler") != "DummySampler":
        failures.append(f"label: {samplers.label('dummy-sampler')}")
    if "dummy-sampler" not in samplers.own():
        failures.append("not among this project's own samplers (bench/plot.py, bench/accuracy_scenes.py)")
    if "dummy-sampler" in samplers.policies():
        failures.append("listed as a policy")
    if samplers.style("dummy-sampler") == ("black", "x"):
        failures.append("no chart style of its own")
    if "dummy-sampler" not in samplers.thesis():
        failures.append("not among the thesis's samplers (bench/compare/thesis.py, bench/plot.py, tools/speed.sh)")
    if samplers.baseline() == "dummy-sampler":
        failures.append("taken for the baseline")
    # A control: the real registry's listing, where there is one, has no dummy (the check can fail).
    real = os.path.join(root, "build")
    if os.path.exists(os.path.join(real, "bench", "vrlis_samplers")):
        if "dummy-sampler" in [e["name"] for e in samplers.registry(real)["segment"]]:
            failures.append("the real registry lists the dummy")
for f in failures:
    print("FAIL:", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
