"""Kitchenware: cookware (pots, pans, lids), utensils (cutlery, spatulas, cutting boards) and
storage jars; what they share is in `_parts`."""
