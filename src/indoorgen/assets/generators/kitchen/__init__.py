"""Kitchen cabinetry (cabinets) and the sink (sink); the cabinet units they are built from are in
`_parts`, what they share with the appliances in `assets.shapes.cabinet_parts`."""
