"""Faster scans for the extractor's regexes, with exactly the results of `re`.

The extractor is some two hundred IGNORECASE word-list patterns run over every sentence; `re` spends most of its
time trying alternatives that cannot match. Two exact rewrites, both derived once from the pattern's parse tree:

1. A literal prefilter. `factors_of(rx)` is a set of lowercase literals one of which every match contains (like
   RE2's and Hyperscan's prefilters); a text holding none of them has no match, and the scan is skipped. Sound
   because a match is a substring of the text.
2. A case-folded scan. With IGNORECASE, `re` enters every branch of an alternation at every position; without it,
   a branch starting with a literal is skipped after one character compare. `folded(rx)` is the case-sensitive
   twin of the pattern for lowercase text (literals lowercased, letter classes given their lowercase members); it
   runs on `text.lower()` to find where each match starts, and the original pattern, anchored there, returns the
   match object - on the original text, so groups, callbacks and replacements see the original characters. A
   disagreement in the end position raises instead of returning a different result. Where that lets `re` skip
   to a first literal or set of first characters, the scan reads the *word-cased* text instead (`wordcase`: each
   letter that begins a word in upper case), where a `\b` before a letter is that letter in upper case.

Both run only on ASCII texts, where IGNORECASE matching and `str.lower` agree exactly (Unicode case folding, such
as the Kelvin sign matching "k", is why any other text runs the original pattern). Where the derivation meets
anything it does not understand (scoped flags, back-references, non-ASCII literals) it gives up and the original
pattern runs. `compile_gated` replaces `re.compile`; `search`, `sub`, ... replace `re`'s module functions for the
rules that write their pattern inline (cached, as `re` caches).
"""

from __future__ import annotations

import re
import weakref
from collections.abc import Callable, Iterator
from typing import Any

try:  # the parser moved in Python 3.11; fall back to the deprecated alias before that
    from re import _constants as _c  # type: ignore[attr-defined]
    from re import _compiler  # type: ignore[attr-defined]
    from re import _parser as _p  # type: ignore[attr-defined]
except ImportError:  # pragma: no cover - Python < 3.11
    import sre_constants as _c  # type: ignore[no-redef]
    import sre_compile as _compiler  # type: ignore[no-redef]
    import sre_parse as _p  # type: ignore[no-redef]

#: Texts shorter than this always run the original pattern: on a few characters the checks cost more than the scan.
MIN_GATED_LEN = 8
#: Factors shorter than this are found in nearly every sentence and make the check pure overhead ...
MIN_FACTOR_LEN = 3
#: ... except punctuation that narratives seldom use ("(" of a parenthesis, "#").
RARE_CHARS = frozenset("()[]{}#:;/\"\\")
#: Words in nearly every narrative: a factor set built on one of them almost never skips a scan, so the derivation
#: prefers another required part of the pattern ("ran over": "ran", not "over").
COMMON = frozenset({"the", "and", "was", "were", "into", "over", "with", "that", "this", "from", "for", "its", "his",
                    "her", "then", "when", "while", "which", "who", "are", "has", "had", "been", "not", "vehicle"})

_REPEATS = {_c.MAX_REPEAT, _c.MIN_REPEAT} | ({_c.POSSESSIVE_REPEAT} if hasattr(_c, "POSSESSIVE_REPEAT") else set())


def _children(op: Any, av: Any) -> list[Any]:
    """The sub-trees under one node of a parsed pattern: a group's body, each alternative, a repeat's body, a
    lookaround's body, an atomic group. The walkers of the tree below descend through these."""
    if op is _c.SUBPATTERN:
        return [av[3]]
    if op is _c.BRANCH:
        return list(av[1])
    if op in _REPEATS:
        return [av[2]]
    if op in (_c.ASSERT, _c.ASSERT_NOT):
        return [av[1]]
    if hasattr(_c, "ATOMIC_GROUP") and op is _c.ATOMIC_GROUP:
        return [av]
    return []


def _minimal(factors: set[str]) -> frozenset[str]:
    """Drop factors that contain another factor: finding the shorter one is already implied."""
    keep = sorted(factors, key=len)
    out: list[str] = []
    for f in keep:
        if not any(g in f for g in out):
            out.append(f)
    return frozenset(out)


def _useful_len(f: str) -> int:
    if f.lower() in COMMON:
        return 1
    return 3 if len(f) < 3 and all(ch in RARE_CHARS for ch in f) else len(f)


def _score(fs: frozenset[str]) -> tuple[int, int]:
    return (min(_useful_len(f) for f in fs), -len(fs))


def _factors(seq: Any, fold: bool = True) -> frozenset[str] | None:
    """Factors one of which every match of the parsed sequence `seq` contains, or None when none are known; lowercase
    when `fold` (an IGNORECASE pattern), else as written (a case-sensitive pattern's literals are exact)."""
    candidates: list[frozenset[str]] = []
    run = ""

    def flush() -> None:
        nonlocal run
        if run:
            candidates.append(frozenset({run}))
        run = ""

    for op, av in seq:
        if op is _c.LITERAL:
            run += chr(av).lower() if fold else chr(av)
            continue
        flush()
        sub: frozenset[str] | None = None
        if op is _c.SUBPATTERN:
            sub = _factors(av[-1], fold)
        elif op is _c.BRANCH:
            parts = [_factors(b, fold) for b in av[1]]
            if parts and all(p is not None for p in parts):
                sub = _minimal(set().union(*parts))  # type: ignore[arg-type]
        elif op in _REPEATS:
            lo, _hi, body = av
            if lo >= 1:
                sub = _factors(body, fold)
        elif hasattr(_c, "ATOMIC_GROUP") and op is _c.ATOMIC_GROUP:
            sub = _factors(av, fold)
        # Anything else (classes, anchors, lookarounds, back-references) requires no known literal.
        if sub:
            candidates.append(sub)
    flush()
    if not candidates:
        return None
    return max(candidates, key=_score)


def factors_of(rx: re.Pattern[str], tree: Any = None) -> frozenset[str] | None:
    """The pattern's prefilter factors, or None when no useful set is derivable: lowercase for an IGNORECASE pattern
    (looked for in the lowercase text), as written for a case-sensitive one (looked for in the text itself).
    `tree`: the pattern already parsed (only read here)."""
    if not isinstance(rx.pattern, str):
        return None
    try:
        tree = tree if tree is not None else _p.parse(rx.pattern, rx.flags)
        if tree.data and tree.data[0] == (_c.AT, _c.AT_BEGINNING_STRING) or \
                tree.data and tree.data[0] == (_c.AT, _c.AT_BEGINNING) and not rx.flags & re.MULTILINE:
            # Anchored at the start: the scan tries one position and fails fast, while the prefilter would look
            # for every factor in the whole text (~10x the scan's cost on the extractor's "^\s*(?:lanes?|...)").
            return None
        fs = _factors(tree, bool(rx.flags & re.IGNORECASE))
    except Exception:  # an unexpected parse-tree shape: no gate, the regex always runs (always correct)
        return None
    if not fs or not all(f.isascii() for f in fs) or min(_useful_len(f) for f in fs) < MIN_FACTOR_LEN:
        return None
    return fs


# Lowercase of the texts seen lately: the extractor runs dozens of patterns over one sentence, and over the same
# clause slices, interleaved; a bounded dict (cleared when full) keeps each text's lowercase for its next pattern.
_LOWER: dict[str, str | None] = {}
_LOWER_MAX = 512
_MISSING = object()


def _lower_ascii(s: str) -> str | None:
    """`s.lower()` for an ASCII text, None for any other (cached for the texts seen lately)."""
    low = _LOWER.get(s, _MISSING)
    if low is _MISSING:
        if len(_LOWER) >= _LOWER_MAX:
            _LOWER.clear()
        low = _LOWER[s] = s.lower() if s.isascii() else None
    return low  # type: ignore[return-value]


class _Unfoldable(Exception):
    """The pattern holds something `_fold` does not turn into an exact lowercase equivalent."""


def _fold_class(items: list[tuple[Any, Any]]) -> list[tuple[Any, Any]]:
    out = list(items)
    for op, av in items:
        if op is _c.LITERAL:
            if av > 127:
                raise _Unfoldable
            low = ord(chr(av).lower())
            if low != av:
                out.append((_c.LITERAL, low))
        elif op is _c.RANGE:
            lo, hi = av
            if hi > 127:
                raise _Unfoldable
            a, b = max(lo, 65), min(hi, 90)  # the part of the range that is A-Z
            if a <= b:
                out.append((_c.RANGE, (a + 32, b + 32)))
        elif op not in (_c.NEGATE, _c.CATEGORY):
            raise _Unfoldable
    return out


def _fold(seq: Any) -> None:
    """Rewrite a pattern parsed with IGNORECASE, in place, into the case-sensitive pattern that matches the
    lowercase of an ASCII text exactly where the original matches the text: literals lowercased, letter classes
    given their lowercase members (a negated class then excludes both cases, as IGNORECASE does)."""
    for k, (op, av) in enumerate(seq.data):
        if op in (_c.LITERAL, _c.NOT_LITERAL):
            if av > 127:
                raise _Unfoldable
            seq.data[k] = (op, ord(chr(av).lower()))
        elif op is _c.IN:
            seq.data[k] = (op, _fold_class(av))
        elif kids := _children(op, av):
            if op is _c.SUBPATTERN and (av[1] | av[2]) & (re.IGNORECASE | re.LOCALE | re.ASCII):
                raise _Unfoldable  # a scoped case-sensitive part ("(?-i:[A-Z])") cannot run on lowercase text
            for kid in kids:
                _fold(kid)
        elif op not in (_c.AT, _c.ANY):
            raise _Unfoldable  # back-references, conditionals


_WORD_CHAR = re.compile(r"\w")


def _boundary_after() -> tuple[Any, Any]:
    r"""`(?<!\w.)` as a parse-tree item: placed right after a word character, it holds exactly where a `\b` before
    that character would (the character before it is no word character, or there is none)."""
    return _p.parse(r"(?<!\w.)").data[0]  # type: ignore[no-any-return]


def _hoist_boundary(seq: Any, implied: bool = False) -> None:
    r"""Rewrite, in place, a leading `\b` before a word literal (`\bturn`, `\b(?:came|come)`) as the literal followed
    by a look-behind (`t(?<!\w.)urn`, `(?:c(?<!\w.)ame|...)`). The two match at exactly the same places, but `re`
    scans for a pattern's first literal (or the set of its branches' first characters) in C, while a pattern that
    starts with `\b` is tried at every position of the text. Only the scanners get this (a folded one finds where
    matches start; the original pattern, anchored there, still makes the match). `implied`: the scanner reads
    the `wordcase` text, where an upper-case letter begins a word: a `\b` before one is dropped, and one before an
    alternation goes into each alternative."""
    data = seq.data
    if not data:
        return
    op, av = data[0]
    if op is _c.BRANCH:
        for b in av[1]:
            _hoist_boundary(b, implied)
        return
    if op is _c.SUBPATTERN and len(data) == 1:
        _hoist_boundary(av[3], implied)
        return
    if op is not _c.AT or av is not _c.AT_BOUNDARY or len(data) < 2:
        return
    nop, nav = data[1]
    if nop is _c.LITERAL and implied and 65 <= nav <= 90:
        seq.data = data[1:]
    elif nop is _c.LITERAL and _WORD_CHAR.match(chr(nav)):
        seq.data = [data[1], _boundary_after()] + data[2:]
    elif nop is _c.SUBPATTERN and not (nav[1] | nav[2]) and len(nav[3].data) == 1 and nav[3].data[0][0] is _c.BRANCH:
        # "\b(?:a|b)c" -> "(?:\ba|\bb)c": the boundary moves into each branch, then each is rewritten.
        for b in nav[3].data[0][1][1]:
            b.data = [(_c.AT, _c.AT_BOUNDARY)] + b.data
            _hoist_boundary(b, implied)
        seq.data = data[1:]
    elif nop is _c.BRANCH and implied:
        for b in nav[1]:
            b.data = [(_c.AT, _c.AT_BOUNDARY)] + b.data
            _hoist_boundary(b, implied)
        seq.data = data[1:]


def _merge_prefixes(seq: Any) -> None:
    """Rewrite, in place, alternatives that open with the same literal (or `\\b` and the same literal) as that
    opening followed by their alternation ("made...|making...|makes..." -> "ma(?:de...|king...|kes...)"), in every
    alternation of the tree. `re` tests the shared opening once per position instead of once per alternative.

    Alternatives are gathered across others only where that cannot change the match: an alternative moves before
    another only when no character can begin a match of both (their sets of first characters are known and
    disjoint), so at any position the alternatives that can match are tried in the same order as before; where a
    first character is not known (a class with categories, an optional opening) nothing moves past it."""
    for k, (op, av) in enumerate(seq.data):
        for kid in _children(op, av):
            _merge_prefixes(kid)
        if op is _c.BRANCH:
            seq.data[k] = (op, (av[0], _merged(av[1], seq.state)))


def _first_chars(data: Any) -> frozenset[int] | None:
    """The characters a match of the item sequence can begin with, or None where that is not known (it may match
    an empty string, or begins with a class of categories or a negated class)."""
    for op, av in data:
        if op is _c.AT or op in (_c.ASSERT, _c.ASSERT_NOT):
            continue  # zero-width: the first character comes from what follows
        if op is _c.LITERAL:
            return frozenset((av,))
        if op is _c.IN:
            chars: set[int] = set()
            for o, a in av:
                if o is _c.LITERAL:
                    chars.add(a)
                elif o is _c.RANGE and a[1] - a[0] < 128:
                    chars.update(range(a[0], a[1] + 1))
                else:
                    return None
            return frozenset(chars)
        if op is _c.SUBPATTERN:
            body = av[3]
            return _first_chars(body.data) if body.getwidth()[0] > 0 else None
        if op is _c.BRANCH:
            sets = [_first_chars(b.data) for b in av[1]]
            return None if any(f is None for f in sets) else frozenset().union(*sets)  # type: ignore[arg-type]
        if op in _REPEATS:
            lo, _hi, body = av
            return _first_chars(body.data) if lo >= 1 else None
        return None
    return None  # nothing that consumes a character: it may match an empty string


def _opening(b: Any) -> tuple[Any, ...] | None:
    """The opening alternatives can share: a literal, or `\\b` and a literal."""
    d = b.data
    if d and d[0][0] is _c.LITERAL:
        return (d[0],)
    if len(d) > 1 and d[0] == (_c.AT, _c.AT_BOUNDARY) and d[1][0] is _c.LITERAL:
        return (d[0], d[1])
    return None


def _merged(branches: list[Any], state: Any) -> list[Any]:
    runs: list[tuple[Any, frozenset[int] | None, list[Any]]] = []  # (opening or None, first characters, alternatives)
    for b in branches:
        head, first = _opening(b), _first_chars(b.data)
        for run in reversed(runs) if head is not None else ():
            if run[0] == head:
                run[2].append(b)
                break
            if run[1] is None or first is None or run[1] & first:
                runs.append((head, first, [b]))  # it may not move before this one
                break
        else:
            runs.append((head, first, [b]))
    out = []
    for head, _first, bs in runs:
        if head is None or len(bs) == 1:
            out += bs
            continue
        tails = _merged([_p.SubPattern(state, b.data[len(head):]) for b in bs], state)
        out.append(_p.SubPattern(state, list(head) + (list(tails[0].data) if len(tails) == 1 else
                                                      [(_c.BRANCH, (None, tails))])))
    return out


#: A class of at most this many characters that opens an alternative is spelled out as one alternative per
#: character (`_spell_out`); a larger one stays a class.
MAX_SPELLED = 8


def _class_chars(items: list[tuple[Any, Any]]) -> list[int] | None:
    """The characters of a class of plain characters and small ranges, or None (categories, negation, large)."""
    chars: list[int] = []
    for op, av in items:
        if op is _c.LITERAL:
            chars.append(av)
        elif op is _c.RANGE and av[1] - av[0] < MAX_SPELLED:
            chars.extend(range(av[0], av[1] + 1))
        else:
            return None
    chars = list(dict.fromkeys(chars))
    return chars if len(chars) <= MAX_SPELLED else None


def _few_frequent(alts: list[list[tuple[Any, Any]]]) -> bool:
    """Do the alternatives begin with known characters of which at most three are lowercase letters?"""
    sets = [_first_chars(a) for a in alts]
    if any(f is None for f in sets):
        return False
    return sum(97 <= c <= 122 for c in frozenset().union(*sets)) <= 3  # type: ignore[arg-type]


def _openings(data: list[tuple[Any, Any]], wordcased: bool = False) -> list[list[tuple[Any, Any]]]:
    """The item sequence `data` as alternatives in the same order, spelled out at their opening (see `_spell_out`)."""
    if not data:
        return [data]
    op, av = data[0]
    if op is _c.BRANCH:
        # "(?:x|y)z" is "xz|yz": the same alternatives tried in the same order
        return [a for b in av[1] for a in _openings(list(b.data) + data[1:], wordcased)]
    k = 1 if op is _c.AT and av is _c.AT_BOUNDARY and len(data) > 1 else 0
    nop, nav = data[k]
    if wordcased and nop is _c.SUBPATTERN and not (nav[1] | nav[2]):
        # "(x)y" is "xy" to a folded scanner: the original, anchored where it found a match, makes the groups
        return _openings(data[:k] + list(nav[3].data) + data[k + 1:], wordcased)
    if wordcased and nop is _c.MAX_REPEAT and nav[0] == 0 and nav[1] == 1:
        # "(?:x)?y" is "xy|y": greedy, the optional part is tried first, then left out
        return _openings(data[:k] + list(nav[2].data) + data[k + 1:], wordcased) + \
            _openings(data[:k] + data[k + 1:], wordcased)
    if k and data[1][0] is _c.BRANCH:
        alts = [data[:1] + a for a in _openings(data[1:], wordcased)]
        return alts if wordcased or _few_frequent(alts) else [data]
    if data[k][0] is _c.IN and (chars := _class_chars(data[k][1])):
        return [data[:k] + [(_c.LITERAL, ch)] + data[k + 1:] for ch in chars]
    return [data]


def _spell_out(seq: Any, wordcased: bool = False) -> None:
    r"""Rewrite, in place, the opening of the pattern so that `re` can skip in C to where a match may begin (a
    "charset prefix": every alternative of the opening alternation starts with a literal):

    - a small class opening the pattern or one of its opening alternatives is spelled out, one alternative per
      character ("[,;]|when" -> ",|;|when", "[Aa]n" -> "An|an"): only one of them can match where the
      class did, in the class's place in the order, so the match is the same;
    - a `` before an alternation (Python 3.11 inlines "(?:x|y)") moves into each alternative ("x|y"),
      where `_hoist_boundary` then puts it behind each first literal, but only where those first characters
      include at most three lowercase letters (the frequent ones): where they are most letters, the look-behind
      at each of them costs more than the failed `` it replaces (measured in session 11).

    Alternations are spelled out only at the opening; where that gives no literal-first alternatives the tree
    stays as it was."""
    alts = _openings(list(seq.data), wordcased)
    if len(alts) > 1 and len(alts) <= 64 and all(_literal_first(_p.SubPattern(seq.state, a[1:] if a[:1] == [
            (_c.AT, _c.AT_BOUNDARY)] else a)) for a in alts):
        seq.data = [(_c.BRANCH, (None, [_p.SubPattern(seq.state, a) for a in alts]))]


def _literal_first(seq: Any) -> bool:
    """Does every match of the tree begin with a literal character (so `re` can look for it in C)?"""
    data = seq.data
    if not data:
        return False
    op, av = data[0]
    if op is _c.LITERAL:
        return True
    if op is _c.BRANCH:
        return all(_literal_first(b) for b in av[1])
    if op is _c.SUBPATTERN:
        return _literal_first(av[3])
    return False


#: What Unicode's \s matches among ASCII characters: ASCII's \s lacks the four separators \x1c-\x1f.
_ASCII_SPACE = [(_c.RANGE, (9, 13)), (_c.RANGE, (28, 32))]


def _ascii_spaces(seq: Any) -> bool:
    r"""Rewrite, in place, every `\s` of the tree as the explicit set of the ASCII characters Unicode's `\s` matches,
    so that compiling with ASCII semantics matches exactly as before on ASCII text; False (tree then unusable for
    that) where a `\S` or a negated class with `\s` makes the rewrite not a plain substitution."""
    for k, (op, av) in enumerate(seq.data):
        if op is _c.IN:
            if any(o is _c.CATEGORY and a in (_c.CATEGORY_NOT_SPACE, _c.CATEGORY_LINEBREAK, _c.CATEGORY_NOT_LINEBREAK)
                   for o, a in av):
                return False
            if any(o is _c.CATEGORY and a is _c.CATEGORY_SPACE for o, a in av):
                if any(o is _c.NEGATE for o, _ in av):
                    return False
                seq.data[k] = (op, [x for x in av if not (x[0] is _c.CATEGORY and x[1] is _c.CATEGORY_SPACE)]
                               + list(_ASCII_SPACE))
        elif kids := _children(op, av):
            if not all(_ascii_spaces(kid) for kid in kids):
                return False
        elif op is _c.CATEGORY:
            return False  # a bare category outside a class: not produced by the parser for \s; be safe
    return True


def _scanner(rx: re.Pattern[str], fold: bool, words: bool = False) -> re.Pattern[str]:
    r"""The pattern recompiled for scanning ASCII text: literals lowercased when `fold` (its text is then the
    lowercase one; with `words`, the `wordcase` one), a leading `\b` moved behind its literal, ASCII classes where
    they are exact. Raises _Unfoldable (or anything from an unexpected parse tree) where that is not derivable,
    and, with `words`, where `re` would find no first literal or set of first characters to skip to: the pattern
    is then tried at every position, and there a leading `\b` fails sooner than the alternatives it was moved
    into (measured: "\b(one|two|\d)\s+lanes" 2x slower on the word-cased text)."""
    tree = _p.parse(rx.pattern, rx.flags)
    flags = rx.flags
    if fold:
        _fold(tree)
        tree.state.flags &= ~re.IGNORECASE
        flags &= ~re.IGNORECASE
    elif _scoped_flags(tree):
        raise _Unfoldable  # "(?i:...)" inside: its letters' cases under ASCII rules are not worth proving here
    _merge_prefixes(tree)
    _spell_out(tree, words)
    if words:
        _wordcased(tree, _EITHER, True)
        _spell_branches(tree)
        _merge_prefixes(tree)
    _hoist_boundary(tree, words)
    if words and not _skips(tree, flags):
        raise _Unfoldable
    if not fold and not _literal_first(tree):
        # A case-sensitive pattern gains only where `re` can now look for its first literal (measured: "\s+"
        # ran no faster, or slower, through the twin; "[,;]|\bwhen\b" spelled out runs ~20x faster).
        raise _Unfoldable
    if _ascii_spaces(tree):
        # The scanner only ever reads ASCII text, where ASCII \w, \d and \b agree with Unicode's and cost a
        # table look-up instead of a Unicode category query per character.
        tree.state.flags = (tree.state.flags & ~re.UNICODE) | re.ASCII
        flags = (flags & ~re.UNICODE) | re.ASCII
    return _compiler.compile(tree, flags)  # type: ignore[no-any-return]


def _skips(tree: Any, flags: int) -> bool:
    """Does `re` compile the tree with a first literal or a set of first characters to skip to?"""
    try:
        return bool(_compiler._get_literal_prefix(tree, flags)[0] or _compiler._get_charset_prefix(tree, flags))
    except Exception:  # another Python's compiler: no such claim
        return False


# The folded scanner reads the lowercase text with every letter that begins a word in upper case (`wordcase`):
# a `\b` before a letter of the pattern then is that letter in upper case, and `re` skips in C to the few places
# where a word begins with one of the pattern's first letters, instead of trying the pattern at every position.
_WORD, _NONWORD, _EITHER = "word", "nonword", "either"
_AFTER_WORD_CHAR = re.compile(r"[0-9_][A-Z]")
_WORDCASE: dict[str, str] = {}


def wordcase(low: str) -> str:
    r"""The lowercase ASCII text `low` with each letter that begins a word (a `\b` before it: no letter, digit or
    underscore before it) in upper case, every other letter in lower case. `str.title` does that except after a
    digit or an underscore, which are word characters: those letters are put back in lower case."""
    out = _WORDCASE.get(low)
    if out is None:
        if len(_WORDCASE) >= _LOWER_MAX:
            _WORDCASE.clear()
        out = low.title()
        if _AFTER_WORD_CHAR.search(out):
            out = _AFTER_WORD_CHAR.sub(lambda m: m.group(0).lower(), out)
        _WORDCASE[low] = out
    return out


def _char_kind(ch: int) -> str:
    return _WORD if chr(ch).isalnum() and ch < 128 or ch == 95 else _NONWORD


def _class_kind(items: list[tuple[Any, Any]]) -> str:
    """What a character matched by the class is: a word character, none, or either."""
    kinds: set[str] = set()
    for op, av in items:
        if op is _c.LITERAL:
            kinds.add(_char_kind(av))
        elif op is _c.RANGE and av[1] < 128:
            kinds.update(_char_kind(ch) for ch in range(av[0], av[1] + 1))
        elif op is _c.CATEGORY and av in (_c.CATEGORY_DIGIT, _c.CATEGORY_WORD):
            kinds.add(_WORD)
        elif op is _c.CATEGORY and av in (_c.CATEGORY_SPACE, _c.CATEGORY_NOT_WORD):
            kinds.add(_NONWORD)
        else:
            return _EITHER  # a negation, other categories, wide ranges
    return kinds.pop() if len(kinds) == 1 else _EITHER


def _upper_too(items: list[tuple[Any, Any]]) -> list[tuple[Any, Any]]:
    """A (folded) class that also takes the upper case of each lowercase letter it holds (negated or not)."""
    out = list(items)
    for op, av in items:
        if op is _c.LITERAL and 97 <= av <= 122:
            out.append((_c.LITERAL, av - 32))
        elif op is _c.RANGE and max(av[0], 97) <= min(av[1], 122):
            out.append((_c.RANGE, (max(av[0], 97) - 32, min(av[1], 122) - 32)))
    return out


def _wordcased(seq: Any, before: str, apply: bool) -> str:
    """Rewrite, in place when `apply`, a folded pattern's items for the `wordcase` text; `before` tells what the
    character before them is in any match (a word character, none or either). Returns what the last character
    matched by them is. A letter after no word character is upper case there, after one lower case, else either;
    classes take both cases of their letters; a `\b` right before an upper-case letter is implied by it."""
    data = seq.data
    for k, (op, av) in enumerate(data):
        if op is _c.LITERAL:
            if apply and 97 <= av <= 122:
                data[k] = (_c.LITERAL, av - 32) if before == _NONWORD else (_c.LITERAL, av) if before == _WORD else \
                    (_c.IN, [(_c.LITERAL, av), (_c.LITERAL, av - 32)])
            before = _char_kind(av)
        elif op is _c.NOT_LITERAL:
            if apply and 97 <= av <= 122:
                data[k] = (_c.IN, [(_c.NEGATE, None), (_c.LITERAL, av), (_c.LITERAL, av - 32)])
            before = _EITHER
        elif op is _c.IN:
            if apply:
                data[k] = (op, _upper_too(av))
            before = _class_kind(av)
        elif op is _c.ANY:
            before = _EITHER
        elif op is _c.AT:
            if av in (_c.AT_BOUNDARY, _c.AT_BEGINNING, _c.AT_BEGINNING_STRING, _c.AT_BEGINNING_LINE):
                before = _NONWORD  # (for a letter right after it: a `\b` before a letter has no word character before)
            elif av is _c.AT_NON_BOUNDARY:
                before = _WORD
        elif op is _c.SUBPATTERN:
            before = _wordcased(av[3], before, apply)
        elif op is _c.BRANCH:
            ends = {_wordcased(b, before, apply) for b in av[1]}
            before = ends.pop() if len(ends) == 1 else _EITHER
        elif op in _REPEATS:
            lo, hi, body = av
            start = before
            if hi > 1 and _wordcased(body, before, False) != before:
                start = _EITHER  # a later round follows the body's own end
            end = _wordcased(body, start, apply)
            before = end if lo >= 1 else (end if end == before else _EITHER)
        elif op in (_c.ASSERT, _c.ASSERT_NOT):
            _wordcased(av[1], before if av[0] == 1 else _EITHER, apply)  # (a look-behind's start is not known)
        elif hasattr(_c, "ATOMIC_GROUP") and op is _c.ATOMIC_GROUP:
            before = _wordcased(av, before, apply)
        else:
            raise _Unfoldable  # back-references, conditionals
    if apply:
        seq.data = [it for i, it in enumerate(data) if not (it == (_c.AT, _c.AT_BOUNDARY) and i + 1 < len(data) and
                                                             data[i + 1][0] is _c.LITERAL and 65 <= data[i + 1][1] <= 90)]
    return before


def _spell_branches(seq: Any) -> None:
    """Spell out, in place, the small class that opens an alternative, in every alternation of the tree ("[aA]pollo|
    [bB]aidu" -> "Apollo|apollo|Baidu|baidu"; `_merge_prefixes` then gathers them again by opening): only the one
    for the character at hand can match, in the class's place, and `re` skips an alternative that opens with a
    literal after one compare (a class needs a set look-up)."""
    for k, (op, av) in enumerate(seq.data):
        for kid in _children(op, av):
            _spell_branches(kid)
        if op is _c.BRANCH:
            alts = []
            for b in av[1]:
                d = b.data
                chars = _class_chars(d[0][1]) if d and d[0][0] is _c.IN else None
                alts += [_p.SubPattern(seq.state, [(_c.LITERAL, ch)] + d[1:]) for ch in chars] if chars else [b]
            seq.data[k] = (op, (av[0], alts))


def _scoped_flags(seq: Any) -> bool:
    """Does any group of the tree switch flags on or off ("(?i:...)", "(?-i:...)")?"""
    return any((op is _c.SUBPATTERN and av[1] | av[2]) or any(_scoped_flags(kid) for kid in _children(op, av))
               for op, av in seq.data)


def folded(rx: re.Pattern[str]) -> re.Pattern[str] | None:
    """The case-sensitive twin of an IGNORECASE pattern for lowercase ASCII texts, or None.

    Why: with IGNORECASE, `re` enters every alternative of an alternation at every position; case-sensitive
    alternatives starting with a literal are skipped after one character compare. On the extractor's word lists
    that makes the same scan several times faster."""
    return _folded_scanner(rx, words=False)


def word_scanner(rx: re.Pattern[str]) -> re.Pattern[str] | None:
    """The folded scanner of an IGNORECASE pattern for the `wordcase` text of ASCII texts, where that lets `re` skip
    to a first literal or set of first characters; else None."""
    return _folded_scanner(rx, words=True)


def _folded_scanner(rx: re.Pattern[str], words: bool) -> re.Pattern[str] | None:
    """`_scanner(rx, fold=True, words=words)` for an IGNORECASE str pattern, None where it is not derivable."""
    if not isinstance(rx.pattern, str) or not rx.flags & re.IGNORECASE or rx.flags & (re.LOCALE | re.ASCII):
        return None
    try:
        return _scanner(rx, fold=True, words=words)
    except _Unfoldable:
        return None
    except Exception:  # an unexpected parse-tree shape: keep the original pattern only (always correct)
        return None


def twin(rx: re.Pattern[str]) -> re.Pattern[str] | None:
    r"""A case-sensitive pattern recompiled for ASCII texts, where it matches exactly as the original (every span
    and group), or None.

    Why: a pattern opening with `\b` ("\bEGO\b", "\bEGO\s+EGOD\b") is tried by `re` at every position of the
    text; with the boundary moved behind its first literal `re` looks for that literal in C, ~10x faster on a
    narrative. ASCII classes spare a Unicode category query per character."""
    if not isinstance(rx.pattern, str) or rx.flags & (re.IGNORECASE | re.LOCALE | re.ASCII):
        return None
    try:
        return _scanner(rx, fold=False)
    except _Unfoldable:
        return None
    except Exception:  # an unexpected parse-tree shape: keep the original pattern only (always correct)
        return None


def _reversed(seq: Any) -> list[tuple[Any, Any]]:
    r"""The parse-tree items of `seq` for the reversed text: the sequence and every group in it read backwards.
    Assertions other than the symmetric `\b`/`\B` are dropped and possessive or atomic parts made plain: the
    reversed pattern then matches the reverse of every match of the original, and perhaps more (a gate needs
    no more than that)."""
    out: list[tuple[Any, Any]] = []
    for op, av in reversed(seq.data):
        if op in (_c.LITERAL, _c.NOT_LITERAL, _c.IN, _c.ANY):
            out.append((op, av))
        elif op is _c.AT:
            if av in (_c.AT_BOUNDARY, _c.AT_NON_BOUNDARY):
                out.append((op, av))  # depends on the characters on both sides: the same read backwards
            elif av is _c.AT_BEGINNING_STRING or av is _c.AT_BEGINNING and not seq.state.flags & re.MULTILINE:
                out.append((op, _c.AT_END_STRING))  # the text's start is the reversed text's end
        elif op is _c.SUBPATTERN:
            out.append((op, (None, av[1], av[2], _p.SubPattern(seq.state, _reversed(av[3])))))
        elif op is _c.BRANCH:
            out.append((op, (None, [_p.SubPattern(seq.state, _reversed(b)) for b in av[1]])))
        elif op in _REPEATS:
            lo, hi, body = av
            out.append((_c.MAX_REPEAT, (lo, hi, _p.SubPattern(seq.state, _reversed(body)))))
        elif hasattr(_c, "ATOMIC_GROUP") and op is _c.ATOMIC_GROUP:
            out.append((_c.SUBPATTERN, (None, 0, 0, _p.SubPattern(seq.state, _reversed(av)))))
        elif op in (_c.ASSERT, _c.ASSERT_NOT):
            continue  # dropped: the reversed pattern only matches more
        else:
            raise _Unfoldable  # back-references, conditionals
    return out


#: Reversed ends of ordinary text: a reversed pattern that accepts these accepts nearly every text.
_PLAIN_ENDS = ("x", " x", "x ", ".x")


def end_gate(rx: re.Pattern[str]) -> re.Pattern[str] | None:
    r"""For a pattern anchored at the text's end ("...\s*$"), the reversed pattern run anchored at the start of
    the reversed text: where it fails, the original has no match (every match ends at the end of the text, or
    before a final newline, and its reverse starts there). None for other patterns.

    Why: the extractor asks ~30 such patterns about the words just before a phrase ("the ", "did not "); `re`
    tries every position of that text from the left, while a match can only end at its end."""
    if not isinstance(rx.pattern, str) or rx.flags & re.MULTILINE:
        return None
    try:
        tree = _p.parse(rx.pattern, rx.flags)
        if not tree.data or tree.data[-1] not in ((_c.AT, _c.AT_END), (_c.AT, _c.AT_END_STRING)):
            return None
        rev: re.Pattern[str] = _compiler.compile(_p.SubPattern(tree.state, _reversed(tree)), rx.flags)
        if any(rev.match(t) for t in _PLAIN_ENDS):
            return None  # it passes any text ("\s*$"): a gate would be pure cost
        return rev
    except _Unfoldable:
        return None
    except Exception:  # an unexpected parse-tree shape: no gate (always correct)
        return None


def _start_anchored(rx: re.Pattern[str], tree: Any = None) -> bool:
    r"""Is the pattern anchored at the text's start (`\A`, or `^` without MULTILINE)? `re` then tries one position."""
    try:
        data = (tree if tree is not None else _p.parse(rx.pattern, rx.flags)).data
    except Exception:
        return False
    return bool(data) and (data[0] == (_c.AT, _c.AT_BEGINNING_STRING) or
                           data[0] == (_c.AT, _c.AT_BEGINNING) and not rx.flags & re.MULTILINE)


class Gated:
    """A compiled pattern behind a literal prefilter, an end gate and/or a faster scanner; the methods the extractor
    uses, with the same results as `re`. An IGNORECASE pattern's scanner runs on the lowercase text and finds where
    each match starts; the original, anchored there, returns the match (on the original text). A case-sensitive
    pattern's scanner (`twin`) matches the text itself exactly as the original does: its matches are returned."""

    __slots__ = ("rx", "factors", "cs", "fold", "end", "pattern", "flags", "groups", "words")

    def __init__(self, rx: re.Pattern[str], factors: frozenset[str] | None,
                 cs: re.Pattern[str] | None = None, end: re.Pattern[str] | None = None, words: bool = False) -> None:
        self.rx = rx
        self.words = words  # the folded scanner reads the `wordcase` text
        # Longest first: a long factor is rarer, so when the text holds one it is usually found early.
        self.factors = tuple(sorted(factors or (), key=lambda f: (-len(f), f)))
        self.cs = cs
        self.fold = bool(rx.flags & re.IGNORECASE)
        self.end = end
        self.pattern = rx.pattern
        self.flags = rx.flags
        self.groups = rx.groups

    def _low(self, s: str, whole: bool = True) -> str | None:
        """None: no match possible; "": scan with the original; else the text the scanner runs on (the lowercase
        text for a folded scan, the text itself for a twin). `whole`: the scan reads the text to its end (no
        `endpos`), so the end gate holds."""
        if len(s) < MIN_GATED_LEN:
            return ""
        end = self.end
        if end is not None and whole:
            r = s[::-1]
            if end.match(r) is None and not (r[:1] == "\n" and end.match(r, 1) is not None):
                return None
        if not self.fold:
            # Case-sensitive: the factors are the literals as written, in the text itself.
            if self.factors:
                for f in self.factors:
                    if f in s:
                        break
                else:
                    return None
            return s if self.cs is not None and s.isascii() else ""
        low = _LOWER.get(s, _MISSING)  # `_lower_ascii`, inlined: this runs before every scan of every pattern
        if low is _MISSING:
            low = _lower_ascii(s)
        if low is None:
            return ""
        if self.factors:
            for f in self.factors:
                if f in low:
                    break
            else:
                return None
        if self.cs is None:
            return ""
        return wordcase(low) if self.words else low

    def _may_match(self, s: str, whole: bool = True) -> bool:
        return self._low(s, whole) is not None

    def _original(self, s: str, m: re.Match[str]) -> re.Match[str]:
        """The original pattern's match at the folded match's start (the same match)."""
        r = self.rx.match(s, m.start())
        if r is None or r.end() != m.end():  # never expected: fail loudly rather than change a result
            raise RuntimeError(f"folded pattern disagrees with {self.rx.pattern!r} at {m.start()} of {s!r}")
        return r

    def _iter(self, s: str, low: str, pos: int = 0) -> Iterator[re.Match[str]]:
        # The folded scan finds where each match starts; the original, anchored there, gives the same match.
        anchored = self.rx.match  # inlined `_original`: this loop runs for every match of every scan
        for m in self.cs.finditer(low, pos):  # type: ignore[union-attr]
            r = anchored(s, m.start())
            if r is None or r.end() != m.end():
                self._original(s, m)  # raises, naming the disagreement
            yield r  # type: ignore[misc]

    def search(self, s: str, *a: Any) -> re.Match[str] | None:
        low = self._low(s, len(a) < 2)
        if low is None:
            return None
        if not low:
            return self.rx.search(s, *a)
        if not self.fold:
            return self.cs.search(s, *a)  # type: ignore[union-attr]
        if len(a) > 1:
            return self.rx.search(s, *a)
        m = self.cs.search(low, *a)  # type: ignore[union-attr]
        return None if m is None else self._original(s, m)

    def match(self, s: str, *a: Any) -> re.Match[str] | None:
        if not self.factors and self.end is None:
            return self.rx.match(s, *a)  # no check to make: lowering the text would be pure cost
        return self.rx.match(s, *a) if self._may_match(s, len(a) < 2) else None

    def fullmatch(self, s: str, *a: Any) -> re.Match[str] | None:
        if not self.factors and self.end is None:
            return self.rx.fullmatch(s, *a)
        return self.rx.fullmatch(s, *a) if self._may_match(s, len(a) < 2) else None

    def finditer(self, s: str, *a: Any) -> Iterator[re.Match[str]]:
        low = self._low(s, len(a) < 2)
        if low is None:
            return iter(())
        if not low:
            return self.rx.finditer(s, *a)
        if not self.fold:
            return self.cs.finditer(s, *a)  # type: ignore[union-attr]
        if len(a) > 1:
            return self.rx.finditer(s, *a)
        return self._iter(s, low, *a)

    def findall(self, s: str, *a: Any) -> list[Any]:
        low = self._low(s, len(a) < 2)
        if low is None:
            return []
        if not low:
            return self.rx.findall(s, *a)
        if not self.fold:
            return self.cs.findall(s, *a)  # type: ignore[union-attr]
        if a:
            return self.rx.findall(s, *a)
        if self.groups == 0:
            return [m.group(0) for m in self._iter(s, low)]
        if self.groups == 1:
            return [m.groups("")[0] for m in self._iter(s, low)]
        return [m.groups("") for m in self._iter(s, low)]

    def sub(self, repl: str | Callable[[re.Match[str]], str], s: str, count: int = 0) -> str:
        low = self._low(s)
        if low is None:
            return s
        if not low:
            return self.rx.sub(repl, s, count)
        if not self.fold:
            return self.cs.sub(repl, s, count)  # type: ignore[union-attr]
        # A match of a folded pattern is never empty (see `gate`), so `sub` is exactly the matches of `finditer`
        # replaced in order; `expand` reads a template as `sub` does.
        # A template without a backslash is literal text, for `sub` too: no need to expand it per match.
        literal = repl if isinstance(repl, str) and "\\" not in repl else None
        parts: list[str] = []
        last = 0
        for n, m in enumerate(self._iter(s, low), 1):
            text = literal if literal is not None else repl(m) if callable(repl) else m.expand(repl)
            parts += [s[last:m.start()], text]
            last = m.end()
            if count and n >= count:
                break
        if not parts:
            return s
        parts.append(s[last:])
        return "".join(parts)

    def split(self, s: str, *a: Any) -> list[str]:
        low = self._low(s)
        if low is None:
            return [s]
        if low and not self.fold:
            return self.cs.split(s, *a)  # type: ignore[union-attr]  # a twin matches as the original does
        return self.rx.split(s, *a)

    def __repr__(self) -> str:
        return (f"Gated({self.rx!r}, factors={self.factors!r}, folded={self.cs is not None and self.fold}, "
                f"twin={self.cs is not None and not self.fold}, end_gate={self.end is not None})")


def gate(rx: re.Pattern[str]) -> re.Pattern[str]:
    """`rx` behind a literal prefilter, an end gate and/or a faster scanner when derivable, else `rx` itself (typed
    as a pattern for callers)."""
    try:  # parsed once for the checks below, which only read the tree (the scanners rewrite their own parse)
        tree = _p.parse(rx.pattern, rx.flags) if isinstance(rx.pattern, str) else None
    except Exception:  # an unexpected parser: no gate (always correct)
        return rx
    if _start_anchored(rx, tree):
        # `re` tries one position: any check (a factor looked for in the whole text, the text lowered for a folded
        # scan) costs more than the attempt (measured: ~2.7x on "^\s*(?:on|at|...)").
        return rx
    fs = factors_of(rx, tree)
    # The folded scanner only for patterns that cannot match an empty string: `sub` and `finditer` above rely
    # on it (their empty-match rules would otherwise need copying). A twin matches exactly as the original, empty
    # matches included.
    try:
        nonempty = tree is not None and tree.getwidth()[0] > 0
    except Exception:  # an unexpected parser: no folded scan (always correct)
        nonempty = False
    words = False
    if rx.flags & re.IGNORECASE:
        cs = word_scanner(rx) if nonempty else None
        words = cs is not None
        cs = cs or (folded(rx) if nonempty else None)
    else:
        cs = twin(rx)
    # (Where factors exist, looking for them costs less than the reversed match: measured on the dev narratives.)
    end = end_gate(rx) if not fs else None
    return Gated(rx, fs, cs, end, words) if fs or cs or end else rx  # type: ignore[return-value]


def compile_gated(pattern: str, flags: int = 0) -> re.Pattern[str]:
    """`re.compile` + `gate`, done on first use (`LazyPattern`): the extractor's modules define a few hundred
    patterns at import, and building them all cost most of a cold `txt2sce extract`."""
    return LazyPattern(pattern, flags)  # type: ignore[return-value]


_METHODS = ("search", "match", "fullmatch", "finditer", "findall", "sub", "split")
#: Every live lazy pattern, so a test can build them all (a malformed pattern must not wait for the narrative that
#: reaches it) and `build_all` can warm a process that forks workers. Weak: patterns made per operator name and
#: dropped from their cache must not live on here.
_LAZY: "weakref.WeakSet[LazyPattern]" = weakref.WeakSet()


class LazyPattern:
    """A pattern that is compiled and gated (`gate`) the first time it is used. The first call of any method
    builds it and puts the built pattern's own bound methods on the instance, where they shadow the class's: every
    later call costs what a call of the built pattern costs. `pattern` and `flags` are there from the start."""

    def __init__(self, pattern: str, flags: int = 0) -> None:
        self.pattern = pattern
        self.flags = flags
        self._built: re.Pattern[str] | None = None
        _LAZY.add(self)

    def built(self) -> re.Pattern[str]:
        """The compiled, gated pattern (a `Gated` or a plain `re.Pattern`), built now if it was not yet."""
        b = self._built
        if b is None:
            b = self._built = gate(re.compile(self.pattern, self.flags))
            for name in _METHODS:
                setattr(self, name, getattr(b, name))
        return b

    @property
    def groups(self) -> int:
        return self.built().groups

    def search(self, *a: Any) -> re.Match[str] | None:
        return self.built().search(*a)

    def match(self, *a: Any) -> re.Match[str] | None:
        return self.built().match(*a)

    def fullmatch(self, *a: Any) -> re.Match[str] | None:
        return self.built().fullmatch(*a)

    def finditer(self, *a: Any) -> Iterator[re.Match[str]]:
        return self.built().finditer(*a)

    def findall(self, *a: Any) -> list[Any]:
        return self.built().findall(*a)

    def sub(self, *a: Any) -> str:
        return self.built().sub(*a)

    def split(self, *a: Any) -> list[str]:
        return self.built().split(*a)

    def __repr__(self) -> str:
        return f"LazyPattern({self.pattern!r}, {self.flags!r}, built={self._built is not None})"


def build_all() -> int:
    """Build every lazy pattern made so far (before forking workers, or in a test); how many there are."""
    live = list(_LAZY)
    for lp in live:
        lp.built()
    return len(live)


# `re`'s module functions over gated, folded patterns, for the extractor's rules that name their pattern inline.
# Cached like `re`'s own cache; patterns built from the text ("the <noun>") make it grow, so it is bounded.
_CACHE: dict[tuple[str, int], re.Pattern[str]] = {}
_CACHE_MAX = 1024


def cached(pattern: str, flags: int = 0) -> re.Pattern[str]:
    """`compile_gated`, from the module functions' cache: for a pattern a rule needs as an object."""
    return _cached(pattern, flags)


def _cached(pattern: str, flags: int) -> re.Pattern[str]:
    key = (pattern, flags)  # a RegexFlag hashes and compares as its int: no conversion per call
    rx = _CACHE.get(key)
    if rx is None:
        if len(_CACHE) >= _CACHE_MAX:
            _CACHE.clear()
        rx = _CACHE[key] = gate(re.compile(pattern, flags))  # used at once: no lazy wrapper
    return rx


def search(pattern: str, string: str, flags: int = 0) -> re.Match[str] | None:
    return _cached(pattern, flags).search(string)


def match(pattern: str, string: str, flags: int = 0) -> re.Match[str] | None:
    return _cached(pattern, flags).match(string)


def fullmatch(pattern: str, string: str, flags: int = 0) -> re.Match[str] | None:
    return _cached(pattern, flags).fullmatch(string)


def finditer(pattern: str, string: str, flags: int = 0) -> Iterator[re.Match[str]]:
    return _cached(pattern, flags).finditer(string)


def findall(pattern: str, string: str, flags: int = 0) -> list[Any]:
    return _cached(pattern, flags).findall(string)


def sub(pattern: str, repl: str | Callable[[re.Match[str]], str], string: str, count: int = 0,
        flags: int = 0) -> str:
    return _cached(pattern, flags).sub(repl, string, count)


def split(pattern: str, string: str, maxsplit: int = 0, flags: int = 0) -> list[str]:
    return _cached(pattern, flags).split(string, maxsplit)


def blank(rx: re.Pattern[str], string: str) -> str:
    """`string` with each match of `rx` replaced by as many spaces: the words are gone, every offset stays."""
    return rx.sub(lambda m: " " * len(m.group(0)), string)
