"""Signal phases in the one form both players execute: timed `TrafficSignalStateAction`s.

esmini ignores `RoadNetwork/TrafficSignals/TrafficSignalController` phases and `TrafficSignalControllerAction`
(a `[warn]`, then the lights never change there); what it executes is a `TrafficSignalStateAction` whose `name` is
an OpenDRIVE signal id of a light it knows (country `OpenDRIVE`, type 1000001/1000011) and whose `state` gives one
mode per lamp, top to bottom (`on;off;off` = red). Our player interprets the same actions, so a phase plan written
this way runs identically in both. The form (docs/seed_format.md):

- `Init`: one `GlobalAction` per signal setting the state it shows when the run starts;
- a Story named after the controller (`signal_ctrl_<junction>`) with one Event per phase change, each holding one
  `TrafficSignalStateAction` per signal. `timed` plans start their events by `SimulationTimeCondition` at the
  phase's start time, cycling as a controller does until the time limit; a `triggered` plan (the dilemma-zone
  yellow) starts its first event by a given condition and the later ones `delay` s after that condition held
  (its second phase may also start early: `EarlyStart`).

`write_plan` makes the elements, `read_plan` turns them back into a `SignalPlan` (what the tree's TLS mutation,
its features and the analysis labels read).
"""

from __future__ import annotations

from copy import deepcopy
from dataclasses import dataclass

from lxml import etree

from .model import SignalPhase, SignalPlan

#: Lamp modes of a three-lamp head (red, yellow, green from the top), the states esmini accepts.
LAMPS = {"red": "on;off;off", "yellow": "off;on;off", "green": "off;off;on"}
_COLOURS = {v: k for k, v in LAMPS.items()}
#: Event start rule of a timed phase: `greaterThan` its start time (1.0 has no greaterOrEqual).
_TIME_RULE = "greaterThan"


def lamp_state(colour: str) -> str:
    """The lamp string of a colour name (`red` -> `on;off;off`); other texts pass through."""
    return LAMPS.get(colour, colour)


def colour_of(state: str) -> str:
    """The colour name of a lamp string (`on;off;off` -> `red`); other texts pass through."""
    return _COLOURS.get(state, state)


@dataclass(frozen=True, slots=True)
class DecodedPlan:
    """A signal block read back: the plan, and whether its first phase waits for a trigger (`triggered`) while the
    lights show `waiting` (the states of the Init actions)."""

    plan: SignalPlan
    triggered: bool
    waiting: tuple[tuple[str, str], ...]

    @property
    def tested(self) -> tuple[tuple[str, str], ...]:
        """The states a scenario is labelled by: its first phase's (the yellow of a dilemma-zone plan, not the green
        it waits in)."""
        return self.plan.phases[0].states if self.plan.phases else ()


def _state_action(parent: etree._Element, sid: str, colour: str) -> None:
    tsa = etree.SubElement(etree.SubElement(parent, "InfrastructureAction"), "TrafficSignalAction")
    etree.SubElement(tsa, "TrafficSignalStateAction", name=sid, state=lamp_state(colour))


def init_actions(states: tuple[tuple[str, str], ...]) -> list[etree._Element]:
    """One Init `GlobalAction` per (signal id, colour)."""
    out = []
    for sid, colour in states:
        ga = etree.Element("GlobalAction")
        _state_action(ga, sid, colour)
        out.append(ga)
    return out


def _condition(parent: etree._Element, name: str, delay: float = 0.0) -> etree._Element:
    trig = etree.SubElement(parent, "StartTrigger")
    return etree.SubElement(etree.SubElement(trig, "ConditionGroup"), "Condition", name=name, delay=f"{delay:g}",
                            conditionEdge="none")


def _time_condition(parent: etree._Element, name: str, t: float) -> None:
    bv = etree.SubElement(_condition(parent, name), "ByValueCondition")
    etree.SubElement(bv, "SimulationTimeCondition", value=f"{t:g}", rule=_TIME_RULE)


def _event(man: etree._Element, name: str, phase: SignalPhase) -> etree._Element:
    ev = etree.SubElement(man, "Event", name=name, priority="parallel", maximumExecutionCount="1")
    for k, (sid, colour) in enumerate(phase.states):
        act = etree.SubElement(ev, "Action", name=f"{name}_{sid}" if k else f"{name}_action")
        _state_action(etree.SubElement(act, "GlobalAction"), sid, colour)
    return ev


@dataclass(frozen=True)
class EarlyStart:
    """A second way for phase 1 of a triggered plan to start (`write_plan`): once phase 0 has shown for at least
    `after` s, as soon as `condition` (a `Condition` element) holds — a second ConditionGroup of its StartTrigger,
    the plan's trigger delayed by `after` AND `condition`. Its first group stays the plan's trigger delayed by
    phase 0's duration, so phase 1 starts at the latest then, and `read_plan` reads the plan unchanged."""

    after: float
    condition: etree._Element


def write_plan(plan: SignalPlan, *, time_limit: float, trigger: etree._Element | None = None,
               early: EarlyStart | None = None) -> tuple[list[etree._Element], etree._Element]:
    """The Init GlobalActions and the Story of `plan`.

    Without `trigger` (timed): Init shows phase 0; each later phase starts at its start time, and the phases cycle
    (as a controller's do) while a phase starts before `time_limit`; at least one event is written (a Story needs
    one), so a one-phase plan re-applies its phase after its duration. With `trigger` (a `Condition` element):
    Init shows the last phase (the one the plan settles in), phase 0 starts when `trigger` holds and phase k
    `sum(durations[:k])` s later (the same condition with that delay); the last phase then holds. `early` (with
    `trigger` only): phase 1 may also start sooner (`EarlyStart`); the later phases keep their offsets."""
    name = plan.name
    story = etree.Element("Story", name=name)
    act = etree.SubElement(story, "Act", name=f"{name}_act")
    mg = etree.SubElement(act, "ManeuverGroup", name=f"{name}_mg", maximumExecutionCount="1")
    etree.SubElement(mg, "Actors", selectTriggeringEntities="false")
    man = etree.SubElement(mg, "Maneuver", name=f"{name}_maneuver")
    phases = plan.phases
    if trigger is None:
        init = init_actions(phases[0].states)
        t, k, written = 0.0, 0, 0
        while True:
            dur = phases[k % len(phases)].duration
            if dur <= 0:            # a phase of no duration holds (as in a controller's cycle)
                if not written:     # a Story needs an Event: re-apply the phase at the limit
                    ph = phases[k % len(phases)]
                    _time_condition(_event(man, f"{name}_{ph.name}_{k}", ph), f"{name}_{ph.name}_{k}_start",
                                    time_limit)
                break
            t += dur
            k += 1
            if written and t >= time_limit:
                break
            ph = phases[k % len(phases)]
            _time_condition(_event(man, f"{name}_{ph.name}_{k}", ph), f"{name}_{ph.name}_{k}_start", t)
            written += 1
    else:
        # Every phase starts on the same condition, delayed by the phase's offset from the first: a delay counts
        # from when the condition held, so phase k starts exactly sum(durations[:k]) s after phase 0 (chained on
        # phase 0's completion instead, each would start one step late).
        init = init_actions(phases[-1].states)
        offset = 0.0
        for k, ph in enumerate(phases):
            offset += phases[k - 1].duration if k else 0.0
            cond = deepcopy(trigger)
            cond.set("name", f"{trigger.get('name', name)}_{ph.name}" if k else trigger.get("name", name))
            cond.set("delay", f"{offset:g}")
            start = _trigger_of(cond)
            if k == 1 and early is not None:
                shown = deepcopy(trigger)
                shown.set("name", f"{trigger.get('name', name)}_{ph.name}_shown")
                shown.set("delay", f"{early.after:g}")
                extra = deepcopy(early.condition)
                extra.set("name", f"{trigger.get('name', name)}_{ph.name}_early")
                group = etree.SubElement(start, "ConditionGroup")
                group.append(shown)
                group.append(extra)
            _event(man, f"{name}_{ph.name}", ph).append(start)
    act_start = _condition(act, f"{name}_act_start")
    etree.SubElement(etree.SubElement(act_start, "ByValueCondition"), "SimulationTimeCondition", value="0",
                     rule="greaterThan")
    return init, story


def _trigger_of(condition: etree._Element) -> etree._Element:
    trig = etree.Element("StartTrigger")
    etree.SubElement(trig, "ConditionGroup").append(condition)
    return trig


def time_limit_of(root: etree._Element, default: float = 60.0) -> float:
    """The run's time limit: the Storyboard StopTrigger's SimulationTimeCondition (`default` without one)."""
    cond = root.find("Storyboard/StopTrigger/ConditionGroup/Condition/ByValueCondition/SimulationTimeCondition")
    try:
        return float(cond.get("value", "")) if cond is not None else default
    except ValueError:
        return default


def is_signal_story(story: etree._Element) -> bool:
    """A Story whose every action is a TrafficSignalStateAction (the form `write_plan` writes)."""
    actions = story.findall(".//Action")
    return bool(actions) and all(a.find("GlobalAction/InfrastructureAction/TrafficSignalAction/"
                                        "TrafficSignalStateAction") is not None for a in actions)


def is_signal_init(ga: etree._Element) -> bool:
    return ga.find("InfrastructureAction/TrafficSignalAction/TrafficSignalStateAction") is not None


def _states(el: etree._Element) -> tuple[tuple[str, str], ...]:
    return tuple((a.get("name", ""), colour_of(a.get("state", ""))) for a in el.iter("TrafficSignalStateAction"))


def read_plan(inits: list[etree._Element], story: etree._Element | None) -> DecodedPlan:
    """The plan `write_plan` wrote (one cycle of a timed plan; phase names from the event names)."""
    waiting = tuple(s for ga in inits for s in _states(ga))
    name = story.get("name", "") if story is not None else ""
    events = list(story.iter("Event")) if story is not None else []
    # Triggered: every event delayed from one condition (the first undelayed); timed: events on the clock.
    delays = [float(e.find("StartTrigger//Condition").get("delay", "0")) for e in events]
    timed_first = bool(events) and events[0].find("StartTrigger//ByValueCondition/SimulationTimeCondition") is not None
    if events and (not timed_first or (len(delays) > 1 and all(d > 0 for d in delays[1:]))):
        starts = delays
        names = [_phase_name(e.get("name", ""), name, numbered=False) for e in events]
        states = [_states(e) for e in events]
        durs = [b - a for a, b in zip(starts, starts[1:])] + [0.0]
        phases = tuple(SignalPhase(n, round(d, 3), s) for n, d, s in zip(names, durs, states))
        return DecodedPlan(SignalPlan(name, phases), True, waiting)
    starts, names, states = [0.0], [""], [waiting]
    for e in events:
        st, nm = _states(e), _phase_name(e.get("name", ""), name, numbered=True)
        start = float(e.find("StartTrigger//SimulationTimeCondition").get("value", "0"))
        if st == waiting or nm in names:        # back at phase 0: one cycle read
            names[0] = nm
            starts.append(start)
            break
        starts.append(start)
        names.append(nm)
        states.append(st)
    durs = [b - a for a, b in zip(starts, starts[1:])]
    durs += [0.0] * (len(states) - len(durs))
    phases = tuple(SignalPhase(n, round(d, 3), s) for n, d, s in zip(names, durs, states))
    return DecodedPlan(SignalPlan(name, phases), False, waiting)


def plan_of(root: etree._Element) -> DecodedPlan | None:
    """The signal plan of a whole scenario (its first signal Story and the Init actions that set lights), None
    for a scenario without one."""
    story = next((s for s in root.iterfind("Storyboard/Story") if is_signal_story(s)), None)
    if story is None:
        return None
    inits = [g for g in root.iterfind("Storyboard/Init/Actions/GlobalAction") if is_signal_init(g)]
    return read_plan(inits, story)


def _phase_name(event: str, story: str, *, numbered: bool) -> str:
    rest = event[len(story) + 1:] if event.startswith(story + "_") else event
    return rest.rsplit("_", 1)[0] if numbered and "_" in rest else rest
