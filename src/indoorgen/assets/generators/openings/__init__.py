"""Openings in a wall: door sets (doors.py) and windows (windows.py), in the wall frame of
`indoorgen.assets.shapes.architectural`."""
