"""argparse value types that refuse what would make a command hang, crash or give a wrong verdict: NaN, infinities,
zero or negative steps and limits. argparse prints the refusal as one line and exits with status 2."""

from __future__ import annotations

import argparse
import math
from typing import Callable


def number(*, gt: float | None = None, ge: float | None = None, le: float | None = None,
           lt: float | None = None) -> Callable[[str], float]:
    """A finite float within the given bounds."""

    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError as exc:
            raise argparse.ArgumentTypeError(f"{text!r} is not a number") from exc
        if not math.isfinite(value):
            raise argparse.ArgumentTypeError(f"{text!r}: must be a finite number")
        for ok, what, bound in ((gt is None or value > gt, ">", gt), (ge is None or value >= ge, ">=", ge),
                                (le is None or value <= le, "<=", le), (lt is None or value < lt, "<", lt)):
            if not ok:
                raise argparse.ArgumentTypeError(f"{text}: must be {what} {bound:g}")
        return value

    return parse


def count(*, ge: int = 1, le: int | None = None) -> Callable[[str], int]:
    """An integer within [ge, le]."""

    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError as exc:
            raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from exc
        if value < ge or (le is not None and value > le):
            raise argparse.ArgumentTypeError(f"{text}: must be >= {ge}" + (f" and <= {le}" if le is not None else ""))
        return value

    return parse


#: Simulation step, s: finite, > 0, at most 1 s (a larger step skips whole manoeuvres).
STEP = number(gt=0.0, le=1.0)
#: Simulated time limit, s (the player also bounds the number of steps, config/player.yaml).
TIME_LIMIT = number(gt=0.0)
#: Share in (0, 1].
SHARE = number(gt=0.0, le=1.0)
#: A finite coordinate.
COORD = number()
#: A positive finite factor or duration.
POSITIVE = number(gt=0.0)
