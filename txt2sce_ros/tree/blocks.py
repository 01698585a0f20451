"""Typed records of the scenario tree: block kinds, blocks, the template, mutated variants and their changes."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class BlockKind(str, Enum):
    """What a block holds. Values double as the names used in `config/mutation.yaml` (`tree.order`)."""

    WEATHER = "weather"            # Init GlobalAction/EnvironmentAction/Environment
    EGO = "ego"                    # the ego's Init Private (initial location; its ScenarioObject stays in T)
    NPC = "npc"                    # a party's ScenarioObject + its Init Private
    SIGNAL = "signal"              # the Init actions that set lights + the signal Story (seed.signal_story)
    EVENT = "event"                # one Event of a Maneuver (`<entity>_e<k>_<action>`)
    OBSTACLE = "obstacle"          # an obstacle's ScenarioObject + its Init Private
    NEW_OBSTACLE = "new_obstacle"  # an empty slot (ScenarioObject + Private) that OIM fills
    NEW_PARTY = "new_party"        # an empty slot (ScenarioObject + Private + Story) that NCM fills (parties.py)
    NEW_SIGNAL = "new_signal"      # an empty slot (Init actions + Story) that TLS fills with a plan for the map's
                                   # lights facing the AV (a seed whose report named no signal)


@dataclass(frozen=True)
class Block:
    """One independently mutable part of a seed.

    `slots` are the template's insertion points this block fills (an entity needs two: its ScenarioObject under
    Entities and its Private under Init); `fragments` are the seed's own XML for them ('' for an empty slot)."""

    index: int
    kind: BlockKind
    key: str
    slots: tuple[int, ...]
    fragments: tuple[str, ...]


@dataclass(frozen=True)
class Template:
    """The seed with every block cut out: `pieces[i]` is followed by the fragment of slot `slot_at[i]`."""

    pieces: tuple[str, ...]
    slot_at: tuple[int, ...]

    @property
    def n_slots(self) -> int:
        return len(self.slot_at)


@dataclass(frozen=True)
class Disassembly:
    """δ(seed) = (T, B). Blocks are listed in insertion order (config `tree.order`, then document order)."""

    source: str
    template: Template
    blocks: tuple[Block, ...]

    def originals(self) -> list[str]:
        """Fragment per slot as in the seed: assemble(template, originals()) is the seed."""
        out = [""] * self.template.n_slots
        for b in self.blocks:
            for slot, frag in zip(b.slots, b.fragments):
                out[slot] = frag
        return out


@dataclass(frozen=True)
class Change:
    """One attribute or element a mutation changed: `path` is `Element[@name=..]/@attr` style, values as written."""

    path: str
    old: str | None
    new: str | None


@dataclass(frozen=True)
class Variant:
    """One version of a block: the fragments to insert, which operators made it, what changed, its features."""

    block: int
    index: int
    operator: str
    fragments: tuple[str, ...]
    changes: tuple[Change, ...]
    features: tuple
    rng_seed: int
    # (block kind, feature value) a node's earlier layers must hold for this version to make sense there: a car
    # standing close behind the AV tests a standing start only (an AV driving off leaves it behind). Read from the
    # earlier layers' features; a kind not among them (not yet a layer) does not restrict.
    needs: tuple[tuple[str, str], ...] = ()
    # (block kind, feature value) no earlier layer may hold: the two together make an invalid scenario (a car placed
    # close behind the seed's AV overlaps an AV started back on its approach), so such a node is never written.
    excludes: tuple[tuple[str, str], ...] = ()
