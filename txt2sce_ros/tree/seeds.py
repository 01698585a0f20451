"""Seeds for tree tests and benchmarks: the seed stage run on the hand-labelled dev sketches (dev_gold.jsonl)."""

from __future__ import annotations

from pathlib import Path

from ..paths import shared_dir


def dev_gold_path() -> Path:
    return shared_dir() / "data" / "reports" / "dev_gold.jsonl"


def dev_seeds(out_dir: str | Path, *, seed: int = 0) -> list[Path]:
    """Write one seed per buildable dev sketch into `out_dir` (with their maps) and return the seed files."""
    from ..seed.generate import write_seeds
    from ..sketch import load_sketches

    out = Path(out_dir)
    manifest = write_seeds(load_sketches(dev_gold_path()), out, seed=seed)
    return [out / b["file"] for b in manifest["built"]]
