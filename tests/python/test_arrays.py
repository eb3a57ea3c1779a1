"""Arrays in and out (simulate_arrays, simulate_batch, state_at over instants), continue_from
from a result alone, and documents nested too deep refused."""
import math

import pytest

import nineball

np = pytest.importorskip("numpy")


def two_ball_rows(n, seed=1):
    rng = np.random.default_rng(seed)
    places = np.zeros((n, 2, 2))
    places[:, 0] = [-0.6, 0.0]
    places[:, 1, 0] = rng.uniform(0.0, 0.9, n)
    places[:, 1, 1] = rng.uniform(-0.5, 0.5, n)
    shots = np.zeros((n, 5))
    shots[:, 0] = np.degrees(np.arctan2(places[:, 1, 1], places[:, 1, 0] + 0.6))
    shots[:, 1] = rng.uniform(0.5, 3.0, n)
    shots[:, 3] = rng.uniform(-0.4, 0.4, n)
    return places, shots


def scene_of(places, shot):
    return {"balls": [{"id": i, "x": float(x), "y": float(y)} for i, (x, y) in enumerate(places)],
            "shot": {"heading_deg": float(shot[0]), "speed": float(shot[1]),
                     "tip": [float(shot[2]), float(shot[3])], "elevation_deg": float(shot[4])}}


def test_simulate_arrays_gives_each_row_what_simulate_gives_its_scene():
    places, shots = two_ball_rows(40)
    a = nineball.simulate_arrays(places, shots, threads=2)
    assert a["x"].shape == (40, 2) and a["w"].shape == (40, 2, 3)
    assert list(a["ids"]) == [0, 1]
    for i in range(0, 40, 7):
        r = nineball.simulate(scene_of(places[i], shots[i]))
        for j, b in enumerate(sorted(r["balls"], key=lambda b: b["id"])):
            assert a["x"][i, j] == b["x"] and a["y"][i, j] == b["y"]
            assert list(a["w"][i, j]) == b["w"]
            assert a["pocketed"][i, j] == (b["pocket"] is not None)
        counts = {}
        for e in r["events"]:
            counts[e["type"]] = counts.get(e["type"], 0) + 1
        for k, name in enumerate(a["event_types"]):
            assert a["events"][i, k] == counts.get(name, 0)
            first = [e["t"] for e in r["events"] if e["type"] == name]
            if first:
                assert a["first_event_time"][i, k] == first[0]
            else:
                assert math.isnan(a["first_event_time"][i, k])
        assert a["time"][i] == r["time"]


def test_simulate_arrays_takes_one_layout_for_every_row_and_does_not_depend_on_threads():
    places, shots = two_ball_rows(12)
    one = nineball.simulate_arrays(places[0], shots, threads=1)
    two = nineball.simulate_arrays(np.broadcast_to(places[0], places.shape), shots, threads=2)
    for key in ("x", "y", "w", "time", "events"):
        assert np.array_equal(one[key], two[key], equal_nan=True)


def test_simulate_arrays_names_the_row_and_the_shape_it_refuses():
    places, shots = two_ball_rows(3)
    places[2, 1] = places[2, 0]  # ball 1 on the cue ball
    with pytest.raises(ValueError, match="row 2: "):
        nineball.simulate_arrays(places, shots)
    with pytest.raises(ValueError, match="shots: expected an array of shape"):
        nineball.simulate_arrays(places, shots[:, :3])
    with pytest.raises(ValueError, match="ids: the strokes strike the cue ball"):
        nineball.simulate_arrays(places, shots, ids=[1, 2])
    for column, value, field in ((1, 15.0, "speed"), (1, np.nan, "speed"), (0, np.inf, "heading"),
                                 (2, 0.9, "tip"), (4, 90.0, "elevation_deg")):
        bad = shots.copy()
        bad[1, 3] = 0.9 if field == "tip" else bad[1, 3]
        bad[1, column] = value
        with pytest.raises(ValueError, match=r"row 1: " + field):
            nineball.simulate_arrays(places, bad)


def test_simulate_batch_keeps_spins_and_event_times_and_lines_up_ids():
    places, shots = two_ball_rows(5)
    scenes = [scene_of(places[i], shots[i]) for i in range(5)]
    scenes.append({"balls": [{"id": 0, "x": -0.5, "y": 0.0}, {"id": 7, "x": 0.5, "y": 0.0}],
                   "shot": {"heading_deg": 0, "speed": 1.0}})
    b = nineball.simulate_batch(scenes, chunk=2)
    assert list(b["ids"]) == [0, 1, 7]
    assert b["w"].shape == (6, 3, 3)
    assert math.isnan(b["x"][5, 1]) and not math.isnan(b["x"][5, 2])
    assert math.isnan(b["x"][0, 2])
    assert b["events"].shape == (6, len(b["event_types"]))
    ball = b["event_types"].index("ball")
    assert b["events"][5, ball] == 1 and b["first_event_time"][5, ball] > 0


def test_state_at_over_an_array_of_instants_is_state_at_at_each():
    r = nineball.simulate({"balls": [{"id": 0, "x": -0.5, "y": 0}, {"id": 1, "x": 0.5, "y": 0.02}],
                           "shot": {"heading_deg": 0, "speed": 2}, "trace": {"hz": 5}})
    times = np.linspace(0.0, r["time"], 31)
    many = nineball.state_at(r, times)
    assert many["x"].shape == (31, 2) and many["w"].shape == (31, 2, 3)
    for k in (0, 9, 30):
        one = nineball.state_at(r, float(times[k]))
        for j, b in enumerate(one):
            assert many["ids"][j] == b["id"]
            assert many["x"][k, j] == b["x"] and many["vy"][k, j] == b["vy"]
            assert list(many["w"][k, j]) == b["w"]
            assert many["phase"][k, j] == b["phase"]
    with pytest.raises(ValueError, match=r"t\[1\]: "):
        nineball.state_at(r, [0.0, r["time"] + 1.0])


def test_continue_from_a_result_alone_keeps_its_scenes_table_physics_and_masses():
    scene = {"table": "8ft", "physics": {"rolling_friction": 0.02},
             "balls": [{"id": 0, "x": -0.5, "y": 0, "mass": 0.18}, {"id": 1, "x": 0.5, "y": 0.3}],
             "shot": {"heading_deg": 0, "speed": 1.5}, "until": 0.3}
    r = nineball.simulate(scene)
    assert nineball.continue_from(r) == nineball.continue_from(scene, r)
    nxt = nineball.continue_from(r, shot={"heading_deg": 90, "speed": 1.0})
    assert nxt["table"] == "8ft" and nxt["physics"] == {"rolling_friction": 0.02}
    assert nxt["balls"][0]["mass"] == 0.18 and nxt["shot"]["speed"] == 1.0
    with pytest.raises(TypeError, match="continue_from"):
        nineball.continue_from(dict(r))


def test_a_document_nested_too_deep_or_holding_itself_is_a_value_error_not_a_crash():
    scene = {"balls": []}
    scene["table"] = scene
    with pytest.raises(ValueError, match="nested deeper than"):
        nineball.simulate(scene)
    deep = {"balls": []}
    node = deep
    for _ in range(30000):
        node["x"] = {}
        node = node["x"]
    with pytest.raises(ValueError, match="nested deeper than"):
        nineball.simulate(deep)
    shots = [{}]
    shots[0]["self"] = shots
    with pytest.raises(ValueError, match="nested deeper than"):
        nineball.fit(shots)
