"""Every generator module; importing this package registers them all.

Modules and sub-packages are found by walking the package, so a new generator family needs no
edit here. Names starting with an underscore hold shared helpers, not generators."""
import importlib
import pkgutil

for _mod in sorted(m.name for m in pkgutil.walk_packages(__path__, f"{__name__}.")):
    if not any(part.startswith("_") for part in _mod[len(__name__) + 1:].split(".")):
        importlib.import_module(_mod)
