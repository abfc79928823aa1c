"""The data that flows through indoorgen: semantic tags, the scene, and the room-type table."""
