"""Assignment of a storey's rooms to its spaces (Infinigen Indoors, D.2).

A depth-first search gives each room of the storey graph its own space so that:

- graph neighbours share a straight wall long enough for a door (MIN_DOOR_WALL, full cells);
- bedrooms, garages, balconies and the entrance room have a straight exterior wall of the
  length `rules.exterior_wall_needed` gives (a window, the front door, a garage's vehicle door,
  a balcony's open front);
- the staircase room's space overlaps the staircase placeholder, and other rooms' spaces do not
  lose much to it;
- every room's space is at least the minimum area of its type.

A service room (a bathroom, closet, utility or staircase room) tries a space more than
`OVERSIZE` times its ideal area only after every other: it takes one when nothing else works
(a plan is never dropped for it), not because the noise ranked it first.

Candidates are tried closest to the room's ideal area first (with a little noise), and the
search gives up after a budget of expansions so a hopeless subdivision is dropped quickly.
"""
from __future__ import annotations

import math

import networkx as nx
import numpy as np

from indoorgen.constraints.room_terms import MIN_DOOR_WALL, SERVICE_ROOMS
from indoorgen.floorplan.grid import OUTSIDE, Grid, room_polygon, runs
from indoorgen.floorplan.rooms import room_type_of
from indoorgen.floorplan.rules import exterior_wall_needed
from indoorgen.floorplan.view import polygon_exterior_runs
from indoorgen.model.room_types import ROOM_TYPES, STAIRCASE_ROOM

#: a service room's space this many times its ideal area is oversized (a 24 m^2 bathroom for
#: a 9 m^2 share)
OVERSIZE = 1.6
#: what an oversized space adds to its sorting cost: more than any closeness and noise do
OVERSIZE_LAST = 100.0


def space_stats(grid: Grid, labels: np.ndarray, stair: np.ndarray | None):
    """Per space: area (m^2, outside the placeholder), placeholder cells, longest straight
    exterior wall (cells); per pair of spaces: longest straight shared wall (cells)."""
    n = int(labels.max()) + 1
    cell = grid.size ** 2
    lab = labels[labels >= 0]
    frac = grid.frac[labels >= 0]
    st = stair[labels >= 0] if stair is not None else np.zeros(len(lab), bool)
    area = np.bincount(lab, weights=frac * ~st, minlength=n) * cell
    in_stair = np.bincount(lab, weights=st.astype(float), minlength=n)
    cells = np.bincount(lab, minlength=n)
    ext = np.zeros(n, np.int64)
    door: dict[tuple[int, int], int] = {}
    for r in runs(labels, grid.full):
        if r.left == OUTSIDE or r.right == OUTSIDE:
            s = r.right if r.left == OUTSIDE else r.left
            ext[s] = max(ext[s], r.length)
        else:
            key = (min(r.left, r.right), max(r.left, r.right))
            door[key] = max(door.get(key, 0), r.length)
    # spaces the outline cuts: their straight edges on the outline (any direction)
    for s in np.unique(lab[grid.partial[labels >= 0]]).tolist():
        poly = room_polygon(grid, labels == s)
        if poly is not None:
            walls = polygon_exterior_runs(np.asarray(poly.exterior.coords)[:-1], grid.contour)
            if walls:
                ext[s] = max(ext[s], int(walls[0][0] / grid.size + 1e-9))
    return area, in_stair, cells, ext, door


def assign(rng: np.random.Generator, graph: nx.Graph, entry: str, grid: Grid,
           labels: np.ndarray, stair: np.ndarray | None, ideal: dict[str, float],
           needs_exterior: set[str], budget: int = 400) -> dict[str, int] | None:
    """Map every room of `graph` to a distinct space of `labels`, or None if the search finds
    no assignment within `budget` expansions. `needs_exterior` names rooms beyond the exterior
    types that need an outside wall (the entrance)."""
    rooms = list(graph.nodes)
    n_spaces = int(labels.max()) + 1
    if n_spaces != len(rooms):
        return None
    area, in_stair, cells, ext, door = space_stats(grid, labels, stair)
    k_door = int(math.ceil(MIN_DOOR_WALL / grid.size - 1e-9))
    door_ok: list[set[int]] = [set() for _ in range(n_spaces)]
    for (a, b), n in door.items():
        if n >= k_door:
            door_ok[a].add(b)
            door_ok[b].add(a)
    order = [r for r in rooms if room_type_of(r) == STAIRCASE_ROOM]
    order += [r for r in nx.bfs_tree(graph, entry) if r not in order]
    order += [r for r in rooms if r not in order]
    # the spaces each room could take at all (type, exterior, staircase, area), best first
    fits: dict[str, list[int]] = {}
    for r in rooms:
        t = room_type_of(r)
        out = []
        for s in range(n_spaces):
            if t == STAIRCASE_ROOM:
                if in_stair[s] == 0:
                    continue
            elif in_stair[s] > 0.3 * cells[s] or area[s] < ROOM_TYPES[t].min_area:
                continue
            if (ROOM_TYPES[t].exterior or r in needs_exterior) and \
                    ext[s] * grid.size < exterior_wall_needed(r) - 1e-6:
                continue
            if len(door_ok[s]) < graph.degree(r):
                continue  # too few door-wide neighbours for the room's graph neighbours
            out.append(s)
        noise = rng.normal(0.0, 0.25, len(out))
        cost = [abs(math.log(max(area[s], 0.1) / ideal[r])) + e
                + (OVERSIZE_LAST if t in SERVICE_ROOMS and area[s] > OVERSIZE * ideal[r] else 0.0)
                for s, e in zip(out, noise, strict=False)]
        fits[r] = [s for _, s in sorted(zip(cost, out, strict=False))]
    nbrs = {r: list(graph.neighbors(r)) for r in rooms}

    def candidates(r: str, used: set[int], placed: dict[str, int]) -> list[int]:
        placed_nb = [placed[nb] for nb in nbrs[r] if nb in placed]
        return [s for s in fits[r] if s not in used and all(p in door_ok[s] for p in placed_nb)]

    expansions = 0
    placed: dict[str, int] = {}
    used: set[int] = set()

    def dfs(i: int) -> bool:
        nonlocal expansions
        if i == len(order):
            return True
        r = order[i]
        for s in candidates(r, used, placed):
            expansions += 1
            if expansions > budget:
                return False
            used.add(s)
            placed[r] = s
            # forward check: every unplaced neighbour must keep some space next to this one
            if all(any(x not in used and x in door_ok[s] for x in fits[nb])
                   for nb in nbrs[r] if nb not in placed) and dfs(i + 1):
                return True
            del placed[r]
            used.discard(s)
        return False

    return dict(placed) if dfs(0) else None


def relabel(labels: np.ndarray, mapping: dict[str, int], rooms: list[str]) -> np.ndarray:
    """Space labels -> room indices (position of each room in `rooms`)."""
    lut = np.full(int(labels.max()) + 2, OUTSIDE, np.int64)
    for i, r in enumerate(rooms):
        lut[mapping[r]] = i
    return np.where(labels >= 0, lut[labels], OUTSIDE)
