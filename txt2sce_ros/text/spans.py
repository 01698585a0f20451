"""Map character spans of the normalised narrative back to the narrative as given (for the sketch's `evidence`).

The extractor reads a normalised copy (quotes unified, whitespace collapsed, parenthetical labels dropped, the AV's
names rewritten to `EGO`). Words other than those substitutions survive in order, so the map aligns the two word
sequences greedily: each normalised word is matched to the next equal word of the original within a short
look-ahead. One pass over both texts: linear time. A normalised span then maps to the original words it covers;
an `EGO` token takes the original text between its aligned neighbours (the AV's name as written).
"""

from __future__ import annotations

import bisect
import re

_WORD = re.compile(r"[A-Za-z0-9]+")
_LOOKAHEAD = 40  # original words one normalised word may skip (a dropped parenthesis, an AV's long name)


class OffsetMap:
    """Normalised-text span -> original-text span."""

    def __init__(self, original: str, normalised: str) -> None:
        orig = [(m.group(0).lower(), m.start(), m.end()) for m in _WORD.finditer(original)]
        self._len = len(original)
        self._starts: list[int] = []  # normalised word starts, ascending
        self._map: list[tuple[int, int] | None] = []  # original span of each normalised word, None if unaligned
        j = 0
        for m in _WORD.finditer(normalised):
            w = m.group(0).lower()
            found = None
            if w not in ("ego", "egod"):
                for k in range(j, min(len(orig), j + _LOOKAHEAD)):
                    if orig[k][0] == w:
                        found = k
                        break
            self._starts.append(m.start())
            if found is None:
                self._map.append(None)
            else:
                self._map.append((orig[found][1], orig[found][2]))
                j = found + 1
        # Unaligned words (EGO) take the original text between their aligned neighbours; the next aligned start of
        # every word is found in one backward pass (a forward search per EGO was quadratic in long texts).
        next_start = [self._len] * len(self._map)
        upcoming = self._len
        for i in range(len(self._map) - 1, -1, -1):
            next_start[i] = upcoming
            if self._map[i] is not None:
                upcoming = self._map[i][0]  # type: ignore[index]
        prev_end = 0
        for i, sp in enumerate(self._map):
            if sp is not None:
                prev_end = sp[1]
                continue
            end = next_start[i]
            start = prev_end
            while start < end and not original[start].isalnum():
                start += 1
            stop = end
            while stop > start and not original[stop - 1].isalnum():
                stop -= 1
            self._map[i] = (start, max(start, stop))

    def to_original(self, start: int, end: int) -> tuple[int, int] | None:
        """The original span covering the normalised words in [start, end), or None when none lies there."""
        i = bisect.bisect_left(self._starts, start)
        if i > 0 and i - 1 < len(self._starts) and self._starts[i - 1] < start:
            # A span starting inside a word starts with that word.
            prev = self._map[i - 1]
            if prev is not None and start < self._starts[i - 1] + (prev[1] - prev[0]) + 1:
                i -= 1
        k = bisect.bisect_left(self._starts, end)
        spans = [s for s in self._map[i:k] if s is not None and s[1] > s[0]]
        if not spans:
            return None
        return spans[0][0], spans[-1][1]
