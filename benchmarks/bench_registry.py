"""A command's start (plugin discovery) and a staged part's content hash, against plain code.

Every ``sdt`` command discovers its plugins, and every chain compiled for a
recording keys its cache by the sensor's content hash. Two plain ways cost most
of both:

- discovery asked each entry point's ``Distribution.name`` and ``.version``; each
  parses the whole METADATA file again (28 entry points, 2 distributions here);
- a staged part's hash rebuilt each stage's parameter JSON schema with pydantic
  (about 2 ms a stage) every time.

sdt parses each distribution's metadata once per discovery, and builds a
parameter model's schema once per class. Both ways give the same names,
versions and hashes (checked here). Usage:

    .venv/bin/python benchmarks/bench_registry.py
"""

from __future__ import annotations

import importlib.metadata as md
import time
from collections.abc import Callable

from sdt_framework.discovery import _entry_points
from sdt_framework.hookspecs import PROJECT
from sdt_framework.registry import build_registry
from sdt_framework.specs import Spec
from sdt_framework.stages.spec import StageSpec

PART = "adxl355[errors=datasheet,temp=85c]"


def _plain_entry_points() -> list[tuple[md.EntryPoint, str, str]]:
    """Each entry point's distribution name and version asked of the distribution each time."""
    found = md.entry_points(group=PROJECT)
    return sorted(((ep, ep.dist.name, ep.dist.version) for ep in found), key=lambda t: t[1:])


def _plain_stage_content(self: StageSpec) -> dict:
    """The stage's content with its parameter schema built by pydantic every time."""
    data = Spec.content_dict(self)
    data["factory"] = f"{self.factory.__module__}:{self.factory.__qualname__}"
    data["params"] = self.params.model_json_schema()
    return data


def _per_call(work: Callable[[], object], repeats: int) -> float:
    start = time.perf_counter()
    for _ in range(repeats):
        work()
    return (time.perf_counter() - start) / repeats


def main() -> None:
    ours = sorted((ep.name, dist, version) for ep, dist, version in _entry_points())
    plain = sorted((ep.name, dist, version) for ep, dist, version in _plain_entry_points())
    assert ours == plain, "the two discoveries disagree"
    fast, slow = _per_call(_entry_points, 50), _per_call(_plain_entry_points, 50)
    print(
        f"entry points ({len(ours)}) with distribution names and versions: "
        f"{fast * 1e3:.1f} ms, plain {slow * 1e3:.1f} ms -> {slow / fast:.1f}x; same list"
    )
    print(f"build_registry: {_per_call(build_registry, 20) * 1e3:.1f} ms")

    sensor = build_registry().sensor(PART)
    ours_hash = sensor.content_hash()
    fast = _per_call(sensor.content_hash, 200)
    cached = StageSpec.content_dict
    StageSpec.content_dict = _plain_stage_content  # type: ignore[method-assign]
    try:
        plain_hash = sensor.content_hash()
        slow = _per_call(sensor.content_hash, 200)
    finally:
        StageSpec.content_dict = cached  # type: ignore[method-assign]
    assert ours_hash == plain_hash, "the two hashes disagree"
    print(
        f"content hash of {PART} ({len(sensor.stages)} stages): {fast * 1e3:.3f} ms, "
        f"plain {slow * 1e3:.3f} ms -> {slow / fast:.0f}x; same hash"
    )


if __name__ == "__main__":
    main()
