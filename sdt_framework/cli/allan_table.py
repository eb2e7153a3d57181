"""The Allan table of ``sdt validate-noise``: configured noise terms beside the read-off ones."""

from __future__ import annotations

from typing import Any

from .common import console, table

__all__ = ["print_allan_table"]

ROWS = (
    ("nsd_ug_rthz", "White density √2·N, µg/√Hz", "{:.1f}"),
    ("n_ug_rthz", "N = ADEV at 1 s, µg/√Hz", "{:.1f}"),
    ("vrw_mps_rthr", "VRW = N·g0·60, (m/s)/√h", "{:.4f}"),
    ("bias_instability_ug", "Bias instability B = floor/0.664, µg", "{:.1f}"),
)


def _source(name: str, curve: dict[str, Any]) -> str:
    line = (
        f"{name}: {curve['samples']:,} samples at {curve['fs_hz']:g} Hz "
        f"({curve['samples'] / curve['fs_hz']:.4g} s)"
    )
    if curve["tau_range_s"]:
        line += f", tau {curve['tau_range_s'][0]:.3g}-{curve['tau_range_s'][1]:.3g} s"
    if curve["white_fit_tau_s"]:
        fit = curve["white_fit_tau_s"]
        line += f"; -1/2 line fitted over {fit[0]:.3g}-{fit[1]:.3g} s"
    if curve["floor_tau_s"] is not None:
        line += f"; floor {curve['floor_ug']:.1f} µg at {curve['floor_tau_s']:.3g} s"
    return line


def print_allan_table(allan: dict[str, Any], sensor: str, axis: str) -> None:
    """Print the read-off table of ``AllanCheck.to_dict()``, then the record and the reasons.

    A configured term the profile does not have is "-"; a value the curve does
    not show is "n/a (k)", and note k says why.
    """
    sources = [("recording", "Recording")] if "recording" in allan else []
    sources.append(("sdt", "SDT model"))
    notes: list[str] = []
    rows = []
    for key, name, fmt in ROWS:
        value = allan["configured"][key]
        row = [name, "-" if value is None else fmt.format(value)]
        for source, label in sources:
            curve = allan[source]
            value = curve[key]
            if value is None:
                reason = curve["bias_reason" if key == "bias_instability_ug" else "white_reason"]
                if source == "sdt" and reason.startswith("no flat region"):
                    reason += "; more --windows reach longer taus"
                note = f"{label}: {reason}"
                if note not in notes:
                    notes.append(note)
                value = f"n/a ({notes.index(note) + 1})"
            else:
                value = fmt.format(value)
            row.append(value)
        rows.append(row)
    title = f"Allan deviation, {sensor}, {axis} axis (IEEE 952 read-off)"
    table(title, ["Noise term", "Configured", *[label for _, label in sources]], rows)
    terms = "; ".join(allan["configured"]["terms"]) or "no white-noise or bias-instability term"
    console.print(f"Configured: {terms}", highlight=False, soft_wrap=True)
    for source, label in sources:
        console.print(_source(label, allan[source]), highlight=False, soft_wrap=True)
    for k, note in enumerate(notes, 1):
        console.print(f"({k}) {note}", highlight=False, soft_wrap=True)
