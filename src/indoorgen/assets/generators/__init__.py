"""Every generator module; importing this package registers them all.

Modules are found by listing the package, so a new generator family needs no edit here. Names
starting with an underscore hold shared helpers, not generators."""
import importlib
import pkgutil

for _mod in sorted(m.name for m in pkgutil.iter_modules(__path__)):
    if not _mod.startswith("_"):
        importlib.import_module(f"{__name__}.{_mod}")
