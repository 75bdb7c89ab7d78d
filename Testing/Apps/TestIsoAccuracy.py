"""The isosurface accuracy benchmark's properties on fields whose interpolation error is known
(Benchmarks/iso_accuracy.py's scoring, amrdm-isobench's rays through findIsoHit, a .vthb read by
VTK's reader; 3 levels, finest h = 1/128, level 0 h0 = 1/32, refinement around the centre so the
surfaces cross gridlets of every level and the stitching elements between them):

  linear     f = 0.5 x + 0.3 y + 0.2 z (range [0, 1]), iso 0.3, 0.5, 0.7: cell-centred samples of a
             linear field are reproduced exactly by every primitive, so |f(hit) - iso| <= 1e-5 of the
             range for every hit inside the hull of the cell centres, and every ray whose analytic
             crossing lies at least h0 inside that hull hits within 1e-4 of it (t).
  quadratic  f = |x - c|^2, iso R^2 for R = 0.15, 0.25, 0.35: an interpolant with nonnegative
             weights that reproduces linear fields overestimates this convex f by
             sum_i w_i |v_i - p|^2 <= D^2, D the farthest corner of the primitive holding p. A
             dual cell among level-l leaves has its corners within a cell of width h_l (D^2 <=
             3 h_l^2); a stitching element reaches one level coarser (D^2 <= 3 (2 h_l)^2), h_l
             the width of the leaf cell holding p. So iso - e <= f(hit) <= iso (+ float) with
             e = 12 h_l^2 (capped at 3 h0^2), the distance to the sphere is at most
             R - sqrt(R^2 - e), no ray passing outside the sphere hits (the interpolant's surface
             lies inside it), and no ray with impact parameter below R - h0 misses.

    /usr/bin/python3 Testing/Apps/TestIsoAccuracy.py BUILD/bin/amrdm-isobench
"""
import os
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "Benchmarks"))
import analytic_scenes as scenes  # noqa: E402
import iso_accuracy as bench  # noqa: E402

H0 = 1.0 / 32
RAYS = 64
failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


def indicator(x, y, z):
    """Refinement flag field (not the data): level 1 within r ~ 0.27 of the centre, level 2
    within r ~ 0.2 (analytic_scenes.build_boxes flags |indicator| h > 0.05)."""
    r2 = (x - 0.5) ** 2 + (y - 0.5) ** 2 + (z - 0.5) ** 2
    return 8.0 * np.exp(-r2 / (2 * 0.15 ** 2))


def write(name, value, work):
    field = scenes.Field(name, value, indicator, name)
    amr = scenes.make_amr(field)
    levels = amr.GetNumberOfLevels()
    path = os.path.join(work, name + ".vthb")
    scenes.write_vthb(amr, path)
    return path, levels, scenes.build_boxes(field)  # the boxes make_amr built


def leaf_width(p, boxes, box=16):
    """Width of the leaf cell holding each point (the finest level whose boxes contain it)."""
    h = np.full(len(p), H0)
    for level, lows in enumerate(boxes):
        hl = H0 / (1 << level)
        lo = np.asarray(lows, float) * hl
        inside = np.all((p[:, None, :] >= lo[None]) & (p[:, None, :] < lo[None] + box * hl), axis=2)
        h[inside.any(axis=1)] = hl
    return h


def rays_of(rec):
    return rec[:, 1:4], rec[:, 4:7], rec[:, 7] > 0, rec[:, 8], rec[:, 9:12]


def linear(exe, work):
    a = np.array([0.5, 0.3, 0.2])
    path, levels, _ = write("linear", lambda x, y, z: a[0] * x + a[1] * y + a[2] * z, work)
    check(levels == 3, "linear scene has 3 levels (%d)" % levels)
    isos = [0.3, 0.5, 0.7]
    rec = bench.run_ours(exe, path, isos, RAYS, os.path.join(work, "linear.bin"))
    for k, iso in enumerate(isos):
        o, d, hit, t, p = rays_of(rec[k])
        surface = bench.Surface(lambda q: q @ a, plane=(a, iso))
        inside = hit & np.all((p > H0 / 2) & (p < 1 - H0 / 2), axis=1)
        err = np.abs(p[inside] @ a - iso)
        check(inside.sum() > 0.3 * RAYS * RAYS,
              "linear iso %g: %d hits inside the hull" % (iso, inside.sum()))
        check(err.max() <= 1e-5, "linear iso %g: max |f(hit) - iso| %.2e <= 1e-5" % (iso, err.max()))
        t_true = surface.first_hit(o, d)
        q = o + np.where(np.isfinite(t_true), t_true, 0)[:, None] * d
        deep = np.isfinite(t_true) & np.all((q > H0 / 2 + H0) & (q < 1 - H0 / 2 - H0), axis=1)
        agree = deep & hit & (np.abs(t - t_true) <= 1e-4)
        check(agree.sum() == deep.sum(), "linear iso %g: %d of %d rays crossing >= h0 inside the "
              "hull hit within 1e-4 of the analytic t" % (iso, agree.sum(), deep.sum()))


def quadratic(exe, work):
    c = bench.CENTRE
    path, levels, boxes = write("quadratic", lambda x, y, z: (x - c[0]) ** 2 + (y - c[1]) ** 2 +
                         (z - c[2]) ** 2, work)
    check(levels == 3, "quadratic scene has 3 levels (%d)" % levels)
    radii = [0.15, 0.25, 0.35]
    rec = bench.run_ours(exe, path, [r * r for r in radii], RAYS, os.path.join(work, "quad.bin"))
    for k, R in enumerate(radii):
        iso = R * R
        o, d, hit, t, p = rays_of(rec[k])
        surface = bench.Surface(lambda q: np.sum((q - c) ** 2, axis=1), radii=[R])
        f = surface.value(p[hit])
        dist = surface.distance(p[hit])
        e = np.minimum(12 * leaf_width(p[hit], boxes) ** 2, 3 * H0 * H0)
        bound = R - np.sqrt(R * R - e)
        check(hit.sum() > 0, "quadratic R %g: %d hits" % (R, hit.sum()))
        check(f.max() <= iso + 1e-5 and (f >= iso - e).all(),
              "quadratic R %g: f(hit) - iso in [%.2e, %.2e], within [-12 h_l^2 (%.2e .. %.2e), "
              "1e-5]" % (R, f.min() - iso, f.max() - iso, -e.max(), -e.min()))
        check((dist <= bound).all(), "quadratic R %g: distance to the sphere median %.2e, max %.2e;"
              " bound R - sqrt(R^2 - 12 h_l^2) %.2e .. %.2e, worst ratio %.2f" % (
                  R, np.median(dist), dist.max(), bound.min(), bound.max(), (dist / bound).max()))
        oc = o - c
        b = np.linalg.norm(oc - np.einsum("ij,ij->i", oc, d)[:, None] * d, axis=1)
        outside, core = b > R, b < R - H0
        check(not (hit & outside).any(), "quadratic R %g: no hit on the %d rays passing outside "
              "the sphere (%d)" % (R, outside.sum(), (hit & outside).sum()))
        check((hit | ~core).all(), "quadratic R %g: every one of the %d rays with impact "
              "parameter < R - h0 hits (%d miss)" % (R, core.sum(), (core & ~hit).sum()))


def main():
    if len(sys.argv) != 2 or not os.path.isfile(sys.argv[1]):
        sys.exit("usage: TestIsoAccuracy.py PATH/TO/amrdm-isobench (got %s)" % sys.argv[1:])
    with tempfile.TemporaryDirectory(prefix="iso-accuracy-test-") as work:
        linear(sys.argv[1], work)
        quadratic(sys.argv[1], work)
    if failures:
        sys.exit("%d check(s) failed" % len(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
