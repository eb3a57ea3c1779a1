"""The package's types: mypy --strict on its sources and on a user's script (typed_usage.py),
a script it must refuse, the core's stub against the core, and every TypedDict of
nineball.types against what the calls really return."""
import ast
import collections.abc
import os
import re
import subprocess
import sys
import typing

import numpy as np
import pytest

import nineball
from nineball import _core
from nineball import types as nt

SOURCE = os.environ.get("NINEBALL_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
PYTHON = os.path.join(SOURCE, "python")
PACKAGE = os.path.join(PYTHON, "nineball")
HERE = os.path.dirname(os.path.abspath(__file__))
# The package's modules held to --strict (each new one joins the list once typed).
STRICT = ["__init__.py", "types.py", "plot.py", "env.py", "env_spaces.py", "dask.py",
          "_core.pyi"]
# The functions of __init__.py not held to it yet (a name leaves this list once its function
# passes): none.
NOT_YET_STRICT: tuple = ()

# matplotlib ships its types from 3.8 on (Debian 12 has 3.6), tqdm none, and Gymnasium (which
# nineball.env uses when it is installed) is not in Debian: all three are Any to the checker,
# everything else is checked.
MYPY_INI = """\
[mypy]
strict = True
follow_imports = silent
[mypy-matplotlib.*]
ignore_missing_imports = True
[mypy-tqdm.*]
ignore_missing_imports = True
[mypy-gymnasium.*]
ignore_missing_imports = True
"""

# What a strict checker must refuse: (the line, a word of the error it must give).
BAD = [
    ('r["balls"][0]["x"] + "a"', "Unsupported operand"),
    ('made: types.Scene = {"balls": [], "shot": {"sped": 2.0}}', "sped"),
    ("radius: float = r.physics[\"ball_radius\"]", "not indexable"),
    ('nineball.state_at(r, 0.5)[0]["phase"] + 1', "Unsupported operand"),
    ('fits[0]["rmse_m"]["fulll"]', "fulll"),
]

# Revealed types that must hold no Any: what each public call returns, and the reads of it.
REVEALED = [
    "nineball.simulate(scene)",
    'r["balls"]',
    'r["balls"][0]["x"]',
    'r["events"][0]',
    'r["trace"]["0"]["x"]',
    "r.physics",
    'r.get("trace")',
    "nineball.simulate_many([scene])",
    "nineball.iter_simulate([scene])",
    "nineball.state_at(r, 0.5)",
    "nineball.continue_from(r)",
    "nineball.rack()",
    "nineball.Table().pockets",
    "nineball.Table().cushion_loop",
    "nineball.TABLES",
    "nineball.preset()",
    "nineball.plan(scene)",
    "nineball.match({})",
    "nineball.record(scene)",
    "nineball.fit([])",
    "nineball.calibrate([], [])",
    "nineball.simulate_arrays([[0.0, 0.0]], [[0.0, 1.0, 0.0, 0.0, 0.0]])",
    'nineball.simulate_batch([scene])["x"]',
    "nineball.state_at(r, [0.0, 0.5])",
    'nineball.env.make("pot").reset()[0]["balls"]',
    'nineball.env.make("pot").step({"heading_deg": 0.0, "speed": 1.0})[1]',
    'nineball.env.make_vec("pot", 2).teacher()',
]


# The probe's first reveal_type line (after its imports and the def line).
FIRST_PROBE_LINE = 6


def _probe() -> str:
    """A script of reveal_type lines: the REVEALED ones, and each key of ResultDoc read from a
    Result and from a ResultDoc (the two must agree)."""
    lines = ["import nineball", "import nineball.env", "from nineball import types", "",
             "def probe(scene: types.Scene, r: nineball.Result, doc: types.ResultDoc) -> None:"]
    lines += [f"    reveal_type({e})" for e in REVEALED]
    for key in nt.ResultDoc.__annotations__:
        lines += [f'    reveal_type(r["{key}"])', f'    reveal_type(doc["{key}"])']
    return "\n".join(lines) + "\n"


def _bad() -> str:
    lines = ["import nineball", "from nineball import types", "",
             "def bad(scene: types.Scene) -> None:",
             "    r = nineball.simulate(scene)",
             "    fits = nineball.fit([])"]
    lines += ["    " + code for code, _ in BAD]
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def mypy(tmp_path_factory):
    """One mypy --strict run over the package, typed_usage.py, the probe and the bad script:
    {file name: [(line, "error" or "note", message)]}."""
    pytest.importorskip("mypy")
    tmp = tmp_path_factory.mktemp("mypy")
    (tmp / "mypy.ini").write_text(MYPY_INI)
    (tmp / "probe.py").write_text(_probe())
    (tmp / "bad.py").write_text(_bad())
    files = [os.path.join(PACKAGE, f) for f in STRICT] + [
        os.path.join(HERE, "typed_usage.py"), str(tmp / "probe.py"), str(tmp / "bad.py")]
    env = dict(os.environ, MYPYPATH=PYTHON)
    env.pop("PYTHONPATH", None)  # the sources' package, not the build's copy of it
    run = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--config-file",
                          str(tmp / "mypy.ini"), "--cache-dir", str(tmp / "cache"),
                          "--no-error-summary", "--show-error-codes", *files],
                         capture_output=True, text=True, env=env, cwd=str(tmp), check=False)
    assert "Traceback" not in run.stderr, run.stderr
    found = {}
    for line in run.stdout.splitlines():
        m = re.match(r"(.+?):(\d+): (error|note): (.*)", line)
        if m:
            found.setdefault(os.path.basename(m.group(1)), []).append(
                (int(m.group(2)), m.group(3), m.group(4)))
    found["_output"] = run.stdout + run.stderr
    return found


def _lines_not_yet_strict():
    """The lines of __init__.py's NOT_YET_STRICT functions."""
    tree = ast.parse(open(os.path.join(PACKAGE, "__init__.py")).read())
    spans = [range(node.lineno, node.end_lineno + 1) for node in tree.body
             if isinstance(node, ast.FunctionDef) and node.name in NOT_YET_STRICT]
    return {line for span in spans for line in span}


@pytest.mark.parametrize("name", STRICT + ["typed_usage.py"])
def test_mypy_strict_passes(mypy, name):
    skipped = _lines_not_yet_strict() if name == "__init__.py" else set()
    errors = [f"{name}:{line}: {msg}" for line, kind, msg in mypy.get(name, [])
              if kind == "error" and line not in skipped]
    assert errors == [], mypy["_output"]


def test_mypy_refuses_what_is_wrong(mypy):
    errors = {line: msg for line, kind, msg in mypy.get("bad.py", []) if kind == "error"}
    first = 7  # the line of BAD[0] in _bad()
    for i, (code, word) in enumerate(BAD):
        assert first + i in errors, f"mypy took `{code}`:\n" + mypy["_output"]
        assert word in errors[first + i], (code, errors[first + i])
    assert len(errors) == len(BAD), errors


def _revealed(found):
    return {line: re.sub(r'^Revealed type is "(.*)"$', r"\1", msg)
            for line, kind, msg in found.get("probe.py", [])
            if kind == "note" and msg.startswith("Revealed type")}


def _any_in(shown):
    """Whether a revealed type holds Any, beyond numpy's (an array's shape is Any to it)."""
    return "Any" in shown.replace("numpy.ndarray[Any,", "numpy.ndarray[")


def test_the_calls_return_real_types(mypy):
    revealed = _revealed(mypy)
    for i, expr in enumerate(REVEALED):
        shown = revealed.get(FIRST_PROBE_LINE + i)
        assert shown is not None, (expr, mypy["_output"])
        assert not _any_in(shown), f"{expr}: {shown}"
    assert revealed[FIRST_PROBE_LINE + REVEALED.index('r["balls"]')].startswith(
        "builtins.list[TypedDict('nineball.types.ResultBall'")
    assert revealed[FIRST_PROBE_LINE + REVEALED.index('r["balls"][0]["x"]')] == "builtins.float"


def test_a_result_reads_as_its_typeddict(mypy):
    revealed = _revealed(mypy)
    line = FIRST_PROBE_LINE + len(REVEALED)
    for key in nt.ResultDoc.__annotations__:
        assert revealed[line] == revealed[line + 1], (key, revealed[line], revealed[line + 1])
        assert not _any_in(revealed[line]), (key, revealed[line])
        line += 2


def _stub():
    """The names _core.pyi declares, functions with their parameters."""
    tree = ast.parse(open(os.path.join(PACKAGE, "_core.pyi")).read())
    functions, names = {}, set()
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            args = node.args
            functions[node.name] = [(a.arg, i >= len(args.args) - len(args.defaults))
                                    for i, a in enumerate(args.args)]
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
        elif isinstance(node, ast.ClassDef):
            names.add(node.name)
    return functions, names


def test_the_core_stub_declares_every_export_with_its_parameters():
    functions, names = _stub()
    exported = {n for n in dir(_core) if not n.startswith("_") or n == "__version__"}
    declared = set(functions) | names
    assert exported - declared == set(), "exports without a line in _core.pyi"
    assert {n for n in declared if not n.startswith("_")} - exported == set(), \
        "lines of _core.pyi the core does not export"
    for name, params in functions.items():
        # pybind11's signature line: "simulate_many(scenes: object, threads: object = 0, ...)"
        head = getattr(_core, name).__doc__.splitlines()[0]
        inside = head[head.index("(") + 1:head.rindex(") ->")]
        actual = [(p.split(":")[0].strip(), "=" in p)
                  for p in re.split(r",\s*(?![^\[]*\])", inside) if p]
        assert actual == params, (name, actual, params)


# --- the TypedDicts against what the calls return ---------------------------------------


def _is_typeddict(tp):
    return isinstance(tp, type) and issubclass(tp, dict) and hasattr(tp, "__required_keys__")


def conform(value, tp, path="doc"):
    """Asserts ``value`` is what ``tp`` (a nineball.types type) says, to the leaves."""
    origin, args = typing.get_origin(tp), typing.get_args(tp)
    if _is_typeddict(tp):
        assert isinstance(value, dict), f"{path}: {type(value).__name__}, not a dict"
        hints = typing.get_type_hints(tp)
        missing = tp.__required_keys__ - value.keys()
        unknown = value.keys() - hints.keys()
        assert not missing, f"{path}: lacks {sorted(missing)} of {tp.__name__}"
        assert not unknown, f"{path}: {sorted(unknown)} not in {tp.__name__}"
        for key, item in value.items():
            conform(item, hints[key], f"{path}.{key}")
    elif origin is typing.Union:
        failures = []
        for arg in args:
            try:
                conform(value, arg, path)
                return
            except AssertionError as e:
                failures.append(str(e))
        raise AssertionError(f"{path}: none of {tp}: {failures}")
    elif origin is typing.Literal:
        assert value in args, f"{path}: {value!r} not one of {args}"
    elif origin in (list, collections.abc.Sequence):
        if isinstance(value, np.ndarray) and origin is collections.abc.Sequence:
            kind = "f" if args[0] is float else "U"
            assert value.dtype.kind == kind, f"{path}: an array of {value.dtype}"
            return
        assert isinstance(value, list), f"{path}: {type(value).__name__}, not a list"
        for i, item in enumerate(value):
            conform(item, args[0], f"{path}[{i}]")
    elif origin is dict:
        assert isinstance(value, dict), f"{path}: {type(value).__name__}, not a dict"
        for key, item in value.items():
            conform(key, args[0], f"{path} key")
            conform(item, args[1], f"{path}[{key!r}]")
    elif tp is float:
        assert isinstance(value, (int, float)) and not isinstance(value, bool), \
            f"{path}: {value!r} is no number"
    elif tp is type(None):
        assert value is None, f"{path}: {value!r} is not None"
    else:
        assert isinstance(value, tp) and (tp is bool or not isinstance(value, bool)), \
            f"{path}: {value!r} is no {tp.__name__}"


def two(**shot):
    return {"balls": [{"id": 0, "x": -0.6, "y": 0.0}, {"id": 1, "x": 0.0, "y": 0.0}],
            "shot": dict({"heading_deg": 0.0, "speed": 6.0}, **shot), "trace": {"hz": 20}}


def test_conform_can_fail():
    with pytest.raises(AssertionError, match="lacks"):
        conform({"id": 0, "x": 0.0}, nt.Ball)
    with pytest.raises(AssertionError, match="not in"):
        conform({"id": 0, "x": 0.0, "y": 0.0, "spin": 1.0}, nt.Ball)
    with pytest.raises(AssertionError, match="no number"):
        conform({"id": 0, "x": "0", "y": 0.0}, nt.Ball)
    with pytest.raises(AssertionError, match="not one of"):
        conform({"t": 0.0, "type": "bounce"}, nt.Event)


def test_results_states_and_scenes_are_their_typeddicts():
    import json

    with open(os.path.join(SOURCE, "docs", "break.json")) as f:
        brk = dict(json.load(f), trace={"hz": 20})
    runs = [nineball.simulate(s) for s in (
        brk, two(elevation_deg=40.0, tip=[0.0, 0.3]), two(tip=[0.0, 0.7]),
        {"balls": [{"id": 0, "x": 1.0, "y": 0.0, "z": 0.3, "vz": 1.0, "vx": 4.0}],
         "trace": {"events_only": True}})]
    kinds = set()
    for r in runs:
        conform(r, nt.ResultDoc, "result")
        conform(nineball.state_at(r, r["events"][-1]["t"]), typing.List[nt.BallState], "state")
        kinds.update(e["type"] for e in r["events"])
        conform(nineball.continue_from(r, until=0.1), nt.Scene, "continue_from")
    assert kinds == set(typing.get_args(nt.EventType)), kinds
    assert set(typing.get_args(nt.PocketName)) == {p.id for p in nineball.Table().pockets}
    plain = json.loads(nineball.to_json(runs[0]))
    del plain["trace"]  # its columns are lists there, as the TypedDict's docstring says
    conform(plain, nt.ResultDoc, "result from JSON")
    for name in nineball.PRESETS:
        conform(nineball.preset(name), nt.Physics, f"preset {name}")
    for table in nineball.TABLES:
        conform(_core.table_geometry({"balls": [], "table": table}), nt.TableGeometry, table)
    for game in ("nine-ball", "eight-ball", "ten-ball", "snooker"):
        conform(nineball.rack(game, 2, "snooker" if game == "snooker" else "9ft"),
                typing.List[nt.Ball], game)


def test_plans_recordings_fits_and_calibrations_are_their_typeddicts():
    balls = [{"id": 0, "x": -0.6, "y": 0.0}, {"id": 1, "x": 0.5, "y": 0.2},
             {"id": 2, "x": -0.2, "y": -0.3}]
    conform(nineball.plan({"balls": balls}, game="ten-ball", level="club"), nt.PlanAnswer)
    conform(nineball.plan({"balls": balls[1:]}, ball_in_hand=True), nt.PlanAnswer)
    scene = dict(two(), balls=balls)
    recorded = [nineball.record(dict(scene, shot={"heading_deg": h, "speed": 2.0}), hz=20,
                                seed=i) for i, h in enumerate((0.0, 10.0))]
    for r in recorded:
        conform(r, nt.Recording, "recording")
    broken = dict(recorded[0], id=7, balls={"0": {"t": [1.0, 0.0], "x": [0, 0], "y": [0, 0]}})
    fits = nineball.fit(recorded + [broken], evals=100)
    assert "error" in fits[2] and "error" not in fits[0]
    conform(fits, typing.List[nt.FitAnswer], "fits")
    cal = nineball.calibrate(recorded, ["rolling_friction"], evals=100, refit_evals=50,
                             candidates=3)
    conform(cal, nt.CalibrateAnswer, "calibrate")


@pytest.mark.parametrize("script", [
    {"game": "nine-ball", "seed": 3, "turns": [{"heading_deg": 0.0, "speed": 10.0}]},
    {"game": "eight-ball", "seed": 3, "turns": [{"heading_deg": 0.0, "speed": 10.0}]},
    {"game": "ten-ball", "seed": 3, "race_to": 2, "turns": [{"heading_deg": 0.0, "speed": 10.0}]},
    {"game": "three-cushion", "turns": [{"heading_deg": 10.0, "speed": 3.0}]},
    {"game": "snooker", "seed": 2, "players": {"A": "ai:beginner", "B": "human"}},
])
def test_matches_are_their_typeddict(script):
    conform(nineball.match(script), nt.MatchResult, script["game"])
