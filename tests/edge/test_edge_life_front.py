"""What ``sdt explore`` prints of battery life: one row per point, from pareto.csv.

The table is checked against values worked out by hand from a pareto table
written here: the best classifier's rows only, Macro F1 averaged over cells,
the cells where the point is on the front with life counted, longest life first,
and nothing for points without a battery life.
"""

from __future__ import annotations

import math

import pandas as pd

from sdt_framework.explore.output import life_front


def _pareto() -> pd.DataFrame:
    rows = []
    #            point  cost  life  (cell, classifier, macro_f1, on_front_with_life)
    for point, cost, life, cells in [
        ("slow", -1.0, 9.0, [("a", "best", 0.2, True), ("b", "best", 0.4, False)]),
        ("fast", 1.0, 8.0, [("a", "best", 0.6, True), ("b", "best", 0.8, True)]),
        ("nolife", 0.0, math.nan, [("a", "best", 0.9, False), ("b", "best", 0.9, False)]),
    ]:
        for scenario, classifier, f1, front in cells:
            rows.append(
                dict(
                    point=point,
                    machine="M",
                    scenario=scenario,
                    classifier=classifier,
                    macro_f1=f1,
                    cost=cost,
                    battery_life_years=life,
                    on_front_with_life=front,
                )
            )
        # an lr row that must be ignored: only the best classifier is summarised
        rows.append(
            dict(
                point=point,
                machine="M",
                scenario="a",
                classifier="lr",
                macro_f1=0.0,
                cost=cost,
                battery_life_years=life,
                on_front_with_life=True,
            )
        )
    return pd.DataFrame(rows)


def test_life_front_summarises_the_best_classifier_per_point_longest_life_first():
    front = life_front(_pareto())
    assert front["point"].tolist() == ["slow", "fast"]  # 9 years before 8; no life: left out
    slow, fast = front.iloc[0], front.iloc[1]
    assert math.isclose(slow["macro_f1"], (0.2 + 0.4) / 2)
    assert math.isclose(fast["macro_f1"], (0.6 + 0.8) / 2)
    assert (slow["on_front"], slow["cells"]) == (1, 2)
    assert (fast["on_front"], fast["cells"]) == (2, 2)
    assert (slow["cost"], slow["battery_life_years"]) == (-1.0, 9.0)


def test_life_front_is_empty_when_no_point_has_a_battery_life():
    pareto = _pareto()
    pareto["battery_life_years"] = math.nan
    assert life_front(pareto).empty
