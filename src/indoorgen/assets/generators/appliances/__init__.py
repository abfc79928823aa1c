"""Appliances: refrigeration, dishwasher, cooking, laundry and microwave; their grilles and racks
are in `_parts`, what they share with the kitchen cabinets in `assets.shapes.cabinet_parts`."""
