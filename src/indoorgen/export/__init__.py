"""Exporters: one module per format, each a pure function of an `ExportBundle`
(`bundle.py`); `write_formats` writes any set of them into one directory."""
from indoorgen.export.formats import (
    DEFAULT_FORMATS,
    FORMATS,
    UnknownFormatError,
    parse_formats,
    write_formats,
)

__all__ = ["DEFAULT_FORMATS", "FORMATS", "UnknownFormatError", "parse_formats", "write_formats"]
