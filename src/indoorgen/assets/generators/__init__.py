"""Every generator module; importing this package registers them all."""
from . import books, decor, electronics, lighting, seating, storage, tables, tableware  # noqa: F401
