#pragma once

#include <optional>

#include "geometry/BSplineSurface.hpp"
#include "geometry/Point.hpp"

namespace nurbslod {

// A surface point with its partial derivatives up to order two.
struct SurfaceSecondDerivatives {
    Point3 point;
    Vector3 du, dv;
    Vector3 duu, duv, dvv;
};

// The curvature of a surface at a point, with respect to the unit normal du x dv: positive
// where the surface bends towards the normal. minimum <= maximum; mean = (minimum +
// maximum) / 2; gaussian = minimum * maximum. The directions are unit tangents (arbitrary but
// orthogonal at an umbilic).
struct SurfaceCurvature {
    Vector3 normal;
    double gaussian = 0;
    double mean = 0;
    double minimum = 0;
    double maximum = 0;
    Vector3 minimumDirection;
    Vector3 maximumDirection;
};

// Derivatives of the (rational) surface at (u, v), clamped to the domain like
// BSplineSurface::point: the homogeneous derivatives from the basis function derivatives
// (NURBS Book, algorithm A2.3 up to order two), then the rational ones by the quotient rule
// (NURBS Book, equation 4.20 / algorithm A4.4).
SurfaceSecondDerivatives secondDerivatives(const BSplineSurface& surface, double u, double v);

// The curvature at (u, v) from the first and second fundamental forms (do Carmo, section
// 3-3), or nothing at a singular point, where du x dv vanishes (a sphere's pole, a collapsed
// edge) and the normal is undefined.
std::optional<SurfaceCurvature> curvatureAt(const BSplineSurface& surface, double u, double v);

// The curvature a display shows at (u, v): at a singular point the curvature a growing step
// inside the domain, the limit, as BSplineSurface::normal does for the normal. All zero with
// normal (0, 0, 1) only where no nearby point is regular either (a surface collapsed to a
// curve or a point).
SurfaceCurvature displayCurvature(const BSplineSurface& surface, double u, double v);

}  // namespace nurbslod
