"""The benchmark configuration: one validated model, from TOML and the command line.

Every name is resolved through the registry before any work starts, so an
unknown sensor, a negative repetition count or a sensor faster than the data
is one clear message, not a failure half an hour into a sweep. The resolved
configuration is written beside the results as ``config.toml`` and re-runs the
same benchmark with ``sdt benchmark config.toml``.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Literal

import tomli_w
from pydantic import BaseModel, ConfigDict, Field, ValidationInfo, field_validator

from ..errors import SpecFileError, one_line
from ..io import atomic_write_text
from ..machine_files import machines_from_tables
from ..toml_files import read_toml, validate_file
from .config_paths import relative_to, resolve_written, written_by_sdt
from .speed_split import SPEED_TRANSFER, SpeedTransfer, check_speeds

__all__ = [
    "SCENARIOS",
    "BenchmarkConfig",
    "load_config",
    "quick_preset",
    "validate_config",
    "write_config",
]

SCENARIOS = ("forward", "backward", "interpolation")

#: --quick: 2 repetitions, 4 s synthetic acquisitions, one 60 s measurement per NLN-EMP run
QUICK_REPEATS = 2
QUICK_SYNTHETIC_DURATION_S = 4.0
QUICK_NLN_EMP_ACQUISITIONS = 5


class BenchmarkConfig(BaseModel):
    """Everything that defines a benchmark run (SPEC sections 5-7)."""

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)

    dataset: str | None = Field(
        default=None,
        description="Registered dataset name; default: picked from `data`, "
        "or synthetic-pump when no data is given.",
    )
    data: str | None = Field(default=None, description="NLN-EMP root folder or manifest file.")
    dataset_options: dict[str, Any] = Field(
        default_factory=dict, description="Options passed to the dataset loader."
    )
    machines: list[str] | None = Field(default=None, description="Machines to use (all).")
    speeds: list[float | str] | None = Field(
        default=None,
        description="Operating speeds to use, e.g. [50, 100]: the recordings whose "
        "speed_percent or speed label is one of them, also handed to a dataset that takes "
        "`speeds` (NLN-EMP reads those speed folders). Default: every recording the dataset "
        "gives (for NLN-EMP the paper's speeds).",
    )
    channels: list[str] | None = Field(default=None, description="Channels to use (all).")
    sensors: list[str] | None = Field(
        default=None,
        description="Sensor names, parts with a mode as 'adxl355[range=8g]' (default: the "
        "reference, adxl345, adxl357).",
    )
    reference: str | None = Field(
        default=None,
        description="Reference sensor for deltas (default: wilcoxon-786b10 for 20 kHz data, "
        "native-reference otherwise).",
    )
    axes: dict[str, Literal["x", "y", "z"]] = Field(
        default_factory=dict,
        description="Sensor axis each channel is mounted on, e.g. {ch3 = 'z'} (default x): "
        "a part's per-axis noise follows it.",
    )
    transfer: list[str] | None = Field(
        default=None,
        description="Cross-chain runs, each 'TRAIN -> TEST': train on one chain's features, "
        "test on another's, e.g. 'wilcoxon-786b10 -> adxl345,adxl357', 'reference -> *', "
        "or a mix 'wilcoxon-786b10+adxl345 -> adxl345'.",
    )
    sample: Literal["channel", "node"] | None = Field(
        default=None,
        description="'channel' (default, the paper's): every channel's windows are samples; "
        "'node': one sample per window per triaxial node (its axes' features concatenated).",
    )
    nodes: dict[str, list[str]] | None = Field(
        default=None,
        description="Triaxial nodes by name, each three channels mapped in `axes`, e.g. "
        "{de = ['ch1', 'ch2', 'ch3']} (default: one node of the channels in `axes`).",
    )
    classifiers: list[str] | None = Field(default=None, description="Classifiers (all).")
    features: str = Field(default="paper8", description="Feature set, e.g. 'paper8+env_bpfo'.")
    feature_dtype: Literal["float16", "float32"] | None = Field(
        default=None,
        description="Round features to this on-node type before classification "
        "(default: the feature set's declared dtype).",
    )
    window_s: float = Field(
        default=0.64, gt=0, le=3600, description="Window length, s (finite, at most an hour)."
    )
    settle_s: float = Field(
        default=0.1, ge=0, le=3600, description="Settling discarded per acquisition, s."
    )
    scenarios: list[Literal["forward", "backward", "interpolation", "speed-transfer"]] = Field(
        default_factory=lambda: list(SCENARIOS),
        description="Generalisation scenarios; speed-transfer: train at other speeds than "
        "the test runs' (leave one speed out, or the speed_transfer pair).",
    )
    speed_transfer: SpeedTransfer | None = Field(
        default=None,
        description="The speed-transfer scenario's pair, e.g. {train = [100], test = [75]} "
        "(default: leave one speed out), and split: the rule splitting each speed's runs "
        "(forward, backward, interpolation; all: every run, no within-speed arm).",
    )
    allocation: str | None = Field(
        default=None, description="CSV/TOML allocation table replacing the scenario rule."
    )
    zones: dict[str, str] | None = Field(
        default=None,
        description="ISO zone table per machine for the severity figures, e.g. {'Motor-4' = "
        "'iso10816-3-group2-flexible'}: a built-in name, FILE.toml or FILE.toml#NAME "
        "(default: the built-in choice for the synthetic pump and NLN-EMP, docs/severity.md).",
    )
    machine_specs: str | dict[str, dict[str, Any]] | None = Field(
        default=None,
        description="Your machines (shaft speed, bearings with geometry, zone table): a "
        "machine file's path, or [benchmark.machine_specs.NAME] tables; over the dataset's "
        "own (docs/severity.md).",
    )
    repeats: int = Field(default=10, ge=1, description="Repetitions N (noise and seeds).")
    units: int | None = Field(
        default=None,
        ge=1,
        description="Physical units per sensor drawn from its tolerances (None: nominal only).",
    )
    seed: int = Field(default=0, ge=0, description="Base seed.")
    jobs: int = Field(
        default=-1,
        description=(
            "Parallel processes (-1: all cores; a local benchmark estimated under 5 s runs in "
            "this process alone)."
        ),
    )
    backend: Literal["local", "dask"] = Field(default="local", description="Execution engine.")
    scheduler: str | None = Field(default=None, description="Dask scheduler address.")
    cache_dir: str | None = Field(default=None, description="Feature cache folder.")
    report: bool = Field(default=True, description="Write the report at the end.")

    @field_validator("sensors", "classifiers", "machines", "channels", "scenarios", "speeds")
    @classmethod
    def _not_empty(cls, value: list[Any] | None) -> list[Any] | None:
        if value is not None and not value:
            raise ValueError("must name at least one entry (or be left out for all)")
        if value is not None and len(set(value)) != len(value):
            raise ValueError(f"lists a name twice: {value}")
        return value

    @field_validator("speeds", mode="before")
    @classmethod
    def _speeds(cls, value: Any) -> Any:
        if isinstance(value, str):  # "all" is the dataset's option, not a selection
            raise ValueError(
                "give the speeds to use, e.g. [50, 75, 100] (--speeds 50,75,100); every speed "
                "a dataset holds: dataset_options speeds = 'all'"
            )
        return check_speeds(value, "50")

    @field_validator("zones")
    @classmethod
    def _zones(cls, value: dict[str, str] | None) -> dict[str, str] | None:
        for machine, table in (value or {}).items():
            if not machine.strip() or not table.strip():
                raise ValueError(f"{machine!r} = {table!r}: give MACHINE = TABLE, both named")
        return value

    @field_validator("sample")
    @classmethod
    def _sample(cls, value: str | None) -> str | None:
        return None if value == "channel" else value  # the default, spelled out

    @field_validator("transfer")
    @classmethod
    def _transfer(cls, value: list[str] | None) -> list[str] | None:
        if value is not None and not value:
            raise ValueError("must name at least one 'TRAIN -> TEST' pair (or be left out)")
        for pair in value or ():
            if pair.count("->") != 1:
                raise ValueError(f"{pair!r} is not 'TRAIN -> TEST' (e.g. 'wilcoxon-786b10 -> "
                                 f"adxl345')")  # fmt: skip
        return value

    @field_validator("jobs")
    @classmethod
    def _jobs(cls, value: int) -> int:
        if value == 0 or value < -1:
            raise ValueError("must be a positive number of processes, or -1 for all cores")
        return value

    @field_validator("speed_transfer")
    @classmethod
    def _speed_pair(cls, value: SpeedTransfer | None, info: ValidationInfo) -> Any:
        scenarios = info.data.get("scenarios", SCENARIOS)
        if value is not None and SPEED_TRANSFER not in scenarios:
            raise ValueError(
                f"sets the {SPEED_TRANSFER} scenario, which scenarios {list(scenarios)} does "
                f"not name; add it (--scenarios {SPEED_TRANSFER})"
            )
        return value

    def n_jobs(self) -> int:
        """Processes to use."""
        return os.cpu_count() or 1 if self.jobs == -1 else self.jobs


def validate_config(data: dict[str, Any], where: str) -> BenchmarkConfig:
    """``data`` as a :class:`BenchmarkConfig`; an error names ``where``, the field and the value.

    Machines written as ``[benchmark.machine_specs.NAME]`` tables are checked here
    (:func:`~sdt_framework.machine_files.machines_from_tables`): a missing field or an
    impossible bearing names this file. A machine file named by path is read when the
    benchmark is planned (a results folder moved without it keeps its configuration).
    """
    config = validate_file(BenchmarkConfig, data, where, unknown="unknown option", show_input=True)
    if isinstance(config.machine_specs, dict):
        machines_from_tables(config.machine_specs, where, "machine_specs.")
    return config


def load_config(path: str | os.PathLike[str] | None, overrides: dict[str, Any]) -> BenchmarkConfig:
    """Read a TOML config (optional) and apply command-line overrides on top.

    ``overrides`` holds only the options the user actually gave; ``quick``
    (if true) adds the quick preset under everything given explicitly.
    """
    data: dict[str, Any] = {}
    where = "command line"
    if path is not None:
        where = str(path)
        data = read_toml(path, what="config file", missing="config file not found; check the path")
        if "benchmark" in data:
            data = data["benchmark"]
            if not isinstance(data, dict):
                raise SpecFileError(
                    path,
                    "benchmark",
                    f"must be a table of options ([benchmark] followed by lines such as "
                    f"repeats = 3), got {type(data).__name__} {one_line(repr(data), 60)}",
                )
        if written_by_sdt(path):
            data = resolve_written(data, Path(path).parent)
    if overrides.pop("quick", False):
        data = quick_preset({**data, **overrides})
    data.update(overrides)
    return validate_config(data, where)


def quick_preset(data: dict[str, Any]) -> dict[str, Any]:
    """The quick preset, under explicit settings: fewer repetitions and less data per run."""
    options = data.get("dataset_options", {})
    if not isinstance(options, dict):  # the model names the field and the value
        return {"repeats": QUICK_REPEATS, **data}
    options = dict(options)
    source = data.get("data")
    if source is None and data.get("dataset") in (None, "synthetic-pump"):
        options.setdefault("duration", QUICK_SYNTHETIC_DURATION_S)
    elif source is not None and Path(source).is_dir():  # an NLN-EMP root
        options.setdefault("max_acquisitions", QUICK_NLN_EMP_ACQUISITIONS)
    return {"repeats": QUICK_REPEATS, **data, "dataset_options": options}


def write_config(config: BenchmarkConfig, path: str | os.PathLike[str]) -> None:
    """Write the fully resolved config as TOML (re-runnable with `sdt benchmark PATH`).

    Paths are written relative to the file's folder (:mod:`.config_paths`). The
    feature-cache folder is left out: it is where this machine keeps a cache,
    not part of the benchmark, and changes no result (a resume uses
    ``--cache-dir``, ``$SDT_CACHE_DIR`` or the default cache).
    """
    data = {
        k: v
        for k, v in config.model_dump(mode="json", exclude_none=True).items()
        if v is not None and k != "cache_dir"
    }
    atomic_write_text(
        path,
        "# Resolved by sdt benchmark; re-run with: sdt benchmark config.toml\n"
        "# (paths are relative to this file's folder)\n"
        + tomli_w.dumps({"benchmark": relative_to(data, Path(path).parent)}),
    )
