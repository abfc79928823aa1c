"""The built-in room programs, one module per room type, each a function `room -> Problem`."""
