"""Real parts with operating modes and datasheet provenance (see ``docs/sensors.md``).

A plugin registers a :class:`PartSpec` through the ``register_parts`` hook;
``registry.sensor("adxl355[range=8g]")`` resolves a part in a mode to a
:class:`~sdt_framework.specs.SensorSpec` named in canonical form; the mode keys
``errors``, ``cross_axis`` and ``temp`` enable the part's datasheet error terms;
:func:`search` finds the profiles and parts that meet a :class:`PartFilter`.
"""

from __future__ import annotations

from .error_modes import ERROR_KEYS, ErrorTermsError, TermSource
from .error_terms import TERMS, ErrorTerm
from .files import load_part_file, load_part_text
from .model import CHAIN_VALUES, AxisValues, Document, Entry, Mode, NoPrice, PartSpec, Price
from .names import canonical_name, split_name, split_names
from .resolve import FieldSource, ModeError, Resolved, all_modes, resolve, select_mode
from .search import PartFilter, PartMatch, PriceLimit, SearchResult, search

__all__ = [
    "CHAIN_VALUES",
    "ERROR_KEYS",
    "TERMS",
    "AxisValues",
    "Document",
    "Entry",
    "ErrorTerm",
    "ErrorTermsError",
    "FieldSource",
    "Mode",
    "ModeError",
    "NoPrice",
    "PartFilter",
    "PartMatch",
    "PartSpec",
    "Price",
    "PriceLimit",
    "Resolved",
    "SearchResult",
    "TermSource",
    "all_modes",
    "canonical_name",
    "load_part_file",
    "load_part_text",
    "resolve",
    "search",
    "select_mode",
    "split_name",
    "split_names",
]
