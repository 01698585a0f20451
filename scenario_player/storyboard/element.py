"""One storyboard-element base class with the ASAM OpenSCENARIO life cycle.

States: standby -> running -> complete. Transitions: start (standby -> running), end (running -> complete, or back
to standby while executions remain), stop (any -> complete, forced by a stop trigger, a parent or an overriding
event), skip (an event that could not start because of its priority). The state and the *last transition* are kept
apart, with the step it happened in, so StoryboardElementStateConditions can test either exactly.
"""

from __future__ import annotations

import enum
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..world.world import World


class State(str, enum.Enum):
    STANDBY = "standby"
    RUNNING = "running"
    COMPLETE = "complete"


class Transition(str, enum.Enum):
    START = "start"
    END = "end"
    STOP = "stop"
    SKIP = "skip"


# The members as module constants, the same objects: the storyboard is ticked every step, and reading a member off
# its Enum class (`State.RUNNING`) costs ~180 ns on Python 3.11 against ~10 ns for a module global.
STANDBY, RUNNING, COMPLETE = State.STANDBY, State.RUNNING, State.COMPLETE


def all_complete(elements: list["StoryboardElement"]) -> bool:
    """`all(e.state is COMPLETE for e in elements)` without the generator (called for every running element
    every step)."""
    for e in elements:
        if e.state is not COMPLETE:
            return False
    return True


class StoryboardElement:
    """Base of Story, Act, ManeuverGroup, Maneuver, Event and Action. Subclasses override the `_on_*` hooks."""

    kind = "element"

    def __init__(self, name: str, *, max_executions: int = 1, line: int | None = None) -> None:
        self.name = name
        self.line = line
        self.max_executions = max(1, max_executions)
        self.state = STANDBY
        self.last_transition: Transition | None = None
        self.transition_step = -10
        self.executions = 0
        self.children: list[StoryboardElement] = []

    # -- transitions ---------------------------------------------------------------------------------------------
    def _mark(self, world: "World", transition: Transition, state: State) -> None:
        self.last_transition = transition
        self.transition_step = world.step_index
        self.state = state
        world.log_transition(self, transition)

    def start(self, world: "World") -> None:
        if self.state is not STANDBY:
            return
        self._mark(world, Transition.START, RUNNING)
        self._on_start(world)

    def end(self, world: "World") -> None:
        """Normal completion of one execution; restarts into standby while executions remain."""
        if self.state is not RUNNING:
            return
        self.executions += 1
        again = self.executions < self.max_executions
        self._mark(world, Transition.END, STANDBY if again else COMPLETE)
        self._on_end(world, again)

    def stop(self, world: "World") -> None:
        if self.state is COMPLETE:
            return
        for child in self.children:
            child.stop(world)
        self._mark(world, Transition.STOP, COMPLETE)
        self._on_stop(world)

    def skip(self, world: "World") -> None:
        self.last_transition = Transition.SKIP
        self.transition_step = world.step_index
        world.log_transition(self, Transition.SKIP)

    def reset_children(self) -> None:
        for child in self.children:
            child.state = STANDBY
            child.executions = 0
            child.reset_children()
            child._on_reset()

    # -- hooks ---------------------------------------------------------------------------------------------------
    def _on_start(self, world: "World") -> None:
        """Start children that have no trigger of their own (overridden where children wait for triggers)."""
        for child in self.children:
            child.start(world)

    def _on_end(self, world: "World", again: bool) -> None:
        if again:
            self.reset_children()

    def _on_stop(self, world: "World") -> None:
        pass

    def _on_reset(self) -> None:
        pass

    def tick(self, world: "World") -> None:
        """Evaluate triggers and advance the life cycle (called once per step, top-down)."""
        if self.state is RUNNING:
            children = self.children
            for child in children:
                child.tick(world)
            if children and all_complete(children):
                self.end(world)
                if self.state is STANDBY:
                    # Another execution: start again at once (ManeuverGroup/Maneuver have no trigger).
                    self.start(world)
