"""What ``sdt explore`` prints after a sweep: per-point constraints, minimum spec, life front.

Each table is read from the sweep's own tables (pareto.csv, min_spec.csv), so
what is printed is what the files hold.
"""

from __future__ import annotations

from typing import Any

from .common import console, table

__all__ = ["print_tables"]

#: what each fidelity means, in the printed titles
FIDELITY = {
    "full": "full protocol",
    "screen": "screen: lr and knn, 1 repetition",
}
#: label in the minimum-spec table -> min_spec.csv column of that constraint alone
RULES = {"F1": "min_level_macro_f1", "zones": "min_level_zones", "life": "min_level_life"}


def _level(level: float, alone: dict[str, float]) -> str:
    """A minimum level; with constraints, which one alone gives it (F1, zones, life)."""
    text = "none" if level != level else f"{level:g}"
    if not alone:
        return text
    binding = [rule for rule, v in alone.items() if v == level or (v != v and level != level)]
    return f"{text} ({', '.join(binding) or 'together'})"


def _print_min_spec(min_spec: Any) -> None:
    """The minimum specification per machine and scenario (best classifier), as a table."""
    best = min_spec[min_spec["classifier"] == "best"]
    if best.empty:
        return
    rules = {rule: column for rule, column in RULES.items() if column in best}
    wide = best.pivot_table(
        index=["machine", "scenario"],
        columns="parameter",
        values=["min_level", *rules.values()],
        dropna=False,
    )
    rows = []
    for machine, scenario in wide.index:
        row = wide.loc[(machine, scenario)]
        cells = [
            _level(row[("min_level", p)], {r: row[(c, p)] for r, c in rules.items()})
            for p in wide["min_level"].columns
        ]
        rows.append([machine, scenario, *cells])
    wide = wide["min_level"]
    bases = best.drop_duplicates("parameter").set_index("parameter")["base_level"]
    columns = [f"{p} (base {'absent' if bases[p] != bases[p] else f'{bases[p]:g}'})" for p in wide]
    fidelity = FIDELITY[best["fidelity"].iloc[0]]
    title = f"Minimum specification: {best['target'].iloc[0]} (best classifier; {fidelity})"
    table(title, ["machine", "scenario", *columns], rows)
    if rules:
        labels = " / ".join(f"({r})" for r in rules)
        alone = "neither alone" if len(rules) == 2 else "none alone"
        console.print(
            f"{labels}: the constraint that sets the level alone; (together): {alone}; "
            f"see min_spec.csv",
            highlight=False,
            soft_wrap=True,
        )
    notes = best.loc[best["note"].fillna("").str.contains("life"), "note"].drop_duplicates()
    for note in notes:
        console.print(f"note: {note}", highlight=False, soft_wrap=True)


def _print_zone_agreement(pareto: Any, fields: list[str], threshold: float | None) -> None:
    """Each point's zone agreement per machine, with the ones below the target marked."""
    if threshold is None or "zone_agreement" not in pareto:
        return
    shares = pareto.drop_duplicates(["point", "machine"])
    wide = shares.pivot_table(index="point", columns="machine", values="zone_agreement")
    params = shares.drop_duplicates("point").set_index("point")[fields].loc[wide.index]
    order = params.sort_values(fields).index
    rows = [
        [
            *(f"{params.at[point, f]:g}" for f in fields),
            *(f"{100 * v:.1f} %{'' if v >= threshold else ' fails'}" for v in wide.loc[point]),
        ]
        for point in order
    ]
    title = (
        f"Zone agreement per point: share of windows graded in the reference's ISO zone "
        f"(target >= {100 * threshold:g} %)"
    )
    table(title, [*fields, *wide.columns], rows)


def _print_battery_life(pareto: Any, fields: list[str], target: Any) -> None:
    """Each point's battery life against the target's; unknown lives say why, never a figure."""
    threshold = target.min_battery_life_years
    if threshold is None or "battery_life_years" not in pareto:
        return
    points = pareto.drop_duplicates("point").set_index("point")
    rows = []
    for _, row in points.sort_values(fields).iterrows():
        life = row["battery_life_years"]
        if life != life:
            text = f"unknown, fails: {row.get('life_note') or 'no supply figures on record'}"
        else:
            capped = " (shelf-life cap)" if row.get("life_note") else ""
            text = f"{life:.3f}{capped}{'' if life >= threshold else ' fails'}"
        rows.append([*(f"{row[f]:g}" for f in fields), text])
    title = f"Battery life per point, years ({target.node()}; target >= {threshold:g})"
    table(title, [*fields, "battery life (years)"], rows)


def _print_life_front(pareto: Any, target: Any) -> None:
    """Each point's cost, battery life and Macro F1, and the cells where it is on the front."""
    from ..explore import life_front

    front = life_front(pareto)
    if front.empty:
        return
    rows = [
        [
            r.point,
            f"{r.cost:.2f}",
            f"{r.battery_life_years:.2f}",
            f"{r.macro_f1:.3f}",
            f"{r.on_front} of {r.cells}",
        ]
        for r in front.itertuples()
    ]
    title = f"Battery life ({target.node()}), cost and Macro F1 (best classifier)"
    columns = ["point", "cost", "life (years)", "Macro F1 (mean)", "on front with life"]
    table(title, columns, rows)


def print_tables(tables: dict[str, Any], fields: list[str], target: Any) -> None:
    """Per-point zone agreement and battery life (when asked), minimum spec, life front."""
    pareto = tables.get("pareto")
    if pareto is not None:
        _print_zone_agreement(pareto, fields, target.zone_agreement)
        _print_battery_life(pareto, fields, target)
    _print_min_spec(tables["min_spec"])
    if pareto is not None:
        _print_life_front(pareto, target)
