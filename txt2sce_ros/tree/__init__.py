"""Scenario tree (paper §III-C, §III-D.1, Table III): disassembly δ, block mutation, assembly α, pruning, diversity.

    from txt2sce_ros.tree import disassemble, assemble, build_tree
    d = disassemble(seed_bytes, source="seed.xosc")     # template + blocks
    assert canonical(assemble(d.template, d.originals())) == canonical(seed_bytes)
    result = build_tree("seed.xosc", "out/", seed=0)    # writes nodes + manifest.json, GraphML, DOT

No rclpy here: the generator node and the CLI call these functions.
"""

from .assembly import assemble, canonical
from .blocks import Block, BlockKind, Change, Disassembly, Template, Variant
from .disassembly import disassemble

__all__ = ["Block", "BlockKind", "Change", "Disassembly", "Template", "Variant", "assemble", "canonical",
           "disassemble", "build_tree"]


def build_tree(*args, **kwargs):  # noqa: D401 - lazy import keeps `import txt2sce_ros.tree` light
    """See `txt2sce_ros.tree.build.build_tree`."""
    from .build import build_tree as _build

    return _build(*args, **kwargs)
