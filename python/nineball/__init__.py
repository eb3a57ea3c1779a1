"""nineball: the pool table's physics, headless.

The same parser, checks, engines and result format as the command ``nineball sim``: a scene
(a dict, or its JSON text) in, the result dict out, trajectories as numpy arrays when numpy is
installed. A bad scene raises ValueError with the command line's message, naming the field.

- simulate(scene): one scene.
- simulate_many(scenes, threads=0): many, in order, on every core.
- continue_from(result, shot=None, until=None): the scene that goes on from a result.
- to_json(doc): a result or scene as JSON text, numpy arrays as lists.
- state_at(result, t, scene=None): every ball at any instant of a traced run, exactly.
- iter_simulate(scenes, threads=0, chunk=256, progress=None): results streamed in order,
  at most a chunk held at a time; a progress bar (tqdm) for long batches.
- simulate_batch(scenes, threads=0): final states, spins, event counts and times as arrays.
- simulate_arrays(places, shots, ids=None, ...): arrays of ball places and strokes in, arrays out.
- nineball.env: game environments for learning agents (make, make_vec).
- Table(table="9ft", physics=None): the table as the physics builds it.
- rack(game="nine-ball", seed=1, table="9ft"): the balls of a standard rack.
- plan(scene, level=None, game=None, ...): the shot the computer would play.
- match(script): a rack played from a match script, computer players included.
- preset(name) / PRESETS: the physics presets ("real", "paper", "carom", "snooker") with every parameter.
- record(scene, names=None, ...): a scene as a tracker would record it (a recorded shot).
- fit(shots, evals=12000, ...): the shot that best reproduces each recorded shot.
- calibrate(shots, params, holdout=0.5, ...): physics parameters fitted to recorded shots.
- Result: what the simulations return, a dict that keeps its run's physics (.physics).
- nineball.dask.simulate(client, scenes): a sweep on a Dask cluster (optional).
- nineball.plot: pictures of tables, shots and fits, and animations (matplotlib).
- nineball.types: the scene, result, recording and answers as TypedDicts, for type checkers.

Ctrl-C stops a run at its next event and raises KeyboardInterrupt. The scene and result
formats: docs/cli.md; this package: docs/python.md.
"""

import itertools
import json
from typing import (TYPE_CHECKING, Any, Dict, Iterable, Iterator, List, Literal, Mapping,
                    Optional, Sequence, Sized, Tuple, TypeVar, Union, cast, overload)

from . import _core
from . import types

__version__: str = _core.__version__

#: A scene of ``nineball sim``: a dict (numpy numbers and arrays allowed) or its JSON text.
#: nineball.types.Scene spells out its fields for a type checker.
Scene = Union[types.Scene, Mapping[str, Any], str]

_T = TypeVar("_T")

if TYPE_CHECKING:
    # A checker sees a dict of str to object whose documented keys have their own types
    # (the overloads below); at run time Result is a plain dict subclass, indexing at C speed.
    _ResultBase = Dict[str, object]
else:
    _ResultBase = dict


class Result(_ResultBase):
    """A result of ``nineball sim`` as Python objects: the dict the command prints.

    It also remembers the physics its run used (``physics``), which state_at reads; it
    pickles (to Dask workers and back) and ``json.dumps`` as the plain dict it is.

    To a type checker its documented keys have the types of nineball.types.ResultDoc
    (``r["balls"]`` is a List[ResultBall], ``r.get("trace")`` an Optional[Dict[str,
    TraceColumns]]) and any other key is an ``object``.
    """

    if TYPE_CHECKING:
        # The keys of types.ResultDoc, one overload each (a TypedDict can hold no property,
        # and no class is both a TypedDict and a dict subclass). tests/python/test_types.py
        # checks that each reads as ResultDoc's does.
        @overload
        def __getitem__(self, key: Literal["time"]) -> float: ...
        @overload
        def __getitem__(self, key: Literal["steps"]) -> int: ...
        @overload
        def __getitem__(self, key: Literal["wall_ms"]) -> float: ...
        @overload
        def __getitem__(self, key: Literal["end"]) -> types.End: ...
        @overload
        def __getitem__(self, key: Literal["partial"]) -> bool: ...
        @overload
        def __getitem__(self, key: Literal["balls"]) -> List[types.ResultBall]: ...
        @overload
        def __getitem__(self, key: Literal["events"]) -> List[types.Event]: ...
        @overload
        def __getitem__(self, key: Literal["trace"]) -> Dict[str, types.TraceColumns]: ...
        @overload
        def __getitem__(self, key: Literal["trace_truncated"]) -> bool: ...
        @overload
        def __getitem__(self, key: str) -> object: ...

        def __getitem__(self, key: str) -> object:
            return super().__getitem__(key)

        # dict.get's own overloads cannot be matched one for one by these, hence the ignore.
        @overload  # type: ignore[override]
        def get(self, key: Literal["trace"]) -> Optional[Dict[str, types.TraceColumns]]: ...
        @overload
        def get(self, key: Literal["trace"],
                default: _T) -> Union[Dict[str, types.TraceColumns], _T]: ...
        @overload
        def get(self, key: Literal["trace_truncated"]) -> Optional[bool]: ...
        @overload
        def get(self, key: Literal["trace_truncated"], default: _T) -> Union[bool, _T]: ...
        @overload
        def get(self, key: str) -> Optional[object]: ...
        @overload
        def get(self, key: str, default: _T) -> Union[object, _T]: ...

        def get(self, key: str, default: object = None) -> object:
            return super().get(key, default)

    def __init__(self, doc: Union[Mapping[str, object], Iterable[Tuple[str, object]]] = (),
                 physics_json: Optional[str] = None) -> None:
        super().__init__(doc)
        self._physics_json = physics_json

    @property
    def physics(self) -> Optional[types.Physics]:
        """The physics the run used, every parameter, as a scene's "physics" object (a copy);
        None for a result built from a plain dict."""
        if self._physics_json is None:
            return None
        return cast(types.Physics, json.loads(self._physics_json))


#: The named tables, as a scene's "table" takes them.
TABLES = _core.TABLES

__all__ = ["TABLES", "simulate", "simulate_many", "continue_from", "to_json", "state_at", "iter_simulate",
           "simulate_batch", "simulate_arrays", "Table", "Pocket", "rack", "plan", "match", "preset", "PRESETS", "Scene",
           "Result", "record", "fit", "calibrate",
           "__version__"]

#: A batch at least this long shows a progress bar when tqdm is installed (progress=None).
PROGRESS_FROM = 1000


def simulate(scene: Scene) -> Result:
    """Simulates one scene and returns its result.

    The result is what ``nineball sim`` prints, as dicts and lists; a trace's columns come as
    numpy arrays when numpy is installed. The GIL is released while it runs; Ctrl-C stops it
    at the next event (KeyboardInterrupt).

    Raises ValueError for a bad scene (the command line's message, naming the field) and
    RuntimeError for an internal error.
    """
    return _core.simulate(scene)


def simulate_many(scenes: Iterable[Scene], threads: int = 0) -> List[Result]:
    """Checks every scene, then simulates them all; the results in the scenes' order.

    ``threads``: 0 for one per core; more than the cores are capped to them. The results do
    not depend on it. A bad scene raises ValueError naming ``scenes[i]`` and the field; one
    scene passed alone (a dict or a string) raises TypeError. Ctrl-C stops every run at its
    next event and starts no more (KeyboardInterrupt, the results dropped).
    """
    return _core.simulate_many(scenes, threads)


def continue_from(scene: Any, result: Optional[Mapping[str, Any]] = None,
                  shot: Optional[Mapping[str, Any]] = None,
                  until: Optional[float] = None) -> types.Scene:
    """The scene that goes on from where a result stopped: ``continue_from(result)`` (a result
    simulate returned knows its scene's table, physics and step) or ``continue_from(scene,
    result)`` (a result read back from JSON, with the scene it came from).

    It keeps the scene's table, physics and step, puts every ball still on the table where and
    as the result left it (its mass from the scene), and adds ``shot`` and ``until`` when given
    (else the balls roll on to rest). Feed it to simulate.
    """
    if result is None:
        setting = getattr(scene, "_setting", None)
        if setting is None:
            raise TypeError("continue_from(result) takes a result simulate returned; for a plain "
                            "dict pass the scene it came from: continue_from(scene, result)")
        scene, result = setting, scene
    return _core.continue_from(scene, result, shot, until)


def to_json(doc: Union[Result, Mapping[str, Any]]) -> str:
    """A result (or a scene) as JSON text, a trace's numpy arrays written as lists."""
    return _core.to_json(doc)


@overload
def state_at(result: Mapping[str, Any], t: float,
             scene: Optional[Scene] = None) -> List[types.BallState]: ...
@overload
def state_at(result: Mapping[str, Any], t: Union[Sequence[float], types.FloatArray],
             scene: Optional[Scene] = None) -> types.StatesAtTimes: ...


def state_at(result: Mapping[str, Any], t: Any,
             scene: Optional[Scene] = None) -> Union[List[types.BallState], types.StatesAtTimes]:
    """Every ball of a traced run at time ``t`` (s), exactly: one dict per ball, in the
    trace's order, with ``id``, ``x``, ``y`` (m), ``vx``, ``vy`` (m/s), ``z`` (m, the height
    above resting on the cloth), ``vz`` (m/s), ``w`` ([wx, wy, wz], rad/s), ``phase``
    ("sliding", "rolling", "spinning", "rest", "airborne", "pocketed") and ``pocket`` (the
    pocket's name once it has dropped, else None).

    The state is the ball's last sample at or before ``t`` carried on by the closed form of
    its free motion (the cloth's sliding, rolling and spinning), under the physics the run
    used: no event lies between (every event's instant is sampled), so it is the run's own
    motion at any instant, never an interpolation. The smallest trace that covers the whole
    run is ``"trace": {"hz": 1}`` (an events-only trace starts at the first event).

    ``result`` must carry a trace; ``scene`` (the scene it came from) is needed only when
    ``result`` is a plain dict (read back from JSON, say), for its physics. ``t`` outside the
    run (or past a truncated trace's end) raises ValueError.

    ``t`` may be an array (or list) of instants: the answer is then a dict of numpy arrays,
    ``t``, ``ids`` (the trace's balls), ``x``, ``y``, ``vx``, ``vy``, ``z``, ``vz`` (instants x
    balls), ``w`` (instants x balls x 3) and ``phase`` (instants x balls, strings): about 3 us
    an instant, where a call per instant costs some 150 us.
    """
    if scene is None:
        physics = getattr(result, "_physics_json", None)
        if physics is None:
            raise ValueError("scene: needed for a result that does not carry its physics "
                             "(a plain dict): pass the scene it came from")
        scene = {"physics": json.loads(physics), "balls": []}
    elif isinstance(scene, Mapping):
        scene = {"physics": scene.get("physics", {}), "balls": []}
    else:
        scene = {"physics": json.loads(scene).get("physics", {}), "balls": []}
    if isinstance(t, (list, tuple)) or hasattr(t, "__array__") and getattr(t, "ndim", 0) > 0:
        return _core.state_at_times(result, t, scene)
    if isinstance(t, bool) or not isinstance(t, (int, float)) and not hasattr(t, "__float__"):
        raise TypeError("t: expected a number of seconds, found " + type(t).__name__)
    return _core.state_at(result, float(t), scene)


def _progress_bar(total: Optional[int], progress: Optional[bool]) -> Any:
    """A tqdm bar (the notebook's in a notebook), or None."""
    wanted = progress if progress is not None else (total is not None and total >= PROGRESS_FROM)
    if not wanted:
        return None
    try:
        from tqdm.auto import tqdm
    except ImportError:
        if progress:
            raise ImportError("progress=True needs tqdm (Debian: python3-tqdm)") from None
        return None
    return tqdm(total=total, unit="scene")


def iter_simulate(scenes: Iterable[Scene], threads: int = 0, chunk: int = 256,
                  progress: Optional[bool] = None) -> Iterator[Result]:
    """Simulates ``scenes`` and yields the results one by one, in order.

    The scenes are read ``chunk`` at a time and each chunk is simulated as simulate_many does
    (on ``threads`` threads): memory holds one chunk of scenes and results, whatever the
    length of the batch, so a generator of a million scenes streams. A bad scene raises
    ValueError naming its index in the whole batch, when its chunk comes. ``progress``: True
    for a tqdm bar, False for none, None for one when tqdm is installed and the batch (with a
    len()) has at least PROGRESS_FROM scenes.
    """
    for block, first in _chunked(scenes, chunk, progress):
        yield from _core.simulate_many(block, threads, first)


def _chunked(scenes: Iterable[Scene], chunk: int,
             progress: Optional[bool]) -> Iterator[Tuple[List[Scene], int]]:
    """The scenes ``chunk`` at a time, each block with the index of its first scene in the
    whole batch; the progress bar (see iter_simulate) moves once a block has been used."""
    if isinstance(scenes, (dict, str, bytes)):
        raise TypeError("scenes: expected an iterable of scenes, found one "
                        + ("dict" if isinstance(scenes, dict) else "string")
                        + " (use simulate, or [scene])")
    if isinstance(chunk, bool) or not isinstance(chunk, int) or chunk < 1:
        raise ValueError("chunk: expected an int >= 1, found " + repr(chunk))
    total = len(scenes) if isinstance(scenes, Sized) else None
    bar = _progress_bar(total, progress)
    source = iter(scenes)
    done = 0
    try:
        while True:
            block = list(itertools.islice(source, chunk))
            if not block:
                return
            yield block, done
            done += len(block)
            if bar is not None:
                bar.update(len(block))
    finally:
        if bar is not None:
            bar.close()


def simulate_batch(scenes: Iterable[Scene], threads: int = 0, chunk: int = 256,
                   progress: Optional[bool] = None) -> types.SweepArrays:
    """Simulates ``scenes`` and returns their final states as numpy arrays, without a dict per
    shot: the arrays of simulate_arrays, a row per scene, a column per ball id met in any of
    them (NaN, or False, where a scene has no such ball).

    Streams ``chunk`` scenes at a time as iter_simulate does (memory holds one chunk's
    results); a bad scene raises ValueError naming its index. Needs numpy.
    """
    import numpy as np

    parts = [cast(Dict[str, Any], _core.batch_arrays(block, threads, first))
             for block, first in _chunked(scenes, chunk, progress)]
    return _merge_arrays(parts, np)


def _merge_arrays(parts: List[Dict[str, Any]], np: Any) -> types.SweepArrays:
    """The chunks' arrays stacked, their ball columns lined up by id."""
    ids = np.unique(np.concatenate([p["ids"] for p in parts])) if parts else np.zeros(0, np.int64)
    n = sum(len(p["time"]) for p in parts)
    m = len(ids)
    out: Dict[str, Any] = {"ids": ids.astype(np.int64), "event_types": list(_core.EVENT_TYPES)}
    for name in ("x", "y", "vx", "vy", "pocket_time"):
        out[name] = np.full((n, m), np.nan)
    out["w"] = np.full((n, m, 3), np.nan)
    out["pocketed"] = np.zeros((n, m), dtype=bool)
    for name, dtype in (("time", float), ("wall_ms", float), ("partial", bool)):
        out[name] = np.concatenate([p[name] for p in parts]) if parts else np.zeros(0, dtype)
    for name, dtype in (("events", np.int64), ("first_event_time", float)):
        width = len(_core.EVENT_TYPES)
        out[name] = (np.concatenate([p[name] for p in parts]) if parts
                     else np.zeros((0, width), dtype))
    row = 0
    for p in parts:
        rows = slice(row, row + len(p["time"]))
        cols = np.searchsorted(ids, p["ids"])
        for name in ("x", "y", "vx", "vy", "pocket_time", "w", "pocketed"):
            out[name][rows, cols] = p[name]
        row += len(p["time"])
    return cast(types.SweepArrays, out)


def simulate_arrays(places: Any, shots: Any, ids: Optional[Sequence[int]] = None,
                    table: Union[str, Mapping[str, Any], None] = None,
                    physics: Optional[Mapping[str, Any]] = None,
                    step: Optional[Mapping[str, Any]] = None,
                    threads: int = 0) -> types.SweepArrays:
    """Sweeps with arrays in and arrays out: no scene or result dict per shot.

    ``places``: ball places, an array of shape (n, balls, 2) in metres (NaN for a ball not on
    the table in that row), or (balls, 2) for the same layout in every row; ``shots``: (n, 5),
    each row ``heading_deg``, ``speed`` (m/s), ``side``, ``height`` (the tip, fractions of R)
    and ``elevation_deg``, struck on the cue ball; ``ids``: the balls' ids, in the order of
    ``places``' columns (default 0, 1, ...; the cue ball, 0, among them). ``table``,
    ``physics`` and ``step`` as a scene's.

    Returns a dict of numpy arrays, a row per shot: ``ids``; ``x``, ``y``, ``vx``, ``vy`` (n x
    balls, the final states), ``w`` (n x balls x 3, rad/s), ``pocketed`` (n x balls: in a
    pocket or off the table), ``pocket_time`` (n x balls, s, NaN when it stayed up), ``time``,
    ``wall_ms`` (the engine's own time), ``partial`` (n), ``events`` (n x event types, counts),
    ``first_event_time`` (n x event types, s, NaN when none) and ``event_types`` (the columns'
    names). Each row is checked as a scene is (ValueError "row i: ..."); the runs go on
    ``threads`` threads, the GIL released.
    """
    import numpy as np

    shots_a = np.ascontiguousarray(shots, dtype=float)
    if shots_a.ndim == 1:
        shots_a = shots_a[None, :]
    places_a = np.asarray(places, dtype=float)
    if places_a.ndim == 2:
        places_a = np.broadcast_to(places_a, (len(shots_a),) + places_a.shape)
    places_a = np.ascontiguousarray(places_a)
    if ids is None:
        ids = list(range(places_a.shape[1] if places_a.ndim == 3 else 0))
    scene: Dict[str, Any] = {"balls": []}
    for key, value in (("table", table), ("physics", physics), ("step", step)):
        if value is not None:
            scene[key] = value
    return _core.simulate_arrays(scene, places_a, shots_a, [int(i) for i in ids], threads)


class Pocket:
    """One pocket as built: its mouth between two jaw points, and the drop circle (a ball whose
    centre enters it is pocketed). Points are (x, y) in metres, the table's centre at 0."""

    def __init__(self, d: types.PocketGeometry) -> None:
        self.id: types.PocketName = d["id"]
        self.jaw_a: Tuple[float, ...] = tuple(d["jaw_a"])
        self.jaw_b: Tuple[float, ...] = tuple(d["jaw_b"])
        self.outward: Tuple[float, ...] = tuple(d["outward"])
        self.drop_centre: Tuple[float, ...] = tuple(d["drop_centre"])
        self.drop_radius: float = d["drop_radius"]

    def __repr__(self) -> str:
        return f"Pocket({self.id!r}, drop_centre={self.drop_centre})"


class Table:
    """The table as the physics builds it, for a scene's ``table`` and ``physics``.

    ``table``: a name of TABLES ("9ft", "8ft", "7ft", "carom", "carom-small", "snooker",
    "snooker-10ft"; the carom ones have no pockets, the snooker ones rounded jaws) or the scene format's table object; ``physics``: the
    scene's physics object (its ball radius sets how deep the pocket cups are). Attributes, SI
    units, the origin at the table's centre, x along its length: ``length``, ``width``,
    ``ball_radius``, ``corner_pocket`` and ``side_pocket`` (mouth widths), ``pockets`` (Pocket,
    the six in order), ``cushion_loop`` (the cushions' outline, clockwise, a list of points or
    an n x 2 numpy array), ``head_string_x``, ``foot_spot``, ``head_spot``, ``centre_spot``.
    """

    def __init__(self, table: Union[str, types.TableSpec, Mapping[str, Any]] = "9ft",
                 physics: Optional[Union[types.Physics, Mapping[str, Any]]] = None) -> None:
        scene: Dict[str, Any] = {"balls": [], "table": table}
        if physics is not None:
            scene["physics"] = physics
        g = _core.table_geometry(scene)
        self.length: float = g["length"]
        self.width: float = g["width"]
        self.ball_radius: float = g["ball_radius"]
        self.has_pockets: bool = g["pockets_on"]
        self.corner_pocket: float = g["corner_pocket"]
        self.side_pocket: float = g["side_pocket"]
        self.pockets: List[Pocket] = [Pocket(p) for p in g["pockets"]]
        try:
            import numpy as np
            # An n x 2 array (a list of [x, y] without numpy, which a checker is not told).
            self.cushion_loop: types.FloatArray = np.array(g["cushion_loop"])
        except ImportError:
            self.cushion_loop = cast(types.FloatArray, g["cushion_loop"])
        self.head_string_x: float = g["head_string_x"]
        self.foot_spot: Tuple[float, ...] = tuple(g["foot_spot"])
        self.head_spot: Tuple[float, ...] = tuple(g["head_spot"])
        self.centre_spot: Tuple[float, ...] = tuple(g["centre_spot"])

    def __repr__(self) -> str:
        return f"Table({self.length} m x {self.width} m, {len(self.pockets)} pockets)"


def rack(game: str = "nine-ball", seed: int = 1,
         table: Union[str, types.TableSpec, Mapping[str, Any]] = "9ft") -> List[types.Ball]:
    """The object balls of ``game``'s standard rack, as a scene's ``balls`` (no cue ball).

    ``seed`` orders the balls as the game orders them (the same seed, the same rack as the
    game window and ``nineball match``). Add the cue ball, e.g.
    ``[{"id": 0, "x": Table().head_string_x, "y": 0.0}] + rack()``.
    """
    return _core.rack(game, seed, {"balls": [], "table": table})


def plan(scene: Scene, level: Optional[str] = None, game: Optional[str] = None,
         rules: Optional[str] = None,
         ball_in_hand: Optional[bool] = None) -> types.PlanAnswer:
    """The shot the computer would play from ``scene``, as ``nineball plan`` prints it.

    ``level``: one of beginner, casual, club, league, advanced, pro, master (default master);
    ``game``: nine-ball, eight-ball or ten-ball; ``rules``: wpa or paper; ``ball_in_hand``: the
    cue ball placed first. Given here or in the scene. The answer (``heading_deg``, ``speed``,
    ``tip``, and ``cue`` or ``call`` when it places the ball or calls) can go into the scene's
    ``shot`` and be simulated. Ctrl-C stops it.
    """
    doc = dict(scene) if not isinstance(scene, str) else __import__("json").loads(scene)
    for key, value in (("level", level), ("game", game), ("rules", rules),
                       ("ball_in_hand", ball_in_hand)):
        if value is not None:
            doc[key] = value
    return _core.plan(doc)


#: The physics presets' names: "real" (the default: throw, squirt, Mathavan's cushion) and
#: "paper" (the seed paper's models).
PRESETS = _core.PRESETS


def preset(name: str = "real") -> types.Physics:
    """The physics preset ``name`` as a scene's ``physics`` object: its models by name and
    every parameter they read, SI units. Change what you study and pass it back::

        physics = nineball.preset("real")
        physics["cushion_restitution"] = 0.8
        nineball.simulate(dict(scene, physics=physics))
    """
    return _core.preset(name)


def match(script: Union[types.MatchScript, Mapping[str, Any], str]) -> types.MatchResult:
    """A rack played from a match script, as ``nineball match`` prints it.

    The script (docs/cli.md, "nineball match"): ``game``, ``rules``, ``seed``, the table and
    physics, ``players`` ("human" or "ai:<level>"), and the human players' ``turns``; the
    computer's turns are planned. The result holds every turn, the winner, the balls, and
    ``partial``. A bad script or turn raises ValueError naming it; Ctrl-C stops it.
    """
    return _core.match(script)


#: Recorded shots: one dict, a list of them, or their JSON (or JSON Lines) text.
Shots = Union[types.Recording, Mapping[str, Any], Iterable[Mapping[str, Any]], str]


def _shots(shots: Shots) -> Any:
    if isinstance(shots, (str, Mapping)):
        return shots
    return list(shots)


def record(scene: Scene, names: Optional[List[str]] = None, hz: float = 50.0,
           noise: float = 0.005, strike: float = 0.5, seed: int = 1) -> types.Recording:
    """The scene (with a shot) as a tracker would record it: a recorded shot for fit.

    Every ball at every frame (``hz`` per second) from 0 to the end of the run, read off the
    run exactly, with Gaussian ``noise`` (m) on each coordinate from ``seed``, clamped at the
    cushion lines; the shot struck at ``strike`` s on the recording's clock. ``names[i]``
    names scene ball i (default: the ids as strings). For trying the workflow and testing it.
    """
    if names is None:
        parsed = json.loads(scene) if isinstance(scene, str) else scene
        names = [str(b["id"]) for b in parsed["balls"]]
    return _core.record(scene, list(names), float(hz), float(noise), float(strike), int(seed))


def fit(shots: Shots, evals: int = 12000, objective: str = "full", seed: int = 1,
        threads: int = 0) -> List[types.FitAnswer]:
    """The shot that best reproduces each recorded shot, as ``nineball fit`` prints it.

    Each answer: ``id``, ``scene`` (a complete scene: simulate it to see the fit), ``names``
    (scene ball id as a string -> recorded name; the cue ball is "0"), ``strike_time`` (the
    recording's time of the strike), ``rmse_m`` (``full`` and ``early``), ``evals``,
    ``warnings`` (why the fit may mislead: "nothing moves", "did not converge", ...) and
    ``unreproduced`` (the recorded balls the fit moves and the recording does not, or the
    other way round). ``objective``: "full" (every sample) or "early" (4 s after the strike,
    the cue ball weighted 1.5, each sample by 1/(1 + t)). Deterministic for a seed; both cores
    used (``threads``: 0 for one per core). A refused shot's answer is ``{"id", "error"}``
    (``id`` only when it had one; the message names the field), in its place, the others
    fitted; text that holds no shot at all (not JSON) raises ValueError.
    """
    return _core.fit(_shots(shots), int(evals), objective, int(seed), threads)


def calibrate(shots: Shots, params: Iterable[str], holdout: float = 0.5, seed: int = 1,
              evals: int = 6000, refit_evals: int = 900, candidates: int = 60,
              threads: int = 0) -> types.CalibrateAnswer:
    """Physics parameters calibrated to recorded shots of one table, as ``nineball calibrate``
    prints it.

    ``params``: the physics parameters searched, by name (any number the scene's physics
    takes, e.g. "rolling_friction", "cushion_restitution", "ball_friction.a"). A share
    ``holdout`` of the shots (drawn by ``seed``) is kept out of the training and measured
    under the result. Returns ``physics`` (ready for a scene), ``parameters`` (each one's
    ``value`` and ``stderr``, None where it cannot be determined), ``uncertainty`` (the
    standard errors' ``method`` and ``resamples``), ``correlation`` (a list of rows, in
    ``params`` order), ``converged`` and ``convergence`` (why, or why not), ``train`` and
    ``holdout`` (``median_rmse_m``, ``shots``, ``unreproduced_balls``) and ``per_shot`` (each
    shot's fit, with ``set``). A refused shot raises ValueError naming it ("shot 3: balls.white:
    ...").
    """
    if isinstance(params, str):
        params = params.split(",")
    return _core.calibrate(_shots(shots), list(params), float(holdout), int(seed), int(evals),
                           int(refit_evals), int(candidates), threads)
