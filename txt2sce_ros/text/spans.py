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
from itertools import accumulate

_WORD_SPLIT = re.compile(r"([A-Za-z0-9]+)")
_RUN = 8  # words aligned in one step where both texts agree
_LOOKAHEAD = 40  # original words one normalised word may skip (a dropped parenthesis, an AV's long name)


def _words(text: str) -> tuple[list[tuple[int, int]], list[str]]:
    """The spans of the text's words ([A-Za-z0-9] runs) and the words lowercased.

    (One split keeps the words and the text between them in order; their running lengths are the spans. The
    words are ASCII, so lowercasing them joined keeps them one for one; positions come from the text as it is,
    since lowercasing a non-ASCII text can change its length. Several times cheaper than a match object per word.)"""
    parts = _WORD_SPLIT.split(text)  # [between, word, between, word, ..., between]
    ends = list(accumulate(map(len, parts)))
    spans = list(zip(ends[0::2], ends[1::2]))
    return spans, " ".join(parts[1::2]).lower().split()


class OffsetMap:
    """Normalised-text span -> original-text span."""

    def __init__(self, original: str, normalised: str) -> None:
        orig_spans, orig_words = _words(original)
        self._len = len(original)
        norm_spans, norm_words = _words(normalised)
        self._starts = [a for a, _ in norm_spans]  # normalised word starts, ascending
        self._map: list[tuple[int, int] | None] = []  # original span of each normalised word, None if unaligned
        j, n_orig, n_norm = 0, len(orig_words), len(norm_words)
        i = 0
        while i < n_norm:
            # Most of a narrative survives normalisation word for word: a run of _RUN equal words (none of them
            # the AV's token) is aligned at once by one list comparison instead of word by word.
            block = norm_words[i:i + _RUN]
            if len(block) == _RUN and block == orig_words[j:j + _RUN] and "ego" not in block and "egod" not in block:
                self._map.extend(orig_spans[j:j + _RUN])
                i += _RUN
                j += _RUN
                continue
            w = norm_words[i]
            i += 1
            found = None
            if w not in ("ego", "egod") and j < n_orig:
                if orig_words[j] == w:  # the common case: the next original word
                    found = j
                else:
                    try:
                        found = orig_words.index(w, j, min(n_orig, j + _LOOKAHEAD))
                    except ValueError:
                        found = None
            if found is None:
                self._map.append(None)
            else:
                self._map.append(orig_spans[found])
                j = found + 1
        # Unaligned words (EGO) take the original text between their aligned neighbours. Every word of a run of
        # unaligned words has the same neighbours, so each run is spanned once (linear in the text however long
        # the runs).
        unaligned = [i for i, sp in enumerate(self._map) if sp is None]
        k = 0
        while k < len(unaligned):
            first = unaligned[k]
            last = first
            while k + 1 < len(unaligned) and unaligned[k + 1] == last + 1:
                k += 1
                last = unaligned[k]
            k += 1
            start = self._map[first - 1][1] if first > 0 else 0  # type: ignore[index]
            end = self._map[last + 1][0] if last + 1 < len(self._map) else self._len  # type: ignore[index]
            while start < end and not original[start].isalnum():
                start += 1
            stop = end
            while stop > start and not original[stop - 1].isalnum():
                stop -= 1
            span = (start, max(start, stop))
            for i in range(first, last + 1):
                self._map[i] = span

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
