"""USD export: a furnished scene's stage (`scene`, with its `materials` and `objects`), a bare
solidified home's (`architecture`), and the prim, attribute and mesh helpers they share
(`prims`)."""
