"""The two signals of a paired recording, the pair, and the digest that names its files."""

from __future__ import annotations

import hashlib
import os
from collections.abc import Iterable
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from ..errors import SDTError

__all__ = ["Pair", "Signal", "digest", "scaled_reference", "unit_mistake"]


def unit_mistake() -> str:
    """The likely cause a check names when a rate cannot be right (a pair's sides differing
    in length or outside the plausible rates, a device off its part's rate): one wording
    for every such check."""
    return "a time column in ms or a rate_hz in kHz? (time columns are in s, rate_hz in Hz)"


@dataclass(frozen=True)
class Signal:
    """One sensor's recording of the pair: axes on rows, in g, on an even time grid."""

    label: str
    part: str | None
    axes: tuple[str, ...]
    values: np.ndarray  # float64 (n_axes, n_samples)
    rate_hz: float
    start_s: float
    note: str | None = None
    rate_sd_hz: float = float("nan")  # standard error of the measured rate

    @property
    def end_s(self) -> float:
        """Time of the last sample, s."""
        return self.start_s + (self.values.shape[1] - 1) / self.rate_hz


@dataclass(frozen=True)
class Pair:
    """A reference and a device that measured the same vibration on one clock."""

    path: str
    reference: Signal
    device: Signal
    digest: str  # first 12 hex digits of the file's SHA-256 (names the data in provenance)

    @property
    def name(self) -> str:
        """The file's name."""
        return Path(self.path).name


def scaled_reference(pair: Pair, factor: float) -> Pair:
    """``pair`` with its reference's values multiplied by ``factor`` (``--reference-scale``:
    a reference whose calibration the check found off), said in the reference's note.
    A factor of 1 returns ``pair`` itself; the factor is checked by the caller
    (:func:`.verdict.check_reference_scale`) before any file is read."""
    if factor == 1.0:
        return pair
    ref = pair.reference
    note = f"reference values multiplied by {factor:g} (--reference-scale)"
    note = "; ".join(filter(None, (ref.note, note)))
    return replace(pair, reference=replace(ref, values=ref.values * factor, note=note))


def digest(*paths: str | os.PathLike[str]) -> str:
    """First 12 hex digits of the SHA-256 of the files' bytes, in order (names a pair's data
    in a fitted profile's provenance)."""
    sha = hashlib.sha256()
    for path in paths:
        with open(path, "rb") as handle:
            for block in iter(lambda: handle.read(1 << 20), b""):
                sha.update(block)
    return sha.hexdigest()[:12]


def chosen_axes(
    path: str | os.PathLike[str],
    reference: Iterable[str],
    device: Iterable[str],
    axes: list[str] | None,
    between: str,
) -> list[str]:
    """The axes to compare: ``axes`` (default: every axis both sides carry), in x, y, z order.

    ``between`` names the two sides in the error (``"both signals"``, ``"both
    channels 32 and 80"``) when an asked axis is missing on one of them or
    they share none.
    """
    both = set(reference) & set(device)
    common = [a for a in "xyz" if a in both]
    chosen = axes or common
    twice = [a for a in dict.fromkeys(chosen) if chosen.count(a) > 1]
    if twice:
        raise SDTError(
            f"{path}: axes {','.join(chosen)} name axis {twice[0]!r} twice; name each axis "
            f"once (a repeated axis would be compared, and its bands counted, twice)"
        )
    missing = [a for a in chosen if a not in common]
    if missing or not chosen:
        raise SDTError(
            f"{path}: axis {missing[0] if missing else '-'!r} is not on {between}; "
            f"they share {', '.join(common) or 'no axis'}"
        )
    return chosen
