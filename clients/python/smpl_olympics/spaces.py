"""Observation and action spaces: gymnasium's Box when gymnasium is importable, otherwise a small
class with the same surface (shape, dtype, low, high, contains, sample, seed), so code written
for gymnasium runs unchanged and nothing beyond numpy is required."""
import numpy as np


class Box:
    """A box in R^n of float32, like gymnasium.spaces.Box (the parts a trainer uses)."""

    def __init__(self, low, high, shape, dtype=np.float32, seed=None):
        self.shape = tuple(shape)
        self.dtype = np.dtype(dtype)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), self.shape).copy()
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)
        return [seed]

    def contains(self, x):
        x = np.asarray(x)
        if x.shape != self.shape or not np.can_cast(x.dtype, self.dtype, casting="same_kind"):
            return False
        return bool(np.all(x >= self.low) and np.all(x <= self.high))

    def __contains__(self, x):
        return self.contains(x)

    def sample(self):
        """Uniform where both bounds are finite, normal where a bound is infinite (as gymnasium)."""
        low, high = self.low.astype(np.float64), self.high.astype(np.float64)
        out = np.empty(self.shape, dtype=np.float64)
        bounded = np.isfinite(low) & np.isfinite(high)
        out[bounded] = self._rng.uniform(low[bounded], high[bounded])
        below, above = np.isfinite(low) & ~bounded, np.isfinite(high) & ~bounded
        free = ~(bounded | below | above)
        out[free] = self._rng.normal(size=int(free.sum()))
        out[below] = low[below] + self._rng.exponential(size=int(below.sum()))
        out[above] = high[above] - self._rng.exponential(size=int(above.sum()))
        return out.astype(self.dtype)

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"

    def __eq__(self, other):
        return (isinstance(other, Box) and self.shape == other.shape
                and np.array_equal(self.low, other.low) and np.array_equal(self.high, other.high))


def box(low, high):
    """A Box with these per-entry bounds: gymnasium's when installed, else ours."""
    low = np.asarray(low, dtype=np.float32)
    high = np.asarray(high, dtype=np.float32)
    try:
        import gymnasium
    except ImportError:
        return Box(low, high, low.shape)
    return gymnasium.spaces.Box(low, high, shape=low.shape, dtype=np.float32)
