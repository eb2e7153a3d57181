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

from importlib import import_module
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .errors import (
        DuplicateNameError,
        PluginLoadError,
        SDTError,
        SpecFileError,
        UnknownNameError,
    )
    from .hookspecs import hookimpl
    from .registry import Registry, build_registry
    from .specs import ClassifierSpec, DatasetSpec, FeatureSetSpec, SensorSpec

__version__ = "0.1.0"

#: public name -> the module that defines it, imported on first use (PEP 562), so that
#: ``import sdt_framework`` costs nothing until a name is used: the ``sdt`` command can
#: then catch a Ctrl-C while its modules load (``cli.entry``)
_SOURCES = {
    "DuplicateNameError": "errors",
    "PluginLoadError": "errors",
    "SDTError": "errors",
    "SpecFileError": "errors",
    "UnknownNameError": "errors",
    "hookimpl": "hookspecs",
    "Registry": "registry",
    "build_registry": "registry",
    "ClassifierSpec": "specs",
    "DatasetSpec": "specs",
    "FeatureSetSpec": "specs",
    "SensorSpec": "specs",
}


def __getattr__(name: str) -> Any:
    """Import a public name's module on first use."""
    if name in _SOURCES:
        value = getattr(import_module(f".{_SOURCES[name]}", __name__), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted([*globals(), *_SOURCES])


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
