"""The semantic vocabulary: object classes, surface roles and room types.

Tags are plain string enums so that they serialise to `scene.json` and USD as readable names.
Classes are flat; a generator lists every class it belongs to (a dining chair is Furniture,
Seating and Chair), which is what lets a constraint address "all seating" or "all chairs".
"""
from __future__ import annotations

from enum import Enum


class Semantics(str, Enum):
    # rooms and architecture
    Room = "room"
    # broad object groups
    Object = "object"
    Furniture = "furniture"
    Seating = "seating"
    Table = "table"
    Storage = "storage"
    Electronics = "electronics"
    Lighting = "lighting"
    Decor = "decor"
    WallDecoration = "wall_decoration"
    FloorCovering = "floor_covering"
    SmallObject = "small_object"
    Tableware = "tableware"
    # concrete kinds
    Chair = "chair"
    DiningChair = "dining_chair"
    Sofa = "sofa"
    Armchair = "armchair"
    DiningTable = "dining_table"
    CoffeeTable = "coffee_table"
    SideTable = "side_table"
    TVStand = "tv_stand"
    TV = "tv"
    Bookcase = "bookcase"
    FloorLamp = "floor_lamp"
    Rug = "rug"
    WallArt = "wall_art"
    Book = "book"
    Plate = "plate"
    Cup = "cup"
    Vase = "vase"


class Subpart(str, Enum):
    """Roles of named surfaces on assets and rooms."""

    Bottom = "bottom"
    Top = "top"
    Back = "back"
    Front = "front"
    Side = "side"
    SupportSurface = "support_surface"
    Interior = "interior"
    # room surfaces
    Floor = "floor"
    Wall = "wall"
    Ceiling = "ceiling"


class RoomType(str, Enum):
    LivingRoom = "living_room"
    DiningRoom = "dining_room"
    Kitchen = "kitchen"
    Bedroom = "bedroom"
    Bathroom = "bathroom"
    Closet = "closet"
    Hallway = "hallway"
    Garage = "garage"
    Balcony = "balcony"
    Utility = "utility"
    StaircaseRoom = "staircase_room"
