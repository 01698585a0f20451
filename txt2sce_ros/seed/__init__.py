"""Sketch -> OpenSCENARIO seed (paper §III-B.2, §III-B.3): road constraints, map matching, lane assignment,
placement and timing, writing (docs/seed_format.md), and the fidelity check.

Public API: `generate_seed`, `write_seeds`, `SeedResult` (generate.py); `derive_constraints` (constraints.py);
`ScenarioPlan` and friends (model.py); `seed_context` for the tree's context-aware mutations (context.py).
"""

from ..lazy import lazy_exports

# Lazy: importing one light module of the package (`seed.kinematics`) does not load the whole generator.
__getattr__, __dir__ = lazy_exports(__name__, {"RoadConstraints": ".constraints", "derive_constraints": ".constraints",
                                               "SeedResult": ".generate", "generate_seed": ".generate",
                                               "write_seeds": ".generate"})

__all__ = ["RoadConstraints", "SeedResult", "derive_constraints", "generate_seed", "write_seeds"]
