#pragma once

// Our B-spline surface as an OpenCASCADE Geom_BSplineSurface, so that tests and benchmarks can
// evaluate the very same surface with both (header only: shared by tests/unit and tests/bench).

#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <vector>

#include "geometry/BSplineSurface.hpp"

namespace nurbslod::testing {

inline void distinctKnots(const std::vector<double>& flat, std::vector<double>& knots,
                          std::vector<int>& multiplicities) {
    for (double k : flat) {
        if (!knots.empty() && knots.back() == k) {
            ++multiplicities.back();
        } else {
            knots.push_back(k);
            multiplicities.push_back(1);
        }
    }
}

inline Handle(Geom_BSplineSurface) toOcctSurface(const BSplineSurface& s) {
    const int nu = s.countU(), nv = s.countV();
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    TColStd_Array2OfReal weights(1, nu, 1, nv);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const auto& p = s.pole(i, j);
            poles(i + 1, j + 1) = gp_Pnt(p[0] / p[3], p[1] / p[3], p[2] / p[3]);
            weights(i + 1, j + 1) = p[3];
        }
    std::vector<double> ku, kv;
    std::vector<int> mu, mv;
    distinctKnots(s.knotsU().knots(), ku, mu);
    distinctKnots(s.knotsV().knots(), kv, mv);
    TColStd_Array1OfReal knotsU(1, static_cast<int>(ku.size())),
        knotsV(1, static_cast<int>(kv.size()));
    TColStd_Array1OfInteger multsU(1, static_cast<int>(mu.size())),
        multsV(1, static_cast<int>(mv.size()));
    for (size_t k = 0; k < ku.size(); ++k) {
        knotsU(static_cast<int>(k) + 1) = ku[k];
        multsU(static_cast<int>(k) + 1) = mu[k];
    }
    for (size_t k = 0; k < kv.size(); ++k) {
        knotsV(static_cast<int>(k) + 1) = kv[k];
        multsV(static_cast<int>(k) + 1) = mv[k];
    }
    if (s.isRational())
        return new Geom_BSplineSurface(poles, weights, knotsU, knotsV, multsU, multsV, s.degreeU(),
                                       s.degreeV());
    return new Geom_BSplineSurface(poles, knotsU, knotsV, multsU, multsV, s.degreeU(), s.degreeV());
}

}  // namespace nurbslod::testing
