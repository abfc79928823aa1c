"""What the plan-drawing tests share: the drawn text boxes of an axes, and their overlaps."""
from __future__ import annotations

from collections.abc import Callable

import pytest
from matplotlib.axes import Axes
from matplotlib.text import Text
from matplotlib.transforms import Bbox


def text_boxes(ax: Axes) -> list[tuple[Text, Bbox]]:
    """Every non-empty text of `ax` with its extent in pixels (the figure drawn first)."""
    fig = ax.figure
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    return [(t, t.get_window_extent(r)) for t in ax.texts if t.get_text()]


def overlapping(boxes: list[tuple[Text, Bbox]]) -> list[tuple[str, str]]:
    """The pairs of texts whose boxes overlap."""
    out = []
    for i, (s, p) in enumerate(boxes):
        for t, q in boxes[i + 1:]:
            if p.x0 < q.x1 and q.x0 < p.x1 and p.y0 < q.y1 and q.y0 < p.y1:
                out.append((s.get_text(), t.get_text()))
    return out


@pytest.fixture
def drawn_text() -> Callable[[Axes], list[tuple[Text, Bbox]]]:
    """`text_boxes`, for tests."""
    return text_boxes


@pytest.fixture
def text_overlaps() -> Callable[[list[tuple[Text, Bbox]]], list[tuple[str, str]]]:
    """`overlapping`, for tests."""
    return overlapping
