"""The oracle's fast paths must answer exactly as the plain box tests they stand in for (a verdict must not change):
the corridor check `EgoPath.blocker` and `BoxGroup.overlapped_by` against `any(overlaps(...))` box by box, on
boxes placed at random around a curved path (fixed seed), many of them touching or overlapping."""

import math
import random

import numpy as np

from oracle_monitor.egopath import SAMPLE_DS, EgoPath
from oracle_monitor.geometry import Box, BoxGroup, far_apart, footprint, overlaps
from oracle_monitor.unavoidable import _course_clear
from txt2sce_ros.contract import EntityState


def _path() -> EgoPath:
    """A 120 m path that curves left through a quarter circle, one sample per metre."""
    s = np.arange(0.0, 120.0, SAMPLE_DS)
    h = np.minimum(s / 60.0, 1.0) * (0.5 * math.pi)
    x = np.cumsum(np.cos(h)) * SAMPLE_DS + 1000.0
    y = np.cumsum(np.sin(h)) * SAMPLE_DS - 2000.0
    return EgoPath(np.column_stack([x, y, h]), routed=True)


def _entity(name: str, x: float, y: float, heading: float, length: float = 4.5, width: float = 1.9) -> EntityState:
    return EntityState(name=name, category="car", t=0.0, x=x, y=y, heading=heading, speed=0.0, length=length,
                       width=width, center_x=1.3)


def _plain_blocker(path: EgoPath, ego: EntityState, front: tuple[float, float], objects, clear_distance: float,
                   margin: float) -> str:
    """The corridor test written out: a box per path sample, every object against every box."""
    path._s_hint = 0.0
    pts = path.window(path.locate(*front), clear_distance)
    half = 0.5 * ego.width + margin
    boxes = [Box(x, y, math.cos(h), math.sin(h), 0.5 * SAMPLE_DS + 0.05, half) for x, y, h in pts]
    for obj in objects:
        fp = footprint(obj)
        if any(overlaps(b, fp) for b in boxes):
            return obj.name
    return ""


def test_blocker_answers_as_the_plain_box_tests() -> None:
    rng = random.Random(7)
    path = _path()
    found = {"": 0, "hit": 0}
    for trial in range(400):
        k = rng.randrange(0, 100)
        fx, fy = float(path.xyh[k, 0]), float(path.xyh[k, 1])
        ego = _entity("ego", fx, fy, float(path.xyh[k, 2]))
        objects = []
        for j in range(rng.randrange(1, 5)):
            i = min(k + rng.randrange(0, 40), len(path.xyh) - 1)
            # around the corridor's edge: lateral offsets where contact comes and goes
            off = rng.uniform(-5.0, 5.0)
            h = float(path.xyh[i, 2])
            objects.append(_entity(f"o{j}", float(path.xyh[i, 0]) - off * math.sin(h),
                                   float(path.xyh[i, 1]) + off * math.cos(h), h + rng.uniform(-1.5, 1.5),
                                   length=rng.uniform(0.5, 12.0), width=rng.uniform(0.5, 2.6)))
        expected = _plain_blocker(path, ego, (fx, fy), objects, 20.0, 0.3)
        path._s_hint = 0.0
        assert path.blocker(ego, (fx, fy), tuple(objects), clear_distance=20.0, margin=0.3) == expected, trial
        found["hit" if expected else ""] += 1
    assert found["hit"] > 50 and found[""] > 50          # both answers were exercised


def test_box_group_answers_as_any_overlaps() -> None:
    rng = random.Random(11)
    for _ in range(300):
        cx, cy = rng.uniform(-5000, 5000), rng.uniform(-5000, 5000)
        heading = rng.uniform(-0.2, 0.2)
        g = BoxGroup([cx + i * 2.0 for i in range(30)], [cy + rng.uniform(-0.3, 0.3) for _ in range(30)],
                     [heading] * 30, 2.3, 1.0)
        group = [Box(x, y, math.cos(heading), math.sin(heading), 2.3, 1.0) for x, y in zip(g.xs, g.ys)]
        assert g.boxes == group          # the boxes it builds are the boxes it stands for
        for _ in range(20):
            h = rng.uniform(-math.pi, math.pi)
            b = Box(cx + rng.uniform(-10, 70), cy + rng.uniform(-6, 6), math.cos(h), math.sin(h),
                    rng.uniform(0.2, 6.0), rng.uniform(0.2, 1.5))
            assert g.overlapped_by(b) == any(overlaps(a, b) for a in group)


def test_penetrates_answers_as_penetration_above_zero() -> None:
    """`penetrates` (written out, leaving early) against `penetration(a, b) > 0.0`: boxes at random, axis-aligned
    boxes touching edge to edge, boxes with the same centre, and NaN coordinates."""
    from oracle_monitor.geometry import penetrates, penetration

    rng = random.Random(31)
    boxes = []
    for _ in range(3000):
        h = rng.choice([0.0, 0.5 * math.pi, rng.uniform(-math.pi, math.pi)])
        boxes.append(Box(rng.choice([0.0, 1e3, -2e3]) + rng.uniform(-6, 6), rng.uniform(-6, 6), math.cos(h),
                         math.sin(h), rng.uniform(0.2, 5.0), rng.uniform(0.2, 2.0)))
    a = Box(0.0, 0.0, 1.0, 0.0, 2.0, 1.0)
    boxes += [Box(4.0, 0.0, 1.0, 0.0, 2.0, 1.0), Box(0.0, 2.0, 1.0, 0.0, 2.0, 1.0), Box(0.0, 0.0, 1.0, 0.0, 2.0, 1.0),
              Box(math.nan, 0.0, 1.0, 0.0, 2.0, 1.0), Box(0.0, 0.0, math.nan, 0.0, 2.0, 1.0)]
    hits = 0
    for i, b in enumerate(boxes):
        other = boxes[i - 1] if i % 3 else a
        want = penetration(other, b) > 0.0
        assert penetrates(other, *b) == want
        hits += want
    assert 100 < hits < len(boxes) - 300


def test_far_apart_never_skips_an_overlap() -> None:
    rng = random.Random(3)
    for _ in range(20000):
        a = Box(rng.uniform(-3, 3), rng.uniform(-3, 3), 1.0, 0.0, rng.uniform(0.1, 3), rng.uniform(0.1, 3))
        h = rng.uniform(-math.pi, math.pi)
        b = Box(rng.uniform(-6, 6), rng.uniform(-6, 6), math.cos(h), math.sin(h), rng.uniform(0.1, 3),
                rng.uniform(0.1, 3))
        if far_apart(a.cx, a.cy, a.radius, b.cx, b.cy, b.radius):
            assert not overlaps(a, b)


def test_course_clear_only_when_no_position_on_the_course_overlaps() -> None:
    rng = random.Random(5)
    group = BoxGroup([float(i) for i in range(0, 60, 2)], [0.0] * 30, [0.0] * 30, 2.3, 1.0)
    clear = 0
    for _ in range(500):
        h = rng.uniform(-math.pi, math.pi)
        box = Box(rng.uniform(-40, 100), rng.uniform(-60, 60), math.cos(h), math.sin(h), 2.2, 0.9)
        speed = rng.uniform(-2.0, 15.0)
        dx, dy = speed * 5.0 * math.cos(h), speed * 5.0 * math.sin(h)
        if _course_clear(group, box, dx, dy):
            clear += 1
            for k in range(21):
                moved = speed * k * 0.25
                moved_box = box._replace(cx=box.cx + moved * math.cos(h), cy=box.cy + moved * math.sin(h))
                assert not any(overlaps(a, moved_box) for a in group.boxes)
    assert clear > 100


def test_first_overlapped_answers_as_overlapped_by_position_by_position() -> None:
    rng = random.Random(13)
    hits = 0
    for _ in range(200):
        cx, cy = rng.uniform(-3000, 3000), rng.uniform(-3000, 3000)
        hs = [rng.uniform(-0.3, 0.3) for _ in range(31)]
        g = BoxGroup([cx + i * 2.0 for i in range(31)], [cy + rng.uniform(-0.5, 0.5) for _ in range(31)], hs,
                     2.3, 1.0)
        h = rng.uniform(-math.pi, math.pi)
        b = Box(cx + rng.uniform(-10, 70), cy + rng.uniform(-15, 15), math.cos(h), math.sin(h), 2.2, 0.9)
        moved = rng.uniform(0.0, 12.0) * np.arange(21) * 0.25
        cxs, cys = b.cx + moved * b.c, b.cy + moved * b.s
        want = next((t for t in range(21) if g.overlapped_by(b._replace(cx=float(cxs[t]), cy=float(cys[t])))),
                    None)
        assert g.first_overlapped(b, cxs, cys) == want
        hits += want is not None
    assert 20 < hits < 180


def _recorded_run(rng: random.Random) -> "Counterfactual":
    """A counterfactual recorder fed a random run: an ego that drives, creeps (steps far under a micrometre) and
    stands along a wandering course, and parties crossing, following and standing around it, many close to it."""
    from oracle_monitor.unavoidable import Counterfactual
    from txt2sce_ros.contract import Frame

    cf = Counterfactual()
    x, y, h, v = rng.uniform(-3000, 3000), rng.uniform(-3000, 3000), rng.uniform(-math.pi, math.pi), 8.0
    parties = [(f"p{j}", x + rng.uniform(-20, 45), y + rng.uniform(-15, 15), rng.uniform(-math.pi, math.pi),
                rng.uniform(-2.0, 12.0), rng.uniform(0.5, 12.0), rng.uniform(0.5, 2.6)) for j in range(4)]
    for k in range(160):
        t = round(k * 0.05, 9)
        mode = (k // 20) % 4
        step = {0: v * 0.05, 1: rng.uniform(0.0, 5e-7), 2: 0.0, 3: v * 0.05 * rng.uniform(0.2, 1.0)}[mode]
        h += rng.uniform(-0.05, 0.05) if step > 1e-3 else 0.0
        x, y = x + step * math.cos(h), y + step * math.sin(h)
        ego = EntityState(name="ego", category="car", t=t, x=x, y=y, heading=h, speed=step / 0.05, length=4.6,
                          width=1.9, center_x=1.4)
        objects = tuple(EntityState(name=n, category="car", t=t, x=px + sp * t * math.cos(ph),
                                    y=py + sp * t * math.sin(ph), heading=ph, speed=sp, length=ln, width=wd,
                                    center_x=0.4 * ln) for n, px, py, ph, sp, ln, wd in parties)
        cf.observe(Frame(t=t, ego=ego, objects=objects))
    return cf


def _plain_meets(cf, profile, until: float, start: int = 0):
    """`Counterfactual.meets` written out: the braking ego's box at every frame against every party's footprint."""
    if cf.first is None or start >= len(cf.times):
        return None
    t_b, d_b, v_b = cf.times[start], cf.dists[start], cf.ego[start][3]
    brake = profile(v_b)
    for k in range(start, len(cf.times)):
        t, parties = cf.times[k], cf.parties[k]
        if t > until:
            break
        ego = cf._ego_box(d_b + brake(t - t_b))
        for o in parties:
            if overlaps(ego, footprint(o)):
                return o.name, t
    return None


def _plain_foreseeable(cf, name: str, until: float):
    """`Counterfactual.foreseeable` written out: every position of the party's course against every box of the
    path ahead, box by box."""
    from oracle_monitor.unavoidable import AHEAD_STEPS, FORESIGHT, FORESIGHT_DT

    for k in range(0, len(cf.times), 2):
        if cf.times[k] > until:
            return None
        o = next((p for p in cf.parties[k] if p.name == name), None)
        if o is None:
            continue
        boxes = [cf._ego_box(cf.dists[k] + step) for step in AHEAD_STEPS]
        fp = footprint(o)
        for i in range(int(FORESIGHT / FORESIGHT_DT) + 1):
            moved = o.speed * (i * FORESIGHT_DT)
            at = fp._replace(cx=fp.cx + moved * math.cos(o.heading), cy=fp.cy + moved * math.sin(o.heading))
            if any(overlaps(b, at) for b in boxes):
                return k
    return None


def test_stretch_circle_holds_the_ego_box_at_every_distance_in_its_stretch() -> None:
    rng = random.Random(17)
    for _ in range(20):
        cf = _recorded_run(rng)
        for _ in range(40):
            d0 = rng.uniform(0.0, cf.dists[-1] + 5.0)
            d1 = d0 + rng.choice([0.0, rng.uniform(0.0, 1.0), rng.uniform(0.0, 70.0)])
            x, y, r = cf._stretch_circle(d0, d1)
            for i in range(41):
                box = cf._ego_box(d0 + (d1 - d0) * i / 40)
                assert all(math.hypot(px - x, py - y) <= r for px, py in box.corners())


def test_frames_near_keeps_every_frame_with_a_footprint_near_the_circle() -> None:
    """`Counterfactual._frames_near` (the vectorised pre-test of `meets`) leaves out only frames whose every
    footprint is `far_apart` from the circle, and keeps them in order; circles placed to graze the footprints."""
    from oracle_monitor.geometry import far_apart

    rng = random.Random(29)
    kept_and_far = left_out = 0
    for _ in range(15):
        cf = _recorded_run(rng)
        for _ in range(30):
            k0 = rng.randrange(len(cf.times))
            o = rng.choice(cf.parties[k0])
            fp = footprint(o)
            r = rng.uniform(0.5, 40.0)
            # a centre at about the grazing distance from a footprint, give or take a millimetre
            ang, d = rng.uniform(-math.pi, math.pi), fp.radius + r + rng.uniform(-2e-3, 2e-3)
            cx, cy = fp.cx + d * math.cos(ang), fp.cy + d * math.sin(ang)
            start = rng.randrange(len(cf.times))
            end = rng.randrange(start, len(cf.times) + 1)
            got = cf._frames_near(cx, cy, r, start, end)
            assert got == sorted(set(got)) and all(start <= k < end for k in got)
            for k in range(start, end):
                near = not all(far_apart(cx, cy, r, b.cx, b.cy, b.radius) for b in map(footprint, cf.parties[k]))
                if near:
                    assert k in got
                kept_and_far += k in got and not near
                left_out += k not in got
    assert left_out > 1000 and kept_and_far > 0     # it does leave frames out, and only conservatively


def test_ahead_boxes_are_the_ego_boxes_bit_for_bit() -> None:
    """`Counterfactual._ahead(k)` (`_ego_pose` written out, one bisection carried along) holds exactly the boxes
    `_ego_box` gives at each of `AHEAD_STEPS` from frame k: on paths that creep, stand and end within the steps."""
    from oracle_monitor.unavoidable import AHEAD_STEPS

    rng = random.Random(37)
    for _ in range(10):
        cf = _recorded_run(rng)
        for k in sorted({0, len(cf.times) - 1, *rng.sample(range(len(cf.times)), 40)}):
            group = cf._ahead(k)
            for i, step in enumerate(AHEAD_STEPS):
                want = cf._ego_box(cf.dists[k] + step)
                got = group.box(i)
                assert (got.cx, got.cy, got.c, got.s) == (want.cx, want.cy, want.c, want.s), (k, step)


def test_meets_and_foreseeable_answer_as_the_plain_box_tests() -> None:
    from oracle_monitor.unavoidable import emergency_stop, smooth_stop

    rng = random.Random(23)
    answers = {"meets": 0, "foreseen": 0}
    for _ in range(25):
        cf = _recorded_run(rng)
        until = rng.uniform(2.0, 8.5)
        for profile in (lambda v: emergency_stop(v, 8.0), lambda v: smooth_stop(v, 0.9)):
            for start in (0, rng.randrange(0, 160), 159):
                want = _plain_meets(cf, profile, until, start)
                assert cf.meets(profile, until, start=start) == want
                answers["meets"] += want is not None
        for name in sorted({o.name for o in cf.parties[0]}):
            want = _plain_foreseeable(cf, name, until)
            assert cf.foreseeable(name, until) == want
            answers["foreseen"] += want is not None
    assert 10 < answers["meets"] < 140 and 10 < answers["foreseen"] < 90      # both answers were exercised


def _plain_crossing(path: EgoPath, ego: EntityState, front: tuple[float, float], objects, *, distance: float,
                    horizon: float, margin: float, min_speed: float) -> str:
    """`EgoPath.crossing` written out: every mover's whole course against every path sample, no pre-test."""
    from oracle_monitor.egopath import CROSSING_DEG, PREDICT_DT

    path._s_hint = 0.0
    pts = path.window(path.locate(*front), distance)
    taus = np.arange(0.0, horizon + 1e-9, PREDICT_DT)
    for obj in objects:
        if obj.is_static or obj.speed < min_speed:
            continue
        c, s = math.cos(obj.heading), math.sin(obj.heading)
        cx, cy = obj.x + obj.center_x * c, obj.y + obj.center_x * s
        qx, qy = cx + obj.speed * taus * c, cy + obj.speed * taus * s
        d2 = (qx[:, None] - pts[None, :, 0]) ** 2 + (qy[:, None] - pts[None, :, 1]) ** 2
        reach = 0.5 * ego.width + 0.5 * obj.width + margin
        hit = np.argwhere(d2 <= reach * reach)
        if len(hit) and abs(math.sin(obj.heading - float(pts[int(hit[0, 1]), 2]))) >= math.sin(
                math.radians(CROSSING_DEG)):
            return obj.name
    return ""


def test_crossing_with_its_pre_test_answers_as_the_plain_test() -> None:
    # Movers placed around the path, heading every way, many whose course ends just short of or just inside
    # reach of a sample (the pre-test's edge), some far: the answer (who crosses first) must be the plain one's,
    # and the pre-test must never skip a course the plain distance test would find within reach.
    from oracle_monitor.egopath import course_apart

    rng = random.Random(23)
    path = _path()
    answers = {"": 0, "crossing": 0}
    for trial in range(600):
        k = rng.randrange(0, 90)
        fx, fy = float(path.xyh[k, 0]), float(path.xyh[k, 1])
        ego = _entity("ego", fx, fy, float(path.xyh[k, 2]))
        objects = []
        for j in range(4):
            ang = rng.uniform(-math.pi, math.pi)
            dist = rng.choice([rng.uniform(0.0, 30.0), rng.uniform(30.0, 80.0), rng.uniform(80.0, 400.0)])
            x, y = fx + dist * math.cos(ang), fy + dist * math.sin(ang)
            obj = EntityState(name=f"m{j}", category="car", t=0.0, x=x, y=y, heading=rng.uniform(-math.pi, math.pi),
                              speed=rng.choice([0.0, rng.uniform(0.1, 3.0), rng.uniform(3.0, 20.0)]),
                              length=4.5, width=rng.uniform(0.5, 2.6), center_x=1.3)
            objects.append(obj)
        kw = dict(distance=30.0, horizon=4.0, margin=0.5, min_speed=0.5)
        path._s_hint = 0.0
        path._located = None
        got = path.crossing(ego, (fx, fy), tuple(objects), **kw)
        want = _plain_crossing(path, ego, (fx, fy), tuple(objects), **kw)
        assert got == want, trial
        answers["crossing" if want else ""] += 1
    assert answers["crossing"] > 30 and answers[""] > 30
    # The pre-test on its own, at its edge: courses ending just beyond reach + 1 mm, or just within it.
    xs, ys = np.array([0.0, 10.0]), np.array([0.0, 0.0])
    box = (0.0, 10.0, 0.0, 0.0)
    for gap in (1.0, 0.0011, 0.0009, 0.0, -0.5):
        qx = np.array([10.0 + 1.5 + gap, 20.0])
        apart = course_apart(qx, np.zeros(2), box, 1.5)
        d2 = (qx[:, None] - xs[None, :]) ** 2 + (np.zeros(2)[:, None] - ys[None, :]) ** 2
        assert apart == (gap > 0.001)
        assert not (apart and (d2 <= 1.5 * 1.5).any())


def test_contact_oracle_pre_test_finds_every_overlap_the_box_test_finds() -> None:
    """`ContactOracle.observe` skips an object whose reference point is far from the ego's box (its box cannot
    reach it) before building its box: the contacts must be those of testing every box, on objects placed at
    random around the ego (many touching, overlapping, or just clear; large and zero centre offsets), and the
    skip must be what decides most of the far ones."""
    from oracle_monitor.params import OracleParams
    from oracle_monitor.safety import ContactOracle
    from txt2sce_ros.contract import Frame

    rng = random.Random(12)
    params = OracleParams.from_config().safety
    found = skipped = 0
    for k in range(400):
        ego = EntityState(name="ego", category="car", t=0.0, x=500.0 + rng.uniform(-5, 5), y=-300.0,
                          heading=rng.uniform(-math.pi, math.pi), speed=5.0, length=4.6, width=1.9, center_x=1.4)
        objs = []
        for i in range(6):
            d = rng.choice([rng.uniform(0.0, 6.0), rng.uniform(4.0, 9.0), rng.uniform(9.0, 40.0)])
            a = rng.uniform(-math.pi, math.pi)
            objs.append(EntityState(name=f"o{i}", category="car", t=0.0, x=ego.x + d * math.cos(a),
                                    y=ego.y + d * math.sin(a), heading=rng.uniform(-math.pi, math.pi), speed=0.0,
                                    length=rng.choice([0.5, 4.5, 12.0]), width=rng.choice([0.5, 1.9, 2.6]),
                                    center_x=rng.choice([0.0, 1.3, 5.0, -2.0])))
        oracle = ContactOracle(params)
        got = {c.entity.name for c in oracle.observe(Frame(t=0.0, ego=ego, objects=tuple(objs), lights=()))}
        ego_box = footprint(ego)
        want = {o.name for o in objs if overlaps(ego_box, footprint(o))}
        assert got == want, k
        found += len(want)
        for o in objs:
            r = ego_box.radius + 1e-3 + math.hypot(0.5 * o.length, 0.5 * o.width) + abs(o.center_x)
            skipped += (o.x - ego_box.cx) ** 2 + (o.y - ego_box.cy) ** 2 > r * r
    assert found > 300 and skipped > 800


def test_planned_path_is_remembered_by_network_and_exact_poses() -> None:
    """`EgoPath.plan` remembers its samples (read-only) by network and the bits of the ego's and goal's poses:
    asked again it answers with the samples planning afresh gives, as a path of its own; another pose, another
    goal or -0.0 for 0.0 is planned anew."""
    from oracle_monitor import egopath
    from txt2sce_ros.contract import Goal
    from txt2sce_ros.road import load_network

    from .oracle_runs import esmini_map

    net = load_network(esmini_map("fabriksgatan.xodr"))
    ref = next(net.lane_ref(r.id, -1, 0.0) for r in net.roads.values() if r.junction in ("-1", "")
               and -1 in r.sections[0].lanes)
    pts = net.lane_centerline(ref.road_id, ref.lane_id, 0.5, section=ref.section)
    h = math.atan2(pts[3, 1] - pts[2, 1], pts[3, 0] - pts[2, 0])
    ego = _entity("ego", float(pts[2, 0]), float(pts[2, 1]), h)
    goal = Goal(float(pts[-3, 0]), float(pts[-3, 1]), h)
    egopath._PLANNED.clear()
    first = egopath.EgoPath.plan(net, ego, goal)
    again = egopath.EgoPath.plan(net, ego, goal)
    fresh = egopath.EgoPath._plan(net, ego, goal)
    assert first.routed and again is not first and again.xyh.tobytes() == fresh.xyh.tobytes()
    assert again.s.tobytes() == fresh.s.tobytes() and len(egopath._PLANNED) == 1
    assert not again.xyh.flags.writeable
    moved = _entity("ego", float(pts[6, 0]), float(pts[6, 1]), h)
    assert egopath.EgoPath.plan(net, moved, goal).xyh.tobytes() == egopath.EgoPath._plan(net, moved, goal).xyh.tobytes()
    near = Goal(float(pts[-9, 0]), float(pts[-9, 1]), h)
    assert egopath.EgoPath.plan(net, ego, near).xyh.tobytes() == egopath.EgoPath._plan(net, ego, near).xyh.tobytes()
    assert len(egopath._PLANNED) == 3
    zero = _entity("ego", float(pts[2, 0]), float(pts[2, 1]), 0.0)
    egopath.EgoPath.plan(net, zero, goal)
    egopath.EgoPath.plan(net, _entity("ego", float(pts[2, 0]), float(pts[2, 1]), -0.0), goal)
    assert len(egopath._PLANNED) == 5
