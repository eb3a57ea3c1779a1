"""Sweeps that outgrow one machine: nineball's simulations on a Dask cluster.

    from dask.distributed import Client, LocalCluster
    import nineball.dask

    if __name__ == "__main__":  # a LocalCluster's workers import this script again
        client = Client(LocalCluster(n_workers=2))    # or Client("tcp://scheduler:8786")
        results = nineball.dask.simulate(client, scenes)

The scenes are cut into chunks; each chunk runs on a worker with the compiled core
(nineball.simulate_many, the GIL released) and the results come back in the scenes' order.
Every worker needs nineball importable (installed, or on its PYTHONPATH). Dask itself is
optional: ``import nineball`` never imports it, only this module does (Debian:
python3-distributed).
"""

from typing import TYPE_CHECKING, Any, List, Mapping, Sequence, Union

if TYPE_CHECKING:
    from . import Result

__all__ = ["simulate"]


def _simulate_chunk(scenes: List[Any], threads: int, first_index: int) -> List["Result"]:
    # Runs on a worker: imports the worker's own nineball.
    from nineball import _core

    return _core.simulate_many(scenes, threads, first_index)


def simulate(client: Any, scenes: Sequence[Union[Mapping[str, Any], str]], chunk: int = 64,
             threads: int = 1) -> List["Result"]:
    """Simulates ``scenes`` on the cluster behind ``client`` (a dask.distributed.Client);
    the results in the scenes' order, as nineball.simulate_many returns them.

    ``chunk``: scenes per task (fewer, larger tasks cost less in scheduling; more spread
    better over many workers). ``threads``: threads each task uses on its worker (1 suits a
    worker per core). A bad scene raises ValueError naming its index in ``scenes``. The scenes
    are checked on the workers, so check one locally first (nineball.simulate) when a whole
    sweep is built from it.
    """
    if isinstance(scenes, (dict, str, bytes)):
        raise TypeError("scenes: expected a list of scenes, found one "
                        + ("dict" if isinstance(scenes, dict) else "string"))
    if isinstance(chunk, bool) or not isinstance(chunk, int) or chunk < 1:
        raise ValueError("chunk: expected an int >= 1, found " + repr(chunk))
    scenes = list(scenes)
    starts = list(range(0, len(scenes), chunk))
    futures = client.map(_simulate_chunk, [scenes[i:i + chunk] for i in starts],
                         [threads] * len(starts), starts, pure=False)
    results: List["Result"] = []
    try:
        for future in futures:
            results.extend(future.result())
    finally:
        client.cancel(futures)
    return results

