"""What rooms hang at their windows: the one call a room program makes to have its windows
dressed (the constraint language knows no windows, so the solver hangs the dressing, sized to
each window, once the room's furniture stands: `solver.window_dressing`)."""
from indoorgen.constraints import Problem

#: the generator living rooms and bedrooms dress their windows with (a rod and two pleated panels)
CURTAIN = "curtain"


def curtains_at_windows() -> Problem:
    """A pair of curtains at each of the room's windows, hung from above the frame past its sides
    to near the floor (or below the sill where furniture stands under it)."""
    return Problem(window_dressing=CURTAIN)
