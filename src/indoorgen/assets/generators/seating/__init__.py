"""Seating: chairs, office chairs, sofas, stools and benches. Front (+X) is where one sits from."""
