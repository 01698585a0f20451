"""TeleportAction: place the entity at a position (on the lane under it, so its motion follows that lane)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from lxml import etree

from ..syntax.positions import Position, position_from_xml
from ..syntax.xml import ParseContext
from .base import ActionRun

if TYPE_CHECKING:
    from ..world.entity import Entity
    from ..world.world import World


@dataclass(frozen=True, slots=True)
class TeleportAction:
    position: Position
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "TeleportAction":
        return cls(position_from_xml(ctx, ctx.child(el, "Position")))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        world.teleport(ent, self.position.resolve(world))
        return None
