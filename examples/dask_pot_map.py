"""Pot probability over the table, computed on a Dask cluster.

For every cue-ball spot on a grid, the 1 ball (fixed) is aimed at the top-right pocket by the
ghost ball, and the shot is struck `--tries` times with a Gaussian aim error of `--aim-sd`
degrees; the map shows the share that pots the 1 there. Each shot is one nineball scene; the
sweep goes to the cluster in chunks (nineball.dask.simulate), each chunk simulated by the
compiled core on a worker.

    PYTHONPATH=build/python /usr/bin/python3 examples/dask_pot_map.py --out pot_map.png
    # on a running cluster (every worker with nineball importable):
    /usr/bin/python3 examples/dask_pot_map.py --scheduler tcp://scheduler-host:8786

Without --scheduler it starts a LocalCluster of --workers processes on this machine.
"""
import argparse
import math
import random

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from dask.distributed import Client, LocalCluster  # noqa: E402

import nineball  # noqa: E402
import nineball.dask  # noqa: E402

OBJECT = (0.75, 0.35)  # the 1 ball, m
SPEED = 2.5  # m/s


def ghost_heading(cue, obj, pocket, r):
    """Degrees from the cue ball to the ghost ball that sends `obj` at `pocket`."""
    dx, dy = pocket[0] - obj[0], pocket[1] - obj[1]
    d = math.hypot(dx, dy)
    ghost = (obj[0] - 2 * r * dx / d, obj[1] - 2 * r * dy / d)
    return math.degrees(math.atan2(ghost[1] - cue[1], ghost[0] - cue[0]))


def sweep(table, nx, ny, tries, aim_sd, seed):
    """The grid's cue-ball spots that fit, and tries scenes for each."""
    r = table.ball_radius
    pocket = next(p for p in table.pockets if p.id == "top-right").drop_centre
    rng = random.Random(seed)
    spots, scenes = [], []
    for x in np.linspace(-table.length / 2 + 2 * r, table.length / 2 - 2 * r, nx):
        for y in np.linspace(-table.width / 2 + 2 * r, table.width / 2 - 2 * r, ny):
            if math.hypot(x - OBJECT[0], y - OBJECT[1]) < 4 * r:
                continue
            aim = ghost_heading((x, y), OBJECT, pocket, r)
            spots.append((x, y))
            for _ in range(tries):
                scenes.append({
                    "balls": [{"id": 0, "x": x, "y": y},
                              {"id": 1, "x": OBJECT[0], "y": OBJECT[1]}],
                    "shot": {"heading_deg": aim + rng.gauss(0.0, aim_sd), "speed": SPEED},
                })
    return spots, scenes


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scheduler", help="address of a running Dask scheduler")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster processes")
    ap.add_argument("--nx", type=int, default=40)
    ap.add_argument("--ny", type=int, default=20)
    ap.add_argument("--tries", type=int, default=8)
    ap.add_argument("--aim-sd", type=float, default=0.5, help="degrees")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default="pot_map.png")
    args = ap.parse_args()

    table = nineball.Table()
    spots, scenes = sweep(table, args.nx, args.ny, args.tries, args.aim_sd, args.seed)
    cluster = None if args.scheduler else LocalCluster(
        n_workers=args.workers, threads_per_worker=1, dashboard_address=None)
    with Client(args.scheduler or cluster) as client:
        results = nineball.dask.simulate(client, scenes, chunk=256)
    if cluster is not None:
        cluster.close()

    potted = np.array([any(b["id"] == 1 and b["pocket"] == "top-right" for b in r["balls"])
                       for r in results]).reshape(len(spots), args.tries).mean(axis=1)
    xs, ys = np.array(spots).T
    fig, ax = plt.subplots(figsize=(10, 5.4))
    ax.add_patch(plt.Polygon(table.cushion_loop, closed=True, facecolor="#1f6f43",
                             edgecolor="#5a3a1a", linewidth=2))
    dots = ax.scatter(xs, ys, c=potted, cmap="viridis", vmin=0, vmax=1, s=60, marker="s")
    ax.add_patch(plt.Circle(OBJECT, table.ball_radius, color="#f2c94c", zorder=3))
    ax.set_aspect("equal")
    ax.set_title(f"Share of {args.tries} shots that pot the 1 in the top-right pocket, "
                 f"aim error {args.aim_sd} deg sd, {SPEED} m/s")
    fig.colorbar(dots, ax=ax, label="pot probability")
    fig.savefig(args.out, dpi=100, bbox_inches="tight")
    print(f"{len(scenes)} shots from {len(spots)} spots; {args.out}")


if __name__ == "__main__":
    main()
