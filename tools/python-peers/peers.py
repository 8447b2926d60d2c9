"""colour-science and numpy beside speclab, on the same spectra (F11 x H4).

- colour.sd_to_XYZ per call: one light x reflectance, colour's own
  interpolation and integration (its defaults: 1 nm, ASTM E308 weights);
- colour.msds_to_XYZ on a batch of reflectances under one light;
- a numpy Monte Carlo: hero sampling, K = 4, with np.interp (linear) on the
  tabulated data, per wavelength.

Figures are medians of repeated timings in this process; compare them with
`cargo bench --bench peers` (a separate run: ratios across the two are
indicative only).
"""

import re
import statistics
import time
from pathlib import Path

import colour
import numpy as np

DATA = Path(__file__).resolve().parents[2] / "data"


def brace(name):
    """(wavelengths, values) from one of speclab's brace-notation files."""
    pairs = re.findall(r"\{\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*\}", (DATA / name).read_text())
    lam, val = zip(*((float(a), float(b)) for a, b in pairs))
    return np.array(lam), np.array(val)


def sd(name, values=None):
    lam, val = brace(name)
    return colour.SpectralDistribution(dict(zip(lam, val if values is None else values)), name=name)


def timed(f, repeat=15):
    """Median seconds per call of f over `repeat` calls (after one warm-up)."""
    f()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main():
    light, surface = sd("illuminant_f11.txt"), sd("patch_h4.txt")
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"]
    shape = colour.SpectralShape(380, 730, 1)

    per_call = timed(lambda: colour.sd_to_XYZ(surface, cmfs, light, shape=shape), repeat=51)

    # A batch of 16384 reflectances on the patches' 10 nm grid (mixtures).
    patches = np.array([brace(f"patch_{p}.txt")[1] for p in ("e2", "f4", "g4", "h4", "j4", "a1")])
    rng = np.random.default_rng(1)
    weights = rng.random((16384, 6))
    weights /= weights.sum(axis=1, keepdims=True)
    grid = brace("patch_h4.txt")[0]
    msds = colour.MultiSpectralDistributions(dict(zip(grid, (weights @ patches).T)))
    batch = timed(lambda: colour.msds_to_XYZ(msds, cmfs, light, shape=colour.SpectralShape(380, 730, 10)), repeat=5)

    # numpy Monte Carlo, hero K = 4, np.interp on the tabulated data.
    lam_l, val_l = brace("illuminant_f11.txt")
    lam_s, val_s = brace("patch_h4.txt")
    xb, yb, zb = (brace(f"cie1931_{c}.txt") for c in "xyz")
    n = 1 << 16

    def monte_carlo():
        u = rng.random(n)
        lam = 380.0 + 350.0 * ((u[:, None] + np.arange(4) / 4.0) % 1.0)
        v = np.interp(lam, lam_l, val_l) * np.interp(lam, lam_s, val_s)
        return [350.0 * np.mean(np.interp(lam, c[0], c[1]) * v) for c in (xb, yb, zb)]

    mc = timed(monte_carlo, repeat=15)

    print(f"colour-science {colour.__version__}, numpy {np.__version__}")
    print(f"| path | time |\n|---|---|")
    print(f"| colour.sd_to_XYZ, one pair (1 nm) | {per_call * 1e6:.0f} µs |")
    print(f"| colour.msds_to_XYZ, 16384 reflectances | {batch * 1e3:.1f} ms, {16384 / batch / 1e6:.2f} M spectra/s |")
    print(f"| numpy Monte Carlo, hero K = 4, np.interp | {mc / (4 * n) * 1e9:.1f} ns per wavelength |")


if __name__ == "__main__":
    main()
