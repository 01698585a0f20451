"""Value strategies (uniform, Gaussian, context-aware) and the checked attribute writer every operator uses.

Every value an operator writes goes through `Recorder.set`, which checks it against the entity database
(`txt2sce_ros.xosc.entitydb`: enumeration members, number types, documented ranges) and records the change, so a
node's metadata lists exactly what differs from the seed.
"""

from __future__ import annotations

import numpy as np
from lxml import etree

from ..xosc.entitydb import entity_db
from .blocks import Change
from .xml import fnum


def uniform(rng: np.random.Generator, lo: float, hi: float) -> float:
    """Random sampling: uniform in [lo, hi]."""
    return float(lo) if hi <= lo else float(rng.uniform(lo, hi))


def gaussian(rng: np.random.Generator, mean: float, sigma: float, lo: float, hi: float) -> float:
    """Gaussian mutation: mean + N(0, sigma), clipped to [lo, hi] so a draw never leaves the plausible range."""
    return float(np.clip(mean + rng.normal(0.0, sigma), lo, hi))


def element_path(el: etree._Element) -> str:
    """`Event[@name='npc1_e1_go_straight']/Action[...]/.../AbsoluteTargetSpeed` up to the fragment's root."""
    parts = []
    node: etree._Element | None = el
    while node is not None:
        name = node.get("name") or node.get("entityRef")
        parts.append(f"{node.tag}[@name='{name}']" if name else str(node.tag))
        node = node.getparent()
    return "/".join(reversed(parts))


class Recorder:
    """Writes attributes after the entity-database check and keeps the list of changes."""

    def __init__(self, version: str = "1.0") -> None:
        self.db = entity_db(version)
        self.changes: list[Change] = []

    def set(self, el: etree._Element, attr: str, value: float | int | str, *, digits: int = 4) -> str:
        text = value if isinstance(value, str) else fnum(float(value), digits)
        text = self.db.check_value(str(el.tag), attr, text)
        old = el.get(attr)
        if old != text:
            el.set(attr, text)
            self.changes.append(Change(path=f"{element_path(el)}/@{attr}", old=old, new=text))
        return text

    def check_tree(self, root: etree._Element) -> None:
        """Check every attribute of an element written whole (a new entity, an inserted obstacle)."""
        for el in root.iter():
            if isinstance(el.tag, str):
                for attr, value in el.attrib.items():
                    if ":" not in attr:
                        self.db.check_value(str(el.tag), attr, value)

    def note(self, path: str, old: str | None, new: str | None) -> None:
        """A structural change (element replaced, block inserted) that no single attribute captures."""
        self.changes.append(Change(path=path, old=old, new=new))
