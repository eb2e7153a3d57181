"""The benchmark orchestrator: scenarios, runs, results (SPEC sections 5-7).

Public API
----------
run_benchmark_folder(config, registry, out_dir, *, yes, progress, warn, check, started, finish)
    The main job in one call, as ``sdt benchmark`` runs it: plan, size check,
    claim (or resume) the folder, run, write every output file; -> FolderRun.
run_plan_folder(plan, out_dir, ...)
    The same for a plan made already (``sdt explore``'s design points).
load_config(path, overrides), BenchmarkConfig, quick_preset(data)
    A configuration: the ``[benchmark]`` table of a TOML file (or none) under overrides.
plan_benchmark(config, registry) -> Plan
    Everything resolved and checked, nothing run.
run_benchmark(plan, out_dir, progress, warn, *, workers) -> BenchmarkResult
write_outputs(result, out_dir)
    The run and the output files on their own (what ``run_plan_folder`` calls).
check_size(plan, out_dir, yes, what, reduce) -> Estimate ; check_estimate ; stored_runs
    A plan's size (runs, time, memory, disk; the module ``bench.estimate``
    estimates) and the checks every caller refuses by.
build_table4(results, sensor_order) -> Table4 ; table4_markdown(table) ; tidy(runs)
    Table 4 of a results table; the tidy tables of runs.
OUTPUT_FILES
    Every file a benchmark writes at the top of its folder.
ASSUMES ; pool_note ; saturation_summary, saturation_lines ; watch_interrupts ; write_frame
    What the command line prints around a run: what the estimate assumes, the process
    pool, the samples at full scale; the interrupt (Ctrl-C, SIGTERM) watch; a table written.

Names load on first use, so ``sdt --help`` does not import pandas or scikit-learn.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..lazy import lazy_exports

if TYPE_CHECKING:
    from .config import BenchmarkConfig, load_config, quick_preset
    from .estimate import ASSUMES, Estimate
    from .folder import OUTPUT_FILES
    from .interrupt import watch_interrupts
    from .job import BENCHMARK, FolderRun, Wording, run_benchmark_folder, run_plan_folder
    from .output import write_outputs
    from .plan import Plan, plan_benchmark
    from .pool import pool_note
    from .results import tidy, write_frame
    from .runner import BenchmarkResult, run_benchmark
    from .saturation import saturation_lines, saturation_summary
    from .size_check import check_estimate, check_size, stored_runs
    from .table4 import Table4, build_table4, table4_markdown

#: public name -> the submodule that defines it, loaded on first use (PEP 562)
_WHERE = {
    "BenchmarkConfig": "config",
    "load_config": "config",
    "quick_preset": "config",
    "ASSUMES": "estimate",
    "Estimate": "estimate",
    "OUTPUT_FILES": "folder",
    "watch_interrupts": "interrupt",
    "BENCHMARK": "job",
    "FolderRun": "job",
    "Wording": "job",
    "run_benchmark_folder": "job",
    "run_plan_folder": "job",
    "write_outputs": "output",
    "Plan": "plan",
    "plan_benchmark": "plan",
    "pool_note": "pool",
    "tidy": "results",
    "write_frame": "results",
    "BenchmarkResult": "runner",
    "run_benchmark": "runner",
    "saturation_lines": "saturation",
    "saturation_summary": "saturation",
    "check_estimate": "size_check",
    "check_size": "size_check",
    "stored_runs": "size_check",
    "Table4": "table4",
    "build_table4": "table4",
    "table4_markdown": "table4",
}
__all__ = [
    "ASSUMES",
    "BENCHMARK",
    "OUTPUT_FILES",
    "BenchmarkConfig",
    "BenchmarkResult",
    "Estimate",
    "FolderRun",
    "Plan",
    "Table4",
    "Wording",
    "build_table4",
    "check_estimate",
    "check_size",
    "load_config",
    "plan_benchmark",
    "pool_note",
    "quick_preset",
    "run_benchmark",
    "run_benchmark_folder",
    "run_plan_folder",
    "saturation_lines",
    "saturation_summary",
    "stored_runs",
    "table4_markdown",
    "tidy",
    "watch_interrupts",
    "write_frame",
    "write_outputs",
]

__getattr__, __dir__ = lazy_exports(__name__, _WHERE, globals())
