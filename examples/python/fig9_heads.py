"""The paper's Fig. 9 from Python: the symmetric flexure model run over a range of head
differentials, the central fractured region's conductivity (normalised by the unfractured case)
plotted against the head.

    PYTHONPATH=build/python python3 examples/python/fig9_heads.py [--heads 5 10 20] [--out out/fig9-python]

Each head is one run folder under --out, as `hydrodda run` writes it; the figure is
OUT/fig9.png. It is what `hydrodda sweep ... --set 'flow.boundary[0].head=...'` does, one run
after another, with the loop in your hands.
"""

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no window
import matplotlib.pyplot as plt

import hydrodda

REPOSITORY = Path(__file__).resolve().parents[2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--heads", type=float, nargs="+", default=[5, 10, 15, 20, 30, 40],
                        help="head differentials (m), one run each")
    parser.add_argument("--out", type=Path, default=Path("out/fig9-python"))
    args = parser.parse_args()

    base = hydrodda.Scenario.load(REPOSITORY / "scenarios/paper/symmetric_flexure_20m.toml")
    ratios = []
    for head in args.heads:
        scenario = base.copy()
        scenario.set("flow.boundary[0].head", head)  # the high-head base; the top stays at 0 m
        result = hydrodda.run(scenario, args.out / f"head_{head:g}m", overwrite=True)
        if not result.converged:
            raise SystemExit(f"head {head:g} m: {result.status}: {result.message}")
        ratio = result.summary["flow"]["regions"]["fractured"]["normalised_conductivity"]
        ratios.append(ratio)
        print(f"head {head:5g} m: {result.iterations} passes, K_eff / K_matrix = {ratio:.4f}")

    figure, axes = plt.subplots(figsize=(5, 3.5))
    axes.plot(args.heads, ratios, "o-")
    axes.set_xlabel("head differential (m)")
    axes.set_ylabel("K_eff / K_matrix, fractured region")
    axes.set_title("Symmetric flexure (Fig. 9)")
    axes.grid(True, alpha=0.3)
    figure.tight_layout()
    figure.savefig(args.out / "fig9.png", dpi=120)
    print(f"figure: {args.out / 'fig9.png'}")


if __name__ == "__main__":
    main()
