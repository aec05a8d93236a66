#!/usr/bin/env python3
"""transient_step_cost.py SCENARIO [--threads N]

The CPU time of each time step of a flow-only transient scenario, stepped by
hydrodda.Simulation (the program's steps, without its files): prints the model's size, then the
median, lowest and highest CPU seconds a step over the steps after the first (which factors the
first matrix in every case). Run with PYTHONPATH=build/python. CPU time, not wall: the machine
may be shared.
"""
import argparse
import statistics
import time

import hydrodda


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenario")
    parser.add_argument("--threads", type=int, default=1)
    args = parser.parse_args()
    sim = hydrodda.Simulation(hydrodda.Scenario.load(args.scenario), threads=args.threads)
    fluid = sim.fluid
    costs = []
    while not sim.finished:
        start = time.process_time()
        sim.step()
        costs.append(time.process_time() - start)
    later = costs[1:]
    print(f"{len(fluid['nodes'])} nodes, {len(fluid['triangles'])} triangles, {len(costs)} steps on "
          f"{args.threads} thread(s): first {costs[0]:.3f} s, then median {statistics.median(later):.3f} s "
          f"(lowest {min(later):.3f}, highest {max(later):.3f}) of CPU a step")


if __name__ == "__main__":
    main()
