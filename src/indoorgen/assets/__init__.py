"""Procedural assets: the protocol (`base`), shared mesh parts (`parts`) and the generators."""
from indoorgen.assets.base import (
           Asset,
           AssetFactory,
           Joint,
           Param,
           Surface,
           box_surfaces,
           factories_with,
           factory_names,
           get_factory,
           register,
)

__all__ = ["Asset", "AssetFactory", "Joint", "Param", "Surface", "box_surfaces",
           "factories_with", "factory_names", "get_factory", "register"]
