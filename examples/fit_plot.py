"""A recorded shot against its fit: the paths on the table and the error against time.

Without --shots it records a three-cushion shot itself (nineball.record: 50 Hz, 5 mm of
tracking noise, struck at an unknown instant), so that it runs anywhere; with --shots FILE it
plots the first shot of your own recordings (the format of docs/calibrating.md).

    python3 examples/fit_plot.py --out fit.png [--shots my_shots.jsonl]
"""

import argparse
import json
import math

import matplotlib.pyplot as plt
import nineball

# Carom balls by name; other names take the palette's colours in turn.
COLOURS = {"white": "#f2f2f2", "yellow": "#f5c518", "red": "#d62828"}
PALETTE = ["#f2f2f2", "#f5c518", "#d62828", "#2a9d8f", "#8338ec", "#fb8500"]
# The error's running RMS over this many samples (half a second at 50 Hz).
WINDOW = 25


def colour(name, sid):
    return COLOURS.get(name, PALETTE[int(sid) % len(PALETTE)])


def running_rms(values, n):
    out = []
    for i in range(len(values)):
        part = values[max(0, i - n // 2):i + n // 2 + 1]
        out.append(math.sqrt(sum(v * v for v in part) / len(part)))
    return out


def synthetic_shot():
    scene = {"table": "carom", "physics": {"preset": "carom"},
             "balls": [{"id": 0, "x": -0.6, "y": -0.25}, {"id": 1, "x": -0.15, "y": -0.1},
                       {"id": 2, "x": 0.9, "y": 0.45}],
             "shot": {"heading_deg": 19.0, "speed": 3.0, "tip": [0.2, 0.1]},
             "step": {"engine": "reference"}}
    shot = nineball.record(scene, ["white", "yellow", "red"], hz=50, noise=0.005, strike=0.83)
    shot["id"] = "synthetic three-cushion shot"
    return shot


def first_shot(path):
    with open(path) as f:
        text = f.read()
    doc = json.loads(text.splitlines()[0]) if text.lstrip().startswith("{") and "\n{" in text \
        else json.loads(text)
    return doc[0] if isinstance(doc, list) else doc


def simulated_paths(fit, recorded):
    """Each recorded ball's simulated position at its recorded instants."""
    scene = dict(fit["scene"], trace={"hz": 1})
    result = nineball.simulate(scene)
    strike = fit["strike_time"]
    start = {str(b["id"]): (b["x"], b["y"]) for b in scene["balls"]}
    paths = {}
    for sid, name in fit["names"].items():
        ts = recorded["balls"][name]["t"]
        xs, ys = [], []
        for t in ts:
            if t <= strike or t - strike > result["time"]:
                x, y = start[sid] if t <= strike else (xs[-1], ys[-1])
            else:
                at = next(b for b in nineball.state_at(result, t - strike) if str(b["id"]) == sid)
                x, y = at["x"], at["y"]
            xs.append(x)
            ys.append(y)
        paths[sid] = (ts, xs, ys)
    return paths


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="fit.png")
    parser.add_argument("--shots", help="recorded shots (JSON or JSON Lines); default: a synthetic one")
    parser.add_argument("--evals", type=int, default=12000)
    args = parser.parse_args()

    recorded = first_shot(args.shots) if args.shots else synthetic_shot()
    fit = nineball.fit(recorded, evals=args.evals)[0]
    if "error" in fit:
        raise SystemExit("the shot is refused: " + fit["error"])
    paths = simulated_paths(fit, recorded)
    table = nineball.Table(fit["scene"]["table"], fit["scene"]["physics"])

    fig, (ax, err) = plt.subplots(1, 2, figsize=(12, 4.6), gridspec_kw={"width_ratios": [1.6, 1]})
    ax.set_facecolor("#1f6f8b")
    half_l, half_w = table.length / 2, table.width / 2
    ax.plot([-half_l, half_l, half_l, -half_l, -half_l], [-half_w, -half_w, half_w, half_w, -half_w],
            color="#6b3e1d", lw=4)
    for sid, name in fit["names"].items():
        c = colour(name, sid)
        rec = recorded["balls"][name]
        ax.plot(rec["x"], rec["y"], ".", ms=2.5, color=c, alpha=0.8)
        ts, xs, ys = paths[sid]
        ax.plot(xs, ys, "-", lw=1.0, color=c)
        ax.plot([], [], ".-", color=c, label=f"{name} (ball {sid})")
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("recorded (dots) and fitted (lines)")
    ax.legend(loc="upper left", fontsize=8, facecolor="#cccccc")

    strike = fit["strike_time"]
    for sid, name in fit["names"].items():
        rec = recorded["balls"][name]
        ts, xs, ys = paths[sid]
        d = [math.hypot(x - rx, y - ry) * 1000 for x, y, rx, ry in zip(xs, ys, rec["x"], rec["y"])]
        c = colour(name, sid)
        c = "#555555" if c == "#f2f2f2" else c  # white on white would not show
        after = [t - strike for t in ts]
        err.plot(after, d, lw=0.4, color=c, alpha=0.35)
        err.plot(after, running_rms(d, WINDOW), lw=1.5, color=c, label=f"{name} (0.5 s RMS)")
    err.axvline(0, color="k", lw=0.5)
    err.set_xlabel("time after the strike (s)")
    err.set_ylabel("distance recorded to simulated (mm)")
    rmse = fit["rmse_m"]
    err.set_title(f"RMSE {rmse['full'] * 1000:.1f} mm whole shot, {rmse['early'] * 1000:.1f} mm early")
    err.legend(fontsize=8)
    fig.suptitle(f"{fit['id']}: heading {fit['scene']['shot']['heading_deg']:.2f} deg, "
                 f"speed {fit['scene']['shot']['speed']:.3f} m/s, "
                 f"tip {fit['scene']['shot']['tip'][0]:+.2f} {fit['scene']['shot']['tip'][1]:+.2f} R")
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print(json.dumps({"id": fit["id"], "rmse_m": rmse, "out": args.out}))
    # A fit of nineball's own recording is as good as its noise allows: 5 mm a coordinate is
    # 7.1 mm at best; more would mean the search failed.
    if not args.shots and rmse["full"] > 0.012:
        raise SystemExit("the fit missed its own recording: RMSE %.4f m" % rmse["full"])


if __name__ == "__main__":
    main()
