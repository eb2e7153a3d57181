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
  (``g/a-b`` and ``g-a/b`` are both ``g-a-b``) would give one channel. Names
  that collide anywhere in the manifest get ``~1``, ``~2``... in the order of
  the signal names (``g-a/b`` is ``g-a-b~1`` in every run), and a note says so;
- with ``{channel}`` in the template, two files giving the same recording (the
  reader strips labels: ``run1`` and ``run1 `` are one) are refused naming both.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

from ..errors import SDTError
from ..signals.rules import SignalInfo
from ..signals.tokens import quote

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
    """Channel names from the signals (no ``{channel}``), one per source name; notes.

    A signal's source name is its variable (the file's stem when it has none);
    its channel is that name with ``/`` written ``-``. Where two source names
    give one channel anywhere in the manifest, each gets ``~N`` by the order of
    the source names, so a variable has the same channel in every run."""
    sources: dict[str, set[str]] = {}
    for m in matched:
        m.channels = []
        for info in m.infos:
            source = m.file.stem if info.variable is None else str(info.variable)
            name = source.replace("/", "-").strip() or m.file.stem
            sources.setdefault(name, set()).add(source)
            m.channels.append(name)
    numbers = {
        (name, source): f"{name}~{number}"
        for name, found in sources.items()
        if len(found) > 1
        for number, source in enumerate(sorted(found), 1)
    }
    for m in matched:
        for index, info in enumerate(m.infos):
            source = m.file.stem if info.variable is None else str(info.variable)
            m.channels[index] = numbers.get((m.channels[index], source), m.channels[index])
    shared = {name: sorted(found) for name, found in sources.items() if len(found) > 1}
    if not shared:
        return []
    name, found = next(iter(shared.items()))
    what = ", ".join(f"{quote(source, 60)} -> {name}~{k}" for k, source in enumerate(found, 1))
    return [
        f"{len(shared)} channel name(s) would be given to signals of different names, e.g. "
        f"{quote(name, 60)} ({what}); numbered by signal name, the same in every run (the "
        f"manifest's variable column says which is which)"
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
