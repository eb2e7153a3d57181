"""The archive's speed folders: which ones to read, and the speed each one stands for.

The archive keeps every operating point in a folder of its own,
``Vibration/Motor-<k>/<speed>/``, named by the percentage of rated speed:
Motor-2 at 50, 75 and 100 %, Motor-4 at 70 %. The shaft speed at that point
is the rig's (``../pump_rig.toml``: each operating point with its source, read
by :meth:`~sdt_framework.specs.MachineSpec.speed_at`, which scales the rated
speed where no source gives the point, and says so). So every recording
carries ``speed`` (the folder's name), ``speed_percent`` (its number),
``speed_rpm`` (the rig's) and ``speed_source`` (which of them says what).

A ``speeds`` option selects folders: ``"all"``, one speed or a list of them
(``"50"``, ``50`` and ``50.0`` all name the folder ``50``), or a mapping
machine -> those; a machine it does not name reads the paper's speed.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping
from numbers import Real

from sdt_framework.errors import SDTError
from sdt_framework.specs import MachineSpec

__all__ = ["ALL", "FolderSpeed", "asked_speeds", "folder_speed", "speed_filter"]

#: the ``speeds`` value that reads every speed folder of the archive
ALL = "all"

#: (speed_percent, speed_rpm, speed_source) of one speed folder
FolderSpeed = tuple[float | None, float | None, str]


def _number(text: str) -> float | None:
    """``"50"`` -> 50.0; a name that is no finite positive number -> None."""
    try:
        value = float(text) if text.isascii() else math.nan
    except ValueError:
        return None
    return value if math.isfinite(value) and value > 0 else None


def _names(value: object) -> list[str | float]:
    """The speeds one selection names, each a folder name or a number; anything else refused."""
    items = [value] if isinstance(value, str | Real) else value
    if not isinstance(items, Iterable) or isinstance(items, Mapping):
        raise SDTError(
            f"speeds = {value!r}: give 'all', a speed folder ('50' or 50) or a list of them"
        )
    out: list[str | float] = []
    for item in items:
        if isinstance(item, bool) or not isinstance(item, str | Real):
            raise SDTError(
                f"speeds: {item!r} is not a speed folder; give its name ('50') or its number (50)"
            )
        out.append(str(item).strip() if isinstance(item, str) else float(item))
    if not out:
        raise SDTError("speeds: an empty list selects nothing; name a speed folder, or 'all'")
    return out


def _matcher(value: object) -> Callable[[str], bool]:
    """Whether a folder name is one of the speeds ``value`` names (``"all"``: every one)."""
    if isinstance(value, str) and value.strip().lower() == ALL:
        return lambda folder: True
    names = _names(value)
    texts = {n for n in names if isinstance(n, str)}
    numbers = [n for n in names if isinstance(n, float)] + [
        v for v in map(_number, texts) if v is not None
    ]

    def matches(folder: str) -> bool:
        number = _number(folder)
        return folder in texts or (
            number is not None and any(math.isclose(number, n) for n in numbers)
        )

    return matches


def asked_speeds(speeds: object, machine: str) -> object:
    """What ``speeds`` asks of ``machine`` (None: nothing, the paper's speed); a bad value
    anywhere in it is refused now, before any folder is read."""
    for value in speeds.values() if isinstance(speeds, Mapping) else [speeds]:
        if value is not None:
            _matcher(value)
    return speeds.get(machine) if isinstance(speeds, Mapping) else speeds


def speed_filter(
    speeds: object, machine: str, paper_speed: str | None
) -> Callable[[str], bool] | None:
    """Which speed folders of ``machine`` to read; None: every one.

    ``speeds`` None (or a mapping that does not name the machine) reads the
    paper's speed of the machine (``paper_speed``; None: a machine the paper
    does not use, all of its folders).
    """
    speeds = asked_speeds(speeds, machine)
    if speeds is None:
        return None if paper_speed is None else (lambda folder: folder == paper_speed)
    return _matcher(speeds)


def folder_speed(machine: str, folder: str, spec: MachineSpec | None) -> FolderSpeed:
    """The speed the folder ``folder`` of ``machine`` stands for, with where it comes from."""
    percent = _number(folder)
    where = f"the archive's speed folder {folder!r}"
    if percent is None:
        return None, None, f"{where} (not a percentage of rated speed: no shaft speed)"
    if spec is None:
        return percent, None, f"{where} (% of rated); the rig describes no {machine}: no rpm"
    point = spec.speed_at(percent)
    if point is None:
        return (
            percent,
            None,
            f"{where} (% of rated); no shaft speed: the rig's machine file gives none for "
            f"{machine} at {percent:g} % and no rated speed to scale",
        )
    return percent, point.shaft_rpm, f"{where} (% of rated), shaft speed: {point.source}"
