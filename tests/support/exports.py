"""Writing a set of generated scenes' exports for the session fixtures (tests/conftest.py,
tests/export/conftest.py)."""
from __future__ import annotations

from indoorgen.export import write_formats
from indoorgen.export.bundle import bundle_from_generated


def export_each(generated: dict, tmp_path_factory, formats: str, tex: int) -> dict:
    """name -> (bundle, directory holding `formats` at texture size `tex`, exporter timings),
    for each name -> Generated in `generated`, each in a fresh directory named after it."""
    out = {}
    for name, gen in generated.items():
        d = tmp_path_factory.mktemp(name)
        bundle = bundle_from_generated(gen)
        timings: dict = {}
        write_formats(bundle, d, formats, texture_resolution=tex, timings=timings)
        out[name] = (bundle, d, timings)
    return out
