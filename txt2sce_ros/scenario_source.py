"""Scenario files -> ScenarioEnvelopes: what the generator node publishes (core, no rclpy).

Accepts `.xosc` files, directories of them (sorted, recursive), and scenario-tree directories holding a
`manifest.json` (nodes listed with their file, parent and tree). The OpenDRIVE map named by the scenario's
`RoadNetwork/LogicFile` is resolved relative to the scenario file and shipped in the envelope, so a player on
another machine needs no shared disk.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Callable, Iterator

from .contract import ScenarioEnvelope
from .errors import InputError
from .xosc.schema import parse_document

def logic_file(xosc_path: Path, xosc_text: bytes) -> Path | None:
    """The map a scenario names, resolved like esmini does: relative to the scenario's directory."""
    return logic_file_of(parse_document(xosc_text, source=str(xosc_path)), xosc_path)


def logic_file_of(root: Any, xosc_path: Path) -> Path | None:
    """`logic_file` of a scenario already parsed (`root`: its document element)."""
    node = root.find("RoadNetwork/LogicFile")
    if node is None or not node.get("filepath"):
        return None
    return (xosc_path.parent / node.get("filepath")).resolve()


def _read_text(path: str) -> str:
    return Path(path).read_text(encoding="utf-8")


def envelope_for(path: Path, *, scenario_id: str | None = None, parent: str | None = None,
                 tree: str | None = None, read_map: Callable[[str], str] = _read_text) -> ScenarioEnvelope:
    """Read one scenario file and its map into an envelope (`read_map`: path -> text, e.g. a cache when many
    scenarios share a map)."""
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise InputError(f"cannot read scenario: {exc.strerror}", source=str(path)) from exc
    map_path = logic_file(path, data)
    map_text = ""
    if map_path is not None:
        try:
            map_text = read_map(str(map_path))
        except OSError as exc:
            raise InputError(f"map {map_path} named by RoadNetwork/LogicFile cannot be read",
                             source=str(path), element="LogicFile") from exc
    return ScenarioEnvelope(id=scenario_id or path.stem, xosc=data.decode("utf-8"),
                            map_path=str(map_path or ""), map_xodr=map_text, parent=parent, tree=tree,
                            meta={"file": str(path)})


def write_envelope(env: ScenarioEnvelope, directory: Path) -> Path:
    """The inverse of `envelope_for` on another machine: write the scenario and its map under `directory` so that
    the scenario's `LogicFile` names the map; returns the scenario file. The scenario's bytes stay as shipped when
    its map path is relative (the directories it climbs with `..` are made inside `directory`); an absolute map
    path, which cannot be recreated, is pointed at the copy beside the scenario."""
    xosc = env.xosc
    root = parse_document(xosc.encode("utf-8"), source=env.id)
    node = root.find("RoadNetwork/LogicFile")
    rel = Path(node.get("filepath", "")) if node is not None else Path()
    scen_dir = directory / "scenario"
    if env.map_xodr and str(rel) not in ("", "."):
        if rel.is_absolute():
            xosc = xosc.replace(f'filepath="{node.get("filepath")}"', f'filepath="{rel.name}"', 1)
            rel = Path(rel.name)
        ups = sum(1 for part in rel.parts if part == "..")
        scen_dir = directory.joinpath("scenario", *(["d"] * ups))
        map_file = scen_dir / rel
        map_file.parent.mkdir(parents=True, exist_ok=True)
        map_file.write_text(env.map_xodr, encoding="utf-8")
    scen_dir.mkdir(parents=True, exist_ok=True)
    # the driver's file name (the graph's generator names the run by it), never its directories
    out = scen_dir / (Path(str(env.meta.get("file", ""))).name or "scenario.xosc")
    out.write_text(xosc, encoding="utf-8")
    return out


def _from_manifest(d: Path, data: dict) -> Iterator[tuple[Path, str, str | None, str | None]]:
    if "nodes" in data:  # a scenario tree: nodes with their parents
        tree = str(data.get("tree") or data.get("id") or d.name)
        for node in data["nodes"]:
            if node.get("file"):
                yield d / node["file"], str(node.get("id", Path(node["file"]).stem)), node.get("parent"), tree
    else:  # a seed directory: built seeds
        for entry in data.get("built", []):
            yield d / entry["file"], str(entry.get("report_id", Path(entry["file"]).stem)), None, None


def iter_scenario_files(inputs: list[str | Path]) -> Iterator[tuple[Path, str, str | None, str | None]]:
    """(file, id, parent, tree) for every scenario the inputs name, in a stable order: tree and seed directories
    through their manifest.json, a directory of such directories one by one, other directories by their .xosc
    files (recursively), files as given."""
    for item in inputs:
        p = Path(item)
        manifest = p / "manifest.json"
        if p.is_dir() and manifest.is_file():
            yield from _from_manifest(p, json.loads(manifest.read_text(encoding="utf-8")))
        elif p.is_dir():
            subdirs = sorted(c for c in p.iterdir() if (c / "manifest.json").is_file())
            if subdirs:
                for c in subdirs:
                    yield from _from_manifest(c, json.loads((c / "manifest.json").read_text(encoding="utf-8")))
            else:
                for f in sorted(p.rglob("*.xosc")):
                    yield f, f.stem, None, None
        elif p.is_file():
            yield p, p.stem, None, None
        else:
            raise InputError("no such scenario file or directory", source=str(p))


def iter_envelopes(inputs: list[str | Path]) -> Iterator[ScenarioEnvelope]:
    for f, sid, parent, tree in iter_scenario_files(inputs):
        yield envelope_for(f, scenario_id=sid, parent=parent, tree=tree)
