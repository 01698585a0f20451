"""The world knows nothing of actions, the storyboard or the syntax: every import in scenario_player/world/ (type-only
ones included) stays inside world/ or outside scenario_player. Actions and the storyboard reach it through the
protocols in world/protocols.py, positions through world/pose.py, entity records through world/spec.py."""

from __future__ import annotations

import ast
from pathlib import Path

import scenario_player

WORLD = Path(scenario_player.__file__).parent / "world"
FORBIDDEN = ("actions", "syntax", "storyboard", "conditions")


def _imports(path: Path) -> list[str]:
    """Every module an `import` or `from ... import` in the file names, relative ones resolved to scenario_player.*"""
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out.extend(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level == 0:
                out.append(node.module or "")
            else:
                base = ["scenario_player", "world"][: 2 - (node.level - 1)]
                out.append(".".join(base + ([node.module] if node.module else [])))
    return out


def test_world_imports_nothing_of_actions_storyboard_or_syntax() -> None:
    files = sorted(WORLD.glob("*.py"))
    assert len(files) >= 8
    bad = [(f.name, m) for f in files for m in _imports(f)
           if m.startswith("scenario_player.") and m.split(".")[1] in FORBIDDEN]
    assert bad == []


def test_the_check_sees_a_relative_import_of_actions(tmp_path) -> None:
    # Not vacuous: a type-only relative import of the actions package is found and resolved.
    f = tmp_path / "x.py"
    f.write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from ..actions.base import ActionRun\n")
    assert "scenario_player.actions.base" in _imports(f)
