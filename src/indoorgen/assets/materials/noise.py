"""Periodic building blocks for the material generators.

Everything here tiles: a field of shape (res, res) continues from its last column into its first
(and last row into first row) without a seam. That follows from three rules:

* lattice noise uses integer frequencies and indexes its lattice modulo the frequency;
* spectral noise only holds integer frequencies (an inverse FFT is periodic by construction);
* distances (Worley, layouts) are measured on the torus, and every layout repeats an integer
  number of times across the texture.

Layouts are additionally shifted so that the texture's wrap seam falls *inside* tiles rather than
on a joint: a hard edge exactly on the seam would tile correctly but would make the seam column
statistically different from the interior ones, which the tileability check compares against.

Texture coordinates: `u` runs along columns (x, left to right), `v` along rows (y, top to
bottom), both in [0, 1). Pixel centres sit at (i + 0.5) / res.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import scipy.fft as sfft

F32 = np.float32
SQRT3 = math.sqrt(3.0)


# --------------------------------------------------------------------------- basics

@lru_cache(maxsize=16)
def _axis(res: int) -> np.ndarray:
    a = ((np.arange(res, dtype=np.float64) + 0.5) / res).astype(F32)
    a.setflags(write=False)
    return a


def grid(res: int) -> tuple[np.ndarray, np.ndarray]:
    """Pixel-centre texture coordinates as broadcastable arrays: u (1, res) and v (res, 1)."""
    a = _axis(res)
    return a[None, :], a[:, None]


def smoothstep(e0: float | np.ndarray, e1: float | np.ndarray, x: np.ndarray) -> np.ndarray:
    """Hermite ramp from 0 at e0 to 1 at e1 (float32)."""
    t = np.clip((x - e0) / (np.asarray(e1, F32) - e0 + F32(1e-12)), 0.0, 1.0)
    t = t.astype(F32, copy=False)
    return t * t * (F32(3.0) - F32(2.0) * t)


def standardize(x: np.ndarray) -> np.ndarray:
    """Zero mean, unit standard deviation over the last two axes (float32)."""
    x = x.astype(F32, copy=False)
    m = x.mean(axis=(-2, -1), keepdims=True)
    s = x.std(axis=(-2, -1), keepdims=True)
    return ((x - m) / (s + F32(1e-8))).astype(F32, copy=False)


def unit(x: np.ndarray) -> np.ndarray:
    """Rescale to [0, 1] over the last two axes."""
    lo = x.min(axis=(-2, -1), keepdims=True)
    hi = x.max(axis=(-2, -1), keepdims=True)
    return ((x - lo) / (hi - lo + F32(1e-8))).astype(F32, copy=False)


def fract(x: np.ndarray) -> np.ndarray:
    """The fractional part x - floor(x), in [0, 1) (wraps coordinates onto the tile)."""
    return x - np.floor(x)


# --------------------------------------------------------------------------- spectral noise

@lru_cache(maxsize=16)
def _freqs(res: int) -> tuple[np.ndarray, np.ndarray]:
    ky = np.fft.fftfreq(res, 1.0 / res)[:, None]
    kx = np.fft.rfftfreq(res, 1.0 / res)[None, :]
    return kx, ky


@lru_cache(maxsize=256)
def _filter(res: int, knee: float, beta: float, lo: float, hi: float, sx: float, sy: float,
            angle: float, band: float, band_width: float) -> tuple[np.ndarray, int]:
    """The amplitude filter on the rfft2 grid, and K: the filter is negligible (< 1e-4 of its
    peak) outside |kx|, |ky| <= K, so only that box needs random coefficients."""
    kx, ky = _freqs(res)
    kx, ky = kx.astype(F32), ky.astype(F32)
    if angle:
        c, s = F32(math.cos(angle)), F32(math.sin(angle))
        kx, ky = c * kx + s * ky, -s * kx + c * ky
    k = np.sqrt((kx * F32(sx)) ** 2 + (ky * F32(sy)) ** 2)
    if band > 0:
        amp = np.exp(-((k - F32(band)) / F32(band_width)) ** 2)
    else:
        amp = (F32(1.0) + (k / F32(knee)) ** 2) ** F32(-beta / 2.0)
    if lo > 0:
        amp = amp * (F32(1.0) - np.exp(-(k / F32(lo)) ** 2))
    if hi > 0:
        amp = amp * np.exp(-(k / F32(hi)) ** 2)
    amp[0, 0] = 0.0
    amp = amp.astype(F32)
    peak = float(amp.max()) or 1.0
    big = amp > peak * 1e-4
    cols = np.nonzero(big.any(axis=0))[0]
    rows = np.nonzero(big.any(axis=1))[0]
    kmax_x = int(cols.max()) if cols.size else 0
    ky_abs = np.minimum(rows, res - rows) if rows.size else np.zeros(1, int)
    K = max(1, kmax_x, int(ky_abs.max()))
    amp.setflags(write=False)
    return amp, K


def _shaped(res: int, rng: np.random.Generator, filt: tuple[np.ndarray, int],
            count: int | None) -> np.ndarray:
    """Random coefficients (uniform real and imaginary parts; the inverse FFT's sums make the
    result Gaussian) inside the filter's support box, shaped and inverse-transformed."""
    amp, K = filt
    lead = () if count is None else (count,)
    half = res // 2 + 1
    if res <= 2 * K + 1 or half <= K + 1:
        spec = (rng.random(lead + (res, half, 2), dtype=F32) - F32(0.5)).view(np.complex64)[..., 0]
        spec *= amp
    else:
        spec = np.zeros(lead + (res, half), np.complex64)
        kc = K + 1
        top = (rng.random(lead + (kc, kc, 2), dtype=F32) - F32(0.5)).view(np.complex64)[..., 0]
        bot = (rng.random(lead + (K, kc, 2), dtype=F32) - F32(0.5)).view(np.complex64)[..., 0]
        spec[..., :kc, :kc] = top * amp[:kc, :kc]
        spec[..., res - K:, :kc] = bot * amp[res - K:, :kc]
    out = sfft.irfft2(spec, s=(res, res), axes=(-2, -1))
    return standardize(out)


def spectral_noise(res: int, rng: np.random.Generator, *, knee: float = 4.0, beta: float = 1.5,
                   lo: float = 0.0, hi: float | None = None,
                   stretch: tuple[float, float] = (1.0, 1.0), angle: float = 0.0,
                   count: int | None = None) -> np.ndarray:
    """FFT-filtered noise: a random-phase spectrum whose amplitude is flat below `knee` cycles per
    texture and falls as k^-beta above it (beta 1 looks like classic fBm, 2 like soft clouds).

    `lo`/`hi` add a soft high-pass / low-pass (cycles per texture; hi defaults to 24 x knee, so
    smooth noise has no pixel grain; 0 disables it); `stretch` (sx, sy) scales the frequency
    axes, so sx > 1 makes features long along u (wood grain, brushing). Periodic by
    construction because only integer frequencies exist. Zero mean, unit std, float32.
    """
    hi = 24.0 * knee if hi is None else hi
    filt = _filter(res, float(knee), float(beta), float(lo), float(hi), float(stretch[0]),
                   float(stretch[1]), float(angle), 0.0, 1.0)
    return _shaped(res, rng, filt, count)


def grain(res: int, rng: np.random.Generator) -> np.ndarray:
    """Pixel-scale micro-texture (near-white noise, unit std): the surface variation below
    any feature size that keeps smooth materials from looking like flat CG fills."""
    return spectral_noise(res, rng, knee=res / 3.0, beta=0.3, hi=0.0)


def band_noise(res: int, rng: np.random.Generator, freq: float, width: float | None = None, *,
               stretch: tuple[float, float] = (1.0, 1.0), angle: float = 0.0,
               count: int | None = None) -> np.ndarray:
    """Noise concentrated around one spatial frequency (cycles per texture): blobs of a single
    size, e.g. orange peel, carpet tufts, fabric slubs. Zero mean, unit std."""
    width = freq * 0.35 if width is None else width
    filt = _filter(res, 1.0, 0.0, 0.0, 0.0, float(stretch[0]), float(stretch[1]), float(angle),
                   float(freq), float(max(width, 0.5)))
    return _shaped(res, rng, filt, count)


def blur(field: np.ndarray, sigma: float) -> np.ndarray:
    """Periodic Gaussian blur with `sigma` in texture units (applied in the frequency domain)."""
    res = field.shape[0]
    kx, ky = _freqs(res)
    g = np.exp(-2.0 * (math.pi * sigma) ** 2 * (kx ** 2 + ky ** 2)).astype(F32)
    spec = sfft.rfft2(field, axes=(0, 1))
    if field.ndim == 3:
        g = g[..., None]
    return sfft.irfft2(spec * g, s=(res, res), axes=(0, 1)).astype(F32)


# --------------------------------------------------------------------------- lattice noise

def _fade(t: np.ndarray) -> np.ndarray:
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0)


@lru_cache(maxsize=64)
def _lattice_weights(res: int, freq: int) -> tuple[np.ndarray, np.ndarray]:
    """Interpolation matrices (res, freq) for one axis: W[x, i] is the quintic-fade weight of
    lattice node i at pixel x (indices wrap modulo freq), D[x, i] = W[x, i] * (pos - node)."""
    pos = (np.arange(res) + 0.5) / res * freq
    i0 = np.floor(pos).astype(int)
    t = pos - i0
    w1 = _fade(t)
    W = np.zeros((res, freq))
    D = np.zeros((res, freq))
    rows = np.arange(res)
    np.add.at(W, (rows, i0 % freq), 1.0 - w1)
    np.add.at(W, (rows, (i0 + 1) % freq), w1)
    np.add.at(D, (rows, i0 % freq), (1.0 - w1) * t)
    np.add.at(D, (rows, (i0 + 1) % freq), w1 * (t - 1.0))
    W, D = W.astype(F32), D.astype(F32)
    W.setflags(write=False)
    D.setflags(write=False)
    return W, D


def value_noise(res: int, freq: int, rng: np.random.Generator) -> np.ndarray:
    """Value noise on a wrapped freq x freq lattice, in [-1, 1]. Bilinear interpolation with a
    quintic fade is separable, so the whole field is two small matrix products."""
    freq = max(1, int(freq))
    lat = rng.uniform(-1.0, 1.0, (freq, freq)).astype(F32)
    W, _ = _lattice_weights(res, freq)
    return (W @ lat @ W.T).astype(F32)


def gradient_noise(res: int, freq: int, rng: np.random.Generator) -> np.ndarray:
    """Perlin gradient noise on a wrapped lattice (roughly in [-0.7, 0.7]). Also separable:
    sum_ij wy_j wx_i (gx_ij dx_i + gy_ij dy_j) = Wy Gx Dx^T + Dy Gy Wx^T."""
    freq = max(1, int(freq))
    ang = rng.uniform(0.0, 2.0 * math.pi, (freq, freq))
    gx, gy = np.cos(ang).astype(F32), np.sin(ang).astype(F32)
    W, D = _lattice_weights(res, freq)
    return (W @ gx @ D.T + D @ gy @ W.T).astype(F32)


def fbm(res: int, rng: np.random.Generator, freq: int = 4, octaves: int = 5, gain: float = 0.5,
        lacunarity: int = 2) -> np.ndarray:
    """Fractal sum of gradient-noise octaves at integer frequencies freq * lacunarity**o,
    standardised to zero mean, unit std. Octaves finer than 4 px per lattice cell are dropped
    (they would only alias)."""
    out = np.zeros((res, res), F32)
    amp = 1.0
    f = int(freq)
    for _ in range(octaves):
        if f > res // 4:
            break
        out += F32(amp) * gradient_noise(res, f, rng)
        amp *= gain
        f *= int(lacunarity)
    return standardize(out)


# --------------------------------------------------------------------------- sampling / warping

def sample(field: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Bilinear lookup of `field` at pixel coordinates (x = column, y = row), wrapping around.
    Uses flat indices and `take`, several times faster than 2-D fancy indexing."""
    h, w = field.shape[:2]
    x0f = np.floor(x)
    y0f = np.floor(y)
    tx = (x - x0f).astype(F32, copy=False)
    ty = (y - y0f).astype(F32, copy=False)
    x0 = x0f.astype(np.intp) % w
    y0 = y0f.astype(np.intp) % h
    x1 = x0 + 1
    x1[x1 == w] = 0
    r0 = y0 * w
    r1 = r0 + w
    r1[r1 == h * w] = 0
    flat = field.reshape(h * w, -1) if field.ndim == 3 else field.ravel()
    if field.ndim == 3:
        tx, ty = tx[..., None], ty[..., None]
    a = np.take(flat, r0 + x0, axis=0)
    top = a + (np.take(flat, r0 + x1, axis=0) - a) * tx
    a = np.take(flat, r1 + x0, axis=0)
    bot = a + (np.take(flat, r1 + x1, axis=0) - a) * tx
    return (top + (bot - top) * ty).astype(F32, copy=False)


def resample(field: np.ndarray, res: int) -> np.ndarray:
    """Band-limited periodic resize of a square field by FFT zero-padding / truncation: the
    exact trigonometric interpolant, so the result still tiles. Used to compute smooth fields
    (warps, large-scale patterns) at a low working resolution and bring them up cheaply."""
    src = field.shape[0]
    if src == res:
        return field.astype(F32, copy=False)
    spec = sfft.rfft2(field)
    out = np.zeros((res, res // 2 + 1), np.complex64)
    k = min(src, res) // 2
    out[:k, :k] = spec[:k, :k]
    out[res - k:, :k] = spec[src - k:, :k]
    return (sfft.irfft2(out, s=(res, res)) * F32((res * res) / (src * src))).astype(F32)


def smooth_warp(res: int, rng: np.random.Generator, knee: float, amount: float, *,
                beta: float = 2.0, stretch: tuple[float, float] = (1.0, 1.0), angle: float = 0.0,
                max_res: int = 192) -> np.ndarray:
    """Domain-warped smooth noise (unit std before warping), computed at a working resolution
    of at most `max_res` and resampled: the field and the displacements are band-limited, so
    nothing is lost, and the bilinear warp is the costly step at full size."""
    work = min(res, max_res)
    base = spectral_noise(work, rng, knee=knee, beta=beta, hi=6.0 * knee, stretch=stretch,
                          angle=angle)
    du, dv = warp_fields(work, rng)
    return resample(warp(base, amount * du, amount * dv), res)


def warp_fields(res: int, rng: np.random.Generator,
                knee: float = 3.0) -> tuple[np.ndarray, np.ndarray]:
    """Two smooth displacement fields for `warp` (unit std). Strongly low-passed: any pixel-scale
    content in a displacement shreds the warped field's fine lines."""
    d = spectral_noise(res, rng, knee=knee, beta=2.0, hi=4.0 * knee, count=2)
    return d[0], d[1]


def warp(field: np.ndarray, du: np.ndarray, dv: np.ndarray) -> np.ndarray:
    """Domain warping: `field` sampled at (u + du, v + dv); displacements in texture units.
    Periodic if field, du and dv are."""
    res = field.shape[0]
    cols = np.arange(res, dtype=F32)[None, :]
    rows = np.arange(res, dtype=F32)[:, None]
    return sample(field, cols + du * res, rows + dv * res)


# --------------------------------------------------------------------------- cellular noise

@dataclass
class Cells:
    """Worley noise result. Distances in cell units (1 = one cell of the jitter grid)."""

    f1: np.ndarray       # distance to the nearest feature point
    f2: np.ndarray       # distance to the second nearest
    cell: np.ndarray     # int index of the nearest point, in [0, n*n)
    n: int

    @property
    def border(self) -> np.ndarray:
        """Approximate distance to the Voronoi border (F2 - F1): 0 on cell walls."""
        return self.f2 - self.f1


def worley(res: int, n: int, rng: np.random.Generator, jitter: float = 0.9) -> Cells:
    """Cellular noise with one jittered feature point per cell of an n x n grid on the torus.
    Neighbour cells are looked up modulo n but positioned unwrapped, so distances wrap.
    Updates are branch-free (min/max and integer blends), which numpy runs much faster than
    `np.where` on random masks."""
    n = max(1, int(n))
    jitter = float(np.clip(jitter, 0.0, 1.0))
    jx = (0.5 + jitter * (rng.random((n, n)) - 0.5)).astype(F32).ravel()
    jy = (0.5 + jitter * (rng.random((n, n)) - 0.5)).astype(F32).ravel()
    # a quarter-cell shift: with one point per cell, Voronoi walls crowd near the grid lines,
    # so the wrap seam should not sit on one
    a = _axis(res) * F32(n) + F32(0.25)
    x, y = a[None, :], a[:, None]
    cxf, cyf = np.floor(x), np.floor(y)
    fx, fy = x - cxf, y - cyf  # position inside own cell (float32)
    cx, cy = cxf.astype(np.int32), cyf.astype(np.int32)
    f1 = np.full((res, res), np.inf, F32)
    f2 = np.full((res, res), np.inf, F32)
    cell = np.zeros((res, res), np.int32)
    for oy in (-1, 0, 1):
        rowidx = ((cy + oy) % n) * n
        for ox in (-1, 0, 1):
            idx = rowidx + (cx + ox) % n
            dx = jx.take(idx) + F32(ox) - fx
            dy = jy.take(idx) + F32(oy) - fy
            d = dx * dx + dy * dy
            closer = (d < f1).view(np.int8)
            cell += closer * (idx - cell)
            np.minimum(f2, np.maximum(f1, d), out=f2)
            np.minimum(f1, d, out=f1)
    return Cells(np.sqrt(f1), np.sqrt(f2), cell, n)


# --------------------------------------------------------------------------- layouts

@dataclass
class Layout:
    """A periodic tiling of the texture. Local coordinates `a` (along the tile's length) and `b`
    (across it) are distances from the tile's corner in texture units; `edge` is the distance
    to the nearest joint (texture units); `tile` is an int id, unique per tile in one period,
    in [0, count); `vertical` flags tiles rotated by 90 degrees (herringbone), else None."""

    tile: np.ndarray
    count: int
    a: np.ndarray
    b: np.ndarray
    edge: np.ndarray
    length: float
    width: float
    vertical: np.ndarray | None = None


def seam_safe_offsets(rng: np.random.Generator, rows: int, steps: int = 8) -> np.ndarray:
    """Random per-row offsets (in tile lengths) that keep every joint well off the wrap seam:
    multiples of 1/steps shifted by half a step, skipping the two nearest the seam (so even at
    low resolution a joint's bevel and the normal's finite differences stay clear of it)."""
    return ((rng.integers(1, steps - 1, rows) + 0.5) / steps).astype(F32)


def grid_layout(res: int, nx: int, ny: int, offsets: np.ndarray | None = None) -> Layout:
    """nx x ny rectangular tiles. Row r is shifted along u by offsets[r] tile lengths (default
    half a tile, so the seam is mid-tile); rows are shifted half a row so the seam is mid-row.
    Running bond: offsets = [0.25, 0.75, 0.25, ...]."""
    nx, ny = max(1, int(nx)), max(1, int(ny))
    u, v = grid(res)
    if offsets is None:
        offsets = np.full(ny, 0.5, F32)
    y = v * F32(ny) + F32(0.5)
    rowf = np.floor(y)
    row = rowf.astype(np.int32) % ny
    b = (y - rowf) / F32(ny)
    off = np.asarray(offsets, F32)[row]
    x = u * F32(nx) + off
    colf = np.floor(x)
    a = (x - colf) / F32(nx)
    tile = row * nx + colf.astype(np.int32) % nx
    lx, ly = 1.0 / nx, 1.0 / ny
    edge = np.minimum(np.minimum(a, F32(lx) - a), np.minimum(b, F32(ly) - b))
    return Layout(tile.astype(np.int32), nx * ny, np.broadcast_to(a, (res, res)),
                  np.broadcast_to(b, (res, res)), edge.astype(F32), lx, ly)


def hex_layout(res: int, nx: int) -> Layout:
    """Pointy-top hexagons, nx across; the row count is chosen so the hexagons are as close to
    regular as a square period allows. Nearest centre = the nearer of two rectangular lattices.
    `edge` is exact (hexagonal metric); `a`, `b` are offsets from the centre (texture units)."""
    nx = max(2, int(nx))
    rows = max(1, int(round(nx / SQRT3)))  # lattice-A rows; B rows interleave
    u, v = grid(res)
    x = u * F32(nx) + F32(0.25)          # seam off the vertical hexagon sides
    y = v * F32(rows * SQRT3)
    ya = y / F32(SQRT3)
    ia, ja = np.floor(x + 0.5), np.floor(ya + 0.5)
    ib, jb = np.floor(x), np.floor(ya)
    dxa, dya = x - ia, y - ja * F32(SQRT3)
    dxb, dyb = x - (ib + 0.5), y - (jb + 0.5) * F32(SQRT3)
    use_b = dxb * dxb + dyb * dyb < dxa * dxa + dya * dya
    dx = np.where(use_b, dxb, dxa)
    dy = np.where(use_b, dyb, dya)
    ida = (ja.astype(np.int32) % rows) * nx + ia.astype(np.int32) % nx
    idb = rows * nx + (jb.astype(np.int32) % rows) * nx + ib.astype(np.int32) % nx
    tile = np.where(use_b, idb, ida).astype(np.int32)
    adx, ady = np.abs(dx), np.abs(dy)
    hexd = np.maximum(adx, 0.5 * adx + (SQRT3 / 2) * ady)
    edge = ((0.5 - hexd) / nx).astype(F32)
    return Layout(tile, 2 * rows * nx, (dx / nx).astype(F32), (dy / nx).astype(F32), edge,
                  1.0 / nx, 1.0 / nx)


def _fmod(x: np.ndarray, m: float) -> np.ndarray:
    """x mod m for floats, in [0, m) (faster than np.mod, which handles signs the slow way)."""
    return x - F32(m) * np.floor(x * F32(1.0 / m))


def herringbone_layout(res: int, ratio: int = 2, repeats: int = 2) -> Layout:
    """Axis-aligned herringbone of planks `ratio` widths long. The pattern is a staircase of
    horizontal planks H_k = [k, k+n] x [k, k+1] and vertical planks V_k = [k, k+1] x [k+1, k+1+n]
    translated by the lattice (1, 1), (n, -n); a square period holds P = 2 n m widths. A pixel
    belongs to a horizontal plank iff (x - floor(y)) mod 2n < n, else to a vertical one.
    Selections are arithmetic blends (h * a + (1 - h) * b), cheaper than np.where."""
    n = max(2, int(ratio))
    period = 2 * n * max(1, int(repeats))
    u, v = grid(res)
    x = u * F32(period) + F32(0.5)   # (1, res); the seam is half a width off every joint
    y = v * F32(period) + F32(0.5)   # (res, 1)
    fx, fy = np.floor(x), np.floor(y)
    s = _fmod(x - fy, 2 * n)                   # along a horizontal plank, if in one
    h = (s < n).astype(F32)
    t = _fmod(y - F32(1.0) - fx, 2 * n)        # along a vertical plank, if in one
    g = F32(1.0) - h
    a = h * s + g * t
    b = h * (y - fy) + g * (x - fx)
    cx = np.rint(h * (x - s) + g * fx)          # plank corner (integers, as floats)
    cy = np.rint(h * fy + g * (y - t))
    cx = cx - F32(period) * np.floor((cx + F32(0.5)) * F32(1.0 / period))  # exact mod P
    cy = cy - F32(period) * np.floor((cy + F32(0.5)) * F32(1.0 / period))
    tile = (g * F32(period * period) + cx * F32(period) + cy + F32(0.5)).astype(np.int32)
    edge = np.minimum(np.minimum(a, F32(n) - a), np.minimum(b, F32(1.0) - b)) * F32(1.0 / period)
    return Layout(tile, 2 * period * period, a * F32(1.0 / period), b * F32(1.0 / period),
                  edge, n / period, 1.0 / period, h < 0.5)


def joint_mask(edge: np.ndarray, half_width: float, bevel: float, res: int) -> np.ndarray:
    """1 on the tile face, 0 in the joint: a ramp from `half_width` to `half_width + bevel`
    (texture units), widened to at least a pixel so it never aliases."""
    px = 1.0 / res
    return smoothstep(half_width - 0.5 * px, half_width + max(bevel, px), edge)
