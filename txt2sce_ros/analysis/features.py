"""Scenario elements read from a scenario file: the vocabulary of trigger conditions (paper Table VI).

Elements are short strings, e.g. `position:R7`, `category:bicycle`, `npcs:2`, `events:ah`, `weather:rain`,
`signal:red`, `obstacle:yes`, and pairs such as `R7+ah` (a party's position with its event sequence), so a lift
ranking can name what the paper's table names ("R7, ah", "R7, km, 2", bicycle, fog).

They are read from the file itself (names per docs/seed_format.md, properties `txt2sce:category` and
`txt2sce:position` on the ScenarioObjects), so any scenario the tree wrote can be analysed without its history.
"""

from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

from lxml import etree

_PARSER = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=False, remove_blank_text=True)

#: Event-name suffix -> sketch action code (docs/seed_format.md).
ACTION_NAMES = {
    "go_straight": "a", "accelerate": "b", "decelerate": "c", "turn_left": "d", "turn_right": "e",
    "lane_change_left": "f", "lane_change_right": "g", "stop": "h", "start": "i", "u_turn": "j",
    "reverse": "k", "pull_over": "l", "cross": "m",
}
_EVENT = re.compile(r"^(?P<entity>[a-z]+\d*)_e(?P<k>\d+)_(?P<action>[a-z_]+)$")


def _props(obj: etree._Element) -> dict[str, str]:
    return {p.get("name", ""): p.get("value", "") for p in obj.iter("Property")}


def weather_label(root: etree._Element) -> str:
    """clear / cloudy / rain / snow / fog, from the Init environment (the weather block)."""
    env = root.find(".//EnvironmentAction/Environment")
    if env is None:
        return "default"
    w = env.find("Weather")
    if w is None:
        return "default"
    precip = w.find("Precipitation")
    kind = ""
    if precip is not None:
        kind = precip.get("precipitationType", "dry")
        intensity = float(precip.get("intensity", precip.get("precipitationIntensity", "0")) or 0)
        if kind in ("rain", "snow") and intensity > 0:
            return kind
    fog = w.find("Fog")
    if fog is not None and float(fog.get("visualRange", "100000") or 100000) < 1000:
        return "fog"
    cloud = w.get("cloudState", w.get("fractionalCloudCover", ""))
    if cloud in ("cloudy", "overcast", "rainy") or cloud.startswith("oktas") and cloud not in ("oktas0", "oktas1"):
        return "cloudy"
    return "clear"


def signal_label(root: etree._Element) -> str:
    """The first phase's state of the first signal controller ('none' without one)."""
    ctrl = root.find(".//TrafficSignalController")
    if ctrl is None:
        return "none"
    state = ctrl.find("Phase/TrafficSignalState")
    if state is None:
        return "none"
    value = state.get("state", "").lower()
    for colour in ("red", "yellow", "green"):
        if colour in value:
            return colour
    return value or "none"


def scenario_elements(xml: bytes) -> frozenset[str]:
    root = etree.fromstring(xml, _PARSER)
    out: set[str] = set()
    npcs: dict[str, dict[str, str]] = {}
    obstacles = 0
    for obj in root.iterfind("Entities/ScenarioObject"):
        name = obj.get("name", "")
        props = _props(obj)
        if name.startswith("npc"):
            npcs[name] = props
        elif name.startswith("obs"):
            obstacles += 1
            out.add(f"obstacle:{props.get('txt2sce:category', 'other')}")
    events: dict[str, list[tuple[int, str]]] = {}
    for ev in root.iter("Event"):
        m = _EVENT.match(ev.get("name", ""))
        if m and m["entity"].startswith("npc") and m["action"] in ACTION_NAMES:
            events.setdefault(m["entity"], []).append((int(m["k"]), ACTION_NAMES[m["action"]]))
    out.add(f"npcs:{len(npcs)}")
    out.add("obstacle:yes" if obstacles else "obstacle:no")
    for name, props in npcs.items():
        pos = props.get("txt2sce:position", "")
        cat = props.get("txt2sce:category", "")
        codes = "".join(code for _, code in sorted(events.get(name, [])))
        if pos:
            out.add(f"position:{pos}")
        if cat:
            out.add(f"category:{cat}")
        if codes:
            out.add(f"events:{codes}")
            if pos:
                out.add(f"{pos}+{codes}")
    out.add(f"weather:{weather_label(root)}")
    out.add(f"signal:{signal_label(root)}")
    return frozenset(out)


@lru_cache(maxsize=65536)
def elements_of_file(path: str) -> frozenset[str]:
    return scenario_elements(Path(path).read_bytes())
