"""nineball.env: the game environments (one table and many), their actions, noise, rewards,
starting positions, determinism and wrappers."""
import math

import pytest

np = pytest.importorskip("numpy")

import nineball.env as nenv  # noqa: E402


def ghost_ball_action(obs, pocket=None, speed=2.0):
    """A stroke that sends the cue ball to the ghost ball of the 1 for the nearest corner."""
    (cx, cy), (ox, oy) = obs["balls"][0], obs["balls"][1]
    corners = [(-1.27, -0.635), (-1.27, 0.635), (1.27, -0.635), (1.27, 0.635)]
    px, py = pocket or min(corners, key=lambda p: math.hypot(p[0] - ox, p[1] - oy))
    d = math.hypot(px - ox, py - oy)
    gx, gy = ox - (px - ox) / d * 0.05715, oy - (py - oy) / d * 0.05715
    return {"heading_deg": math.degrees(math.atan2(gy - cy, gx - cx)), "speed": speed}


def test_the_pot_task_is_one_stroke_paid_for_the_pot():
    env = nenv.make("pot", seed=1)
    pots = 0
    for seed in range(30):
        obs, info = env.reset(seed=seed)
        assert env.observation_space.contains(obs) or hasattr(env.observation_space, "spaces")
        assert obs["balls"].shape == (2, 2) and obs["on_table"].all()
        action = ghost_ball_action(obs)
        obs, reward, terminated, truncated, info = env.step(action)
        assert terminated and not truncated
        assert info["executed"]["heading_deg"] == pytest.approx(action["heading_deg"], abs=1e-12)
        assert set(info["executed"]) == {"heading_deg", "speed", "tip", "elevation_deg"}
        if info["potted"] == 1 and info["legal"]:
            assert reward == 1.0 and not obs["on_table"][1]
            pots += 1
        else:
            assert reward in (0.0, -1.0)
    # Ghost-ball aims from anywhere on the table: most drop (cuts past 80 degrees miss).
    assert pots >= 12
    with pytest.raises(ValueError, match="the episode is over"):
        env.step(action)


def test_the_noise_models_err_as_named():
    assert {"none", "olympiad", "olympiad-5x", "beginner", "master"} <= set(nenv.NOISE_MODELS)
    errors = {}
    for noise in ("olympiad", "olympiad-5x"):
        vec = nenv.make_vec("pot", 400, noise=noise, seed=5)
        obs, _ = vec.reset(seed=5)
        actions = np.zeros((400, 7))
        actions[:, 0] = 30.0
        actions[:, 1] = 2.0
        actions[:, 5:] = np.nan
        _, _, _, _, info = vec.step(actions)
        errors[noise] = np.std(info["executed"][:, 0] - 30.0)
        assert np.all(info["executed"][:, 4] >= 0.0)
    # FastFiz's Noise.h: 0.125 degree of aim; five times that (sampling error ~4% at n = 400).
    assert errors["olympiad"] == pytest.approx(0.125, rel=0.15)
    assert errors["olympiad-5x"] == pytest.approx(0.625, rel=0.15)
    with pytest.raises(ValueError, match="noise: unknown model \"olympic\""):
        nenv.make("pot", noise="olympic")


def test_a_vector_environment_plays_the_same_on_any_number_of_threads():
    def run(threads):
        vec = nenv.make_vec("pot", 16, noise="club", seed=11, threads=threads)
        obs, _ = vec.reset(seed=11)
        rng = np.random.default_rng(2)
        out = [obs["balls"].copy()]
        for _ in range(4):
            actions = np.column_stack([rng.uniform(-180, 180, 16), rng.uniform(0.5, 4, 16),
                                       np.zeros(16), np.zeros(16), np.zeros(16),
                                       np.full(16, np.nan), np.full(16, np.nan)])
            obs, reward, terminated, truncated, info = vec.step(actions)
            out += [obs["balls"].copy(), reward.copy(), info["executed"].copy()]
        return out

    for a, b in zip(run(1), run(2)):
        assert np.array_equal(a, b, equal_nan=True)


def test_eight_ball_against_the_computer_plays_to_the_end_of_the_rack():
    env = nenv.make("eight-ball", opponent="club", noise="olympiad", seed=3, max_turns=60)
    obs, info = env.reset(seed=3)
    assert obs["state"][nenv.STATE_NAMES.index("break")] == 1
    total, steps = 0.0, 0
    terminated = truncated = False
    while not (terminated or truncated):
        action = env.teacher("club")
        obs, reward, terminated, truncated, info = env.step(action)
        assert set(info["executed"]) >= {"heading_deg", "speed"} or "decision" in action
        total += reward
        steps += 1
    assert terminated or steps == 60
    if terminated:
        assert info["winner"] in ("A", "B")
        assert (reward >= 10.0 - 1.0) if info["winner"] == "A" else (reward <= -10.0 + 8.0)


def test_a_rack_starts_from_any_game_state():
    env = nenv.make("eight-ball", seed=1)
    start = {"balls": [{"id": 0, "x": -0.5, "y": 0.0}, {"id": 1, "x": 0.5, "y": 0.1},
                       {"id": 9, "x": 0.6, "y": -0.2}, {"id": 8, "x": 0.9, "y": 0.3}],
             "shooter": "B", "ball_in_hand": True, "fouls": {"B": 1},
             "groups": {"A": "stripes"}}
    obs, _ = env.reset(seed=1, options={"start": start})
    state = dict(zip(nenv.STATE_NAMES, obs["state"]))
    assert state["shooter"] == 1 and state["ball_in_hand"] == 1 and state["break"] == 0
    assert state["fouls_shooter"] == 1 and state["group_shooter"] == 1  # B on solids
    assert list(obs["on_table"]) == [b in (0, 1, 8, 9) for b in env.ids]
    obs, reward, terminated, truncated, info = env.step(
        {"heading_deg": 0.0, "speed": 2.0, "cue": [0.0, 0.1]})
    assert info["executed"]["cue"] == [0.0, 0.1]
    with pytest.raises(ValueError, match=r"^start\.fouls\.A: "):
        env.reset(options={"start": dict(start, fouls={"A": 3})})
    with pytest.raises(ValueError, match=r"^start\.balls: eight-ball has no ball 16"):
        env.reset(options={"start": {"balls": [{"id": 0, "x": 0, "y": 0},
                                               {"id": 16, "x": 0.5, "y": 0}]}})


def test_an_action_the_rules_refuse_names_the_table_and_the_field():
    vec = nenv.make_vec("nine-ball", 2, seed=1)
    in_hand = {"balls": [{"id": 1, "x": 0.5, "y": 0.0}, {"id": 9, "x": 0.8, "y": 0.2}],
               "ball_in_hand": True}
    obs, _ = vec.reset(seed=1, options={"starts": [None, in_hand]})
    assert not obs["on_table"][1][0]  # the cue ball waits off the table to be placed
    with pytest.raises(ValueError, match=r"actions\[1\]: the cue ball is in hand"):
        vec.step([{"heading_deg": 0, "speed": 8, "cue": [-0.64, 0.0]},
                  {"heading_deg": 0, "speed": 8}])
    with pytest.raises(ValueError, match=r"actions\[1\]: cue: the cue ball would be on ball 1"):
        vec.step([{"heading_deg": 0, "speed": 8}, {"heading_deg": 0, "speed": 8, "cue": [0.5, 0]}])
    with pytest.raises(ValueError, match=r"actions\[0\]\.speed"):
        vec.step([{"heading_deg": 0, "speed": -1}, {"heading_deg": 0, "speed": 8}])
    with pytest.raises(ValueError, match=r"actions: expected an array of shape \(2, 7\)"):
        vec.step(np.zeros((2, 5)))
    with pytest.raises(ValueError, match="unknown environment"):
        nenv.make("nine-pin")
    with pytest.raises(ValueError, match="opponent: unknown level"):
        nenv.make("nine-ball", opponent="grandmaster")
    with pytest.raises(ValueError, match=r"actions\[0\]: expected a dict of finite numbers"):
        vec.step([{"heading_deg": float("nan"), "speed": 1}, {"heading_deg": 0, "speed": 8}])
    with pytest.raises(TypeError, match="actions: expected a"):
        vec.step("hello")
    for n in (0, -3, 10**7):
        with pytest.raises(ValueError, match="n: expected from 1 to 10000 tables"):
            nenv.make_vec("pot", n)
    with pytest.raises(TypeError, match="rewards.pot: expected a number"):
        nenv.make("pot", rewards={"pot": "x"})


def test_flat_and_grid_actions_drive_a_vector_environment():
    vec = nenv.make_vec("nine-ball", 4, opponent="beginner", seed=2)
    flat = nenv.FlatActions(vec)
    flat.reset(seed=2)
    a = np.zeros((4, 7))
    a[:, 1] = 1.0  # full speed
    a[:, 5] = -0.5  # the ball in hand placed halfway to the head rail
    obs, reward, terminated, truncated, info = flat.step(a)
    assert np.allclose(info["executed"][:, 1], 8.0, atol=0.5)
    grid = nenv.GridActions(nenv.make_vec("pot", 3, seed=4), headings=36, speeds=(1.0, 3.0))
    grid.reset(seed=4)
    assert grid.action_space.n == 72
    obs, reward, terminated, truncated, info = grid.step([0, 35, 71])
    assert list(info["executed"][:, 1]) == [1.0, 3.0, 3.0]
    assert info["executed"][1, 0] == pytest.approx(-180.0 + 17 * 10.0)


def test_custom_rewards_are_paid():
    env = nenv.make("pot", seed=1, rewards={"pot": 5.0, "foul": -2.0})
    for seed in range(10):
        obs, _ = env.reset(seed=seed)
        _, reward, _, _, info = env.step(ghost_ball_action(obs))
        assert reward == (5.0 if info["potted"] and info["legal"] else
                          (-2.0 if not info["legal"] else 0.0))
    with pytest.raises(ValueError, match="rewards.bonus: unknown reward"):
        nenv.make("pot", rewards={"bonus": 1.0})


def test_with_gymnasium_installed_every_environment_is_registered_and_its_env(monkeypatch):
    """Gymnasium is not in Debian: a stand-in with its names shows what nineball.env does
    when it is there."""
    import importlib
    import sys
    import types as pytypes

    registered = {}
    gym = pytypes.ModuleType("gymnasium")

    class GymEnv:
        pass

    gym.Env = GymEnv
    gym.spaces = nenv.spaces
    gym.registry = registered
    gym.register = lambda id, entry_point, kwargs: registered.setdefault(id, (entry_point,
                                                                              kwargs))
    monkeypatch.setitem(sys.modules, "gymnasium", gym)
    try:
        reloaded = importlib.reload(nenv)
        assert registered["nineball/EightBall-v0"] == ("nineball.env:make",
                                                       {"name": "eight-ball"})
        assert registered["nineball/Pot-v0"] == ("nineball.env:make", {"name": "pot"})
        assert len(registered) == len(reloaded.NAMES)
        assert isinstance(reloaded.make("pot"), GymEnv)
    finally:
        monkeypatch.delitem(sys.modules, "gymnasium")
        importlib.reload(nenv)


def test_without_autoreset_a_finished_table_stands_still_until_reset():
    vec = nenv.make_vec("pot", 3, seed=6, autoreset=False)
    obs, _ = vec.reset(seed=6)
    strokes = np.array([[0.0, 1.0, 0.0, 0.0, 0.0, np.nan, np.nan]] * 3)
    _, _, terminated, _, info = vec.step(strokes)
    assert terminated.all() and not np.isnan(info["executed"][:, 1]).any()
    after, reward, terminated, _, info = vec.step([None, None, None])
    assert terminated.all() and (reward == 0).all() and np.isnan(info["executed"]).all()
    again, _, _, _, _ = vec.step(strokes)
    assert np.array_equal(again["balls"], after["balls"])
    vec.reset()
    _, _, terminated, _, info = vec.step(strokes)
    assert not np.isnan(info["executed"][:, 1]).any()
