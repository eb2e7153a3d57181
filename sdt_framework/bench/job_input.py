"""A featurising job's input: its recording read, with its node's other axes.

A worker reads the recording once (and the node's other two axes, which the
plan gives only when a sensor's chain reads them: cross-axis sensitivity) and
hands the samples to every sensor of the job as one
:class:`~sdt_framework.chain.shared.SharedPrefix`. A feature-cache entry found
corrupt on the way is a warning the worker cannot print reliably (on Dask its
output goes to the worker's log): it becomes a note the orchestrator shows.
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence

from ..chain.shared import SharedPrefix
from ..data.cache import CacheEntryWarning
from ..data.recording import Recording

__all__ = ["open_noting", "other_axes"]


def other_axes(axis: str) -> list[str]:
    """The node's other two axes, in the order the plan gives their recordings."""
    return sorted({"x", "y", "z"} - {axis})


def _open(recording: Recording, node: Sequence[Recording], axis: str) -> SharedPrefix:
    label = f"{recording.source} ({recording.recording_id})"
    others = None
    if node:
        others = {name: r.load() for name, r in zip(other_axes(axis), node, strict=True)}
    return SharedPrefix(
        recording.load(), recording.sampling_rate_hz, label=label, other_axes=others
    )


def open_noting(
    recording: Recording, node: Sequence[Recording], axis: str, notes: list[str]
) -> SharedPrefix:
    """``recording`` read (with ``node``, the other axes of ``axis``), the cache entries
    discarded on the way added to ``notes``; other warnings are issued again as they were."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", CacheEntryWarning)
        shared = _open(recording, node, axis)
    for item in caught:
        if issubclass(item.category, CacheEntryWarning):
            notes.append(str(item.message))
        else:  # not ours to reword: issued again as it was
            warnings.warn_explicit(item.message, item.category, item.filename, item.lineno)
    return shared
