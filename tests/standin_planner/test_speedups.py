"""The planner's fast paths must give bit-identical results to the plain formulas they replaced (the closed loop's
commands must not change by a single bit): each is compared with `==` against the straightforward form, on the
bundled maps' real lanes."""

import math
from collections.abc import Iterator

import numpy as np
import pytest

from standin_planner.params import PlannerParams
from standin_planner.pure_pursuit import curve_speed, curve_speed_profile, curve_targets
from standin_planner.refline import PathPoint, RefLine
from standin_planner.route import lane_widths
from txt2sce_ros.paths import BUNDLED_MAPS
from txt2sce_ros.road import load_network

from .helpers import FABRIKSGATAN

MAPS = sorted(BUNDLED_MAPS.glob("*.xodr")) + [FABRIKSGATAN]


def _lanes(net):
    """(road id, lane id, section index) of every driving lane of every section."""
    for rid, road in net.roads.items():
        for si, sec in enumerate(road.sections):
            for lid, lane in sec.lanes.items():
                if lid != 0 and lane.type == "driving":
                    yield rid, lid, si


def _lines(path) -> list[RefLine]:
    net = load_network(path)
    lines = []
    for rid, lid, si in _lanes(net):
        pts = net.lane_centerline(rid, lid, 0.5, section=si)
        if len(pts) >= 4:
            lines.append(RefLine(pts[:, :2]))
    return lines


@pytest.mark.parametrize("path", MAPS, ids=lambda p: p.stem)
def test_array_lane_widths_equal_the_scalar_lane_width_bit_for_bit(path):
    net = load_network(path)
    checked = 0
    for rid, lid, si in _lanes(net):
        s = net.lane_centerline(rid, lid, 0.5, section=si)[:, 2]
        fast = lane_widths(net, rid, lid, s)
        plain = np.array([net.lane_width(rid, lid, float(v)) for v in s])
        assert fast.tobytes() == plain.tobytes(), (rid, lid, si)
        checked += 1
    assert checked > 0


def _plain_project(line: RefLine, x: float, y: float, near_s: float | None = None, window: float = 60.0
                   ) -> PathPoint:
    """RefLine.project as first written (np.searchsorted / np.clip, no caches)."""
    def index(s):
        return int(np.clip(np.searchsorted(line.s, s, side="right") - 1, 0, len(line._seg) - 1))

    lo, hi = 0, len(line._seg)
    if near_s is not None:
        lo = max(0, index(near_s - window))
        hi = min(len(line._seg), index(near_s + window) + 1)
    p0, d = line.xy[lo:hi], line._seg[lo:hi]
    L2 = np.maximum(line._seg_len[lo:hi] ** 2, 1e-12)
    u = np.clip(((x - p0[:, 0]) * d[:, 0] + (y - p0[:, 1]) * d[:, 1]) / L2, 0.0, 1.0)
    px, py = p0[:, 0] + u * d[:, 0], p0[:, 1] + u * d[:, 1]
    j = int(np.argmin((x - px) ** 2 + (y - py) ** 2))
    i = lo + j
    h = float(line._seg_heading[i])
    s = float(line.s[i] + u[j] * line._seg_len[i])
    if i == len(line._seg) - 1 and u[j] >= 1.0 or i == 0 and u[j] <= 0.0:
        ref_x, ref_y = line.xy[i] if u[j] <= 0.0 else line.xy[i + 1]
        along = (x - ref_x) * math.cos(h) + (y - ref_y) * math.sin(h)
        s = float(line.s[i] if u[j] <= 0.0 else line.s[i + 1]) + along
    cross = -(x - px[j]) * math.sin(h) + (y - py[j]) * math.cos(h)
    return PathPoint(s=s, offset=float(cross), heading=h)


@pytest.mark.parametrize("path", [BUNDLED_MAPS / "roundabout.xodr", BUNDLED_MAPS / "curve.xodr", FABRIKSGATAN],
                         ids=lambda p: p.stem)
def test_projection_equals_the_plain_formula_bit_for_bit(path):
    rng = np.random.default_rng(7)
    for line in _lines(path)[:12]:
        for _ in range(25):
            # Points around the line and beyond both ends (the straight extension), sometimes with a hint.
            s = rng.uniform(-15.0, line.length + 15.0)
            x, y, _ = line.position(s, rng.normal(0.0, 3.0))
            near = float(rng.uniform(0.0, line.length)) if rng.random() < 0.5 else None
            want = _plain_project(line, x, y, near_s=near)
            assert line.project(x, y, near_s=near) == want
            assert line.project(x, y, near_s=near) == want           # the memo returns the same answer
            assert line._index(s) == int(np.clip(np.searchsorted(line.s, s, side="right") - 1, 0,
                                                  len(line._seg) - 1))


def test_projection_memo_does_not_answer_a_different_question():
    line = _lines(BUNDLED_MAPS / "curve.xodr")[0]
    x, y, _ = line.position(20.0, 1.0)
    a = line.project(x, y)
    b = line.project(x + 5.0, y)
    assert b != a and line.project(x, y) == a
    assert line.project(x, y, near_s=20.0, window=5.0) == _plain_project(line, x, y, near_s=20.0, window=5.0)
    # A window that excludes the nearest stretch gets its own answer, not the remembered whole-line one.
    far = line.project(x, y, near_s=line.length - 3.0, window=2.0)
    assert far == _plain_project(line, x, y, near_s=line.length - 3.0, window=2.0) and far.s != a.s
    # Many distinct points (the memo forgets when full) still get their own answers.
    for k in range(600):
        px, py, _ = line.position(0.1 * k, 0.5)
        assert line.project(px, py) == _plain_project(line, px, py)


@pytest.mark.parametrize("path", [BUNDLED_MAPS / "roundabout.xodr", BUNDLED_MAPS / "curve.xodr", FABRIKSGATAN],
                         ids=lambda p: p.stem)
def test_curve_targets_equal_the_per_sample_curve_speed_bit_for_bit(path):
    p = PlannerParams.from_config().lateral
    found = 0
    for line in _lines(path):
        prof = curve_speed_profile(line, p)
        assert prof == [curve_speed(k, p) for k in line.curvature]
        for s_ego in np.linspace(-5.0, line.length + 5.0, 9):
            for v, v_max in ((0.0, 13.9), (8.0, 13.9), (15.0, 30.0)):
                want = []
                for s, k in line.max_abs_curvature(s_ego - 2.0, s_ego + max(p.curve_preview,
                                                                            v * v / 6.0 + 3.0 * v + 5.0)):
                    vc = curve_speed(k, p)
                    if vc < v_max:
                        want.append((max(s - s_ego, 0.0), vc))
                got = curve_targets(line, float(s_ego), v, v_max, p, 3.0)
                assert got == want
                found += len(got)
    assert found > 0        # the maps' curves do limit the speed somewhere


def _plain_project_many(line: RefLine, xs: np.ndarray, ys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """RefLine.project_many as first written (strided views, np.clip)."""
    xs, ys = np.asarray(xs, dtype=float)[:, None], np.asarray(ys, dtype=float)[:, None]
    p0, d = line.xy[:-1][None, :, :], line._seg[None, :, :]
    L2 = np.maximum(line._seg_len ** 2, 1e-12)[None, :]
    u = np.clip(((xs - p0[..., 0]) * d[..., 0] + (ys - p0[..., 1]) * d[..., 1]) / L2, 0.0, 1.0)
    px, py = p0[..., 0] + u * d[..., 0], p0[..., 1] + u * d[..., 1]
    j = np.argmin((xs - px) ** 2 + (ys - py) ** 2, axis=1)
    rows = np.arange(len(j))
    h = line._seg_heading[j]
    s = line.s[j] + u[rows, j] * line._seg_len[j]
    off = -(xs[:, 0] - px[rows, j]) * np.sin(h) + (ys[:, 0] - py[rows, j]) * np.cos(h)
    return s, off


def test_project_many_equals_the_plain_formula_bit_for_bit():
    rng = np.random.default_rng(11)
    for line in _lines(BUNDLED_MAPS / "roundabout.xodr")[:8]:
        pts = np.array([line.position(s, o)[:2] for s, o in zip(rng.uniform(-10.0, line.length + 10.0, 40),
                                                                 rng.normal(0.0, 4.0, 40))])
        s, off = line.project_many(pts[:, 0], pts[:, 1])
        ws, woff = _plain_project_many(line, pts[:, 0], pts[:, 1])
        assert s.tobytes() == ws.tobytes() and off.tobytes() == woff.tobytes()


def _long_lines() -> list[RefLine]:
    """Lines long enough for project_many's chunk pruning: the esmini junction's 300 m approaches, and a loop that
    passes near itself (two turns of a slowly widening circle), where candidate chunks are far apart."""
    lines = [line for line in _lines(FABRIKSGATAN) if len(line.s) > 400]
    a = np.linspace(0.0, 4.0 * math.pi, 1200)
    r = 40.0 + 0.3 * a
    lines.append(RefLine(np.stack([r * np.cos(a), r * np.sin(a)], axis=1)))
    return lines


def test_project_many_with_chunk_pruning_equals_the_plain_formula_bit_for_bit():
    rng = np.random.default_rng(5)
    lines = _long_lines()
    assert len(lines) >= 2
    pruned = 0
    for line in lines:
        for _ in range(20):
            # A predicted path: a straight run of 31 points from somewhere near the line, in some direction.
            x, y, _ = line.position(rng.uniform(-20.0, line.length + 20.0), rng.normal(0.0, 6.0))
            h = rng.uniform(-math.pi, math.pi)
            xs, ys = x + np.arange(31) * 0.6 * math.cos(h), y + np.arange(31) * 0.6 * math.sin(h)
            pruned += line._candidate_segments(xs[:, None], ys[:, None]) is not None
            s, off = line.project_many(xs, ys)
            ws, woff = _plain_project_many(line, xs, ys)
            assert s.tobytes() == ws.tobytes() and off.tobytes() == woff.tobytes()
    assert pruned > 20           # the pruned path is the one exercised


def _points_around_kinked_lines(rng: np.random.Generator) -> Iterator[tuple[RefLine, float, float]]:
    """(line, x, y): 60 points around each of six roundabout lanes, the long lines and a line with a sharp kink,
    beyond both ends and up to ~25 m beside them."""
    kink = RefLine(np.array([[0.0, 0.0], [20.0, 0.0], [20.5, 0.0], [30.0, 9.0], [60.0, 9.0]]))
    for line in _lines(BUNDLED_MAPS / "roundabout.xodr")[:6] + _long_lines() + [kink]:
        for _ in range(60):
            x, y, _ = line.position(rng.uniform(-25.0, line.length + 25.0), rng.normal(0.0, 8.0))
            yield line, x, y


def test_far_from_never_rules_out_a_point_the_projection_would_find_near():
    """`far_from` lets the yield rule skip a mover's projection: it may say True only when no predicted point has
    |offset| < reach with s inside the window, on lanes, a self-approaching loop, and a line with a sharp kink,
    with points around both ends and beside the line."""
    rng = np.random.default_rng(3)
    said_far = near = ruled_out = partly = 0
    for line, x, y in _points_around_kinked_lines(rng):
        h = rng.uniform(-math.pi, math.pi)
        xs, ys = x + np.arange(33) * 0.5 * math.cos(h), y + np.arange(33) * 0.5 * math.sin(h)
        reach = float(rng.uniform(1.0, 4.0))
        s0 = float(rng.uniform(-10.0, line.length))
        s1 = s0 + 81.0
        s, off = line.project_many(xs, ys)
        hits = (np.abs(off) < reach) & (s > s0) & (s < s1)
        hit = bool(hits.any())
        far = line.far_from(xs, ys, reach, s0, s1)
        assert not (far and hit), (s0, reach)
        said_far += far
        near += hit
        # Point by point: a point ruled out is never a hit, and projecting only the others finds the same hits.
        far_points = line.far_points(xs, ys, reach, s0, s1)
        if far_points is not None:
            assert not (far_points & hits).any()
            assert far == bool(far_points.all())
            rows = np.flatnonzero(~far_points)
            ruled_out += len(xs) - len(rows)
            if len(rows):
                rs, roff = line.project_many(xs[rows], ys[rows])
                assert rs.tobytes() == s[rows].tobytes() and roff.tobytes() == off[rows].tobytes()
                partly += 0 < len(rows) < len(xs)
    assert said_far > 50 and near > 50           # both answers are exercised
    assert ruled_out > 1000 and partly > 50      # and courses partly ruled out


def test_projection_through_remembered_cells_equals_the_plain_formula_bit_for_bit():
    """`project` searches only the segments a point's cell can have nearest when they all lie in the window: an
    ego-like track along each line (points 0.3 m apart, so cells are met again), points off to the side, on lane
    lines, the self-approaching loop and a line far from the origin; the cell path must answer as the plain
    window search, and must be the path taken for most of them."""
    rng = np.random.default_rng(9)
    far = RefLine(np.stack([np.linspace(0.0, 300.0, 601) + 35000.0, 8.0 * np.sin(np.linspace(0.0, 6.0, 601))
                            - 12000.0], axis=1))
    lines = _lines(BUNDLED_MAPS / "roundabout.xodr")[:6] + _long_lines() + [far]
    searched = total = 0
    for line in lines:
        for s in np.arange(-5.0, line.length + 5.0, 0.3):
            x, y, _ = line.position(float(s), float(rng.normal(0.0, 2.5)))
            near = float(s) if rng.random() < 0.7 else None
            window = float(rng.choice([5.0, 60.0, 150.0]))
            cand = line._candidates(x, y)
            searched += cand is not None
            total += 1
            line._projections.clear()
            assert line.project(x, y, near_s=near, window=window) == _plain_project(line, x, y, near_s=near,
                                                                                    window=window), (s, near)
    assert searched > 0.8 * total


def test_far_from_straight_never_rules_out_a_course_the_projection_would_find_near():
    """The yield rule tests a straight course as one piece (`far_from_straight`) before computing its points: it
    may say True only when none of the course's points (as `predict` places them) is near the path ahead."""
    from standin_planner.behaviour import predict
    from txt2sce_ros.contract import EntityState

    rng = np.random.default_rng(4)
    said_far = near = 0
    for line, x, y in _points_around_kinked_lines(rng):
        o = EntityState(name="o", category="car", t=0.0, x=x, y=y, heading=rng.uniform(-math.pi, math.pi),
                        speed=float(rng.choice([0.5, 2.0, 8.0])), length=4.5, width=1.9, center_x=1.3)
        traj = predict(o, 8.0, 0.25)
        reach = float(rng.uniform(1.0, 4.0))
        s0 = float(rng.uniform(-10.0, line.length))
        s, off = line.project_many(traj[:, 1], traj[:, 2])
        hit = bool(((np.abs(off) < reach) & (s > s0) & (s < s0 + 81.0)).any())
        c, sn = math.cos(o.heading), math.sin(o.heading)
        ax, ay = o.x + o.center_x * c, o.y + o.center_x * sn
        run = o.speed * (8.0 + 1e-9)
        far = line.far_from_straight(ax, ay, ax + run * c, ay + run * sn, reach, s0, s0 + 81.0)
        assert not (far and hit)
        assert far == line.far_from(traj[:, 1], traj[:, 2], reach, s0, s0 + 81.0) or not far
        said_far += far
        near += hit
    assert said_far > 50 and near > 50


def _chunk_loop_far_from_straight(line: RefLine, ax: float, ay: float, bx: float, by: float, reach: float,
                                  s0: float, s1: float) -> bool:
    """`far_from_straight` as written before its one-circle first test: every live chunk tested in turn."""
    import bisect

    from standin_planner.refline import CHUNK_SLACK, _affine_interval

    cs0, cs1, cxs, cys, crs, inv_cos = line._chunk_lists
    slack = 2.0 * CHUNK_SLACK
    k_lo = bisect.bisect_right(cs1, s0 - CHUNK_SLACK)
    k_hi = bisect.bisect_left(cs0, s1 + CHUNK_SLACK)
    if k_lo >= k_hi:
        return True
    vx, vy = bx - ax, by - ay
    v2 = vx * vx + vy * vy
    for k in range(k_lo, k_hi):
        if inv_cos[k] == math.inf:
            return False
        cx, cy = cxs[k], cys[k]
        t = 0.0 if v2 == 0.0 else min(max(((cx - ax) * vx + (cy - ay) * vy) / v2, 0.0), 1.0)
        if not math.hypot(cx - (ax + t * vx), cy - (ay + t * vy)) - crs[k] > reach * inv_cos[k] * (1.0 + 1e-9) + slack:
            return False
    for end, seg, sign, is_live in ((0, 0, -1.0, k_lo == 0), (len(line.xy) - 1, line._last_seg, 1.0,
                                                             k_hi == len(cs0))):
        if not is_live:
            continue
        h = float(line._seg_heading[seg])
        c, s = math.cos(h), math.sin(h)
        ex, ey = float(line.xy[end, 0]), float(line.xy[end, 1])
        along = [sign * ((px - ex) * c + (py - ey) * s) for px, py in ((ax, ay), (bx, by))]
        across = [(py - ey) * c - (px - ex) * s for px, py in ((ax, ay), (bx, by))]
        a_lo, a_hi = _affine_interval(along[0], along[1], -slack, math.inf)
        c_lo, c_hi = _affine_interval(across[0], across[1], -(reach + slack), reach + slack)
        if max(a_lo, c_lo) <= min(a_hi, c_hi):
            return False
    return True


def test_far_from_straight_first_circle_answers_as_the_chunk_loop():
    """`far_from_straight` first tests the piece against one circle holding all live chunks' circles: its answer
    must be the chunk loop's for every piece (clear of the path, grazing it at every distance, crossing it), on
    lanes, the self-approaching loop, a line far from the origin and the kinked line; and the circle must settle
    most clear pieces by itself."""
    rng = np.random.default_rng(11)
    offset = RefLine(np.stack([np.linspace(0.0, 300.0, 601) + 35000.0, 8.0 * np.sin(np.linspace(0.0, 6.0, 601))
                               - 12000.0], axis=1))
    cases = list(_points_around_kinked_lines(rng))
    cases += [(offset, *offset.position(float(rng.uniform(-25.0, 325.0)), float(rng.normal(0.0, 30.0)))[:2])
              for _ in range(200)]
    clear = settled = 0
    for line, x, y in cases:
        for _ in range(5):
            h = float(rng.uniform(-math.pi, math.pi))
            run = float(rng.choice([0.0, 2.0, 20.0, 70.0]))
            reach = float(rng.uniform(1.0, 12.0))
            s0 = float(rng.uniform(-10.0, line.length))
            args = (x, y, x + run * math.cos(h), y + run * math.sin(h), reach, s0, s0 + 81.0)
            want = _chunk_loop_far_from_straight(line, *args)
            assert line.far_from_straight(*args) == want, args
            if want:
                clear += 1
                group = line._chunk_group(*_live_range(line, s0, s0 + 81.0))
                gx, gy, gr, worst = group
                settled += _piece_distance(*args[:4], gx, gy) - gr > reach * worst * (1.0 + 1e-9) + 2e-6
    assert clear > 300 and settled > 0.5 * clear


def _live_range(line: RefLine, s0: float, s1: float) -> tuple[int, int]:
    import bisect

    from standin_planner.refline import CHUNK_SLACK

    return (bisect.bisect_right(line._chunk_lists[1], s0 - CHUNK_SLACK),
            bisect.bisect_left(line._chunk_lists[0], s1 + CHUNK_SLACK))


def _piece_distance(ax: float, ay: float, bx: float, by: float, px: float, py: float) -> float:
    vx, vy = bx - ax, by - ay
    v2 = vx * vx + vy * vy
    t = 0.0 if v2 == 0.0 else min(max(((px - ax) * vx + (py - ay) * vy) / v2, 0.0), 1.0)
    return math.hypot(px - (ax + t * vx), py - (ay + t * vy))


def test_chunk_group_circle_holds_every_chunk_circle():
    for line in _lines(BUNDLED_MAPS / "roundabout.xodr")[:6] + _long_lines():
        n = len(line._chunk_r)
        for k_lo in range(n):
            for k_hi in range(k_lo + 1, min(n, k_lo + 12) + 1):
                group = line._chunk_group(k_lo, k_hi)
                if group is None:
                    assert np.isinf(line._chunk_inv_cos[k_lo:k_hi]).any()
                    continue
                gx, gy, gr, worst = group
                for k in range(k_lo, k_hi):
                    d = math.hypot(line._chunk_x[k] - gx, line._chunk_y[k] - gy) + line._chunk_r[k]
                    assert d + 1e-7 <= gr
                    assert line._chunk_inv_cos[k] <= worst


def test_turns_across_memo_answers_as_the_plain_formula():
    """`turns_across` remembers its answers by (heading, segments, threshold): asked again, or asked something
    else (another heading, stretch or threshold), it answers as the formula does."""
    line = _lines(BUNDLED_MAPS / "roundabout.xodr")[0]
    rng = np.random.default_rng(2)

    def plain(h: float, s0: float, s1: float, m: float) -> bool:
        i0, i1 = line._index(s0), line._index(s1)
        return bool(np.any(np.abs(np.sin(line._seg_heading[i0:i1 + 1] - h)) >= m))

    answers = set()
    for _ in range(3000):
        h = float(rng.choice([0.0, -0.0, 1.0, float(rng.uniform(-math.pi, math.pi))]))
        s0 = float(rng.uniform(-5.0, line.length))
        s1 = s0 + float(rng.choice([1.0, 10.0, 80.0]))
        m = float(rng.choice([0.2, 0.42, 0.9]))
        got = line.turns_across(h, s0, s1, m)
        assert got == plain(h, s0, s1, m), (h, s0, s1, m)
        answers.add(got)
    assert answers == {True, False}
    assert 0 < len(line._turns) <= 256


def test_standing_object_measure_memo_equals_the_plain_measurement():
    """`measure` remembers a standing object's measurement per line: the answer for a later frame (another t,
    another state object) must be the plain one bit for bit, for the same object and for others at the same
    place with another heading, size or centre; a moving object, or one at speed -0.0, is measured afresh."""
    import dataclasses

    from standin_planner.behaviour import _MEASURED, _measure, measure
    from txt2sce_ros.contract import EntityState

    line = _lines(BUNDLED_MAPS / "roundabout.xodr")[0]
    fresh = _lines(BUNDLED_MAPS / "roundabout.xodr")[0]          # the same line with nothing remembered
    rng = np.random.default_rng(6)
    base = []
    for k in range(40):
        x, y, h = line.position(float(rng.uniform(0.0, line.length)), float(rng.normal(0.0, 3.0)))
        base.append(EntityState(name=f"o{k}", category="obstacle", t=0.0, x=x, y=y, heading=h + 0.3, speed=0.0,
                                length=4.0, width=1.8, center_x=1.2, is_static=True))
    for t in range(6):
        for o in base:
            for variant in (o, dataclasses.replace(o, heading=o.heading + 0.5), dataclasses.replace(o, width=2.5),
                            dataclasses.replace(o, center_x=0.0), dataclasses.replace(o, speed=-0.0),
                            dataclasses.replace(o, speed=1.5)):
                v = dataclasses.replace(variant, t=0.05 * t)
                near = float(rng.choice([0.0, 40.0, line.length]))
                got = measure(v, line, near)
                want = _measure(v, fresh, near)
                assert got == want and got.state is v
                assert repr([got.v_along, got.offset, got.rel_heading]) == repr([want.v_along, want.offset,
                                                                                 want.rel_heading])
    memo = line.cache[_MEASURED]
    assert 0 < len(memo) <= 256
    assert all(key[0] != 0.0 for key in memo)


def test_width_and_neighbour_room_memos_answer_as_the_plain_lookups():
    """`width_at` and `neighbour_room` remember their answers by the exact arc lengths asked (a static obstacle's
    pass asks the same every step): asked again or asked anew, beyond the ends and with a NaN bound, they answer
    as the plain interpolation and mask do."""
    rng = np.random.default_rng(8)
    lines = _lines(BUNDLED_MAPS / "roundabout.xodr")[:3]
    ramp = np.linspace(3.0, 4.0, 200)
    lines.append(RefLine(np.stack([np.linspace(0.0, 100.0, 200), np.zeros(200)], axis=1), lane_width=ramp,
                         room_left=np.where(np.arange(200) < 120, 3.5, 0.0), room_right=ramp - 1.0))
    for line in lines:
        asked = [float(v) for v in rng.uniform(-20.0, line.length + 20.0, 60)] + [0.0, -0.0, float("nan")]
        for _ in range(3):
            for s in asked + [float(v) for v in rng.uniform(0.0, line.length, 20)]:
                want_w = float(np.interp(s, line.s, line.lane_width))
                assert repr(line.width_at(s)) == repr(want_w)
                for s1 in (s + 10.0, s + 0.01, s - 1.0):
                    mask = (line.s >= s) & (line.s <= s1)
                    want = ((float(line.room_left[mask].min()), float(line.room_right[mask].min())) if mask.any()
                            else (float(np.interp(s, line.s, line.room_left)),
                                  float(np.interp(s, line.s, line.room_right))))
                    assert repr(line.neighbour_room(s, s1)) == repr(want), (s, s1)
        assert 0 < len(line._widths) <= 256 and 0 < len(line._rooms) <= 256


# --- min/max written as comparisons ----------------------------------------------------------------------------

_SPECIAL = (-math.inf, -7.5, -1.0, -0.05, -0.0, 0.0, 1e-3, 0.04, 0.7, 1.0, 2.5, 30.0, math.inf, math.nan)


def _same(a, b) -> bool:
    """Equal to the bit (repr tells -0.0 from 0.0 and shows NaN), element by element for tuples."""
    return repr(a) == repr(b)


def test_comparisons_answer_as_the_builtin_min_and_max():
    """The hot functions write min(max(x, lo), hi) as `b if b > a else a` / `b if b < a else a`: the values the
    builtins give, NaN and signed zeros included (the originals, kept here, against the rewritten functions)."""
    from standin_planner import idm
    from standin_planner.params import LongitudinalParams

    lp = LongitudinalParams()

    def free_road(v, v0, p):
        if v0 <= 0.0:
            return -p.comfort_decel if v > 0.0 else 0.0
        return p.max_accel * (1.0 - (max(v, 0.0) / v0) ** p.accel_exponent)

    def plain_stop(v, distance, p, *, plan_decel, cruise, lag=0.0, braking=False, hold=True):
        if distance <= 0.05:
            if v <= 0.0:
                return min(0.0, cruise)
            return -p.max_decel if v > 1.0 else -max(p.comfort_decel, v * v / 0.1)
        need = v * v / (2.0 * max(distance - min(lag, 0.5 * distance), 0.05))
        onset = p.stop_onset_ratio * plan_decel
        if need >= onset or (braking and v > 0.0 and (need >= 0.3 * onset or distance < idm.CREEP_ZONE)):
            return -need
        if hold and v < 0.1 and distance < idm.HOLD_ZONE:
            return min(cruise, 0.0)
        v_cap = math.sqrt(2.0 * onset * max(distance - lag - idm.CREEP_ZONE / 3.0, 0.0))
        if v >= v_cap:
            return min(cruise, 0.0)
        return cruise

    checked = 0
    for v in _SPECIAL:
        for other in _SPECIAL:
            if other > 0.0:
                assert _same(idm.free_road_accel(v, other, lp), free_road(v, other, lp))
            assert _same(idm.braking_decel(lp, other), min(lp.planned_stop_decel,
                                                             lp.friction_safety * other * lp.gravity))
            for lag in (0.0, -0.0, 0.3, 4.0, math.inf, math.nan):
                for plan_decel, braking in ((1e-15, True), (2.0, False), (2.0, True)):
                    kw = dict(plan_decel=plan_decel, cruise=0.5, lag=lag, braking=braking)
                    assert _same(idm.stop_accel(v, other, lp, **kw), plain_stop(v, other, lp, **kw)), (v, other, kw)
                    checked += 1
    assert checked > 3000


def test_planner_limits_answer_as_the_builtins():
    """`Planner._limit`, `_build_up` and `_braking_model` (min/max as comparisons) against their plain forms."""
    from standin_planner.planner import Planner

    planner = Planner(None, None)  # type: ignore[arg-type]
    c, lp = planner.params.comfort, planner.params.longitudinal

    def plain_limit(accel, a_des, v, dt, urgent, max_decel):
        if v < 0.05 and accel < 0.0:
            accel = 0.0
        jerk = c.emergency_jerk if urgent else c.max_jerk
        a = min(max(a_des, accel - jerk * dt), accel + c.max_jerk * dt)
        a = min(max(a, -max_decel), lp.max_accel)
        if a < 0.0 and not urgent:
            a = max(a, -math.sqrt(2.0 * c.max_jerk * max(v, 0.0)) - c.max_jerk * dt)
        if v + a * dt < 0.0:
            a = -v / dt
        return a

    n = 0
    for accel in (-4.0, -0.0, 0.0, 0.3, 2.0):
        for a_des in _SPECIAL:
            for v in (-0.0, 0.0, 0.01, 0.3, 6.0, 25.0):
                for urgent in (False, True):
                    for max_decel in (0.0, 3.0, 9.0):
                        planner._accel = accel
                        got = planner._limit(a_des, v, 0.05, urgent=urgent, max_decel=max_decel)
                        assert _same(got, plain_limit(accel, a_des, v, 0.05, urgent, max_decel))
                        assert _same(planner._accel, got)
                        n += 1
            for decel in _SPECIAL:
                planner._accel = accel
                assert _same(planner._build_up(a_des, decel, 2.0), 0.5 * a_des * max(0.0, decel + accel) / 2.0)
    for friction in (-0.5, -0.0, 0.0, 0.2, 1.0, 3.0, math.inf, math.nan):
        planner.road_friction = friction
        b = planner._braking_model(5.0)
        assert _same(b.idm_decel, min(lp.comfort_decel, lp.friction_safety * friction * lp.gravity))
        assert _same(b.max_decel, min(lp.max_decel, friction * lp.gravity))
    assert n > 1000


def test_index_clamps_as_min_max_did():
    for line in _lines(BUNDLED_MAPS / "curve.xodr")[:2]:
        for s in (-math.inf, -5.0, -0.0, 0.0, 0.25, line.length / 2, line.length, line.length + 3.0, math.inf,
                  math.nan) + tuple(float(v) for v in line.s[:5]):
            want = min(max(int(np.searchsorted(line.s, s, side="right")) - 1, 0), len(line._seg) - 1)
            assert line._index(s) == want
            lo, hi = line.window(s, 20.0) if s == s else (None, None)
            if lo is not None:
                assert (lo, hi) == (max(0, line._index(s - 20.0)), min(len(line._seg), line._index(s + 20.0) + 1))
