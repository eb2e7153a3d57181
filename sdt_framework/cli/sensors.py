"""``sdt sensors``: the sensor profiles and parts the registry knows."""

from __future__ import annotations

import typer
from rich.table import Table

from ..specs import SensorSpec
from . import sensor_views as views
from .common import console, print_json, print_table, registry, table

app = typer.Typer(help="List and inspect sensor profiles and parts.", no_args_is_help=True)


def _fmt(value: object) -> str:
    if value is None:
        return "-"
    return value if isinstance(value, str) else f"{value:g}"


def _profile_row(s: SensorSpec) -> list[object]:
    digital = f"{s.digital_cutoff_hz:g} ({s.digital_order})" if s.digital_cutoff_hz else "-"
    noise = f"{s.noise_density_ug_rthz:g}" + ("" if s.inject_noise else " (off)")
    return [
        s.name,
        _fmt(s.sampling_rate_hz),
        _fmt(s.full_scale_g),
        _fmt(s.adc_bits),
        noise,
        _fmt(s.mech_cutoff_hz),
        _fmt(s.analog_cutoff_hz),
        digital,
        s.distribution,
    ]


def _widths(columns: list[str], cells: list[list[str]]) -> list[int]:
    """Column widths that fit the console and never split a word (a name or a number).

    Each column gets its longest word; what the console has left is shared out
    in proportion to how much more each column's longest line would take. When
    even the longest words do not fit, the natural widths are returned and
    :func:`print_table` prints the rows as lines.
    """
    texts = [[column, *(row[i] for row in cells)] for i, column in enumerate(columns)]
    words = [max((len(w) for t in col for w in t.split()), default=1) for col in texts]
    lines = [max((len(line) for t in col for line in t.splitlines()), default=1) for col in texts]
    spare = console.width - (3 * len(columns) + 1) - sum(words)  # borders and padding
    if spare < 0:
        return lines
    want = [max(0, line - word) for line, word in zip(lines, words, strict=True)]
    total = sum(want) or 1
    extra = [min(w, spare * w // total) for w in want]
    return [word + add for word, add in zip(words, extra, strict=True)]


def _table_by_distribution(title: str, columns: list[str], rows: list[list[object]]) -> None:
    """A table whose last column is the distribution; one shared distribution goes in the title.

    Every built-in profile comes from sdt-framework and every catalogue part from
    sdt-sensors-catalog: a column repeating one long word on every row is what
    kept the table from fitting 80 columns, so it is named once instead.
    """
    shared = {str(row[-1]) for row in rows}
    if len(shared) == 1:
        title = f"{title}; distribution {shared.pop()}"
        columns, rows = columns[:-1], [row[:-1] for row in rows]
    cells = [["" if cell is None else str(cell) for cell in row] for row in rows]
    out = Table(title=title, title_justify="left")
    for column, width in zip(columns, _widths(columns, cells), strict=True):
        out.add_column(column, width=width)
    for row in cells:
        out.add_row(*row)
    print_table(out)


@app.command("list")
def list_sensors(
    ctx: typer.Context,
    max_price: str | None = typer.Option(
        None, "--max-price", help="Parts priced at most this, e.g. 10EUR (profiles have no price)."
    ),
    min_rate: float | None = typer.Option(
        None, "--min-rate", help="Some mode samples at least this fast, Hz."
    ),
    max_noise: float | None = typer.Option(
        None, "--max-noise", help="Some mode's X-axis noise density at most this, µg/√Hz."
    ),
    simulable_at: float | None = typer.Option(
        None, "--simulable-at", help="Some mode can be simulated from a recording at HZ."
    ),
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
) -> None:
    """List sensor profiles (paper Table 1) and parts with their mode options.

    A part passes a filter when at least one of its modes does; --json lists
    those modes under "matching_modes".

    Example:

      sdt sensors list --max-price 15EUR --min-rate 3200

      sdt sensors list --simulable-at 20000 --max-noise 100 --json
    """
    from ..parts import PartFilter, search

    reg = registry(ctx)
    price = views.parse_price(max_price) if max_price else None
    found = search(reg.sensors(), reg.parts(), PartFilter(price, min_rate, max_noise, simulable_at))
    profiles, parts = list(found.profiles), [match.part for match in found.parts]
    if as_json:
        out = [views.sensor_json(s) for s in profiles]
        for match in found.parts:
            entry = views.part_json(match.part)
            if match.modes is not None:  # some filter was given
                entry["matching_modes"] = list(match.modes)
            out.append(entry)
        print_json(out)
        return
    if profiles:
        _table_by_distribution(
            "Sensor profiles (paper Table 1)",
            ["name", "rate Hz", "±g", "bits", "NSD µg/√Hz", "f_mech Hz", "f_ana Hz",
             "f_dig Hz (order)", "distribution"],
            [_profile_row(s) for s in profiles],
        )  # fmt: skip
    if not profiles and not parts:
        console.print("No sensor profile or part matches these filters.")
    if parts:
        _table_by_distribution(
            "Parts: use as name or name[key=option,...] (sdt sensors show NAME)",
            [
                "part",
                "modes",
                "rate Hz",
                "±g",
                "bits",
                "NSD µg/√Hz (default mode)",
                "price",
                "distribution",
            ],
            [[cell for cell in views.part_row(p)] for p in parts],
        )


@app.command("show")
def show_sensor(
    ctx: typer.Context,
    name: str = typer.Argument(
        ..., help="Sensor or part name, e.g. adxl345 or adxl355\\[range=8g]."
    ),
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
) -> None:
    """Show every field of a sensor profile, or a part in a mode with each value's source.

    A part's datasheet error terms are listed too; errors=datasheet,
    cross_axis=datasheet and temp=85c in the mode turn them on.

    Example:

      sdt sensors show adxl345

      sdt sensors show "adxl355\\[range=8g,odr=1000]"

      sdt sensors show "adxl355\\[errors=datasheet,temp=85c]"
    """
    from ..parts import resolve, split_name

    reg = registry(ctx)
    base, modes = split_name(name)
    if base in {p.name for p in reg.parts()}:
        resolved = resolve(reg.part(base), modes)
        if as_json:
            print_json(
                {
                    **views.part_json(resolved.part),
                    "sensor": views.sensor_json(resolved.sensor),
                    "mode": resolved.mode,
                    "provenance": [s.as_dict() for s in resolved.sources],
                    "error_mode": resolved.error_mode,
                    "error_terms": [t.as_dict() for t in resolved.terms],
                }
            )
            return
        _print_part(resolved)
        return
    spec = reg.sensor(name)
    if as_json:
        print_json(views.sensor_json(spec))
        return
    data = views.sensor_json(spec)
    rows = [
        [field, views.profile_cell(spec, field, data), info.description or ""]
        for field, info in SensorSpec.model_fields.items()
        if field != "supply"  # shown by `sdt budget --sensor`, with its sources
    ]
    step = spec.quantisation_step_g
    rows.append(["quantisation_step_g", _fmt(step and float(f"{step:.6g}")), "2 G_max / 2**B, g"])
    rows.append(["content_hash", spec.content_hash()[:16], "Stable hash of the chain fields"])
    table(
        f"Sensor {spec.name}",
        ["field", "value", "meaning"],
        [[str(c) for c in r] for r in rows],
    )


def _say(text: str) -> None:
    console.print(text, highlight=False, markup=False)


def _print_part(resolved) -> None:
    part, sensor = resolved.part, resolved.sensor
    rows, notes = views.provenance_rows(resolved)
    table(
        f"{sensor.name}: {sensor.description}",
        ["field", "value", "source", "where", "basis", "set by"],
        [[str(c) for c in row] for row in rows],
    )
    for note in notes:
        _say(note)
    title, rows, notes = views.error_rows(resolved)
    if rows:
        table(title, ["term", "figure", "per unit → stage", "state", "doc", "where"], rows)
        for note in notes:
            _say(note)
    table(
        f"Modes of {part.name}: {part.name}[key=option,...]",
        ["key", "options", "default", "why the default"],
        [
            [str(c) for c in (key, ", ".join(mode.options), mode.default, mode.default_why)]
            for key, mode in sorted(part.modes.items())
        ],
    )
    if part.price:
        p = part.price
        _say(
            f"Indicative price: {p.amount:g} {p.currency} ({p.quantity}; {p.source}, {p.date})"
            + (f"; {p.note}" if p.note else "")
        )
    elif part.no_price:
        n = part.no_price
        _say(
            f"Indicative price: no public price found ({len(n.searched)} searches on {n.date}, "
            f"listed in the part file's [no_price])."
        )
    else:
        _say("Indicative price: not found.")
    _say("Sources:")
    for doc_id, doc in part.documents.items():
        kind = " (secondary source)" if doc.secondary else ""
        _say(f"  {doc_id}: {doc.title}, {doc.revision}{kind} {doc.url}".rstrip())
    for note in part.notes:
        _say(f"Note: {note}")
