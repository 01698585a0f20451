"""Block mutation: the M(b) versions of every block, each made by the operators of its kind (Table III).

| block | operators | versions (paper defaults) |
|---|---|---|
| weather | WM | enumerate every weather type, parameters drawn per type |
| ego | WPM (initial location, context-aware); TSM-start (standing start); WPM-approach (started back on its approach to the light it faces, where the seed's start is too close for a dilemma zone) | `mutations_per_block`, + 1, + 1 where an approach start exists (enumerated: a budget keeps a standing and a moving start) |
| npc | NCM (+ DM, VPM follow the category) + WPM initial location; WPM-near (close to the AV) | enumerate every category, + 1 |
| signal | TLS (yellow: switched on in the ego's dilemma zone; needs the approach start where the seed has one) | enumerate yellow / red / green |
| new_signal | TLS-new: a plan for the map's lights facing the AV, in a seed without one (environment.new_signal) | enumerate yellow / red / green |
| event | TSM, DTM, WPM (lane changes) — whichever the event's actions allow | `mutations_per_block` |
| obstacle | DM + OIM (re-placed on the AV's path) | `mutations_per_block` |
| new_party | NCM-new: a cyclist ahead, a pedestrian who starts to cross, a car close behind, a lead that brakes, on the AV's path (parties.py) | enumerate every role the road allows |
| new_obstacle | OIM (inserted on the AV's path, random dimensions) | `mutations_per_block` |

Each block's versions draw from their own Generator seeded by (RNG seed, seed-file key, block index), so the
versions of a block do not depend on how many other blocks the seed has or on the order they are mutated in.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from lxml import etree

from ..errors import InputError
from .blocks import Block, BlockKind, Variant
from ..seed.context import SeedContext
from ..seed.signal_story import time_limit_of
from .dynamics import dtm, standing_start, tsm
from .environment import configured_approach, dilemma_yellow, new_signal, obstacle_fragments, oim_position, tls, wm
from .features import block_features, split_event_name
from .parties import ROLE_EXCLUDES, ROLE_NEEDS, ROLES, new_party
from .physical import DIM_ATTRS, entity_element, dm, init_speed_follow, ncm
from .trajectory import (clear_of_starts, keep_clear_of_queue, move_start, place_near_ego, route_through,
                         shift_init_location, wpm_lane_change)
from .values import Recorder, uniform
from .xml import parse_fragment, to_text


def _parse(fragments: tuple[str, ...]) -> list[etree._Element | None]:
    return [parse_fragment(f) if f else None for f in fragments]


def _choices(kind: str, values: list[str], cfg: dict[str, Any], rng: np.random.Generator) -> list[str]:
    """All values when the kind is enumerated, else `mutations_per_block` draws without replacement."""
    if kind in cfg["tree"]["enumerate"]:
        return list(values)
    m = min(int(cfg["tree"]["mutations_per_block"]), len(values))
    idx = sorted(rng.choice(len(values), size=m, replace=False).tolist())
    return [values[i] for i in idx]


def block_variants(block: Block, ctx: SeedContext, cfg: dict[str, Any], *, seed: int, seed_key: int) -> list[Variant]:
    """The mutated versions of one block, in a fixed order; identical versions are merged, and a block no operator
    can change gets none (it then stays as in the seed and is not a layer of the tree)."""
    ss = np.random.SeedSequence([int(seed), int(seed_key), int(block.index)])
    rng = np.random.default_rng(ss)
    rng_seed = int(ss.generate_state(1, dtype=np.uint32)[0])
    originals = _parse(block.fragments)
    m = int(cfg["tree"]["mutations_per_block"])
    out: list[Variant] = []
    init = cfg["trajectory"]["init_location"]
    # a start on the AV's approach to the light it faces, where the seed's start is too close to it for a
    # dilemma-zone yellow (the ego block writes it; the yellow versions of the signal blocks need it)
    approach = configured_approach(ctx, init) \
        if block.kind in (BlockKind.EGO, BlockKind.SIGNAL, BlockKind.NEW_SIGNAL) else None
    yellow_needs = (("ego", "approach"),) if approach is not None else ()

    seen: set[tuple[str, ...]] = set()

    def emit(elements: list[etree._Element | None], operator: str, rec: Recorder,
             per_slot: tuple[int, ...] | None = None, needs: tuple[tuple[str, str], ...] = (),
             excludes: tuple[tuple[str, str], ...] = ()) -> None:
        # `per_slot`: how many of `elements` go into each of the block's slots, in order (default one each: a slot
        # that takes several siblings, the Init actions of a new signal plan, holds their texts joined)
        counts = per_slot or (1,) * len(elements)
        bounds = [sum(counts[:k]) for k in range(len(counts) + 1)]
        frags = tuple("".join(to_text(e) for e in elements[a:b] if e is not None)
                      for a, b in zip(bounds, bounds[1:]))
        if frags in seen:  # two draws that made the same XML would make the same files: keep one
            return
        seen.add(frags)
        feats = block_features(block.kind, elements, originals, ctx, cfg)
        out.append(Variant(block=block.index, index=len(out), operator=operator, fragments=frags,
                           changes=tuple(rec.changes), features=feats, rng_seed=rng_seed, needs=needs,
                           excludes=excludes))

    try:
        if block.kind is BlockKind.WEATHER:
            for wtype in _choices("weather", list(cfg["environment"]["weather"]), cfg, rng):
                els, rec = _parse(block.fragments), Recorder()
                wm(els[0], wtype, rng, cfg["environment"], rec)
                emit(els, "WM", rec)
        elif block.kind is BlockKind.EGO:
            # a party the new-party slot stands `near_gap` m behind the seed's AV (close_behind) must still be clear
            # of a start moved back: at most near_gap - 0.5 m back then
            back = float(init["near_gap"]) - 0.5 if int(cfg["tree"].get("new_party_slots", 0)) else None
            for _ in range(m):
                els, rec = _parse(block.fragments), Recorder()
                shift_init_location(els[0], "ego", rng, init, ctx, rec, max_back=back)
                emit(els, "WPM-init", rec)
            # then the AV standing at its start (a moving seed's start speed set to 0): the state in which start
            # refusals and wheel spin on a slippery road can show at all. The block is enumerated, so a budget keeps
            # both start states; the seed's own (moving) one first, because the deeper layers' chain grows under
            # the first parent, and a cyclist ahead, a crossing or a yellow tests an AV that arrives at speed
            els, rec = _parse(block.fragments), Recorder()
            if standing_start(els[0], rec):
                emit(els, "TSM-start", rec)
            # last: the AV started back on its approach to the light it faces, at speed (enumerated, so a budget
            # keeps it; after the seed's own start, so the deeper layers' chain still grows under that one)
            if approach is not None:
                els, rec = _parse(block.fragments), Recorder()
                move_start(els[0], approach.s, rec)
                speed = els[0].find("PrivateAction/LongitudinalAction/SpeedAction/SpeedActionTarget/"
                                    "AbsoluteTargetSpeed")
                if speed is not None:
                    rec.set(speed, "value", approach.speed, digits=3)
                operator = "WPM-approach"
                if approach.goal is not None:       # the route, and the run's end, carried through the light
                    route_through(els, approach.goal, rec)
                    operator = "WPM-approach+route"
                emit(els, operator, rec)
        elif block.kind is BlockKind.NPC:
            for cat in _choices("npc", list(cfg["physical"]["categories"]), cfg, rng):
                els, rec = _parse(block.fragments), Recorder()
                old = ncm(els[0], cat, rng, cfg, rec)
                priv = els[1] if len(els) > 1 else None
                if old != cat:
                    init_speed_follow(priv, cat, cfg, rec)
                ops = "NCM+DM" + ("+VPM" if cfg["physical"]["categories"][cat]["element"] == "Vehicle" else "")
                if priv is not None and shift_init_location(priv, block.key, rng,
                                                            cfg["trajectory"]["init_location"], ctx, rec):
                    ops += "+WPM-init"
                if priv is not None:
                    keep_clear_of_queue(priv, block.key, els[0], ctx, rec, cfg["trajectory"]["init_location"])
                    # the new size must not reach into another start in any lane (moved back, or the version
                    # dropped: every node under it would start in a collision)
                    if not clear_of_starts(priv, block.key, els[0], ctx, rec, cfg["trajectory"]["init_location"]):
                        continue
                emit(els, ops, rec)
            # one more version: the party as in the seed, started close to the AV (where the road allows)
            els, rec = _parse(block.fragments), Recorder()
            if len(els) > 1 and els[1] is not None and place_near_ego(els[1], block.key, els[0], ctx, rec,
                                                                      cfg["trajectory"]["init_location"]):
                emit(els, "WPM-near", rec)
        elif block.kind is BlockKind.SIGNAL:
            for state in _choices("signal", list(cfg["environment"]["signal_states"]), cfg, rng):
                els, rec = _parse(block.fragments), Recorder()
                limit = time_limit_of(ctx.root)
                tls(els, state, rec, facing=ctx.ego_signals, time_limit=limit)
                if state == "yellow":  # the yellow waits for the ego's dilemma zone where it can reach the line
                    dilemma_yellow(els, ctx, rec, slack=cfg["trajectory"]["init_location"]["max_shift"],
                                   time_limit=limit, approach=approach)
                # a yellow tests an AV that arrives at speed: under a budget, the approach start where the seed's
                # start is too close to the light
                emit(els, "TLS", rec, needs=yellow_needs if state == "yellow" else ())
        elif block.kind is BlockKind.NEW_SIGNAL:
            limit = time_limit_of(ctx.root)
            slack = float(cfg["trajectory"]["init_location"]["max_shift"])
            for state in _choices("new_signal", list(cfg["environment"]["signal_states"]), cfg, rng):
                rec = Recorder()
                made = new_signal(ctx, state, rec, slack=slack, time_limit=limit, approach=approach)
                if made is None:
                    break                   # no light faces the AV where it drives: nothing to bring in
                if state == "yellow":       # reachable (new_signal checked the stop line): the dilemma zone
                    dilemma_yellow(made, ctx, rec, slack=slack, time_limit=limit, approach=approach)
                emit(made, "TLS-new", rec, per_slot=(len(made) - 1, 1),
                     needs=yellow_needs if state == "yellow" else ())
        elif block.kind is BlockKind.EVENT:
            entity, action = split_event_name(block.key)
            cat = ctx.categories.get(entity, "car")
            width = cfg["physical"]["categories"].get(cat, cfg["physical"]["categories"]["car"])["dims"][0]
            for _ in range(m):
                els, rec = _parse(block.fragments), Recorder()
                ops = []
                if tsm(els[0], action, rng, cfg["dynamics"]["tsm"], rec):
                    ops.append("TSM")
                if dtm(els[0], rng, cfg["dynamics"]["dtm"], rec):
                    ops.append("DTM")
                if wpm_lane_change(els[0], action, entity, width, rng, cfg["trajectory"]["wpm"], ctx, rec):
                    ops.append("WPM")
                if not ops:
                    break  # nothing in this event any operator mutates (e.g. a route alone): not a tree layer
                emit(els, "+".join(ops), rec)
        elif block.kind is BlockKind.OBSTACLE:
            spec = cfg["environment"]["obstacle"]
            for _ in range(m):
                els, rec = _parse(block.fragments), Recorder()
                ent = entity_element(els[0])
                dims = ent.find("BoundingBox/Dimensions") if ent is not None else None
                if dims is not None:
                    mean = tuple(float(dims.get(a, "1")) for a in DIM_ATTRS)
                    lo = tuple(min(a, b) for a, b in zip(spec["dims_lo"], mean))
                    hi = tuple(max(a, b) for a, b in zip(spec["dims_hi"], mean))
                    dm(dims, mean, lo, hi, rng, cfg["physical"]["dm"], rec)
                ops = "DM"
                tele = els[1].find("PrivateAction/TeleportAction/Position/LanePosition") if len(els) > 1 else None
                width = float(dims.get("width", "1")) if dims is not None else 1.0
                pos = oim_position(ctx, width, rng, spec) if tele is not None else None
                if pos is not None:
                    for attr, val in (("roadId", pos.road), ("laneId", str(pos.lane))):
                        rec.set(tele, attr, val)
                    rec.set(tele, "s", pos.s, digits=3)
                    rec.set(tele, "offset", pos.offset, digits=3)
                    ops += "+OIM"
                emit(els, ops, rec)
        elif block.kind is BlockKind.NEW_PARTY:
            for role in _choices("new_party", list(ROLES), cfg, rng):
                rec = Recorder()
                made = new_party(role, block.key, ctx, rng, cfg, rec)
                if made is not None:
                    emit(list(made), f"NCM-new:{role}", rec, needs=ROLE_NEEDS.get(role, ()),
                         excludes=ROLE_EXCLUDES.get(role, ()))
        elif block.kind is BlockKind.NEW_OBSTACLE:
            spec = cfg["environment"]["obstacle"]
            for _ in range(m):
                rec = Recorder()
                dims3 = tuple(uniform(rng, lo, hi) for lo, hi in zip(spec["dims_lo"], spec["dims_hi"]))
                pos = oim_position(ctx, dims3[0], rng, spec)
                if pos is None:
                    break  # no map or no ego start: nothing to place the obstacle relative to
                obj, priv = obstacle_fragments(block.key, pos, dims3, spec, rec)
                emit([obj, priv], "OIM", rec)
    except InputError as exc:
        raise InputError(f"mutating block {block.key}: {exc.message}", source=ctx.source,
                         element=exc.element or block.key) from exc
    return out


def original_features(block: Block, ctx: SeedContext, cfg: dict[str, Any]) -> tuple:
    els = _parse(block.fragments)
    return block_features(block.kind, els, els, ctx, cfg)
