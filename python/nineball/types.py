"""The documents nineball reads and returns, as TypedDicts for type checkers.

Each one is the JSON format of docs/cli.md (the scene, the result, a recorded shot, the answers
of plan, fit, calibrate and match) spelled as a ``typing.TypedDict``, so that a strict checker
(mypy, pyright) knows ``r["balls"][0]["x"]`` is a float and refuses ``scene["shot"]["sped"]``::

    import nineball
    from nineball.types import Scene

    scene: Scene = {"balls": [{"id": 0, "x": -0.6, "y": 0.0}, {"id": 1, "x": 0.0, "y": 0.0}],
                    "shot": {"heading_deg": 0.0, "speed": 2.0}, "trace": {"hz": 100}}
    r = nineball.simulate(scene)          # nineball.Result: r["balls"] is List[ResultBall]

At run time these are plain dicts (a TypedDict is a dict to Python); nothing here checks
anything. Vectors (``w``, ``tip``, ``cue``, the table's points) are lists, and a trace's
columns numpy arrays (``FloatArray``; lists in a result read back from JSON, or without
numpy). Fields a document may leave out are optional keys (``total=False``): ``r.get("trace")``.
Importing this module imports nothing else (not numpy).
"""

from typing import TYPE_CHECKING, Dict, List, Literal, Optional, Sequence, TypedDict, Union

if TYPE_CHECKING:
    import numpy
    import numpy.typing

    #: A trace column of numbers (float64).
    FloatArray = numpy.typing.NDArray[numpy.float64]
    #: A trace column of words (the phases).
    StrArray = numpy.typing.NDArray[numpy.str_]
    #: Flags (on the table, pocketed, partial) and counts and ids.
    BoolArray = numpy.typing.NDArray[numpy.bool_]
    IntArray = numpy.typing.NDArray[numpy.int64]
else:
    # At run time (typing.get_type_hints) without importing numpy; checkers see the arrays.
    FloatArray = Sequence[float]
    StrArray = Sequence[str]
    BoolArray = Sequence[bool]
    IntArray = Sequence[int]

__all__ = [
    "FloatArray", "StrArray", "BoolArray", "IntArray", "SweepArrays", "StatesAtTimes",
    "Observation", "PocketName", "Phase", "EventType", "End",
    "Ball", "BallFriction", "Physics", "TableSpec", "Shot", "Call", "Step", "TraceRequest",
    "Scene", "PlanScene",
    "ResultBall", "Event", "TraceColumns", "ResultDoc", "BallState",
    "PocketGeometry", "TableGeometry",
    "PlanAnswer",
    "RecordedBall", "Recording", "Rmse", "FitAnswer",
    "CalibratedParameter", "Uncertainty", "ShotSet", "CalibratedShot", "CalibrateAnswer",
    "ScriptTurn", "MatchScript", "CaromScore", "SnookerScore", "MatchTurn", "RackSummary",
    "MatchResult",
]

#: The pockets' names (top = +y, right = +x).
PocketName = Literal["top-left", "top-side", "top-right", "bottom-left", "bottom-side",
                     "bottom-right"]
#: A ball's phase in a trace and in state_at.
Phase = Literal["sliding", "rolling", "spinning", "rest", "airborne", "pocketed"]
#: An event's type.
EventType = Literal["ball", "cushion", "pocket", "miscue", "airborne", "land", "off_table",
                    "rest"]
#: How a run ended: "rest" and "until" complete, "max_time" and "budget" partial.
End = Literal["rest", "until", "max_time", "budget"]


# --- the scene (docs/cli.md, "The scene") ------------------------------------------------


class _BallRequired(TypedDict):
    id: int
    x: float
    y: float


class Ball(_BallRequired, total=False):
    """A scene's ball: ``id`` (0 the cue ball), ``x``, ``y`` (m), and optionally its velocity
    (m/s), spin ``w`` [wx, wy, wz] (rad/s), ``mass`` (kg), height ``z`` (m) and ``vz``."""

    vx: float
    vy: float
    w: List[float]
    mass: float
    z: float
    vz: float


class BallFriction(TypedDict):
    """The ball-ball friction mu = a + b exp(-c v)."""

    a: float
    b: float
    c: float


class Physics(TypedDict, total=False):
    """A scene's ``physics``: a ``preset`` and any parameter its models read (SI units), the
    models chosen by name. preset() returns one with every parameter spelled out."""

    preset: str
    cloth: str
    ball_ball: str
    ball_friction: Union[float, BallFriction]
    cushion: str
    cushion_height: float
    cushion_restitution_base: float
    cushion_restitution_slope: float
    cushion_restitution_quadratic: float
    cushion_restitution_min: float
    pocket: str
    pocket_restitution: float
    frozen: str
    corner: str
    cushion_contact_time: float
    frozen_tolerance: float
    ball_mass: float
    ball_radius: float
    ball_restitution: float
    cushion_restitution: float
    rolling_friction: float
    sliding_friction: float
    spin_decay: float
    cushion_friction: float
    miscue_limit: float
    cue_end_mass: float
    gravity: float
    linear_damping: float
    rest_speed: float
    table_restitution: float
    min_bounce_height: float


class _TableSpecRequired(TypedDict):
    length: float
    width: float


class TableSpec(_TableSpecRequired, total=False):
    """A table given by its sizes (m, between the cushion noses) instead of by name."""

    pockets: bool
    corner_pocket: float
    side_pocket: float
    corner_jaw_deg: float
    side_jaw_deg: float
    corner_jaw_radius: float
    side_jaw_radius: float


class Shot(TypedDict, total=False):
    """A scene's ``shot`` (it strikes ball 0): a heading (``heading_deg`` or ``heading_rad``),
    ``speed`` (m/s) or ``force`` (N) with ``contact_time`` (s), ``tip`` [side, height] as
    fractions of R, and the cue's ``elevation_deg`` (or ``elevation_rad``)."""

    heading_deg: float
    heading_rad: float
    speed: float
    force: float
    contact_time: float
    tip: List[float]
    elevation_deg: float
    elevation_rad: float


class Call(TypedDict):
    """A called shot: the ball and the pocket."""

    ball: int
    pocket: PocketName


class Step(TypedDict, total=False):
    """A scene's ``step``: the engine and its settings."""

    engine: Literal["box2d", "reference"]
    hz: float
    velocity_iterations: int
    position_iterations: int
    scale: float
    contacts: Literal["pairwise", "box2d"]
    baseline: bool
    max_time: float


class TraceRequest(TypedDict, total=False):
    """A scene's ``trace``: ``{"hz": N}`` or ``{"events_only": True}``."""

    hz: float
    events_only: bool


class _SceneRequired(TypedDict):
    balls: List[Ball]


class Scene(_SceneRequired, total=False):
    """The scene of ``nineball sim``: ``balls`` and, optionally, ``table`` (a name of
    nineball.TABLES or a TableSpec), ``physics``, ``shot``, ``until`` ("rest" or seconds),
    ``step`` and ``trace``."""

    table: Union[str, TableSpec]
    physics: Physics
    shot: Shot
    until: Union[float, Literal["rest"]]
    step: Step
    trace: TraceRequest


class PlanScene(Scene, total=False):
    """The scene of ``nineball plan``: a scene with ``game``, ``rules``, ``ball_in_hand`` and
    ``level``."""

    game: str
    rules: str
    ball_in_hand: bool
    level: str


# --- the result (docs/cli.md, "The result" and "Trajectories") ---------------------------


class ResultBall(TypedDict):
    """A ball where the run left it: ``pocket`` the pocket's name once it dropped (else None),
    ``off_table`` True for a ball that left over a rail."""

    id: int
    x: float
    y: float
    vx: float
    vy: float
    z: float
    vz: float
    w: List[float]
    pocket: Optional[PocketName]
    off_table: bool


class _EventRequired(TypedDict):
    t: float
    type: EventType


class Event(_EventRequired, total=False):
    """An event: ``t`` and ``type``, then by type: "ball" ``a``, ``b``, ``va``, ``vb`` (the
    velocities just after); "cushion", "airborne", "land", "off_table" ``ball``, ``v``;
    "pocket" ``ball``, ``pocket``; "miscue" ``ball``; "rest" nothing more."""

    a: int
    b: int
    va: List[float]
    vb: List[float]
    ball: int
    v: List[float]
    pocket: PocketName


class TraceColumns(TypedDict):
    """One ball's trace: a column per quantity, a row per instant (``w`` n x 3)."""

    t: FloatArray
    x: FloatArray
    y: FloatArray
    vx: FloatArray
    vy: FloatArray
    z: FloatArray
    vz: FloatArray
    w: FloatArray
    phase: StrArray


class _ResultDocRequired(TypedDict):
    time: float
    steps: int
    wall_ms: float
    end: End
    partial: bool
    balls: List[ResultBall]
    events: List[Event]


class ResultDoc(_ResultDocRequired, total=False):
    """A result as a plain dict (``json.load`` of what ``nineball sim`` prints); simulate
    returns a nineball.Result, which reads the same. ``trace`` (by ball id as a string) and
    ``trace_truncated`` are there when the scene asked for a trace."""

    trace: Dict[str, TraceColumns]
    trace_truncated: bool


class BallState(TypedDict):
    """A ball at an instant, as state_at gives it."""

    id: int
    x: float
    y: float
    vx: float
    vy: float
    z: float
    vz: float
    w: List[float]
    phase: Phase
    pocket: Optional[PocketName]


# --- the table as built (nineball._core.table_geometry) ----------------------------------


class PocketGeometry(TypedDict):
    id: PocketName
    jaw_a: List[float]
    jaw_b: List[float]
    outward: List[float]
    drop_centre: List[float]
    drop_radius: float


class TableGeometry(TypedDict):
    length: float
    width: float
    ball_radius: float
    pockets_on: bool
    corner_pocket: float
    side_pocket: float
    pockets: List[PocketGeometry]
    cushion_loop: List[List[float]]
    head_string_x: float
    foot_spot: List[float]
    head_spot: List[float]
    centre_spot: List[float]


# --- plan (docs/cli.md, "nineball plan") -------------------------------------------------


class PlanAnswer(Shot, total=False):
    """The shot the computer would play: a scene's ``shot``, plus ``cue`` (where it places the
    cue ball, when in hand) and ``call``."""

    cue: List[float]
    call: Call


# --- recorded shots and fits (docs/cli.md, "nineball fit" and "nineball calibrate") -----


class RecordedBall(TypedDict):
    """A tracked ball's samples: ``t`` (s, the recording's clock), ``x``, ``y`` (m)."""

    t: List[float]
    x: List[float]
    y: List[float]


class _RecordingRequired(TypedDict):
    balls: Dict[str, RecordedBall]


class Recording(_RecordingRequired, total=False):
    """A recorded shot: ``balls`` by name, and optionally ``id``, ``table``, ``physics`` and
    ``cue_ball`` (a name)."""

    id: Union[str, int]
    table: Union[str, TableSpec]
    physics: Physics
    cue_ball: str


class Rmse(TypedDict):
    full: float
    early: float


class FitAnswer(TypedDict, total=False):
    """A fit: ``id``, ``scene`` (simulate it to see the fit), ``names`` (scene ball id as a
    string -> recorded name), ``strike_time``, ``rmse_m``, ``evals``, ``warnings`` and
    ``unreproduced``; a refused shot's answer holds ``error`` (and ``id`` when it had one)
    instead: look for "error" first."""

    id: Union[str, int]
    scene: Scene
    names: Dict[str, str]
    strike_time: float
    rmse_m: Rmse
    evals: int
    warnings: List[str]
    unreproduced: List[str]
    error: str


class CalibratedParameter(TypedDict):
    value: float
    stderr: Optional[float]


class Uncertainty(TypedDict):
    method: str
    resamples: int


class ShotSet(TypedDict):
    median_rmse_m: Optional[float]
    shots: int
    unreproduced_balls: int


class CalibratedShot(FitAnswer, total=False):
    """A shot's fit under the calibrated physics, with the ``set`` it was in."""

    set: Literal["train", "holdout"]


class CalibrateAnswer(TypedDict):
    """What calibrate returns (docs/calibrating.md)."""

    physics: Physics
    parameters: Dict[str, CalibratedParameter]
    uncertainty: Uncertainty
    correlation: List[List[Optional[float]]]
    converged: bool
    convergence: str
    train: ShotSet
    holdout: ShotSet
    per_shot: List[CalibratedShot]


# --- match (docs/cli.md, "nineball match") -----------------------------------------------


class ScriptTurn(Shot, total=False):
    """A human's turn in a match script: a shot (with ``cue`` to place the cue ball in hand and
    ``call``), a push-out (``push_out``) or a ``decision``."""

    cue: List[float]
    call: Call
    push_out: bool
    decision: str


class MatchScript(TypedDict, total=False):
    """A match script: the game, its players ("human" or "ai:LEVEL") and the humans' turns;
    a rack joined in the middle gives ``balls`` with ``shooter``, ``ball_in_hand``, ``fouls``,
    ``groups`` and ``score``."""

    game: str
    rules: str
    seed: int
    table: Union[str, TableSpec]
    physics: Physics
    step: Step
    balls: List[Ball]
    players: Dict[str, str]
    turns: List[ScriptTurn]
    points: int
    race_to: int
    breaks: Literal["alternate", "winner"]
    shooter: str
    ball_in_hand: bool
    fouls: Dict[str, int]
    groups: Dict[str, Optional[str]]
    score: Dict[str, int]


class CaromScore(TypedDict):
    """A three-cushion player's score."""

    points: int
    innings: int
    run: int
    average: float
    high_run: int


#: A snooker player's score ("break" is a Python keyword, hence this spelling).
SnookerScore = TypedDict("SnookerScore", {"points": int, "break": int, "high_break": int})

#: A turn of a match result; which keys it has depends on the game (docs/cli.md).
MatchTurn = TypedDict("MatchTurn", {
    "rack": int,
    "shooter": str,
    "player": str,
    "shot": Shot,
    "cue": List[float],
    "call": Call,
    "push_out": bool,
    "decision": str,
    "result": Literal["legal", "foul"],
    "foul": Optional[str],
    "pocketed": List[int],
    "next": str,
    "ball_on": int,
    "ball_in_hand": bool,
    "winner": Optional[str],
    "call_breach": Optional[str],
    "groups": Dict[str, Optional[str]],
    "point": bool,
    "cushions": int,
    "score": Dict[str, Union[CaromScore, SnookerScore]],
    "nominated": Optional[int],
    "free_ball": bool,
    "miss": bool,
    "points": int,
    "penalty": int,
    "choices": Optional[List[str]],
    "black_respotted": bool,
    "break": int,
    "points_remaining": int,
    "free_ball_next": bool,
}, total=False)


class RackSummary(TypedDict, total=False):
    """A rack (or frame) of a race."""

    rack: int
    seed: int
    breaker: str
    winner: Optional[str]
    turns: int
    score: Dict[str, Union[CaromScore, SnookerScore]]
    points_remaining: int
    snookers_required: Dict[str, bool]


class _MatchResultRequired(TypedDict):
    turns: List[MatchTurn]
    winner: Optional[str]
    balls: List[ResultBall]
    partial: bool


class MatchResult(_MatchResultRequired, total=False):
    """What match returns: every turn, the ``winner`` (None while undecided), the balls and
    ``partial``; a race adds ``race_to``, ``breaks``, ``racks`` and ``racks_won``,
    three-cushion ``points``, ``draw`` and ``score``, snooker ``score``,
    ``points_remaining`` and ``snookers_required``."""

    race_to: int
    breaks: Literal["alternate", "winner"]
    racks: List[RackSummary]
    racks_won: Dict[str, int]
    points: int
    draw: bool
    score: Dict[str, Union[CaromScore, SnookerScore]]
    points_remaining: int
    snookers_required: Dict[str, bool]


class SweepArrays(TypedDict):
    """simulate_arrays' and simulate_batch's answer: a row per shot, a column per ball of
    ``ids`` (NaN, or False, where a shot has no such ball), a column per event type of
    ``event_types``."""

    ids: IntArray
    x: FloatArray
    y: FloatArray
    vx: FloatArray
    vy: FloatArray
    w: FloatArray
    pocketed: BoolArray
    pocket_time: FloatArray
    time: FloatArray
    wall_ms: FloatArray
    partial: BoolArray
    events: IntArray
    event_types: List[str]
    first_event_time: FloatArray


class StatesAtTimes(TypedDict):
    """state_at over an array of instants: a row per instant, a column per ball of ``ids``."""

    t: FloatArray
    ids: IntArray
    x: FloatArray
    y: FloatArray
    vx: FloatArray
    vy: FloatArray
    z: FloatArray
    vz: FloatArray
    w: FloatArray
    phase: StrArray


class Observation(TypedDict):
    """A game environment's observation (nineball.env): every ball's place (m; 0 off the
    table), whether it is on the table, and the rules' state (nineball.env.STATE_NAMES); a
    vector environment's have a row per table first."""

    balls: FloatArray
    on_table: BoolArray
    state: FloatArray
