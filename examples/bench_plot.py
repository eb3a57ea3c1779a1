"""Run time against error: `nineball bench --csv` plotted, one point per solver setting.

Each point is one solver setting (contact model, world scale, step rate, iterations): across,
the wall time of the break at that setting (median); up, its worst error over the canonical
cases as a fraction of each case's target (1 = at the target). The Pareto front is joined.

    /usr/bin/python3 examples/bench_plot.py --nineball build/nineball --out bench.png [--full]
"""
import argparse
import csv
import os
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nineball", default="build/nineball")
    parser.add_argument("--out", default="bench.png")
    parser.add_argument("--full", action="store_true", help="the whole sweep, not --quick")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "bench.csv")
        cmd = [args.nineball, "bench", "--csv", path] + ([] if args.full else ["--quick"])
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit("nineball bench wrote no rows")

    fig, ax = plt.subplots(figsize=(8, 5))
    colours = {"pairwise": "tab:blue", "box2d": "tab:green"}
    seen = set()
    for r in rows:
        x, y = float(r["break_wall_ms_median"]), max(float(r["worst_over_target"]), 1e-9)
        baseline = r["baseline"] == "1"
        model = r["contacts"]
        label = None if model in seen else f"contacts: {model}"
        seen.add(model)
        ax.plot(x, y, "s" if baseline else "o", label=label,
                color="tab:red" if baseline else colours.get(model, "tab:gray"))
        # Many settings: only the front and the baseline are named, or the names pile up.
        if len(rows) <= 8 or baseline or r["pareto"] == "1":
            ax.annotate(r["setting"], (x, y), fontsize=7, xytext=(4, 3),
                        textcoords="offset points")
    front = sorted((float(r["break_wall_ms_median"]), max(float(r["worst_over_target"]), 1e-9))
                   for r in rows if r["pareto"] == "1")
    if len(front) > 1:
        ax.plot(*zip(*front), "-", color="tab:blue", alpha=0.5, label="Pareto front")
    ax.axhline(1.0, color="k", lw=0.8, ls="--", label="at the targets")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("break to rest, wall time (ms, median)")
    ax.set_ylabel("worst error / target over the canonical cases")
    ax.set_title("nineball: run time against error (red: the plain baseline)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print(f"{args.out}: {len(rows)} settings")


if __name__ == "__main__":
    main()
