"""Every generator module; importing this package registers them all.

Modules and family sub-packages (`seating/`, `storage/`...) are found by walking the package, so
a new generator module needs no edit here. Names starting with an underscore hold shared helpers
(`_kitchen_common`, a family's `_parts`), not generators, and are imported only by those that
need them.
"""
import importlib
import pkgutil

for _mod in sorted(m.name for m in pkgutil.walk_packages(__path__, f"{__name__}.")):
    if not _mod.rsplit(".", 1)[-1].startswith("_"):
        importlib.import_module(_mod)
