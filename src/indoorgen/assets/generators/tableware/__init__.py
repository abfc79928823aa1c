"""Tableware: dishes (plates, bowls), drinkware (cups, mugs, glasses) and bottles."""
