"""Names with a mode, benchopt style: ``adxl355[range=8g,odr=4000]``.

The canonical form of a part in a mode lists every mode key, sorted, with the
chosen option (defaults filled in): ``adxl355[odr=4000,range=8g]``. So
``adxl355`` and ``adxl355[range=2g]`` name the same sensor and give the same
results rows, and a name in a results table says the whole mode.
"""

from __future__ import annotations

import re

from ..errors import SDTError

__all__ = ["canonical_name", "split_name", "split_names"]

_FORM = re.compile(r"^(?P<base>[^\[\]]+)(\[(?P<modes>[^\[\]]*)\])?$")


def split_name(text: str) -> tuple[str, dict[str, str]]:
    """``"adxl355[range=8g, odr=4000]"`` -> ``("adxl355", {"range": "8g", "odr": "4000"})``.

    Keys and options are stripped and lower-cased; a key given twice or a
    malformed bracket is one clear error.
    """
    match = _FORM.match(text.strip())
    if match is None:
        raise SDTError(
            f"{text!r} is not a sensor name: write name or name[key=option,...], "
            f"e.g. adxl355[range=8g,odr=4000]"
        )
    base = match["base"].strip()
    modes: dict[str, str] = {}
    if match["modes"] is not None:
        if not match["modes"].strip():
            raise SDTError(f"{text!r}: empty brackets; give key=option or leave them out")
        for item in match["modes"].split(","):
            key, sep, option = (part.strip().lower() for part in item.partition("="))
            if not sep or not key or not option:
                raise SDTError(f"{text!r}: {item.strip()!r} is not key=option")
            if key in modes:
                raise SDTError(f"{text!r}: mode key {key!r} is given twice")
            modes[key] = option
    return base, modes


def canonical_name(base: str, modes: dict[str, str]) -> str:
    """``base[k1=v1,k2=v2]`` with keys sorted, or ``base`` for a part without modes."""
    if not modes:
        return base
    return f"{base}[{','.join(f'{k}={modes[k]}' for k in sorted(modes))}]"


def split_names(text: str) -> list[str]:
    """Split a comma-separated list of names, keeping commas inside brackets.

    ``"adxl355[range=8g,odr=4000],mpu6050"`` -> ``["adxl355[range=8g,odr=4000]", "mpu6050"]``.
    """
    names: list[str] = []
    depth = 0
    current = ""
    for char in text:
        depth += (char == "[") - (char == "]")
        if char == "," and depth == 0:
            names.append(current)
            current = ""
        else:
            current += char
    names.append(current)
    if depth != 0:
        raise SDTError(f"{text!r}: unbalanced brackets")
    return [name.strip() for name in names if name.strip()]
