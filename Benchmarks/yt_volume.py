"""yt 4.1 volume rendering (Debian python3-yt) as a peer, on the same analytic AMR and camera.

yt cannot read .vthb, so the scene is handed to yt.load_amr_grids from the very block arrays
that analytic_scenes.make_amr writes (same boxes, same cell-centre values).

Transfer function, as close to ours (analytic_truth.py) as yt allows:
  * a ColorTransferFunction with grey_opacity=True: yt composites each sample as
        rgb <- dt * rgb_tab(v) * a_tab(v) + (1 - dt * a_tab(v)) * rgb
    (dt in units of the ray's parameter t), i.e. emission sigma * rgb and extinction sigma to
    first order in dt: our C = int T sigma rgb ds with exp(-sigma ds) -> 1 - sigma ds;
  * the red/green/blue tables are our linear colour table (exact: the table's nodes are on
    yt's bin nodes), the alpha table is sigma(v) = -ln(1 - alpha(v)) / u times the length of
    the image's centre ray vector (yt's dt is a fraction of that vector, not a length);
  * x_bounds are widened by 2 % beyond [lo, hi] (yt returns 0 outside its bounds, we clamp).
Residual mismatch (documented in the report): (1) first-order compositing, error O(sigma dt)
per sample; (2) yt's perspective ray vectors are not unit length: a pixel at angle theta off
the view axis gets its optical depth scaled by 1 / cos(theta) (up to about 5 % in the corners
of a 30-degree view); (3) yt places pixel centres at linspace(-0.5, 0.5, n) of its width: we
shrink the width by (n - 1) / n so the horizontal centres coincide, the vertical ones then
differ by under a quarter pixel; (4) yt interpolates vertex-centred data it derives from the
cells (averaging, extrapolated at brick faces unless use_ghost_zones), not the dual mesh;
(5) one ray a pixel (our truth box-filters 2 x 2); (6) with ghost zones the domain is made
periodic (yt needs it), which changes only the outer vertex layer.
"""
import time

import numpy as np

import analytic_scenes as scenes


def available():
    """(True, version) or (False, why)."""
    try:
        import yt  # noqa: F401
        return True, yt.__version__
    except Exception as e:  # noqa: BLE001 - any import failure means: skip with the reason
        return False, "yt import failed: %s" % e


def load_scene(field, base=32, levels=3, box=16, threshold=0.05):
    """The analytic AMR as a yt stream dataset (load_amr_grids), from analytic_scenes' boxes."""
    import yt
    boxes = scenes.build_boxes(field, base, levels, box, threshold)
    grids = []
    for level, level_boxes in enumerate(boxes):
        h = 1.0 / (base << level)
        for lo in level_boxes:
            x, y, z = scenes._centres(lo, (box,) * 3, h)
            grids.append({"left_edge": [lo[a] * h for a in range(3)],
                          "right_edge": [(lo[a] + box) * h for a in range(3)],
                          "level": level, "dimensions": [box] * 3,
                          scenes.ARRAY: field.value(x, y, z).astype(np.float64)})
    yt.set_log_level(40)
    return yt.load_amr_grids(grids, [base] * 3, bbox=np.array([[0.0, 1.0]] * 3),
                             periodicity=(False, False, False), refine_by=2)


def transfer_function(tf, centre_ray_length, nbins=None):
    """yt ColorTransferFunction for analytic_truth.TransferFunction `tf` (see module doc)."""
    from yt.visualization.volume_rendering.api import ColorTransferFunction
    span = tf.hi - tf.lo if tf.hi > tf.lo else 1.0
    pad = 0.02 * span
    nodes = len(tf.table) - 1
    per = 500  # bins per table interval: the table's nodes fall on yt's bin nodes
    n = nbins or nodes * per + 2 * int(round(pad / span * nodes * per)) + 1
    x = np.linspace(tf.lo - pad, tf.hi + pad, n)
    ctf = ColorTransferFunction((x[0], x[-1]), nbins=n, grey_opacity=True)
    sigma, rgb = tf.extinction_rgb(x)
    for c, t in enumerate((ctf.red, ctf.green, ctf.blue)):
        t.y[:] = rgb[:, c]
    ctf.alpha.y[:] = sigma * centre_ray_length
    return ctf


class YtRenderer:
    """One yt scene (source + perspective camera) matching analytic_truth.Camera `cam`."""

    def __init__(self, ds, tf, cam, width, height):
        import yt
        self.ds = ds
        self.sc = yt.create_scene(ds, ("stream", scenes.ARRAY), lens_type="perspective")
        self.source = self.sc[0]
        self.source.set_log(False)
        # One thread: with yt's OpenMP on 2 threads of this shared 2-core machine a frame took
        # 2.7 s instead of 0.3 s (threads spinning at each brick's barrier under load).
        self.source.num_threads = 1
        camera = self.sc.camera
        camera.resolution = (width, height)
        focus = cam.position + cam.direction
        dist = float(np.linalg.norm(cam.direction))
        plane_h = 2.0 * dist * np.tan(np.radians(0.5 * cam.view_angle))
        plane_w = plane_h * width / height
        camera.set_position(ds.arr(cam.position, "code_length"), north_vector=cam.up)
        camera.focus = ds.arr(focus, "code_length")
        camera.switch_orientation(normal_vector=cam.direction, north_vector=cam.up)
        camera.width = ds.arr([plane_w * (width - 1) / width, plane_h, dist], "code_length")
        centre = 0.5 * (ds.domain_left_edge.d + ds.domain_right_edge.d)
        dw = ds.domain_width.d
        # yt's ray vector (PerspectiveLens._get_sampler_params) at the image centre, in code units.
        self.centre_ray_length = float(np.linalg.norm(cam.position - centre) + 0.5 * np.linalg.norm(dw))
        self.source.set_transfer_function(transfer_function(tf, self.centre_ray_length))
        self.width, self.height = width, height

    def configure(self, num_samples, ghost_zones):
        self.source.num_samples = int(num_samples)
        if bool(self.source.use_ghost_zones) != bool(ghost_zones):
            if ghost_zones:
                # yt 4.1 gathers ghost zones only inside a periodic domain ("attempted to read
                # outside the boundaries of a non-periodic domain"): wrap it. Only the outer
                # vertex layer sees the wrapped values; our scenes are constant or ~0 there.
                self.ds.force_periodicity()
            self.source.set_use_ghost_zones(bool(ghost_zones))
            self.source._volume = None  # rebuild the bricks with (or without) ghost zones

    def render(self):
        """Linear RGB (height, width, 3), row 0 at the bottom, like a VTK capture."""
        self.sc.render()
        im = np.asarray(self.source.current_image)[..., :3]  # (width, height, 3), [x, y]
        # yt's east vector points to the image's left in this convention: flip x.
        return np.ascontiguousarray(np.transpose(im, (1, 0, 2))[:, ::-1])

    def memory_bytes(self):
        """Bytes of the bricks yt samples (vertex-centred float64 data + masks)."""
        total = 0
        for brick in self.source.volume.traverse():
            total += sum(d.nbytes for d in brick.my_data)
            mask = getattr(brick, "mask", None)
            total += mask.nbytes if mask is not None else 0
        return total


def timed(renderer, frames):
    t = time.perf_counter()
    img = renderer.render()
    first = time.perf_counter() - t
    times = []
    for _ in range(frames):
        t = time.perf_counter()
        img = renderer.render()
        times.append(time.perf_counter() - t)
    return first, times, img
