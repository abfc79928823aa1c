"""Appliances: refrigeration, dishwasher, cooking, laundry and microwave; their grilles and racks
are in `_parts`, what they share with the kitchen cabinets in `generators._cabinet_parts`."""
