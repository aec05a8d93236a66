"""A load raised step by step on one model, against each step run from the start: does the
answer depend on the path to it?

    PYTHONPATH=build/python python3 examples/python/loading_path.py [SCENARIO]
        [--key 'flow.boundary[0].head'] [--values 75 125 175 225 275] [--region seal]
        [--out out/loading-path]

Along the path one `hydrodda.Simulation` meets each value in turn, starting from where the last
one converged: the blocks, their contacts and the heads carry over, as in a reservoir whose
pressure rises. From the start each value is a model of its own, loaded from its in-situ state
at once, as a `hydrodda sweep` case is. Blocks held by friction can end in different
equilibria by the two roads; where the region's K_eff / K_matrix differs, the answer depends on
the loading path. Writes OUT/loading_path.csv and OUT/loading_path.png. The default is the seal
over a reservoir (scenarios/examples/seal_over_reservoir.toml) over the reservoir's head.
"""

import argparse
import csv
import tomllib
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no window
import matplotlib.pyplot as plt

import hydrodda

REPOSITORY = Path(__file__).resolve().parents[2]


def converge(simulation, most_passes):
    """Passes until the loop converges or `most_passes` are run: (passes, converged)."""
    for passes in range(1, most_passes + 1):
        if simulation.run_pass()["converged"]:
            return passes, True
    return most_passes, False


def conductivity(simulation, region):
    return simulation.summary["flow"]["regions"][region]["normalised_conductivity"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenario", type=Path, nargs="?",
                        default=REPOSITORY / "scenarios/examples/seal_over_reservoir.toml")
    parser.add_argument("--key", default="flow.boundary[0].head", help="the load raised (a key sim.set takes)")
    parser.add_argument("--values", type=float, nargs="+", default=[75, 125, 175, 225, 275])
    parser.add_argument("--region", default="seal", help="the [[flow.region]] whose K_eff / K_matrix is compared")
    parser.add_argument("--out", type=Path, default=Path("out/loading-path"))
    args = parser.parse_args()

    base = hydrodda.Scenario.load(args.scenario)
    most_passes = tomllib.loads(base.to_toml()).get("coupling", {}).get("max_iterations", 50)
    along = hydrodda.Simulation(base)
    rows = []
    for value in args.values:
        along.set(args.key, value)
        path_passes, path_converged = converge(along, most_passes)
        scenario = base.copy()
        scenario.set(args.key, value)
        alone = hydrodda.Simulation(scenario)
        start_passes, start_converged = converge(alone, most_passes)
        path, start = conductivity(along, args.region), conductivity(alone, args.region)
        rows.append([value, path_passes, path_converged, path, start_passes, start_converged, start])
        print(f"{args.key} = {value:g}: along the path {path:.4f} ({path_passes} passes"
              f"{'' if path_converged else ', not converged'}), from the start {start:.4f} ({start_passes} passes"
              f"{'' if start_converged else ', not converged'}), {100 * (path - start) / start:+.2f}%")

    args.out.mkdir(parents=True, exist_ok=True)
    with open(args.out / "loading_path.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow([args.key, "passes_along_path", "converged_along_path", "ratio_along_path",
                         "passes_from_start", "converged_from_start", "ratio_from_start"])
        writer.writerows(rows)
    figure, axes = plt.subplots(figsize=(5, 3.5))
    axes.plot(args.values, [r[3] for r in rows], "o-", label="along the path")
    axes.plot(args.values, [r[6] for r in rows], "s--", label="each from the start")
    axes.set_xlabel(args.key)
    axes.set_ylabel(f"K_eff / K_matrix, {args.region}")
    axes.set_title(base.title, fontsize=9)
    axes.legend()
    axes.grid(True, alpha=0.3)
    figure.tight_layout()
    figure.savefig(args.out / "loading_path.png", dpi=120)
    print(f"table: {args.out / 'loading_path.csv'}; figure: {args.out / 'loading_path.png'}")


if __name__ == "__main__":
    main()
