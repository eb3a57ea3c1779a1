"""What a shot and an environment step cost from Python, and Python's share of it.

Three measurements, each the median of `--repeats` runs (wall time):
- the game environment: `make_vec("pot", n)` stepped with random strokes on every core, in
  steps a second; Python's share is the step's wall time less the time the tables' stepping
  took in C++ (VecEnv.last_step_seconds);
- arrays in and out: `simulate_arrays` of n two-ball shots; Python's share is its wall time
  less the engines' own (wall_ms summed), on one thread;
- one dict a shot: `simulate(scene)` of the same shots, against the same engine time.

    PYTHONPATH=build/python /usr/bin/python3 examples/throughput.py
"""
import argparse
import statistics
import time

import numpy as np

import nineball
import nineball.env


def random_strokes(rng, n):
    return np.column_stack([rng.uniform(-180, 180, n), rng.uniform(0.5, 4.0, n), np.zeros(n),
                            np.zeros(n), np.zeros(n), np.full(n, np.nan), np.full(n, np.nan)])


def env_rate(n, steps, threads, seed):
    vec = nineball.env.make_vec("pot", n, seed=seed, threads=threads)
    vec.reset(seed=seed)
    rng = np.random.default_rng(seed)
    actions = [random_strokes(rng, n) for _ in range(steps)]
    inside = 0.0
    started = time.perf_counter()
    for a in actions:
        vec.step(a)
        inside += vec.last_step_seconds
    wall = time.perf_counter() - started
    return n * steps / wall, (wall - inside) / wall


def two_ball_shots(rng, n):
    places = np.zeros((n, 2, 2))
    places[:, 0] = [-0.6, 0.0]
    places[:, 1, 0] = rng.uniform(-0.2, 1.0, n)
    places[:, 1, 1] = rng.uniform(-0.5, 0.5, n)
    shots = np.zeros((n, 5))
    shots[:, 0] = np.degrees(np.arctan2(places[:, 1, 1], places[:, 1, 0] + 0.6))
    shots[:, 1] = rng.uniform(0.5, 3.0, n)
    return places, shots


def arrays_share(places, shots):
    started = time.perf_counter()
    a = nineball.simulate_arrays(places, shots, threads=1, step={"engine": "reference"})
    wall = time.perf_counter() - started
    engine = a["wall_ms"].sum() / 1000.0
    return wall / len(shots), (wall - engine) / wall


def dict_share(places, shots):
    scenes = [{"step": {"engine": "reference"},
               "balls": [{"id": i, "x": float(x), "y": float(y)} for i, (x, y) in enumerate(p)],
               "shot": {"heading_deg": float(s[0]), "speed": float(s[1])}}
              for p, s in zip(places, shots)]
    engine = 0.0
    started = time.perf_counter()
    for scene in scenes:
        engine += nineball.simulate(scene)["wall_ms"] / 1000.0
    wall = time.perf_counter() - started
    return wall / len(shots), (wall - engine) / wall


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tables", type=int, default=256)
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--shots", type=int, default=2000)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--threads", type=int, default=0)
    args = ap.parse_args()
    rng = np.random.default_rng(1)
    places, shots = two_ball_shots(rng, args.shots)
    runs = {"env": [], "arrays": [], "dicts": []}
    for k in range(args.repeats):
        runs["env"].append(env_rate(args.tables, args.steps, args.threads, k + 1))
        runs["arrays"].append(arrays_share(places, shots))
        runs["dicts"].append(dict_share(places, shots))
    med = {key: tuple(statistics.median(r[i] for r in value) for i in range(2))
           for key, value in runs.items()}
    print(f"environment, pot task, {args.tables} tables: {med['env'][0]:,.0f} steps/s, "
          f"Python's share {med['env'][1]:.1%}")
    print(f"simulate_arrays, two balls: {med['arrays'][0] * 1e6:.1f} us a shot, "
          f"Python's share {med['arrays'][1]:.1%}")
    print(f"simulate, two balls, a dict a shot: {med['dicts'][0] * 1e6:.1f} us a shot, "
          f"Python's share {med['dicts'][1]:.1%}")


if __name__ == "__main__":
    main()
