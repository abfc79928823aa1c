"""The floorplan solver: seed (+ room counts, area or outline) -> a home's `Floorplan` (the data
is in `indoorgen.model.floorplan`). Room graph (`graph`), outlines (`contour`), grid and
subdivision (`grid`, `subdivide`), room assignment (`assign`), annealing (`solve`) on the
solver's view of a plan (`view`) under its hard rules (`rules`), then doors, windows and stairs
(`openings`); `generate` runs it end to end and `check` judges any plan."""
