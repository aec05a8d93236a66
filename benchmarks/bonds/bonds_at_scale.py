#!/usr/bin/env python3
"""bonds_at_scale.py [--build DIR] [--rounds N] [--threads 1|default|both] [--cases ...] [--keep DIR]

Bonded sub-blocks at 10^4 against ordinary blocks of the same count (docs/performance.md,
"Bonded sub-blocks at 10^4"): each round runs every case once, in turn, as a fresh process
of `hydrodda run` under /usr/bin/time, at default settings (`--threads 1`, the program's own
choice of threads, or both), and prints, per case, the medians of the rounds: CPU (user +
system) and wall time, summary.json's `timings`, the DDA steps or coupling passes, the
open-close passes a step, the closed contacts, and each step's CPU per block against the
grid of ordinary blocks. A slab (20 static steps) is run a second time cut to its first step,
so that a step's CPU is the difference over the 19 steps after the first (the model's
building, the first step's factorisation and the output left out).

The cases (benchmarks/bonds/):
  bonded_slab_10k    the 10 m slab in ~10^4 sub-blocks, Voronoi cells zoned, 20 static steps
  triangle_slab_10k  the same slab in ~10^4 bonded triangles, 20 static steps
  grid_slab_10k      the same slab cut into 100 x 100 ordinary blocks by two joint sets
  wall_100x100       the brick wall of shared/peers/brickwall.py 100 100 (10,001 blocks,
                     20 static steps), if the peers folder is found (HYDRODDA_PEERS)
  wall_100x100_band  the same wall with tension_cutoff = false (Shi's contact rule, as
                     bench_dda's BM_BrickWall steps it; not the default)
  intact_seal_10k    the tutorial's intact seal in ~10^4 bonded triangles, coupled, at its
                     shipped head (the loop's passes until it converges)
The 1,000-block pair of docs/studies/2026-11-29-bond-cost.md is `bonded_slab` and `grid_slab`, and
`wall_100x100_band` the wall under Shi's contact rule (cases that are not run by default).
"""
import argparse
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SLABS = ["bonded_slab_10k", "triangle_slab_10k", "grid_slab_10k", "wall_100x100"]
STATIC_RUNS = SLABS + ["wall_100x100_band", "bonded_slab", "grid_slab"]  # 20 static steps each
REFERENCE = "grid_slab_10k"


def scenario_path(case, work):
    if not case.startswith("wall_100x100"):
        return os.path.join(HERE, case + ".toml")
    peers = os.environ.get("HYDRODDA_PEERS", os.path.join(HERE, "..", "..", "..", "shared", "peers"))
    script = os.path.join(peers, "brickwall.py")
    if not os.path.exists(script):
        sys.exit(f"bonds_at_scale.py: no brickwall.py in {peers}; set HYDRODDA_PEERS or leave out wall_100x100")
    wall = subprocess.run([sys.executable, script, "100", "100", "--format", "toml"], capture_output=True, text=True,
                          check=True).stdout
    if case == "wall_100x100_band":
        wall = wall.replace("[mechanics]\n", "[mechanics]\ntension_cutoff = false\n", 1)
    path = os.path.join(work, case + ".toml")
    open(path, "w").write(wall)
    return path


def run_once(program, scenario, folder, threads):
    """One fresh process; its wall and CPU seconds and its run folder's figures."""
    times = folder + ".time"
    command = ["/usr/bin/time", "-f", "%e %U %S", "-o", times, program, "-q", "run", scenario, "-o", folder,
               "--overwrite"]
    if threads != "default":
        command += ["--threads", threads]
    subprocess.run(command, check=True)
    wall, user, system = map(float, open(times).read().split()[-3:])
    summary = json.load(open(os.path.join(folder, "summary.json")))
    rows = list(csv.DictReader(open(os.path.join(folder, "history.csv"))))
    record = {"wall": wall, "cpu": user + system, "timings": summary["timings"],
              "blocks": len(summary["blocks"]), "rows": len(rows), "converged": summary.get("converged")}
    if "open_close_iterations" in rows[0]:  # a mechanics run: one row a step
        record["open_close"] = statistics.mean(int(r["open_close_iterations"]) for r in rows)
        record["contacts"] = int(rows[-1]["contacts"])
    else:  # a coupled run: one row a pass
        record["open_close"] = max(int(r["most_open_close_iterations"]) for r in rows)
        record["contacts"] = None
    return record


def one_step_copy(scenario, work):
    """The scenario cut to its first step (its [mechanics] steps = 20 made 1)."""
    text = open(scenario).read()
    if text.count("steps = 20") != 1:
        sys.exit(f"bonds_at_scale.py: {scenario} has no single 'steps = 20' to cut")
    path = os.path.join(work, os.path.basename(scenario)[:-5] + "_1step.toml")
    open(path, "w").write(text.replace("steps = 20", "steps = 1"))
    return path


def median(records, key):
    return statistics.median(r[key] for r in records)


def print_tables(results, results_one, threads):
    print(f"\nthreads: {threads}")
    print("| case | blocks | steps or passes | open-close passes a step | closed contacts (last step) "
          "| CPU (s) | wall (s) | mechanics (s) | CPU a step after the first (ms) | per block (µs) | ÷ grid |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    per_block, per_step_cpu = {}, {}
    for case, records in results.items():
        if case not in STATIC_RUNS:
            continue
        # A step's CPU: the run's less its first step's, over the 19 steps after the first.
        steps = [(r["cpu"] - one["cpu"]) / (r["rows"] - one["rows"]) for r, one in zip(records, results_one[case])]
        per_step_cpu[case] = statistics.median(steps)
        per_block[case] = 1e6 * per_step_cpu[case] / records[0]["blocks"]
    for case, records in results.items():
        first = records[0]
        mechanics = statistics.median(r["timings"]["mechanics"] for r in records)
        if case in STATIC_RUNS:
            per_step = f"{1e3 * per_step_cpu[case]:.1f}"
            block_step = f"{per_block[case]:.2f}"
            ratio = f"{per_block[case] / per_block[REFERENCE]:.2f}" if REFERENCE in per_block else ""
            contacts = f"{first['contacts']:,}"
            open_close = f"{first['open_close']:.2f}"
        else:
            per_step = block_step = ratio = contacts = ""
            open_close = f"{first['open_close']} (most)"
        print(f"| {case} | {first['blocks']:,} | {first['rows']} | {open_close} | {contacts} | {median(records, 'cpu'):.2f} "
              f"| {median(records, 'wall'):.2f} | {mechanics:.2f} | {per_step} | {block_step} | {ratio} |")
    for case, records in results.items():
        phases = sorted(records[0]["timings"])
        cells = ", ".join(f"{p} {statistics.median(r['timings'][p] for r in records):.3f}" for p in phases)
        spread = ", ".join(f"{r['cpu']:.2f}" for r in records)
        ones = ", ".join(f"{r['cpu']:.2f}" for r in results_one.get(case, []))
        print(f"{case}: timings (s, medians) {cells}; CPU by round {spread}; first step only {ones}; "
              f"converged {records[0]['converged']}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--threads", choices=["1", "default", "both"], default="both")
    parser.add_argument("--cases", nargs="+", default=SLABS)
    parser.add_argument("--keep", help="keep the run folders here (default: a temporary folder)")
    args = parser.parse_args()
    program = os.path.join(args.build, "bin", "hydrodda")
    work = args.keep or tempfile.mkdtemp(prefix="bonds_at_scale_")
    os.makedirs(work, exist_ok=True)
    scenarios = {case: scenario_path(case, work) for case in args.cases}
    one_step = {case: one_step_copy(scenarios[case], work) for case in args.cases if case in STATIC_RUNS}
    threads_list = ["1", "default"] if args.threads == "both" else [args.threads]
    results = {t: {case: [] for case in args.cases} for t in threads_list}
    results_one = {t: {case: [] for case in one_step} for t in threads_list}
    print(f"load average before: {open('/proc/loadavg').read().split()[:3]}")
    for round_ in range(args.rounds):
        for threads in threads_list:
            for case in args.cases:
                folder = os.path.join(work, f"{case}_t{threads}_r{round_}")
                record = run_once(program, scenarios[case], folder, threads)
                results[threads][case].append(record)
                print(f"round {round_ + 1}, threads {threads}, {case}: CPU {record['cpu']:.2f} s, wall {record['wall']:.2f} s",
                      flush=True)
                if case in one_step:
                    one = run_once(program, one_step[case], folder + "_1step", threads)
                    results_one[threads][case].append(one)
                    print(f"round {round_ + 1}, threads {threads}, {case} (first step only): CPU {one['cpu']:.2f} s", flush=True)
    print(f"load average after: {open('/proc/loadavg').read().split()[:3]}")
    for threads in threads_list:
        print_tables(results[threads], results_one[threads], threads)


if __name__ == "__main__":
    main()
