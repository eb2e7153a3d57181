"""MATLAB v5-v7 ``.mat`` files through scipy.io; v7.3 (HDF5) files go to :mod:`.mat73`.

The two share the suffix, so each sniffs the file's header; a headerless v4
file is refused as neither (save it with ``-v7`` or ``-v7.3``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.data.readers import SignalInfo, as_acquisitions, names, orient
from sdt_framework.data.recording import DataFileError
from sdt_framework.data.tokens import brief, quote
from sdt_framework.specs import ReaderSpec

#: HDF5's signature, where a MATLAB v7.3 file (512-byte user block) holds it
HDF5_AT_512 = b"\x89HDF\r\n\x1a\n"


def _variables(path: Path) -> dict[str, tuple[int, ...]]:
    import scipy.io

    try:
        return {name: shape for name, shape, _ in scipy.io.whosmat(path)}
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, NotImplementedError, TypeError) as exc:
        raise DataFileError(f"{path}: not a readable MATLAB file ({brief(exc)})") from None


def scan(path: Path) -> list[SignalInfo]:
    """Every variable of 1 or 2 dimensions (headers only)."""
    found = _variables(path)
    return [SignalInfo(n, *orient(path, s)) for n, s in sorted(found.items()) if len(s) in (1, 2)]


def probe(path: Path, variable: str | None) -> SignalInfo:
    """The named variable, or the file's only one."""
    found = _variables(path)
    if variable is None:
        if len(found) != 1:
            raise DataFileError(
                f"{path}: holds variables {names(sorted(found))}; name one in 'variable'"
            )
        variable = next(iter(found))
    if variable not in found:
        raise DataFileError(f"{path}: no variable {quote(variable)}; found {names(sorted(found))}")
    return SignalInfo(variable, *orient(path, found[variable]))


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (n_acquisitions, n_samples), all finite."""
    import scipy.io

    name = probe(path, variable).variable
    try:
        data = scipy.io.loadmat(path, variable_names=[name])[name]
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, NotImplementedError, TypeError) as exc:
        raise DataFileError(f"{path}: not a readable MATLAB file ({brief(exc)})") from None
    return as_acquisitions(path, data)


def sniff(head: bytes) -> bool:
    """A MATLAB v5-v7 file: its 116-byte text header says so (v7.3 goes to :mod:`.mat73`)."""
    return head.startswith(b"MATLAB 5.0") and head[512:520] != HDF5_AT_512


@hookimpl
def register_signal_readers(register):
    """Register the MATLAB v5-v7 reader."""
    register(
        ReaderSpec(
            name="mat",
            label="MATLAB v5",
            suffixes=(".mat",),
            description="MATLAB v5-v7 .mat variables (scipy.io.loadmat)",
            source="scipy.io",
            sniff=sniff,
            scan=scan,
            probe=probe,
            read=read,
        )
    )
