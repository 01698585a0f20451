"""δ and α: blocks found by tag and name, round trip α(δ(seed)) == seed (canonical XML)."""

from __future__ import annotations

import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.tree import BlockKind, assemble, canonical, disassemble

from .conftest import CUT_IN, JUNCTION


def test_blocks_of_the_junction_seed_in_insertion_order(junction_bytes):
    d = disassemble(junction_bytes, source=str(JUNCTION), new_obstacle_slots=1)
    got = [(b.kind, b.key, len(b.slots)) for b in d.blocks]
    assert got == [
        (BlockKind.EGO, "ego", 2),                  # Init Private + the StopTrigger's goal condition
        (BlockKind.WEATHER, "environment", 1),
        (BlockKind.SIGNAL, "signal_ctrl_4", 4),      # an Init GlobalAction per light + the signal Story
        (BlockKind.NPC, "npc1", 2),                 # ScenarioObject + Init Private
        (BlockKind.EVENT, "npc1_e1_go_straight", 1),
        (BlockKind.EVENT, "npc1_e2_turn_left", 1),
        (BlockKind.OBSTACLE, "obs1", 2),
        (BlockKind.NEW_OBSTACLE, "obs2", 2),        # first free obstacle name
    ]
    assert d.blocks[0].fragments[1].startswith('<Condition name="ego_goal_reached"')
    assert d.blocks[1].fragments[0].startswith("<Environment name=\"environment\">")
    assert d.blocks[3].fragments[1].startswith("<Private entityRef=\"npc1\">")
    assert d.blocks[-1].fragments == ("", "")
    assert d.blocks[2].fragments[-1].startswith('<Story name="signal_ctrl_4">')
    assert all(f.startswith("<GlobalAction>") for f in d.blocks[2].fragments[:-1])
    # the template keeps everything else: the ego's ScenarioObject and the story skeleton
    text = "".join(d.template.pieces)
    assert '<ScenarioObject name="ego">' in text and "<Maneuver name=\"npc1_maneuver\">" in text
    assert "<Event " not in text and "<Environment " not in text


@pytest.mark.parametrize("path", [JUNCTION, CUT_IN])
def test_round_trip_of_fixture_seeds(path):
    data = path.read_bytes()
    d = disassemble(data, source=str(path), new_obstacle_slots=2)
    assert canonical(assemble(d.template, d.originals())) == canonical(data)


def test_round_trip_of_every_esmini_example():
    """δ works on any OpenSCENARIO file, not only ours: the 18 third-party examples survive the round trip."""
    files = sorted((shared_dir() / "data" / "conformance" / "esmini" / "xosc").glob("*.xosc"))
    assert len(files) >= 18
    n_events = 0
    for f in files:
        data = f.read_bytes()
        d = disassemble(data, source=str(f), new_obstacle_slots=1)
        n_events += sum(b.kind is BlockKind.EVENT for b in d.blocks)
        assert canonical(assemble(d.template, d.originals())) == canonical(data), f.name
    assert n_events > 18


def test_changing_one_block_changes_only_that_block(junction_bytes):
    d = disassemble(junction_bytes, source="j")
    frags = d.originals()
    ev = next(b for b in d.blocks if b.key == "npc1_e1_go_straight")
    frags[ev.slots[0]] = ev.fragments[0].replace('<AbsoluteTargetSpeed value="6.0"/>',
                                                 '<AbsoluteTargetSpeed value="7.5"/>')
    out = assemble(d.template, frags)
    assert out.count('value="7.5"') == 1
    assert canonical(out) != canonical(junction_bytes)


def test_bad_input_names_the_file():
    with pytest.raises(InputError, match="bad.xosc"):
        disassemble(b"<OpenSCENARIO><Entities>", source="bad.xosc")
    with pytest.raises(InputError, match="not <OpenSCENARIO>"):
        disassemble(b"<OpenDRIVE/>", source="map.xodr")
