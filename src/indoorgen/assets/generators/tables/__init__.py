"""Tables: dining tables (rectangular, round, oval), coffee, side and console tables, and desks.

Every table exposes `top` (a SupportSurface: the tabletop's upper face minus a 2 cm border).
Dining, coffee and side tables add side surfaces `side_0..` spanning the full height, where
chairs are pushed in (box `side_left`/`side_right` are replaced by these); a desk's `side_0` is
the plane of its front edge, where its chair goes.
"""
