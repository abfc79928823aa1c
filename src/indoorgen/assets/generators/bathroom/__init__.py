"""Bathroom fixtures: sinks and vanities, bathtubs, toilets, showers and wall accessories;
what they share is in `_parts`."""
