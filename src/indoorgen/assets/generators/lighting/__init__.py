"""Lighting: ceiling lights and pendants, floor, desk and table lamps, and wall sconces.

Light-emitting pieces (bulbs, opal diffusers, LED faces) use the "emissive" slot, which the
exporters turn into lights. Ceiling-mounted fixtures have a flat canopy at the top of their
bounding box (their `top` surface, which attaches to the ceiling); wall sconces have a flat
wall plate at the back (their `back`).
"""
