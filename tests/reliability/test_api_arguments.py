"""The Python API takes names as well as specs, and refuses wrong types instead of converting.

``degrade(x, fs, sensor, seed)`` and ``extract(x, fs, feature_set)``: a name resolves through
the default registry (built once); a seed must be an integer (``int(1.5)`` would silently be
1, ``int("3")`` 3, ``int(True)`` 1); samples must be real numbers (a bool array would become
0/1 g, a complex one would lose its imaginary part or fail deep inside numpy).
"""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework import SDTError, build_registry
from sdt_framework.api import degrade, extract
from sdt_framework.registry import default_registry


@pytest.fixture(autouse=True)
def fresh_default_registry(monkeypatch: pytest.MonkeyPatch):
    """Each test resolves names in a registry of the installed plugins, without switches."""
    for key in ("SDT_PLUGINS", "SDT_BLOCK_PLUGINS", "SDT_SENSOR_PATH"):
        monkeypatch.delenv(key, raising=False)
    default_registry.cache_clear()
    yield
    default_registry.cache_clear()


@pytest.fixture(scope="module")
def registry():
    return build_registry(environ={})


@pytest.fixture(scope="module")
def signal() -> np.ndarray:
    return 0.2 * np.random.default_rng(3).normal(size=20000)


def test_degrade_takes_a_sensor_name(registry, signal):
    by_name, fs_name = degrade(signal, 20000, "adxl345", seed=7)
    by_spec, fs_spec = degrade(signal, 20000, registry.sensor("adxl345"), seed=7)
    assert fs_name == fs_spec == 3200.0
    np.testing.assert_array_equal(by_name, by_spec)


def test_extract_takes_a_feature_set_name(registry, signal):
    by_name = extract(signal, 3200.0, "paper8")
    by_spec = extract(signal, 3200.0, registry.feature_set("paper8"))
    assert by_name.names == by_spec.names and by_name.feature_set == "paper8"
    np.testing.assert_array_equal(by_name.values, by_spec.values)


def test_the_default_registry_is_built_once(signal):
    degrade(signal, 20000, "adxl345")
    first = default_registry()
    extract(signal, 20000.0, "paper8")
    assert default_registry() is first


def test_unknown_name_lists_what_exists(signal):
    with pytest.raises(KeyError, match=r"unknown sensor 'adxl34'\. Did you mean 'adxl345'"):
        degrade(signal, 20000, "adxl34")
    with pytest.raises(SDTError, match="unknown feature set 'paper9'"):
        extract(signal, 20000.0, "paper9")


@pytest.mark.parametrize("sensor", [3, None, {"name": "adxl345"}, b"adxl345"])
def test_degrade_refuses_other_sensor_types(signal, sensor):
    with pytest.raises(TypeError) as info:
        degrade(signal, 20000, sensor)
    assert str(info.value) == (
        f"sensor must be a SensorSpec or the name of a registered sensor (str), "
        f"got {type(sensor).__name__}"
    )
    assert isinstance(info.value, SDTError)  # the CLI prints it as one line


@pytest.mark.parametrize("feature_set", [8, None, ["paper8"]])
def test_extract_refuses_other_feature_set_types(signal, feature_set):
    with pytest.raises(TypeError, match="feature_set must be a FeatureSetSpec or the name"):
        extract(signal, 3200.0, feature_set)


@pytest.mark.parametrize(
    ("seed", "shown"), [(1.5, "float 1.5"), ("3", "str '3'"), (True, "bool True"), (None, "None")]
)
def test_degrade_refuses_a_non_integer_seed(signal, seed, shown):
    with pytest.raises(TypeError, match=f"seed must be an integer, got {shown}"):
        degrade(signal, 20000, "adxl345", seed=seed)


def test_degrade_takes_numpy_integer_seeds(signal):
    a, _ = degrade(signal, 20000, "adxl345", seed=np.int64(5))
    b, _ = degrade(signal, 20000, "adxl345", seed=5)
    np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("fs", ["20000", True, None])
def test_rates_of_the_wrong_type_are_refused(signal, fs):
    with pytest.raises(TypeError, match="fs must be a number of Hz"):
        degrade(signal, fs, "adxl345")
    with pytest.raises(TypeError, match="fs must be a number of Hz"):
        extract(signal, fs, "paper8")


BAD_ARRAYS = {
    "booleans (dtype bool)": lambda x: x > 0,
    "Python objects (dtype object)": lambda x: x.astype(object),
    "text (dtype <U": lambda x: x.astype(str),
    "complex numbers (dtype complex128)": lambda x: x + 0j,
}


@pytest.mark.parametrize("what", list(BAD_ARRAYS))
def test_non_real_samples_are_refused_by_degrade(signal, what):
    with pytest.raises(TypeError) as info:
        degrade(BAD_ARRAYS[what](signal), 20000, "adxl345", label="rec.npy")
    message = str(info.value)
    assert message.startswith("sensor 'adxl345', recording 'rec.npy': samples must be real")
    assert what in message and "convert x first" in message


@pytest.mark.parametrize("what", list(BAD_ARRAYS))
def test_non_real_samples_are_refused_by_extract(signal, what):
    with pytest.raises(TypeError) as info:
        extract(BAD_ARRAYS[what](signal), 20000.0, "paper8")
    assert str(info.value).startswith(f"x must hold real numbers (int or float), got {what}")


def test_integer_samples_are_still_accepted(registry):
    counts = np.random.default_rng(1).integers(-100, 100, size=20000)
    y, _ = degrade(counts, 20000, "adxl345", noise=False)
    expected, _ = degrade(counts.astype(float), 20000, registry.sensor("adxl345"), noise=False)
    np.testing.assert_array_equal(y, expected)
