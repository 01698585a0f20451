"""Behaviour table, lift ranking and derivation triggers on small constructed campaigns."""

import pytest

from txt2sce_ros.analysis.behaviours import behaviour_table
from txt2sce_ros.analysis.derivation import aggregate, trigger_candidates
from txt2sce_ros.analysis.lift import lift_table, rank_of


def test_lift_ranks_the_element_the_category_depends_on() -> None:
    runs = []
    # Collisions happen in 9 of 10 bicycle runs and in 1 of 30 others; weather is irrelevant noise.
    for i in range(10):
        runs.append((frozenset({"category:bicycle", f"weather:{'rain' if i % 2 else 'clear'}"}),
                     frozenset({"Collisions"} if i < 9 else set())))
    for i in range(30):
        runs.append((frozenset({"category:car", f"weather:{'rain' if i % 2 else 'clear'}"}),
                     frozenset({"Collisions"} if i == 0 else set())))
    table = lift_table(runs, min_support=1)
    top = table["Collisions"][0]
    assert top.element == "category:bicycle"
    assert top.lift == pytest.approx((9 / 10) / (10 / 40))
    assert top.support == 9 and top.with_element == 10
    assert rank_of(table["Collisions"], contains="bicycle") == 1
    assert rank_of(table["Collisions"], contains="truck") is None
    # min_support drops thin evidence.
    assert all(r.support >= 3 for r in lift_table(runs, min_support=3)["Collisions"])


def test_behaviour_table_counts_failures_and_keeps_errors_apart() -> None:
    rows, verdicts = behaviour_table([("fail", ("Collisions", "Smooth")), ("fail", ("Smooth",)), ("pass", ()),
                                      ("error", ())])
    by = {r.category: r for r in rows}
    assert by["Smooth"].count == 2 and by["Collisions"].count == 1 and by["StartFail"].count == 0
    assert by["Smooth"].share_of_behaviours == pytest.approx(2 / 3)
    assert by["Smooth"].share_of_runs == pytest.approx(2 / 3)   # 3 judged runs, the error is not judged
    assert verdicts == {"fail": 2, "pass": 1, "error": 1}


def test_derivation_attributes_new_categories_to_the_added_block() -> None:
    nodes = {
        "n1": {"parent": None, "block": "weather", "operator": "original"},
        "n2": {"parent": "n1", "block": "npc:npc1", "operator": "NCM", "changes": [
            {"path": "Vehicle/@vehicleCategory", "old": "car", "new": "bicycle"}]},
        "n3": {"parent": "n2", "block": "event:npc1_e1_go_straight", "operator": "TSM"},
    }
    results = {"n1": ("pass", ()), "n2": ("fail", ("Collisions",)), "n3": ("fail", ("Collisions", "Smooth"))}
    cands = trigger_candidates(nodes, results)
    assert [(c.node, c.category, c.operator) for c in cands] == [("n2", "Collisions", "NCM"),
                                                                  ("n3", "Smooth", "TSM")]
    assert "car -> bicycle" in cands[0].changes[0]
    assert aggregate(cands) == {"Collisions": [("npc / NCM", 1)], "Smooth": [("event / TSM", 1)]}
