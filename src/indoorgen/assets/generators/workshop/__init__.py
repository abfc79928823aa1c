"""Workshop tools: what a garage's workbench, tool chest and shelves hold (toolboxes, cans of paint)."""
