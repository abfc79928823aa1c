"""Architecture as solids: one room's walls, floor, ceiling, surfaces and door zones (`room`), a
whole home's from its floorplan (`solidify`, laid out by `walls`, with catalogue doors, windows
and stairs from `fixtures`), and a saved scene's rebuilt from scene.json (`rebuild`)."""
