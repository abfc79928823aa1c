"""Storage furniture: TV stands, cabinets, dressers, nightstands, wardrobes and open shelving
(bookcases, cube, wall, corner and shoe shelves). Fronts and open sides face +X."""
