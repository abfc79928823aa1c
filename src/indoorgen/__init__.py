"""indoorgen: procedural indoor scenes in pure Python."""
