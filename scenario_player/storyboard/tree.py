"""Storyboard elements (Story, Act, ManeuverGroup, Maneuver, Event, Action) parsed from the resolved tree.

Each class only adds what the standard gives it on top of the base life cycle: Acts and Events wait for their
StartTrigger (none = start at once), Acts and the Storyboard watch a StopTrigger, Events apply their priority
among the events of their Maneuver, Actions end when every actor's run of them has finished.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from lxml import etree

from ..actions import ActionSpec, action_from_xml
from ..conditions import Trigger, trigger_from_xml
from ..syntax.xml import ParseContext, children, first
from .element import RUNNING, STANDBY, State, StoryboardElement, Transition, all_complete

if TYPE_CHECKING:
    from ..world.world import World


class ActionElement(StoryboardElement):
    kind = "action"

    def __init__(self, name: str, spec: ActionSpec, actors: tuple[str, ...], line: int | None) -> None:
        super().__init__(name, line=line)
        self.spec = spec
        self.actors = actors
        self.runs: list[object] = []

    def _on_start(self, world: "World") -> None:
        self.runs = world.start_action(self, self.spec, self.actors)

    def _on_stop(self, world: "World") -> None:
        world.cancel_runs(self.runs)

    def _on_reset(self) -> None:
        self.runs = []

    def tick(self, world: "World") -> None:
        # An action ends at the first tick after its runs finished, never in the tick it started: an instant
        # action (teleport, step speed) completes one step later, which is when esmini reports its end too.
        if self.state is RUNNING and self.transition_step < world.step_index:
            for r in self.runs:
                if not r.done:  # type: ignore[attr-defined]
                    return
            self.end(world)


class Event(StoryboardElement):
    kind = "event"

    def __init__(self, name: str, priority: str, trigger: Trigger | None, max_executions: int,
                 line: int | None) -> None:
        super().__init__(name, max_executions=max_executions, line=line)
        self.priority = {"override": "overwrite"}.get(priority, priority)
        self.trigger = trigger
        self.maneuver: Maneuver | None = None

    def tick(self, world: "World") -> None:
        if self.state is STANDBY:
            if self.trigger is None or self.trigger.evaluate(world):
                self._try_start(world)
        if self.state is RUNNING:
            children = self.children
            for child in children:
                child.tick(world)
            if all_complete(children):
                self.end(world)

    def _try_start(self, world: "World") -> None:
        siblings = [e for e in (self.maneuver.children if self.maneuver else []) if e is not self]
        running = [e for e in siblings if e.state is RUNNING]
        if self.priority == "skip" and running:
            self.skip(world)
            return
        if self.priority == "overwrite":
            for other in running:
                other.stop(world)
        self.start(world)

    def _on_end(self, world: "World", again: bool) -> None:
        if again:
            self.reset_children()


class Maneuver(StoryboardElement):
    kind = "maneuver"

    def _on_start(self, world: "World") -> None:
        pass        # events wait for their own triggers


class ManeuverGroup(StoryboardElement):
    kind = "maneuverGroup"

    def __init__(self, name: str, actors: tuple[str, ...], max_executions: int, line: int | None) -> None:
        super().__init__(name, max_executions=max_executions, line=line)
        self.actors = actors


class Act(StoryboardElement):
    kind = "act"

    def __init__(self, name: str, start: Trigger | None, stop: Trigger | None, line: int | None) -> None:
        super().__init__(name, line=line)
        self.start_trigger, self.stop_trigger = start, stop

    def tick(self, world: "World") -> None:
        if self.state is STANDBY and (self.start_trigger is None or self.start_trigger.evaluate(world)):
            self.start(world)
        if self.state is RUNNING and self.stop_trigger is not None and self.stop_trigger.evaluate(world):
            self.stop(world)
            return
        StoryboardElement.tick(self, world)


class Story(StoryboardElement):
    kind = "story"

    def _on_start(self, world: "World") -> None:
        pass        # acts wait for their own start triggers (ticked while the story runs)


def _actors(ctx: ParseContext, mg: etree._Element) -> tuple[str, ...]:
    actors = ctx.child(mg, "Actors")
    if ctx.bool(actors, "selectTriggeringEntities", False):
        # Actors chosen at run time from the entities that triggered the events: not implemented.
        ctx.note_unsupported(actors, "Actors selectTriggeringEntities=true")
    return tuple(ctx.req(r, "entityRef") for r in children(actors, "EntityRef"))


def _event(ctx: ParseContext, el: etree._Element, actors: tuple[str, ...]) -> Event:
    event = Event(ctx.req(el, "name"), el.get("priority", "overwrite"),
                  trigger_from_xml(ctx, first(el, "StartTrigger")), ctx.int(el, "maximumExecutionCount", 1),
                  el.sourceline)
    for a in children(el, "Action"):
        spec = action_from_xml(ctx, a)
        event.children.append(ActionElement(a.get("name", ""), spec, actors, a.sourceline))
    if not event.children:
        raise ctx.error(el, "an Event needs at least one Action")
    return event


def _maneuver(ctx: ParseContext, el: etree._Element, actors: tuple[str, ...]) -> Maneuver:
    man = Maneuver(ctx.req(el, "name"), line=el.sourceline)
    for e in children(el, "Event"):
        event = _event(ctx, e, actors)
        event.maneuver = man
        man.children.append(event)
    return man


def story_from_xml(ctx: ParseContext, el: etree._Element) -> Story:
    story = Story(el.get("name", ""), line=el.sourceline)
    for act_el in children(el, "Act"):
        act = Act(ctx.req(act_el, "name"), trigger_from_xml(ctx, first(act_el, "StartTrigger")),
                  trigger_from_xml(ctx, first(act_el, "StopTrigger")), act_el.sourceline)
        for mg_el in children(act_el, "ManeuverGroup"):
            actors = _actors(ctx, mg_el)
            mg = ManeuverGroup(ctx.req(mg_el, "name"), actors, ctx.int(mg_el, "maximumExecutionCount", 1),
                               mg_el.sourceline)
            # A Maneuver catalog reference was already replaced by the Maneuver itself.
            for m in children(mg_el, "Maneuver"):
                mg.children.append(_maneuver(ctx, m, actors))
            act.children.append(mg)
        story.children.append(act)
    return story


def index_elements(stories: list[Story]) -> dict[tuple[str, str], StoryboardElement]:
    """(type, name) -> element for StoryboardElementStateConditions; first declaration wins on duplicates."""
    index: dict[tuple[str, str], StoryboardElement] = {}

    def visit(el: StoryboardElement) -> None:
        index.setdefault((el.kind, el.name), el)
        for c in el.children:
            visit(c)

    for s in stories:
        visit(s)
    return index


__all__ = ["Story", "Act", "ManeuverGroup", "Maneuver", "Event", "ActionElement", "story_from_xml",
           "index_elements", "Transition", "State"]
