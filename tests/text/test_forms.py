"""Form evidence (OL 316 boxes) merged into sketches, and agreement with the real company-filed labels."""

from __future__ import annotations

import json
from dataclasses import replace

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import Collision, Environment, Sketch, load_sketches
from txt2sce_ros.text.forms import COLLISION, form_agreement, load_form_labels, merge_form
from txt2sce_ros.text.pdf import FormFields

REPORTS = shared_dir() / "data" / "reports"


def _gold() -> dict[str, Sketch]:
    return {s.report_id: s for s in load_sketches(REPORTS / "dev_gold.jsonl") if isinstance(s, Sketch)}


def test_boxes_fill_only_what_the_narrative_left_unknown() -> None:
    g = _gold()["dmvca-weride-20210629-r190"]  # the narrative says "sunny day" and gives a 2:54 PM clock time
    assert g.environment == Environment(weather="clear", lighting="day", surface="unknown")
    form = FormFields({"weather": ("raining",), "lighting": ("dark-street lights",), "roadway_surface": ("wet",)})
    merged = merge_form(g, form)
    assert merged.environment == Environment(weather="clear", lighting="day", surface="wet")
    assert merge_form(g, None) is g


def test_form_collision_type_only_replaces_other() -> None:
    g = _gold()["dmvca-cruise-20210421-r176"]
    form = FormFields({"type_of_collision": ("head-on",)})
    assert merge_form(g, form).collision == g.collision  # the narrative's rear_end stands
    vague = replace(g, collision=Collision(with_=g.collision.with_, type="other"))
    assert merge_form(vague, form).collision.type == "head_on"


def test_agreement_with_real_form_labels() -> None:
    rows = load_form_labels(REPORTS / "dev_form_labels.jsonl")
    assert len(rows) == 180
    gold = _gold()
    ag = form_agreement(rows, gold)
    # Only reports with a prediction are compared; OL 316 rows carry a collision type, SGO rows do not.
    assert 0 < ag["collision_type"].total <= len(gold)
    assert ag["party_category"].total > 0 and ag["av_movement"].total > 0
    # A prediction that copies the form's own collision type agrees with it on that report.
    row = next(r for r in rows if r["id"] in gold and "ol316" in r
               and r["ol316"]["vehicle_1_av"].get("type_of_collision"))
    filed = COLLISION[row["ol316"]["vehicle_1_av"]["type_of_collision"][0]]
    g = gold[row["id"]]
    copied = replace(g, collision=Collision(with_=g.collision.with_, type=filed))  # type: ignore[arg-type]
    one = form_agreement([row], {g.report_id: copied})["collision_type"]
    assert (one.agree, one.total) == (1, 1)
    other = "broadside" if filed != "broadside" else "rear_end"
    wrong = replace(g, collision=Collision(with_=g.collision.with_, type=other))  # type: ignore[arg-type]
    one = form_agreement([row], {g.report_id: wrong})["collision_type"]
    assert (one.agree, one.total) == (0, 1) and one.disagreements[0][2] == g.report_id
    json.dumps([a.__dict__ for a in ag.values()])  # plain data, printable


def test_sgo_pickup_is_a_car_and_a_stop_before_contact_is_stopped() -> None:
    # sketch.md files pickups under `car`; SGO's "Crash With: Pickup Truck" must not read as a truck. And SGO's
    # "SV Pre-Crash Movement: Stopped" is the movement just before the contact: an AV that travelled, then came to a
    # stop ("ah") and was struck, agrees with it; one still moving ("a") does not.
    g = _gold()["dmvca-weride-20210629-r190"]
    row = {"id": g.report_id, "sgo": {"Crash With": "Pickup Truck", "SV Pre-Crash Movement": "Stopped",
                                      "CP Pre-Crash Movement": "Proceeding Straight"}}
    ag = form_agreement([row], {g.report_id: g})
    assert ag["party_category"].total == 1
    assert ag["party_category"].agree == (g.party(g.collision.with_).category == "car")  # type: ignore[union-attr]
    for start, actions, agrees in (("moving", "ah", True), ("stopped", "", True), ("moving", "al", True),
                                   ("moving", "a", False), ("moving", "ha", False)):
        moved = replace(g, ego=replace(g.ego, start=start, actions=actions))  # type: ignore[arg-type]
        one = form_agreement([row], {g.report_id: moved})["av_movement"]
        assert (one.agree, one.total) == (int(agrees), 1), (start, actions)


def test_sgo_contact_at_the_av_s_rear_wants_the_party_behind() -> None:
    g = _gold()["dmvca-weride-20210629-r190"]  # its collision party is at R5 (ahead, right)
    party = g.party(g.collision.with_)
    assert party is not None and party.position == "R5"
    rear = {"id": g.report_id, "sgo": {"SV Contact Area": ["Rear", "Rear Left"]}}
    front = {"id": g.report_id, "sgo": {"SV Contact Area": ["Front Right"]}}
    mixed = {"id": g.report_id, "sgo": {"SV Contact Area": ["Front Right", "Rear"]}}
    behind = replace(g, npcs=[replace(party, position="R6")])  # type: ignore[arg-type]
    for row, sketch, agrees in ((rear, g, False), (rear, behind, True), (front, g, True), (front, behind, False)):
        one = form_agreement([row], {g.report_id: sketch})["party_front_rear"]
        assert (one.agree, one.total) == (int(agrees), 1)
    assert form_agreement([mixed], {g.report_id: g})["party_front_rear"].total == 0  # no single end: not compared
