"""Procedural assets: the protocol, the registry, shared mesh parts (`shapes`), materials, generators."""
from indoorgen.assets.catalogue import factories_with, factory_names, get_factory
from indoorgen.assets.protocol import (
    Asset,
    AssetFactory,
    Joint,
    Param,
    Surface,
    box_surfaces,
)
from indoorgen.assets.registry import register

__all__ = ["Asset", "AssetFactory", "Joint", "Param", "Surface", "box_surfaces",
           "factories_with", "factory_names", "get_factory", "register"]
