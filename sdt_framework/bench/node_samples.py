"""Node-level samples: one feature vector per window per triaxial node.

The paper classifies every channel on its own; a triaxial MEMS node sends one
feature vector per axis (96 bytes for paper8 at float32) and the diagnosis
is made per node. With ``[benchmark] sample = "node"`` each window of a node
becomes one sample whose features are its x, y and z vectors concatenated
(``x:rms, x:kurtosis, ..., z:...``: 24 values for paper8), the split still by
physical run. A node is three channels of one run that ``[benchmark] axes``
maps to x, y and z: by default the one node those channels form, or several
named in ``[benchmark] nodes`` (e.g. a motor and a pump bearing housing), each
its own sample set. Node runs are added beside the channel runs (the paper's
protocol, unchanged), labelled ``sensor = "S @ NODE"``.

Every run the benchmark scores must hold every node's three channels, with
the same rate and shape: checked before any work, one line naming what is
missing.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import pandas as pd

from ..data.recording import Recording
from ..errors import SDTError

__all__ = ["Node", "node_frame", "resolve_nodes"]

AXES = ("x", "y", "z")
EXAMPLE = "e.g. axes = {ch1 = 'x', ch2 = 'y', ch3 = 'z'}"


@dataclass(frozen=True)
class Node:
    """A named node: its channels in x, y, z order."""

    name: str
    channels: tuple[str, str, str]


def _node(name: str, channels: Sequence[str], axes: Mapping[str, str]) -> Node:
    unmapped = [c for c in channels if c not in axes]
    if unmapped:
        raise SDTError(
            f"sample = 'node': node {name!r} channel {unmapped[0]!r} has no axis in "
            f"[benchmark] axes ({EXAMPLE})"
        )
    by_axis = {axes[c]: c for c in channels}
    if len(channels) != 3 or sorted(by_axis) != list(AXES):
        found = ", ".join(f"{c}={axes[c]}" for c in channels)
        raise SDTError(
            f"sample = 'node': node {name!r} ({found}) needs one channel on each of x, y and z"
        )
    return Node(name, (by_axis["x"], by_axis["y"], by_axis["z"]))


def _check_names_and_channels(named: Mapping[str, Sequence[str]]) -> None:
    """Refuse an empty or blank node name and a channel two nodes claim.

    An empty name labelled rows ``adxl345 @ `` (unreadable, and the same label
    for every such node); a channel in two nodes made one recording count as
    two samples of two nodes, so both nodes and the channel are named.
    """
    owner: dict[str, str] = {}
    for name, channels in named.items():
        if not name.strip() or name != name.strip():
            raise SDTError(
                f"sample = 'node': [benchmark] nodes has a node named {name!r}; give each node "
                f"a non-blank name without surrounding spaces, e.g. nodes = {{de = [...]}}"
            )
        for channel in dict.fromkeys(channels):
            if channel in owner:
                raise SDTError(
                    f"sample = 'node': channel {channel!r} is in node {owner[channel]!r} and in "
                    f"node {name!r}; a channel belongs to one node (one sensor records it)"
                )
            owner[channel] = name


def resolve_nodes(
    axes: Mapping[str, str],
    named: Mapping[str, Sequence[str]] | None,
    used: Sequence[Recording],
) -> list[Node]:
    """The nodes to classify, each checked complete in every run of ``used``.

    Raises
    ------
    SDTError
        No axes, a node without one channel per axis, or a run lacking a node's
        channel (or holding it at another rate or shape).
    """
    if not axes:
        raise SDTError(
            f"sample = 'node' needs [benchmark] axes mapping three channels of a node to "
            f"x, y and z ({EXAMPLE})"
        )
    if named:
        _check_names_and_channels(named)
        nodes = [_node(name, list(channels), axes) for name, channels in named.items()]
    else:
        if sorted(axes.values()) != list(AXES):
            raise SDTError(
                f"sample = 'node': [benchmark] axes {dict(axes)} is not one node (one channel "
                f"per axis); name the nodes, e.g. nodes = {{de = ['ch1', 'ch2', 'ch3']}}"
            )
        nodes = [_node("node", list(axes), axes)]
    runs: dict[tuple[str, str], dict[str, Recording]] = {}
    for rec in used:
        held = runs.setdefault((rec.machine, rec.run), {})
        if rec.channel in held:
            raise SDTError(
                f"sample = 'node': run {rec.machine}/{rec.run} holds channel {rec.channel!r} "
                f"twice ({held[rec.channel].source}, {rec.source}); a node needs one recording "
                f"per channel and run"
            )
        held[rec.channel] = rec
    for (machine, run), channels in sorted(runs.items()):
        for node in nodes:
            missing = [c for c in node.channels if c not in channels]
            if missing:
                raise SDTError(
                    f"sample = 'node': run {machine}/{run} has no channel {missing[0]!r} of node "
                    f"{node.name!r}; every run needs all three (check --channels and the data)"
                )
            shapes = {
                (r.sampling_rate_hz, r.n_acquisitions, r.samples_per_acquisition)
                for r in (channels[c] for c in node.channels)
            }
            if len(shapes) != 1:
                raise SDTError(
                    f"sample = 'node': the channels of node {node.name!r} in run {machine}/{run} "
                    f"differ in rate or shape; a node's axes are recorded together"
                )
    return nodes


def node_frame(features: pd.DataFrame, node: Node, names: Sequence[str]) -> pd.DataFrame:
    """One row per window of ``node``: its axes' feature vectors side by side.

    ``features`` is the benchmark's per-channel feature table; the result has
    its metadata columns (``channel`` gone, ``recording_id`` the node's:
    ``<x channel's id>@<node>``) and the columns ``x:<feature>``, ``y:...``,
    ``z:...``, rows in a fixed order (machine, run, sensor, unit, repeat,
    acquisition, window).
    """
    keys = ["machine", "run", "sensor", *(["unit"] if "unit" in features else []), "repeat",
            "acquisition", "window"]  # fmt: skip
    part = features[features["channel"].isin(node.channels)]
    wide = part.set_index([*keys, "channel"])[list(names)].unstack("channel")
    columns = [(f, c) for c in node.channels for f in names]
    values = wide.reindex(columns=pd.MultiIndex.from_tuples(columns))
    if values.isna().to_numpy().any():
        raise SDTError(f"node {node.name!r}: a window lacks one of its axes {node.channels}")
    values.columns = [f"{axis}:{f}" for axis in AXES for f in names]
    values = values.sort_index().reset_index()
    first = part[part["channel"] == node.channels[0]]
    meta = first.drop_duplicates(["machine", "run"]).set_index(["machine", "run"])
    meta = meta.reindex(pd.MultiIndex.from_frame(values[["machine", "run"]]))
    values.insert(2, "condition", meta["condition"].to_numpy())
    values.insert(3, "severity", meta["severity"].to_numpy())
    values.insert(4, "recording_id", [f"{r}@{node.name}" for r in meta["recording_id"]])
    values["severity"] = values["severity"].astype("Int64")
    return values
