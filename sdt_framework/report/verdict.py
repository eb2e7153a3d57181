"""The report's opening section: the verdict of :mod:`sdt_framework.verdict` as blocks.

Each sensor against the reference at the default margin: sentences per
machine and scenario, overall and for the ranking, a table of the group
labels, and the critical-difference diagram. The numbers are those ``sdt
compare`` prints for the same folder; a folder that cannot be compared (no
reference run, a single sensor) gets one sentence saying why.
"""

from __future__ import annotations

from pathlib import Path

from ..errors import SDTError
from ..verdict import Comparison, compare, plot_cd_diagram, verdict
from ..verdict.sentences import fmt_delta
from .document import Block, Figure, Heading, Items, Paragraph, Table, code, literal
from .load import ResultsFolder
from .style import save_figure

__all__ = ["CD_FIGURE", "folder_comparison", "missing_reference_note", "verdict_blocks"]

CD_FIGURE = "cd_diagram.png"


def _intro(comparison: Comparison) -> Paragraph:
    return Paragraph(
        f"Each sensor against the reference {code(comparison.baseline)}, runs paired by machine, "
        f"scenario, classifier and repetition, at a margin of ±{comparison.margin:g} Macro F1. "
        "Δ is the sensor's Macro F1 minus the reference's, with its 95 % interval over "
        "repetitions in brackets and, where per-recording counts exist, its 95 % interval "
        "over resampled test recordings (recording CI). **equivalent**: the 95 % intervals "
        "over repetitions and over resampled test recordings both lie inside ±margin; "
        "**worse** / **better**: both lie below −margin / above +margin; otherwise "
        "**inconclusive**, with the reason. `sdt compare` prints the per-cell table and "
        "writes comparison.csv; the statistics are explained in docs/report.md."
    )


def folder_comparison(folder: ResultsFolder, margin: float) -> Comparison:
    """The folder's paired comparison with the reference at ``margin``, computed once.

    The Verdict section and the decision table both show it; its bootstrap is
    the costly part, so the result is kept on the folder.
    """
    if margin not in folder.comparisons:
        folder.comparisons[margin] = compare(
            folder.results,
            folder.reference,
            margin=margin,
            per_recording=folder.per_recording,
            allocation=folder.allocation,
            order=folder.sensors,
        )
    return folder.comparisons[margin]


def missing_reference_note(folder: ResultsFolder) -> str | None:
    """Why the sections measured against the reference are absent, and what to run; or None.

    The verdict and the delta table compare every sensor with the reference; a
    benchmark whose ``--sensors`` left the reference out (or whose reference
    runs all failed) has nothing to compare with. The note says which, and
    suggests commands that exist: the benchmark again with the reference added,
    and ``sdt compare --baseline`` against a sensor the folder does hold.
    """
    reference = folder.reference
    present = [s for s in folder.sensors if s in set(folder.ok["sensor"].dropna())]
    if reference in present:
        return None
    holds = ", ".join(map(literal, present)) if present else "no successful run"
    text = f"Not available: the reference {literal(reference)} "
    if reference in set(folder.results["sensor"].dropna()):
        text += (
            f"has no successful run (every run of it failed), so nothing is compared with it "
            f"(this folder holds {holds}); the failed runs' errors say why"
        )
    else:
        sensors = ",".join([reference, *present])
        command = code(f"sdt benchmark --sensors {sensors} --out NEW_FOLDER")
        text += (
            f"was not among the benchmark's sensors, so nothing is compared with it (this "
            f"folder holds {holds}). For this section, run the benchmark again with the "
            f"reference in --sensors, e.g. {command}"
        )
    if len(present) >= 2:
        text += (
            f"; to compare the sensors here with one of them: "
            f"{code(f'sdt compare {folder.path} --baseline {present[0]}')}"
        )
    return text + "."


def _group_table(comparison: Comparison) -> Table | None:
    table = comparison.table
    groups = table[table["level"] == "group"]
    if groups.empty:
        return None
    keys = comparison.groups
    shown = [
        i for i, k in enumerate(keys) if groups[k].nunique() > 1 or k in ("machine", "scenario")
    ]
    candidates = comparison.candidates
    rows = []
    for key, part in groups.groupby(keys, sort=False):
        key = key if isinstance(key, tuple) else (key,)
        by_candidate = {r.candidate: r for r in part.itertuples()}
        cells = [
            f"**{literal(r.label)}** {fmt_delta(r)}"  # numbers only
            if (r := by_candidate.get(c)) is not None
            else "–"
            for c in candidates
        ]
        rows.append((*(literal(key[i]) for i in shown), *cells))
    note = "Label over all classifiers of the machine and scenario (group rows of comparison.csv)."
    header = (*(literal(keys[i]) for i in shown), *map(literal, candidates))
    return Table(header, tuple(rows), note)


def _cd_figure(comparison: Comparison, colors: dict[str, str], figures_dir: Path) -> Block:
    ranking = comparison.ranking
    assert ranking is not None
    try:
        fig = plot_cd_diagram(ranking, colors, title="Average rank of Macro F1")
        path = save_figure(fig, figures_dir, CD_FIGURE)
    except Exception as exc:  # one broken figure must not lose the rest of the report
        message = f"{type(exc).__name__}: {exc}".splitlines()[0][:300]
        return Paragraph(f"Critical-difference diagram not drawn: {literal(message)}.")
    caption = (
        "Critical-difference diagram (Demšar 2006): average rank of each sensor over the "
        f"{ranking.n_blocks} blocks (1 = best, on the left); sensors joined by a bar are not "
        "significantly different (Nemenyi); the CD bar shows the distance two average ranks "
        "must exceed."
    )
    return Figure(path, caption, "Critical-difference diagram")


def verdict_blocks(
    folder: ResultsFolder, colors: dict[str, str], figures_dir: Path, margin: float = 0.02
) -> list[Block]:
    """The verdict section: heading, how to read it, findings, group table, CD diagram.

    A folder that cannot be compared (no reference run, nothing to pair) gets
    one sentence saying why; an unexpected failure is reported the same way,
    so the rest of the report is still written.
    """
    blocks: list[Block] = [Heading("Verdict", 2)]
    note = missing_reference_note(folder)
    if note is not None:
        return [*blocks, Paragraph(note)]
    try:
        comparison = folder_comparison(folder, margin)
        findings = verdict(comparison)
    except SDTError as exc:
        return [*blocks, Paragraph(f"Not available: {literal(exc)}.")]
    except Exception as exc:  # a failing verdict must not lose the rest of the report
        message = f"{type(exc).__name__}: {exc}".splitlines()[0][:300]
        return [*blocks, Paragraph(f"Not available: the comparison failed ({literal(message)}).")]
    blocks.append(_intro(comparison))
    blocks.append(Items(tuple(f"**{literal(f.scope)}**: {literal(f.text)}" for f in findings)))
    group_table = _group_table(comparison)
    if group_table is not None:
        blocks.append(group_table)
    if comparison.ranking is not None:
        blocks.append(_cd_figure(comparison, colors, figures_dir))
    return blocks
