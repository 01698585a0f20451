"""Diversity-aware pruning (paper §III-D.1, §IV-C): cluster the nodes of one tree layer by identical feature
vectors and keep a configurable share of every cluster, chosen by a seeded Generator. Pruned nodes are neither
written nor expanded, so pruning also bounds the tree's growth."""

from __future__ import annotations

import math
from collections.abc import Hashable, Sequence

import numpy as np


def clusters(vectors: Sequence[Hashable]) -> list[list[int]]:
    """Indices grouped by identical vector, clusters in order of first appearance (deterministic)."""
    groups: dict[Hashable, list[int]] = {}
    for i, v in enumerate(vectors):
        groups.setdefault(v, []).append(i)
    return list(groups.values())


def keep_count(size: int, share: float) -> int:
    """How many of a cluster of `size` survive: ceil(share·size), at least one (a cluster is never emptied: it is
    a distinct scenario category)."""
    return max(1, min(size, math.ceil(share * size - 1e-9)))


def prune(vectors: Sequence[Hashable], share: float, rng: np.random.Generator) -> list[int]:
    """Sorted indices of the nodes kept. share >= 1 keeps everything without drawing from `rng`."""
    if share >= 1.0:
        return list(range(len(vectors)))
    kept: list[int] = []
    for group in clusters(vectors):
        k = keep_count(len(group), share)
        if k == len(group):
            kept.extend(group)
        else:
            pick = rng.choice(len(group), size=k, replace=False)
            kept.extend(group[int(i)] for i in pick)
    return sorted(kept)


def spread(indices: Sequence[int], vectors: Sequence[Hashable], limit: int) -> list[int]:
    """At most `limit` of `indices`, taken round robin over their clusters (first member of every cluster, then
    the second…), so a node budget drops repeats of a category before it drops a category. Sorted."""
    if len(indices) <= limit:
        return list(indices)
    groups = clusters(vectors)
    out: list[int] = []
    rank = 0
    while len(out) < limit:
        for g in groups:
            if rank < len(g) and len(out) < limit:
                out.append(indices[g[rank]])
        rank += 1
    return sorted(out)


def spread_covering(indices: Sequence[int], vectors: Sequence[Hashable], labels: Sequence[Hashable],
                    limit: int) -> list[int]:
    """Like `spread`, but first one member of every `labels` value (the variant an enumerated block takes: a
    bicycle, a yellow light), in `spread`'s round-robin order, then the rest by `spread`. Sorted."""
    if len(indices) <= limit:
        return list(indices)
    ranked = sorted(range(len(indices)), key=_round_robin_rank(vectors))
    first: dict[Hashable, int] = {}
    for pos in ranked:
        first.setdefault(labels[pos], pos)
    chosen = list(first.values())[:limit]            # filled in round-robin order
    taken = set(chosen)
    rest = [pos for pos in range(len(indices)) if pos not in taken]
    if len(chosen) < limit and rest:
        chosen += spread(rest, [vectors[p] for p in rest], limit - len(chosen))
    return sorted(indices[p] for p in chosen)


def _round_robin_rank(vectors: Sequence[Hashable]):
    """Sort key: the round in which `spread` takes a position (first members of clusters first), then cluster."""
    rank: dict[int, tuple[int, int]] = {}
    for ci, group in enumerate(clusters(vectors)):
        for r, pos in enumerate(group):
            rank[pos] = (r, ci)
    return rank.__getitem__


def diagonal(keep: Sequence[int], variants: int, limit: int, *, cover: bool = False) -> list[int]:
    """At most `limit` of the candidate indices `keep` of one layer (candidate i = parent i // variants, version
    i % variants), chosen along diagonals: in round r every parent p gets version (p + r) mod variants, so a
    small budget spreads the layer's versions over different parents (a standing start under a snowy road and
    another under a dry one) instead of giving every version to the first parent and none to the others.
    `cover` (enumerated blocks): first one candidate per version value, each under the first parent without a
    version yet where it survived pruning (so version j under parent j while there are parents), then under
    parent j mod parents. Sorted."""
    if len(keep) <= limit:
        return list(keep)
    parents = max(1, (max(keep) // variants) + 1)
    kept = set(keep)
    chosen: list[int] = []
    if cover:
        taken_parents: set[int] = set()
        for j in range(variants):
            here = [i for i in keep if i % variants == j]
            if not here or len(chosen) >= limit:
                continue
            # the first parent still without a version (where the version survived pruning and fits it), so
            # the versions spread over the parents; once every parent has one, parent j mod parents
            free = [i for i in here if i // variants not in taken_parents]
            want = (j % parents) * variants + j
            pick = free[0] if free else (want if want in kept else here[0])
            chosen.append(pick)
            taken_parents.add(pick // variants)
    taken = set(chosen)
    order = sorted((i for i in keep if i not in taken),
                   key=lambda i: (((i % variants) - (i // variants)) % variants, i // variants))
    chosen += order[:max(0, limit - len(chosen))]
    return sorted(chosen)
