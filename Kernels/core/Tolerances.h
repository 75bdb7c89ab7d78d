// The tolerances that keep majorants and culling conservative, in one place, with the
// static_asserts that tie them together: a point the field sampler accepts (an element test's
// inside / residual tolerance, samplePrimitive's box pad) must fall in a macrocell that holds
// its primitive's value range (the majorant grid's box pads), and a value it returns there (the
// interpolant extrapolated by up to those tolerances, plus float rounding) must lie in the
// padded ranges the majorants and the culling ranges are built from. Loosen one and the asserts
// say which others must follow. Host/device code (plain constants).
#pragma once

namespace amrdm
{

// --- Element tests (Kernels/mesh/Elements.h). Lengths in the element-local frame (1 = the
// largest bounding-box extent of the element); pcoord tolerances in parametric units. ---

/// Pcoord slack of the reference-element test. Shared faces of neighbouring elements are then
/// claimed from both sides despite float rounding (no cracks); the overlap is harmless because
/// the interpolant is continuous across faces.
inline constexpr float kInsideTolerance = 1e-5f;
/// Largest |x(pcoords) - p| (local lengths) with which a non-converged Newton iteration may
/// still claim a point.
inline constexpr float kResidualTolerance = 1e-4f;

// --- Field sampling (Kernels/sampling/FieldSampler.h). ---

/// samplePrimitive rejects a point outside an element's vertex box grown by this fraction of
/// the box's extent per axis, before any Newton work, sized to the element test's residual
/// tolerance (the same fraction, of the largest extent) so that shared faces stay watertight.
inline constexpr float kElementBoxPad = 1e-4f;

// --- Majorant grid and primitive culling (Kernels/accel/MajorantGridBuilder.cpp,
// PrimitiveCulling.cpp). ---

/// The majorant grid bins an element by its box grown by this fraction of its extent: more than
/// kElementBoxPad, so that every point samplePrimitive accepts lies in a binned macrocell.
inline constexpr double kMajorantElementBoxPad = 2e-4;
/// Primitive boxes are grown by this fraction of a macrocell before they are binned, so that a
/// sample point whose world position was rounded across a macrocell face (ray t rounding, the
/// world <-> grid transform, DDA crossings) still finds the primitive's range in its macrocell.
inline constexpr double kMacrocellPad = 1e-4;
/// Value ranges (majorant grid and culling alike) are widened by this fraction of their width:
/// the element tests accept points up to kInsideTolerance (pcoords) or kResidualTolerance
/// (local lengths) outside an element, where the interpolant extrapolates slightly.
inline constexpr float kRangePadRelative = 1e-3f;
/// ... and by this fraction of their magnitude: trilinear interpolation in float can exceed the
/// corner range by a few ulps (2^-24 each); 4e-6 covers about 64 ulps.
inline constexpr float kRangePadUlps = 4e-6f;

/// Ulps of float rounding kRangePadUlps must cover.
inline constexpr float kRangeRoundingUlps = 64.0f;
/// Extrapolation bound, in units of a range's width, per unit of parametric overshoot: a
/// trilinear interpolant's value changes by at most (range width) per unit of each of its 3
/// pcoords, and an overshoot of d local lengths is at most d / kMinElementAspect in pcoords.
inline constexpr float kExtrapolationPerOvershoot = 3.0f;
/// Smallest pcoord-per-local-length ratio the range pad is sized for: elements of the dual mesh
/// span at most two levels (refinement ratio 2), so a pcoord unit is at least half the largest
/// extent.
inline constexpr float kMinElementAspect = 0.5f;

static_assert(kElementBoxPad >= kResidualTolerance,
  "samplePrimitive's box pad must let through every point the residual test may claim");
static_assert(kMajorantElementBoxPad > double(kElementBoxPad),
  "the majorant grid must bin an element over at least the box samplePrimitive accepts");
static_assert(kMacrocellPad > 0.0, "a zero macrocell pad loses points rounded across a face");
static_assert(kRangePadRelative >= kExtrapolationPerOvershoot *
                                     (kInsideTolerance + kResidualTolerance / kMinElementAspect),
  "value-range pads must cover the interpolant extrapolated by the element tests' tolerances");
static_assert(kRangePadUlps >= kRangeRoundingUlps * (1.0f / 16777216.0f),
  "the relative range pad must cover kRangeRoundingUlps of float rounding (2^-24 each)");
static_assert(kInsideTolerance < kResidualTolerance,
  "the pcoord slack is the tighter test; the residual test only rescues non-converged Newton");

// --- Closed-form checks of the whole field (Testing/Kernels/mesh/TestBoundaryLayer.cxx). ---

/// A constant field fills the domain box, the clamped boundary layer included: the
/// level-adaptive ray marcher's opacity along any chord must equal 1 - exp(-sigma * chord) to
/// within this (absolute; float rounding of the strata). A missing half cell at each face of a
/// 20-cell domain is off by about 0.02 at sigma * chord = 1.
inline constexpr float kDomainTransmittanceTolerance = 1e-5f;

// --- The element tests (mesh/Elements.h). Lengths are in the element-local frame (1 = the largest
// bounding-box extent of the element), so they are scale- and offset-free; pcoord tolerances are in
// parametric units. ---

/// Newton stops when every component of the update is below this (parametric units). Newton
/// converges quadratically, so the error after the final update is far smaller; 1e-5 is still
/// comfortably above float noise of pcoords (~1e-7 times the element's condition number).
inline constexpr float kNewtonConverged = 1e-5f;
/// A pcoord beyond this magnitude means the iteration ran away: the point is far outside (the
/// caller already checked the bounding box) or the element folds; reported as outside.
inline constexpr float kNewtonDiverged = 1e3f;
// kInsideTolerance (pcoord slack) and kResidualTolerance (non-converged Newton residual) live in
// core/Tolerances.h, tied to the box and value-range pads that keep culling conservative.
/// A point whose clamped pcoords map to within this distance (local lengths, about 8 float ulps
/// of the element size) is inside whatever its pcoords say. Near a pyramid apex or a collapsed
/// hex edge a fixed pcoord slack shrinks to nothing physically; this keeps those regions and
/// their shared faces crack-free. Small enough that the clamped value stays within 1e-6 of the
/// range of the exact one.
inline constexpr float kInsideDistance = 1e-6f;
/// The Jacobian (or a tet's edge matrix) is singular when |det| <= this times the product of its
/// column lengths, i.e. when the sine-volume of the columns is below 1e-6. This measures shape,
/// not size: it is independent of scale and of anisotropic cell aspect, and still lets Newton run
/// towards a pyramid apex where the columns shrink but stay orthogonal. Float noise of the
/// determinant of a truly flat element is about 1e-7 of the product.
inline constexpr float kSingularJacobian = 1e-6f;
/// PlanarFaces: a point is inside when it is no farther than this (local lengths) on the outer
/// side of any face plane. Same role as kInsideTolerance.
inline constexpr float kPlanarInsideTolerance = 1e-5f;
/// PlanarFaces: a face whose normal (cross of diagonals or edges, ~2x its area) is shorter than
/// this has collapsed to a segment or point and has no plane; distance ratios with a smaller
/// denominator are undefined.
inline constexpr float kDegenerateFace = 1e-6f;

} // namespace amrdm
