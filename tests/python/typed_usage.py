"""A user's script, typed: test_types.py runs ``mypy --strict`` on it (it must pass, with real
types, no Any) and runs it (the types must describe what the calls return). Not a test file
itself: it only uses the package as a user would."""

import json
from typing import Dict, List, Optional

import nineball
from nineball.types import (Ball, BallState, CalibrateAnswer, FitAnswer, MatchResult,
                            Physics, PlanAnswer, Recording, ResultBall, Scene, TraceColumns)


def stun(heading: float = 0.0, hz: float = 50.0) -> Scene:
    scene: Scene = {"balls": [{"id": 0, "x": -0.6, "y": 0.0}, {"id": 1, "x": 0.0, "y": 0.03}],
                    "shot": {"heading_deg": heading, "speed": 2.0, "tip": [0.0, 0.1]},
                    "trace": {"hz": hz}}
    return scene


def main() -> None:
    # simulate: the result's documented keys have their types.
    r = nineball.simulate(stun())
    x: float = r["balls"][0]["x"]
    pocket: Optional[str] = r["balls"][1]["pocket"]
    balls: List[ResultBall] = r["balls"]
    trace: Dict[str, TraceColumns] = r["trace"]
    xs = trace["0"]["x"]                      # a numpy array of float64
    moved = float(xs[-1] - xs[0])
    physics: Optional[Physics] = r.physics
    assert physics is not None and physics["ball_radius"] > 0
    first = r["events"][0]
    if first["type"] == "ball":
        assert first["a"] == 0 and first["vb"][0] > 0
    assert r["end"] == "rest" and not r["partial"] and r.get("trace") is not None
    print(f"cue ball at {x:.3f} m, moved {moved:.3f} m, the 1 in {pocket}, {len(balls)} balls")

    # simulate_many and iter_simulate: lists and streams of results.
    many = nineball.simulate_many([stun(h) for h in (-1.0, 0.0, 1.0)], threads=2)
    times: List[float] = [res["time"] for res in many]
    streamed = [res["steps"] for res in nineball.iter_simulate(stun(h) for h in (0.5, 1.5))]
    print(len(times), sum(streamed) >= 0)

    # state_at: every ball at an instant.
    states: List[BallState] = nineball.state_at(r, r["time"] / 2)
    speed: float = (states[0]["vx"] ** 2 + states[0]["vy"] ** 2) ** 0.5
    print(f"{states[0]['phase']} at {speed:.3f} m/s")

    # continue_from: a scene again.
    follow: Scene = nineball.continue_from(r, until=0.2)
    assert len(follow["balls"]) == 2

    # Table and rack: the table's numbers and a scene's balls.
    table = nineball.Table("9ft")
    corner = table.pockets[0]
    cue: Ball = {"id": 0, "x": table.head_string_x, "y": 0.0}
    scene: Scene = {"balls": [cue] + nineball.rack("nine-ball", 3),
                    "shot": {"heading_deg": 0.0, "speed": 9.0}}
    r2 = nineball.simulate(scene)
    down = [b["id"] for b in r2["balls"] if b["pocket"] is not None]
    print(f"{corner.id} drops at {corner.drop_radius:.3f} m; the break pots {down}")

    # plan: a shot the scene takes.
    shot: PlanAnswer = nineball.plan(dict(scene, game="ten-ball"), level="club")
    heading: float = shot["heading_deg"]
    call = shot.get("call")
    print(f"plan {heading:.2f} deg" + (f", calls the {call['ball']}" if call else ""))

    # preset: a physics block to change.
    p = nineball.preset("paper")
    p["ball_restitution"] = 0.9
    assert nineball.simulate(dict(stun(), physics=p))["time"] > 0

    # record and fit: a recorded shot and the fits of it.
    recorded: Recording = nineball.record(stun(hz=1), names=["white", "one"], hz=25)
    recorded["id"] = 7
    fits: List[FitAnswer] = nineball.fit(recorded, evals=200)
    for f in fits:
        if "error" in f:
            print("refused:", f["error"])
        else:
            print(f["id"], f["names"]["0"], f"{f['rmse_m']['full'] * 1000:.1f} mm",
                  f["scene"]["balls"][0]["x"], f["warnings"])

    # calibrate: physics from recordings.
    shots = [nineball.record(stun(h, hz=1), hz=25, seed=s) for s, h in enumerate((0.0, 2.0))]
    cal: CalibrateAnswer = nineball.calibrate(shots, ["rolling_friction"], evals=100,
                                              refit_evals=50, candidates=3)
    value: float = cal["parameters"]["rolling_friction"]["value"]
    stderr: Optional[float] = cal["parameters"]["rolling_friction"]["stderr"]
    print(value, stderr, cal["holdout"]["median_rmse_m"], cal["per_shot"][0].get("set"))

    # match: a rack played from a script.
    m: MatchResult = nineball.match({"game": "nine-ball", "seed": 5,
                                     "turns": [{"heading_deg": 0.0, "speed": 10.0}]})
    winner: Optional[str] = m["winner"]
    turn = m["turns"][0]
    print(winner, turn["shooter"], turn["result"], turn.get("pocketed"), m["balls"][0]["x"])

    # to_json: what json.dumps refuses (a trace's arrays).
    assert json.loads(nineball.to_json(r))["time"] == r["time"]


if __name__ == "__main__":
    main()
