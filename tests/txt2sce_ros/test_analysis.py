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


# --- scenario elements read from real seeds (dev-gold sketches -> seeds), positions derived on their maps ---------

import itertools  # noqa: E402
import math  # noqa: E402
from pathlib import Path  # noqa: E402

from txt2sce_ros.analysis.features import derived_position, elements_of_file, scenario_elements  # noqa: E402
from txt2sce_ros.paths import shared_dir  # noqa: E402


@pytest.fixture(scope="module")
def gold_seeds(tmp_path_factory: pytest.TempPathFactory) -> dict[str, tuple[Path, dict]]:
    import json

    from txt2sce_ros.seed import write_seeds
    from txt2sce_ros.sketch import load_sketches

    gold = shared_dir() / "data" / "reports" / "dev_gold.jsonl"
    out = tmp_path_factory.mktemp("seeds")
    write_seeds(itertools.islice(load_sketches(gold), 8), out, seed=0)
    sketches = {}
    with gold.open(encoding="utf-8") as fh:
        for line in itertools.islice(fh, 8):
            d = json.loads(line)
            sketches[d["report_id"]] = d
    return {p.stem: (p, sketches[p.stem]) for p in sorted(out.glob("*.xosc"))}


def test_elements_of_real_seeds_match_their_sketches(gold_seeds: dict[str, tuple[Path, dict]]) -> None:
    checked = 0
    for rid, (path, sketch) in gold_seeds.items():
        elems = elements_of_file(str(path))
        assert f"npcs:{len(sketch['npcs'])}" in elems
        assert ("obstacle:yes" in elems) == bool(sketch["obstacles"])
        for npc in sketch["npcs"]:
            assert f"category:{npc['category']}" in elems
            assert f"events:{npc['actions']}" in elems
        expected_signal = sketch["signal_state"] if sketch["signal_state"] in ("red", "yellow", "green") else "none"
        assert f"signal:{expected_signal}" in elems
        # derived positions agree with the labelled ones for parties that move along a lane (a crossing party,
        # actions 'm', starts across the road: its heading says R1/R3 whatever side of the road it stands)
        for npc in sketch["npcs"]:
            if npc["actions"] != "m":
                assert f"position:{npc['position']}" in elems, (rid, npc, sorted(elems))
                checked += 1
    assert checked >= 3


def test_derived_position_follows_the_sketch_definitions() -> None:
    ego = (0.0, 0.0, 0.0)                                   # heading +x
    assert derived_position(ego, (10.0, 0.0, 0.0)) == ("R5", "same")
    assert derived_position(ego, (-10.0, 3.5, 0.0)) == ("R6", "left")
    assert derived_position(ego, (30.0, 3.5, math.pi)) == ("R7", "left")
    assert derived_position(ego, (40.0, 30.0, -math.pi / 2)) == ("R1", None)   # comes from the left, heading right
    assert derived_position(ego, (40.0, -30.0, math.pi / 2)) == ("R3", None)


def test_near_start_is_a_bumper_gap_as_close_as_the_start_refusal_acts() -> None:
    """`near_start` is measured between footprints (a long vehicle is no closer than a short one at the same gap),
    and a party within the tree's start spacing (6 m) counts; a party farther off does not."""
    from txt2sce_ros.analysis.features import NEAR_START_GAP, start_gap

    ego, car = (-1.0, 3.5), (-1.0, 3.5)                      # (rear, front) from the reference point
    bus = (-6.0, 6.0)
    # a car whose rear bumper is 5 m ahead of the ego's front: centres 9.5 m apart, beyond the old 8 m radius
    assert start_gap((0.0, 0.0, 0.0), ego, (9.5, 0.0, 0.0), car) == pytest.approx(5.0)
    assert start_gap((0.0, 0.0, 0.0), ego, (9.5, 0.0, 0.0), car) <= NEAR_START_GAP
    assert start_gap((0.0, 0.0, 0.0), ego, (12.0, 0.0, 0.0), car) > NEAR_START_GAP
    # behind: a bus whose front is 2 m behind the ego's rear bumper, heading the other way round the circle
    assert start_gap((0.0, 0.0, math.pi), ego, (9.0, 0.0, math.pi), bus) == pytest.approx(2.0)


def test_written_position_wins_and_weather_is_read(gold_seeds: dict[str, tuple[Path, dict]]) -> None:
    path, _ = gold_seeds["dmvca-apple-20211111-r241"]
    xml = path.read_bytes()
    written = b'<Property name="txt2sce:position" value="R6"/>'
    assert written in xml                                        # the seed writes the report's reading
    without = xml.replace(written, b"")
    other = xml.replace(written, b'<Property name="txt2sce:position" value="R2"/>')
    from txt2sce_ros.road import load_network
    from txt2sce_ros.scenario_source import logic_file

    net = load_network(str(logic_file(path, xml)))
    assert "position:R6" in scenario_elements(without, net)      # derived on the map when not written
    assert "position:R2" in scenario_elements(other, net)        # a written one wins over the derived one
    assert "position:R6" not in scenario_elements(other, net)
    rainy = xml.replace(b'precipitationType="dry" intensity="0.0"', b'precipitationType="rain" intensity="0.8"')
    assert "weather:rain" in scenario_elements(rainy) and "weather:clear" in scenario_elements(xml)


def test_stratified_lift_counts_a_constant_stratum_as_no_evidence() -> None:
    """One mutation adds a car close behind the AV (`category:car` and `near_start:yes` together) in each tree, but
    tree `b`'s seed has a car in every run: there the car shows the category exactly as often as expected (O = E),
    so it earns nothing and its lift is pulled towards 1, while near_start, which varies in both trees, is not."""
    runs, strata = [], []
    for t in ("a", "b"):
        for i in range(6):
            added = {"category:car", "near_start:yes"} if i < 2 else set()
            own = {"category:car"} if t == "b" else set()
            runs.append((frozenset(added | own | {f"weather:{'rain' if i % 2 else 'clear'}"}),
                         frozenset({"StartFail"} if i < 2 else ())))
            strata.append(t)
    rows = lift_table(runs, min_support=1, strata=strata)["StartFail"]
    by = {r.element: r for r in rows}
    assert by["near_start:yes"].lift == pytest.approx(3.0)              # 4 observed, 4/3 expected
    assert by["category:car"].lift == pytest.approx(6 / 4)              # tree b adds 2 to O and to E
    assert by["category:car"].support == 4 and by["category:car"].with_element == 8
    assert rows[0].element == "near_start:yes"
    # measured only where it varies (the old rule), the car tied with near_start on tree a alone
    assert by["category:car"].lift < by["near_start:yes"].lift
    # an element constant in every stratum is not ranked
    const = [(e | {"map:x"}, c) for e, c in runs]
    assert "map:x" not in {r.element for r in lift_table(const, min_support=1, strata=strata)["StartFail"]}
    with pytest.raises(ValueError):
        lift_table(runs, strata=strata[:-1])


def test_elements_in_exactly_the_same_runs_are_one_joint_condition() -> None:
    """No count can tell apart elements that occur in exactly the same runs (one mutation adds them together), so
    they are one row, parts sorted, rather than one of them winning the tie on its name."""
    from txt2sce_ros.analysis.lift import joint_parts

    runs = []
    for i in range(8):
        close = i < 3
        added = {"near_start:yes", "position:R6", "position:R6/same"} if close else set()
        runs.append((frozenset(added | {"weather:clear" if i % 2 else "weather:rain"}),
                     frozenset({"StartFail"} if close else ())))
    rows = lift_table(runs, min_support=1)["StartFail"]
    assert rows[0].element == "near_start:yes & position:R6 & position:R6/same"
    assert joint_parts(rows[0].element) == ["near_start:yes", "position:R6", "position:R6/same"]
    assert rows[0].support == 3 and rows[0].lift == pytest.approx(8 / 3)
    # one run that holds position:R6 without the others splits them again
    runs.append((frozenset({"position:R6", "weather:clear"}), frozenset()))
    elements = {r.element for r in lift_table(runs, min_support=1)["StartFail"]}
    assert {"position:R6", "near_start:yes & position:R6/same"} <= elements


def test_prior_ranks_many_runs_above_two_that_happen_to_share_an_element() -> None:
    """Shrunk by one pseudo-run, (O + 1) / (E + 1): two runs at 3× rank below twelve at 2×; without it the two
    runs win. The reported lift stays O / E."""
    runs = []
    for i in range(36):
        shown = frozenset({"Collisions"}) if i < 12 else frozenset()
        common = {"category:bicycle"} if i < 12 or 24 <= i < 30 else set()   # 12 of 18 runs with it show it
        rare = {"weather:fog"} if i in (0, 1) else set()                     # both of its 2 runs show it
        runs.append((frozenset(common | rare), shown))
    plain = lift_table(runs, min_support=2)["Collisions"]
    shrunk = lift_table(runs, min_support=2, prior=1.0)["Collisions"]
    assert plain[0].element == "weather:fog" and plain[0].lift == pytest.approx(3.0)
    assert shrunk[0].element == "category:bicycle" and shrunk[0].lift == pytest.approx(2.0)
    assert shrunk[0].score == pytest.approx((12 + 1) / (6 + 1))
    assert {r.element: r.lift for r in shrunk}["weather:fog"] == pytest.approx(3.0)


def test_elements_of_files_on_a_pool_answers_as_file_by_file(gold_seeds: dict[str, tuple[Path, dict]],
                                                            monkeypatch: pytest.MonkeyPatch) -> None:
    """The report reads many files' elements on forked workers: each file's elements as `elements_of_file` gives
    them in this process, by path, repeated paths once."""
    import txt2sce_ros.analysis.features as features

    paths = [str(p) for p, _ in gold_seeds.values()] * 3
    want = {p: elements_of_file(p) for p in paths}
    monkeypatch.setattr(features, "PARALLEL_FILES", 2)
    elements_of_file.cache_clear()       # the workers must read the files, not inherit answers
    got = features.elements_of_files(paths, workers=2)
    assert got == want and list(got) == list(dict.fromkeys(paths))
    assert elements_of_file.cache_info().currsize == 0      # read on the pool, not here
    assert features.elements_of_files(paths, workers=1) == want
    with features.ElementsReading(paths, workers=2) as reading:     # begun now, answered later
        assert reading._pool is not None
        assert reading.result() == want and reading.result() == want and reading._pool is None
    with features.ElementsReading(paths, workers=1) as reading:
        assert reading._pool is None and reading.result() == want


def _plain_elements_of_file(path: str) -> frozenset[str]:
    """`elements_of_file` as written before it parsed each file once: the map's name, the signals and the elements
    each from their own parse."""
    from txt2sce_ros.road import load_network
    from txt2sce_ros.scenario_source import logic_file
    from txt2sce_ros.seed.context import build_context
    from txt2sce_ros.xosc.schema import parse_document

    data = Path(path).read_bytes()
    net, facing = None, ()
    try:
        xodr = logic_file(Path(path), data)
        if xodr is not None and xodr.is_file():
            net = load_network(str(xodr))
            if b"TrafficSignalController" in data or b"TrafficSignalStateAction" in data:
                facing = build_context(parse_document(data, source=path), source=path, seed_path=Path(path)).ego_signals
    except Exception:
        pass
    return scenario_elements(data, net, facing)


def test_elements_of_file_parsed_once_answers_as_parsed_per_step(gold_seeds: dict[str, tuple[Path, dict]],
                                                                 tmp_path: Path) -> None:
    from txt2sce_ros.errors import InputError

    # (the gold seeds name no light: `tests/tree/test_new_signal.py` compares nodes with a signal plan)
    for path, _ in gold_seeds.values():
        elements_of_file.cache_clear()
        assert elements_of_file(str(path)) == _plain_elements_of_file(str(path))
    # a map that is not there, and a file that is not XML: as before
    moved = tmp_path / "elsewhere.xosc"
    moved.write_bytes(next(iter(gold_seeds.values()))[0].read_bytes())
    assert elements_of_file(str(moved)) == _plain_elements_of_file(str(moved))
    broken = tmp_path / "broken.xosc"
    broken.write_bytes(b"<OpenSCENARIO><FileHeader")
    with pytest.raises(InputError) as want:
        _plain_elements_of_file(str(broken))
    with pytest.raises(InputError) as got:
        elements_of_file(str(broken))
    assert str(got.value) == str(want.value)
