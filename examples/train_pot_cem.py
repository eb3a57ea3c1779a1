"""Training a small potting policy with the cross-entropy method, numpy only.

The environment is nineball.env's "pot" task: the cue ball and the 1 anywhere on the table, one
stroke an episode, a reward of 1 for the pot (and -1 for a foul). The policy sees the two balls
and the nearest corner pocket and aims at the object ball's centre turned by a learnt share of
the ghost-ball correction, plus a learnt bias, at a learnt speed:

    heading = direction to the 1 + k * (ghost-ball correction) + bias,   speed = s

Aiming at the centre (k = 0) pots only the nearly straight shots; k = 1 is the ghost ball. The
cross-entropy method draws policies from a Gaussian over (k, bias, s), plays each on the same
tables (the same seeds: common random numbers), keeps the best fifth and refits the Gaussian.

    PYTHONPATH=build/python /usr/bin/python3 examples/train_pot_cem.py --out cem.png
"""
import argparse
import math
import sys
import time

import numpy as np

import nineball.env

CORNERS = None  # set from the table once the environment exists


def corners_of(length, width):
    return np.array([[x * length / 2, y * width / 2] for x in (-1, 1) for y in (-1, 1)])


def features(obs, radius):
    """Per table: the direction to the 1 and the ghost-ball correction for its nearest corner."""
    cue, obj = obs["balls"][:, 0], obs["balls"][:, 1]
    d = np.linalg.norm(CORNERS[None, :, :] - obj[:, None, :], axis=2)
    pocket = CORNERS[np.argmin(d, axis=1)]
    to_pocket = pocket - obj
    to_pocket /= np.linalg.norm(to_pocket, axis=1, keepdims=True)
    ghost = obj - 2.0 * radius * to_pocket
    direct = np.arctan2(obj[:, 1] - cue[:, 1], obj[:, 0] - cue[:, 0])
    aimed = np.arctan2(ghost[:, 1] - cue[:, 1], ghost[:, 0] - cue[:, 0])
    correction = (aimed - direct + np.pi) % (2 * np.pi) - np.pi
    return direct, correction


def actions_for(theta, obs, radius):
    k, bias_deg, speed = theta
    direct, correction = features(obs, radius)
    n = len(direct)
    heading = np.degrees(direct + k * correction) + bias_deg
    heading = (heading + 180.0) % 360.0 - 180.0
    return np.column_stack([heading, np.full(n, np.clip(speed, 0.3, 8.0)), np.zeros(n),
                            np.zeros(n), np.zeros(n), np.full(n, np.nan), np.full(n, np.nan)])


def mean_reward(env, theta, seed, radius):
    obs, _ = env.reset(seed=seed)
    _, reward, _, _, _ = env.step(actions_for(theta, obs, radius))
    return float(np.mean(reward))


def main():
    global CORNERS
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--iterations", type=int, default=12)
    ap.add_argument("--population", type=int, default=24)
    ap.add_argument("--tables", type=int, default=256, help="positions each policy is tried on")
    ap.add_argument("--noise", default="club", help="the execution noise (nineball.env)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", help="a PNG of the learning curve (needs matplotlib)")
    ap.add_argument("--check", action="store_true",
                    help="exit 1 unless the policy learnt (the tests run it so)")
    args = ap.parse_args()

    env = nineball.env.make_vec("pot", args.tables, noise=args.noise, seed=args.seed)
    CORNERS = corners_of(*env.table_size)
    radius = 0.028575
    rng = np.random.default_rng(args.seed)
    mean = np.array([0.0, 0.0, 1.0])  # aim at the 1's centre, softly
    std = np.array([1.5, 2.0, 1.5])
    elite = max(2, args.population // 5)
    history = [mean_reward(env, mean, 10**6, radius)]  # the starting policy, before any update
    started = time.perf_counter()
    steps = 0
    for it in range(args.iterations):
        seed = args.seed * 1000 + it  # new positions each iteration, shared by its candidates
        thetas = mean + std * rng.standard_normal((args.population, 3))
        scores = np.array([mean_reward(env, t, seed, radius) for t in thetas])
        steps += args.population * args.tables
        best = thetas[np.argsort(scores)[-elite:]]
        mean, std = best.mean(axis=0), best.std(axis=0) + np.array([0.05, 0.1, 0.05])
        held_out = mean_reward(env, mean, 10**6 + it + 1, radius)
        history.append(held_out)
        print(f"iteration {it + 1:2d}: mean policy k={mean[0]:+.2f} bias={mean[1]:+.2f} deg "
              f"speed={mean[2]:.2f} m/s -> reward {held_out:+.3f} on new tables")
    seconds = time.perf_counter() - started
    print(f"{steps} strokes in {seconds:.1f} s ({steps / seconds:.0f} a second)")
    first = mean_reward(env, np.array([0.0, 0.0, 1.0]), 10**7, radius)
    last = mean_reward(env, mean, 10**7, radius)
    print(f"the starting policy's reward {first:+.3f}, the trained one's {last:+.3f} "
          f"(the same {args.tables} new tables)")
    if args.out:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 3.5))
        ax.plot(range(len(history)), history, marker="o", label="the mean policy")
        ax.axhline(0.0, color="grey", linewidth=0.5)
        ax.set_xlabel("iteration (0: aiming at the 1's centre, softly)")
        ax.set_ylabel("mean reward on new tables")
        ax.set_title(f"Cross-entropy method on the pot task ({args.noise} noise)")
        ax.legend()
        fig.tight_layout()
        fig.savefig(args.out, dpi=100)
    if args.check and not last > first + 0.15:
        print("the policy did not learn", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
