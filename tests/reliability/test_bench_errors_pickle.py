"""Every exception class sdt defines survives pickling: a worker's error reaches the user.

An error raised in a loky or Dask worker travels to the main process pickled.
Python rebuilds an exception by calling ``cls(*exc.args)``; for a class whose
``__init__`` takes other arguments than its message (``ChainInputError(sensor,
label, reason)``) that call failed in the main process, and any bad input met
in a worker became ``internal error: BrokenProcessPool`` (exit 70).

The classes are found, not listed: every module of sdt_framework and of the
built-in plugins (and of the sensor catalogue, when installed) is imported and
every exception class it defines is built from its own signature and pickled.
"""

from __future__ import annotations

import importlib
import importlib.util
import inspect
import io
import pickle
import pkgutil
from types import ModuleType

import pytest
import sdt_plugins

import sdt_framework

PACKAGES: list[ModuleType] = [sdt_framework, sdt_plugins]
if importlib.util.find_spec("sdt_sensors_catalog") is not None:
    PACKAGES.append(importlib.import_module("sdt_sensors_catalog"))


def _modules() -> list[ModuleType]:
    found = []
    for package in PACKAGES:
        found.append(package)
        prefix = package.__name__ + "."
        for info in pkgutil.walk_packages(package.__path__, prefix):
            if not info.name.endswith(".__main__"):  # importing it runs the command line
                found.append(importlib.import_module(info.name))
    return found


def _exception_classes() -> list[type[BaseException]]:
    """Every exception (and warning) class defined in a module of the packages."""
    classes = {}
    for module in _modules():
        for _, obj in inspect.getmembers(module, inspect.isclass):
            if issubclass(obj, BaseException) and obj.__module__ == module.__name__:
                classes[f"{obj.__module__}.{obj.__qualname__}"] = obj
    return [classes[name] for name in sorted(classes)]


CLASSES = _exception_classes()


def _round_trip(exc: BaseException) -> BaseException:
    """``exc`` pickled by Python's own rules and back.

    Not through copyreg's table: importing ``distributed`` (a Dask test run earlier in
    the same process) registers tblib's reducer there for every exception class then
    defined, which would hide a class that loky's workers cannot send.
    """
    buffer = io.BytesIO()
    pickler = pickle.Pickler(buffer)
    pickler.dispatch_table = {}
    pickler.dump(exc)
    return pickle.loads(buffer.getvalue())


def _arguments(cls: type[BaseException]) -> tuple[tuple[object, ...], dict[str, object]]:
    """Arguments for ``cls``: each parameter of its ``__init__`` a distinct text naming it."""
    init = cls.__init__
    if init is BaseException.__init__ or getattr(init, "__objclass__", None) is not None:
        return ("a message naming <file.csv>",), {}  # a builtin's __init__: one message
    args: list[object] = []
    kwargs: dict[str, object] = {}
    for name, param in list(inspect.signature(init).parameters.items())[1:]:
        if param.kind is param.VAR_POSITIONAL:
            args.append(f"<{name}>")
        elif param.kind is param.KEYWORD_ONLY:
            kwargs[name] = f"<{name}>"
        elif param.kind is not param.VAR_KEYWORD:
            args.append(f"<{name}>")
    return tuple(args), kwargs


def test_the_walk_finds_the_classes_that_broke_the_pool():
    names = {cls.__name__ for cls in CLASSES}
    assert {"ChainInputError", "ChainInputTypeError", "UnknownNameError", "SpecFileError"} <= names
    assert {"DataFileError", "OutputError", "SDTError", "InternalError", "SDTWarning"} <= names
    assert len(CLASSES) >= 20


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: f"{c.__module__}.{c.__qualname__}")
def test_every_exception_class_survives_a_pickle_round_trip(cls):
    args, kwargs = _arguments(cls)
    original = cls(*args, **kwargs)
    original.add_note("raised in a worker")
    copy = _round_trip(original)
    assert type(copy) is cls
    assert str(copy) == str(original)
    assert copy.args == original.args
    assert vars(copy) == vars(original)  # the attributes a handler reads (sensor, path...)
    for value in [*args, *kwargs.values()]:  # the message still names what was given
        if cls.__name__ != "UnknownNameError" or value != "<available>":  # listed sorted
            assert str(value) in str(copy) or str(value) in vars(copy).values()


def test_the_same_through_dasks_reducer():
    """distributed's reducer (tblib's, in copyreg) rebuilds them too, the attributes kept."""
    import distributed  # noqa: F401  (installs tblib's pickling support)

    from sdt_framework.chain import ChainInputError

    copy = pickle.loads(pickle.dumps(ChainInputError("adxl345", "run-7.npy", "empty signal")))
    assert str(copy) == "sensor 'adxl345', recording 'run-7.npy': empty signal"
    assert (copy.sensor, copy.label, copy.reason) == ("adxl345", "run-7.npy", "empty signal")


def test_an_exception_with_an_errno_keeps_it():
    import errno

    from sdt_framework.io import OutputError

    copy = _round_trip(OutputError(errno.ENOSPC, "No space left on device"))
    assert (copy.errno, copy.strerror) == (errno.ENOSPC, "No space left on device")
    assert str(copy) == "[Errno 28] No space left on device"
