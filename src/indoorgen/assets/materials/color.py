"""Colour helpers shared by the material generators (all colours sRGB-encoded, in [0, 1])."""
from __future__ import annotations

import colorsys

import numpy as np

F32 = np.float32


def rgb(hexstr: str) -> np.ndarray:
    """'#a0b1c2' -> float32 array of 3 in [0, 1]."""
    h = hexstr.lstrip("#")
    return np.array([int(h[i:i + 2], 16) / 255.0 for i in (0, 2, 4)], F32)


def jitter(color: np.ndarray, rng: np.random.Generator, hue: float = 0.02, sat: float = 0.06,
           val: float = 0.06) -> np.ndarray:
    """A random nearby colour: hue shifted by up to +-hue (turns), saturation and value scaled by
    up to +-sat / +-val (relative). Used so two seeds of one material never look identical."""
    h, s, v = colorsys.rgb_to_hsv(*[float(c) for c in color])
    h = (h + rng.uniform(-hue, hue)) % 1.0
    s = float(np.clip(s * (1.0 + rng.uniform(-sat, sat)), 0.0, 1.0))
    v = float(np.clip(v * (1.0 + rng.uniform(-val, val)), 0.0, 1.0))
    return np.array(colorsys.hsv_to_rgb(h, s, v), F32)


def scale_value(color: np.ndarray, factor: float) -> np.ndarray:
    """Darken (factor < 1) or lighten a colour in HSV value, keeping hue."""
    h, s, v = colorsys.rgb_to_hsv(*[float(c) for c in color])
    return np.array(colorsys.hsv_to_rgb(h, s, float(np.clip(v * factor, 0.0, 1.0))), F32)


def mix(a: np.ndarray, b: np.ndarray, t: np.ndarray | float | np.floating) -> np.ndarray:
    """Linear blend of colours (or colour fields) a -> b by t (scalar or (H, W) field)."""
    t = np.asarray(t, F32)
    if t.ndim >= 2:
        t = t[..., None]
    return (np.asarray(a, F32) + (np.asarray(b, F32) - np.asarray(a, F32)) * t).astype(F32)


def ramp(t: np.ndarray, stops: list[tuple[float, np.ndarray]]) -> np.ndarray:
    """Map a scalar field through a piecewise-linear colour gradient given as (position, rgb)."""
    pos = np.array([s[0] for s in stops], F32)
    cols = np.stack([np.asarray(s[1], F32) for s in stops])
    flat = t.astype(F32).ravel()
    out = np.stack([np.interp(flat, pos, cols[:, c]) for c in range(3)], axis=-1)
    return out.reshape(t.shape + (3,)).astype(F32)


def modulate(color: np.ndarray, factor: np.ndarray) -> np.ndarray:
    """Multiply a colour (3,) or colour field (H, W, 3) by a scalar field (H, W)."""
    return (np.asarray(color, F32) * factor.astype(F32)[..., None]).astype(F32)


def solid(color: np.ndarray, res: int) -> np.ndarray:
    """A (res, res, 3) image of one colour."""
    return np.broadcast_to(np.asarray(color, F32), (res, res, 3)).astype(F32)
