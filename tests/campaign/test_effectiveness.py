"""The effectiveness study: differential attribution (fault vs nominal) and the study on real seeds."""

from __future__ import annotations

import json
from pathlib import Path

from txt2sce_ros.campaign.effectiveness import FAULTS, StudyConfig, assess, pick_seeds, run_study
from txt2sce_ros.campaign.store import ResultStore

from .conftest import TIME_LIMIT


def test_assess_counts_only_what_the_fault_added() -> None:
    spec = next(f for f in FAULTS if f.name == "ignore_cyclists")
    elements = {f"s{i}": frozenset({"category:bicycle" if i < 4 else "category:car", "weather:clear"})
                for i in range(10)}
    nominal = {f"s{i}": frozenset({"Collisions"} if i == 9 else ()) for i in range(10)}
    # the fault adds collisions in three bicycle scenarios; s9 collided anyway (not the fault's doing)
    faulty = {f"s{i}": frozenset({"Collisions"} if i in (0, 1, 2, 9) else ()) for i in range(10)}
    row, lift = assess(spec, nominal, faulty, elements)
    assert row.found and row.differential == 3
    assert (row.runs_with_fault, row.runs_nominal) == (4, 1)
    assert row.right_rank == 1 and row.top_trigger.startswith("category:bicycle")
    assert lift[0].support == 3 and lift[0].with_element == 4
    # nothing added: not found, no ranking
    row, lift = assess(spec, nominal, nominal, elements)
    assert not row.found and row.right_rank is None and lift == []


def test_pick_seeds_covers_new_elements_first(seed_files: list[Path]) -> None:
    picked = pick_seeds(seed_files, 3)
    assert len(picked) == 3 and len(set(picked)) == 3
    assert pick_seeds(seed_files, 3) == picked                     # deterministic
    assert pick_seeds(list(reversed(seed_files)), 3) == picked      # independent of input order


def test_study_shares_nominal_runs_and_writes_the_table(seed_dir: Path, tmp_path: Path) -> None:
    faults = ("ignore_cyclists", "no_start_when_close")
    cfg = StudyConfig(out=tmp_path / "study", seeds=2, nodes=6, time_limit=TIME_LIMIT, faults=faults,
                      workers=2, progress=False)
    rows = run_study([seed_dir], cfg)
    assert [r.fault for r in rows] == list(faults)
    data = json.loads((tmp_path / "study" / "effectiveness.json").read_text(encoding="utf-8"))
    n = data["scenarios"]
    assert n > 2 and len(data["seeds"]) == 2
    with ResultStore(tmp_path / "study" / "results.sqlite") as store:
        # one nominal set, one set per fault, except the ignore_cyclists runs of scenarios without a cyclist (the
        # fault cannot act there: the nominal verdict stands for them), which a 6-node tree always has
        assert n * len(faults) <= store.count() < n * (1 + len(faults))
    for r in rows:
        assert r.found == (r.differential > 0)
        assert r.differential <= r.runs_with_fault
        assert r.right_rank is None or r.right_rank >= 1
    table = (tmp_path / "study" / "effectiveness.txt").read_text(encoding="utf-8")
    assert all(f in table for f in faults)
    # resumed: nothing reruns, the same rows come back
    assert run_study([seed_dir], cfg) == rows


def test_a_combined_element_names_the_triggers_of_its_parts() -> None:
    from txt2sce_ros.campaign.effectiveness import names_trigger

    stale = next(f for f in FAULTS if f.name == "stale_tracking")
    assert names_trigger("R5+m", stale.triggers) and names_trigger("R6+ah", stale.triggers)   # events:ah
    assert names_trigger("position:R5/same", stale.triggers)
    assert not names_trigger("R2+a", stale.triggers) and not names_trigger("weather:rain", stale.triggers)
    cyclists = next(f for f in FAULTS if f.name == "ignore_cyclists")
    assert not names_trigger("R5+m", cyclists.triggers)
    # a joint condition (elements in exactly the same runs) names what any of its parts names
    close = next(f for f in FAULTS if f.name == "no_start_when_close")
    assert names_trigger("category:car & near_start:yes", close.triggers)
    assert names_trigger("R3+m & category:pedestrian", stale.triggers)
    assert not names_trigger("category:car & position:R6", close.triggers)


def test_the_ranking_leaves_party_counts_out_and_shrinks_thin_evidence() -> None:
    """Within a tree the party count changes only when the new-party slot adds a party, whatever its role: a
    cyclist added to a one-party seed makes `npcs:2` as surely as `category:bicycle`, and the count is not what
    the fault depends on. Two scenarios that happen to share the fog are not ranked above the bicycle either."""
    spec = next(f for f in FAULTS if f.name == "ignore_cyclists")
    elements, trees = {}, {}
    for i in range(12):
        cyclist = i < 6                                     # the new party: a cyclist in 6 nodes, nobody in 6
        elements[f"t/n{i}"] = frozenset({"npcs:2", "category:bicycle"} if cyclist else {"npcs:1"}) | \
            {"weather:fog" if i in (0, 1) else "weather:clear"} | ({"category:car"} if i == 11 else set())
        trees[f"t/n{i}"] = "t"
    nominal = {i: frozenset() for i in elements}
    faulty = {i: frozenset({"Collisions"} if i in ("t/n0", "t/n1", "t/n2", "t/n3", "t/n4") else ()) for i in elements}
    row, lift = assess(spec, nominal, faulty, elements, min_support=2, trees=trees)
    assert row.right_rank == 1 and lift[0].element == "category:bicycle"
    assert not any(r.element.startswith("npcs:") for r in lift)
    assert {r.element: r.lift for r in lift}["weather:fog"] > lift[0].lift      # higher lift, thinner evidence


def test_draws_are_seeded_random_subsets(seed_files: list[Path]) -> None:
    from txt2sce_ros.campaign.effectiveness import draw_seeds

    draws = draw_seeds(seed_files, 3, 4, draw_seed=7)
    assert len(draws) == 4 and all(len(d) == 3 and len(set(d)) == 3 for d in draws)
    assert all(set(d) <= set(seed_files) for d in draws)
    assert draw_seeds(list(reversed(seed_files)), 3, 4, draw_seed=7) == draws     # listing order does not matter
    assert len({tuple(d) for d in draws}) > 1                                     # draws differ from each other
    assert draw_seeds(seed_files, 3, 4, draw_seed=8) != draws                     # and with the draw seed


def test_draws_from_no_more_seeds_than_a_draw_takes_are_flagged(tmp_path: Path, capsys) -> None:
    # Every draw would be the same study: the user is told instead of being shown k identical results as k draws.
    from txt2sce_ros.campaign.effectiveness import _chosen_seeds

    seeds = tmp_path / "seeds"
    seeds.mkdir()
    (seeds / "manifest.json").write_text(json.dumps({"built": [{"file": "a.xosc"}, {"file": "b.xosc"}]}))
    draws = _chosen_seeds(seeds, StudyConfig(out=tmp_path / "study", seeds=10, draws=3))
    assert len(draws) == 3 and all(len(d) == 2 for d in draws)
    assert "2 seed(s) built, not more than --seeds 10" in capsys.readouterr().err
    _chosen_seeds(seeds, StudyConfig(out=tmp_path / "study2", seeds=1, draws=3))
    assert "warning" not in capsys.readouterr().err


def test_study_over_draws_assesses_each_draw_on_its_own_trees(seed_dir: Path, tmp_path: Path) -> None:
    from txt2sce_ros.campaign.effectiveness import format_draws, run_draws

    cfg = StudyConfig(out=tmp_path / "draws", seeds=1, nodes=4, time_limit=TIME_LIMIT,
                      faults=("no_start_when_close",), workers=2, progress=False, draws=3, draw_seed=1)
    draws = run_draws([seed_dir], cfg)
    assert [d.index for d in draws] == [0, 1, 2] and all(len(d.seeds) == 1 for d in draws)
    data = json.loads((tmp_path / "draws" / "effectiveness.json").read_text(encoding="utf-8"))
    assert [d["seeds"] for d in data["draws"]] == [list(d.seeds) for d in draws]
    # each draw counts only the scenarios of its own seed's tree
    trees = {p.name for p in (tmp_path / "draws" / "trees").iterdir() if p.is_dir()}
    assert trees == {Path(s).stem for d in draws for s in d.seeds}
    for d, entry in zip(draws, data["draws"]):
        tree = tmp_path / "draws" / "trees" / Path(d.seeds[0]).stem
        assert entry["scenarios"] == len(list((tree / "nodes").glob("*.xosc")))
    text = format_draws(draws)
    assert text.splitlines()[-2].startswith("min") and text.splitlines()[-1].startswith("med")
    assert run_draws([seed_dir], cfg) == draws                                    # resumed: same results


def test_format_draws_prints_min_and_median() -> None:
    from txt2sce_ros.campaign.effectiveness import DrawResult, EffectivenessRow, format_draws

    def row(found: bool, rank: int | None) -> EffectivenessRow:
        return EffectivenessRow("f", "Collisions", found, 1, 0, int(found), "-", rank)

    draws = [DrawResult(0, ("a",), (row(True, 1), row(True, 2))), DrawResult(1, ("b",), (row(False, None),
             row(True, None))), DrawResult(2, ("c",), (row(True, 1), row(True, 1)))]
    lines = format_draws(draws).splitlines()
    assert lines[2].split()[1:3] == ["2/2", "1/2"] and lines[2].endswith("1 2")
    assert lines[3].endswith("- x")
    assert lines[-2].split()[1:3] == ["1/2", "0/2"]            # min found, min right-first
    assert lines[-1].split()[1:3] == ["2/2", "1/2"]            # medians


def test_assess_within_trees_ranks_what_the_mutations_changed() -> None:
    """Tree `a` (4 scenarios) grew from a seed with a party turning across (`R1+d`) in all of them; trees b-d
    (8 scenarios each) from seeds without one. The fault acts on a yellow light, which a mutation brings into two
    scenarios of every tree. Across all scenarios, the rare `R1+d` rides along with tree `a`'s differential runs
    and outranks the yellow; within trees it never varies and says nothing, and the yellow comes first."""
    spec = next(f for f in FAULTS if f.name == "red_light_misread")
    elements, trees = {}, {}
    for t, n, seed_own in (("a", 4, {"R1+d"}), ("b", 8, set()), ("c", 8, set()), ("d", 8, set())):
        for i in range(n):
            sid = f"{t}/n{i}"
            trees[sid] = t
            elements[sid] = frozenset(seed_own | {"signal:yellow" if i < 2 else "signal:green"})
    nominal = {i: frozenset() for i in elements}
    # the fault shows in both yellow scenarios of `a`, in one of `b`'s
    faulty = {i: frozenset({"Misinterp"} if i in ("a/n0", "a/n1", "b/n0") else ()) for i in elements}
    row, lift = assess(spec, nominal, faulty, elements, min_support=1, prior=0.0)
    assert row.right_rank == 2 and lift[0].element == "R1+d"           # pooled: the seed's own element first
    row, lift = assess(spec, nominal, faulty, elements, min_support=1, trees=trees, prior=0.0)
    assert row.right_rank == 1 and lift[0].element == "signal:yellow"
    assert "R1+d" not in {r.element for r in lift}                      # constant within its tree: not ranked
    # O/E within trees: 3 observed; expected 2 * 2/4 (tree a) + 2 * 1/8 (tree b), c and d showed nothing
    assert lift[0].support == 3 and abs(lift[0].lift - 3 / 1.25) < 1e-9


def test_table_keeps_the_rank_column_aligned_under_a_long_joint_trigger() -> None:
    from txt2sce_ros.campaign.effectiveness import EffectivenessRow, format_table

    joint = "near_start:yes & position:R6 & position:R6/same (1.34×)"
    lines = format_table([EffectivenessRow("no_start_when_close", "StartFail", True, 5, 0, 5, joint, 1),
                          EffectivenessRow("ignore_cyclists", "Collisions", True, 9, 2, 7,
                                           "category:bicycle (2.97×)", 2)]).splitlines()
    assert joint in lines[2]
    # every line (header, rule, rows) ends at the same column, the rank right-aligned in it
    assert len({len(line) for line in lines}) == 1
    assert lines[2].endswith(" 1") and lines[3].endswith(" 2") and lines[0].endswith("right rank")
