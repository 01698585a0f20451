"""Sketch -> OpenSCENARIO seed (paper §III-B.2, §III-B.3): road constraints, map matching, lane assignment,
placement and timing, writing (docs/seed_format.md), and the fidelity check.

Public API: `generate_seed`, `write_seeds`, `SeedResult` (generate.py); `derive_constraints` (constraints.py);
`ScenarioPlan` and friends (model.py); `seed_context` for the tree's context-aware mutations (context.py).
"""

from .constraints import RoadConstraints, derive_constraints
from .generate import SeedResult, generate_seed, write_seeds

__all__ = ["RoadConstraints", "SeedResult", "derive_constraints", "generate_seed", "write_seeds"]
