"""Pydantic v2 specs for everything a plugin can provide.

Specs are frozen and reject unknown fields, so a typo in a TOML sensor file or
a plugin is an error rather than a silently ignored setting. Each spec carries
``plugin`` and ``distribution`` provenance (stamped by the registry, excluded
from the content hash) and a ``source`` reference (datasheet, paper, URL).

One module per kind: :mod:`.base` (:class:`Spec`), :mod:`.sensor`,
:mod:`.features`, :mod:`.classifier`, :mod:`.dataset`, :mod:`.reader`, :mod:`.stage_use`
(a profile's extra stages and tolerances, as data) and :mod:`.machine` (a machine a
dataset's recordings come from: speed, bearings, zone table). This package re-exports
them, so ``from sdt_framework.specs import SensorSpec`` is the import to use.
"""

from __future__ import annotations

from .base import _NAME as _NAME
from .base import Spec
from .classifier import ClassifierSpec
from .dataset import DatasetSpec
from .features import DTYPE_BYTES as DTYPE_BYTES
from .features import FeatureBand, FeatureContext, FeatureSetSpec, OrderBand
from .machine import BearingSpec, MachineSpec, OperatingPoint
from .reader import ReaderSpec
from .sensor import AXIS_FIELDS as AXIS_FIELDS
from .sensor import MODE_SUFFIX as MODE_SUFFIX
from .sensor import NATIVE as NATIVE
from .sensor import POINT_SUFFIX as POINT_SUFFIX
from .sensor import Axis as Axis
from .sensor import SensorSpec
from .stage_use import StageUse, Tolerance
from .supply import Supply, SupplyFigure

__all__ = [
    "BearingSpec",
    "ClassifierSpec",
    "DatasetSpec",
    "FeatureBand",
    "FeatureContext",
    "FeatureSetSpec",
    "MachineSpec",
    "OperatingPoint",
    "OrderBand",
    "ReaderSpec",
    "SensorSpec",
    "Spec",
    "StageUse",
    "Supply",
    "SupplyFigure",
    "Tolerance",
]
