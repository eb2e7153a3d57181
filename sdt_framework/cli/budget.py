"""``sdt budget``: what sending a feature set over LoRaWAN costs a node per day."""

from __future__ import annotations

from dataclasses import replace

import typer

from ..errors import SDTError
from .common import console, print_json, print_table, registry

__all__ = ["budget"]


def budget(
    ctx: typer.Context,
    features: str = typer.Option(
        "paper8", "--features", help="Feature set, or names joined by '+' (paper8+env_bpfo)."
    ),
    axes: int = typer.Option(3, "--axes", help="Axes per report (3: triaxial)."),
    interval: str = typer.Option(
        "10min", "--interval", help="Time between reports: 30s, 10min, 1h, 1d."
    ),
    region: str = typer.Option("EU868", "--region", help="LoRaWAN regional plan: EU868, US915."),
    dtype: str | None = typer.Option(
        None, "--dtype", help="Send values as float16 or float32 (default: the set's dtype)."
    ),
    radio: str = typer.Option(
        "sx1276-rfo-13dbm",
        "--radio",
        help="Radio model: sx1276-rfo-7dbm, sx1276-rfo-13dbm, sx1276-boost-17dbm, "
        "sx1276-boost-20dbm.",
    ),
    tx_current_ma: float | None = typer.Option(
        None, "--tx-current-ma", help="Override the radio's transmit current, mA."
    ),
    voltage: float | None = typer.Option(None, "--voltage", help="Override the supply, V."),
    repeater: bool = typer.Option(
        True,
        "--repeater/--no-repeater",
        help="Payload limits of the repeater-compatible table (default) or the larger one.",
    ),
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
) -> None:
    """Payload, LoRaWAN airtime, duty cycle and radio energy of one report per interval.

    One report is one window's feature vector on every axis. For each data rate
    of the region: whether it fits one uplink (else how many), time on air
    (Semtech SX127x formula), the shortest interval the duty cycle allows,
    airtime and transmit energy per day. Formulas and sources: docs/edge.md.

    Example:

      sdt budget --features paper8 --axes 3 --interval 10min --region EU868

      sdt budget --dtype float16 --region US915 --json
    """
    from ..edge import edge_budget, parse_interval
    from ..edge import radio as radio_named
    from ..edge.table import budget_rows, budget_summary
    from ..features import resolve_feature_set

    if axes < 1:
        raise SDTError(f"--axes must be 1 or more, got {axes}")
    if dtype is not None and dtype not in ("float16", "float32"):
        raise SDTError(f"--dtype must be float16 or float32, got {dtype!r}")
    seconds = parse_interval(interval)
    model = radio_named(radio)
    if tx_current_ma is not None or voltage is not None:
        model = replace(
            model,
            name=f"{model.name} (custom)",
            tx_current_a=model.tx_current_a if tx_current_ma is None else tx_current_ma / 1e3,
            supply_v=model.supply_v if voltage is None else voltage,
            source="user override",
        )
    spec = resolve_feature_set(registry(ctx), features)
    result = edge_budget(
        spec,
        axes=axes,
        interval_s=seconds,
        region=region,
        radio=model,
        dtype=dtype,
        repeater=repeater,
    )
    if as_json:
        print_json(result.to_dict())
        return
    from rich import box
    from rich.table import Table

    columns, rows = budget_rows(result)
    console.print(budget_summary(result), highlight=False, soft_wrap=True, markup=False)
    out = Table(box=box.SIMPLE_HEAD, padding=0, pad_edge=False, show_edge=False)
    for i, column in enumerate(columns):
        widest = max(len(row[i]) for row in rows)  # data never wraps; headers may
        out.add_column(column, justify="left" if i < 2 else "right", min_width=widest)
    for row in rows:
        out.add_row(*row)
    print_table(out)
