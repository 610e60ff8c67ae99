#!/usr/bin/env bash
# Speed of one commit against another, measured as ratios in one run: both commits are
# exported (git archive), built alike (Release, the lab and the renderer, the same flags),
# and their binaries are interleaved run by run (a shared machine slows both alike); each
# cell is the median of the repetitions.
#
#   tools/speed.sh BASE NEW [outdir=out/speed]      e.g. tools/speed.sh main~20 HEAD
#
# Prints (and writes to <outdir>/speed.md):
# - vrl_render VRL gathers per second, per scene x sampler x commit, on 1 and 2 threads, and
#   the 2-thread speedup;
# - vrlis_bench's camera step per sample (fit + sample + pdf), per sampler x g x commit, and
#   the ratios of the thesis's samplers to the baseline (Novák's), both as NEW's lab lists them
#   (vrlis_samplers, so NEW is a commit that has it);
# - step one per sample (VrlPoint, VrlMarginal) in both commits;
# - NEW's camera step on each scene's own queries (SceneCamera/, from vrl_render --dump-queries)
#   and the cost of one gather.
# A row either commit has no benchmark (or sampler) for is listed as not compared; the
# benchmarks of an old commit are timed as that commit wrote them, on its own query pool.
# Environment: VRLIS_SPEED_REPS (5), VRLIS_SPEED_SCENES (bidirectional cube),
# VRLIS_SPEED_SAMPLERS (default: NEW's registry, policies left out), VRLIS_SPEED_SIZE (128:
# image side), VRLIS_SPEED_SPP (4; at 64 x 64 x 2 a 2-thread render lasts 0.09 s and thread
# start-up and the last rows' imbalance held its speedup to 1.7-1.9, against 1.95-2.0 here),
# VRLIS_SPEED_PIN (a CPU number: single-threaded runs are pinned to it with taskset; on a
# shared machine whose cores are unequally loaded this keeps a run from migrating between them),
# VRLIS_SPEED_CXXFLAGS (compiler flags for both builds, e.g. -march=x86-64-v3: the same for
# both, so that the ratios compare code, not flags; the results then go to
# docs/speed-<flags>.md, and docs/bench.md keeps the default build's).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 2 ]; then
  echo "usage: tools/speed.sh BASE NEW [outdir=out/speed]  (two commits)" >&2
  exit 2
fi
base_ref=$(git rev-parse --short "$1^{commit}")
new_ref=$(git rev-parse --short "$2^{commit}")
out=${3:-out/speed}
reps=${VRLIS_SPEED_REPS:-5}
scenes=${VRLIS_SPEED_SCENES:-bidirectional cube}
size=${VRLIS_SPEED_SIZE:-128}
spp=${VRLIS_SPEED_SPP:-4}
mkdir -p "$out/runs"
pin=()
[ -z "${VRLIS_SPEED_PIN:-}" ] || pin=(taskset -c "$VRLIS_SPEED_PIN")
# The other CPU: single-threaded renders run on it too, so that the 2-thread speedup is taken
# over the mean of both CPUs' single-thread rates (on a VM one CPU can be much slower for minutes).
other=()
[ -z "${VRLIS_SPEED_PIN:-}" ] || other=(taskset -c "$(( (VRLIS_SPEED_PIN + 1) % $(nproc) ))")

tools/deps.sh
build_commit() {  # commit, build dir, [more targets]: the commit's renderer and benchmarks, built alike
  rm -rf "$2-src" && mkdir -p "$2-src"
  git archive "$1" | tar -x -C "$2-src"
  cmake -S "$2-src" -B "$2" -G Ninja -DCMAKE_BUILD_TYPE=Release -DVRLIS_BUILD_TESTS=OFF -DVRLIS_BUILD_BENCH=ON \
    -DVRLIS_BUILD_EXAMPLES=ON "-DCMAKE_CXX_FLAGS=${VRLIS_SPEED_CXXFLAGS:-}" >/dev/null
  cmake --build "$2" --target vrl_render vrlis_bench "${@:3}" -j"$(nproc)" >/dev/null
}
base="$out/base"
new="$out/new"
build_commit "$base_ref" "$base"
build_commit "$new_ref" "$new" vrlis_samplers  # the sampler list (tools/samplers.py), NEW's alone
# The samplers: NEW's registry and their roles in the lab (vrlis_samplers), policies left out.
samplers=${VRLIS_SPEED_SAMPLERS:-$(/usr/bin/python3 tools/samplers.py "$new" --per-sample | tr '\n' ' ')}
baseline=$(VRLIS_BUILD="$new" /usr/bin/python3 -c 'import sys; sys.path.insert(0, "tools"); import samplers; print(samplers.baseline())')
# Profiled: the baseline where the medium-to-medium gathers are all (bidirectional), and the
# registry's first sampler (equiangular, the cost floor) where Embree and medium-to-surface
# gathers take most of the time (cube).
set -- $samplers
profiled="bidirectional:$baseline cube:$1"

# Per build, the flags under which both render the same transport: every gather taken once
# where the build has the effort control, and without VPL gathers in a build that has them
# against one that has none (their time is no VRL gather's; the cube's passes took 1.2 times as
# long with them).
has_option() { grep -q -- "$2" <<< "$("$1/examples/vrl_render" --help)"; }
declare -A same
for build in base new; do
  dir=$([ "$build" = base ] && echo "$base" || echo "$new")
  flags=()
  ! has_option "$dir" --effort || flags+=(--effort off)
  if has_option "$dir" --vpl-bound && ! has_option "$base" --vpl-bound; then flags+=(--vpl-bound 0); fi
  same[$build]="${flags[*]}"
done

echo "== vrl_render: $reps rounds, builds interleaved (${size}x${size}, $spp passes)"
for rep in $(seq "$reps"); do
  for scene in $scenes; do
    for sampler in $samplers; do
      for threads in 1 1b 2; do  # 1b: one thread on the other CPU
        [ "$threads" != 1b ] || [ ${#other[@]} -gt 0 ] || continue
        for build in base new; do
          dir=$([ "$build" = base ] && echo "$base" || echo "$new")
          stem="$out/runs/${scene}_${sampler}_${threads}_${build}_$rep"
          run=("$dir/examples/vrl_render")
          read -r -a once <<< "${same[$build]}"
          [ "$threads" != 1 ] || run=("${pin[@]}" "${run[@]}")
          [ "$threads" != 1b ] || run=("${other[@]}" "${run[@]}")
          "${run[@]}" --scene "$scene" --sampler "$sampler" --threads "${threads%b}" --width "$size" \
            --height "$size" --spp "$spp" "${once[@]}" --quiet --out "$stem" >/dev/null 2>&1 || true  # absent: not compared
        done
      done
    done
  done
  echo "   round $rep done"
done

echo "== vrlis_bench Gather/*, SurfaceGatherBatch/*, GatherPart/*, Fit/*, Camera/*: this tree only (the parts in one run)"
"${pin[@]}" "$new/bench/vrlis_bench" --benchmark_filter='^(Surface)?Gather|^(Fit|Camera)/.*g:(-0.90|0.50|0.90)$' --benchmark_min_time=0.1 \
  --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/runs/parts.json" --benchmark_out_format=json >/dev/null
if command -v perf >/dev/null; then
  # bidirectional: medium-to-medium gathers only; cube: mostly medium-to-surface ones, and Embree.
  for run in $profiled; do
    set -- ${run/:/ }
    echo "== perf profile of vrl_render ($1, $2, 1 thread)"
    perf record -q -o "$out/runs/perf_$1.data" "$new/examples/vrl_render" --scene "$1" --sampler "$2" --effort off --threads 1 \
      --width "$size" --height "$size" --spp "$((4 * spp))" --quiet --out "$out/runs/perf_$1" >/dev/null 2>&1 || true
    { perf report -q -i "$out/runs/perf_$1.data" --no-children --sort dso --stdio 2>/dev/null | grep -E '^ +[0-9]' | head -4
      echo
      perf report -q -i "$out/runs/perf_$1.data" --no-children --sort symbol --stdio 2>/dev/null | grep -E '^ +[0-9]' |
        grep -v ' 0x0' | head -12; } | sed -E 's/[ -]+$//' >"$out/runs/perf_$1.txt" || true
  done
fi

echo "== vrlis_bench SceneCamera/*: the camera step on each scene's own queries (this tree)"
for scene in $scenes; do
  "$new/examples/vrl_render" --scene "$scene" --sampler "$baseline" --effort off --threads 1 --width "$size" --height "$size" --spp "$spp" \
    --quiet --dump-queries "$out/runs/$scene.qlog" --dump-every 20 --out "$out/runs/${scene}_queries" >/dev/null
  "${pin[@]}" "$new/bench/vrlis_bench" --vrlis_queries="$out/runs/$scene.qlog" --benchmark_filter='^SceneCamera/' \
    --benchmark_min_time=0.1 --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
    --benchmark_out="$out/runs/scene_$scene.json" --benchmark_out_format=json >/dev/null
done

echo "== vrlis_bench Camera/*: $reps rounds, builds interleaved"
for rep in $(seq "$reps"); do
  for build in base new; do
    dir=$([ "$build" = base ] && echo "$base" || echo "$new")
    "${pin[@]}" "$dir/bench/vrlis_bench" --benchmark_filter='^Camera(Separate)?/|^VrlPoint|^VrlMarginalBounded/' --benchmark_min_time=0.05 \
      --benchmark_out="$out/runs/bench_${build}_$rep.json" --benchmark_out_format=json >/dev/null
  done
done

VRLIS_BUILD="$new" /usr/bin/python3 - "$out" "$reps" "$scenes" "$samplers" "$profiled" <<'EOF' | tee "$out/speed.md"
import json, math, os, statistics, sys
out, reps, scenes, samplers = sys.argv[1], int(sys.argv[2]), sys.argv[3].split(), sys.argv[4].split()
profiled = [run.split(":") for run in sys.argv[5].split()]
missing = set()  # what one of the commits has no benchmark or sampler for
def median(b):  # the median of the repetitions; with one repetition, Google Benchmark writes the run alone
    return b.get("aggregate_name") == "median" or (reps == 1 and b.get("run_type") != "aggregate")
def gps(scene, sampler, threads, build):
    try:
        return statistics.median(json.load(open(f"{out}/runs/{scene}_{sampler}_{threads}_{build}_{r}.json"))["gathers_per_second"]
                                 for r in range(1, reps + 1))
    except OSError:
        missing.add(f"vrl_render --sampler {sampler} ({build})")
        return math.nan
both = os.path.exists(f"{out}/runs/{scenes[0]}_{samplers[0]}_1b_new_1.json")  # 1T runs on both CPUs
print(f"VRL gathers per second (median of {reps} interleaved runs; M = 1e6; 1T pinned to one CPU"
      + ("; the speedup is 2T over the mean of the 1T rates on either CPU" if both else "")
      + "; every gather taken once, and a build with VPL gathers without them against one that has none)\n")
print("| scene | sampler | base 1T | new 1T | new / base 1T | base 2T | new 2T | new / base 2T | speedup 2T base | speedup 2T new |")
print("|---|---|---|---|---|---|---|---|---|---|")
def one_thread(scene, s, b):
    return (gps(scene, s, "1", b) + gps(scene, s, "1b", b)) / 2 if both else gps(scene, s, "1", b)
for scene in scenes:
    for s in samplers:
        b1, n1, b2, n2 = (gps(scene, s, t, b) for t, b in (("1", "base"), ("1", "new"), ("2", "base"), ("2", "new")))
        print(f"| {scene} | {s} | {b1/1e6:.2f} M | {n1/1e6:.2f} M | **{n1/b1:.2f}** | {b2/1e6:.2f} M | {n2/1e6:.2f} M | "
              f"{n2/b2:.2f} | {b2/one_thread(scene, s, 'base'):.2f} | **{n2/one_thread(scene, s, 'new'):.2f}** |")
# Older commits name their benchmarks by class (Camera/CauchySum), newer ones by registry name
# (Camera/cauchy-sum): both are read under the registry name's label (tools/samplers.py).
sys.path.insert(0, "tools")
from samplers import baseline, label, thesis
def by_class(name):
    kind, sampler, rest = name.split("/", 2)
    return f"{kind}/{label(sampler) if sampler in samplers else sampler}/{rest}"
def load(path):
    runs = json.load(open(path))["benchmarks"]
    for b in runs:
        b["name"] = by_class(b["name"]) if b["name"].count("/") >= 2 else b["name"]
    return runs
times = {}
for build in ("base", "new"):
    runs = [load(f"{out}/runs/bench_{build}_{r}.json") for r in range(1, reps + 1)]
    for name in {b["name"] for b in runs[0]}:
        times[build, name] = statistics.median(b["cpu_time"] for run in runs for b in run if b["name"] == name)
names = sorted({n for _, n in times if ":" in n}, key=lambda n: (n.split("/")[1], float(n.split(":")[1])))
gs = sorted({float(n.split(":")[1]) for n in names})
cams = [label(s) for s in samplers]
base_cam, base_name = label(baseline()), baseline()  # every ratio is to the baseline (Novák's) ...
claimed = [label(s) for s in thesis()]  # ... and the thesis's samplers are the ones its claims are about
class Missing(float):
    """A time one commit has no benchmark for: printed as n/a, and listed below the tables."""
    def __new__(cls, what):
        missing.add(what)
        return super().__new__(cls, math.nan)
    def __format__(self, spec): return "n/a"
def get(build, name): return times.get((build, name)) or Missing(f"{name} ({build})")
def t(build, cam, g): return get(build, f"Camera/{cam}/g:{g:.2f}")
print(f"\nCamera step per sample, ns (fit + sample + pdf, float, as each commit's Camera/ benchmark times it; median of {reps} interleaved runs)\n")
print("| g | " + " | ".join(f"{c} base | {c} new" for c in cams) + " | "
      + " | ".join(f"{c}/{base_cam} {b}" for c in claimed for b in ("base", "new")) + " |")
print("|---|" + "---|" * (2 * len(cams) + 2 * len(claimed)))
def geo(xs): return math.exp(sum(map(math.log, xs)) / len(xs))
for g in gs:
    row = [f"{t(b, c, g):.0f}" for c in cams for b in ("base", "new")]
    ratios = [t(b, c, g) / t(b, base_cam, g) for c in claimed for b in ("base", "new")]
    print(f"| {g:g} | " + " | ".join(row) + " | " + " | ".join(f"{r:.2f}" for r in ratios) + " |")
# Step one alone on the line queries (VrlPointFromLine: VrlPoint without validating a whole
# gather query).
base_vp, new_vp = get("base", "VrlPointFromLine"), get("new", "VrlPointFromLine")
print(f"\nStep one per sample, ns (VrlPoint from the camera line, g = 0 pool; median of {reps} interleaved runs): "
      f"base {base_vp:.0f}, new {new_vp:.0f}, new / base **{new_vp / base_vp:.2f}**")
vm = [(g, get("base", f"VrlMarginalBounded/step/g:{g:.2f}"), get("new", f"VrlMarginalBounded/step/g:{g:.2f}"))
      for g in gs]
print(f"\nStep one with VrlMarginal per sample, ns (fit + sample + pdf as above, over the pool's bounded camera segments: "
      f"which every commit's VrlMarginal can fit; median of {reps} interleaved runs)\n")
print("| g | " + " | ".join(f"{g:g}" for g, _, _ in vm) + " |")
print("|---|" + "---|" * len(vm))
print("| base | " + " | ".join(f"{b:.0f}" for _, b, _ in vm) + " |")
print("| new | " + " | ".join(f"{n:.0f}" for _, _, n in vm) + " |")
print("| new / base | " + " | ".join(f"**{n / b:.2f}**" for _, b, n in vm) + " |")
print(f"\nWhat the fused call saves in this tree: fit + sample_pdf (Camera) over fit, sample, then pdf(t) (CameraSeparate), per sample\n")
print("| g | " + " | ".join(cams) + " |")
print("|---|" + "---|" * len(cams))
for g in gs:
    print(f"| {g:g} | " + " | ".join(f"{t('new', c, g) / get('new', f'CameraSeparate/{c}/g:{g:.2f}'):.2f}" for c in cams) + " |")
print(f"\nCamera step per sample on the scenes' own queries, ns (fit + sample_pdf, float; vrlis_bench SceneCamera/ over "
      f"a log of the scene's medium-to-medium gathers, vrl_render --dump-queries; median of {reps} repetitions), and over {base_cam}\n")
scene_methods = samplers
print("| scene | " + " | ".join(scene_methods) + " | " + " | ".join(f"{c}/{base_cam}" for c in claimed) + " |")
print("|---|" + "---|" * (len(scene_methods) + len(claimed)))
for scene in scenes:
    st = {b["name"].split("/")[1].rsplit("_", 1)[0]: b["cpu_time"] for b in json.load(open(f"{out}/runs/scene_{scene}.json"))["benchmarks"]
          if median(b)}
    print(f"| {scene} | " + " | ".join(f"{st[m]:.0f}" for m in scene_methods) +
          " | " + " | ".join(f"{st[c] / st[base_name]:.2f}" for c in thesis()) + " |")
parts = {b["name"].rsplit("_", 1)[0]: b["cpu_time"] for b in load(f"{out}/runs/parts.json") if median(b)}
# ns per gather of a batched benchmark, from its own count of gathers per iteration
per_gather = {b["name"].rsplit("_", 1)[0]: 1e9 / b["items_per_second"] for b in load(f"{out}/runs/parts.json")
              if median(b) and "items_per_second" in b}
print(f"\nCost of one gather, ns (this tree; medians of {reps} repetitions; Gather = everything but the occlusion ray, "
      "one VRL at a time; batched gather: one gather of SampleMediumGathers, 32 VRLs (kGatherChunk) against one camera segment, "
      "the renderer's call; batched surface gather: one of SampleSurfaceGathers, eight VRLs seen from one surface "
      "point, the medium-to-surface gather, which makes most of the cube scene's gathers)\n")
print("| method | g | whole gather | validate | step one (VrlPoint) | camera fit | camera sample + pdf | integrand | rest | batched gather | batched surface gather |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for c, m in zip(cams, samplers):
    for g in (-0.9, 0.5, 0.9):
        whole, fit, cam = parts[f"Gather/{c}/g:{g:.2f}"], parts[f"Fit/{c}/g:{g:.2f}"], parts[f"Camera/{c}/g:{g:.2f}"]
        v, s1, f = parts["GatherPart/validate"], parts["GatherPart/step-one"], parts["GatherPart/integrand"]
        batched = per_gather[f"GatherBatch/{c}/g:{g:.2f}"]
        surface = per_gather[f"SurfaceGatherBatch/{c}/g:{g:.2f}"]
        print(f"| {m} | {g:g} | {whole:.0f} | {v:.0f} | {s1:.0f} | {fit:.0f} | {cam - fit:.0f} | {f:.0f} | {whole - v - s1 - cam - f:.0f} | {batched:.0f} | {surface:.0f} |")
# This table is one run of this tree, not interleaved with the baseline: a slow phase of a
# shared machine inflates all of it. The same benchmark in both runs shows by how much.
here, rounds = parts[f"Camera/{base_cam}/g:0.50"], t("new", base_cam, 0.5)
print(f"\nMachine phase: Camera/{base_name} at g = 0.5 took {here:.0f} ns in this table's run and {rounds:.0f} ns in the "
      f"interleaved rounds above ({here / rounds:.2f}x); this table's absolute times carry that factor.")


def short_symbol(line, width=160):
    """A profile line with what its symbol nests two brackets deep elided: a batched gather's
    lambda otherwise spells out every type it nests, a page long."""
    kept, depth = [], 0
    for ch in line:
        if ch in "<(":
            depth += 1
            if depth <= 2:
                kept.append(ch + ("\u2026" if depth == 2 else ""))
        elif ch in ">)":
            depth = max(depth - 1, 0)
            if depth <= 1:
                kept.append(ch)
        elif depth <= 1:
            kept.append(ch)
    text = "".join(kept)
    return text if len(text) <= width else text[:width - 1] + "\u2026"


for scene, sampler in profiled:
    try:
        prof = "\n".join(map(short_symbol, open(f"{out}/runs/perf_{scene}.txt").read().rstrip().splitlines()))
    except OSError:
        continue
    print(f"\nProfile of `vrl_render --scene {scene} --sampler {sampler} --threads 1` (perf, self time: by library, "
          "then the top symbols of known name):\n")
    print("```\n" + prof + "\n```")
if missing:
    print("\nNot compared (one commit has no such benchmark or sampler): " + ", ".join(sorted(missing)))
print("\nGeometric mean over g: " + ", ".join(f"{c} new / base {geo([t('new', c, g) / t('base', c, g) for g in gs]):.2f}" for c in cams))
for c in claimed:
    print(f"{c} / {base_cam}: base {geo([t('base', c, g) / t('base', base_cam, g) for g in gs]):.2f}, "
          f"new {geo([t('new', c, g) / t('new', base_cam, g) for g in gs]):.2f}")
EOF

# The generated section of docs/bench.md (tools/bench.sh keeps it when it rewrites the rest),
# or with VRLIS_SPEED_CXXFLAGS a page of its own.
if [ "${VRLIS_SPEED_NO_DOCS:-0}" != 1 ]; then
  model=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
  header() {
    echo "Generated $(date -u '+%Y-%m-%d %H:%M UTC') on ${model:-unknown CPU}, $(nproc) cores, $(uname -sr) by \`${VRLIS_SPEED_CXXFLAGS:+VRLIS_SPEED_CXXFLAGS=\"$VRLIS_SPEED_CXXFLAGS\" }tools/speed.sh\`"
    echo "(base: commit $base_ref, new: commit $new_ref; both builds ${VRLIS_SPEED_CXXFLAGS:+with $VRLIS_SPEED_CXXFLAGS, }Release;"
    echo "$reps interleaved rounds;${VRLIS_SPEED_PIN:+ single-threaded runs pinned to CPU $VRLIS_SPEED_PIN;} load average"
    echo "at the end $(cut -d' ' -f1-3 /proc/loadavg); the runs' own load is about 1, and a load above the core count would mean the 2-thread columns also measure other work)."
    echo
  }
  if [ -n "${VRLIS_SPEED_CXXFLAGS:-}" ]; then
    page="docs/speed-$(echo "$VRLIS_SPEED_CXXFLAGS" | tr -c 'A-Za-z0-9.\n-' '_' | sed 's/^-*//').md"
    { echo "# Speed against the baseline, both built with \`$VRLIS_SPEED_CXXFLAGS\`"
      echo
      echo "The same measurements as [the default build's](bench.md#speed-against-the-baseline-and-the-cost-of-one-gather)."
      echo
      header
      cat "$out/speed.md"; } >"$page"
  else
    { sed '/^<!-- speed -->$/,$d' docs/bench.md
      echo '<!-- speed -->'
      echo '## Speed against the baseline and the cost of one gather'
      echo
      header
      cat "$out/speed.md"; } >"$out/bench.md.new"
    mv "$out/bench.md.new" docs/bench.md
  fi
fi
