# Types of the compiled core (python/nineball_module.cpp and the module_*.cpp); the documented
# calls are nineball's (see __init__.py), which check and convert their arguments first.
# Every function the core exports has a line here (tests/python/test_types.py checks it).
from typing import Any, ClassVar, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

import numpy
import numpy.typing

from . import Result
from .types import (Ball, BallState, CalibrateAnswer, FitAnswer, MatchResult, Physics,
                    PlanAnswer, Recording, Scene, ScriptTurn, StatesAtTimes, SweepArrays,
                    TableGeometry)

# A scene, script or result as the core reads it: a dict (numpy numbers and arrays allowed)
# or its JSON text.
_Doc = Union[Mapping[str, Any], str]
# Recorded shots: one, a list of them, or their JSON (or JSON Lines) text.
_Shots = Union[Mapping[str, Any], Sequence[Mapping[str, Any]], str]

__version__: str
PRESETS: Tuple[str, ...]
TABLES: Tuple[str, ...]

def simulate(scene: _Doc) -> Result: ...
def simulate_many(scenes: Iterable[_Doc], threads: int = ...,
                  first_index: int = ...) -> List[Result]: ...
def continue_from(scene: _Doc, result: Mapping[str, Any],
                  shot: Optional[Mapping[str, Any]] = ...,
                  until: Optional[Union[float, str]] = ...) -> Scene: ...
def state_at(result: Mapping[str, Any], t: float, scene: _Doc) -> List[BallState]: ...
def table_geometry(scene: _Doc) -> TableGeometry: ...
def rack(game: str, seed: int, scene: _Doc) -> List[Ball]: ...
def match(script: _Doc) -> MatchResult: ...
def preset(name: str) -> Physics: ...
def plan(scene: _Doc) -> PlanAnswer: ...
def to_json(doc: object) -> str: ...
def fit(shots: _Shots, evals: int, objective: str, seed: int, threads: int) -> List[FitAnswer]: ...
def calibrate(shots: _Shots, params: List[str], holdout: float, seed: int, evals: int,
              refit_evals: int, candidates: int, threads: int) -> CalibrateAnswer: ...
def record(scene: _Doc, names: List[str], hz: float, noise: float, strike: float,
           seed: int) -> Recording: ...

# The arrays calls (python/module_arrays.cpp, module_state.cpp): numpy arrays in, a dict of
# numpy arrays out (docs/python.md, simulate_arrays and state_at).
EVENT_TYPES: List[str]

def simulate_arrays(scene: _Doc, places: numpy.typing.ArrayLike, shots: numpy.typing.ArrayLike,
                    ids: List[int], threads: int = ...) -> SweepArrays: ...
def batch_arrays(scenes: Iterable[_Doc], threads: int = ...,
                 first_index: int = ...) -> SweepArrays: ...
def state_at_times(result: Mapping[str, Any], times: numpy.typing.ArrayLike,
                   scene: _Doc) -> StatesAtTimes: ...

# The game environments' tables (python/module_env.cpp), behind nineball.env.
GAMES: Tuple[str, ...]
NOISE_MODELS: Tuple[str, ...]

_Floats = numpy.typing.NDArray[numpy.float64]
_Bools = numpy.typing.NDArray[numpy.bool_]
_Ints = numpy.typing.NDArray[numpy.int64]
# places, on_table, state
_Observation = Tuple[_Floats, _Bools, _Floats]
# places, on_table, state, reward, terminated, truncated, executed, legal, potted,
# opponent_turns, winner
_Step = Tuple[_Floats, _Bools, _Floats, _Floats, _Bools, _Bools, _Floats, _Bools, _Ints, _Ints,
              _Ints]

class Tables:
    state_names: ClassVar[List[str]]
    def __init__(self, name: str, n: int, opponent: Optional[str], noise: str, engine: str,
                 seed: int, threads: int, rewards: Optional[Mapping[str, float]],
                 max_turns: int) -> None: ...
    def __len__(self) -> int: ...
    @property
    def ids(self) -> List[int]: ...
    @property
    def table_size(self) -> Tuple[float, float]: ...
    @property
    def last_step_seconds(self) -> float: ...
    def reset(self, seed: Optional[int],
              starts: Optional[Sequence[Optional[Mapping[str, Any]]]]) -> _Observation: ...
    def step_array(self, actions: numpy.typing.ArrayLike, autoreset: bool) -> _Step: ...
    def step_dicts(self, actions: List[Mapping[str, Any]], autoreset: bool) -> _Step: ...
    def teacher(self, level: str) -> List[Optional[ScriptTurn]]: ...
