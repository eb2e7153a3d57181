"""Every hook sdt-framework calls, in one place.

Each hook receives a ``register`` callback and calls it once per thing the
plugin provides. The callback validates the spec (a spec instance or a dict of
its fields), stamps the plugin and distribution on it and rejects duplicate
names, so a plugin never repeats those checks. A plugin (a module, a class,
instantiated without arguments, or an instance) implements any
subset of these hooks with ``@sdt_framework.hookimpl`` and is announced through
the ``sdt_framework`` entry-point group.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pluggy

PROJECT = "sdt_framework"

hookspec = pluggy.HookspecMarker(PROJECT)
hookimpl = pluggy.HookimplMarker(PROJECT)

Register = Callable[[Any], None]


@hookspec
def register_sensors(register: Register) -> None:
    """Provide sensor profiles.

    Called once when a registry is built. Call ``register(SensorSpec(...))``
    (or ``register({...fields...})``) for each profile.
    """


@hookspec
def register_features(register: Register) -> None:
    """Provide feature sets.

    Called once when a registry is built. Call ``register(FeatureSetSpec(...))``
    for each set; ``compute(windows, fs)`` maps (n_windows, n_samples) to
    (n_windows, n_features).
    """


@hookspec
def register_classifiers(register: Register) -> None:
    """Provide classifiers.

    Called once when a registry is built. Call ``register(ClassifierSpec(...))``
    for each classifier; ``ClassifierSpec.build(seed)`` makes a fresh estimator.
    """


@hookspec
def register_datasets(register: Register) -> None:
    """Provide datasets.

    Called once when a registry is built. Call ``register(DatasetSpec(...))``
    for each dataset; ``loader(path, **options)`` opens it.
    """


@hookspec
def register_parts(register: Register) -> None:
    """Provide real parts with operating modes (``sdt_framework.parts.PartSpec``).

    Called once when a registry is built. Call ``register(PartSpec(...))`` for
    each part (a part file read with ``sdt_framework.parts.load_part_file`` is
    a PartSpec). A part is used as a sensor by its name, optionally with a mode:
    ``registry.sensor("adxl355[range=8g]")``. Its name may not equal a sensor
    profile's.
    """


@hookspec
def register_stages(register: Register) -> None:
    """Provide chain stages (``sdt_framework.stages.StageSpec``).

    Called once when a registry is built. Call ``register(StageSpec(...))``
    for each stage: its name, a pydantic model of its parameters (units in the
    field descriptions), where it runs (``domain`` analog or digital,
    ``where`` before or after an ``anchor`` built-in stage, or ``sampler``)
    and ``factory(params, context)``, which builds the stage object. A sensor
    profile adds it by listing ``{name = "...", params = {...}}`` in its
    ``stages``.
    """


@hookspec
def register_signal_readers(register: Register) -> None:
    """Provide signal file readers (``sdt_framework.specs.ReaderSpec``).

    Called once when a registry is built. Call ``register(ReaderSpec(...))``
    for each file format: its suffixes, an optional ``sniff(head)`` of the
    file's first 1024 bytes (needed when another reader shares a suffix), and
    ``scan``/``probe``/``read`` functions returning
    ``sdt_framework.signals.SignalInfo`` and float64 samples; optionally a
    ``count`` of the values before parsing, and ``channels``/``read_channel``
    for a file of several channels (an IDE recording). A manifest row, ``sdt
    dataset inspect FILE``, ``sdt dataset manifest``, ``sdt degrade``, ``sdt
    features extract`` and a twin pair pick the reader by suffix and sniff,
    among the readers the caller hands down; one format per plugin (a module,
    or a package for a larger one).
    """
