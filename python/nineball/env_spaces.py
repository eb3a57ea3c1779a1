"""The spaces nineball.env describes its observations and actions with when Gymnasium is not
installed: the attributes and methods of Gymnasium's (shape, dtype, low, high, n, spaces,
sample, contains, seed), so code written for either reads both."""

from typing import Any, Dict as _Dict, Optional, Sequence, Tuple, Union

__all__ = ["Box", "Discrete", "MultiBinary", "Dict"]


class _Space:
    def __init__(self) -> None:
        import numpy as np

        self._rng = np.random.default_rng()

    def seed(self, seed: Optional[int] = None) -> None:
        import numpy as np

        self._rng = np.random.default_rng(seed)


class Box(_Space):
    """Reals between ``low`` and ``high`` (numbers or arrays) of ``shape``."""

    def __init__(self, low: Any, high: Any, shape: Optional[Sequence[int]] = None,
                 dtype: Any = float):
        import numpy as np

        super().__init__()
        if shape is None:
            shape = np.shape(low)
        self.shape: Tuple[int, ...] = tuple(int(d) for d in shape)
        self.dtype = np.dtype(dtype)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), self.shape).copy()

    def sample(self) -> Any:
        return self._rng.uniform(self.low, self.high).astype(self.dtype)

    def contains(self, x: Any) -> bool:
        import numpy as np

        a = np.asarray(x)
        return bool(a.shape == self.shape and np.all(a >= self.low) and np.all(a <= self.high))

    def __repr__(self) -> str:
        return f"Box({self.shape}, {self.dtype})"


class Discrete(_Space):
    """The integers 0 to n - 1."""

    def __init__(self, n: int):
        import numpy as np

        super().__init__()
        self.n = int(n)
        self.shape: Tuple[int, ...] = ()
        self.dtype = np.dtype(np.int64)

    def sample(self) -> int:
        return int(self._rng.integers(self.n))

    def contains(self, x: Any) -> bool:
        return isinstance(x, int) and 0 <= x < self.n or hasattr(x, "item") and 0 <= x < self.n

    def __repr__(self) -> str:
        return f"Discrete({self.n})"


class MultiBinary(_Space):
    """Arrays of 0 and 1 of ``shape``."""

    def __init__(self, shape: Union[int, Sequence[int]]):
        import numpy as np

        super().__init__()
        self.shape: Tuple[int, ...] = (int(shape),) if isinstance(shape, int) else tuple(shape)
        self.n = self.shape
        self.dtype = np.dtype(np.int8)

    def sample(self) -> Any:
        return self._rng.integers(0, 2, self.shape, dtype=self.dtype)

    def contains(self, x: Any) -> bool:
        import numpy as np

        a = np.asarray(x)
        return bool(a.shape == self.shape and np.all((a == 0) | (a == 1)))

    def __repr__(self) -> str:
        return f"MultiBinary({self.shape})"


class Dict(_Space):
    """Named spaces (an observation's parts)."""

    def __init__(self, spaces: _Dict[str, Any]):
        super().__init__()
        self.spaces = dict(spaces)

    def __getitem__(self, key: str) -> Any:
        return self.spaces[key]

    def sample(self) -> _Dict[str, Any]:
        return {k: s.sample() for k, s in self.spaces.items()}

    def contains(self, x: Any) -> bool:
        return isinstance(x, dict) and set(x) == set(self.spaces) and all(
            s.contains(x[k]) for k, s in self.spaces.items())

    def __repr__(self) -> str:
        return "Dict(" + ", ".join(f"{k}: {s!r}" for k, s in self.spaces.items()) + ")"
