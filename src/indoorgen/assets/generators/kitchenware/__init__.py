"""Kitchenware: cookware (pots, pans, lids), utensils (cutlery, spatulas, cutting boards),
storage jars and what stands out on a counter in use (kettles, toasters, knife blocks, utensil
crocks); what they share is in `_parts`."""
