"""Recording ids of a built manifest: one per physical run and channel, never two merged.

A manifest reader groups rows by (machine, recording_id, channel): rows that
share them are one recording's acquisitions. A manifest built from a tree
must therefore give each run of a machine its own ``recording_id`` and each
signal of a run its own ``channel``, or two recordings become one:

- a tree that reuses run names under each condition folder (``healthy/run1``,
  ``fault/run1``) would give one ``run1`` holding both conditions. When a run
  name repeats with different labels (speed, condition, severity) on one
  machine, every ``recording_id`` is built from the labels as
  ``[speed/]condition [severity]/run`` (``fault 2/run1``), and a note says so;
- a file's signals named after their variable with ``/`` made ``-``
  (``g/a-b`` and ``g-a/b`` are both ``g-a-b``), or two files of one run with
  the same stem (``a.npy``, ``a.csv``), would give one channel. Names that
  collide get ``~1``, ``~2``... in path and variable order (the same in every
  run), and a note says so;
- with ``{channel}`` in the template, two files giving the same recording (the
  reader strips labels: ``run1`` and ``run1 `` are one) are refused naming both.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

from ..errors import SDTError
from .readers import SignalInfo
from .tokens import quote

__all__ = ["Matched", "name_recordings"]


@dataclass
class Matched:
    """A file the template matched: labels from its path, signals from its reader."""

    where: PurePosixPath
    file: Path
    fields: dict[str, str]
    infos: list[SignalInfo]
    full_scale_g: str = ""
    run_id: str = ""
    channels: list[str] = field(default_factory=list)


def _labels(m: Matched) -> tuple[str, str, str]:
    return m.fields.get("speed", ""), m.fields["condition"], m.fields["severity"]


def _run_ids(matched: list[Matched], template: str) -> list[str]:
    """Set each file's run id; a note when run names repeat and ids come from the labels."""
    runs: dict[tuple[str, str], dict[tuple[str, str, str], PurePosixPath]] = {}
    for m in matched:
        key = (m.fields.get("machine", ""), m.fields["run"])
        runs.setdefault(key, {}).setdefault(_labels(m), m.where)
    clashes = [(key, found) for key, found in runs.items() if len(found) > 1]
    for m in matched:
        speed, condition, severity = _labels(m)
        run = m.fields["run"]
        m.run_id = "/".join([*([speed] if speed else []), f"{condition} {severity}".strip(), run])
        m.run_id = m.run_id if clashes else run
    if not clashes:
        return []
    labels: dict[tuple[str, str], Matched] = {}
    for m in matched:  # "x 2" with no severity and "x" at severity 2 read alike
        first = labels.setdefault((m.fields.get("machine", ""), m.run_id), m)
        if _labels(first) != _labels(m):
            raise SDTError(
                f"--pattern {quote(template, 80)}: {first.where} and {m.where} would both be "
                f"run {quote(m.run_id)} with different labels; rename one run"
            )
    (_, run), found = clashes[0]
    first_path, second_path = list(found.values())[:2]
    example = next(m.run_id for m in matched if m.where == first_path)
    return [
        f"run names repeat with different labels on one machine ({len(clashes)} of them, e.g. "
        f"{quote(run)} in {first_path} and {second_path}); each recording_id is built from "
        f"the labels as [speed/]condition [severity]/run, e.g. {quote(example)}"
    ]


def _numbered(matched: list[Matched]) -> list[str]:
    """Channel names from the signals (no ``{channel}``), collisions numbered; notes."""
    by_run: dict[tuple[str, str], dict[str, list[tuple[str, str, Matched, int]]]] = {}
    for m in matched:
        m.channels = []
        for index, info in enumerate(m.infos):
            variable = "" if info.variable is None else str(info.variable)
            name = (variable or m.file.stem).replace("/", "-").strip() or m.file.stem
            m.channels.append(name)
            run = by_run.setdefault((m.fields.get("machine", ""), m.run_id), {})
            run.setdefault(name, []).append((str(m.where), variable, m, index))
    collisions = []
    for (_, run_id), names in by_run.items():
        for name, signals in names.items():
            if len(signals) < 2:
                continue
            signals.sort(key=lambda s: s[:2])
            for number, (_, _, m, index) in enumerate(signals, 1):
                m.channels[index] = f"{name}~{number}"
            collisions.append((run_id, name, signals))
    if not collisions:
        return []
    run_id, name, signals = collisions[0]
    what = ", ".join(quote(f"{w} {v}" if v else w, 60) for w, v, *_ in signals[:3])
    return [
        f"{len(collisions)} channel name(s) shared by several signals of a run, e.g. "
        f"{quote(name)} in run {quote(run_id)} ({what}); named {name}~1, {name}~2, ... in "
        f"that order (the manifest's variable column says which is which)"
    ]


def _refuse_shared(matched: list[Matched], template: str, with_channel: bool) -> None:
    """Two signals still giving one (machine, run, channel): refuse naming both.

    With ``{channel}`` the signals of one file are that channel's acquisitions;
    without it, each signal must have a channel of its own."""
    seen: dict[tuple[str, str, str], tuple[PurePosixPath, str]] = {}
    for m in matched:
        for info, channel in zip(m.infos, m.channels, strict=True):
            key = (m.fields.get("machine", ""), m.run_id, channel)
            signal = (m.where, "" if info.variable is None else str(info.variable))
            first = seen.setdefault(key, signal)
            if first[0] != m.where or (not with_channel and first != signal):
                both = " and ".join(
                    f"{w} {quote(v, 60)}" if v else str(w) for w, v in (first, signal)
                )
                machine = f" of machine {quote(key[0], 60)}" if key[0] else ""
                raise SDTError(
                    f"--pattern {quote(template, 80)}: {both} would both be run "
                    f"{quote(m.run_id, 60)} channel {quote(channel, 60)}{machine} (labels are "
                    f"read without leading or trailing spaces); rename one"
                )


def name_recordings(matched: list[Matched], template: str, with_channel: bool) -> list[str]:
    """Set ``run_id`` and ``channels`` of every matched file; notes for the user.

    Raises
    ------
    SDTError
        When two files would still be one recording; the message names both.
    """
    notes = _run_ids(matched, template)
    if with_channel:
        for m in matched:
            m.channels = [m.fields["channel"]] * len(m.infos)
    else:
        notes += _numbered(matched)
    _refuse_shared(matched, template, with_channel)
    return notes
