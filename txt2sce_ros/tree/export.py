"""Tree exports, streamed from node records (memory stays flat for large trees): the JSON manifest, GraphML (for
graph tools such as Gephi/yEd/networkx) and Graphviz DOT."""

from __future__ import annotations

import json
from collections.abc import Iterable
from pathlib import Path
from typing import Any
from xml.sax.saxutils import quoteattr


def write_manifest(head: dict[str, Any], nodes: Iterable[dict[str, Any]], path: str | Path) -> None:
    """`head` (sorted keys) plus a "nodes" list written one node per line; a plain JSON document."""
    text = json.dumps(head, indent=1, sort_keys=True)
    assert text.endswith("\n}")
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(text[:-2] + ',\n "nodes": [\n')
        first = True
        for n in nodes:
            fh.write(("" if first else ",\n") + "  " + json.dumps(n, sort_keys=True))
            first = False
        fh.write("\n ]\n}\n")


_KEYS = (("depth", "int"), ("file", "string"), ("operator", "string"), ("block", "string"), ("kind", "string"))


def write_graphml(name: str, nodes: Iterable[dict[str, Any]], path: str | Path) -> None:
    """GraphML: one node per tree node (depth, file, operator, block key, block kind), edges parent -> child."""
    with open(path, "w", encoding="utf-8") as fh:
        fh.write('<?xml version="1.0" encoding="UTF-8"?>\n'
                 '<graphml xmlns="http://graphml.graphdrawing.org/xmlns">\n')
        for key, typ in _KEYS:
            fh.write(f'  <key id="{key}" for="node" attr.name="{key}" attr.type="{typ}"/>\n')
        fh.write(f'  <graph id={quoteattr(str(name))} edgedefault="directed">\n')
        for n in nodes:
            vals = {"depth": n["depth"], "file": n["file"], "operator": n["operator"],
                    "block": n.get("block_key") or "", "kind": n.get("block_kind") or ""}
            data = "".join(f'<data key="{k}">{_esc(str(vals[k]))}</data>' for k, _ in _KEYS)
            fh.write(f'    <node id={quoteattr(n["id"])}>{data}</node>\n')
            if n["parent"] is not None:
                fh.write(f'    <edge source={quoteattr(n["parent"])} target={quoteattr(n["id"])}/>\n')
        fh.write("  </graph>\n</graphml>\n")


def _esc(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def _q(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def write_dot(name: str, nodes: Iterable[dict[str, Any]], path: str | Path) -> None:
    """Graphviz DOT, left to right; nodes labelled with the block they added and the operator."""
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(f"digraph {_q(str(name))} {{\n  rankdir=LR;\n  node [shape=box, fontsize=9];\n")
        for n in nodes:
            label = "seed" if n["parent"] is None else f"{n['block_key']}\\n{n['operator']}#{n['variant']}"
            fh.write(f"  {_q(n['id'])} [label={_q(label)}];\n")
            if n["parent"] is not None:
                fh.write(f"  {_q(n['parent'])} -> {_q(n['id'])};\n")
        fh.write("}\n")
