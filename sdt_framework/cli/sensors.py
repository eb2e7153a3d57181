"""``sdt sensors``: the sensor profiles the registry knows."""

from __future__ import annotations

import typer

from ..specs import SensorSpec
from .common import print_json, registry, table

app = typer.Typer(help="List and inspect sensor profiles.", no_args_is_help=True)


def _sensor_json(spec: SensorSpec) -> dict:
    return {
        **spec.content_dict(),
        "plugin": spec.plugin,
        "distribution": spec.distribution,
        "quantisation_step_g": spec.quantisation_step_g,
        "content_hash": spec.content_hash(),
    }


@app.command("list")
def list_sensors(
    ctx: typer.Context,
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
) -> None:
    """List sensor profiles with their paper Table 1 parameters.

    Example:

      sdt sensors list --json

      sdt --sensor-file my_sensor.toml sensors list
    """
    sensors = registry(ctx).sensors()
    if as_json:
        print_json([_sensor_json(s) for s in sensors])
        return
    rows = []
    for s in sensors:
        digital = f"{s.digital_cutoff_hz:g} ({s.digital_order})" if s.digital_cutoff_hz else "-"
        noise = f"{s.noise_density_ug_rthz:g}" + ("" if s.inject_noise else " (off)")
        rows.append(
            [
                s.name,
                f"{s.sampling_rate_hz:g}",
                f"{s.full_scale_g:g}",
                s.adc_bits,
                noise,
                f"{s.mech_cutoff_hz:g}",
                f"{s.analog_cutoff_hz:g}",
                digital,
                s.distribution,
            ]
        )
    table(
        "Sensor profiles (paper Table 1)",
        [
            "name",
            "rate Hz",
            "±g",
            "bits",
            "NSD µg/√Hz",
            "f_mech Hz",
            "f_ana Hz",
            "f_dig Hz (order)",
            "distribution",
        ],
        rows,
    )


@app.command("show")
def show_sensor(
    ctx: typer.Context,
    name: str = typer.Argument(..., help="Sensor name, e.g. adxl345."),
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
) -> None:
    """Show every field of one sensor profile, with units and meaning.

    Example:

      sdt sensors show adxl345
    """
    spec = registry(ctx).sensor(name)
    if as_json:
        print_json(_sensor_json(spec))
        return
    data = _sensor_json(spec)
    rows = [
        [field, data.get(field), info.description or ""]
        for field, info in SensorSpec.model_fields.items()
    ]
    rows.append(["quantisation_step_g", f"{spec.quantisation_step_g:.6g}", "2 G_max / 2**B, g"])
    rows.append(["content_hash", spec.content_hash()[:16], "Stable hash of the chain fields"])
    table(f"Sensor {spec.name}", ["field", "value", "meaning"], rows)
