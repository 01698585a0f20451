"""Literal pre-filters for the extractor's regexes: skip a scan that cannot match, with the same results.

Python's `re` has no prefilter for patterns such as `\\b(?:the|a)?\\s*(?:waymo|cruise|...)\\s+vehicle` under
IGNORECASE: it tries the whole pattern at every position of every sentence, and most sentences hold none of the
words the pattern needs. `gate(rx)` reads the compiled pattern's parse tree once, at import, and derives a set of
*factors* - lowercase literals one of which every match must contain (like RE2's and Hyperscan's prefilters).
Before a scan the wrapper checks the text for a factor with plain substring search; with none present it answers
"no match" without running the regex.

Soundness: a match is a substring of the text, so a literal every match contains is in the text. The check runs on
`text.lower()` and only for ASCII texts, where IGNORECASE matching and `str.lower` agree exactly (Unicode case
folding such as the Kelvin sign or the long s is the reason non-ASCII texts always run the regex). When the
derivation meets anything it does not understand it gives up and the wrapper always runs the regex.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from typing import Any

try:  # the parser moved in Python 3.11; fall back to the deprecated alias before that
    from re import _constants as _c  # type: ignore[attr-defined]
    from re import _parser as _p  # type: ignore[attr-defined]
except ImportError:  # pragma: no cover - Python < 3.11
    import sre_constants as _c  # type: ignore[no-redef]
    import sre_parse as _p  # type: ignore[no-redef]

#: Texts shorter than this always run the regex: on a few characters the scan is as cheap as the check.
MIN_GATED_LEN = 24
#: Factors shorter than this are found in nearly every sentence and make the check pure overhead ...
MIN_FACTOR_LEN = 3
#: ... except punctuation that narratives seldom use ("(" of a parenthesis, "#").
RARE_CHARS = frozenset("()[]{}#:;/\"\\")
#: Words in nearly every narrative: a factor set built on one of them almost never skips a scan, so the derivation
#: prefers another required part of the pattern ("ran over": "ran", not "over").
COMMON = frozenset({"the", "and", "was", "were", "into", "over", "with", "that", "this", "from", "for", "its", "his",
                    "her", "then", "when", "while", "which", "who", "are", "has", "had", "been", "not", "vehicle"})

_REPEATS = {_c.MAX_REPEAT, _c.MIN_REPEAT} | ({_c.POSSESSIVE_REPEAT} if hasattr(_c, "POSSESSIVE_REPEAT") else set())


def _minimal(factors: set[str]) -> frozenset[str]:
    """Drop factors that contain another factor: finding the shorter one is already implied."""
    keep = sorted(factors, key=len)
    out: list[str] = []
    for f in keep:
        if not any(g in f for g in out):
            out.append(f)
    return frozenset(out)


def _useful_len(f: str) -> int:
    if f in COMMON:
        return 1
    return 3 if len(f) < 3 and all(ch in RARE_CHARS for ch in f) else len(f)


def _score(fs: frozenset[str]) -> tuple[int, int]:
    return (min(_useful_len(f) for f in fs), -len(fs))


def _factors(seq: Any) -> frozenset[str] | None:
    """Factors one of which every match of the parsed sequence `seq` contains, or None when none are known."""
    candidates: list[frozenset[str]] = []
    run = ""

    def flush() -> None:
        nonlocal run
        if run:
            candidates.append(frozenset({run}))
        run = ""

    for op, av in seq:
        if op is _c.LITERAL:
            run += chr(av).lower()
            continue
        flush()
        sub: frozenset[str] | None = None
        if op is _c.SUBPATTERN:
            sub = _factors(av[-1])
        elif op is _c.BRANCH:
            parts = [_factors(b) for b in av[1]]
            if parts and all(p is not None for p in parts):
                sub = _minimal(set().union(*parts))  # type: ignore[arg-type]
        elif op in _REPEATS:
            lo, _hi, body = av
            if lo >= 1:
                sub = _factors(body)
        elif hasattr(_c, "ATOMIC_GROUP") and op is _c.ATOMIC_GROUP:
            sub = _factors(av)
        # Anything else (classes, anchors, lookarounds, back-references) requires no known literal.
        if sub:
            candidates.append(sub)
    flush()
    if not candidates:
        return None
    return max(candidates, key=_score)


def factors_of(rx: re.Pattern[str]) -> frozenset[str] | None:
    """The pattern's prefilter factors (lowercase), or None when no useful set is derivable."""
    if not isinstance(rx.pattern, str):
        return None
    try:
        fs = _factors(_p.parse(rx.pattern, rx.flags))
    except Exception:  # an unexpected parse-tree shape: no gate, the regex always runs (always correct)
        return None
    if not fs or not all(f.isascii() for f in fs) or min(_useful_len(f) for f in fs) < MIN_FACTOR_LEN:
        return None
    return fs


# The text last lowercased, and its lowercase: the extractor runs a dozen patterns over one sentence in a row.
# One tuple, replaced whole, so a reader never pairs a text with another text's lowercase.
_last: tuple[str, str | None] = ("", "")


def _lower_ascii(s: str) -> str | None:
    """`s.lower()` for an ASCII text, None for any other (cached for the latest text)."""
    global _last
    last = _last
    if last[0] is s:
        return last[1]
    low = s.lower() if s.isascii() else None
    _last = (s, low)
    return low


class Gated:
    """A compiled pattern behind a literal prefilter; the methods the extractor uses, same results as `re`."""

    __slots__ = ("rx", "factors", "pattern", "flags")

    def __init__(self, rx: re.Pattern[str], factors: frozenset[str]) -> None:
        self.rx = rx
        # Longest first: a long factor is rarer, so when the text holds one it is usually found early.
        self.factors = tuple(sorted(factors, key=lambda f: (-len(f), f)))
        self.pattern = rx.pattern
        self.flags = rx.flags

    def _may_match(self, s: str) -> bool:
        if len(s) < MIN_GATED_LEN:
            return True
        low = _lower_ascii(s)
        if low is None:
            return True
        for f in self.factors:
            if f in low:
                return True
        return False

    def search(self, s: str, *a: Any) -> re.Match[str] | None:
        return self.rx.search(s, *a) if self._may_match(s) else None

    def match(self, s: str, *a: Any) -> re.Match[str] | None:
        return self.rx.match(s, *a) if self._may_match(s) else None

    def fullmatch(self, s: str, *a: Any) -> re.Match[str] | None:
        return self.rx.fullmatch(s, *a) if self._may_match(s) else None

    def finditer(self, s: str, *a: Any) -> Iterator[re.Match[str]]:
        return self.rx.finditer(s, *a) if self._may_match(s) else iter(())

    def findall(self, s: str, *a: Any) -> list[Any]:
        return self.rx.findall(s, *a) if self._may_match(s) else []

    def sub(self, repl: str | Callable[[re.Match[str]], str], s: str, *a: Any) -> str:
        return self.rx.sub(repl, s, *a) if self._may_match(s) else s

    def split(self, s: str, *a: Any) -> list[str]:
        return self.rx.split(s, *a) if self._may_match(s) else [s]

    def __repr__(self) -> str:
        return f"Gated({self.rx!r}, factors={self.factors!r})"


def gate(rx: re.Pattern[str]) -> re.Pattern[str]:
    """`rx` behind a literal prefilter when one is derivable, else `rx` itself (typed as a pattern for callers)."""
    fs = factors_of(rx)
    return Gated(rx, fs) if fs else rx  # type: ignore[return-value]


def compile_gated(pattern: str, flags: int = 0) -> re.Pattern[str]:
    """`re.compile` + `gate`."""
    return gate(re.compile(pattern, flags))
