"""Local cache of parsed arrays, keyed by the source file's path and the digest of its bytes.

Parsing a 100 MB NLN-EMP CSV takes a fraction of a second with pyarrow but
the archive is ~80 GB; a second pass (another scenario, another sensor) should
not parse again. Parsed arrays are stored as ``.npz`` files holding the array
and a SHA-256 digest of it and its key (as the feature cache's entries do);
the key changes when the source file's bytes do (:mod:`.digest`: a file
rewritten with its size and mtime kept, by ``cp -p`` or ``rsync -a``, too), so
a stale entry is never used. Writes are atomic, and failures are never cached. An
entry that is corrupt (truncated, foreign) or whose contents were changed after
it was written (its digest does not match: a shared or copied cache folder, a
damaged disk) is named in one :class:`CacheEntryWarning`, discarded and
recomputed. The digest catches a change by anyone who does not recompute it;
it is not a signature.
"""

from __future__ import annotations

import hashlib
import os
import warnings
import zipfile
from collections.abc import Callable, Mapping
from pathlib import Path

import numpy as np

from ..errors import SDTError, SDTWarning
from ..io import atomic_path
from .digest import file_digest

__all__ = [
    "CORRUPT_ENTRY_ERRORS",
    "ENV_CACHE_DIR",
    "ArrayCache",
    "CacheEntryWarning",
    "default_cache_dir",
]

ENV_CACHE_DIR = "SDT_CACHE_DIR"

#: What reading a damaged .npy/.npz raises (truncated, not a zip, pickled, unreadable).
CORRUPT_ENTRY_ERRORS = (OSError, ValueError, EOFError, KeyError, zipfile.BadZipFile)


class CacheEntryWarning(SDTWarning):
    """A cache entry discarded (corrupt, or changed after it was written) and recomputed.

    Raised as a warning where the entry is read; the benchmark's workers pass
    it on to the main process as a note, and the CLI prints it as one
    ``warning:`` line.
    """


def default_cache_dir(environ: Mapping[str, str] | None = None) -> Path:
    """``$SDT_CACHE_DIR`` if set, else ``$HOME/.cache/sdt-framework``.

    Raises
    ------
    SDTError
        When neither is usable: HOME unset or empty (and no home folder in the
        user database) or naming a folder that does not exist. Nothing is
        created in an unintended place (an empty HOME would otherwise mean ``/``).
    """
    environ = os.environ if environ is None else environ
    value = environ.get(ENV_CACHE_DIR)
    if value:
        return Path(value).expanduser()
    hint = f"set {ENV_CACHE_DIR} (or --cache-dir) to a writable folder"
    home = environ.get("HOME")
    if home is None:
        home = _user_database_home()
    if not home:
        raise SDTError(f"cannot find your home folder (HOME is not set) for the cache; {hint}")
    if not Path(home).is_dir():
        raise SDTError(f"HOME is {home!r}, which is not a folder, so there is no cache; {hint}")
    return Path(home) / ".cache" / "sdt-framework"


def _user_database_home() -> str | None:
    """The home folder of this user in the system's user database, if any."""
    try:
        import pwd
    except ImportError:  # not POSIX: Path.home() knows the platform's rule
        try:
            return str(Path.home())
        except RuntimeError:
            return None
    try:
        return pwd.getpwuid(os.getuid()).pw_dir
    except KeyError:  # e.g. a container started with an arbitrary uid
        return None


class ChecksumMismatchError(ValueError):
    """A cache entry whose contents do not match the digest stored with them."""


def _digest(key: str, data: np.ndarray) -> str:
    sha = hashlib.sha256(key.encode())
    sha.update(f"{data.dtype.str}{data.shape}".encode())
    sha.update(np.ascontiguousarray(data).data)
    return sha.hexdigest()


def _read_entry(path: Path, key: str) -> np.ndarray:
    """The array of the entry at ``path``; ValueError if it differs from its digest."""
    with np.load(path, allow_pickle=False) as stored:
        data, digest = stored["data"], str(stored["digest"])
    if digest != _digest(key, data):
        raise ChecksumMismatchError("contents differ from their checksum")
    return data


class ArrayCache:
    """A folder of ``.npz`` entries, one per (source file, its digest, variant).

    Parameters
    ----------
    root
        Cache folder (created on first write). None uses :func:`default_cache_dir`.
    enabled
        False turns the cache into a pass-through (always parse, never write).
    """

    VERSION = "3"  # 2: .npz entries with a digest (1: bare .npy); 3: sources by their digest

    def __init__(self, root: str | os.PathLike[str] | None = None, *, enabled: bool = True) -> None:
        self.enabled = enabled
        if root is not None:
            self.root = Path(root).expanduser()
        else:  # a disabled cache needs no folder (and no HOME)
            self.root = default_cache_dir() if enabled else Path()

    def key(self, source: str | os.PathLike[str], variant: str = "") -> str:
        """Hex key of a source file in its current state (path, digest of its bytes)."""
        path = Path(source).resolve()
        parts = [self.VERSION, str(path), file_digest(path, self.root), variant]
        text = "\x1f".join(parts)
        return hashlib.sha256(text.encode()).hexdigest()[:32]

    def path_for(self, source: str | os.PathLike[str], variant: str = "") -> Path:
        """Where the parsed array of ``source`` is (or would be) stored."""
        return self.root / "arrays" / f"{self.key(source, variant)}.npz"

    def get_or_compute(
        self,
        source: str | os.PathLike[str],
        compute: Callable[[], np.ndarray],
        variant: str = "",
    ) -> np.ndarray:
        """The cached array of ``source``, or ``compute()`` stored for next time.

        A corrupt or changed cache entry is named in a :class:`CacheEntryWarning`,
        removed and recomputed; an exception from ``compute`` propagates and
        nothing is written.
        """
        if not self.enabled:
            return compute()
        key = self.key(source, variant)
        target = self.root / "arrays" / f"{key}.npz"
        if target.exists():
            try:
                return _read_entry(target, key)
            except ChecksumMismatchError:
                reason = "was changed after it was written (its checksum does not match)"
            except CORRUPT_ENTRY_ERRORS as exc:
                reason = f"is corrupt ({type(exc).__name__})"
            warnings.warn(
                f"cache entry {target} of {source} {reason}; discarded, reading the file again",
                CacheEntryWarning,
                stacklevel=2,
            )
            target.unlink(missing_ok=True)
        data = compute()
        try:
            with atomic_path(target) as tmp, open(tmp, "wb") as handle:
                np.savez(handle, data=data, digest=np.array(_digest(key, data)))
        except OSError:
            pass  # a read-only or full cache folder must not stop the analysis
        return data
