"""Game environments for learning agents, in the shape of Gymnasium's API.

    import nineball.env
    env = nineball.env.make("eight-ball", opponent="club", noise="olympiad", seed=1)
    obs, info = env.reset(seed=1)
    obs, reward, terminated, truncated, info = env.step(
        {"heading_deg": 0.0, "speed": 6.0, "cue": [-0.63, 0.0]})

    vec = nineball.env.make_vec("pot", 64, seed=1)       # 64 tables stepped in C++ on every core
    obs, info = vec.reset(seed=1)
    obs, rewards, terminated, truncated, info = vec.step(actions)   # actions: a (64, 7) array

An environment is a game (a rack: the agent breaks as player A, against the computer or both
sides itself) or the task "pot" (the cue ball and the 1 placed at random, one stroke an episode,
paid for the pot). A step is one turn of the agent: a stroke as a dict of a match turn's fields
(``heading_deg``, ``speed``, ``tip``, ``elevation_deg``, and ``cue`` when the ball is in hand,
``call`` when the rules want one, or ``decision`` when one is due), or a row of a flat array.
Its errors come from a named noise model (NOISE_MODELS) and ``info["executed"]`` is the stroke as
played. Rewards, observations and the wrappers: docs/python.md, "Environments".

Gymnasium is optional: when it is installed the environments are its ``Env`` and
``VectorEnv``-shaped, registered as ``nineball/<Game>-v0``, with its spaces; without it they have
the same methods and spaces of their own (``nineball.env.spaces``).
"""

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

from . import _core, types
from . import env_spaces as spaces

__all__ = ["make", "make_vec", "Env", "VecEnv", "FlatActions", "GridActions", "NAMES",
           "NOISE_MODELS", "DEFAULT_REWARDS", "STATE_NAMES", "ACTION_COLUMNS", "spaces"]

#: The environments: the potting task, then every game.
NAMES: Tuple[str, ...] = ("pot",) + tuple(_core.GAMES)
#: The execution-noise models: none, each level's own errors, the Computer Olympiad's (FastFiz's
#: Noise.h) and five times that.
NOISE_MODELS: Tuple[str, ...] = tuple(_core.NOISE_MODELS)
#: What a step pays the agent unless ``rewards`` says otherwise.
DEFAULT_REWARDS: Dict[str, float] = {"pot": 1.0, "point": 1.0, "foul": -1.0, "win": 10.0,
                                     "loss": -10.0}
#: The observation's "state" row, column by column.
STATE_NAMES: Tuple[str, ...] = tuple(_core.Tables.state_names)
#: A flat action's columns.
ACTION_COLUMNS: Tuple[str, ...] = ("heading_deg", "speed", "side", "height", "elevation_deg",
                                   "cue_x", "cue_y")

#: The fastest stroke an action may ask for (m/s), as a scene's shot.
MAX_SPEED = 14.0
#: The highest cue elevation (degrees).
MAX_ELEVATION_DEG = 89.0

Observation = types.Observation
Action = Mapping[str, Any]

try:  # Gymnasium when it is there: its base classes and spaces.
    import gymnasium as _gym

    _EnvBase: Any = _gym.Env
    _space_module: Any = _gym.spaces
except ImportError:  # pragma: no cover - depends on the machine
    _gym = None
    _EnvBase = object
    _space_module = spaces

_WINNERS = {-1: None, 0: "A", 1: "B"}


def _spaces_for(tables: Any, n: Optional[int]) -> Tuple[Any, Any]:
    """The observation space (a Dict of balls, on_table, state) and the dict action's space."""
    import numpy as np

    k = len(tables.ids)
    lead = () if n is None else (n,)
    half = 2.0  # every table's half-length is under 2 m
    observation = _space_module.Dict({
        "balls": _space_module.Box(-half, half, lead + (k, 2), np.float64),
        "on_table": _space_module.MultiBinary(lead + (k,)),
        "state": _space_module.Box(-1.0, 1.0e5, lead + (len(STATE_NAMES),), np.float64),
    })
    action = _space_module.Box(np.array([-180.0, 0.0, -1.0, -1.0, 0.0, -half, -half]),
                               np.array([180.0, MAX_SPEED, 1.0, 1.0, MAX_ELEVATION_DEG, half,
                                         half]), dtype=np.float64)
    if n is not None:
        action = _space_module.Box(np.tile(action.low, (n, 1)), np.tile(action.high, (n, 1)),
                                   dtype=np.float64)
    return observation, action


def _observation(raw: Sequence[Any], row: Optional[int] = None) -> Observation:
    balls, on_table, state = raw[0], raw[1], raw[2]
    if row is not None:
        balls, on_table, state = balls[row], on_table[row], state[row]
    return {"balls": balls, "on_table": on_table, "state": state}


def _executed(row: Any, action: Optional[Mapping[str, Any]]) -> Dict[str, Any]:
    """A row of the executed strokes as the action's dict: the same keys."""
    import math

    if action is not None and "decision" in action:
        return dict(action)
    played: Dict[str, Any] = {"heading_deg": float(row[0]), "speed": float(row[1]),
                              "tip": [float(row[2]), float(row[3])],
                              "elevation_deg": float(row[4])}
    if not math.isnan(row[5]):
        played["cue"] = [float(row[5]), float(row[6])]
    if action is not None and "call" in action:
        played["call"] = dict(action["call"])
    if action is not None and action.get("push_out"):
        played["push_out"] = True
    return played


class VecEnv:
    """``n`` tables of one environment stepped side by side in C++ (the GIL released), seeded
    so that what each table plays depends on the seed alone, never on the threads.

    ``step`` takes a (n, 7) array of flat actions (ACTION_COLUMNS; cue_x, cue_y NaN unless
    placing the ball in hand; a place the ball cannot go, a call or a decision left out is
    filled as the beginner computer would) or a list of n action dicts (checked: a ValueError
    names the table and the field). A table whose episode ends starts its next at once
    (``autoreset``); the step's rewards, flags and info are the ended episode's, its observation
    the new episode's first. Without ``autoreset`` a table whose episode is over stands still
    until ``reset`` (its action ignored: None will do; it reports terminated, reward 0, its
    executed row NaN), so that an evaluation steps until every table is done. Returns the
    observations (a dict of arrays, a row per table), rewards, terminated, truncated and info
    (``executed``: the strokes as played, a (n, 7) array; ``legal``, ``potted``,
    ``opponent_turns``, ``winner``: -1 none, 0 A, 1 B).
    """

    metadata: Dict[str, Any] = {"render_modes": []}

    def __init__(self, name: str, n: int, *, opponent: Optional[str] = None,
                 noise: Optional[str] = None, seed: Optional[int] = None, threads: int = 0,
                 rewards: Optional[Mapping[str, float]] = None, max_turns: int = 200,
                 autoreset: bool = True, engine: str = "reference"):
        if isinstance(n, bool) or not isinstance(n, int):
            raise TypeError("n: expected an int, found " + type(n).__name__)
        self.name = name
        self.num_envs = n
        self.autoreset = autoreset
        self._tables = _core.Tables(name, n, opponent, noise or "none", engine, _seed(seed),
                                    threads, None if rewards is None else dict(rewards),
                                    int(max_turns))
        self.ids: List[int] = list(self._tables.ids)
        #: The table's length and width (m), the origin at its centre.
        self.table_size: Tuple[float, float] = tuple(self._tables.table_size)  # type: ignore
        self.observation_space, self.action_space = _spaces_for(self._tables, n)
        self.single_observation_space, self.single_action_space = _spaces_for(self._tables, None)
        self.opponent = opponent
        self.noise = noise or "none"

    def reset(self, *, seed: Optional[int] = None,
              options: Optional[Mapping[str, Any]] = None) -> Tuple[Observation, Dict[str, Any]]:
        """New episodes on every table. ``options["starts"]``: a position per table (None for
        the game's rack), each ``{"balls", "shooter", "ball_in_hand", "fouls", "groups",
        "score"}`` as a match script writes a rack joined in the middle."""
        starts = None if options is None else options.get("starts")
        raw = self._tables.reset(None if seed is None else _seed(seed), starts)
        return _observation(raw), {}

    def step(self, actions: Any) -> Tuple[Observation, Any, Any, Any, Dict[str, Any]]:
        import numpy as np

        if isinstance(actions, (list, tuple)) and actions and all(
                a is None or isinstance(a, Mapping) for a in actions):
            raw = self._tables.step_dicts(list(actions), self.autoreset)
        else:
            try:
                rows = np.asarray(actions, dtype=float)
            except (TypeError, ValueError):
                raise TypeError("actions: expected a (n, 7) array of numbers (ACTION_COLUMNS) "
                                "or a list of n action dicts") from None
            raw = self._tables.step_array(rows, self.autoreset)
        info = {"executed": raw[6], "legal": raw[7], "potted": raw[8],
                "opponent_turns": raw[9], "winner": raw[10]}
        return _observation(raw), raw[3], raw[4], raw[5], info

    def teacher(self, level: str = "master") -> List[Optional["types.ScriptTurn"]]:
        """The computer's turn at ``level`` for each table's position, as intended (no errors):
        an action dict, None for a table whose episode is over."""
        return self._tables.teacher(level)

    @property
    def last_step_seconds(self) -> float:
        """The wall time the last step spent in C++ (the tables' stepping), for measuring what
        Python costs around it."""
        return float(self._tables.last_step_seconds)

    def close(self) -> None:
        pass


class Env(_EnvBase):  # type: ignore[misc]
    """One table, Gymnasium's ``Env``: ``reset(seed=None, options=None) -> (obs, info)`` and
    ``step(action) -> (obs, reward, terminated, truncated, info)``; the action a dict of a match
    turn's fields. ``info``: ``executed`` (the stroke as played, the action's keys), ``legal``,
    ``potted``, ``opponent_turns`` and ``winner`` ("A", "B" or None)."""

    metadata: Dict[str, Any] = {"render_modes": []}

    def __init__(self, name: str, *, opponent: Optional[str] = None, noise: Optional[str] = None,
                 seed: Optional[int] = None, rewards: Optional[Mapping[str, float]] = None,
                 max_turns: int = 200, engine: str = "reference"):
        self._vec = VecEnv(name, 1, opponent=opponent, noise=noise, seed=seed, threads=1,
                           rewards=rewards, max_turns=max_turns, autoreset=False, engine=engine)
        self.name = name
        self.ids = self._vec.ids
        self.table_size = self._vec.table_size
        self.observation_space = self._vec.single_observation_space
        self.action_space = self._vec.single_action_space
        self._over = False

    def reset(self, *, seed: Optional[int] = None,
              options: Optional[Mapping[str, Any]] = None) -> Tuple[Observation, Dict[str, Any]]:
        """A new episode. ``options["start"]``: the position to start from (``balls`` and the
        standing keys of a match script), else the game's rack (a random pot)."""
        start = None if options is None else options.get("start")
        self._over = False
        try:
            obs, info = self._vec.reset(seed=seed, options={"starts": [start]})
        except ValueError as e:
            raise ValueError(str(e).replace("starts[0]", "start", 1)) from None
        return _observation((obs["balls"], obs["on_table"], obs["state"]), 0), info

    def step(self, action: Union[Action, Any]) -> Tuple[Observation, float, bool, bool,
                                                         Dict[str, Any]]:
        import numpy as np

        given: Optional[Mapping[str, Any]] = action if isinstance(action, Mapping) else None
        if self._over:
            raise ValueError("action: the episode is over: reset the environment")
        try:
            if given is not None:
                obs, reward, terminated, truncated, vinfo = self._vec.step([given])
            else:
                obs, reward, terminated, truncated, vinfo = self._vec.step(
                    np.asarray(action, dtype=float).reshape(1, len(ACTION_COLUMNS)))
        except ValueError as e:
            raise ValueError(str(e).replace("actions[0]", "action", 1)) from None
        self._over = bool(terminated[0])
        info = {"executed": _executed(vinfo["executed"][0], given),
                "legal": bool(vinfo["legal"][0]), "potted": int(vinfo["potted"][0]),
                "opponent_turns": int(vinfo["opponent_turns"][0]),
                "winner": _WINNERS[int(vinfo["winner"][0])]}
        return (_observation((obs["balls"], obs["on_table"], obs["state"]), 0),
                float(reward[0]), bool(terminated[0]), bool(truncated[0]), info)

    def teacher(self, level: str = "master") -> Optional["types.ScriptTurn"]:
        """The computer's turn at ``level`` for the position, as intended: an action."""
        return self._vec.teacher(level)[0]

    def close(self) -> None:
        pass


class FlatActions:
    """An environment whose actions are flat arrays scaled to [-1, 1]: heading (-180 to 180
    degrees), speed (0 to ``max_speed``), side and height (+-``max_tip`` of R), elevation (0 to
    ``max_elevation_deg``), and the ball in hand's x and y (the table's half-length and
    half-width). Values are clipped into the box."""

    def __init__(self, env: Union[Env, VecEnv], max_speed: float = 8.0, max_tip: float = 0.5,
                 max_elevation_deg: float = 0.0):
        import numpy as np

        self.env = env
        length, width = env.table_size
        self._scale = np.array([180.0, max_speed / 2, max_tip, max_tip, max_elevation_deg / 2,
                                length / 2, width / 2])
        self._shift = np.array([0.0, max_speed / 2, 0.0, 0.0, max_elevation_deg / 2, 0.0, 0.0])
        n = getattr(env, "num_envs", None)
        shape = (len(ACTION_COLUMNS),) if n is None else (n, len(ACTION_COLUMNS))
        self.action_space = _space_module.Box(-1.0, 1.0, shape, np.float64)
        self.observation_space = env.observation_space

    def action(self, flat: Any) -> Any:
        """The environment's action for a flat one."""
        import numpy as np

        a = np.clip(np.asarray(flat, dtype=float), -1.0, 1.0) * self._scale + self._shift
        return a

    def reset(self, **kwargs: Any) -> Any:
        return self.env.reset(**kwargs)

    def step(self, flat: Any) -> Any:
        return self.env.step(self.action(flat))


class GridActions:
    """An environment whose actions are integers: ``headings`` directions round the cue ball
    times the ``speeds`` (m/s) times the ``tips`` ([side, height]); action i is heading
    ``i // (len(speeds) * len(tips))``, then speed, then tip. The ball in hand stays where the
    beginner computer would put it."""

    def __init__(self, env: Union[Env, VecEnv], headings: int = 72,
                 speeds: Sequence[float] = (1.0, 2.0, 4.0),
                 tips: Sequence[Sequence[float]] = ((0.0, 0.0),)):
        self.env = env
        self.headings = int(headings)
        self.speeds = [float(s) for s in speeds]
        self.tips = [(float(t[0]), float(t[1])) for t in tips]
        self.n = self.headings * len(self.speeds) * len(self.tips)
        self.action_space = _space_module.Discrete(self.n)
        self.observation_space = env.observation_space

    def action(self, index: Any) -> Any:
        """The environment's flat action (rows) for integer action(s)."""
        import numpy as np

        i = np.asarray(index, dtype=np.int64)
        if np.any((i < 0) | (i >= self.n)):
            raise ValueError(f"action: expected integers from 0 to {self.n - 1}")
        per_heading = len(self.speeds) * len(self.tips)
        heading = (i // per_heading) * (360.0 / self.headings) - 180.0
        speed = np.asarray(self.speeds)[(i // len(self.tips)) % len(self.speeds)]
        tip = np.asarray(self.tips)[i % len(self.tips)]
        rows = np.stack([heading, speed, tip[..., 0], tip[..., 1], np.zeros_like(heading),
                         np.full_like(heading, np.nan), np.full_like(heading, np.nan)], axis=-1)
        return rows

    def reset(self, **kwargs: Any) -> Any:
        return self.env.reset(**kwargs)

    def step(self, index: Any) -> Any:
        return self.env.step(self.action(index))


def _seed(seed: Optional[int]) -> int:
    if seed is None:
        return 0
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise ValueError("seed: expected an int >= 0, found " + repr(seed))
    return seed


def make(name: str, *, opponent: Optional[str] = None, noise: Optional[str] = None,
         seed: Optional[int] = None, rewards: Optional[Mapping[str, float]] = None,
         max_turns: int = 200, engine: str = "reference") -> Env:
    """One table of ``name`` (NAMES: "pot" or a game). ``opponent``: a level of the computer
    ("beginner" ... "master") playing B, else the agent plays both sides (each step's reward
    then belongs to the player who shot it); ``noise``: NOISE_MODELS ("none" by default);
    ``rewards``: DEFAULT_REWARDS' keys to change; ``max_turns``: the agent's turns before an
    episode is truncated; ``engine``: "reference" (the exact event-based engine, the default:
    half Box2D's cost a stroke) or "box2d" (the game window's)."""
    return Env(name, opponent=opponent, noise=noise, seed=seed, rewards=rewards,
               max_turns=max_turns, engine=engine)


def make_vec(name: str, n: int, *, opponent: Optional[str] = None, noise: Optional[str] = None,
             seed: Optional[int] = None, threads: int = 0,
             rewards: Optional[Mapping[str, float]] = None, max_turns: int = 200,
             autoreset: bool = True, engine: str = "reference") -> VecEnv:
    """``n`` tables of ``name`` stepped side by side on ``threads`` threads (0: every core);
    the other arguments as make's."""
    return VecEnv(name, n, opponent=opponent, noise=noise, seed=seed, threads=threads,
                  rewards=rewards, max_turns=max_turns, autoreset=autoreset, engine=engine)


def _register() -> None:
    """Registers every environment with Gymnasium as nineball/<Name>-v0 (nineball/Pot-v0,
    nineball/EightBall-v0, ...)."""
    if _gym is None:
        return
    for name in NAMES:
        env_id = "nineball/" + "".join(part.capitalize() for part in name.split("-")) + "-v0"
        if env_id not in _gym.registry:
            _gym.register(id=env_id, entry_point="nineball.env:make", kwargs={"name": name})


_register()
