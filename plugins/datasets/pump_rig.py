"""The pump rig's machines (``pump_rig.toml``): what both pump datasets expose.

Motor-2 and Motor-4 of NLN-EMP with their speeds, motors, bearings and zone
tables, each figure with its source in the file. ``nln-emp`` hands them with
the real archive's recordings, ``synthetic-pump`` with its generated ones
(its generator reads its speeds and bearing geometry from here too), so
severity and the report read the same machine whichever the data is.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

from sdt_framework.machine_files import load_machine_file
from sdt_framework.specs import MachineSpec

__all__ = ["RIG_FILE", "rig_machines"]

RIG_FILE = Path(__file__).with_name("pump_rig.toml")


@cache
def rig_machines() -> dict[str, MachineSpec]:
    """Motor-2 and Motor-4, by name, as ``pump_rig.toml`` gives them."""
    origin = "the pump rig's machine file (sdt_plugins/datasets/pump_rig.toml)"
    machines = load_machine_file(RIG_FILE)
    return {name: spec.model_copy(update={"origin": origin}) for name, spec in machines.items()}
