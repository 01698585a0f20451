"""Shortcuts the batch player takes for speed give the bits of the plain computation they skip:

- a lane entity standing where its last standing step left it repeats that step (`Entity.still`);
- documents with nothing to substitute skip the parameter walk;
- `syntax.xml.first` / `children` are lxml's `find` / `findall` for plain tag names;
- the contact scan's written-out separating-axis test agrees with the projections as sets of values.
"""

from __future__ import annotations

import math
import random
from pathlib import Path

import pytest
from lxml import etree

import scenario_player.simulation as simulation_module
from scenario_player import Simulation, SimulationConfig, load_scenario
from scenario_player.syntax import document
from scenario_player.syntax.xml import children, first
from scenario_player.world import motion
from scenario_player.world.collision import obb_overlap

from .conftest import xosc

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "scenarios"

# Files with many standing steps: parked and waiting vehicles, a pedestrian, a red light.
STANDING = [xosc("traffic_lights"), xosc("straight_500m"), xosc("drop-bike"), xosc("pedestrian"),
            EXAMPLES / "fault_no_start_when_close.xosc", EXAMPLES / "benign_parked_car.xosc"]


def _run(path: Path, mode: str) -> tuple[dict, str, float]:
    sim = Simulation(load_scenario(path), SimulationConfig(ego_mode=mode, time_limit=20.0))
    status = sim.run()
    return sim.trajectory, status.end_reason, status.t


def test_standing_repeat_gives_the_bits_of_the_lane_walk(esmini, monkeypatch: pytest.MonkeyPatch) -> None:
    repeats = []
    real_repeat = motion._stand_again

    def counting(ent: object, still: tuple, dt: float) -> None:
        repeats.append(1)
        real_repeat(ent, still, dt)     # type: ignore[arg-type]

    monkeypatch.setattr(motion, "_stand_again", counting)
    fast = {(p.name, m): _run(p, m) for p in STANDING for m in ("storyboard", "planner")}
    assert len(repeats) > 2000, "the scenarios stand still often: the repeat must have been taken"

    real_move = simulation_module.move_storyboard

    def never_repeat(world: object, ent: object, *args: object) -> None:
        ent.still = None                # type: ignore[attr-defined]
        real_move(world, ent, *args)    # type: ignore[arg-type]

    monkeypatch.setattr(simulation_module, "move_storyboard", never_repeat)
    repeats.clear()
    for (name, mode), (traj, end, t) in fast.items():
        p = next(f for f in STANDING if f.name == name)
        slow_traj, slow_end, slow_t = _run(p, mode)
        assert (slow_end, slow_t) == (end, t), (name, mode)
        assert slow_traj.keys() == traj.keys()
        for ent in traj:
            assert slow_traj[ent].tobytes() == traj[ent].tobytes(), (name, mode, ent)
    assert not repeats


def test_documents_without_substitutions_resolve_as_walked(esmini, monkeypatch: pytest.MonkeyPatch) -> None:
    files = sorted(EXAMPLES.glob("*.xosc")) + sorted((esmini / "xosc").glob("*.xosc"))
    skipped = 0
    resolved = {}
    for f in files:
        doc = document.resolve_document(f.read_bytes(), source=str(f), base_dir=f.parent)
        skipped += not document._NEEDS_WALK(doc.root)
        resolved[f] = (etree.tostring(doc.root), doc.parameters)
    assert skipped >= 17, "the examples hold no parameter references: their walk is skipped"
    monkeypatch.setattr(document, "_NEEDS_WALK", lambda root: True)
    for f in files:
        doc = document.resolve_document(f.read_bytes(), source=str(f), base_dir=f.parent)
        assert (etree.tostring(doc.root), doc.parameters) == resolved[f], f.name


@pytest.mark.parametrize("text, walk", [
    (b'<OpenSCENARIO><ParameterDeclarations/><Storyboard x="1"/></OpenSCENARIO>', False),
    (b'<OpenSCENARIO><Storyboard x="$a"/></OpenSCENARIO>', True),
    (b'<OpenSCENARIO><Storyboard x="&#36;a"/></OpenSCENARIO>', True),           # a `$` written as a reference
    (b'<OpenSCENARIO><Entities><CatalogReference/></Entities></OpenSCENARIO>', True),
    (b'<OpenSCENARIO><Storyboard><ParameterDeclarations/></Storyboard></OpenSCENARIO>', True),
])
def test_walk_is_skipped_only_with_nothing_to_act_on(text: bytes, walk: bool) -> None:
    assert document._NEEDS_WALK(etree.fromstring(text)) is walk


def test_a_nested_declaration_without_name_is_still_refused() -> None:
    text = (b'<OpenSCENARIO><Storyboard><Story><ParameterDeclarations><ParameterDeclaration value="1"/>'
            b'</ParameterDeclarations></Story></Storyboard></OpenSCENARIO>')
    from txt2sce_ros.errors import InputError

    with pytest.raises(InputError, match="without name"):
        document.resolve_document(text, source="t.xosc", base_dir=Path("."))


def test_first_and_children_are_find_and_findall(esmini) -> None:
    for f in sorted((esmini / "xosc").glob("*.xosc"))[:8] + [EXAMPLES / "benign_parked_car.xosc"]:
        root = etree.parse(str(f)).getroot()
        for el in root.iter():
            if not isinstance(el.tag, str):
                continue
            for tag in {c.tag for c in el if isinstance(c.tag, str)} | {"Missing"}:
                assert first(el, tag) is el.find(tag)
                assert children(el, tag) == el.findall(tag)


def _box(cx: float, cy: float, h: float, length: float, width: float) -> list[tuple[float, float]]:
    c, s = math.cos(h), math.sin(h)
    return [(cx + c * dx - s * dy, cy + s * dx + c * dy)
            for dx, dy in ((length / 2, width / 2), (-length / 2, width / 2), (-length / 2, -width / 2),
                           (length / 2, -width / 2))]


def _overlap_by_sets(a: list, b: list) -> bool:
    """The separating-axis test stated plainly: on the edge normals of both boxes, the projection intervals."""
    for poly in (a, b):
        for i in (0, 1):
            ax, ay = -(poly[i + 1][1] - poly[i][1]), poly[i + 1][0] - poly[i][0]
            pa = sorted(p[0] * ax + p[1] * ay for p in a)
            pb = sorted(p[0] * ax + p[1] * ay for p in b)
            if pa[-1] < pb[0] or pb[-1] < pa[0]:
                return False
    return True


def test_contact_test_agrees_with_the_plain_statement() -> None:
    rng = random.Random(7)
    hits = 0
    for _ in range(4000):
        a = _box(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-4, 4), rng.uniform(0.5, 5), rng.uniform(0.5, 2))
        b = _box(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.choice([0.0, math.pi / 2, rng.uniform(-4, 4)]),
                 rng.uniform(0.5, 5), rng.uniform(0.5, 2))
        got = obb_overlap(a, b)
        assert got == _overlap_by_sets(a, b)
        hits += got
    assert 400 < hits < 3600
    touching = _box(0.0, 0.0, 0.0, 2.0, 2.0), _box(2.0, 0.0, 0.0, 2.0, 2.0)     # edges meet exactly
    assert obb_overlap(*touching)


def _plain_contacts(entities: list) -> list[tuple[str, str]]:
    """Every pair of present entities, corners from `measure.box_corners`, the plain separating-axis statement."""
    from scenario_player.world.measure import box_corners

    live = [e for e in entities if e.present]
    return [(a.name, b.name) for i, a in enumerate(live) for b in live[i + 1:]
            if _overlap_by_sets(box_corners(a), box_corners(b))]


def test_contact_scan_finds_the_pairs_of_the_plain_scan() -> None:
    from scenario_player.world.collision import detect
    from scenario_player.world.entity import Entity
    from scenario_player.world.spec import EntitySpec

    rng = random.Random(11)
    found = 0
    for trial in range(1500):
        ents = []
        for k in range(rng.randint(2, 6)):
            length, width = rng.uniform(0.4, 12.0), rng.uniform(0.4, 3.0)
            spec = EntitySpec(name=f"e{k}", kind="vehicle", category="car", length=length, width=width,
                              height=1.5, center_x=rng.choice([0.0, rng.uniform(-2.0, 3.0)]),
                              center_y=rng.choice([0.0, rng.uniform(-0.5, 0.5)]), max_speed=30.0, max_accel=3.0,
                              max_decel=6.0, wheelbase=2.7, max_steering=0.5)
            e = Entity(spec)
            e.x, e.y = rng.uniform(-15.0, 15.0), rng.uniform(-6.0, 6.0)
            e.h = rng.choice([0.0, math.pi, rng.uniform(-7.0, 7.0)])
            e.present = rng.random() < 0.9
            ents.append(e)
        if trial % 100 == 0:
            ents[0].h = math.nan            # a broken heading: never pruned, as the plain scan never prunes it
        want = _plain_contacts(ents)
        assert detect(ents) == want
        found += len(want)
    assert found > 300


def _first_bad_reference(root: etree._Element, names: set[str]) -> tuple[str, int] | None:
    """The plain statement of the entity-reference check: every element in document order, its attributes in
    the check's order, an empty trailer reference allowed."""
    from scenario_player.syntax.scenario import _ENTITY_ATTRS

    for el in root.iter():
        if not isinstance(el.tag, str):
            continue
        for attr in _ENTITY_ATTRS:
            ref = el.get(attr)
            if el.tag == "TrailerRef" and not ref:
                continue
            if ref is not None and ref not in names:
                return str(el.tag), el.sourceline
    return None


def test_reference_check_refuses_the_first_unknown_reference(esmini) -> None:
    from scenario_player.syntax.scenario import _ENTITY_ATTRS, _check_references
    from scenario_player.syntax.xml import ParseContext
    from txt2sce_ros.errors import InputError

    rng = random.Random(3)
    refused = 0
    for f in sorted((esmini / "xosc").glob("*.xosc")):
        doc = document.resolve_document(f.read_bytes(), source=str(f), base_dir=f.parent)
        holders = [el for el in doc.root.iter() if isinstance(el.tag, str) and any(el.get(a) for a in _ENTITY_ATTRS)]
        names = {o.get("name") for o in doc.root.iter("ScenarioObject")}
        for el in rng.sample(holders, min(2, len(holders))):        # two unknown references, in either order
            el.set(next(a for a in _ENTITY_ATTRS if el.get(a)), f"Ghost{el.sourceline}")
        want = _first_bad_reference(doc.root, names)
        try:
            _check_references(ParseContext(str(f)), doc.root, names)
            got = None
        except InputError as exc:
            got = (exc.element, exc.line)
            refused += 1
        assert got == want, f.name
    assert refused >= 15


def _same(a, b) -> bool:
    """Equal to the bit (repr tells -0.0 from 0.0 and shows NaN), field by field."""
    return repr(a) == repr(b)


def test_bicycle_command_comparisons_answer_as_the_builtins():
    import itertools

    from scenario_player.world.kinematics import G, BicycleResult, bicycle_command

    def plain(v, v_cmd, w_cmd, dt, *, wheelbase, max_steer, max_accel, max_decel, max_speed, friction,
              is_vehicle=True):
        a = (v_cmd - v) / dt
        a = min(max(a, -max_decel if max_decel > 0 else -math.inf), max_accel if max_accel > 0 else math.inf)
        w = w_cmd
        if is_vehicle and abs(v) > 1e-3:
            w_max = abs(v) * math.tan(max_steer) / max(wheelbase, 1e-3)
            w = min(max(w, -w_max), w_max)
        elif is_vehicle:
            w = 0.0
        slipping = False
        if is_vehicle:
            mu_g = max(friction, 0.0) * G
            lat = abs(v * w)
            if lat > mu_g:
                w = math.copysign(mu_g / max(abs(v), 1e-6), w)
                lat = mu_g
            if a > 0.0:
                steer = abs(w_cmd) * max(abs(v), abs(v_cmd), 1.0)
                if math.hypot(a, max(lat, steer)) > mu_g:
                    a = 0.0
                    slipping = True
            elif a < 0.0:
                room = math.sqrt(max(mu_g * mu_g - lat * lat, 0.0))
                a = max(a, -room)
        v_new = v + a * dt
        if v_cmd >= 0.0 and v_new < 0.0 <= v:
            v_new = 0.0
        v_new = min(max(v_new, -max_speed), max_speed) if max_speed > 0 else v_new
        return BicycleResult(v_new, w, (v_new - v) / dt, slipping)

    values = (-3.0, -0.0, 0.0, 0.5, 8.0, 40.0, math.nan)
    n = 0
    for v, v_cmd, w_cmd in itertools.product(values, values, (-0.9, -0.0, 0.0, 0.2, 3.0, math.nan)):
        for kw in (dict(wheelbase=2.8, max_steer=0.6, max_accel=3.0, max_decel=8.0, max_speed=30.0, friction=1.0),
                   dict(wheelbase=0.0, max_steer=0.6, max_accel=0.0, max_decel=0.0, max_speed=0.0, friction=-0.2),
                   dict(wheelbase=2.8, max_steer=0.6, max_accel=3.0, max_decel=8.0, max_speed=30.0, friction=0.1,
                        is_vehicle=False)):
            got = bicycle_command(v, v_cmd, w_cmd, 0.05, **kw)
            assert _same(got, plain(v, v_cmd, w_cmd, 0.05, **kw)), (v, v_cmd, w_cmd, kw)
            n += 1
    assert n == 7 * 7 * 6 * 3
