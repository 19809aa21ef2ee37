#include "geometry/TriangularBezierPatch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace nurbslod {

namespace {

using Row = std::array<HomogeneousPoint3, TriangularBezierPatch::kMostDegree + 1>;

// One de Casteljau level at x over the first count points, in place (count - 1 left).
inline void step(Row& points, int count, double x) {
    for (int i = 0; i + 1 < count; ++i) points[i] = (1 - x) * points[i] + x * points[i + 1];
}

// The blossom of the Bezier curve `points` (degree + 1 of them) at every multiset of c0 copies
// of x0, c1 of x1 and the rest of x2, into out[indexOf(degree, c0, c1)]: the curve over a
// triangle of its parameter line. The levels of x0 and then of x1 are shared by every multiset
// that begins with them (the blossom is symmetric: the order of its arguments is free).
void blossomsOverTriangle(const Row& points, int degree, const std::array<double, 3>& x,
                          HomogeneousPoint3* out) {
    // only the points still in use are copied (a Row holds room for the highest degree)
    Row first, second, last;
    std::copy_n(points.begin(), degree + 1, first.begin());
    for (int c0 = 0; c0 <= degree; ++c0) {
        if (c0 > 0) step(first, degree - c0 + 2, x[0]);
        std::copy_n(first.begin(), degree - c0 + 1, second.begin());
        for (int c1 = 0; c0 + c1 <= degree; ++c1) {
            if (c1 > 0) step(second, degree - c0 - c1 + 2, x[1]);
            const int left = degree - c0 - c1;
            std::copy_n(second.begin(), left + 1, last.begin());
            for (int count = left + 1; count > 1; --count) step(last, count, x[2]);
            out[TriangularBezierPatch::indexOf(degree, c0, c1)] = last[0];
        }
    }
}

struct BinomialTable {
    double value[TriangularBezierPatch::kMostDegree + 1][TriangularBezierPatch::kMostDegree + 1] =
        {};
    BinomialTable() {
        for (int r = 0; r <= TriangularBezierPatch::kMostDegree; ++r) {
            value[r][0] = 1;
            for (int k = 1; k <= r; ++k) value[r][k] = value[r - 1][k - 1] + value[r - 1][k];
        }
    }
};

}  // namespace

TriangularBezierPatch::TriangularBezierPatch(const BezierPatch& patch,
                                             const std::array<Point2, 3>& corner) {
    const int p = patch.degreeU(), q = patch.degreeV(), n = p + q;
    if (n > kMostDegree) throw std::invalid_argument("triangular patch of too high a degree");
    degree_ = n;
    const std::array<double, 3> s{corner[0].x(), corner[1].x(), corner[2].x()};
    const std::array<double, 3> t{corner[0].y(), corner[1].y(), corner[2].y()};
    // f(a; b): the tensor blossom at u-arguments a (a0 copies of s0, a1 of s1, a2 of s2) and
    // v-arguments b, for every such multiset pair: each column over the triangle in u, then
    // each row of those over the triangle in v
    const int countU = (p + 1) * (p + 2) / 2, countV = (q + 1) * (q + 2) / 2;
    std::vector<HomogeneousPoint3> columns(countU * (q + 1));  // [j * countU + a]
    Row line;
    for (int j = 0; j <= q; ++j) {
        for (int i = 0; i <= p; ++i) line[i] = patch.pole(i, j);
        blossomsOverTriangle(line, p, s, columns.data() + j * countU);
    }
    std::vector<HomogeneousPoint3> tensor(countU * countV);  // [a * countV + b]
    for (int a = 0; a < countU; ++a) {
        for (int j = 0; j <= q; ++j) line[j] = columns[j * countU + a];
        blossomsOverTriangle(line, q, t, tensor.data() + a * countV);
    }
    // b_I = sum over a <= I, |a| = p, of C(i0, a0) C(i1, a1) C(i2, a2) f(a; I - a) / C(n, p)
    static const BinomialTable binomials;
    const auto& binomial = binomials.value;
    poles_.assign((n + 1) * (n + 2) / 2, HomogeneousPoint3::Zero());
    for (int i0 = 0; i0 <= n; ++i0)
        for (int i1 = 0; i0 + i1 <= n; ++i1) {
            const int i2 = n - i0 - i1;
            HomogeneousPoint3 sum = HomogeneousPoint3::Zero();
            for (int a0 = std::max(0, p - i1 - i2); a0 <= std::min(i0, p); ++a0)
                for (int a1 = std::max(0, p - a0 - i2); a1 <= std::min(i1, p - a0); ++a1) {
                    const int a2 = p - a0 - a1;
                    sum += binomial[i0][a0] * binomial[i1][a1] * binomial[i2][a2] *
                           tensor[indexOf(p, a0, a1) * countV + indexOf(q, i0 - a0, i1 - a1)];
                }
            poles_[indexOf(n, i0, i1)] = sum / binomial[n][p];
        }
}

Point3 TriangularBezierPatch::point(double l0, double l1, double l2) const {
    // in place: each level's b_ij is written over the old b_(i+1)j, in rising index order, and
    // reads only indices at or above its own
    std::vector<HomogeneousPoint3> level = poles_;
    for (int m = degree_; m > 0; --m)
        for (int i = m - 1; i >= 0; --i)
            for (int j = 0; i + j < m; ++j)
                level[indexOf(m - 1, i, j)] = l0 * level[indexOf(m, i + 1, j)] +
                                              l1 * level[indexOf(m, i, j + 1)] +
                                              l2 * level[indexOf(m, i, j)];
    return projectHomogeneous(level[0]);
}

std::vector<std::vector<HomogeneousPoint3>> TriangularBezierPatch::levelsAt(
    const std::array<double, 3>& at) const {
    std::vector<std::vector<HomogeneousPoint3>> levels{poles_};
    for (int m = degree_; m > 0; --m) {
        const std::vector<HomogeneousPoint3>& above = levels.back();
        std::vector<HomogeneousPoint3> level((m * (m + 1)) / 2);
        for (int i = 0; i < m; ++i)
            for (int j = 0; i + j < m; ++j)
                level[indexOf(m - 1, i, j)] = at[0] * above[indexOf(m, i + 1, j)] +
                                              at[1] * above[indexOf(m, i, j + 1)] +
                                              at[2] * above[indexOf(m, i, j)];
        levels.push_back(std::move(level));
    }
    return levels;
}

TriangularBezierPatch TriangularBezierPatch::fromLevels(
    const std::vector<std::vector<HomogeneousPoint3>>& levels, int degree,
    const std::array<int, 3>& corners) {
    TriangularBezierPatch part;
    part.degree_ = degree;
    part.poles_.resize(((degree + 1) * (degree + 2)) / 2);
    for (int a = 0; a <= degree; ++a)
        for (int b = 0; a + b <= degree; ++b) {
            // copies of the old corners 0, 1, 2 and of the point (3) in this pole's multiset
            std::array<int, 4> count{};
            count[corners[0]] += a;
            count[corners[1]] += b;
            count[corners[2]] += degree - a - b;
            part.poles_[indexOf(degree, a, b)] =
                levels[count[3]][indexOf(degree - count[3], count[0], count[1])];
        }
    return part;
}

std::array<TriangularBezierPatch, 2> TriangularBezierPatch::halves(int side) const {
    const int k = side, next = (side + 1) % 3;
    std::array<double, 3> middle{};
    middle[k] = middle[next] = 0.5;
    const auto levels = levelsAt(middle);
    std::array<int, 3> first{0, 1, 2}, second{0, 1, 2};
    first[next] = 3;
    second[k] = 3;
    return {fromLevels(levels, degree_, first), fromLevels(levels, degree_, second)};
}

double TriangularBezierPatch::farthestFromAffine(const std::array<Point3, 3>& image) const {
    const int n = degree_, raised = n + 1;
    double farthest2 = 0;
    // D_J = sum over k of J_k / (n + 1) (P_{J - e_k} - w_{J - e_k} X_k), W_J the same sum of
    // weights: the patch raised to n + 1 less the affine map times the weight
    for (int j0 = 0; j0 <= raised; ++j0)
        for (int j1 = 0; j0 + j1 <= raised; ++j1) {
            const int j2 = raised - j0 - j1;
            Point3 difference = Point3::Zero();
            double weight = 0;
            auto add = [&](int share, int i0, int i1, const Point3& x) {
                if (share == 0) return;
                const HomogeneousPoint3& b = poles_[indexOf(n, i0, i1)];
                const double f = static_cast<double>(share) / raised;
                difference += f * (b.head<3>() - b[3] * x);
                weight += f * b[3];
            };
            add(j0, j0 - 1, j1, image[0]);
            add(j1, j0, j1 - 1, image[1]);
            add(j2, j0, j1, image[2]);
            if (!(weight > 0)) return std::numeric_limits<double>::infinity();
            farthest2 = std::max(farthest2, difference.squaredNorm() / (weight * weight));
        }
    return std::sqrt(farthest2);
}

}  // namespace nurbslod
