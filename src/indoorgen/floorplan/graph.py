"""Room graphs: which rooms a home has on each storey and which of them connect.

A probabilistic grammar (Infinigen Indoors, Tables 6 and 7) grows each storey's graph from a
living room: every room, once added, draws its children by type. Then:

- a balcony or a bathroom is a leaf: what the grammar hangs on it (a utility room, a closet)
  goes on its parent, since a small room with two doors on its walls has no wall left for
  its fixtures;
- hallways are shared: the other children of a room that has hallways are redistributed among
  them (with probability `HALLWAY_SHARE`), so a hallway serves several siblings;
- a living room keeps at most `MAX_LIVING_NEIGHBOURS` doors to other rooms: the private and
  service rooms past that move onto a hallway (one is added if it has none), since a living
  room with a door on every wall has nowhere to put a sofa facing a TV;
- homes with 2-3 storeys get one staircase room per storey, hung on a hallway (preferring those
  with few children) or the living room; stairs join consecutive staircase rooms;
- the ground floor gets an entrance: a hallway (always where the living room already has
  `MAX_LIVING_NEIGHBOURS` doors) or the living room;
- graphs that are not planar or break bathroom privacy are rejected (see `privacy_problems`);
- user room counts are met by repairing a sampled graph (adding rooms under grammar-valid
  parents, removing leaves), so unusual counts do not need millions of rejections.

A `HomeGraph` holds one networkx Graph per storey (nodes are room names ``<type>_<k>``, unique
across the home, with attributes ``type`` and ``level``) plus the entrance and staircase rooms.
"""
from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass, field

import networkx as nx
import numpy as np

from indoorgen.errors import ConfigError
from indoorgen.floorplan.rooms import room_type_of
from indoorgen.model.room_types import (
    BALCONY,
    BATHROOM,
    BEDROOM,
    CLOSET,
    DINING_ROOM,
    GARAGE,
    HALLWAY,
    KITCHEN,
    LIVING_ROOM,
    ROOM_TYPES,
    STAIRCASE_ROOM,
    UTILITY,
    room_type,
)

log = logging.getLogger(__name__)

#: Children per parent type on the ground floor (Table 6). A float is a Bernoulli probability of
#: one child; a tuple is a categorical over 0, 1, 2... children. The paper prints the bedroom row
#: as Cat(0, .3, .3, .3, 1); we read the last weight as .1, which makes it sum to one.
GROUND_CHILDREN: dict[str, dict[str, float | tuple[float, ...]]] = {
    LIVING_ROOM: {LIVING_ROOM: 0.1, BEDROOM: (0.0, 0.3, 0.3, 0.3, 0.1), CLOSET: 0.1,
                  BATHROOM: 0.4, GARAGE: 0.4, BALCONY: 0.2, DINING_ROOM: 0.8, UTILITY: 0.2,
                  HALLWAY: (0.5, 0.4, 0.1)},
    KITCHEN: {GARAGE: 0.1, UTILITY: 0.2},
    BEDROOM: {BATHROOM: 0.3, CLOSET: 0.5},
    BATHROOM: {CLOSET: 0.2},
    DINING_ROOM: {KITCHEN: 1.0, HALLWAY: 0.2},
}
#: Children per parent type on upper floors (Table 7; categoricals are normalised).
UPPER_CHILDREN: dict[str, dict[str, float | tuple[float, ...]]] = {
    LIVING_ROOM: {BEDROOM: (0.0, 0.4, 0.5, 0.2), CLOSET: 0.2, BATHROOM: 0.4, BALCONY: 0.4,
             UTILITY: 0.2, HALLWAY: (0.0, 0.5, 0.5)},
    BEDROOM: {BATHROOM: 0.3, CLOSET: 0.5},
    BATHROOM: {CLOSET: 0.2},
    BALCONY: {UTILITY: 0.4, HALLWAY: 0.1},
}
#: Probability that a sibling of a hallway is moved from the common parent onto a hallway.
HALLWAY_SHARE = 0.6
#: Types whose children go on their own parent instead (`grow_storey`).
LEAVES = frozenset({BALCONY, BATHROOM})
#: Doors a living room keeps to other rooms at most, and the kinds of room that move from it
#: onto a hallway past that (`_relieve_living_rooms`); the dining room, kitchen, balcony,
#: hallways and another living room stay, as they belong to the shared zone.
MAX_LIVING_NEIGHBOURS = 3
OFF_HALLWAY = (BEDROOM, BATHROOM, CLOSET, UTILITY, GARAGE)
#: Graphs with more rooms than this on one storey (staircase included), or a room with more
#: neighbours than MAX_DEGREE, are resampled unless counts are fixed: they rarely fit a plan.
MAX_ROOMS_PER_STOREY = 12
MAX_DEGREE = 6
#: Where a room of each type may be attached when a count has to be raised, best first.
PARENTS: dict[str, tuple[str, ...]] = {
    LIVING_ROOM: (LIVING_ROOM,), DINING_ROOM: (LIVING_ROOM,), KITCHEN: (DINING_ROOM, LIVING_ROOM),
    BEDROOM: (HALLWAY, LIVING_ROOM), BATHROOM: (HALLWAY, LIVING_ROOM),
    CLOSET: (BEDROOM, HALLWAY, LIVING_ROOM), HALLWAY: (LIVING_ROOM, DINING_ROOM),
    GARAGE: (KITCHEN, LIVING_ROOM), BALCONY: (LIVING_ROOM, BEDROOM),
    UTILITY: (KITCHEN, HALLWAY, LIVING_ROOM),
}
#: The share of a storey's area its rooms' least areas may take at most (the floor plan needs
#: the rest to shape them; `floorplan.generate` refuses a smaller area).
MIN_AREA_SHARE = 0.8
#: Graphs whose storey's rooms' typical areas add up to more than this times the storey's area
#: are drawn again while attempts remain (`sample_home_graph`).
TYPICAL_AREA_SHARE = 1.25
#: Types every home keeps whatever its area: what one lives and arrives in.
ESSENTIAL = frozenset({LIVING_ROOM, HALLWAY})
#: Types that only live on the ground floor.
GROUND_ONLY = frozenset({KITCHEN, DINING_ROOM, GARAGE})
MAX_STOREYS = 3


@dataclass
class HomeGraph:
    """The room graph of a home: `storeys[k]` is storey k's graph; `entrance` the ground-floor
    room with the front door; `stairs[k]` the staircase room of storey k (empty for one
    storey)."""

    storeys: list[nx.Graph]
    entrance: str
    stairs: list[str] = field(default_factory=list)

    @property
    def n_storeys(self) -> int:
        """Number of storeys."""
        return len(self.storeys)

    def rooms(self, level: int | None = None) -> list[str]:
        """Room names (of one storey, or all), in a stable order."""
        levels = range(self.n_storeys) if level is None else [level]
        return [n for k in levels for n in self.storeys[k].nodes]

    def type_counts(self) -> dict[str, int]:
        """Rooms per type over the whole home."""
        out: dict[str, int] = {}
        for n in self.rooms():
            out[room_type_of(n)] = out.get(room_type_of(n), 0) + 1
        return out

    def storey_entry(self, level: int) -> str:
        """Where one arrives on storey `level`: the entrance room or the staircase room."""
        return self.entrance if level == 0 else self.stairs[level]

    def home(self) -> nx.Graph:
        """All storeys in one graph, consecutive staircase rooms joined by 'stair' edges."""
        g = nx.union_all(self.storeys) if self.storeys else nx.Graph()
        for a, b in zip(self.stairs, self.stairs[1:], strict=False):
            g.add_edge(a, b, kind="stair")
        return g

    def to_json(self) -> dict:
        """The graph as JSON (the form `graph_from_spec` reads back)."""
        return {"storeys": [{"rooms": list(g.nodes), "edges": [sorted(e) for e in g.edges]}
                            for g in self.storeys],
                "entrance": self.entrance, "stairs": list(self.stairs)}


# --------------------------------------------------------------------------------------------
# sampling


def _draw_count(rng: np.random.Generator, spec: float | tuple[float, ...]) -> int:
    if isinstance(spec, tuple):
        p = np.asarray(spec, float)
        return int(rng.choice(len(p), p=p / p.sum()))
    return int(rng.random() < spec)


def grow_storey(rng: np.random.Generator, level: int) -> tuple[nx.Graph, dict[int, int]]:
    """Grow one storey's tree by the grammar, breadth first from a living room.

    Returns a graph on integer nodes (attribute ``type``) and the parent of each node."""
    table = GROUND_CHILDREN if level == 0 else UPPER_CHILDREN
    g = nx.Graph()
    g.add_node(0, type=LIVING_ROOM)
    parent: dict[int, int] = {}
    queue = [0]
    while queue and g.number_of_nodes() < 3 * MAX_ROOMS_PER_STOREY:
        i = queue.pop(0)
        host = parent[i] if g.nodes[i]["type"] in LEAVES else i
        for child_type, spec in table.get(g.nodes[i]["type"], {}).items():
            for _ in range(_draw_count(rng, spec)):
                j = g.number_of_nodes()
                g.add_node(j, type=child_type)
                g.add_edge(host, j)
                parent[j] = host
                queue.append(j)
    _share_hallways(rng, g, parent)
    return g, parent


def _share_hallways(rng: np.random.Generator, g: nx.Graph, parent: dict[int, int]) -> None:
    """Move siblings of hallways from their common parent onto one of the hallways."""
    for p in sorted(g.nodes):
        kids = sorted(c for c, q in parent.items() if q == p)
        halls = [c for c in kids if g.nodes[c]["type"] == HALLWAY]
        if not halls:
            continue
        for c in kids:
            if g.nodes[c]["type"] in (HALLWAY, KITCHEN, BALCONY) or \
                    rng.random() >= HALLWAY_SHARE:
                continue
            h = halls[int(rng.integers(len(halls)))]
            g.remove_edge(p, c)
            g.add_edge(h, c)
            parent[c] = h


def _relieve_living_rooms(rng: np.random.Generator, g: nx.Graph, parent: dict[int, int],
                          stairs: bool, entrance: bool) -> None:
    """Move private and service children (`OFF_HALLWAY`) of a living room with more than
    `MAX_LIVING_NEIGHBOURS` neighbours onto its hallways, adding a hallway if it has none. A
    storey without a hallway keeps a door free for each thing `_finish` hangs on its living
    room: the staircase room with `stairs` (a home of several storeys), the front door with
    `entrance` (the ground floor)."""
    for p in _of_type(g, LIVING_ROOM):
        movable = [c for c in sorted(g.neighbors(p))
                   if parent.get(c) == p and g.nodes[c]["type"] in OFF_HALLWAY]
        reserve = 0 if _of_type(g, HALLWAY) else int(stairs) + int(entrance)
        excess = g.degree(p) - MAX_LIVING_NEIGHBOURS + reserve
        if excess <= 0 or not movable:
            continue
        halls = [c for c in sorted(g.neighbors(p)) if g.nodes[c]["type"] == HALLWAY]
        if not halls:
            halls = [_hang(rng, g, parent, HALLWAY, [p])]
            # the stairs hang on the hallway, and the front door opens into it (`_finish`)
            excess = g.degree(p) - MAX_LIVING_NEIGHBOURS
        order = rng.permutation(len(movable))
        for c in (movable[k] for k in order[:excess]):
            load = [sum(1 for q in parent.values() if q == h) for h in halls]
            h = halls[int(np.argmin(load))]
            g.remove_edge(p, c)
            g.add_edge(h, c)
            parent[c] = h


def _hang(rng: np.random.Generator, g: nx.Graph, parent: dict[int, int], room_type: str,
          hosts: list[int]) -> int:
    """Add a room of `room_type` under one of `hosts`, preferring hosts with few children."""
    w = np.array([1.0 / (1 + sum(1 for q in parent.values() if q == h)) for h in hosts])
    host = hosts[int(rng.choice(len(hosts), p=w / w.sum()))]
    j = max(g.nodes) + 1
    g.add_node(j, type=room_type)
    g.add_edge(host, j)
    parent[j] = host
    return j


def _of_type(g: nx.Graph, *types: str) -> list[int]:
    return sorted(n for n in g.nodes if g.nodes[n]["type"] in types)


def _repair_counts(rng: np.random.Generator, trees: list[tuple[nx.Graph, dict]],
                   counts: dict[str, int]) -> bool:
    """Add or remove rooms until the home has `counts[t]` rooms of each given type t. Returns
    False if a count cannot be met (e.g. no valid parent exists)."""
    for t in sorted(counts):
        want = counts[t]
        have = sum(len(_of_type(g, t)) for g, _ in trees)
        guard = 0
        while have > want and guard < 64:
            guard += 1
            cands = [(k, n) for k, (g, par) in enumerate(trees) for n in _of_type(g, t)
                     if n != 0 and n in par]
            if not cands:
                return False
            leaves = [(k, n) for k, n in cands if trees[k][0].degree(n) == 1]
            k, n = (leaves or cands)[int(rng.integers(len(leaves or cands)))]
            g, par = trees[k]
            up = par.pop(n)
            for c in sorted(g.neighbors(n)):
                if par.get(c) == n:
                    g.add_edge(up, c)
                    par[c] = up
            g.remove_node(n)
            have -= 1
        while have < want and guard < 128:
            guard += 1
            levels = [0] if t in GROUND_ONLY else list(range(len(trees)))
            if t == BEDROOM and len(trees) > 1:
                levels = levels[1:] + levels[1:] + [0]
            k = levels[int(rng.integers(len(levels)))]
            g, par = trees[k]
            for ptype in PARENTS[t]:
                hosts = _of_type(g, ptype)
                if hosts:
                    _hang(rng, g, par, t, hosts)
                    have += 1
                    break
            else:
                if all(not any(_of_type(trees[k][0], p) for p in PARENTS[t]) for k in levels):
                    return False
    return True


def privacy_problems(home: nx.Graph, entrance: str | None = None,
                     types: dict[str, str] | None = None) -> list[str]:
    """Bathroom privacy (D.1) on a whole-home graph; an empty list when respected.

    - an en-suite bathroom (one next to a bedroom) opens onto that bedroom and closets only;
    - every bedroom reaches a bathroom without walking through another bedroom;
    - a guest reaches a bathroom from the entrance (``entrance``, default: the graph's first
      living room) without walking through a bedroom (an en-suite comes on top).

    `types` gives the rooms' types by name (default: read off the names, ``<type>_<k>``).
    """
    out = []
    types = types or {n: room_type_of(n) for n in home.nodes}
    for b in sorted(n for n, t in types.items() if t == BATHROOM):
        beds = [n for n in home.neighbors(b) if types[n] == BEDROOM]
        others = [n for n in home.neighbors(b) if types[n] not in (BEDROOM, CLOSET)]
        if len(beds) > 1 or (beds and others):
            out.append(f"{b} is shared by {sorted(beds + others)}")
    baths = {n for n, t in types.items() if t == BATHROOM}
    for bed in sorted(n for n, t in types.items() if t == BEDROOM):
        allowed = [n for n in home.nodes if types[n] != BEDROOM or n == bed]
        reach = nx.node_connected_component(home.subgraph(allowed), bed)
        if baths and not reach & baths:
            out.append(f"{bed} reaches no bathroom without crossing another bedroom")
    start = entrance if entrance is not None else next(
        (n for n in sorted(home.nodes) if types[n] == LIVING_ROOM), None)
    if baths and start is not None and start in home and types[start] != BEDROOM:
        shared = home.subgraph(n for n in home.nodes if types[n] != BEDROOM)
        if not nx.node_connected_component(shared, start) & baths:
            out.append("every bathroom is behind a bedroom")
    return out


#: What may lie behind a bedroom (reached only through it): its en-suite, closet or balcony.
PRIVATE_ANNEXES = frozenset({BATHROOM, CLOSET, BALCONY})


def zone_problems(home: nx.Graph, entrance: str | None = None,
                  types: dict[str, str] | None = None) -> list[str]:
    """Rooms of the shared zone (everything but bedrooms and their annexes) that one reaches
    from the entrance only through a bedroom; `types` as in `privacy_problems`."""
    types = types or {n: room_type_of(n) for n in home.nodes}
    if entrance is None or entrance not in home or types[entrance] == BEDROOM:
        return []
    shared = home.subgraph(n for n in home.nodes if types[n] != BEDROOM)
    reach = nx.node_connected_component(shared, entrance)
    everywhere = nx.node_connected_component(home, entrance)
    return [f"{n} is reached only through a bedroom" for n in sorted(everywhere - reach)
            if types[n] not in PRIVATE_ANNEXES and types[n] != BEDROOM]


def balcony_problems(home: nx.Graph, types: dict[str, str] | None = None) -> list[str]:
    """Balconies not entered from a living room or a bedroom only (`types`: room types by
    name, default: read off the names)."""
    out = []
    types = types or {n: room_type_of(n) for n in home.nodes}
    for b in sorted(n for n in home.nodes if types[n] == BALCONY):
        others = sorted(n for n in home.neighbors(b) if types[n] not in (LIVING_ROOM, BEDROOM))
        if others or not home.degree(b):
            out.append(f"{b} is entered from {others or 'nowhere'}, not a living room or "
                       "bedroom")
    return out


#: What `graph_problems` finds that a user's own graph may still do (the generator does not).
USER_CHOICES = ("the home has no", "a balcony on the ground floor", "more than one garage")


def graph_problems(hg: HomeGraph, counts: dict[str, int] | None = None) -> list[str]:
    """Why `hg` is not an acceptable home graph (empty if it is): planarity, connectivity,
    a living room on every storey, a bathroom on every storey (unless counts are fixed), a
    bathroom and a kitchen in the home (unless counts set them to 0), no balcony on the ground
    floor and one garage at most (unless counts name them), privacy, counts."""
    out = []
    home = hg.home()
    if not nx.is_connected(home):
        out.append("the rooms are not all connected")
    for k, g in enumerate(hg.storeys):
        if not nx.check_planarity(g)[0]:
            out.append(f"storey {k} graph is not planar")
        if not any(room_type_of(n) == LIVING_ROOM for n in g.nodes):
            out.append(f"storey {k} has no living room")
        if counts is None and not any(room_type_of(n) == BATHROOM for n in g.nodes):
            out.append(f"storey {k} has no bathroom")
        if k == 0 and BALCONY not in (counts or {}) and \
                any(room_type_of(n) == BALCONY for n in g.nodes):
            out.append("a balcony on the ground floor")
    garages = sum(1 for n in home.nodes if room_type_of(n) == GARAGE)
    if garages > 1 and GARAGE not in (counts or {}):
        out.append(f"more than one garage ({garages})")
    for t in (BATHROOM, KITCHEN):
        if not any(room_type_of(n) == t for n in home.nodes) and (counts or {}).get(t, 1):
            out.append(f"the home has no {t}")
    out += privacy_problems(home, hg.entrance)
    out += balcony_problems(home) + zone_problems(home, hg.entrance)
    if counts:
        have = hg.type_counts()
        for t, n in sorted(counts.items()):
            if have.get(t, 0) != n:
                out.append(f"{have.get(t, 0)} {t} rooms, wanted {n}")
    return out


def _finish(rng: np.random.Generator, trees: list[tuple[nx.Graph, dict]]) -> HomeGraph:
    """Add staircases and the entrance, then give nodes their home-wide names."""
    n = len(trees)
    stair_nodes, entrance = [], 0
    for k, (g, par) in enumerate(trees):
        if n > 1:
            hosts = _of_type(g, HALLWAY) or _of_type(g, LIVING_ROOM)[:1]
            stair_nodes.append(_hang(rng, g, par, STAIRCASE_ROOM, hosts))
        if k == 0:
            # the front door opens into a hallway, or into the living room (never its fourth
            # door, `MAX_LIVING_NEIGHBOURS`)
            halls = [h for h in _of_type(g, HALLWAY) if h not in stair_nodes]
            busy = g.degree(0) >= MAX_LIVING_NEIGHBOURS
            entrance = halls[int(rng.integers(len(halls)))] \
                if halls and (rng.random() < 0.6 or busy) else 0
    counters: dict[str, int] = {}
    storeys, names = [], []
    for k, (g, _) in enumerate(trees):
        mapping = {}
        for node in nx.bfs_tree(g, 0):
            t = g.nodes[node]["type"]
            mapping[node] = f"{t}_{counters.get(t, 0)}"
            counters[t] = counters.get(t, 0) + 1
        h = nx.Graph()
        for node in nx.bfs_tree(g, 0):
            h.add_node(mapping[node], type=g.nodes[node]["type"], level=k)
        h.add_edges_from(sorted((mapping[a], mapping[b]) for a, b in g.edges))
        storeys.append(h)
        names.append(mapping)
    stairs = [names[k][s] for k, s in enumerate(stair_nodes)]
    return HomeGraph(storeys, names[0][entrance], stairs)


def _typical_area(g: nx.Graph, n_storeys: int) -> float:
    """The typical areas of a storey's rooms added up (a staircase room's too, in a home of
    several storeys)."""
    return (sum(ROOM_TYPES[g.nodes[n]["type"]].typical_area for n in g.nodes)
            + (ROOM_TYPES[STAIRCASE_ROOM].typical_area if n_storeys > 1 else 0.0))


def _optional_rooms(g: nx.Graph, counts: dict[str, int]) -> list[int]:
    """The rooms of a storey the user's counts did not ask for and a home can do without (all
    but living rooms and hallways): a dining room, a utility room, a closet."""
    return [n for n in g.nodes
            if g.nodes[n]["type"] not in counts and g.nodes[n]["type"] not in ESSENTIAL]


def sample_home_graph(rng_for: Callable[[int], np.random.Generator], n_storeys: int = 1,
                      counts: dict[str, int] | None = None, max_attempts: int = 400,
                      max_area: float | None = None) -> HomeGraph:
    """Sample a home graph of `n_storeys` storeys, optionally with fixed counts of room types.

    `rng_for(attempt)` gives the random stream of each attempt, so a rejected attempt never
    shifts the randomness of the next. With `max_area` (a storey's area, when the user fixed
    it), graphs whose storeys' typical areas add up to more than `TYPICAL_AREA_SHARE` times it
    are resampled in the first half of the attempts; with counts fixed, only those that also
    hold rooms the counts do not name (`_optional_rooms`): a 55 m^2 flat asked for with one
    bedroom, a bathroom and a kitchen is a living room (dining in it), the kitchen, the
    bedroom, the bathroom and perhaps a hall, not also a dining, utility room and closet too
    small to furnish. Raises ConfigError if no acceptable graph is found."""
    if not 1 <= n_storeys <= MAX_STOREYS:
        raise ConfigError(f"--floors {n_storeys} is out of range; a home has 1 to {MAX_STOREYS} "
                          "storeys")
    counts = {room_type(t, floorplan=True).name: int(c) for t, c in (counts or {}).items()}
    if STAIRCASE_ROOM in counts and counts[STAIRCASE_ROOM] != (n_storeys if n_storeys > 1 else 0):
        raise ConfigError(f"staircase_room={counts[STAIRCASE_ROOM]} conflicts with {n_storeys} "
                          f"storey(s); staircase rooms follow from the number of floors "
                          f"(one per storey when there are 2 or more)")
    counts.pop(STAIRCASE_ROOM, None)
    if LIVING_ROOM in counts and counts[LIVING_ROOM] < n_storeys:
        raise ConfigError(f"living_room={counts[LIVING_ROOM]} is too few for {n_storeys} storeys; "
                          "every storey grows from a living room")
    last = []
    for attempt in range(max_attempts):
        rng = rng_for(attempt)
        trees = [grow_storey(rng, k) for k in range(n_storeys)]
        if counts and not _repair_counts(rng, trees, counts):
            last = ["cannot attach the requested rooms"]
            continue
        if HALLWAY not in counts:
            for k, (g, par) in enumerate(trees):
                _relieve_living_rooms(rng, g, par, n_storeys > 1, k == 0)
        if not counts and any(g.number_of_nodes() > MAX_ROOMS_PER_STOREY - (n_storeys > 1)
                              or max(d for _, d in g.degree) > MAX_DEGREE for g, _ in trees):
            continue
        if max_area is not None and attempt < max_attempts // 2 and any(
                _typical_area(g, n_storeys) > TYPICAL_AREA_SHARE * max_area
                and (not counts or _optional_rooms(g, counts)) for g, _ in trees):
            continue  # too many rooms for the area: a small flat grows fewer
        if max_area is not None and attempt < max_attempts // 2 and any(
                sum(ROOM_TYPES[g.nodes[n]["type"]].min_area for n in g.nodes)
                > MIN_AREA_SHARE * max_area for g, _ in trees):
            continue  # the rooms' least areas do not fit (`generate` would refuse the area)
        hg = _finish(rng, trees)
        last = graph_problems(hg, counts or None)
        if not last:
            log.debug("home graph after %d attempt(s): %s", attempt + 1, hg.to_json())
            return hg
    raise ConfigError(f"no valid room graph for {n_storeys} storey(s) with rooms {counts}: "
                      f"{'; '.join(last[:3])}")


def graph_from_spec(spec: dict) -> HomeGraph:
    """A user-fixed home graph from ``{"storeys": [{"rooms": [...], "edges": [[a, b], ...]}],
    "entrance": name, "stairs": [names]}`` (the form `HomeGraph.to_json` writes). Room names
    must be ``<type>_<k>``. Raises ConfigError naming what is wrong."""
    try:
        storeys_spec = spec["storeys"]
        entrance = spec.get("entrance")
    except (TypeError, KeyError):
        raise ConfigError('a room graph must be {"storeys": [{"rooms": [...], "edges": [...]}], '
                          '"entrance": ROOM}') from None
    storeys, seen = [], set()
    for k, s in enumerate(storeys_spec):
        g = nx.Graph()
        for name in s.get("rooms", []):
            t = room_type(room_type_of(name), floorplan=True).name
            if name in seen:
                raise ConfigError(f"room name {name!r} is used twice in the graph")
            seen.add(name)
            g.add_node(name, type=t, level=k)
        for a, b in s.get("edges", []):
            if a not in g or b not in g:
                raise ConfigError(f"graph edge {a!r}-{b!r} names a room not on storey {k}")
            g.add_edge(a, b)
        storeys.append(g)
    if not 1 <= len(storeys) <= MAX_STOREYS:
        raise ConfigError(f"the graph has {len(storeys)} storeys; 1 to {MAX_STOREYS} are allowed")
    stairs = list(spec.get("stairs") or [])
    if len(storeys) > 1 and len(stairs) != len(storeys):
        stairs = [next((n for n in g.nodes if room_type_of(n) == STAIRCASE_ROOM), "") for g in storeys]
        if not all(stairs):
            raise ConfigError("a graph with several storeys needs a staircase_room on each storey")
    if entrance is None:
        entrance = next(iter(storeys[0].nodes))
    if entrance not in storeys[0]:
        raise ConfigError(f"entrance {entrance!r} is not a room on the ground floor")
    hg = HomeGraph(storeys, entrance, stairs if len(storeys) > 1 else [])
    problems = [p for p in graph_problems(hg, {}) if not p.startswith(USER_CHOICES)]
    if problems:
        raise ConfigError(f"the given room graph is not usable: {'; '.join(problems[:3])}")
    return hg
