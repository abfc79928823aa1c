"""Subdivision of a storey's outline into spaces (Infinigen Indoors, D.2).

A Mondrian process splits the outline's bounding rectangle along grid lines, picking large
rectangles first and cutting across their longer side, until there are about 1.5 times as many
spaces as rooms; splits that leave a piece thinner than `min_side` cells or more elongated than
`max_aspect` are rejected. Adjacent spaces are then merged, smallest first, until there are as
many spaces as rooms. The result is a label array (space index per cell, -1 outside).
"""
from __future__ import annotations

import numpy as np
from scipy import ndimage

from indoorgen.floorplan.grid import OUTSIDE, Grid, opening

#: Narrowest space (cells) a split may leave: 3 cells = 1.5 m.
MIN_SIDE = 3
MAX_ASPECT = 3.0


def _inside_bbox(inside: np.ndarray, r: tuple[int, int, int, int]):
    """Bounding box (y0, x0, y1, x1) of the inside cells of rectangle r, or None if empty."""
    y0, x0, y1, x1 = r
    sub = inside[y0:y1, x0:x1]
    if not sub.any():
        return None
    rows, cols = np.flatnonzero(sub.any(axis=1)), np.flatnonzero(sub.any(axis=0))
    return y0 + rows[0], x0 + cols[0], y0 + rows[-1] + 1, x0 + cols[-1] + 1


def _ok(inside: np.ndarray, r, min_side: int, max_aspect: float) -> bool:
    """A piece is acceptable if it is empty, or its inside cells are not too elongated and
    nowhere narrower than `min_side` (the outline may cut a rectangle into an L or a sliver)."""
    b = _inside_bbox(inside, r)
    if b is None:
        return True  # an empty piece simply disappears
    h, w = b[2] - b[0], b[3] - b[1]
    if min(h, w) < min_side or max(h, w) / min(h, w) > max_aspect:
        return False
    sub = inside[b[0]:b[2], b[1]:b[3]]
    return bool(sub.all()) or not (sub & ~opening(sub, min_side)).any()


def _forced(b, fixed) -> list[tuple[int, int, int, int]]:
    """Cut rectangle b along the four sides of the rectangle `fixed` (inside it): bands above
    and below across the whole width, then the pieces left and right of `fixed`."""
    y0, x0, y1, x1 = b
    fy0, fx0, fy1, fx1 = fixed
    out = []
    if fy0 > y0:
        out.append((y0, x0, fy0, x1))
    if fy1 < y1:
        out.append((fy1, x0, y1, x1))
    if fx0 > x0:
        out.append((fy0, x0, fy1, fx0))
    if fx1 < x1:
        out.append((fy0, fx1, fy1, x1))
    return out + [tuple(fixed)]


def mondrian(rng: np.random.Generator, grid: Grid, n_spaces: int, min_side: int = MIN_SIDE,
             max_aspect: float = MAX_ASPECT,
             fixed: tuple[int, int, int, int] | None = None) -> np.ndarray:
    """Split the grid's inside cells into about `n_spaces` rectangles (fewer if no valid split
    remains); returns the label array. A `fixed` rectangle (iy0, ix0, iy1, ix1), the staircase
    placeholder, is cut out first and never split, so it lies within a single space."""
    inside = grid.inside
    b = _inside_bbox(inside, (0, 0, *inside.shape))
    rects = [r for r in (_forced(b, fixed) if fixed is not None else [b])
             if _inside_bbox(inside, r) is not None]
    frozen = {tuple(fixed)} if fixed is not None else set()
    failures = 0
    while len(rects) < n_spaces and failures < 60:
        area = np.array([0.0 if tuple(r) in frozen else inside[r[0]:r[2], r[1]:r[3]].sum()
                         for r in rects], float)
        i = int(rng.choice(len(rects), p=area ** 1.5 / (area ** 1.5).sum()))
        y0, x0, y1, x1 = rects[i]
        h, w = y1 - y0, x1 - x0
        axis = 0 if rng.random() < h / (h + w) else 1  # 0: cut across y (horizontal line)
        side = h if axis == 0 else w
        if side < 2 * min_side:
            failures += 1
            continue
        cut = int(rng.integers(min_side, side - min_side + 1))
        if axis == 0:
            a, c = (y0, x0, y0 + cut, x1), (y0 + cut, x0, y1, x1)
        else:
            a, c = (y0, x0, y1, x0 + cut), (y0, x0 + cut, y1, x1)
        if not (_ok(inside, a, min_side, max_aspect) and _ok(inside, c, min_side, max_aspect)):
            failures += 1
            continue
        rects[i:i + 1] = [r for r in (a, c) if _inside_bbox(inside, r) is not None]
        failures = 0
    labels = np.full(inside.shape, OUTSIDE, np.int64)
    n = 0
    for y0, x0, y1, x1 in rects:
        comp, k = ndimage.label(inside[y0:y1, x0:x1])
        for piece in range(1, k + 1):
            labels[y0:y1, x0:x1][comp == piece] = n
            n += 1
    return labels


def adjacency(labels: np.ndarray) -> dict[tuple[int, int], int]:
    """Shared boundary length (cell edges) for each pair of adjacent labels (a < b)."""
    out: dict[tuple[int, int], int] = {}
    for a, b in ((labels[:-1], labels[1:]), (labels[:, :-1], labels[:, 1:])):
        m = (a != b) & (a >= 0) & (b >= 0)
        lo, hi = np.minimum(a[m], b[m]), np.maximum(a[m], b[m])
        keys, counts = np.unique(lo * 100003 + hi, return_counts=True)
        for k, c in zip(keys.tolist(), counts.tolist(), strict=False):
            pair = (k // 100003, k % 100003)
            out[pair] = out.get(pair, 0) + c
    return out


def grow_hub(rng: np.random.Generator, labels: np.ndarray, degree: int, n_target: int,
             door: int = MIN_SIDE, keep_apart: np.ndarray | None = None) -> np.ndarray:
    """Merge spaces into one hub with at least `degree` neighbours it shares a door-wide wall
    (`door` cell edges) with, for a room graph with a room of that degree (the living room or a
    shared hallway). Stops at `n_target` spaces; never merges cells of `keep_apart` (the
    staircase placeholder) into the hub."""
    labels = labels.copy()
    blocked = set(np.unique(labels[keep_apart]).tolist()) if keep_apart is not None else set()

    def door_nbrs(adj, a):
        return {b if x == a else x for (x, b), n in adj.items() if a in (x, b) and n >= door}

    adj = adjacency(labels)
    ids = [int(i) for i in np.unique(labels[labels >= 0]) if int(i) not in blocked]
    if not ids:
        return labels
    deg = np.array([len(door_nbrs(adj, a)) for a in ids], float)
    hub = ids[int(rng.choice(len(ids), p=(deg + 0.5) ** 3 / ((deg + 0.5) ** 3).sum()))]
    while len(np.unique(labels[labels >= 0])) > n_target:
        have = door_nbrs(adj, hub)
        if len(have) >= degree:
            break
        best = None
        for b in sorted({b if x == hub else x for (x, b) in adj if hub in (x, b)} - blocked):
            trial = np.where(labels == b, hub, labels)
            gain = len(door_nbrs(adjacency(trial), hub))
            key = (gain, -int((labels == b).sum()), rng.random())
            if best is None or key > best[0]:
                best = (key, b, trial)
        if best is None or best[0][0] <= len(have) - 1:
            break
        labels = best[2]
        adj = adjacency(labels)
    return labels


def _narrow(labels: np.ndarray, a: int, min_side: int) -> bool:
    """Whether space a is somewhere narrower than `min_side` cells."""
    m = labels == a
    rows, cols = np.flatnonzero(m.any(axis=1)), np.flatnonzero(m.any(axis=0))
    sub = m[rows[0]:rows[-1] + 1, cols[0]:cols[-1] + 1]
    if sub.all():
        return min(sub.shape) < min_side
    return bool((sub & ~opening(sub, min_side)).any())


def merge(rng: np.random.Generator, labels: np.ndarray, n_target: int,
          min_side: int = MIN_SIDE) -> np.ndarray:
    """Merge adjacent spaces until `n_target` remain: first any space narrower than
    `min_side` (a sliver the outline or the staircase cut left), then the smallest (sometimes a
    random one); returns relabelled 0..n-1 labels."""
    labels = labels.copy()
    while True:
        ids, sizes = np.unique(labels[labels >= 0], return_counts=True)
        narrow = [int(a) for a in ids if _narrow(labels, int(a), min_side)]
        if len(ids) <= n_target and not narrow:
            break
        if len(ids) == 1:
            break
        adj = adjacency(labels)
        if narrow:
            a = narrow[0]
        elif rng.random() < 0.7:
            a = int(ids[np.argmin(sizes + rng.random(len(sizes)) * 0.5)])
        else:
            a = int(ids[rng.integers(len(ids))])
        nbrs = [(b if x == a else x, n) for (x, b), n in adj.items() if a in (x, b)]
        if not nbrs:
            break
        w = np.array([n ** 2 for _, n in nbrs], float)
        for k, (b, _) in enumerate(nbrs):
            both = (labels == a) | (labels == b)
            ys, xs = np.nonzero(both)
            if both.sum() == (np.ptp(ys) + 1) * (np.ptp(xs) + 1):
                w[k] *= 4.0  # the union is a rectangle
        b = nbrs[int(rng.choice(len(nbrs), p=w / w.sum()))][0]
        labels[labels == max(a, b)] = min(a, b)
    _, inv = np.unique(labels, return_inverse=True)
    out = inv.reshape(labels.shape) - (1 if (labels < 0).any() else 0)
    return np.where(labels < 0, OUTSIDE, out)
