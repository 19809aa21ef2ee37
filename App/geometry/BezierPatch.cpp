#include "geometry/BezierPatch.hpp"

namespace nurbslod {

BezierPatch::BezierPatch(int degreeU, int degreeV)
    : degreeU_(degreeU),
      degreeV_(degreeV),
      poles_(static_cast<size_t>((degreeU + 1) * (degreeV + 1)), HomogeneousPoint3::Zero()) {}

namespace {

// Keep the left part [0, t] of the curve: after de Casteljau at t the left control points are
// the first point of each level.
void keepLeft(HomogeneousPoint3* pts, int degree, int stride, double t) {
    for (int level = 1; level <= degree; ++level)
        for (int i = degree; i >= level; --i)
            pts[i * stride] = (1 - t) * pts[(i - 1) * stride] + t * pts[i * stride];
}

// Keep the right part [t, 1]: the last point of each level.
void keepRight(HomogeneousPoint3* pts, int degree, int stride, double t) {
    for (int level = 1; level <= degree; ++level)
        for (int i = 0; i <= degree - level; ++i)
            pts[i * stride] = (1 - t) * pts[i * stride] + t * pts[(i + 1) * stride];
}

}  // namespace

void restrictBezierCurve(HomogeneousPoint3* pts, int degree, int stride, double a, double b) {
    if (b < 1.0) keepLeft(pts, degree, stride, b);
    if (a > 0.0 && b > 0.0) keepRight(pts, degree, stride, a / b);
}

BezierPatch BezierPatch::restricted(double u0, double u1, double v0, double v1) const {
    BezierPatch out = *this;
    const int stride = degreeV_ + 1;
    if (u0 > 0.0 || u1 < 1.0)
        for (int j = 0; j <= degreeV_; ++j)
            restrictBezierCurve(&out.poles_[j], degreeU_, stride, u0, u1);
    if (v0 > 0.0 || v1 < 1.0)
        for (int i = 0; i <= degreeU_; ++i)
            restrictBezierCurve(&out.poles_[i * stride], degreeV_, 1, v0, v1);
    return out;
}

Point3 BezierPatch::point(double s, double t) const {
    std::vector<HomogeneousPoint3> column(degreeU_ + 1);
    std::vector<HomogeneousPoint3> row(degreeV_ + 1);
    for (int i = 0; i <= degreeU_; ++i) {
        for (int j = 0; j <= degreeV_; ++j) row[j] = pole(i, j);
        keepLeft(row.data(), degreeV_, 1, t);
        column[i] = row[degreeV_];
    }
    keepLeft(column.data(), degreeU_, 1, s);
    return projectHomogeneous(column[degreeU_]);
}

}  // namespace nurbslod
