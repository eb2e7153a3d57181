"""Local cache of parsed arrays, keyed by the source file's path, size and mtime.

Parsing a 100 MB NLN-EMP CSV takes a fraction of a second with pyarrow but
the archive is ~80 GB; a second pass (another scenario, another sensor) should
not parse again. Parsed arrays are stored as ``.npy`` files; the key changes
when the source file is modified (size or mtime), so a stale entry is never
used. Writes are atomic, and failures are never cached.
"""

from __future__ import annotations

import hashlib
import os
from collections.abc import Callable, Mapping
from pathlib import Path

import numpy as np

from ..io import atomic_path

__all__ = ["ENV_CACHE_DIR", "ArrayCache", "default_cache_dir"]

ENV_CACHE_DIR = "SDT_CACHE_DIR"


def default_cache_dir(environ: Mapping[str, str] | None = None) -> Path:
    """``$SDT_CACHE_DIR`` if set, else ``~/.cache/sdt-framework``."""
    environ = os.environ if environ is None else environ
    value = environ.get(ENV_CACHE_DIR)
    return Path(value).expanduser() if value else Path.home() / ".cache" / "sdt-framework"


class ArrayCache:
    """A folder of ``.npy`` files, one per (source file, size, mtime, variant).

    Parameters
    ----------
    root
        Cache folder (created on first write). None uses :func:`default_cache_dir`.
    enabled
        False turns the cache into a pass-through (always parse, never write).
    """

    VERSION = "1"

    def __init__(self, root: str | os.PathLike[str] | None = None, *, enabled: bool = True) -> None:
        self.root = Path(root).expanduser() if root is not None else default_cache_dir()
        self.enabled = enabled

    def key(self, source: str | os.PathLike[str], variant: str = "") -> str:
        """Hex key of a source file in its current state (path, size, mtime)."""
        path = Path(source).resolve()
        stat = path.stat()
        parts = [self.VERSION, str(path), str(stat.st_size), str(stat.st_mtime_ns), variant]
        text = "\x1f".join(parts)
        return hashlib.sha256(text.encode()).hexdigest()[:32]

    def path_for(self, source: str | os.PathLike[str], variant: str = "") -> Path:
        """Where the parsed array of ``source`` is (or would be) stored."""
        return self.root / "arrays" / f"{self.key(source, variant)}.npy"

    def get_or_compute(
        self,
        source: str | os.PathLike[str],
        compute: Callable[[], np.ndarray],
        variant: str = "",
    ) -> np.ndarray:
        """The cached array of ``source``, or ``compute()`` stored for next time.

        A corrupt cache entry is recomputed; an exception from ``compute``
        propagates and nothing is written.
        """
        if not self.enabled:
            return compute()
        target = self.path_for(source, variant)
        if target.exists():
            try:
                return np.load(target, allow_pickle=False)
            except (OSError, ValueError):
                target.unlink(missing_ok=True)
        data = compute()
        try:
            with atomic_path(target) as tmp, open(tmp, "wb") as handle:
                np.save(handle, data, allow_pickle=False)
        except OSError:
            pass  # a read-only or full cache folder must not stop the analysis
        return data
