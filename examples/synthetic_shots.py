"""Random three-cushion shots recorded by nineball itself, for trying fit and calibrate.

Each shot: three balls placed at random on a carom match table, a random stroke (heading,
1.5-5 m/s, side up to 0.35 R, height -0.35 to 0.2 R), recorded as a 50 Hz tracker with 5 mm of
noise would (nineball.record), the strike at a random instant 0.3-1 s into the recording. The
table's truth is the carom preset with --rolling and --cushion; each recording claims the
plain carom preset, so that calibrate has something to find.

    python3 examples/synthetic_shots.py --shots 90 --out shots.jsonl
    nineball calibrate shots.jsonl --params rolling_friction,cushion_restitution
"""

import argparse
import json
import random

import nineball


def random_balls(rng, table):
    half_l, half_w = table.length / 2 - 0.1, table.width / 2 - 0.1
    balls = []
    while len(balls) < 3:
        x, y = rng.uniform(-half_l, half_l), rng.uniform(-half_w, half_w)
        if all((x - b["x"]) ** 2 + (y - b["y"]) ** 2 > 0.02 for b in balls):
            balls.append({"id": len(balls), "x": x, "y": y})
    return balls


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shots", type=int, default=90)
    parser.add_argument("--out", default="shots.jsonl")
    parser.add_argument("--seed", type=int, default=5)
    parser.add_argument("--rolling", type=float, default=0.006, help="the truth's rolling_friction")
    parser.add_argument("--cushion", type=float, default=0.93,
                        help="the truth's cushion_restitution")
    args = parser.parse_args()

    rng = random.Random(args.seed)
    truth = nineball.preset("carom")
    truth["rolling_friction"] = args.rolling
    truth["cushion_restitution"] = args.cushion
    table = nineball.Table("carom", truth)
    with open(args.out, "w") as out:
        for n in range(args.shots):
            scene = {"table": "carom", "physics": truth, "balls": random_balls(rng, table),
                     "shot": {"heading_deg": rng.uniform(-180, 180), "speed": rng.uniform(1.5, 5),
                              "tip": [rng.uniform(-0.35, 0.35), rng.uniform(-0.35, 0.2)]},
                     "step": {"engine": "reference"}}
            shot = nineball.record(scene, ["white", "yellow", "red"], hz=50, noise=0.005,
                                   strike=rng.uniform(0.3, 1.0), seed=n + 1)
            shot["id"] = f"shot-{n}"
            shot["physics"] = {"preset": "carom"}
            out.write(json.dumps(shot) + "\n")
    print(json.dumps({"shots": args.shots, "out": args.out, "truth": {
        "rolling_friction": args.rolling, "cushion_restitution": args.cushion}}))


if __name__ == "__main__":
    main()
