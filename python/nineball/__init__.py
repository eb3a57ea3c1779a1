"""nineball: the pool table's physics, headless.

The same parser, checks, engines and result format as the command ``nineball sim``: a scene
(a dict, or its JSON text) in, the result dict out, trajectories as numpy arrays when numpy is
installed. A bad scene raises ValueError with the command line's message, naming the field.

- simulate(scene): one scene.
- simulate_many(scenes, threads=0): many, in order, on every core.
- continue_from(scene, result, shot=None, until=None): the scene that goes on from a result.
- to_json(doc): a result or scene as JSON text, numpy arrays as lists.

Ctrl-C stops a run at its next event and raises KeyboardInterrupt. The scene and result
formats: docs/cli.md; this package: docs/python.md.
"""

from typing import Any, Dict, Iterable, List, Mapping, Optional, Union

from . import _core

__version__: str = _core.__version__

#: A scene of ``nineball sim``: a dict (numpy numbers and arrays allowed) or its JSON text.
Scene = Union[Mapping[str, Any], str]
#: A result of ``nineball sim`` as Python objects.
Result = Dict[str, Any]

__all__ = ["simulate", "simulate_many", "continue_from", "to_json", "Scene", "Result",
           "__version__"]


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


def continue_from(scene: Scene, result: Result, shot: Optional[Mapping[str, Any]] = None,
                  until: Optional[float] = None) -> Dict[str, Any]:
    """The scene that goes on from where ``result`` (of ``scene``) stopped.

    It keeps ``scene``'s table, physics and step, puts every ball still on the table where and
    as the result left it (its mass from ``scene``), and adds ``shot`` and ``until`` when given
    (else the balls roll on to rest). Feed it to simulate.
    """
    return _core.continue_from(scene, result, shot, until)


def to_json(doc: Union[Result, Mapping[str, Any]]) -> str:
    """A result (or a scene) as JSON text, a trace's numpy arrays written as lists."""
    return _core.to_json(doc)
