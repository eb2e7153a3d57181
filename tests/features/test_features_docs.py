"""docs/features.md's Python blocks run as written, so the documented example cannot rot."""

from __future__ import annotations

import re
import types
from pathlib import Path

import numpy as np
import pytest

from sdt_framework import build_registry

DOC = Path(__file__).resolve().parents[2] / "docs" / "features.md"


def test_doc_example_runs_and_does_what_it_says(capsys: pytest.CaptureFixture[str]) -> None:
    blocks = re.findall(r"```python\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S)
    assert len(blocks) >= 3
    module = types.ModuleType("features_doc")  # the doc's plugin block lives in one module
    for number, block in enumerate(blocks):
        exec(compile(block, f"{DOC.name}[python block {number}]", "exec"), module.__dict__)
    out = capsys.readouterr().out
    assert "paper8+env_bpfo" in out and "36 B/window/axis" in out

    table = module.table
    assert table.names[-1] == "env_bpfo" and table.units[-1] == "g"
    assert table.values.shape == (36, 9) and table.values.dtype == np.float32
    env = table.to_frame().groupby("acquisition")["env_bpfo"].mean()
    assert env[1] > 50 * env[0]  # the defect shows at BPFO, the healthy signal does not

    # the plugin block registers through the hook like any plugin
    registry = build_registry(entry_points=False, plugins=[module], environ={})
    assert registry.feature_set("env_bpfo").plugin == "features_doc"
