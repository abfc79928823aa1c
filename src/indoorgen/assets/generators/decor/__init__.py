"""Decor: rugs, wall art, mirrors, clocks, curtains, vases, candles, balloons, aquariums, and
the small pieces on shelves and tables: standing photo frames, sculptures, decorative bowls and trays.

Wall-mounted pieces (pictures, mirrors, curtains, wall clocks) hang with their flat back at the
bounding box's back (-X) and face +X; their `back` surface is the part of that plane the mesh
really covers.
"""
