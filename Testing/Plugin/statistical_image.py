"""Python equivalent of Kernels/render/StatisticalImageTest.h (after Mitsuba 3's image tests):
do two sets of renders estimate the same image? Each side is K independent images (different
seeds); per pixel and channel, their mean and the variance of that mean (K - 1 dof).

1. Per pixel and channel, Welch's t-test with the Welch-Satterthwaite dof, two-sided Student p,
   Sidak over all N tests: reject when p < 1 - (1 - alpha/2)^(1/N). Each side's variance is
   floored at the other's per-image variance over its own count (under H0 both draw the same
   distribution; unfloored, a pixel whose images all agree has variance 0).
2. Per channel, the summed difference z = sum(mean_a - mean_b) / sqrt(sum(v_a + v_b)), Sidak over
   the channels at alpha/2: catches small global biases no single pixel resolves.
Pairs with both variances zero pass only when the means agree.

Two additions for 8-bit images (the C++ helper reads the renderer's float sums): `tile` averages
tile x tile pixel blocks first (a pixel of a few samples takes a handful of discrete values, so
four images often agree exactly and give a variance of 0), and `allowance` (8-bit units) is
subtracted from each |difference| (and from the channels' mean difference) before both criteria: sort-last compositing in 8 bits
truncates once per blend (IceT: integer division), a known bias of up to 1/2 step on average.
"""
import numpy as np
from scipy import stats


def _tiles(images, tile):
    x = np.stack([np.asarray(i, dtype=float) for i in images])
    if tile <= 1:
        return x
    k, h, w, c = x.shape
    h, w = (h // tile) * tile, (w // tile) * tile
    return x[:, :h, :w].reshape(k, h // tile, tile, w // tile, tile, c).mean(axis=(2, 4))


def compare(a_images, b_images, alpha=0.01, tile=1, allowance=0.0):
    """a_images, b_images: lists of HxWxC arrays. Returns (passed, report string)."""
    a = _tiles(a_images, tile)
    b = _tiles(b_images, tile)
    ka, kb = a.shape[0], b.shape[0]
    ma, mb = a.mean(axis=0), b.mean(axis=0)
    sa, sb = a.var(axis=0, ddof=1), b.var(axis=0, ddof=1)  # per image
    va = np.maximum(sa, sb) / ka
    vb = np.maximum(sb, sa) / kb
    v = va + vb
    diff = ma - mb
    diff = np.sign(diff) * np.maximum(np.abs(diff) - allowance, 0.0)
    zero = v == 0
    bad_zero = int((zero & (diff != 0)).sum())
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(zero, 0.0, diff / np.sqrt(np.where(zero, 1.0, v)))
        dof = np.where(zero, 1.0, v ** 2 / (va ** 2 / (ka - 1) + vb ** 2 / (kb - 1) + 1e-300))
    p = 2.0 * stats.t.sf(np.abs(t), np.maximum(dof, 1.0))
    n = p.size
    threshold = 1.0 - (1.0 - alpha / 2.0) ** (1.0 / n)
    pixel_rejects = int((p < threshold).sum())
    channels = a.shape[-1]
    raw = (ma - mb).reshape(-1, channels)
    shrunk = np.maximum(np.abs(raw.sum(axis=0)) - allowance * raw.shape[0], 0.0)
    z = shrunk / np.sqrt(v.reshape(-1, channels).sum(axis=0))
    pz = 2.0 * stats.norm.sf(np.abs(z))
    channel_threshold = 1.0 - (1.0 - alpha / 2.0) ** (1.0 / channels)
    channel_rejects = int((pz < channel_threshold).sum())
    passed = pixel_rejects == 0 and channel_rejects == 0 and bad_zero == 0
    report = ("statistical test (alpha %g, %d vs %d images, %dx%d tiles, allowance %g): min p %.3g (threshold %.3g, "
              "%d rejected), channel z %s (p %s, threshold %.3g), %d zero-variance mismatches"
              % (alpha, ka, kb, tile, tile, allowance, p.min(), threshold, pixel_rejects,
                 " ".join("%.2f" % x for x in z), " ".join("%.3g" % x for x in pz),
                 channel_threshold, bad_zero))
    return passed, report
