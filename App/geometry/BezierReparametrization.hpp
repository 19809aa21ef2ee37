#pragma once

#include "geometry/BezierPatch.hpp"

namespace nurbslod {

// Quadratic reparametrisations of a Bezier patch, one per direction:
//   alpha(s) = s + a s (1 - s),  beta(t) = t + b t (1 - t),  |a|, |b| < 1,
// each a monotone map of [0, 1] onto itself that fixes both ends, so S(alpha(s), beta(t)) is
// the same surface piece with the same corners and each side onto itself.

// The patch S(alpha(s), beta(t)) as a rational Bezier patch, exactly: of degree 2 degreeU along
// u (degreeU where a = 0) and the same along v. alpha is the Bernstein polynomial with
// coefficients (0, (1 + a) / 2, 1); composing with it takes each B^m_i(alpha(s)) =
// C(m, i) alpha^i (1 - alpha)^(m - i) into degree 2m by products of Bernstein polynomials
// (Farin, Curves and Surfaces for CAGD, section 5.2: the product formula).
BezierPatch reparametrized(const BezierPatch& patch, double a, double b);

// The coefficients (a, b) under which the patch's sides run along their chords at about even
// speed. Along u, each side t = 0 and t = 1 has at its ends the speed along its chord, relative
// to the chord: sigma0 = m (w_1 / w_0) (P_1 - P_0).d / |d|^2 at s = 0, d the chord, and sigma1
// the same at s = 1. S(alpha(s)) then moves at sigma0 (1 + a) and sigma1 (1 - a); the a that
// brings both nearest 1 in the least-squares sense is (1 / sigma0 - 1 / sigma1) / 2, averaged
// over the two sides and kept within [-3/4, 3/4]. 0 where a side has no chord or runs back at
// an end. Any a in (-1, 1) is a reparametrisation: this only chooses one.
struct EvenSpeed {
    double a = 0, b = 0;
};
EvenSpeed evenSpeed(const BezierPatch& patch);

}  // namespace nurbslod
