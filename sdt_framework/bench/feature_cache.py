"""One feature-cache entry on disk: the arrays of a block, its counts and their digest.

An entry is an ``.npz`` archive holding a block's feature values, acquisition
and window indices, how many of the degraded signal's samples sat at the
sensor's full scale (and of how many), and a SHA-256 digest of all of them
together with the entry's key. A cache folder may be shared (a lab server, a
copied folder): an entry whose contents were changed after it was written, even
one of the right shape, no longer matches its digest and is refused, so it is
discarded and recomputed instead of changing results without a word. The
digest detects changes by anyone who does not recompute it; it is not a
signature against a deliberate forger with write access to the cache.

An entry's key names the recording's file by the digest of its bytes
(:func:`source_states`), never by its size and modification time alone.
"""

from __future__ import annotations

import hashlib
import os
from collections.abc import Iterable
from pathlib import Path

import numpy as np

from ..data.digest import file_digest
from ..data.recording import Recording
from ..io import atomic_path

__all__ = ["CachedBlock", "ChecksumMismatchError", "read_entry", "source_states", "write_entry"]

#: values, acquisition, window, and (samples at full scale, samples) as an int64 pair
CachedBlock = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]


class ChecksumMismatchError(ValueError):
    """An entry whose contents do not match the digest stored with them."""


def _digest(key: str, arrays: CachedBlock) -> str:
    sha = hashlib.sha256(key.encode())
    for array in arrays:
        contiguous = np.ascontiguousarray(array)
        sha.update(f"{contiguous.dtype.str}{contiguous.shape}".encode())
        sha.update(contiguous.tobytes())
    return sha.hexdigest()


def write_entry(path: Path, key: str, arrays: CachedBlock) -> None:
    """Store ``arrays`` under ``path`` atomically, with their digest."""
    values, acquisition, window, counts = arrays
    with atomic_path(path) as tmp, tmp.open("wb") as handle:
        np.savez(
            handle,
            values=values,
            acquisition=acquisition,
            window=window,
            counts=counts,
            digest=np.array(_digest(key, arrays)),
        )


def read_entry(path: Path, key: str, n_features: int) -> CachedBlock:
    """The arrays of the entry at ``path``, checked.

    Raises
    ------
    ChecksumMismatchError
        The contents differ from what was written (the digest does not match).
    ValueError, KeyError, OSError, zipfile.BadZipFile
        The entry is damaged or not one (see ``data.cache.CORRUPT_ENTRY_ERRORS``).
    """
    with np.load(path, allow_pickle=False) as stored:
        arrays = (stored["values"], stored["acquisition"], stored["window"], stored["counts"])
        digest = str(stored["digest"])
    values, acquisition, window, counts = arrays
    if (
        values.ndim != 2
        or values.shape[1] != n_features
        or values.dtype != np.float32
        or acquisition.shape != (len(values),)
        or window.shape != (len(values),)
        or counts.shape != (2,)
    ):
        raise ValueError("arrays of the wrong shape")
    if digest != _digest(key, arrays):
        raise ChecksumMismatchError("contents differ from their checksum")
    return arrays


def source_states(recordings: Iterable[Recording], cache_dir: str | None) -> dict[str, str | None]:
    """Source -> the digest of its file's bytes (None for generated data, which has no file),
    each file hashed once, the digests remembered in ``cache_dir`` ({} without a cache: no
    entry is keyed)."""
    if cache_dir is None:
        return {}
    return {
        r.source: file_digest(r.source, cache_dir) if os.path.isfile(r.source) else None
        for r in recordings
    }
