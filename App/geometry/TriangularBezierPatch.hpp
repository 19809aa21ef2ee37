#pragma once

#include <array>
#include <vector>

#include "geometry/BezierPatch.hpp"

namespace nurbslod {

// A (rational) Bezier patch over a triangle in Bernstein form of total degree n: homogeneous
// poles b_ijk, i + j + k = n, the weight of corner 0 falling as i falls (b_n00 is corner 0).
//
// Made from a tensor-product patch over a triangle of its parameter square, where it is exact:
// the tensor patch of degrees (p, q) composed with the affine map of the triangle is a
// polynomial of total degree p + q. Its blossom is the mean, over every way of giving p of the
// p + q arguments to u and the others to v, of the tensor patch's blossom (multi-affine in
// each argument, symmetric, the patch on the diagonal), and b_ijk is that blossom at i copies of
// corner 0, j of corner 1 and k of corner 2. The hull of the poles then bounds the surface over
// the triangle itself, where the tensor patch's hull bounds it over the triangle's box.
class TriangularBezierPatch {
public:
    // The highest total degree made: (n + 1)(n + 2) / 2 poles, each a sum of up to
    // (p + 1)(p + 2) / 2 blossom values.
    static constexpr int kMostDegree = 16;

    // `patch` over the triangle whose corners are `corner` (the patch's local parameters);
    // degreeU + degreeV at most kMostDegree.
    TriangularBezierPatch(const BezierPatch& patch, const std::array<Point2, 3>& corner);

    int degree() const { return degree_; }
    // b_ijk with k = degree - i - j
    const HomogeneousPoint3& pole(int i, int j) const { return poles_[indexOf(degree_, i, j)]; }
    // The point at barycentric coordinates (l0, l1, l2), by de Casteljau.
    Point3 point(double l0, double l1, double l2) const;

    // The patches over the two halves of the triangle cut at the middle m of its side `side`
    // (side k joins corners k and k + 1 mod 3): the half with m for corner k + 1, then the half
    // with m for corner k, the other corners kept in place. By de Casteljau's algorithm at m,
    // whose levels hold the nets of the triangles that m cuts off (level r's b_ijk is the
    // blossom at r copies of m and i, j, k of the corners); exact, with no extrapolation.
    std::array<TriangularBezierPatch, 2> halves(int side) const;

    // A bound on the distance between the patch and the affine map that takes the triangle's
    // corners to `image`, over the whole triangle: the largest control point of the difference
    // in degree n + 1 (the affine map times the weight is of degree n + 1; the patch raised once
    // to match, which only brings its hull closer). Infinity where a weight is not positive.
    double farthestFromAffine(const std::array<Point3, 3>& image) const;

    // Index of b_ijk among the poles of degree n (rows of falling i).
    static int indexOf(int n, int i, int j) { return (n - i) * (n - i + 1) / 2 + j; }

private:
    TriangularBezierPatch() = default;
    // De Casteljau's levels at the point of barycentric coordinates `at`; the net of the triangle
    // whose corners are `corners` (0, 1, 2: the triangle's own; 3: the point) read from them.
    std::vector<std::vector<HomogeneousPoint3>> levelsAt(const std::array<double, 3>& at) const;
    static TriangularBezierPatch fromLevels(
        const std::vector<std::vector<HomogeneousPoint3>>& levels, int degree,
        const std::array<int, 3>& corners);

    int degree_ = 0;
    std::vector<HomogeneousPoint3> poles_;
};

}  // namespace nurbslod
