"""Bad --transfer entries and [benchmark] nodes, refused in one line that says what is wrong.

On main: ``--transfer "wilcoxon-786b10 -> ,"`` spoke of a ``*`` the user did not
write; a 2000-sensor entry was echoed whole (a 16 KB line); two nodes sharing a
channel were accepted and the channel counted twice; an empty node name gave
``adxl345 @ `` rows.
"""

from __future__ import annotations

import pytest

NODE_CONFIG = """\
[benchmark]
dataset_options = {{triaxial = true}}
channels = ["ch6", "ch2", "ch3"]
axes = {{ch6 = "x", ch2 = "y", ch3 = "z"}}
sample = "node"
nodes = {nodes}
"""


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def _error(result) -> str:
    lines = result.stderr.splitlines()
    assert result.returncode == 2 and len(lines) == 1, result.stderr[-2000:]
    assert lines[0].startswith("error: ") and "Traceback" not in result.stderr
    return lines[0]


def test_transfer_with_no_test_chain_does_not_speak_of_a_star(sdt, tmp_path):
    line = _error(sdt("benchmark", "--quick", "--transfer", "wilcoxon-786b10 -> ,",
                      "--out", str(tmp_path / "o")))  # fmt: skip
    assert line.startswith("error: transfer 'wilcoxon-786b10 -> ,': no test chain after '->'")
    assert "'*' leaves" not in line


def test_a_2000_sensor_entry_is_echoed_bounded_with_its_size(sdt, tmp_path):
    names = [f"adxl{i}" for i in range(2000)]
    entry = "wilcoxon-786b10 -> " + ",".join(names)
    line = _error(sdt("benchmark", "--quick", "--transfer", entry, "--out", str(tmp_path / "o")))
    assert len(line) < 1000  # the entry alone is len(entry) characters
    assert len(entry) > 16000
    assert f"({len(entry)} characters, 2000 test chains)" in line
    assert "unknown sensor 'adxl0'" in line


def test_two_nodes_sharing_a_channel_are_refused_naming_both(sdt, tmp_path):
    config = tmp_path / "shared.toml"
    nodes = '{a = ["ch6", "ch2", "ch3"], b = ["ch3", "ch6", "ch2"]}'
    config.write_text(NODE_CONFIG.format(nodes=nodes))
    line = _error(sdt("benchmark", str(config), "--quick", "--out", str(tmp_path / "o")))
    assert "channel 'ch3' is in node 'a' and in node 'b'" in line  # b's first channel
    assert not (tmp_path / "o" / "results.parquet").exists()


def test_an_empty_or_blank_node_name_is_refused(sdt, tmp_path):
    for name in ('""', '" "'):
        config = tmp_path / "empty.toml"
        config.write_text(NODE_CONFIG.format(nodes=f'{{{name} = ["ch6", "ch2", "ch3"]}}'))
        line = _error(sdt("benchmark", str(config), "--quick", "--out", str(tmp_path / "o")))
        assert "[benchmark] nodes has a node named" in line and "non-blank name" in line
