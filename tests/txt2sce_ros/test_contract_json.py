"""The scenario envelope's JSON: the same text `json.dumps(asdict(...), sort_keys=True)` gives, whatever the fields
hold, now that the texts' escaped forms are cached."""

import json
from dataclasses import asdict

from txt2sce_ros.contract import ScenarioEnvelope, _json_text
from txt2sce_ros.paths import shared_dir

_XODR = shared_dir() / "data" / "conformance" / "esmini" / "xodr" / "fabriksgatan.xodr"
_XOSC = shared_dir() / "data" / "conformance" / "esmini" / "xosc" / "pedestrian_collision.xosc"


def _envelopes() -> list[ScenarioEnvelope]:
    return [
        ScenarioEnvelope(id="s", xosc=""),
        ScenarioEnvelope(id="real", xosc=_XOSC.read_text(), map_path=str(_XODR), map_xodr=_XODR.read_text()),
        ScenarioEnvelope(id='q"\\\n\t\x01é→', xosc="<OpenSCENARIO a=\"1\">\u2028</OpenSCENARIO>", parent="p",
                         tree="t", meta={"z": [1, 2.5, None], "a": {"y": True, "b": "é"}}),
    ]


def test_to_json_is_the_sorted_dump_of_every_field() -> None:
    for env in _envelopes():
        text = env.to_json()
        assert text == json.dumps(asdict(env), sort_keys=True)
        assert ScenarioEnvelope.from_json(text) == env


def test_a_repeated_text_is_escaped_once() -> None:
    _json_text.cache_clear()
    for _ in range(3):
        # A fresh string each time, as a campaign reads the map again for every scenario.
        ScenarioEnvelope(id="r", xosc=_XOSC.read_text(), map_xodr=_XODR.read_text()).to_json()
    info = _json_text.cache_info()
    assert info.misses == 4 and info.hits == 8          # id, xosc, map_path, map_xodr: four texts, escaped once
