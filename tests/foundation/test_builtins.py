"""Every built-in plugin is registered through the entry-point group and conforms."""

from __future__ import annotations

import importlib
import importlib.metadata as md
import tomllib
from pathlib import Path

import pytest

from sdt_framework.conformance import ConformanceError, check_plugin

ROOT = Path(__file__).resolve().parents[2]
DECLARED = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["entry-points"][
    "sdt_framework"
]


def plugin_modules() -> list[str]:
    """Every module under plugins/ that implements a hook (other distributions excluded)."""
    found = []
    own = [p.parent for p in (ROOT / "plugins").rglob("pyproject.toml")]  # e.g. sensors-catalog
    for path in sorted((ROOT / "plugins").rglob("*.py")):
        if any(folder in path.parents for folder in own):
            continue
        if "def register_" in path.read_text():
            parts = path.relative_to(ROOT / "plugins").with_suffix("").parts
            if parts[-1] == "__init__":  # a plugin that is a package: the package is the module
                parts = parts[:-1]
            found.append(".".join(("sdt_plugins", *parts)))
    return found


def test_every_builtin_plugin_module_is_an_entry_point():
    assert sorted(plugin_modules()) == sorted(DECLARED.values())


def test_installed_entry_points_match_pyproject():
    installed = {
        ep.name: ep.value
        for ep in md.entry_points(group="sdt_framework")
        if ep.dist and ep.dist.name == "sdt-framework"
    }
    assert installed == DECLARED, "reinstall with `pip install -e .` after editing pyproject"


@pytest.mark.parametrize("module", sorted(DECLARED.values()))
def test_builtin_plugin_conforms(module):
    specs = check_plugin(importlib.import_module(module))
    assert specs


def test_conformance_catches_a_misbehaving_feature_set():
    import types

    import numpy as np

    from sdt_framework import FeatureSetSpec, hookimpl

    module = types.ModuleType("bad_features")
    spec = FeatureSetSpec(
        name="bad",
        feature_names=("a", "b"),
        units=("g", "g"),
        compute=lambda w, fs: np.zeros((len(w), 3)),
    )
    module.register_features = hookimpl(lambda register: register(spec))
    with pytest.raises(ConformanceError, match=r"feature set 'bad'.*shape \(4, 3\)"):
        check_plugin(module)


def test_conformance_catches_a_name_clash():
    import types

    from sdt_framework import ClassifierSpec, hookimpl

    module = types.ModuleType("clash")
    spec = ClassifierSpec(name="lr", estimator="sklearn.dummy:DummyClassifier", seed_param=None)
    module.register_classifiers = hookimpl(lambda register: register(spec))
    with pytest.raises(ConformanceError, match="already provided by plugin 'lr'"):
        check_plugin(module)


def test_the_core_never_imports_a_builtin_plugin():
    offenders = [
        str(path.relative_to(ROOT))
        for path in sorted((ROOT / "sdt_framework").rglob("*.py"))
        if "sdt_plugins" in path.read_text()
    ]
    assert offenders == []
