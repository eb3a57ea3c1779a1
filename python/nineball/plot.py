"""Pictures of tables, shots and fits with matplotlib, one call each, for a notebook.

    import nineball, nineball.plot
    r = nineball.simulate(dict(scene, trace={"hz": 100}))
    nineball.plot.shot(r, scene=scene)            # the paths, by phase, and the events
    nineball.plot.animate(r, "shot.gif")          # the run as a GIF (or .html)

- table(ax=None, table="9ft", physics=None): the table as the physics builds it.
- shot(result, ax=None, scene=None, table=None, events=True): each ball's path from its
  trace, coloured by phase, the balls where they started and stopped, the events marked.
- fit(answer, recording, ax=None): a fit of nineball.fit over the recorded positions.
- animate(result, path=None, fps=30, scene=None): the run as a matplotlib animation.

Each returns the Axes it drew on (animate the animation), so a notebook shows it in one call.
matplotlib is imported by these functions, not by ``import nineball``.
"""

import json
from typing import (TYPE_CHECKING, Any, Dict, Iterable, List, Mapping, NamedTuple, Optional,
                    Sequence, Tuple, Union)

import nineball
from . import types

if TYPE_CHECKING:
    from matplotlib.animation import FuncAnimation
    from matplotlib.axes import Axes

__all__ = ["table", "shot", "fit", "animate", "PHASE_COLOURS", "ball_colour"]

# The game's colours (include/nineball/colours.hpp, which the game window and `nineball sim
# --svg` draw with), as RGB.
_CLOTH = (46, 139, 87)
_CUSHION = (28, 104, 62)
_WOOD = (96, 56, 30)
_POCKET = (12, 12, 12)
_DIAMOND = (236, 228, 206)
_CUE_BALL = (246, 244, 232)
# Pool: 1 yellow, 2 blue, 3 red, 4 purple, 5 orange, 6 green, 7 maroon, 8 black; 9-15 striped.
_POOL = [(250, 196, 16), (24, 64, 196), (214, 30, 36), (104, 44, 150), (246, 118, 20),
         (0, 96, 44), (128, 24, 36), (18, 18, 18)]
# Carom: 0 white, 1 yellow, 2 red.
_CAROM = [_CUE_BALL, (246, 200, 40), (206, 26, 32)]
# Snooker: reds 1-15, then yellow, green, brown, blue, pink, black (16-21).
_SNOOKER_RED = (200, 22, 30)
_SNOOKER_COLOURS = [(246, 210, 30), (0, 120, 56), (120, 70, 30), (30, 80, 200),
                    (240, 130, 170), (18, 18, 18)]

#: The colour of a path in each phase of a trace (pocketed balls draw no path).
PHASE_COLOURS: Dict[str, str] = {
    "sliding": "#ff8c1a",
    "rolling": "#ffffff",
    "spinning": "#40c4ff",
    "airborne": "#ff4fd8",
    "rest": "#9e9e9e",
}

# How each event is marked: (marker, face, edge, size, label).
_EVENT_MARKS: Dict[str, Tuple[str, str, str, float, str]] = {
    "ball": ("o", "none", "#ff2d2d", 9.0, "ball contact"),
    "cushion": ("D", "#ffe14d", "#1a1a1a", 5.0, "cushion"),
    "pocket": ("X", "#ff2dd2", "#1a1a1a", 8.0, "pocketed"),
    "miscue": ("^", "#ff8c1a", "#1a1a1a", 8.0, "miscue"),
    "airborne": ("^", "#ff4fd8", "#1a1a1a", 6.0, "leaves the cloth"),
    "land": ("v", "#ff4fd8", "#1a1a1a", 6.0, "lands"),
    "off_table": ("*", "#ff2d2d", "#1a1a1a", 10.0, "off the table"),
}

# Colour words a recording may name its balls by (carom's, snooker's, the cue ball's).
_NAMED = {"white": _CUE_BALL, "cue": _CUE_BALL, "yellow": (246, 200, 40), "red": (206, 26, 32),
          "green": (0, 120, 56), "brown": (120, 70, 30), "blue": (30, 80, 200),
          "pink": (240, 130, 170), "black": (18, 18, 18)}

# Instants a path is drawn from when the run's physics is known: the trace's own (every event
# and change of phase) plus this many a second, at most _MAX_INSTANTS in all.
_DRAW_HZ = 200.0
_MAX_INSTANTS = 20000

TableLike = Union[str, types.TableSpec, Mapping[str, Any], "nineball.Table"]


def _hex(rgb: Tuple[int, int, int]) -> str:
    return "#%02x%02x%02x" % rgb


def ball_colour(ball_id: int, game: str = "pool") -> Tuple[str, bool]:
    """A ball's colour (hex) and whether it is striped, in ``game``'s set: "pool" (0 the cue
    ball, 1-8 solids, 9-15 stripes), "carom" (0 white, 1 yellow, 2 red) or "snooker" (1-15
    reds, 16-21 yellow, green, brown, blue, pink, black): the game's own colours."""
    if game == "carom":
        return _hex(_CAROM[ball_id] if 0 <= ball_id < 3 else _CUE_BALL), False
    if game == "snooker":
        if 1 <= ball_id <= 15:
            return _hex(_SNOOKER_RED), False
        if 16 <= ball_id <= 21:
            return _hex(_SNOOKER_COLOURS[ball_id - 16]), False
        return _hex(_CUE_BALL), False
    if ball_id <= 0:
        return _hex(_CUE_BALL), False
    if ball_id <= 8:
        return _hex(_POOL[ball_id - 1]), False
    return _hex(_POOL[(ball_id - 9) % 7]), True


def _ink(colour: str) -> str:
    """Black or white, whichever reads on ``colour``."""
    r, g, b = (int(colour[i:i + 2], 16) for i in (1, 3, 5))
    return "#111111" if 0.299 * r + 0.587 * g + 0.114 * b > 140 else "#ffffff"


# --- arguments ------------------------------------------------------------------------


def _as_table(table: Any, physics: Any) -> "nineball.Table":
    if isinstance(table, nineball.Table):
        return table
    if not isinstance(table, (str, Mapping)):
        raise TypeError("table: expected a table's name (one of nineball.TABLES), a table "
                        "object or a nineball.Table, found " + type(table).__name__)
    if physics is not None and not isinstance(physics, Mapping):
        raise TypeError("physics: expected a scene's physics object (a dict), found "
                        + type(physics).__name__)
    return nineball.Table(table, physics)


def _as_scene(scene: Any) -> Optional[Mapping[str, Any]]:
    if scene is None:
        return None
    if isinstance(scene, str):
        scene = json.loads(scene)
    if not isinstance(scene, Mapping) or not isinstance(scene.get("balls"), list):
        raise TypeError("scene: expected the scene the result came from (a dict with "
                        "\"balls\"), found " + type(scene).__name__)
    return scene


def _check_result(result: Any) -> Mapping[str, Any]:
    if (not isinstance(result, Mapping) or not isinstance(result.get("balls"), list)
            or not isinstance(result.get("events"), list)):
        raise TypeError("result: expected a result of nineball.simulate (a dict with "
                        "\"balls\" and \"events\"), found " + type(result).__name__)
    return result


def _game(table_given: Any, t: "nineball.Table", scene: Optional[Mapping[str, Any]],
          ids: Iterable[int]) -> str:
    """Which set of balls to colour by: carom on a table without pockets, snooker on a
    snooker table (or with snooker's colours' ids), else pool."""
    if not t.has_pockets:
        return "carom"
    name = table_given if isinstance(table_given, str) else ""
    if scene is not None and isinstance(scene.get("table"), str):
        name = name or scene["table"]
    if name.startswith("snooker") or any(i > 15 for i in ids):
        return "snooker"
    return "pool"


def _physics_of(result: Mapping[str, Any], scene: Optional[Mapping[str, Any]]) -> Any:
    if scene is not None:
        return scene.get("physics")
    return result.physics if isinstance(result, nineball.Result) else None


# --- drawing --------------------------------------------------------------------------


def _new_axes(t: "nineball.Table", width: float = 9.0, legend: bool = True) -> "Axes":
    """A new figure's axes, the table's shape (with room for a legend below it)."""
    import matplotlib.pyplot as plt

    rail = _rail(t)
    height = width * (t.width + 2.1 * rail) / (t.length + 2.1 * rail)
    fig, ax = plt.subplots(figsize=(width, height + (0.4 if legend else 0.0)))
    if not legend:
        fig.subplots_adjust(left=0, right=1, bottom=0, top=1)
    return ax


def _rail(t: "nineball.Table") -> float:
    """The rail's width beyond the cushion noses, drawn (m)."""
    return 0.045 * t.length + 0.02


def _draw_table(ax: "Axes", t: "nineball.Table") -> None:
    import matplotlib.patches as mpatches
    import numpy as np

    rail = _rail(t)
    half_l, half_w = t.length / 2, t.width / 2
    ax.add_patch(mpatches.FancyBboxPatch(
        (-half_l - rail, -half_w - rail), t.length + 2 * rail, t.width + 2 * rail,
        boxstyle="round,pad=0,rounding_size=%f" % (rail * 0.6), facecolor=_hex(_WOOD),
        edgecolor="#3a2212", linewidth=1.0, zorder=0))
    cushion = 0.45 * rail
    ax.add_patch(mpatches.Rectangle((-half_l - cushion, -half_w - cushion),
                                    t.length + 2 * cushion, t.width + 2 * cushion,
                                    facecolor=_hex(_CUSHION), edgecolor="none", zorder=0.1))
    loop = np.asarray(t.cushion_loop, dtype=float)
    ax.add_patch(mpatches.Polygon(loop, closed=True, facecolor=_hex(_CLOTH),
                                  edgecolor="#0b3d1e", linewidth=1.0, zorder=0.2))
    for p in t.pockets:
        ax.add_patch(mpatches.Circle(p.drop_centre, p.drop_radius, facecolor=_hex(_POCKET),
                                     edgecolor="none", zorder=0.3))
    # Diamonds on the rails, an eighth of the length (a quarter of the width) apart.
    # The middle diamond of a long rail gives way to the side pocket.
    out = rail * 0.72  # the diamonds' line, beyond the cushion nose
    along = [-half_l + k * t.length / 8 for k in range(1, 8) if k != 4 or not t.has_pockets]
    across = [-half_w + k * t.width / 4 for k in range(1, 4)]
    diamonds = ([(x, s * (half_w + out)) for x in along for s in (1, -1)]
                + [(s * (half_l + out), y) for y in across for s in (1, -1)])
    ax.plot([d[0] for d in diamonds], [d[1] for d in diamonds], linestyle="none", marker="D",
            markersize=2.5, color=_hex(_DIAMOND), zorder=0.4)
    spots = [t.head_spot, t.foot_spot, t.centre_spot]
    ax.plot([s[0] for s in spots], [s[1] for s in spots], linestyle="none", marker="o",
            markersize=2.0, color="#e8f0e8", zorder=0.4)
    ax.set_xlim(-half_l - rail * 1.05, half_l + rail * 1.05)
    ax.set_ylim(-half_w - rail * 1.05, half_w + rail * 1.05)
    ax.set_aspect("equal")
    ax.set_axis_off()


def _draw_ball(ax: "Axes", ball_id: int, x: float, y: float, radius: float, game: str,
               alpha: float = 1.0, number: bool = True,
               colour: Optional[str] = None) -> List[Any]:
    """A ball to scale in its colour (``colour``, else its game's; a stripe as a band on
    white), numbered in pool; the artists drawn, so that an animation can move them."""
    import matplotlib.patches as mpatches

    own, striped = ball_colour(ball_id, game)
    if colour is None:
        colour = own
    else:
        striped = False
    base = _hex(_CUE_BALL) if striped else colour
    circle = mpatches.Circle((x, y), radius, facecolor=base, edgecolor="#111111",
                             linewidth=0.6, alpha=alpha, zorder=5)
    ax.add_patch(circle)
    artists: List[Any] = [circle]
    if striped:
        band = mpatches.Rectangle((x - radius, y - 0.55 * radius), 2 * radius, 1.1 * radius,
                                  facecolor=colour, edgecolor="none", alpha=alpha, zorder=5.1)
        ax.add_patch(band)
        band.set_clip_path(circle)
        artists.append(band)
    if number and game == "pool" and ball_id > 0:
        artists.append(ax.text(x, y, str(ball_id), ha="center", va="center", fontsize=5.5,
                               color=_ink(colour), alpha=alpha, zorder=5.2,
                               fontweight="bold"))
    return artists


class _Path(NamedTuple):
    """One ball's run: its instants, positions and the phase from each instant on."""

    t: "types.FloatArray"
    x: "types.FloatArray"
    y: "types.FloatArray"
    phase: List[str]


def _paths(result: Mapping[str, Any], physics_scene: Optional[Mapping[str, Any]],
           hz: float = _DRAW_HZ) -> Dict[int, _Path]:
    """Each traced ball's path: the run's own motion at the trace's instants and ``hz`` more a
    second (state_at) when its physics is known, else the trace's samples as they are."""
    import numpy as np

    trace = result["trace"]
    if not isinstance(trace, Mapping) or not trace:
        raise ValueError("result: its \"trace\" holds no ball")
    own = {int(k): (np.asarray(v["t"], dtype=float), v) for k, v in trace.items()}
    known = physics_scene is not None or (isinstance(result, nineball.Result)
                                          and result.physics is not None)
    if known:
        first = max(float(t[0]) for t, _ in own.values())
        last = min(float(t[-1]) for t, _ in own.values())
        count = int(min(_MAX_INSTANTS, max(2.0, (last - first) * hz)))
        instants = np.unique(np.concatenate(
            [np.linspace(first, last, count)] + [t[(t >= first) & (t <= last)]
                                                 for t, _ in own.values()]))
        try:
            states = nineball.state_at(result, instants, physics_scene)
        except (TypeError, ValueError):
            states = None
        if states is not None:
            paths: Dict[int, _Path] = {}
            for j, ball_id in enumerate(np.asarray(states["ids"]).tolist()):
                paths[int(ball_id)] = _Path(instants, np.asarray(states["x"])[:, j],
                                            np.asarray(states["y"])[:, j],
                                            [str(p) for p in np.asarray(states["phase"])[:, j]])
            return paths
    return {ball_id: _Path(t, np.asarray(v["x"], dtype=float), np.asarray(v["y"], dtype=float),
                           [str(p) for p in v["phase"]])
            for ball_id, (t, v) in own.items()}


def _at(path: _Path, t: float) -> Tuple[float, float]:
    import numpy as np

    return float(np.interp(t, path.t, path.x)), float(np.interp(t, path.t, path.y))


def _draw_paths(ax: "Axes", paths: Mapping[int, _Path]) -> List[str]:
    """The paths as line segments coloured by phase; the phases drawn."""
    from matplotlib.collections import LineCollection

    drawn: List[str] = []
    for phase, colour in PHASE_COLOURS.items():
        segments = []
        for p in paths.values():
            for k in range(len(p.t) - 1):
                if p.phase[k] == phase and (p.x[k] != p.x[k + 1] or p.y[k] != p.y[k + 1]):
                    segments.append([(p.x[k], p.y[k]), (p.x[k + 1], p.y[k + 1])])
        if segments:
            ax.add_collection(LineCollection(segments, colors=colour, linewidths=1.6,
                                             linestyles="dotted" if phase == "airborne"
                                             else "solid", capstyle="round", zorder=3))
            drawn.append(phase)
    return drawn


def _draw_events(ax: "Axes", events: Sequence[Mapping[str, Any]],
                 paths: Mapping[int, _Path]) -> List[str]:
    """A mark at every event, where it happened; the event types marked."""
    where: Dict[str, List[Tuple[float, float]]] = {}
    for e in events:
        kind = e.get("type")
        if not isinstance(kind, str) or kind not in _EVENT_MARKS:
            continue
        if kind == "ball":
            a, b = paths.get(int(e["a"])), paths.get(int(e["b"]))
            if a is None or b is None:
                continue
            (ax_, ay), (bx, by) = _at(a, e["t"]), _at(b, e["t"])
            point = ((ax_ + bx) / 2, (ay + by) / 2)  # the contact point
        else:
            path = paths.get(int(e.get("ball", 0)))
            if path is None:
                continue
            point = _at(path, e["t"])
        where.setdefault(kind, []).append(point)
    for kind, points in where.items():
        marker, face, edge, size, _ = _EVENT_MARKS[kind]
        ax.plot([p[0] for p in points], [p[1] for p in points], linestyle="none",
                marker=marker, markersize=size, markerfacecolor=face, markeredgecolor=edge,
                markeredgewidth=1.2 if kind == "ball" else 0.6, zorder=6)
    return [k for k in _EVENT_MARKS if k in where]


def _legend(ax: "Axes", phases: Sequence[str], events: Sequence[str],
            extra: Sequence[Any] = ()) -> None:
    from matplotlib.lines import Line2D

    handles = [Line2D([], [], color=PHASE_COLOURS[p], linewidth=2,
                      linestyle="dotted" if p == "airborne" else "solid", label=p)
               for p in phases]
    for kind in events:
        marker, face, edge, size, label = _EVENT_MARKS[kind]
        handles.append(Line2D([], [], linestyle="none", marker=marker, markersize=size * 0.8,
                              markerfacecolor=face, markeredgecolor=edge, label=label))
    handles.extend(extra)
    if handles:
        legend = ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, 0.0),
                           ncol=min(len(handles), 6), fontsize=8, frameon=True,
                           facecolor=_hex(_CUSHION), edgecolor="none", labelcolor="white",
                           handlelength=1.6, columnspacing=1.2)
        legend.set_zorder(10)


# --- the calls ------------------------------------------------------------------------


def table(ax: Optional["Axes"] = None, table: TableLike = "9ft",
          physics: Optional[Union[types.Physics, Mapping[str, Any]]] = None) -> "Axes":
    """Draws the table as the physics builds it: the cloth inside the cushion loop (its jaws
    and pocket cups), the pockets' drop circles, the rails with their diamonds and the spots.

    ``table``: a name of nineball.TABLES, a scene's table object or a nineball.Table;
    ``physics``: the scene's physics (its ball radius shapes the pocket cups). Draws on ``ax``
    (a new figure when None) and returns it, x along the length in metres.
    """
    t = _as_table(table, physics)
    if ax is None:
        ax = _new_axes(t)
    _draw_table(ax, t)
    return ax


def shot(result: Union["nineball.Result", types.ResultDoc, Mapping[str, Any]],
         ax: Optional["Axes"] = None,
         scene: Optional[Union[types.Scene, Mapping[str, Any], str]] = None,
         table: Optional[TableLike] = None, events: bool = True) -> "Axes":
    """Draws a run on its table: each ball's path from the result's trace coloured by phase
    (PHASE_COLOURS: sliding, rolling, spinning, airborne), every ball to scale in its colour
    where it started (faded) and where it stopped, a mark at each event (``events``: ball
    contacts at the contact point, cushions, pockets, ...) and a legend.

    ``scene``: the scene the result came from (its table, physics and starting places; needed
    for a result read back from JSON). ``table``: the table when no scene says it (default
    "9ft"). With a Result that knows its physics (or with ``scene``) the paths are the run's
    own motion drawn 200 times a second through every event, however coarse the trace; else
    the trace's samples joined by straight lines. A result without a trace gets its balls
    where they started (with ``scene``) and stopped only, and its title says so.
    """
    result = _check_result(result)
    given = _as_scene(scene)
    physics = _physics_of(result, given)
    table_given: Any = table if table is not None else (given.get("table", "9ft")
                                                        if given is not None else "9ft")
    t = _as_table(table_given, physics)
    ids = [int(b["id"]) for b in result["balls"]]
    game = _game(table_given, t, given, ids)
    if ax is None:
        ax = _new_axes(t)
    _draw_table(ax, t)
    trace = result.get("trace")
    paths: Dict[int, _Path] = {}
    if trace:
        paths = _paths(result, {"balls": [], "physics": physics or {}} if given is not None
                       else None)
    starts: Dict[int, Tuple[float, float]] = {}
    if given is not None:
        starts = {int(b["id"]): (float(b["x"]), float(b["y"])) for b in given["balls"]}
    else:
        starts = {i: (float(p.x[0]), float(p.y[0])) for i, p in paths.items()
                  if len(p.t) and float(p.t[0]) == 0.0}
    for ball_id, (x, y) in starts.items():
        _draw_ball(ax, ball_id, x, y, t.ball_radius, game, alpha=0.35, number=False)
    for b in result["balls"]:
        if b.get("pocket") is None and not b.get("off_table", False):
            _draw_ball(ax, int(b["id"]), float(b["x"]), float(b["y"]), t.ball_radius, game)
    phases = _draw_paths(ax, paths) if paths else []
    marked = _draw_events(ax, result["events"], paths) if events and paths else []
    _legend(ax, phases, marked)
    if not trace:
        ax.set_title("no trace in the result: the balls where they "
                     + ("started (faded) and " if given is not None else "")
                     + "stopped only (simulate with \"trace\": {\"hz\": 100} for the paths)",
                     fontsize=8)
    return ax


def fit(answer: Union[types.FitAnswer, Mapping[str, Any]],
        recording: Union[types.Recording, Mapping[str, Any], str],
        ax: Optional["Axes"] = None) -> "Axes":
    """Draws a fit over its recording: the recorded positions as dots and the fitted run
    (``answer["scene"]`` simulated with a trace) as lines, each ball in its colour, on the
    recording's table, with the fit's RMSE in the title.

    ``answer``: one answer of nineball.fit (or calibrate's ``per_shot``); ``recording``: the
    recorded shot it fitted (docs/cli.md, "nineball fit"). A refused shot's answer (with
    ``"error"``) raises ValueError.
    """
    import numpy as np
    from matplotlib.lines import Line2D

    if not isinstance(answer, Mapping):
        raise TypeError("answer: expected one answer of nineball.fit (a dict), found "
                        + type(answer).__name__)
    if "error" in answer:
        raise ValueError("answer: the shot was refused, nothing to draw: " + str(answer["error"]))
    if not all(k in answer for k in ("scene", "names", "strike_time")):
        raise TypeError("answer: expected one answer of nineball.fit (with \"scene\", "
                        "\"names\" and \"strike_time\"), found keys " + ", ".join(answer))
    if isinstance(recording, str):
        recording = json.loads(recording)
    if not isinstance(recording, Mapping) or not isinstance(recording.get("balls"), Mapping):
        raise TypeError("recording: expected the recorded shot the answer fitted (a dict with "
                        "\"balls\"), found " + type(recording).__name__)
    scene: Dict[str, Any] = dict(answer["scene"])
    names: Mapping[str, str] = answer["names"]
    recorded: Mapping[str, Any] = recording["balls"]
    missing = [n for n in names.values() if n not in recorded]
    if missing:
        raise ValueError("recording: has no ball " + ", ".join(map(repr, missing))
                         + " of the answer's names: is it the shot the answer fitted?")
    t = _as_table(scene.get("table", "9ft"), scene.get("physics"))
    game = _game(scene.get("table", "9ft"), t, scene, [int(i) for i in names])
    if ax is None:
        ax = _new_axes(t)
    _draw_table(ax, t)
    run = nineball.simulate(dict(scene, trace={"hz": 100}))
    paths = _paths(run, None)
    handles: List[Any] = []
    colours: Dict[int, str] = {}
    for sid, name in names.items():
        # A ball recorded by its colour's name or by its number takes that colour, else its
        # scene id's (fit numbers the scene's balls 0, 1, ... whatever they were called).
        named = _NAMED.get(name.lower())
        colour = (_hex(named) if named is not None
                  else ball_colour(int(name) if name.isdigit() else int(sid), game)[0])
        colours[int(sid)] = colour
        rec = recorded[name]
        ax.plot(np.asarray(rec["x"], dtype=float), np.asarray(rec["y"], dtype=float),
                linestyle="none", marker="o", markersize=2.2, color=colour, alpha=0.85,
                markeredgewidth=0, zorder=4)
        path = paths.get(int(sid))
        if path is not None:
            ax.plot(path.x, path.y, color=colour, linewidth=1.1, zorder=4.5)
            ax.plot(path.x, path.y, color="#111111", linewidth=2.4, alpha=0.35, zorder=4.4)
        handles.append(Line2D([], [], color=colour, marker="o", markersize=4,
                              label=name if name == sid else f"{name} (scene ball {sid})"))
    for b in scene["balls"]:
        name = names.get(str(b["id"]), "")
        if name.isdigit():  # drawn as the numbered ball it is (a stripe striped)
            _draw_ball(ax, int(name), float(b["x"]), float(b["y"]), t.ball_radius, game,
                       alpha=0.45, number=False)
        else:
            _draw_ball(ax, int(b["id"]), float(b["x"]), float(b["y"]), t.ball_radius, game,
                       alpha=0.45, number=False, colour=colours.get(int(b["id"])))
    handles.append(Line2D([], [], linestyle="none", marker="o", markersize=3, color="#dddddd",
                          label="recorded"))
    handles.append(Line2D([], [], color="#dddddd", label="fitted"))
    _legend(ax, [], [], handles)
    rmse = answer.get("rmse_m") or {}
    ident = answer.get("id", "")
    ax.set_title((f"{ident}: " if ident != "" else "")
                 + "recorded (dots) and fitted (lines)"
                 + (f", RMSE {rmse['full'] * 1000:.1f} mm" if "full" in rmse else ""),
                 fontsize=9)
    return ax


def animate(result: Union["nineball.Result", types.ResultDoc, Mapping[str, Any]],
            path: Optional[str] = None, fps: float = 30,
            scene: Optional[Union[types.Scene, Mapping[str, Any], str]] = None
            ) -> "FuncAnimation":
    """The run as a matplotlib FuncAnimation, ``fps`` frames a second of simulated time: the
    balls to scale in their colours, each trailing its path, until the run ends.

    ``result`` must carry a trace; with a Result that knows its physics (or with ``scene``)
    each frame is the run's exact state (state_at), else the trace's samples interpolated.
    ``scene`` (the scene the result came from) also gives the table, else "9ft". ``path`` ending in ".gif" saves a GIF (Pillow), ".html" a page that plays it
    (``to_jshtml``). In a notebook the returned animation shows as that player.
    """
    import matplotlib
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.animation import FuncAnimation, PillowWriter

    result = _check_result(result)
    if not result.get("trace"):
        raise ValueError("result: has no trace to animate; simulate the scene with "
                         "\"trace\": {\"hz\": 100} (or {\"events_only\": true})")
    if isinstance(fps, bool) or not isinstance(fps, (int, float)) or not 0 < fps <= 240:
        raise ValueError("fps: expected a number of frames a second in (0, 240], found "
                         + repr(fps))
    if path is not None and not str(path).lower().endswith((".gif", ".html")):
        raise ValueError("path: expected a file name ending in .gif or .html, found "
                         + repr(path))
    given = _as_scene(scene)
    physics = _physics_of(result, given)
    t = _as_table(given.get("table", "9ft") if given is not None else "9ft", physics)
    ids = [int(b["id"]) for b in result["balls"]]
    game = _game(None, t, given, ids)
    paths = _paths(result, {"balls": [], "physics": physics or {}} if given is not None
                   else None)
    first = max(float(p.t[0]) for p in paths.values())
    last = min(float(p.t[-1]) for p in paths.values())
    frames = np.append(np.arange(first, last, 1.0 / fps), last)
    gone: Dict[int, float] = {}  # a ball off the table vanishes at its event
    for e in result["events"]:
        if e.get("type") == "off_table":
            gone.setdefault(int(e["ball"]), float(e["t"]))

    fig_ax = _new_axes(t, width=8.0, legend=False)
    fig = fig_ax.figure
    fig.set_facecolor("#161a1e")
    _draw_table(fig_ax, t)
    balls: Dict[int, List[Any]] = {}
    trails: Dict[int, Any] = {}
    for ball_id, p in paths.items():
        colour = ball_colour(ball_id, game)[0]
        (trails[ball_id],) = fig_ax.plot([], [], color=colour, linewidth=1.0, alpha=0.6,
                                         zorder=3)
        balls[ball_id] = _draw_ball(fig_ax, ball_id, float(p.x[0]), float(p.y[0]),
                                    t.ball_radius, game)
    clock = fig_ax.text(0.01, 0.99, "", transform=fig_ax.transAxes, ha="left", va="top",
                        color="white", fontsize=9, zorder=10)

    def frame(k: int) -> List[Any]:
        now = float(frames[k])
        for ball_id, p in paths.items():
            i = max(int(np.searchsorted(p.t, now, side="right")) - 1, 0)
            x, y = _at(p, now)
            hidden = p.phase[i] == "pocketed" or now >= gone.get(ball_id, np.inf)
            upto = p.t <= now
            trails[ball_id].set_data(np.append(p.x[upto], x), np.append(p.y[upto], y))
            for artist in balls[ball_id]:
                artist.set_visible(not hidden)
                if hasattr(artist, "set_center"):
                    artist.set_center((x, y))
                elif hasattr(artist, "set_xy"):
                    artist.set_xy((x - t.ball_radius, y - 0.55 * t.ball_radius))
                else:
                    artist.set_position((x, y))
        clock.set_text(f"t = {now:5.2f} s")
        return []

    anim = FuncAnimation(fig, frame, frames=len(frames), interval=1000.0 / fps, blit=False)
    # A notebook shows an animation through _repr_html_, which matplotlib leaves empty unless
    # rcParams["animation.html"] says how: here the JavaScript player, unless set otherwise.
    if matplotlib.rcParams["animation.html"] == "none":
        setattr(anim, "_repr_html_", anim.to_jshtml)
    if path is not None:
        if str(path).lower().endswith(".gif"):
            anim.save(path, writer=PillowWriter(fps=fps), dpi=80)
        else:
            with open(path, "w", encoding="utf-8") as f:
                f.write(anim.to_jshtml(fps=fps))
    backend = matplotlib.get_backend().lower()
    if "inline" in backend or backend in ("agg", "pdf", "ps", "svg", "cairo", "template"):
        # The animation keeps the figure; a notebook would also show it as a still.
        plt.close(fig)
    return anim
