"""``sdt twin``: check a sensor's twin against a paired real recording, and fit one from it."""

from __future__ import annotations

from functools import partial
from pathlib import Path

import typer

from ..errors import SDTError
from .common import console, print_json, registry, table
from .guards import OVERWRITE_HELP, os_errors

app = typer.Typer(help="The twin against real hardware: check and fit.", no_args_is_help=True)

_SENSOR = typer.Option(..., "--sensor", help="Twin to check: a sensor name or part mode.")
_AXES = typer.Option(None, "--axes", help="Axes to compare, e.g. x or x,y,z (default: all).")
_DEVICE = typer.Option(None, "--device-channel", help="Channel id of the real device.")
_REFERENCE = typer.Option(None, "--reference-channel", help="Channel id of the reference.")


def _load(ctx: typer.Context, pair: Path, sensor: str, axes: str | None, device: int | None,
          reference: int | None, reference_scale: float = 1.0):  # fmt: skip
    from ..twin import check_reference_scale, load_pair, require_rate, scaled_reference

    check_reference_scale(reference_scale)
    spec = registry(ctx).sensor(sensor)
    chosen = [a.strip().lower() for a in axes.split(",")] if axes else None
    require_rate(spec)  # before the pair is read: check and fit refuse alike
    with os_errors(str(pair)):
        loaded = load_pair(pair, spec.name, axes=chosen, device_channel=device,
                           readers=registry(ctx).signal_readers(),
                           reference_channel=reference)  # fmt: skip
    return scaled_reference(loaded, reference_scale), spec


def _say(line: str) -> None:
    console.print(line, highlight=False, soft_wrap=True)


@app.command("check")
def check(
    ctx: typer.Context,
    pair: Path = typer.Argument(
        ..., help="Paired recording: an enDAQ .IDE file, or a pair .toml naming two signals."
    ),
    sensor: str = _SENSOR,
    axes: str | None = _AXES,
    device_channel: int | None = _DEVICE,
    reference_channel: int | None = _REFERENCE,
    all_bands: bool = typer.Option(False, "--all-bands", help="List unjudgeable bands too."),
    reference_scale: float = typer.Option(
        1.0,
        "--reference-scale",
        help="Multiply the reference by this factor first (0.1-10): correct a reference "
        "whose calibration the check found off (its 'calibration' line).",
    ),
    plot: Path | None = typer.Option(
        None, "--plot", help="Save the spectra and transfer figure here (.png, .pdf, .svg)."
    ),
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
    overwrite: bool = typer.Option(False, "--overwrite", help=OVERWRITE_HELP),
) -> None:
    """Run the pair's reference through the twin of --sensor and compare it with the device.

    Alignment first (device rate from timestamps, time offset, signs, axis
    alignment), then third-octave bands: real RMS, twin RMS, error in dB, and
    whether the reference can judge the band. Formulas and limits:
    docs/validation.md.

    Example:

      sdt twin check tests/data/endaq/SSX66115.IDE --sensor adxl345 --plot ssx.png

      sdt twin check tests/data/endaq/DAQ12006_000005.IDE --sensor adxl357 --reference-scale 1.626

      sdt twin fit tests/data/endaq/SSX_Data.IDE --sensor adxl345 --out adxl345-fitted.toml

      sdt --sensor-file adxl345-fitted.toml twin check tests/data/endaq/SSX66115.IDE \\
        --sensor adxl345-fitted --json
    """
    from ..twin import check_twin, describe, plot_check
    from ..validation import plot_formats
    from .guards import check_output_file
    from .signal_io import check_pair_size

    if plot is not None:
        formats = [f".{f}" for f in plot_formats()]
        check_output_file(plot, "--plot", formats, [pair], overwrite=overwrite)
    check_pair_size(pair, registry(ctx).signal_readers())  # from the headers, before reading
    loaded, spec = _load(ctx, pair, sensor, axes, device_channel, reference_channel,
                         reference_scale)  # fmt: skip
    result = check_twin(loaded, spec)
    if plot is not None:
        with os_errors(str(plot)):
            plot_check(result, plot)
    if as_json:
        print_json(result.as_dict())
        return
    p, a, s = result.pair, result.alignment, result.summary
    fitted_here = "; IN-SAMPLE: this twin was fitted on this file" if p.in_sample else ""
    _say(f"{p.file}: reference {p.reference.channel} ({p.reference.part}, "
         f"{p.reference.rate_hz:.1f} Hz) -> twin of {spec.name} vs device "
         f"{p.device.channel} ({p.device.part}), {p.overlap_s:.1f} s overlap"
         f"{fitted_here}")  # fmt: skip
    for note in dict.fromkeys(p.notes):  # both channels of one file may carry its note
        _say(f"note: {note}")
    angles = ", ".join(f"{x} {d:.2f} deg" for x, d in zip(loaded.device.axes, a.angles_deg,
                                                          strict=True))  # fmt: skip
    mounting = f"signs {list(a.signs)}, axis angles {angles}" if a.rotation_estimated else (
        f"axes kept as mounted (device and twin correlate {a.correlation:.2f}: no shared "
        f"motion to align on)")  # fmt: skip
    setting = result.rate_setting or f"nominal {p.device.nominal_rate_hz}"
    _say(f"alignment: device rate {a.rate_hz:.2f} Hz ({setting}), "
         f"delay {1e3 * a.delay_s:+.3f} ms, {mounting}")  # fmt: skip
    rows = [
        [b.axis, f"{b.f_lower_hz:.0f}-{b.f_upper_hz:.0f}", f"{b.real_rms_g:.4g}",
         f"{b.twin_rms_g:.4g}", f"{b.error_db:+.1f}",
         f"{b.transfer.coherence:.3f}" if b.transfer else "-",
         "yes" if b.judgeable else f"no: {b.reason}"]
        for b in result.bands if b.judgeable or all_bands
    ]  # fmt: skip
    table("third-octave bands (g RMS)", ["axis", "band Hz", "real", "twin", "error dB",
                                          "coherence", "judgeable"], rows)  # fmt: skip
    floors = [
        [f.axis, f"{f.reference_ug:.0f}", f"{f.twin_ug:.0f}", f"{f.device_ug:.0f}",
         f"{f.twin_error_db:+.1f}", "yes" if f.judgeable else f"no: {f.reason}"]
        for f in result.floors
    ]  # fmt: skip
    table("noise floor (ug/sqrt(Hz), median away from tones)",
          ["axis", "reference", "twin", "device", "twin error dB", "judgeable"],
          floors)  # fmt: skip
    d, c = result.distortion, result.clipped
    _say(f"THD of the {d.tone_hz:.1f} Hz tone on {d.axis}: reference {d.reference:.2%}, "
         f"twin {d.twin:.2%}, device {d.device:.2%}; samples at full scale: device "
         f"{describe(c.device_clipping)}, twin {describe(c.twin_clipping)}")  # fmt: skip
    k = result.calibration
    gain = f"; device/twin gain {k.tone_gain:.3f} at {k.tone_hz:.1f} Hz" if k.tone_gain else ""
    _say(f"calibration: the device's mean vector is {k.static_g:.3f} g{gain}: {k.verdict}")
    _say(f"summary: {s.judgeable_bands} judgeable bands; worst {s.worst_error_db:+.1f} dB "
         f"({s.worst_axis}, {s.worst_band_hz:.0f} Hz band); RMS error "
         f"{s.rms_error_db:.1f} dB" + (" (in-sample)" if p.in_sample else ""))  # fmt: skip
    if plot is not None:
        _say(f"figure: {plot}")


@app.command("fit")
def fit(
    ctx: typer.Context,
    pair: Path = typer.Argument(
        ..., help="Paired recording: an enDAQ .IDE file, or a pair .toml naming two signals."
    ),
    sensor: str = typer.Option(..., "--sensor", help="Base profile to start from."),
    out: Path = typer.Option(..., "--out", help="Sensor file to write (.toml)."),
    name: str | None = typer.Option(None, "--name", help="Profile name (default NAME-fitted)."),
    axes: str | None = _AXES,
    device_channel: int | None = _DEVICE,
    reference_channel: int | None = _REFERENCE,
    overwrite: bool = typer.Option(False, "--overwrite", help=OVERWRITE_HELP),
) -> None:
    """Fit the twin parameters the pair supports; write them as an ordinary sensor file.

    Fitted, each with an uncertainty and its data: output rate, noise density per
    axis (and the floor's slope), the sensitivity error when the pair has
    judgeable bands. Everything else stays at the base profile's value, and the
    file says so.

    Example:

      sdt twin fit tests/data/endaq/SSX_Data.IDE --sensor adxl345 --out adxl345-fitted.toml

      sdt --sensor-file adxl345-fitted.toml twin check tests/data/endaq/SSX66115.IDE \\
        --sensor adxl345-fitted
    """
    from ..io import atomic_write_text
    from ..twin import fit_twin, profile_name, profile_toml
    from .guards import check_output_file

    check_output_file(out, "--out", [".toml"], [pair], overwrite=overwrite)  # before work
    name = profile_name(name, registry(ctx).sensor(sensor), partial(_known, ctx))
    loaded, spec = _load(ctx, pair, sensor, axes, device_channel, reference_channel)
    result = fit_twin(loaded, spec, name)
    with os_errors(str(out)):
        atomic_write_text(out, profile_toml(result))
    for line in result.provenance:
        _say(line)
    _say(f"wrote {out}: profile {result.profile['name']} (use --sensor-file {out})")


def _known(ctx: typer.Context, name: str) -> bool:
    """Whether ``--sensor name`` finds a sensor (built in or loaded): a fitted profile's
    name must not shadow one."""
    try:
        registry(ctx).sensor(name)
    except SDTError:
        return False
    return True
