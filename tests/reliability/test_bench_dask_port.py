"""A local Dask benchmark while port 8787 is taken prints no "Port 8787 is already in use".

On main the local cluster was started with ``dashboard_address=None``, which still binds
the scheduler's HTTP routes to 8787: a second benchmark on ``--backend dask`` at the same
time (or a Dask dashboard the user runs) made distributed print a ``UserWarning`` on
stderr. The cluster now takes any free port.
"""

from __future__ import annotations

import socket
import warnings

from sdt_framework.bench.execute import open_executor


def test_a_taken_port_8787_gives_no_warning(tmp_path):
    taken = socket.socket()
    try:
        taken.bind(("", 8787))
        taken.listen()
    except OSError:
        pass  # another program holds it already: the same situation
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            with open_executor("dask", 1, None, [], str(tmp_path)) as executor:
                assert list(executor.map_unordered(abs, [-2])) == [2]
    finally:
        taken.close()
    assert not [w for w in caught if "8787" in str(w.message)], [str(w.message) for w in caught]
