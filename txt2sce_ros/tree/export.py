"""Tree exports from the manifest: GraphML (for graph tools) and Graphviz DOT."""

from __future__ import annotations

from pathlib import Path
from typing import Any


def _graph(manifest: dict[str, Any]):
    import networkx as nx

    g = nx.DiGraph(name=str(manifest.get("tree", "")))
    for n in manifest["nodes"]:
        g.add_node(n["id"], depth=int(n["depth"]), file=str(n["file"]), operator=str(n["operator"]),
                   block=str(n.get("block_key") or ""), kind=str(n.get("block_kind") or ""))
        if n["parent"] is not None:
            g.add_edge(n["parent"], n["id"], block=str(n.get("block_key") or ""), operator=str(n["operator"]))
    return g


def write_graphml(manifest: dict[str, Any], path: str | Path) -> None:
    import networkx as nx

    nx.write_graphml(_graph(manifest), str(path))


def _q(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def write_dot(manifest: dict[str, Any], path: str | Path) -> None:
    """Nodes labelled with the block they added and its operator; one rank per insertion layer."""
    lines = [f"digraph {_q(str(manifest.get('tree', 'tree')))} {{", "  rankdir=LR;", "  node [shape=box, fontsize=9];"]
    for n in manifest["nodes"]:
        label = "seed" if n["parent"] is None else f"{n['block_key']}\\n{n['operator']}#{n['variant']}"
        lines.append(f"  {_q(n['id'])} [label={_q(label)}];")
    for n in manifest["nodes"]:
        if n["parent"] is not None:
            lines.append(f"  {_q(n['parent'])} -> {_q(n['id'])};")
    lines.append("}")
    Path(path).write_text("\n".join(lines) + "\n", encoding="utf-8")
