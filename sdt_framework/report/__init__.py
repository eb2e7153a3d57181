"""Reports: the paper's tables and figures from a results folder.

Plots: a figure is drawn in the package whose results it shows (the
zero-motion check in :mod:`sdt_framework.validation`, the twin check in
``twin/plot.py``, the critical-difference diagram in ``verdict/cdplot.py``);
this package draws the benchmark's own figures and composes the document,
reusing those ``draw_*`` functions.

Public API
----------
write_report(results_dir, formats=("md", "html"), *, registry=None) -> dict[str, Path]
    report.md (figures linked from ``figures/``) and a self-contained report.html.
load_results(results_dir) -> ResultsFolder
    The folder's tables, tolerating missing optional files.
sensor_colors(sensors, reference)
    The one sensor -> colour mapping every figure uses.
folder_machines(folder, registry) ; no_spec_line(machine) ; condition_cells(agreement)
    The machines of the folder's benchmark (their specs), what one without a spec lacks,
    and the severity table's cells, as ``sdt compare`` prints them beside the report.
"""

from __future__ import annotations

from .build import write_report
from .load import ResultsFolder, load_results
from .machines import folder_machines, no_spec_line
from .severity_tables import condition_cells
from .style import sensor_colors

__all__ = [
    "ResultsFolder",
    "condition_cells",
    "folder_machines",
    "load_results",
    "no_spec_line",
    "sensor_colors",
    "write_report",
]
