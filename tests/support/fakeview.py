"""A minimal in-memory ObjectView for testing the DSL without assets or a solver."""
from __future__ import annotations

import math

import numpy as np
import shapely.geometry as sg
import trimesh

from indoorgen.model.tags import Semantics


class FakeView:
    def __init__(self):
        self.objs: dict[str, dict] = {}
        self.rooms: dict[str, sg.Polygon] = {}

    def add_room(self, name, polygon):
        self.rooms[name] = sg.Polygon(polygon)

    def add(self, name, tags, center=(0, 0, 0), yaw=0.0, extents=(1, 1, 1), relations=(),
            generator="box", support=None, params=None):
        self.objs[name] = dict(tags=frozenset(tags), center=np.array(center, float), yaw=yaw,
                               extents=np.array(extents, float), relations=list(relations),
                               generator=generator, support=support, params=dict(params or {}))

    def move(self, name, center=None, yaw=None):
        o = self.objs[name]
        if center is not None:
            o["center"] = np.array(center, float)
        if yaw is not None:
            o["yaw"] = yaw

    def all_ids(self):
        return frozenset(self.objs) | frozenset(self.rooms)

    def tags(self, o):
        return frozenset({Semantics.Room}) if o in self.rooms else self.objs[o]["tags"]

    def generator(self, o):
        return "" if o in self.rooms else self.objs[o]["generator"]

    def params(self, o):
        return {} if o in self.rooms else self.objs[o]["params"]

    def relations(self, o):
        return [] if o in self.rooms else self.objs[o]["relations"]

    def children(self, o):
        return {n for n, d in self.objs.items() if any(p == o for _, p in d["relations"])}

    def center(self, o):
        if o in self.rooms:
            c = self.rooms[o].centroid
            return np.array([c.x, c.y, 1.35])
        return self.objs[o]["center"]

    def floor_z(self, o):
        return 0.0

    def yaw(self, o):
        return 0.0 if o in self.rooms else self.objs[o]["yaw"]

    def front(self, o):
        y = self.yaw(o)
        return np.array([math.cos(y), math.sin(y), 0.0])

    def side_axis(self, o):
        y = self.yaw(o)
        return np.array([-math.sin(y), math.cos(y), 0.0])

    def extents(self, o):
        if o in self.rooms:  # as the solver's view: plan bounds and a storey's height
            x0, y0, x1, y1 = self.rooms[o].bounds
            return np.array([x1 - x0, y1 - y0, 2.7])
        return self.objs[o]["extents"]

    def front_point(self, o):
        return self.center(o) + self.front(o) * self.extents(o)[0] / 2

    def footprint(self, o):
        if o in self.rooms:
            return self.rooms[o]
        c, (dx, dy, _), y = self.center(o), self.extents(o), self.yaw(o)
        pts = np.array([[-dx, -dy], [dx, -dy], [dx, dy], [-dx, dy]]) / 2
        r = np.array([[math.cos(y), -math.sin(y)], [math.sin(y), math.cos(y)]])
        return sg.Polygon(pts @ r.T + c[:2])

    def outline(self, o):
        return self.rooms[o].exterior if o in self.rooms else self.footprint(o)

    def world_mesh(self, o):
        m = trimesh.creation.box(self.extents(o))
        t = trimesh.transformations.rotation_matrix(self.yaw(o), [0, 0, 1])
        t[:3, 3] = self.center(o)
        m.apply_transform(t)
        return m

    def support_polygon(self, o):
        return self.objs[o]["support"]
