"""Layers only point down: every import inside sdt_framework follows a declared edge.

Each package or top-level module of ``sdt_framework`` (a "unit") lists the
units it may import. The table is acyclic, so it is a stack of layers; any
import not in it fails here, whether at the top of a module, inside a function
(a lazy import) or under ``TYPE_CHECKING``. A new unit must be added to the
table, which forces the decision where it sits. A second test finds import
circles between modules, lazy imports included.
"""

from __future__ import annotations

import ast
import sys
from collections.abc import Iterator
from pathlib import Path

import sdt_framework

ROOT = Path(sdt_framework.__file__).parent

#: unit -> the units it may import (besides itself): exactly those it does import, no more
#: (``test_the_table_is_no_looser_than_the_code``); a new edge is a decision made here
ALLOWED: dict[str, set[str]] = {
    "errors": set(),
    "dtypes": set(),
    "seeding": set(),
    "hookspecs": set(),
    "labels": set(),
    "lazy": set(),
    "speed": set(),  # the running speed off a spectrum: numpy and scipy only
    "csv_cells": set(),
    "units": set(),
    "inputs": {"errors"},
    "io": {"errors"},
    "toml_files": {"errors", "inputs"},
    "specs": {"errors"},
    "arguments": {"dtypes", "errors", "specs"},
    "discovery": {"errors", "hookspecs"},
    "stages": {"errors", "seeding", "specs"},
    "parts": {"chain", "errors", "specs", "toml_files"},  # chain: search --simulable-at
    "sensor_files": {"errors", "specs", "toml_files"},
    "machine_files": {"errors", "specs", "toml_files"},
    "registry_lookup": {"discovery", "errors", "parts", "specs", "stages"},
    "registry": {
        "discovery",
        "errors",
        "hookspecs",
        "parts",
        "registry_lookup",
        "sensor_files",
        "specs",
        "stages",
    },
    "signals": {"dtypes", "errors", "inputs", "lazy", "units"},
    # seeding left with the generator, now the synthetic-pump plugin's package
    "data": {
        "csv_cells",
        "errors",
        "inputs",
        "io",
        "lazy",
        "machine_files",
        "signals",
        "specs",
        "speed",
        "units",
    },
    "chain": {"arguments", "dtypes", "errors", "lazy", "seeding", "specs", "stages"},
    "features": {"arguments", "csv_cells", "errors", "io", "specs"},
    "edge": {"errors", "specs", "toml_files"},
    "validation": {"chain", "io", "specs", "stages", "units"},
    "api": {"chain", "errors", "features", "registry", "specs"},
    "conformance": {"chain", "errors", "features", "parts", "registry", "specs", "stages"},
    "sklearn": {"api", "arguments", "chain", "errors", "features", "specs"},
    "twin": {"chain", "errors", "inputs", "io", "signals", "specs", "toml_files", "units"},
    "bench": {
        "chain",
        "csv_cells",
        "data",
        "errors",
        "features",
        "io",
        "lazy",
        "machine_files",
        "parts",
        "registry",
        "seeding",
        "signals",
        "specs",
        "stages",
        "toml_files",
    },
    "verdict": {"bench", "errors", "seeding"},
    "severity": {"chain", "errors", "seeding", "specs", "speed", "toml_files", "units", "verdict"},
    "explore": {
        "bench",
        "data",
        "edge",
        "errors",
        "io",
        "registry",
        "seeding",
        "sensor_files",
        "severity",
        "signals",
        "specs",
        "stages",
        "toml_files",
    },
    "report": {
        "bench",
        "chain",
        "csv_cells",
        "data",
        "edge",
        "errors",
        "explore",
        "features",
        "io",
        "labels",
        "machine_files",
        "registry",
        "severity",
        "specs",
        "validation",
        "verdict",
    },
    "cli": {
        "bench",
        "chain",
        "data",
        "edge",
        "errors",
        "explore",
        "features",
        "inputs",
        "io",
        "labels",
        "machine_files",  # sdt features extract --machines (order features)
        "parts",
        "registry",
        "report",
        "severity",
        "signals",
        "specs",
        "speed",  # sdt features extract --nominal-rpm (order features)
        "twin",
        "units",
        "validation",
        "verdict",
    },
    "__init__": {"errors", "hookspecs", "registry", "specs"},
    "__main__": {"cli"},
}


def _module_name(path: Path) -> tuple[str, ...]:
    parts = path.relative_to(ROOT).with_suffix("").parts
    return parts[:-1] if parts[-1] == "__init__" else parts


def _from(path: Path, node: ast.ImportFrom) -> tuple[str, ...] | None:
    """The module under sdt_framework a ``from X import ...`` names as X (None: another
    distribution's)."""
    package = list(path.relative_to(ROOT).parts[:-1])
    if node.level:
        base = package[: len(package) - node.level + 1]
    elif (node.module or "").split(".")[0] == "sdt_framework":
        base = []
    else:
        return None
    module = (node.module or "").split(".")
    if node.level == 0:
        module = module[1:]
    return tuple(base + [m for m in module if m])


def _targets(path: Path, node: ast.stmt) -> Iterator[tuple[tuple[str, ...], str]]:
    """(imported module under sdt_framework, local name) of each name ``node`` imports."""
    if isinstance(node, ast.ImportFrom):
        target = _from(path, node)
        if target is None:
            return
        for alias in node.names:  # `from . import x` may name a module
            sub = (*target, alias.name)
            known = (ROOT.joinpath(*sub).with_suffix(".py").exists()) or (
                ROOT.joinpath(*sub).is_dir()
            )
            yield (sub if known else target), alias.asname or alias.name
    elif isinstance(node, ast.Import):
        for alias in node.names:
            pieces = alias.name.split(".")
            if pieces[0] == "sdt_framework":
                yield tuple(pieces[1:]), alias.asname or pieces[0]


def _imports(path: Path) -> Iterator[tuple[tuple[str, ...], int]]:
    """(imported module under sdt_framework, line) of every import in ``path``, lazy ones too."""
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom | ast.Import):
            for module, _ in _targets(path, node):
                yield module, node.lineno


def _unit(module: tuple[str, ...]) -> str:
    return module[0] if module else "__init__"


def _sources() -> list[Path]:
    return sorted(ROOT.rglob("*.py"))


def test_the_table_is_a_stack_of_layers():
    """No unit may reach itself through the table: every declared edge points down."""
    done: set[str] = set()

    def visit(unit: str, path: tuple[str, ...]) -> None:
        assert unit not in path, f"declared circle: {' -> '.join((*path, unit))}"
        if unit in done:
            return
        for below in ALLOWED[unit]:
            visit(below, (*path, unit))
        done.add(unit)

    for unit in ALLOWED:
        visit(unit, ())


def test_every_unit_of_the_package_has_a_place_in_the_table():
    units = {_unit(_module_name(path)) for path in _sources()}
    assert units - set(ALLOWED) == set(), "add the new unit to ALLOWED"
    assert set(ALLOWED) - units == set(), "remove the unit that went from ALLOWED"


def test_every_import_follows_a_declared_edge():
    wrong = []
    for path in _sources():
        unit = _unit(_module_name(path))
        for module, line in _imports(path):
            target = _unit(module)
            if target != unit and target not in ALLOWED[unit]:
                where = f"{path.relative_to(ROOT)}:{line}"
                wrong.append(f"{where}: {unit} imports {'.'.join(module) or 'sdt_framework'}")
    assert wrong == [], "\n".join(wrong)


def test_no_import_circle_between_modules():
    """Module to module, lazy imports included (a lazy import hides a circle, it does not end it).

    Importing a package counts as importing its ``__init__``; a package's
    ``__init__`` importing its own modules is the package, not a circle.
    """
    graph: dict[tuple[str, ...], set[tuple[str, ...]]] = {}
    for path in _sources():
        name = _module_name(path)
        graph[name] = {m for m, _ in _imports(path) if m != name}
    for name, targets in graph.items():
        if ROOT.joinpath(*name).is_dir():  # a package's __init__
            graph[name] = {t for t in targets if t[: len(name)] != name}
    state: dict[tuple[str, ...], int] = {}
    circles = []

    def visit(node: tuple[str, ...], stack: list[tuple[str, ...]]) -> None:
        state[node] = 1
        for target in sorted(graph.get(node, ())):
            if target not in graph:
                continue
            if state.get(target) == 1:
                cycle = [*stack[stack.index(target) :], target]
                circles.append(" -> ".join(".".join(m) or "sdt_framework" for m in cycle))
            elif target not in state:
                visit(target, [*stack, target])
        state[node] = 2

    for node in sorted(graph):
        if node not in state:
            visit(node, [node])
    assert circles == [], "\n".join(circles)


def _installs(path: Path) -> Iterator[str]:
    """Top-level statements of ``path`` that call, or assign into, what another unit exports:
    a module that, when imported, changes a module of another unit (installs a callback)."""
    unit = _unit(_module_name(path))
    tree = ast.parse(path.read_text(encoding="utf-8"))
    given = {
        name: _unit(module)
        for node in tree.body
        if isinstance(node, ast.ImportFrom | ast.Import)
        for module, name in _targets(path, node)
    }
    for node in tree.body:
        roots: list[ast.expr] = []
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Call):
            roots.append(node.value.func)
        if isinstance(node, ast.Assign | ast.AugAssign):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            roots += [t for t in targets if isinstance(t, ast.Attribute | ast.Subscript)]
        for root in roots:
            while isinstance(root, ast.Attribute | ast.Subscript | ast.Call):
                root = root.func if isinstance(root, ast.Call) else root.value
            if isinstance(root, ast.Name) and given.get(root.id, unit) != unit:
                yield f"{path.relative_to(ROOT)}:{node.lineno}: {ast.unparse(node)[:80]}"


def test_no_module_installs_anything_into_another_unit_at_import():
    """Importing a module changes no other unit: a lower layer that needs the registered
    readers or stages takes them as an argument (a callback a higher module installs at
    import keeps the table above green while calls still run up); and no function rebinds
    a module's global state (``global``), the means of such an install."""
    installs = [line for path in _sources() if path.name != "__main__.py"
                for line in _installs(path)]  # fmt: skip
    rebinds = [
        f"{path.relative_to(ROOT)}:{node.lineno}: global {', '.join(node.names)}"
        for path in _sources()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8")))
        if isinstance(node, ast.Global)
    ]
    assert installs + rebinds == [], "\n".join(installs + rebinds)


def test_the_installed_tables_are_gone():
    """The registry installed its readers (``reader_table``) and its binder of stages
    (``stages.install_stage_binder``) into lower layers when imported; both are handed down."""
    import sdt_framework.stages as stages

    assert not ROOT.joinpath("reader_table.py").exists()
    assert not [name for name in dir(stages) if name.startswith("install")]


def _exports(package: str) -> set[str]:
    """The names a package's face (its ``__init__``) lists in ``__all__``."""
    tree = ast.parse((ROOT / package / "__init__.py").read_text(encoding="utf-8"))
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(
            isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets
        ):
            return {e.value for e in node.value.elts if isinstance(e, ast.Constant)}  # type: ignore[attr-defined]
    return set()


def _behind_faces(path: Path) -> Iterator[str]:
    """Imports of ``path`` that reach behind a package's face: ``sdt_framework.X.y`` for a
    package X, written out or as ``from sdt_framework.X import y`` naming a submodule the
    face does not export (a lazy face then imports the submodule itself)."""
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            base = _from(path, node)
            names = [(base, alias.name) for alias in node.names] if base is not None else []
        elif isinstance(node, ast.Import):
            names = [
                (tuple(alias.name.split(".")[1:]), "")
                for alias in node.names
                if alias.name.split(".")[0] == "sdt_framework"
            ]
        else:
            continue
        for base, name in names:
            if not base or base[0] == _unit(_module_name(path)) or not (ROOT / base[0]).is_dir():
                continue  # the package itself, its own modules, or a top-level module
            submodule = (ROOT / base[0] / f"{name}.py").exists() or (ROOT / base[0] / name).is_dir()
            if len(base) > 1 or (submodule and name not in _exports(base[0])):
                shown = ".".join(base) + (f" import {name}" if name else "")
                yield f"{path.relative_to(ROOT)}:{node.lineno}: {shown}"


def test_cli_imports_package_faces_only():
    """The command line sees each package through its face (``from ..bench import Plan``,
    never ``from ..bench.plan import Plan``): what a command needs is public, listed in the
    package's ``__init__``, so a package can move its modules without breaking the CLI. A
    top-level module (``errors``, ``io``, ``units``) is its own face."""
    wrong = [line for path in sorted((ROOT / "cli").rglob("*.py")) for line in _behind_faces(path)]
    assert wrong == [], "export the name from the package's __init__:\n" + "\n".join(wrong)


def test_the_faces_rule_finds_what_it_forbids(tmp_path, monkeypatch):
    """The rule's own check, on a module written as the CLI was (71 of 127 imports)."""
    monkeypatch.setattr(sys.modules[__name__], "ROOT", tmp_path)
    for package in ("bench", "cli"):
        (tmp_path / package).mkdir()
        (tmp_path / package / "__init__.py").write_text('__all__ = ["Plan"]\n')
    (tmp_path / "bench" / "estimate.py").write_text("")
    (tmp_path / "errors.py").write_text("")
    (tmp_path / "cli" / "x.py").write_text(
        "from ..bench.plan import Plan\nimport sdt_framework.bench.estimate\n"
        "from ..bench import estimate\nfrom ..bench import Plan\nfrom ..errors import E\n"
        "from . import common\n"
    )
    found = [line.split(":")[1] for line in _behind_faces(tmp_path / "cli" / "x.py")]
    assert found == ["1", "2", "3"]


def test_the_table_is_no_looser_than_the_code():
    """Every permission in ALLOWED is used by an import: a permission nothing uses would let
    the next import run up a layer unnoticed. Drop it (or the import that needed it went)."""
    used: dict[str, set[str]] = {unit: set() for unit in ALLOWED}
    for path in _sources():
        unit = _unit(_module_name(path))
        used[unit] |= {_unit(module) for module, _ in _imports(path)} - {unit}
    unused = {unit: sorted(ALLOWED[unit] - used[unit]) for unit in ALLOWED}
    assert {u: names for u, names in unused.items() if names} == {}
