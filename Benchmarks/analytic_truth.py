"""Truth images of the analytic scenes: direct, fine quadrature of the emission-absorption
integral of the *analytic* field (analytic_scenes.py), never of a sampled or interpolated one.

Conventions are those of our renderer and of VTK's volume mappers (Kernels/sampling/
TransferFunction.h, Kernels/transport/RayMarcher.h, Kernels/core/Camera.h), restated here
independently:
  * transfer function: RGBA table over [lo, hi], linear between entries, clamped outside;
    opacity clamped to kMaxTableOpacity = 0.9999; extinction sigma = -ln(1 - alpha) / u with u
    the opacity unit distance (vtkVolumeProperty's ScalarOpacityUnitDistance);
  * emission-absorption: C = int_0^L T(s) sigma(s) rgb(s) ds, T(s) = exp(-int_0^s sigma),
    alpha = 1 - T(L), over a black background, linear RGB;
  * the medium fills the whole domain box [0, 1]^3 (what a user expects; ParaView's Volume
    covers it);
  * camera: vtkCamera's (view angle = full vertical angle, parallel scale = half height),
    pixel (0, 0) at the bottom left, `ss` x `ss` stratified samples a pixel (box filter).

Quadrature: `steps` midpoint segments over each ray's chord of the box, each segment composited
exactly for its midpoint extinction (C += T (1 - exp(-sigma h)) rgb, T *= exp(-sigma h)). For a
constant field that is the closed form; for smooth fields it converges as h^2, and
`truth_image` returns the largest change against half the steps as its own error estimate.
"""
import numpy as np

K_MAX_TABLE_OPACITY = 0.9999


class TransferFunction:
    def __init__(self, table, lo, hi, unit_distance):
        self.table = np.asarray(table, np.float64).reshape(-1, 4)
        if len(self.table) < 1 or not hi >= lo or not unit_distance > 0:
            raise ValueError("transfer function: expected >= 1 RGBA entries, hi >= lo and unit "
                             "distance > 0 (got %d entries, [%g, %g], u = %g)"
                             % (len(self.table), lo, hi, unit_distance))
        self.lo, self.hi, self.u = float(lo), float(hi), float(unit_distance)

    def lookup(self, v):
        """RGBA (..., 4) at values v, linear between entries, clamped."""
        n = len(self.table)
        span = self.hi - self.lo
        x = (v - self.lo) / span * (n - 1) if span > 0 else np.zeros_like(v)
        x = np.clip(np.nan_to_num(x), 0.0, n - 1)
        i0 = np.minimum(x.astype(np.int64), n - 1)
        i1 = np.minimum(i0 + 1, n - 1)
        f = (x - i0)[..., None]
        return self.table[i0] + f * (self.table[i1] - self.table[i0])

    def extinction_rgb(self, v):
        c = self.lookup(v)
        a = np.clip(c[..., 3], 0.0, K_MAX_TABLE_OPACITY)
        return -np.log1p(-a) / self.u, c[..., :3]


class Camera:
    def __init__(self, position, focal_point, up=(0, 0, 1), view_angle=30.0, parallel=False,
                 parallel_scale=1.0):
        self.position = np.asarray(position, np.float64)
        self.direction = np.asarray(focal_point, np.float64) - self.position
        self.up = np.asarray(up, np.float64)
        self.view_angle, self.parallel, self.parallel_scale = view_angle, parallel, parallel_scale

    def rays(self, width, height, jx, jy):
        """Origins and unit directions (height, width, 3) through pixel points (px + jx, py + jy)."""
        w = self.direction / np.linalg.norm(self.direction)
        u = np.cross(w, self.up)
        u /= np.linalg.norm(u)
        v = np.cross(u, w)
        py, px = np.mgrid[0:height, 0:width].astype(np.float64)
        sx = (2.0 * (px + jx) / width - 1.0) * (width / height)
        sy = 2.0 * (py + jy) / height - 1.0
        if self.parallel:
            o = self.position + self.parallel_scale * (sx[..., None] * u + sy[..., None] * v)
            d = np.broadcast_to(w, o.shape).copy()
        else:
            t = np.tan(np.radians(0.5 * self.view_angle))
            d = w + t * (sx[..., None] * u + sy[..., None] * v)
            d /= np.linalg.norm(d, axis=-1, keepdims=True)
            o = np.broadcast_to(self.position, d.shape).copy()
        return o, d


def default_camera(lo=(0, 0, 0), hi=(1, 1, 1), view_angle=30.0):
    """amrdm-bench's default view (Benchmarks/BenchScene.cxx): azimuth 35, elevation 25, the
    bounding sphere filling the view."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    centre, radius = 0.5 * (lo + hi), 0.5 * np.linalg.norm(hi - lo)
    az, el = np.radians(35.0), np.radians(25.0)
    to_eye = np.array([np.cos(el) * np.sin(az), -np.cos(el) * np.cos(az), np.sin(el)])
    eye = centre + radius / np.sin(np.radians(0.5 * view_angle)) * to_eye
    return Camera(eye, centre, (0, 0, 1), view_angle)


def box_chords(o, d, lo=(0, 0, 0), hi=(1, 1, 1)):
    """Entry and exit parameters of the rays with the box (t1 <= t0 where a ray misses)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / d
        ta = (np.asarray(lo) - o) * inv
        tb = (np.asarray(hi) - o) * inv
    t0 = np.maximum(np.nanmax(np.minimum(ta, tb), axis=-1), 0.0)
    t1 = np.nanmin(np.maximum(ta, tb), axis=-1)
    return t0, t1


def integrate(field, tf, o, d, steps, lo=(0, 0, 0), hi=(1, 1, 1), chunk=4096):
    """Linear RGBA (n, 4) of rays o, d (n, 3) through the box, `steps` segments a chord."""
    n = len(o)
    out = np.zeros((n, 4))
    t0, t1 = box_chords(o, d, lo, hi)
    hit = np.nonzero(t1 > t0)[0]
    mid = (np.arange(steps) + 0.5) / steps
    for s in range(0, len(hit), chunk):
        idx = hit[s:s + chunk]
        length = (t1[idx] - t0[idx])[:, None]
        t = t0[idx][:, None] + mid[None, :] * length
        p = o[idx][:, None, :] + t[..., None] * d[idx][:, None, :]
        sigma, rgb = tf.extinction_rgb(field.value(p[..., 0], p[..., 1], p[..., 2]))
        tau = sigma * (length / steps)
        trans_before = np.exp(-(np.cumsum(tau, axis=1) - tau))
        w = trans_before * -np.expm1(-tau)
        out[idx, :3] = (w[..., None] * rgb).sum(axis=1)
        out[idx, 3] = -np.expm1(-tau.sum(axis=1))
    return out


def truth_image(field, tf, camera, width, height, steps=512, ss=2, lo=(0, 0, 0), hi=(1, 1, 1)):
    """(image (height, width, 4) linear RGBA, estimated max abs error): the quadrature with
    `steps` segments against `steps // 2`, averaged over ss x ss pixel samples."""
    fine = np.zeros((height, width, 4))
    coarse = np.zeros((height, width, 4))
    for a in range(ss):
        for b in range(ss):
            o, d = camera.rays(width, height, (a + 0.5) / ss, (b + 0.5) / ss)
            o, d = o.reshape(-1, 3), d.reshape(-1, 3)
            fine += integrate(field, tf, o, d, steps, lo, hi).reshape(height, width, 4)
            coarse += integrate(field, tf, o, d, steps // 2, lo, hi).reshape(height, width, 4)
    fine /= ss * ss
    coarse /= ss * ss
    # Midpoint quadrature: error(steps) ~ (error(steps/2) - error(steps)) / 3.
    return fine, float(np.abs(fine - coarse).max() / 3.0)


def linear_to_srgb8(rgb):
    """8-bit sRGB of linear RGB in [0, 1] over black, as a user sees it on screen."""
    c = np.clip(rgb, 0.0, 1.0)
    s = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
    return np.round(s * 255.0).astype(np.uint8)


def srgb8_to_linear(u8):
    s = np.asarray(u8, np.float64) / 255.0
    return np.where(s <= 0.04045, s / 12.92, np.power((s + 0.055) / 1.055, 2.4))


def errors(image, truth):
    """RMSE, 99th percentile and max of the per-channel RGB difference (same units as inputs)."""
    e = np.abs(np.asarray(image, np.float64)[..., :3] - np.asarray(truth, np.float64)[..., :3])
    return {"rmse": float(np.sqrt((e * e).mean())), "p99": float(np.percentile(e, 99)),
            "max": float(e.max())}
