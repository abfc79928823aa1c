"""The semantic vocabulary: object classes and surface roles (room types: `room_types`).

Tags are plain string enums so that they serialise to `scene.json` and USD as readable names.
Classes are flat; a generator lists every class it belongs to (a dining chair is Furniture,
Seating and Chair), which is what lets a constraint address "all seating" or "all chairs".
"""
from __future__ import annotations

from enum import Enum


class Semantics(str, Enum):
    """Object classes (flat: an object carries every class it belongs to) and room tags."""

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
    Appliance = "appliance"
    KitchenAppliance = "kitchen_appliance"
    BathroomFixture = "bathroom_fixture"
    Bed = "bed"
    Cabinet = "cabinet"
    Shelf = "shelf"
    Kitchenware = "kitchenware"
    Cutlery = "cutlery"
    Food = "food"
    Textile = "textile"
    Plant = "plant"
    Container = "container"
    Architecture = "architecture"
    Door = "door"
    Window = "window"
    Staircase = "staircase"
    WallMounted = "wall_mounted"
    CeilingMounted = "ceiling_mounted"
    Warehouse = "warehouse"
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
    # appliances and kitchen
    Fridge = "fridge"
    BeverageFridge = "beverage_fridge"
    Dishwasher = "dishwasher"
    Microwave = "microwave"
    Oven = "oven"
    Cooktop = "cooktop"
    Range = "range"
    Monitor = "monitor"
    KitchenSink = "kitchen_sink"
    WashingMachine = "washing_machine"
    RangeHood = "range_hood"
    KitchenCabinet = "kitchen_cabinet"
    WallCabinet = "wall_cabinet"
    Countertop = "countertop"
    KitchenIsland = "kitchen_island"
    # -- appliances: more tags here
    # bathroom
    BathroomSink = "bathroom_sink"
    Vanity = "vanity"
    Bathtub = "bathtub"
    Toilet = "toilet"
    Shower = "shower"
    TowelBar = "towel_bar"
    TowelRing = "towel_ring"
    ToiletRollHolder = "toilet_roll_holder"
    RobeHook = "robe_hook"
    MirrorCabinet = "mirror_cabinet"
    # -- bathroom: more tags here
    # seating, beds, tables
    SideChair = "side_chair"
    UpholsteredChair = "upholstered_chair"
    OfficeChair = "office_chair"
    BarStool = "bar_stool"
    Stool = "stool"
    Bench = "bench"
    BunkBed = "bunk_bed"
    Desk = "desk"
    ConsoleTable = "console_table"
    SectionalSofa = "sectional_sofa"
    # -- seating, beds, tables: more tags here
    # storage and lighting
    Wardrobe = "wardrobe"
    Dresser = "dresser"
    Nightstand = "nightstand"
    CellShelf = "cell_shelf"
    WallShelf = "wall_shelf"
    CornerShelf = "corner_shelf"
    ShoeRack = "shoe_rack"
    PalletRack = "pallet_rack"
    Pallet = "pallet"
    CeilingLight = "ceiling_light"
    PendantLight = "pendant_light"
    DeskLamp = "desk_lamp"
    WallSconce = "wall_sconce"
    # -- storage and lighting: more tags here
    TableLamp = "table_lamp"
    # decor
    Mirror = "mirror"
    PottedPlant = "potted_plant"
    Aquarium = "aquarium"
    Curtain = "curtain"
    Clock = "clock"
    Balloon = "balloon"
    Candle = "candle"
    # -- decor: more tags here
    # small objects
    Bowl = "bowl"
    Mug = "mug"
    Wineglass = "wineglass"
    Bottle = "bottle"
    Jar = "jar"
    Can = "can"
    FoodBox = "food_box"
    FoodBag = "food_bag"
    Pot = "pot"
    Pan = "pan"
    Lid = "lid"
    Knife = "knife"
    Fork = "fork"
    Spoon = "spoon"
    Chopsticks = "chopsticks"
    Spatula = "spatula"
    CuttingBoard = "cutting_board"
    FruitBowl = "fruit_bowl"
    Towel = "towel"
    BathMat = "bath_mat"
    FoldedClothes = "folded_clothes"
    Garment = "garment"
    Shoes = "shoes"
    Laptop = "laptop"
    Remote = "remote"
    Basket = "basket"
    Box = "box"
    # -- small objects: more tags here
    # architecture
    InteriorDoor = "interior_door"
    ExteriorDoor = "exterior_door"
    # -- architecture: more tags here
    Railing = "railing"


class Subpart(str, Enum):
    """Roles of named surfaces on assets and rooms."""

    Bottom = "bottom"
    Top = "top"
    Back = "back"
    Front = "front"
    Side = "side"
    SupportSurface = "support_surface"
    Interior = "interior"
    #: a hanging rail's top (upward, along the rail: u runs along it), what hooks rest on
    Rail = "rail"
    #: the inside of a hanger's hook (downward), what rests on a rail
    Hook = "hook"
    # room surfaces
    Floor = "floor"
    Wall = "wall"
    Ceiling = "ceiling"

