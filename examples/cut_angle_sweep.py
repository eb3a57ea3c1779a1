"""Cut angle sweep: nineball's object-ball direction and both balls' speeds against the paper.

Sweeps the cut angle (the angle between the cue ball's path and the line of centres at
contact) and plots, for each, what nineball's physics gives right after the contact against
the seed paper's frictionless oblique collision (paper-formulas.md, section 5):
    object ball: along the line of centres, at (1 + e) / 2 * u cos(theta)
    cue ball:    normal part (1 - e) / 2 * u cos(theta), tangential part u sin(theta) kept
u is the cue ball's speed just before the contact, read from the same trace.

    PYTHONPATH=build/python /usr/bin/python3 examples/cut_angle_sweep.py --out cut_angle_sweep.png
"""
import argparse
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import nineball  # noqa: E402

R = 0.028575  # ball radius of the default physics, m
E = 0.9  # the paper's ball-ball restitution
SPEED = 2.0  # m/s the cue ball is struck at


def scene_for(theta_deg):
    theta = math.radians(theta_deg)
    # The object ball sits where a cue ball on the x axis meets it with the line of centres
    # at theta to its path.
    obj = (0.3, 2.0 * R * math.sin(theta))
    return {
        "physics": {"preset": "paper", "ball_restitution": E},
        "balls": [{"id": 0, "x": -0.4, "y": 0.0}, {"id": 1, "x": obj[0], "y": obj[1]}],
        "shot": {"heading_deg": 0.0, "speed": SPEED},
        "trace": {"hz": 5000},
    }


def after_contact(result):
    """The cue ball's speed just before the first ball-ball contact, and both velocities after."""
    t_hit = min(e["t"] for e in result["events"] if e["type"] == "ball")
    cue, obj = result["trace"]["0"], result["trace"]["1"]
    t = np.asarray(cue["t"])
    before = np.searchsorted(t, t_hit) - 1  # the last sample strictly before the contact
    at = int(np.searchsorted(t, t_hit))  # the contact's own sample: the state just after it
    u = math.hypot(cue["vx"][before], cue["vy"][before])
    v_cue = (cue["vx"][at], cue["vy"][at])
    v_obj = (obj["vx"][at], obj["vy"][at])
    return u, v_cue, v_obj


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="cut_angle_sweep.png")
    args = parser.parse_args()

    angles = np.arange(0.0, 76.0, 5.0)
    results = nineball.simulate_many([scene_for(a) for a in angles])
    direction, obj_ratio, cue_ratio = [], [], []
    for r in results:
        u, v_cue, v_obj = after_contact(r)
        direction.append(math.degrees(math.atan2(v_obj[1], v_obj[0])))
        obj_ratio.append(math.hypot(*v_obj) / u)
        cue_ratio.append(math.hypot(*v_cue) / u)
    th = np.radians(angles)
    paper_obj = (1 + E) / 2 * np.cos(th)
    paper_cue = np.hypot((1 - E) / 2 * np.cos(th), np.sin(th))

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    left.plot(angles, angles, "k-", label="paper: along the line of centres")
    left.plot(angles, direction, "o", color="tab:orange", label="nineball")
    left.set_xlabel("cut angle (deg)")
    left.set_ylabel("object ball's direction (deg)")
    left.legend()
    right.plot(angles, paper_obj, "k-", label="paper: object ball")
    right.plot(angles, obj_ratio, "o", color="tab:orange", label="nineball: object ball")
    right.plot(angles, paper_cue, "k--", label="paper: cue ball")
    right.plot(angles, cue_ratio, "s", color="tab:blue", label="nineball: cue ball")
    right.set_xlabel("cut angle (deg)")
    right.set_ylabel("speed after contact / speed before")
    right.legend()
    worst_dir = max(abs(d - a) for d, a in zip(direction, angles))
    worst_speed = max(np.max(np.abs(np.array(obj_ratio) - paper_obj)),
                      np.max(np.abs(np.array(cue_ratio) - paper_cue)))
    fig.suptitle(f"Cut angle sweep, paper preset, e = {E}: worst direction error "
                 f"{worst_dir:.2g} deg, worst speed-ratio error {worst_speed:.2g}")
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print(f"{args.out}: worst direction error {worst_dir:.3g} deg, "
          f"worst speed-ratio error {worst_speed:.3g}")
    # The paper's model is what the preset implements: a large error means a broken physics.
    if worst_dir > 0.01 or worst_speed > 1e-3:
        raise SystemExit("nineball is off the paper's formulas")


if __name__ == "__main__":
    main()
