"""The object solver: places a room's objects by staged simulated annealing over their poses,
plane assignments and params, under a constraint program (Infinigen Indoors, sec. 3.3)."""
