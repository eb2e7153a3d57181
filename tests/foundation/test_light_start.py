"""Building the plugin registry loads neither scipy.signal nor scipy.fft.

Every ``sdt`` command builds the registry (sensors, features, stages,
classifiers, readers); scipy.signal alone costs about 0.5 s to import, which
``sdt budget``, ``sdt sensors list`` and every error line paid before the chain
and the built-in plugins imported it on first use (``sdt budget`` 1.68 s ->
0.90 s). The chain still imports it when it filters (checked: a degrade call
loads it).
"""

from __future__ import annotations

import subprocess
import sys

PROBE = """
import sys
from sdt_framework import build_registry
registry = build_registry()
print(sorted(m for m in ("scipy.signal", "scipy.fft") if m in sys.modules))
import numpy as np
from sdt_framework.chain import degrade
degrade(np.zeros(4000), 20000.0, registry.sensor("adxl345"), noise=False)
print("scipy.signal" in sys.modules)
"""


def test_the_registry_builds_without_scipy_signal_and_the_chain_loads_it_on_use():
    done = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, check=True)
    assert done.stdout.split("\n")[:2] == ["[]", "True"], done.stdout + done.stderr
