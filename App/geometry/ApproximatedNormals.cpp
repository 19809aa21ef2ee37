#include "geometry/ApproximatedNormals.hpp"

#include <cmath>
#include <stdexcept>

namespace nurbslod {

const char* toString(NormalWeighting weighting) {
    switch (weighting) {
        case NormalWeighting::Uniform:
            return "uniform";
        case NormalWeighting::Area:
            return "area";
        case NormalWeighting::InverseArea:
            return "inverse area";
        case NormalWeighting::Angle:
            return "angle";
    }
    return "?";
}

namespace {

// The weighted sum of the facet normals around an interior vertex; e[0..3] are the edges to
// the neighbours in turn: +u, +v, -u, -v, so that the sum points along du x dv.
template <NormalWeighting kWeighting>
Vector3 facetSum(const Vector3 (&e)[4]) {
    Vector3 sum = Vector3::Zero();
    for (int f = 0; f < 4; ++f) {
        const Vector3& a = e[f];
        const Vector3& b = e[(f + 1) % 4];
        const Vector3 n = a.cross(b);  // twice the area times the unit facet normal
        if constexpr (kWeighting == NormalWeighting::Area) {
            sum += n;
        } else {
            const double length2 = n.squaredNorm();
            if (!(length2 > 0)) continue;
            if constexpr (kWeighting == NormalWeighting::Uniform) {
                sum += n / std::sqrt(length2);
            } else if constexpr (kWeighting == NormalWeighting::InverseArea) {
                sum += n / length2;  // unit normal over (twice) the area
            } else {
                const double angle = std::atan2(std::sqrt(length2), a.dot(b));
                sum += (angle / std::sqrt(length2)) * n;
            }
        }
    }
    return sum;
}

Vector3 unitOr(const Vector3& n, const Vector3& fallback) {
    const double length = n.norm();
    return length > 0 && std::isfinite(length) ? Vector3(n / length) : fallback;
}

// Section 3, figure 1: reflect the normal of the last interior vertex across the plane
// perpendicular to the chord d from it to the boundary vertex (the axis of symmetry lies in
// the plane of N and d, perpendicular to d): N' = N - 2 (N.d) d / |d|^2.
Vector3 extrapolate(const Vector3& interiorNormal, const Point3& interior, const Point3& boundary) {
    const Vector3 d = boundary - interior;
    const double d2 = d.squaredNorm();
    if (!(d2 > 0)) return interiorNormal;
    return unitOr(interiorNormal - (2 * interiorNormal.dot(d) / d2) * d, interiorNormal);
}

template <NormalWeighting kWeighting>
void interiorNormals(const Point3* points, int rows, int columns, Vector3* normals) {
    if constexpr (kWeighting == NormalWeighting::Area) {
        // the four cross products summed as they are telescope into one: e0 x e1 + e1 x e2 +
        // e2 x e3 + e3 x e0 = (e0 - e2) x (e1 - e3), the central differences' cross product.
        // This is why area weighting is the cheapest (section 3): it removes work.
        for (int i = 1; i + 1 < rows; ++i) {
            const Point3* row = points + static_cast<size_t>(i) * columns;
            for (int j = 1; j + 1 < columns; ++j) {
                const Vector3 n =
                    (row[j + columns] - row[j - columns]).cross(row[j + 1] - row[j - 1]);
                normals[static_cast<size_t>(i) * columns + j] = unitOr(n, Vector3(0, 0, 1));
            }
        }
        return;
    }
    for (int i = 1; i + 1 < rows; ++i) {
        const Point3* row = points + static_cast<size_t>(i) * columns;
        for (int j = 1; j + 1 < columns; ++j) {
            const Point3& p = row[j];
            const Vector3 e[4] = {row[j + columns] - p, row[j + 1] - p, row[j - columns] - p,
                                  row[j - 1] - p};
            normals[static_cast<size_t>(i) * columns + j] =
                unitOr(facetSum<kWeighting>(e), Vector3(0, 0, 1));
        }
    }
}

}  // namespace

void approximateGridNormals(const Point3* points, int rows, int columns, NormalWeighting weighting,
                            Vector3* normals, BoundaryExtrapolation extrapolation) {
    if (rows < 3 || columns < 3)
        throw std::invalid_argument("approximated normals need a grid of at least 3 x 3 points");
    switch (weighting) {
        case NormalWeighting::Uniform:
            interiorNormals<NormalWeighting::Uniform>(points, rows, columns, normals);
            break;
        case NormalWeighting::Area:
            interiorNormals<NormalWeighting::Area>(points, rows, columns, normals);
            break;
        case NormalWeighting::InverseArea:
            interiorNormals<NormalWeighting::InverseArea>(points, rows, columns, normals);
            break;
        case NormalWeighting::Angle:
            interiorNormals<NormalWeighting::Angle>(points, rows, columns, normals);
            break;
    }
    auto at = [columns](int i, int j) { return static_cast<size_t>(i) * columns + j; };
    // boundary vertex b from the interior vertices one (near) and two (far) steps inside
    auto boundaryNormal = [&](size_t b, size_t near, size_t far, bool linear) {
        if (linear) return unitOr(2 * normals[near] - normals[far], normals[near]);
        return extrapolate(normals[near], points[near], points[b]);
    };
    const bool linearRows = extrapolation == BoundaryExtrapolation::Linear && columns >= 4;
    const bool linearColumns = extrapolation == BoundaryExtrapolation::Linear && rows >= 4;
    // first and last column of each interior row, along the row's iso-parametric line
    for (int i = 1; i + 1 < rows; ++i) {
        normals[at(i, 0)] = boundaryNormal(at(i, 0), at(i, 1), at(i, 2), linearRows);
        normals[at(i, columns - 1)] =
            boundaryNormal(at(i, columns - 1), at(i, columns - 2), at(i, columns - 3), linearRows);
    }
    // first and last row, corners included, along the columns
    for (int j = 0; j < columns; ++j) {
        normals[at(0, j)] = boundaryNormal(at(0, j), at(1, j), at(2, j), linearColumns);
        normals[at(rows - 1, j)] =
            boundaryNormal(at(rows - 1, j), at(rows - 2, j), at(rows - 3, j), linearColumns);
    }
}

}  // namespace nurbslod
