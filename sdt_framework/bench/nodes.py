"""Triaxial nodes: the other two axes a node stage (cross-axis sensitivity) reads.

A node is one run's three channels that ``[benchmark] axes`` maps to x, y and
z: the same acquisitions recorded at once on the three axes of one sensor.
When a sensor's chain has a node stage, every recording the benchmark uses
must belong to a complete node; :func:`find_nodes` pairs each with its two
partners (looked up among all the dataset's recordings, so a benchmark may
score one channel while reading the others) or names, in one line, what is
missing before any work starts.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from ..data.recording import Recording
from ..errors import SDTError
from ..registry import Registry
from ..specs import SensorSpec
from ..stages import uses_node

__all__ = ["find_nodes", "node_sensors"]

EXAMPLE = "e.g. axes = {ch1 = 'x', ch2 = 'y', ch3 = 'z'}"


def node_sensors(sensors: Sequence[SensorSpec], registry: Registry) -> list[str]:
    """Names of the sensors whose chain (or a unit drawn from it) has a node stage."""
    names = []
    for sensor in sensors:
        drawn = {key.partition(".")[0] for key in sensor.tolerances if "." in key}
        if uses_node(registry.bind(sensor)) or any(registry.stage(n).node for n in drawn):
            names.append(sensor.name)
    return names


def find_nodes(
    used: Sequence[Recording],
    everything: Sequence[Recording],
    axes: Mapping[str, str],
    users: Sequence[str],
) -> dict[str, tuple[Recording, Recording]]:
    """The two partner recordings (in axis order) of every recording in ``used``.

    Parameters
    ----------
    used
        The recordings the benchmark scores.
    everything
        All the dataset's recordings (partners may be channels not scored).
    axes
        Channel -> axis, from the configuration.
    users
        The sensors that need nodes, named in the errors.

    Raises
    ------
    SDTError
        A channel with no axis, a run lacking an axis or mapping two channels
        to one, or partners whose shape or rate differ.
    """
    need = f"sensor(s) {list(users)} read triaxial nodes (cross-axis)"
    runs: dict[tuple[str, str, str], list[Recording]] = {}
    for rec in everything:
        if rec.channel in axes:
            runs.setdefault((rec.machine, rec.run, axes[rec.channel]), []).append(rec)
    out: dict[str, tuple[Recording, Recording]] = {}
    for rec in used:
        if rec.channel not in axes:
            raise SDTError(
                f"{need}: channel {rec.channel!r} (e.g. {rec.recording_id}) has no axis; map "
                f"three channels of each run to x, y and z in [benchmark] axes ({EXAMPLE})"
            )
        partners = []
        for axis in sorted({"x", "y", "z"} - {axes[rec.channel]}):
            found = runs.get((rec.machine, rec.run, axis), [])
            if len(found) != 1:
                have = "no channel" if not found else f"channels {[r.channel for r in found]}"
                raise SDTError(
                    f"{need}: run {rec.machine}/{rec.run} has {have} on axis {axis!r}; a node "
                    f"needs one channel per axis in [benchmark] axes ({EXAMPLE})"
                )
            partners.append(found[0])
        for other in partners:
            if (other.sampling_rate_hz, other.n_acquisitions, other.samples_per_acquisition) != (
                rec.sampling_rate_hz,
                rec.n_acquisitions,
                rec.samples_per_acquisition,
            ):
                raise SDTError(
                    f"{need}: {other.recording_id} ({other.source}) and {rec.recording_id} "
                    f"({rec.source}) differ in rate or shape; the axes of a node must be "
                    f"recorded together"
                )
        out[rec.recording_id] = (partners[0], partners[1])
    return out
