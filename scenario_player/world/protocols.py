"""What the world asks of the things it holds but does not define: running actions and storyboard elements.

`actions/` and `storyboard/` implement these; the world only steps, cancels and indexes them, so it imports
neither (and neither syntax): the dependency runs one way, from the storyboard and its actions to the world.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:
    from .world import World


class Run(Protocol):
    """A running action on one entity (actions/base.py ActionRun)."""

    entity: Any
    done: bool
    domains: frozenset[str]
    moves_entity: bool            # the run places the entity itself (default motion skips it)
    consumes_travel: bool         # its sideways motion takes part of the step's travel (lane changes)
    travels_at_offset: bool       # the entity advances at the radius of its offset path

    def step(self, world: "World", dt: float) -> None: ...

    def cancel(self) -> None: ...


class Startable(Protocol):
    """A parsed action (actions/base.py ActionSpec): private ones start per actor, global ones once."""

    is_private: bool

    def start(self, world: "World", entity: Any) -> Run | None: ...


class Element(Protocol):
    """A storyboard element, as far as the world indexes it (storyboard/element.py StoryboardElement)."""

    kind: str
    name: str


class Change(Protocol):
    """A storyboard transition (storyboard/element.py Transition)."""

    value: str
