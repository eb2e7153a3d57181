"""The one seeding function of the project.

Every random draw (SDT noise per acquisition, classifier seeds per repetition)
derives its seed from the run's base seed and the names/indices of the
components involved, so results are reproducible and independent of the order
or the process in which runs execute.
"""

from __future__ import annotations

import hashlib

import numpy as np

__all__ = ["derive_seed", "rng"]


def derive_seed(base: int, *components: object) -> int:
    """A 32-bit seed determined by ``base`` and ``components`` (any str-able values)."""
    text = "\x1f".join([str(int(base)), *map(str, components)])
    return int.from_bytes(hashlib.sha256(text.encode()).digest()[:4], "little")


def rng(base: int, *components: object) -> np.random.Generator:
    """A numpy Generator seeded by :func:`derive_seed`."""
    return np.random.default_rng(derive_seed(base, *components))
