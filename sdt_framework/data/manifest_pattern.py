"""The path template of ``sdt dataset manifest``: fields, optional fields, and why a path fails.

A template such as ``{machine}/{condition} {severity?}/{run}/{channel}.tdms``
is matched against every file's path below the folder (``/`` separated).
Fields: ``machine``, ``speed``, ``condition``, ``severity``, ``run`` and
``channel``; each matches one or more characters within one folder or file
name (``severity``: a whole number in ASCII digits ``0-9``, or ``-`` for
healthy; a Unicode digit class would take an Arabic-Indic ``٣`` for 3), the
rest of the template literally. ``condition`` and ``run`` are required; an
unknown field (``{cond}``) or a lone brace is refused naming it and the known
ones.

A campaign's healthy folders carry no severity (``healthy/run1`` beside
``bearing 2/run1``, or ``bearing/2/run1``), so one template reads the whole
tree when the field is written optional, ``{severity?}`` (also
``{machine?}``, ``{speed?}``):

- within a name, the field may be missing together with the text between it
  and the field before it (or, first in the name, after it):
  ``{condition} {severity?}`` matches ``healthy`` (no severity) and
  ``bearing 2`` (severity 2); a name ending in a space and a number takes the
  number as the severity, and one holding a digit other than ASCII ``0-9``
  (``bearing ٣``) is not matched;
- alone in a folder name, the folder may be missing:
  ``{condition}/{severity?}/{run}.tdms`` matches ``healthy/run1.tdms`` and
  ``bearing/2/run1.tdms``; where several such folders could be the missing
  ones, the first of them in the template is missing first.

A missing severity is empty (healthy, as ``-``), a missing machine or speed
empty (the manifest reader's defaults).
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Sequence
from dataclasses import dataclass

from ..errors import SDTError
from ..signals.tokens import quote

__all__ = ["FIELDS", "Template", "compile_template"]

FIELDS = ("machine", "speed", "condition", "severity", "run", "channel")
REQUIRED_FIELDS = ("condition", "run")
MAY_BE_MISSING = ("machine", "speed", "severity")
_FIELD = re.compile(r"\{([^{}]*)\}")
_KNOWN = ", ".join("{" + f + "}" for f in FIELDS)


@dataclass(frozen=True)
class Level:
    """One folder or file name of the template; ``optional``: a folder that may be missing."""

    segment: str
    pattern: re.Pattern[str]
    optional: bool


@dataclass(frozen=True)
class Template:
    """A compiled template: its levels and the fields it names (without ``?``)."""

    text: str
    levels: tuple[Level, ...]
    names: tuple[str, ...]

    def match(self, parts: Sequence[str]) -> dict[str, str] | str:
        """The fields of a path (its parts below the folder), or why it does not match."""
        missing = len(self.levels) - len(parts)
        optional = [i for i, level in enumerate(self.levels) if level.optional]
        if not 0 <= missing <= len(optional):
            fewest = len(self.levels) - len(optional)
            levels = f"{fewest} to {len(self.levels)}" if optional else str(len(self.levels))
            return f"{len(parts)} path levels, the pattern has {levels}"
        why = ""
        for dropped in itertools.combinations(optional, missing):
            levels = [level for i, level in enumerate(self.levels) if i not in dropped]
            found = _match_levels(parts, levels)
            if isinstance(found, dict):
                return found
            why = why or found
        return why


def _value(name: str) -> str:
    return "[0-9]+|-" if name == "severity" else "[^/]+?"  # not \d: ٣ is no level


def _segment_regex(segment: str) -> str:
    """The regex of one name; ``{x?}`` takes the literal text before it (after it, when it
    begins the name) into its optional group."""
    parts = re.split(r"(\{[^{}]*\})", segment)  # literal, field, literal, field, ..., literal
    out = [re.escape(text) if i % 2 == 0 else "" for i, text in enumerate(parts)]
    for i in range(1, len(parts), 2):
        name, optional = parts[i][1:-1].rstrip("?"), parts[i].endswith("?}")
        group = f"(?P<{name}>{_value(name)})"
        if not optional:
            out[i] = group
        elif i > 1 or not parts[i + 1] or len(parts) == 3:
            out[i - 1], out[i] = "", f"(?:{re.escape(parts[i - 1])}{group})?"
        else:
            out[i], out[i + 1] = f"(?:{group}{re.escape(parts[i + 1])})?", ""
    return "".join(out)


def _match_levels(parts: Sequence[str], levels: list[Level]) -> dict[str, str] | str:
    fields: dict[str, str] = {}
    for part, level in zip(parts, levels, strict=True):
        found = level.pattern.fullmatch(part)
        digits = "{severity" in level.segment and any(c.isdigit() and not c.isascii() for c in part)
        if found is None or (digits and found.group("severity") is None):
            hint = "; {severity} is ASCII digits 0-9 or '-'" if digits else ""
            return f"{quote(part, 60)} does not match {quote(level.segment, 60)}{hint}"
        for name, value in found.groupdict().items():
            if value is not None:
                if not value.strip():  # the manifest reader strips labels: no label
                    return f"{{{name}}} is only spaces"
                fields[name] = value.strip()
    severity = fields.get("severity", "")
    fields["severity"] = "" if severity == "-" else severity
    return fields


def compile_template(template: str) -> Template:
    """The compiled ``template``; bad templates refused in one line naming the field."""
    written = _FIELD.findall(template)
    names = [name.removesuffix("?") for name in written]
    unknown = [name for name in dict.fromkeys(names) if name not in FIELDS]
    if unknown:
        raise SDTError(
            f"--pattern {quote(template, 80)}: unknown field(s) "
            f"{', '.join('{' + quote(n, 40)[1:-1] + '}' for n in unknown)}; the fields are {_KNOWN}"
        )
    stray = _FIELD.sub("", template)
    if "{" in stray or "}" in stray:
        raise SDTError(
            f"--pattern {quote(template, 80)}: a {'{' if '{' in stray else '}'!r} without its "
            f"pair; write each field as {{name}}, one of {_KNOWN}"
        )
    fixed = [n for n, w in zip(names, written, strict=True) if w.endswith("?")]
    fixed = [n for n in fixed if n not in MAY_BE_MISSING]
    if fixed:
        raise SDTError(
            f"--pattern {quote(template, 80)}: {{{fixed[0]}?}} cannot be missing; only "
            f"{', '.join('{' + n + '?}' for n in MAY_BE_MISSING)} may be (write {{{fixed[0]}}})"
        )
    missing = [f for f in REQUIRED_FIELDS if f not in names]
    if missing:
        raise SDTError(
            f"--pattern {quote(template, 80)}: names no {{{missing[0]}}}; a manifest needs the "
            f"condition and the run of every file"
        )
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise SDTError(f"--pattern {quote(template, 80)}: field {{{repeated[0]}}} appears twice")
    levels = []
    for segment in template.strip("/").split("/"):
        alone = re.fullmatch(r"\{[^{}]*\?\}", segment) is not None
        levels.append(Level(segment, re.compile(_segment_regex(segment)), alone))
    return Template(template, tuple(levels), tuple(names))
