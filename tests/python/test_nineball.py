"""The Python module against the command line: same results, same refusals."""
import json
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest

import nineball

SOURCE = os.environ.get("NINEBALL_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
# build/python/nineball/__init__.py -> build/nineball
BUILD_PYTHON = os.path.dirname(os.path.dirname(nineball.__file__))
BINARY = os.path.join(BUILD_PYTHON, "..", "nineball")


def stun(speed=2.0, engine="box2d", trace=None):
    scene = {
        "balls": [{"id": 0, "x": -0.6, "y": 0.0}, {"id": 1, "x": 0.0, "y": 0.03}],
        "shot": {"heading_deg": 0, "speed": speed},
        "step": {"engine": engine},
    }
    if trace is not None:
        scene["trace"] = trace
    return scene


def cli(scene):
    """What `nineball sim -` prints and says for the scene."""
    run = subprocess.run([BINARY, "sim", "-"], input=json.dumps(scene), capture_output=True,
                         text=True, check=False)
    return run.returncode, run.stdout, run.stderr


def without_wall_time(doc):
    doc = dict(doc)
    doc.pop("wall_ms")
    return doc


def test_simulate_returns_what_the_command_line_prints():
    scene = stun()
    status, out, _ = cli(scene)
    assert status == 0
    assert without_wall_time(nineball.simulate(scene)) == without_wall_time(json.loads(out))
    # JSON text is a scene too.
    assert without_wall_time(nineball.simulate(json.dumps(scene))) == without_wall_time(
        json.loads(out))


def test_traces_come_as_numpy_arrays_matching_the_json():
    scene = stun(trace={"hz": 100})
    r = nineball.simulate(scene)
    _, out, _ = cli(scene)
    expected = json.loads(out)["trace"]
    assert set(r["trace"]) == {"0", "1"}
    assert r["trace_truncated"] is False
    for ball, t in r["trace"].items():
        for key in ("t", "x", "y", "vx", "vy"):
            assert isinstance(t[key], np.ndarray) and t[key].dtype == np.float64
            np.testing.assert_array_equal(t[key], expected[ball][key])
        assert t["w"].shape == (len(t["t"]), 3)
        np.testing.assert_array_equal(t["w"], expected[ball]["w"])
        assert list(t["phase"]) == expected[ball]["phase"]
    assert r["trace"]["0"]["phase"][1] == "sliding"


@pytest.mark.parametrize("scene, message", [
    ({"balls": [{"id": 0, "x": "left", "y": 0}]}, "balls[0].x: expected a number"),
    ({"balls": [], "colour": 1}, "colour: unknown field"),
    (stun(trace={"hz": 0}), "trace.hz: must be >= 1"),
    (stun(trace={"hz": 5, "events_only": True}), "trace: give either"),
])
def test_bad_scenes_raise_value_error_with_the_command_lines_message(scene, message):
    with pytest.raises(ValueError) as refused:
        nineball.simulate(scene)
    status, out, err = cli(scene)
    assert status == 2 and out == ""
    assert str(refused.value).startswith(message)
    assert err.strip() == "nineball sim: <stdin>: " + str(refused.value)


def test_numpy_numbers_are_accepted_in_a_scene():
    scene = stun()
    scene["shot"]["speed"] = np.float32(2.0)
    scene["balls"][1]["y"] = np.array([0.03])[0]
    assert nineball.simulate(scene)["events"][0]["type"] == "ball"
    with pytest.raises(TypeError):
        nineball.simulate({"balls": [{"id": 0, "x": object(), "y": 0}]})


def test_simulate_many_gives_each_result_in_order():
    scenes = [stun(speed=s, engine=e) for s in (1.0, 2.0, 3.0) for e in ("box2d", "reference")]
    many = nineball.simulate_many(scenes)
    assert len(many) == len(scenes)
    for scene, r in zip(scenes, many):
        assert without_wall_time(r) == without_wall_time(nineball.simulate(scene))
    assert nineball.simulate_many([], threads=1) == []


def test_simulate_many_refuses_before_simulating_and_names_the_scene():
    with pytest.raises(ValueError, match=r"^scenes\[1\]: balls: required field missing"):
        nineball.simulate_many([stun(), {}])
    with pytest.raises(ValueError, match="threads"):
        nineball.simulate_many([stun()], threads=-1)


def test_the_example_in_the_readme_runs(tmp_path, monkeypatch):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    with open(os.path.join(SOURCE, "README.md")) as f:
        readme = f.read()
    example = readme.split("```python\n", 1)[1].split("```", 1)[0]
    os.symlink(os.path.join(SOURCE, "docs"), tmp_path / "docs")
    monkeypatch.chdir(tmp_path)
    exec(compile(example, "README.md", "exec"), {})
    assert (tmp_path / "shot.png").stat().st_size > 1000


def test_simulate_many_releases_the_gil():
    import threading
    import time

    # Balls running to and fro between the short rails without friction for 100 s: long in
    # C++, and handed over as JSON text so that no Python code runs while they are read.
    scene = {"physics": {"preset": "paper", "cloth": "friction", "rolling_friction": 0.0,
                         "ball_restitution": 1.0, "cushion_restitution": 1.0},
             "balls": [{"id": i, "x": 0.1 * i, "y": -0.4 + 0.2 * i, "vx": 5.0} for i in range(5)],
             "until": 100}
    scenes = [json.dumps(scene)] * 3
    done = threading.Event()

    def count_until(deadline):
        n = 0
        while not done.is_set() and time.perf_counter() < deadline:
            n += 1
        return n

    rate = count_until(time.perf_counter() + 0.05) / 0.05
    # One simulation thread, so that a core is left for this one to count on.
    worker = threading.Thread(target=lambda: (nineball.simulate_many(scenes, threads=1), done.set()))
    start = time.perf_counter()
    worker.start()
    counted = count_until(start + 60.0)
    took = time.perf_counter() - start
    worker.join()
    # Holding the GIL, the call would stop this loop for all but its first few milliseconds.
    assert counted > 0.25 * rate * took, (counted, rate, took)


def test_simulate_many_gives_the_same_results_on_any_thread_count():
    with open(os.path.join(SOURCE, "docs", "break.json")) as f:
        scenes = [json.load(f)] * 6
    one = [without_wall_time(r) for r in nineball.simulate_many(scenes, threads=1)]
    two = [without_wall_time(r) for r in nineball.simulate_many(scenes, threads=2)]
    assert one == two
    assert all(r == one[0] for r in one)


def test_without_numpy_traces_are_lists():
    code = (
        "import sys, json\n"
        "sys.modules['numpy'] = None  # import numpy now fails\n"
        "import nineball\n"
        "t = nineball.simulate(json.loads(sys.argv[1]))['trace']['0']\n"
        "assert all(type(t[k]) is list for k in ('t', 'x', 'y', 'vx', 'vy', 'w', 'phase'))\n"
        "assert len(t['w'][0]) == 3 and t['phase'][1] == 'sliding'\n"
        "print(json.dumps(t))\n")
    scene = stun(trace={"hz": 50})
    run = subprocess.run([sys.executable, "-c", code, json.dumps(scene)], capture_output=True,
                         text=True, check=False)
    assert run.returncode == 0, run.stderr
    _, out, _ = cli(scene)
    assert json.loads(run.stdout) == json.loads(out)["trace"]["0"]


def test_a_number_json_cannot_hold_is_named_by_its_field():
    for bad in (float("nan"), float("inf"), -float("inf")):
        scene = stun()
        scene["balls"][1]["x"] = bad
        with pytest.raises(ValueError, match=r"^balls\[1\]\.x: expected a finite number"):
            nineball.simulate(scene)
        with pytest.raises(ValueError, match=r"^scenes\[1\]: balls\[1\]\.x: expected a finite"):
            nineball.simulate_many([stun(), scene])
    scene = stun()
    scene["balls"][0]["w"] = np.array([0.0, np.nan, 0.0])  # inside a numpy array too
    with pytest.raises(ValueError, match=r"^balls\[0\]\.w\[1\]: expected a finite number"):
        nineball.simulate(scene)


def test_simulate_many_refuses_one_scene_passed_alone():
    with pytest.raises(TypeError, match="scenes: expected a list of scenes, found one dict"):
        nineball.simulate_many(stun())
    with pytest.raises(TypeError, match="found one string"):
        nineball.simulate_many(json.dumps(stun()))
    with pytest.raises(TypeError, match="found int"):
        nineball.simulate_many(3)


def test_threads_are_checked_briefly_and_capped_at_the_cores():
    for bad in (True, 1.5, "2", [stun()] * 1000):
        with pytest.raises(TypeError) as refused:
            nineball.simulate_many([stun()], threads=bad)
        assert str(refused.value).startswith("threads: expected an int, found ")
        assert len(str(refused.value)) < 100
    with pytest.raises(ValueError, match="threads: must be >= 0"):
        nineball.simulate_many([stun()], threads=-1)
    # Far more threads than cores: capped, the same results in order, no thread storm.
    many = nineball.simulate_many([stun(speed=1.0 + i / 10) for i in range(6)], threads=5000)
    one = nineball.simulate_many([stun(speed=1.0 + i / 10) for i in range(6)], threads=1)
    assert [without_wall_time(r) for r in many] == [without_wall_time(r) for r in one]


def long_run():
    """A row of 29 balls bouncing end to end without friction for an hour of simulated time:
    about 700,000 events, some seconds of work."""
    return {
        "physics": {"preset": "paper", "rolling_friction": 0.0, "cushion_restitution": 1.0,
                    "ball_restitution": 1.0},
        "step": {"max_time": 3600},
        "balls": [{"id": 0, "x": -1.1, "y": 0.0}]
        + [{"id": i, "x": -1.0 + 0.07 * i, "y": 0.0} for i in range(1, 29)],
        "shot": {"heading_deg": 0, "speed": 6},
    }


def interrupted_after(seconds, call):
    """Runs `call` with Ctrl-C sent to this process after `seconds`; the seconds until it gave
    up with KeyboardInterrupt."""
    import signal
    import threading
    import time

    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    started = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
    finally:
        timer.cancel()
    return time.monotonic() - started


def test_ctrl_c_stops_a_long_run_at_its_next_event():
    assert interrupted_after(0.3, lambda: nineball.simulate(long_run())) < 2.0
    # The module is none the worse: the next call runs as ever.
    assert nineball.simulate(stun())["end"] == "rest"


def test_ctrl_c_stops_a_batch_and_drops_its_results():
    assert interrupted_after(0.3, lambda: nineball.simulate_many([long_run()] * 4)) < 2.0
    assert len(nineball.simulate_many([stun()] * 3)) == 3


def test_thousands_of_threads_asked_for_cannot_abort_the_interpreter():
    # Under a 3 GB address-space limit 3,000 threads could not all start: the interpreter died
    # with SIGABRT. Now the threads are capped at the cores, and a thread that cannot start
    # leaves its work to the others.
    code = (
        "import resource, sys\n"
        "resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))\n"
        "import nineball\n"
        "scene = {'balls': [{'id': 0, 'x': -0.6, 'y': 0}, {'id': 1, 'x': 0, 'y': 0.03}],\n"
        "         'shot': {'heading_deg': 0, 'speed': 2}}\n"
        "print(len(nineball.simulate_many([scene] * 3000, threads=3000)))\n")
    env = dict(os.environ, PYTHONPATH=BUILD_PYTHON)
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=env, check=False, timeout=300)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "3000"


def test_the_module_lends_no_clock_to_other_libraries():
    # The executable mutes gettimeofday for Box2D's unused timers; the module must not export
    # that, or a library loaded after it with RTLD_GLOBAL would read a clock that stands still.
    nm = subprocess.run(["nm", "-D", "--defined-only", nineball._core.__file__],
                        capture_output=True, text=True, check=False)
    if nm.returncode != 0:
        pytest.skip("nm is not installed")
    exported = {line.split()[-1] for line in nm.stdout.splitlines() if line.strip()}
    assert "gettimeofday" not in exported


def test_a_scene_larger_than_the_command_line_reads_is_refused():
    scene = stun()
    scene["note"] = "x" * (5 << 20)
    with pytest.raises(ValueError, match=r"^scene: larger than 4 MiB"):
        nineball.simulate(scene)
    with pytest.raises(ValueError, match=r"^scenes\[0\]: scene: larger than 4 MiB"):
        nineball.simulate_many([scene])


def test_a_truncated_trace_warns():
    scene = stun(trace={"hz": 10000})
    scene["until"] = 120  # two balls at 10 kHz for 2 minutes: past the million samples
    with pytest.warns(RuntimeWarning, match="trace_truncated"):
        result = nineball.simulate(scene)
    assert result["trace_truncated"] is True
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert nineball.simulate(stun(trace={"hz": 100}))["trace_truncated"] is False


def test_a_run_goes_on_from_its_result():
    scene = stun(speed=3.0)
    whole = nineball.simulate(scene)
    first = nineball.simulate(dict(scene, until=0.25))
    assert first["end"] == "until"
    with pytest.raises(ValueError, match="unknown field"):
        nineball.simulate(dict(scene, balls=first["balls"]))  # "pocket" is the result's own
    rest = nineball.simulate(nineball.continue_from(scene, first))
    assert rest["end"] == "rest"
    # Split at 0.25 s or not, the balls stop at the same places (1 mm, the suite's tolerance for
    # the same physics run two ways; the split restarts each ball's arc from printed numbers).
    for a, b in zip(whole["balls"], rest["balls"]):
        assert a["id"] == b["id"]
        assert abs(a["x"] - b["x"]) < 1e-3 and abs(a["y"] - b["y"]) < 1e-3
    # A new shot from there, and a pocketed ball left out.
    again = nineball.continue_from(scene, rest, shot={"heading_deg": 90, "speed": 1.0})
    assert again["shot"]["speed"] == 1.0
    pocketed = dict(rest, balls=[dict(rest["balls"][0]), dict(rest["balls"][1], pocket="top-right")])
    assert [b["id"] for b in nineball.continue_from(scene, pocketed)["balls"]] == [0]
    with pytest.raises(TypeError, match="result: expected the dict simulate returned"):
        nineball.continue_from(scene, [])


def test_a_result_with_a_trace_serialises():
    result = nineball.simulate(stun(trace={"hz": 100}))
    with pytest.raises(TypeError):
        json.dumps(result)  # numpy arrays: the standard encoder refuses them
    back = json.loads(nineball.to_json(result))
    assert back["trace"]["0"]["x"] == result["trace"]["0"]["x"].tolist()
    assert back["balls"] == result["balls"]


def test_every_call_has_a_signature_and_a_docstring():
    import inspect
    import pydoc

    page = pydoc.render_doc(nineball)
    calls = [name for name in nineball.__all__ if callable(getattr(nineball, name))
             and not name.startswith("_") and name not in ("Scene",)]
    assert len(calls) >= 14, calls
    for name in calls:
        call = getattr(nineball, name)
        if not isinstance(call, type):
            assert inspect.signature(call).parameters, name
        assert call.__doc__ and len(call.__doc__) > 40, name
        assert name in page, name
    assert inspect.signature(nineball.simulate_many).parameters["threads"].default == 0
    package = os.path.dirname(nineball.__file__)
    assert os.path.exists(os.path.join(package, "py.typed"))
    assert os.path.exists(os.path.join(package, "_core.pyi"))


def break_scene(trace):
    with open(os.path.join(SOURCE, "docs", "break.json")) as f:
        scene = json.load(f)
    scene["trace"] = trace
    return scene


def test_state_at_is_the_run_itself_at_any_instant():
    # A break traced once a second (plus its events and phase changes) gives, at every instant
    # of a 400 Hz trace of the same run, that trace's own sample: both are the engine's closed
    # forms, read from different starting points, so they agree to rounding (1e-11 m, m/s,
    # rad/s: some 300 times the 2.8e-14 measured), where a straight line between samples misses
    # by centimetres.
    coarse = nineball.simulate(break_scene({"hz": 1}))
    fine = nineball.simulate(break_scene({"hz": 400}))
    assert coarse["balls"] == fine["balls"]
    ids = list(fine["trace"])
    times = fine["trace"][ids[0]]["t"]
    assert len(times) > len(coarse["trace"][ids[0]]["t"]) * 20
    worst = 0.0
    for k in range(0, len(times), 3):
        states = nineball.state_at(coarse, times[k])
        assert [str(s["id"]) for s in states] == ids
        for s in states:
            sample = fine["trace"][str(s["id"])]
            assert s["phase"] == sample["phase"][k], (s["id"], times[k])
            for key in ("x", "y", "vx", "vy"):
                worst = max(worst, abs(s[key] - sample[key][k]))
            worst = max(worst, float(np.max(np.abs(np.array(s["w"]) - sample["w"][k]))))
    assert worst < 1e-11, worst
    # A pocketed ball says where it dropped.
    end = nineball.state_at(coarse, coarse["time"])
    dropped = {b["id"]: b["pocket"] for b in coarse["balls"] if b["pocket"] is not None}
    assert dropped
    assert {s["id"]: s["pocket"] for s in end if s["pocket"] is not None} == dropped
    assert all(s["phase"] == "pocketed" for s in end if s["pocket"] is not None)


def test_state_at_needs_a_trace_an_instant_of_the_run_and_the_physics():
    scene = stun(trace={"hz": 1}, engine="reference")
    result = nineball.simulate(scene)
    with pytest.raises(ValueError, match="has no trace"):
        nineball.state_at(nineball.simulate(stun()), 0.1)
    with pytest.raises(ValueError, match="outside the run"):
        nineball.state_at(result, result["time"] + 0.1)
    with pytest.raises(ValueError, match="outside the run"):
        nineball.state_at(result, -0.1)
    events_only = nineball.simulate(stun(trace={"events_only": True}, engine="reference"))
    with pytest.raises(ValueError, match="before the trace's first sample"):
        nineball.state_at(events_only, 0.01)
    with pytest.raises(TypeError, match="t: expected a number"):
        nineball.state_at(result, "0.1")
    # Read back from JSON, a result is a plain dict: the scene gives its physics.
    plain = json.loads(nineball.to_json(result))
    with pytest.raises(ValueError, match="scene: needed"):
        nineball.state_at(plain, 0.2)
    assert nineball.state_at(plain, 0.2, scene) == nineball.state_at(result, 0.2)
    # The physics the run used, not the scene's later changes nor the default.
    slow_cloth = dict(scene, physics={"rolling_friction": 0.03})
    slow = nineball.simulate(slow_cloth)
    assert slow.physics["rolling_friction"] == 0.03
    assert nineball.state_at(slow, 0.8) == nineball.state_at(json.loads(nineball.to_json(slow)),
                                                             0.8, slow_cloth)
    assert nineball.state_at(slow, 0.8)[0]["x"] != nineball.state_at(result, 0.8)[0]["x"]


def test_a_result_keeps_its_physics_through_pickle_and_json():
    import pickle

    result = nineball.simulate(stun(trace={"hz": 1}))
    assert isinstance(result, dict) and isinstance(result, nineball.Result)
    back = pickle.loads(pickle.dumps(result))
    assert back.physics == result.physics == nineball.preset("real")
    assert nineball.state_at(back, 0.3) == nineball.state_at(result, 0.3)
    assert json.loads(nineball.to_json(result))["balls"] == result["balls"]


def test_iter_simulate_streams_in_order_a_chunk_at_a_time():
    speeds = [1.0 + i / 20 for i in range(11)]
    whole = nineball.simulate_many([stun(speed=s) for s in speeds])
    produced = []

    def scenes():  # a generator: no len(), read lazily
        for s in speeds:
            produced.append(s)
            yield stun(speed=s)

    stream = nineball.iter_simulate(scenes(), chunk=4, progress=False)
    first = next(stream)
    assert len(produced) == 4, "one chunk read, not the whole batch"
    rest = list(stream)
    assert [without_wall_time(r) for r in [first] + rest] == [without_wall_time(r) for r in whole]
    bad = [stun() for _ in range(6)]
    bad[5]["balls"][0]["x"] = "left"
    with pytest.raises(ValueError, match=r"^scenes\[5\]: balls\[0\]\.x"):
        list(nineball.iter_simulate(bad, chunk=4, progress=False))
    with pytest.raises(ValueError, match="chunk"):
        list(nineball.iter_simulate([stun()], chunk=0))
    with pytest.raises(TypeError, match="found one dict"):
        list(nineball.iter_simulate(stun()))


def test_simulate_batch_gives_final_states_as_arrays():
    speeds = [1.0, 2.0, 3.0]
    batch = nineball.simulate_batch([stun(speed=s) for s in speeds], progress=False)
    results = nineball.simulate_many([stun(speed=s) for s in speeds])
    assert batch["ids"].tolist() == [0, 1]
    assert batch["x"].shape == (3, 2)
    for k, r in enumerate(results):
        for j, b in enumerate(r["balls"]):
            assert batch["x"][k, j] == b["x"] and batch["y"][k, j] == b["y"]
            assert batch["pocketed"][k, j] == (b["pocket"] is not None)
        assert batch["time"][k] == r["time"]
        for j, name in enumerate(batch["event_types"]):
            assert batch["events"][k, j] == sum(e["type"] == name for e in r["events"])


def test_a_long_batch_shows_its_progress(capsys):
    pytest.importorskip("tqdm")
    results = list(nineball.iter_simulate([stun()] * 5, chunk=2, progress=True))
    assert len(results) == 5
    err = capsys.readouterr().err
    assert "5/5" in err, err


def test_the_table_as_the_physics_builds_it():
    t = nineball.Table()
    assert (t.length, t.width) == (2.54, 1.27)
    assert [p.id for p in t.pockets] == ["top-left", "top-side", "top-right", "bottom-right",
                                         "bottom-side", "bottom-left"]
    assert t.foot_spot == (t.length / 4, 0.0) and t.head_string_x == -t.length / 4
    assert t.cushion_loop.shape[1] == 2 and len(t.cushion_loop) > 20
    assert nineball.Table("7ft").length < t.length
    with pytest.raises(ValueError, match="table"):
        nineball.Table("12ft")


def test_a_standard_rack_fits_the_table_and_repeats_by_seed():
    t = nineball.Table()
    for game, n in (("nine-ball", 9), ("eight-ball", 15), ("ten-ball", 10)):
        balls = nineball.rack(game, seed=3)
        assert sorted(b["id"] for b in balls) == list(range(1, n + 1)), game
        assert nineball.rack(game, seed=3) == balls
        scene = {"balls": [{"id": 0, "x": t.head_string_x, "y": 0.0}] + balls}
        assert nineball.simulate(scene)["end"] == "rest", game  # a valid scene, at rest
    assert nineball.rack("nine-ball", 1)[0] == {"id": 1, "x": t.foot_spot[0], "y": 0.0}
    with pytest.raises(ValueError, match="unknown game"):
        nineball.rack("crokinole")


def test_plan_is_what_the_command_line_plans():
    scene = {"balls": [{"id": 0, "x": -0.6, "y": 0.0}, {"id": 1, "x": 0.0, "y": 0.03},
                       {"id": 2, "x": 0.5, "y": -0.3}]}
    shot = nineball.plan(scene, level="club")
    run = subprocess.run([BINARY, "plan", "-"], input=json.dumps(dict(scene, level="club")),
                         capture_output=True, text=True, check=True)
    assert shot == json.loads(run.stdout)
    with pytest.raises(ValueError, match="unknown level"):
        nineball.plan(scene, level="grandmaster")


def test_a_sweep_runs_on_a_dask_cluster_in_order():
    distributed = pytest.importorskip("distributed")
    import nineball.dask

    scenes = [stun(speed=1.0 + i / 10) for i in range(9)]
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        on_cluster = nineball.dask.simulate(client, scenes, chunk=2)
        bad = list(scenes)
        bad[7] = dict(stun(), balls=[{"id": 0, "x": "left", "y": 0}])
        with pytest.raises(ValueError, match=r"scenes\[7\]: balls\[0\]\.x"):
            nineball.dask.simulate(client, bad, chunk=2)
    here = nineball.simulate_many(scenes)
    assert [without_wall_time(r) for r in on_cluster] == [without_wall_time(r) for r in here]


def test_the_package_works_without_dask():
    code = ("import sys; sys.modules['dask'] = None; sys.modules['distributed'] = None\n"
            "import nineball\n"
            "print(nineball.simulate({'balls': [{'id': 0, 'x': 0, 'y': 0}]})['end'])\n")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=dict(os.environ, PYTHONPATH=BUILD_PYTHON), check=False)
    assert run.returncode == 0 and run.stdout.strip() == "rest", run.stderr


def test_a_preset_with_every_parameter_reads_back_as_itself():
    for name in nineball.PRESETS:
        physics = nineball.preset(name)
        # carom's balls are 61.5 mm, snooker's 52.5 mm
        radius = {"carom": 0.03075, "snooker": 0.02625}.get(name, 0.028575)
        assert physics["ball_radius"] == radius and "cloth" in physics, name
        by_name = nineball.simulate(dict(stun(), physics={"preset": name}))
        spelled_out = nineball.simulate(dict(stun(), physics=physics))
        assert without_wall_time(spelled_out) == without_wall_time(by_name), name
    real = nineball.preset("real")
    real["cushion_restitution"] = 0.5
    assert nineball.simulate(dict(stun(speed=3.0), physics=real))["balls"] != \
        nineball.simulate(dict(stun(speed=3.0), physics={"preset": "real"}))["balls"]
    with pytest.raises(ValueError, match="unknown preset"):
        nineball.preset("fast")


def test_match_is_what_the_command_line_plays():
    script = {"game": "nine-ball", "seed": 3, "players": {"A": "ai:club", "B": "ai:casual"}}
    played = nineball.match(script)
    run = subprocess.run([BINARY, "match", "-"], input=json.dumps(script), capture_output=True,
                         text=True, check=True)
    assert played == json.loads(run.stdout)
    assert played["winner"] in ("A", "B") and played["partial"] is False
    with pytest.raises(ValueError, match=r"^turns\[0\]"):
        nineball.match({"seed": 1, "turns": [{"heading_deg": 0, "speed": 1, "cue": [5, 5]}]})
    with pytest.raises(ValueError, match="players.A: unknown player"):
        nineball.match({"players": {"A": "ai:grandmaster"}})


def test_ball_ids_from_a_numpy_float_array_are_taken():
    table = np.array([[0.0, -0.6, 0.0], [1.0, 0.0, 0.03]])  # id, x, y as one float array
    scene = {"balls": [{"id": row[0], "x": row[1], "y": row[2]} for row in table],
             "shot": {"heading_deg": 0, "speed": 2.0}}
    assert without_wall_time(nineball.simulate(scene)) == without_wall_time(nineball.simulate(stun()))
    scene["balls"][1]["id"] = 1.5
    with pytest.raises(ValueError, match=r"balls\[1\]\.id: expected an integer"):
        nineball.simulate(scene)


def test_the_documented_commands_name_the_python_the_module_is_built_for():
    # `PYTHONPATH=build/python python3 ...` fails where the first python3 on the PATH is not
    # Debian's (no numpy, no matplotlib, another ABI): the docs name /usr/bin/python3.
    import re

    for doc in ("README.md", "docs/python.md", "examples/cut_angle_sweep.py",
                "examples/dask_pot_map.py", "examples/bench_plot.py"):
        with open(os.path.join(SOURCE, doc), encoding="utf-8") as f:
            text = f.read()
        assert not re.search(r"PYTHONPATH=\S+ python3 ", text), doc
        assert not re.search(r"^\s*python3 examples/", text, re.M), doc


def test_the_worked_example_in_the_docs_is_the_script_ctest_runs():
    # docs/python.md shows examples/worked_example.py cell by cell; Examples.WorkedExample runs
    # the script and checks what the text says, so the two must not drift apart.
    import re

    with open(os.path.join(SOURCE, "docs", "python.md")) as f:
        docs = f.read()
    section = docs[docs.index("## A worked example"):docs.index("## API reference")]
    shown = re.findall(r"\*\*(\d\. [^*]+)\*\*.*?```python\n(.*?)```", section, re.S)
    with open(os.path.join(SOURCE, "examples", "worked_example.py")) as f:
        cells = re.split(r"(?m)^# %% ", f.read())[1:]
    script = {c.splitlines()[0]: "\n".join(c.splitlines()[1:]).strip() for c in cells}
    assert len(shown) == 5
    for title, code in shown:
        assert script.get(title) == code.strip(), title


def carom_scene(heading_deg=19.0, speed=3.0, tip=(0.2, 0.1)):
    return {"table": "carom", "physics": {"preset": "carom"},
            "balls": [{"id": 0, "x": -0.6, "y": -0.25}, {"id": 1, "x": -0.15, "y": -0.1},
                      {"id": 2, "x": 0.9, "y": 0.45}],
            "shot": {"heading_deg": heading_deg, "speed": speed, "tip": list(tip)},
            "step": {"engine": "reference"}}


def test_fit_is_what_the_command_line_prints_and_finds_the_shot(tmp_path):
    shot = nineball.record(carom_scene(), ["white", "yellow", "red"], strike=0.83)
    assert sorted(shot["balls"]) == ["red", "white", "yellow"]
    assert shot["balls"]["white"]["t"][0] == 0.0
    got = nineball.fit(shot, evals=3000)[0]
    path = tmp_path / "shot.json"
    path.write_text(json.dumps(shot))
    out = subprocess.run([BINARY, "fit", str(path), "--evals", "3000"], check=True,
                         capture_output=True, text=True).stdout
    assert json.loads(out) == got
    assert list(got) == ["id", "scene", "names", "strike_time", "rmse_m", "evals", "warnings",
                         "unreproduced"]
    assert got["unreproduced"] == []
    # The printed scene simulates (it is a complete scene of nineball sim).
    assert nineball.simulate(got["scene"])["end"] == "rest"
    assert abs(got["strike_time"] - 0.83) < 0.01


def test_fit_and_calibrate_refuse_bad_input_by_name():
    shot = nineball.record(carom_scene(), ["white", "yellow", "red"])
    broken = json.loads(json.dumps(shot))
    broken["balls"]["red"]["x"] = broken["balls"]["red"]["x"][:-1]
    # A refused shot has its dict in its place, as the command line's line; the others are fitted.
    impossible = {"id": 7, "balls": {"white": {"t": [0, 1e-200], "x": [-0.6, -0.5994],
                                               "y": [0, 0]}}}
    got = nineball.fit([shot, broken, impossible], evals=100)
    assert len(got) == 3 and "rmse_m" in got[0]
    assert list(got[1]) == ["id", "error"] and got[1]["error"].startswith("balls.red")
    assert got[2] == {"id": 7, "error": "balls.white: samples 0-1 imply 6e+196 m/s"}
    # What holds no shot at all is refused whole.
    with pytest.raises(ValueError, match="invalid JSON"):
        nineball.fit("[{", evals=100)
    with pytest.raises(ValueError, match="objective"):
        nineball.fit(shot, objective="late")
    with pytest.raises(ValueError, match="nonsense"):
        nineball.calibrate([shot], ["nonsense"])
    with pytest.raises(ValueError, match="shot 2: balls.white: samples 0-1 imply 6e"):
        nineball.calibrate([shot, impossible], ["rolling_friction"])


def test_fit_takes_repeated_times_and_gives_an_integer_id_back():
    shot = nineball.record(carom_scene(), ["white", "yellow", "red"])
    shot["id"] = 123
    for ball in shot["balls"].values():
        ball["t"][5::5] = ball["t"][4:-1:5]
    got = nineball.fit(shot, evals=200)[0]
    assert got["id"] == 123
    assert isinstance(got["warnings"], list)


def test_calibrate_returns_physics_a_scene_takes():
    shots = [nineball.record(carom_scene(h, v), ["white", "yellow", "red"], seed=k)
             for k, (h, v) in enumerate([(19.0, 3.0), (12.0, 2.5), (25.0, 3.5)])]
    got = nineball.calibrate(shots, "rolling_friction", holdout=0.0, evals=300, refit_evals=20,
                             candidates=4)
    assert list(got) == ["physics", "parameters", "uncertainty", "correlation", "converged",
                         "convergence", "train", "holdout", "per_shot"]
    assert list(got["parameters"]) == ["rolling_friction"]
    assert got["parameters"]["rolling_friction"]["value"] == got["physics"]["rolling_friction"]
    assert got["uncertainty"] == {"method": "bootstrap over shots", "resamples": 200}
    assert got["correlation"] == [[1.0]]
    assert isinstance(got["converged"], bool) and got["convergence"]
    assert list(got["train"]) == ["median_rmse_m", "shots", "unreproduced_balls"]
    assert got["train"]["shots"] == 3 and got["holdout"]["shots"] == 0
    assert got["holdout"]["median_rmse_m"] is None
    assert nineball.simulate(dict(carom_scene(), physics=got["physics"]))["end"] == "rest"
