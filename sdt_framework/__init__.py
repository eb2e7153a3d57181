"""sdt-framework: Sensor Digital Twin virtual benchmarking of accelerometers.

Public API
----------
hookimpl
    Decorator marking a plugin's hook implementations.
build_registry, Registry
    Discover plugins and look up sensors, feature sets, classifiers, datasets.
SensorSpec, FeatureSetSpec, ClassifierSpec, DatasetSpec
    The pydantic models every plugin registers.
SDTError
    Base of every error a user can act on.
"""

from __future__ import annotations

from .errors import DuplicateNameError, PluginLoadError, SDTError, SpecFileError, UnknownNameError
from .hookspecs import hookimpl
from .registry import Registry, build_registry
from .specs import ClassifierSpec, DatasetSpec, FeatureSetSpec, SensorSpec

__version__ = "0.1.0"

__all__ = [
    "ClassifierSpec",
    "DatasetSpec",
    "DuplicateNameError",
    "FeatureSetSpec",
    "PluginLoadError",
    "Registry",
    "SDTError",
    "SensorSpec",
    "SpecFileError",
    "UnknownNameError",
    "__version__",
    "build_registry",
    "hookimpl",
]
