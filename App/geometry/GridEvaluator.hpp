#pragma once

#include <span>
#include <vector>

#include "geometry/BSplineSurface.hpp"
#include "geometry/Point.hpp"

namespace nurbslod {

// Exact evaluation of a (rational) B-spline surface on a tensor grid of parameters us x vs:
// points, and optionally exact unit normals. Vertex (i, j) (u = us[i], v = vs[j]) is written at
// index i * vs.size() + j.
//
// Coherence between the vertices of a grid (evaluation paper, section 2.2, the optimized direct
// evaluation of the NURBS Book): the basis functions and their derivatives are computed once per
// distinct u and once per distinct v; for each row (one u) the sums over the u direction,
// Q_j = sum_k N_k(u) P_kj and Q'_j = sum_k N'_k(u) P_kj, are computed once per control-point
// column j; each vertex then needs only the sums over its pv+1 columns. Rational surfaces are
// evaluated in homogeneous coordinates and their derivatives follow from the quotient rule
// (NURBS Book, equation 4.19).
//
// Beyond the paper: the per-vertex sums run on four vertices at once with AVX2+FMA where the
// CPU has it (the basis functions of four consecutive v values are laid out side by side over
// the union of their spans, padded with zeros), with a scalar path giving the same results to
// rounding; rows are spread over threads with oneTBB.
//
// Parameters outside the domain are clamped to it, and a normal where du x dv is unreliable (a
// pole) comes from BSplineSurface::normal: the same results as BSplineSurface point by point.
class GridEvaluator {
public:
    enum class InstructionSet { Scalar, Avx2 };

    // Throws std::invalid_argument naming the problem if the surface cannot be evaluated.
    explicit GridEvaluator(const BSplineSurface& surface);

    // Whether this CPU can run the AVX2+FMA path.
    static bool avx2Available();
    // The path used by evaluate(): AVX2 where available unless told otherwise.
    void setInstructionSet(InstructionSet set);
    InstructionSet instructionSet() const { return instructionSet_; }

    const BSplineSurface& surface() const { return surface_; }

    // Evaluates the grid. `points` needs us.size() * vs.size() entries, `normals` as many or
    // null for points only. `threads` <= 1 runs on the calling thread. Throws
    // std::invalid_argument for a parameter that is not finite.
    void evaluate(std::span<const double> us, std::span<const double> vs, Point3* points,
                  Vector3* normals, int threads = 1) const;

    // Convenience form returning vectors.
    void evaluate(std::span<const double> us, std::span<const double> vs,
                  std::vector<Point3>& points, std::vector<Vector3>* normals,
                  int threads = 1) const;

private:
    BSplineSurface surface_;
    // Control points as structure of arrays: component c of pole (i, j) at
    // poles_[(c * countU + i) * countV + j], so that the row sums run over contiguous memory.
    std::vector<double> poles_;
    bool rational_ = false;
    InstructionSet instructionSet_ = InstructionSet::Scalar;
};

}  // namespace nurbslod
