"""Discrete, Box and MultiDiscrete spaces: Gymnasium's own when gymnasium is importable, else
these, which offer the same attributes and methods (n or nvec; low, high, shape, dtype; sample,
contains, seed). batch_space: the space of N envs' actions or observations, as Gymnasium's."""
import numpy as np

try:
    import gymnasium

    GYMNASIUM = True
except ImportError:  # everything works the same without it
    gymnasium = None
    GYMNASIUM = False


class _Space:
    def __init__(self, shape, dtype, seed=None):
        self.shape = shape
        self.dtype = np.dtype(dtype)
        self.np_random = np.random.default_rng(seed)

    def seed(self, seed=None):
        self.np_random = np.random.default_rng(seed)
        return [seed]


class FallbackDiscrete(_Space):
    """{0, ..., n - 1}."""

    def __init__(self, n, seed=None):
        super().__init__((), np.int64, seed)
        self.n = int(n)
        self.start = 0

    def sample(self, mask=None):
        if mask is None:
            return np.int64(self.np_random.integers(self.n))
        allowed = np.flatnonzero(np.asarray(mask))
        return np.int64(self.np_random.choice(allowed)) if allowed.size else np.int64(0)

    def contains(self, x):
        if isinstance(x, (bool, np.bool_)):
            return False
        if isinstance(x, (int, np.integer)):
            return 0 <= int(x) < self.n
        if isinstance(x, np.ndarray) and x.shape == () and np.issubdtype(x.dtype, np.integer):
            return 0 <= int(x) < self.n
        return False

    def __repr__(self):
        return "Discrete(%d)" % self.n


class FallbackBox(_Space):
    """The product of the intervals [low[i], high[i]]."""

    def __init__(self, low, high, dtype=np.float32, seed=None):
        low = np.asarray(low, dtype=dtype)
        high = np.asarray(high, dtype=dtype)
        super().__init__(low.shape, dtype, seed)
        self.low, self.high = low, high

    def sample(self, mask=None):
        return self.np_random.uniform(self.low, self.high).astype(self.dtype)

    def contains(self, x):
        x = np.asarray(x)
        return (x.shape == self.shape and np.issubdtype(x.dtype, np.number)
                and bool(np.all(np.isfinite(x))) and bool(np.all(x >= self.low))
                and bool(np.all(x <= self.high)))

    def __repr__(self):
        return "Box(%s, %s, %s, %s)" % (self.low, self.high, self.shape, self.dtype)


class FallbackMultiDiscrete(_Space):
    """One Discrete(nvec[i]) per element: N envs' discrete actions."""

    def __init__(self, nvec, dtype=np.int64, seed=None):
        self.nvec = np.asarray(nvec, dtype=dtype)
        super().__init__(self.nvec.shape, dtype, seed)
        self.start = np.zeros_like(self.nvec)

    def sample(self, mask=None):
        return self.np_random.integers(self.nvec).astype(self.dtype)

    def contains(self, x):
        x = np.asarray(x)
        return (x.shape == self.shape and x.dtype.kind in "iu" and bool(np.all(x >= 0))
                and bool(np.all(x < self.nvec)))

    def __repr__(self):
        return "MultiDiscrete(%s)" % self.nvec


def fallback_batch_space(space, n):
    """Gymnasium's batch_space for our two spaces: Discrete(k) -> MultiDiscrete([k] * n), a Box
    of shape s -> a Box of shape (n, *s) with the bounds repeated."""
    if isinstance(space, FallbackDiscrete):
        return FallbackMultiDiscrete(np.full(n, space.n, dtype=space.dtype), dtype=space.dtype)
    repeats = (n,) + (1,) * space.low.ndim
    return FallbackBox(np.tile(space.low, repeats), np.tile(space.high, repeats), dtype=space.dtype)


if GYMNASIUM:
    Discrete = gymnasium.spaces.Discrete
    Box = gymnasium.spaces.Box
    MultiDiscrete = gymnasium.spaces.MultiDiscrete
    batch_space = gymnasium.vector.utils.batch_space
else:
    Discrete = FallbackDiscrete
    Box = FallbackBox
    MultiDiscrete = FallbackMultiDiscrete
    batch_space = fallback_batch_space


def float32_box(bounds):
    """A float32 Box between the C++ env's (low, high) bounds."""
    low, high = bounds
    return Box(np.array(low, np.float32), np.array(high, np.float32), dtype=np.float32)


def action_space_of(env):
    """The C++ env's moves, or with no moves (a continuous action space) its displacement Box."""
    if env.action_count > 0:
        return Discrete(env.action_count)
    return float32_box(env.action_bounds)
