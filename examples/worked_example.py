"""A draw shot, cell by cell: the worked example of docs/python.md.

The cells (``# %%``, the percent format that Jupyter, VS Code and jupytext open as a notebook)
are the ones docs/python.md shows, with their printed output and pictures; each imports what it
uses. Run as a script it saves the three pictures in --out (a folder) and checks what the text
says about them; opened as a notebook the pictures go to the notebook's folder.

    PYTHONPATH=build/python /usr/bin/python3 examples/worked_example.py --out build/examples
"""
import argparse
import os
import sys

import matplotlib

if "ipykernel" not in sys.modules:  # a script draws off screen; a notebook shows its pictures
    matplotlib.use("Agg")

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", default=".", help="folder for the pictures")
# parse_known_args: a notebook's kernel has arguments of its own (-f kernel.json).
OUT = parser.parse_known_args()[0].out
os.makedirs(OUT, exist_ok=True)

# %% 1. The table, and a half-ball cut on the 1 into the top-right corner
import os
import numpy as np
import matplotlib.pyplot as plt
import nineball

table = nineball.Table()
corner = next(p for p in table.pockets if p.id == "top-right")
print(table, corner)

R = table.ball_radius
pocket = np.array(corner.drop_centre)
along = (pocket - (0.3, 0.0)) / np.linalg.norm(pocket - (0.3, 0.0))   # the 1's way in
one = pocket - 0.55 * along
ghost = one - 2 * R * along                       # where the cue ball touches the 1
cut = np.radians(30.0)                            # a half-ball hit
path = np.array([np.cos(cut) * along[0] - np.sin(cut) * along[1],
                 np.sin(cut) * along[0] + np.cos(cut) * along[1]])
cue = ghost - 0.6 * path
ghost_heading = np.degrees(np.arctan2(path[1], path[0]))


def shot(heading, tip, speed=2.0, trace=None):
    scene = {"balls": [{"id": 0, "x": cue[0], "y": cue[1]}, {"id": 1, "x": one[0], "y": one[1]}],
             "shot": {"heading_deg": heading, "speed": speed, "tip": [0.0, tip]}}
    if trace:
        scene["trace"] = trace
    return scene


# %% 2. Aim: the ghost-ball line misses with draw; where is the window that pots the 1?
headings = ghost_heading + np.linspace(-1.5, 1.5, 121)
b = nineball.simulate_batch([shot(h, -0.45) for h in headings])   # numpy arrays, a row a shot
pots = b["pocketed"][:, list(b["ids"]).index(1)]
window = headings[pots]
aim = window.mean()
print(f"ghost-ball line {ghost_heading:.2f} deg; the 1 drops from {window.min():.2f} to "
      f"{window.max():.2f} deg: aim {aim - ghost_heading:+.2f} deg off the line (throw)")
r = nineball.simulate(shot(aim, -0.45, trace={"hz": 1}))   # once a second + events + phases
for e in r["events"]:
    who = f'{e["a"]} on {e["b"]}' if e["type"] == "ball" else e.get("ball", "")
    print(f'{e["t"]:.4f} s  {e["type"]:8} {who}')

# %% 3. Where each ball is at any instant: state_at, from the trace's closed forms
def outline(ax):
    loop = np.vstack([table.cushion_loop, table.cushion_loop[:1]])
    ax.fill(loop[:, 0], loop[:, 1], color="#1d6b3a")
    ax.plot(loop[:, 0], loop[:, 1], color="#0b3d1e", lw=1)
    for p in table.pockets:
        ax.add_patch(plt.Circle(p.drop_centre, p.drop_radius, color="black"))
    ax.set_aspect("equal")
    ax.axis("off")


times = np.linspace(0.0, r["time"], 600)
states = [nineball.state_at(r, t) for t in times]       # one list of balls per instant
colour = {"sliding": "#ff8c1a", "rolling": "white", "spinning": "#40c4ff", "rest": "grey",
          "pocketed": "black"}
fig, ax = plt.subplots(figsize=(9, 5))
outline(ax)
for ball in (0, 1):
    xy = np.array([[s[ball]["x"], s[ball]["y"]] for s in states])
    phase = [s[ball]["phase"] for s in states]
    for k in range(len(times) - 1):
        if phase[k] != "pocketed":
            ax.plot(xy[k:k + 2, 0], xy[k:k + 2, 1], color=colour[phase[k]], lw=2.5)
for name in ("sliding", "rolling"):
    ax.plot([], [], color=colour[name], lw=2.5, label=name)
ax.scatter([cue[0], one[0]], [cue[1], one[1]], s=120, c=["white", "gold"], edgecolors="black",
           zorder=3)
ax.legend(loc="lower left", facecolor="#1d6b3a", labelcolor="white")
fig.savefig(os.path.join(OUT, "worked-path.png"), dpi=100, bbox_inches="tight")

# %% 4. The cloth: the slip at the contact point falls at (7/2) mu g until the ball rolls
mu, g = r.physics["sliding_friction"], r.physics["gravity"]
contact = next(e["t"] for e in r["events"] if e["type"] == "ball")
after = np.linspace(contact, contact + 0.5, 400)
cue_ball = np.array([[s[0]["vx"], s[0]["vy"], *s[0]["w"]]
                     for s in (nineball.state_at(r, t) for t in after)])
speed = np.hypot(cue_ball[:, 0], cue_ball[:, 1])
slip = np.hypot(cue_ball[:, 0] - R * cue_ball[:, 3], cue_ball[:, 1] + R * cue_ball[:, 2])
rolls_from = contact + 2.0 * slip[0] / (7.0 * mu * g)          # the paper's sliding time
rolled = next(t for t, s in zip(after, (nineball.state_at(r, t)[0] for t in after))
              if s["phase"] == "rolling")
print(f"slip after the contact {slip[0]:.3f} m/s; rolling from {rolls_from:.4f} s "
      f"(paper), first seen rolling at {rolled:.4f} s (grid of {after[1] - after[0]:.4f} s)")
fig, ax = plt.subplots(figsize=(8, 4))
ax.plot(after - contact, speed, label="speed |v|")
ax.plot(after - contact, slip, label="slip |v + w x r|")
ax.plot(after - contact, np.maximum(slip[0] - 3.5 * mu * g * (after - contact), 0), "k:",
        label="paper: slip0 - (7/2) mu g t")
ax.axvline(rolls_from - contact, color="grey", lw=0.8)
ax.set_xlabel("time after the contact (s)")
ax.set_ylabel("m/s")
ax.legend()
fig.savefig(os.path.join(OUT, "worked-slip.png"), dpi=100, bbox_inches="tight")

# %% 5. From draw to follow: the cue ball's paths, the tangent line and the 30-degree rule
tips = np.linspace(-0.45, 0.45, 10)               # inside the miscue limit (0.5 R)
fig, ax = plt.subplots(figsize=(8, 6))
outline(ax)
turn = []
for tip, res in zip(tips, nineball.iter_simulate(shot(aim, t, trace={"hz": 1}) for t in tips)):
    hit = next(e["t"] for e in res["events"] if e["type"] == "ball")
    cushion = next((e["t"] for e in res["events"] if e["type"] == "cushion"
                    and e["ball"] == 0), res["time"])
    xy = np.array([[s[0]["x"], s[0]["y"]] for s in       # up to the first cushion
                   (nineball.state_at(res, t) for t in np.linspace(0, cushion, 200))])
    ax.plot(xy[:, 0], xy[:, 1], color=plt.cm.coolwarm((tip + 0.45) / 0.9), lw=1.5)
    late = nineball.state_at(res, cushion - 1e-3)[0]       # rolling again, before a cushion
    turn.append(np.degrees(np.arctan2(late["vy"], late["vx"])) - aim)
e = r.physics["ball_restitution"]
k = 2 / 7 + 5 * (1 - e) / 14          # 2/7 for perfectly elastic balls: Alciatore's 30-degree rule
rule = np.degrees(np.arctan2(np.sin(cut), k * np.cos(cut)) - cut)
for turned, style, name in ((90.0 - np.degrees(cut), "--", "tangent line"),
                            (rule, ":", f"30-degree rule, e = {e}")):
    d = np.arctan2(path[1], path[0]) + np.radians(turned)
    ax.plot(*np.transpose([ghost, ghost + 0.9 * np.array([np.cos(d), np.sin(d)])]), "w" + style,
            label=name)
ax.legend(loc="lower right", facecolor="#1d6b3a", labelcolor="white")
ax.scatter([cue[0], one[0]], [cue[1], one[1]], s=120, c=["white", "gold"], edgecolors="black",
           zorder=3)
ax.set_xlim(0.25, 1.35)
ax.set_ylim(-0.3, 0.7)
fig.colorbar(plt.cm.ScalarMappable(plt.Normalize(-0.45, 0.45), "coolwarm"), ax=ax,
             label="tip height (fraction of R; - draw, + follow)", shrink=0.7)
fig.savefig(os.path.join(OUT, "worked-tips.png"), dpi=100, bbox_inches="tight")
print("tip: the cue ball's turn from its first path (deg)\n" + ", ".join(
    f"{t:+.2f}: {a:.1f}" for t, a in zip(tips, turn)) + f"\na rolling ball, the rule: {rule:.1f}")

# %% What the text says, checked (not a cell of the docs)
assert 0.2 < window.max() - window.min() < 2.0, "a pot window of a fraction of a degree"
assert abs(rolled - rolls_from) <= after[1] - after[0], (rolled, rolls_from)
slope = np.polyfit(after[after < rolls_from] - contact, slip[after < rolls_from], 1)[0]
assert abs(slope + 3.5 * mu * g) < 1e-6 * mu * g, slope
# Rolling at the contact (tip -0.05 up, 0.6 m at 2 m/s): the e-corrected rule within 0.5 deg, the
# balls' friction (throw), which the rule leaves out, measured at 0.35 deg at most.
rolling = np.array(turn)[tips > -0.1]
assert np.all(np.abs(rolling - rule) < 0.5), (rolling, rule)
assert turn[0] > 60.0, "a draw shot turns the cue ball back past the tangent line"
print("worked example: checks pass", file=sys.stderr)
