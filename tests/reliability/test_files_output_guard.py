"""An output path built from data cannot leave the folder the user named (issue 39, item 1).

``io.atomic_path`` created any missing parent of its destination, so a figure
named after a machine ``x/../../../../PWNED`` was written four folders above
the results. The report names such files with :func:`sdt_framework.labels.slug`;
beneath that, every writer given ``root`` (the report's writes all are)
refuses a destination that resolves outside it, before creating anything.
"""

from __future__ import annotations

import os

import pytest

from sdt_framework.io import OutputError, atomic_write_text
from sdt_framework.labels import slug
from sdt_framework.report.style import new_figure, save_figure


@pytest.mark.parametrize(
    "name",
    ["../escaped.txt", "a/../../escaped.txt", "/tmp/escaped-absolute.txt", ".", ""],
    ids=["parent", "through-a-folder", "absolute", "the-folder-itself", "empty"],
)
def test_a_destination_outside_root_is_refused_and_nothing_is_created(tmp_path, name):
    root = tmp_path / "out"
    root.mkdir()
    before = set(tmp_path.rglob("*"))
    with pytest.raises(OutputError, match=r"refusing to write .*outside the output folder"):
        atomic_write_text(root / name, "x", root=root)
    assert set(tmp_path.rglob("*")) == before
    assert not os.path.exists("/tmp/escaped-absolute.txt")


def test_a_link_below_root_leading_out_is_refused(tmp_path):
    root, elsewhere = tmp_path / "out", tmp_path / "elsewhere"
    root.mkdir()
    elsewhere.mkdir()
    (root / "figures").symlink_to(elsewhere)
    with pytest.raises(OutputError, match="outside the output folder"):
        atomic_write_text(root / "figures" / "fig.png", "x", root=root)
    assert list(elsewhere.iterdir()) == []


def test_inside_root_a_new_subfolder_is_created(tmp_path):
    root = tmp_path / "out"
    atomic_write_text(root / "a" / ".." / "b" / "file.txt", "x", root=tmp_path)
    assert (root / "b" / "file.txt").read_text() == "x"


def test_a_figure_named_from_a_label_stays_in_the_figures_folder(tmp_path):
    figures = tmp_path / "results" / "figures"
    fig = new_figure(2, 2)
    fig.subplots().plot([0, 1])
    with pytest.raises(OutputError):
        save_figure(fig, figures, "velocity_x/../../../PWNED.png")  # a raw label: refused
    path = save_figure(fig, figures, f"{slug('velocity', 'x/../../../PWNED')}.png")
    assert path.parent == figures and path.is_file()
    assert [p.name for p in tmp_path.rglob("*.png")] == [path.name]
