#include "geometry/GridBasis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/BasisFunctions.hpp"

namespace nurbslod {

GridBasis makeGridBasis(const KnotVector& knots, std::span<const double> parameters, char name) {
    GridBasis table;
    table.degree = knots.degree();
    const size_t width = table.degree + 1;
    table.parameter.resize(parameters.size());
    table.span.resize(parameters.size());
    table.values.resize(parameters.size() * width);
    table.derivatives.resize(parameters.size() * width);
    for (size_t k = 0; k < parameters.size(); ++k) {
        if (!std::isfinite(parameters[k]))
            throw std::invalid_argument(std::string("grid parameter ") + name + "[" +
                                        std::to_string(k) + "] is not finite");
        // clamped like BSplineSurface: a parameter past the border meets the border
        const double t = std::clamp(parameters[k], knots.first(), knots.last());
        table.parameter[k] = t;
        table.span[k] = knots.findSpan(t);
        basisFunctionsWithDerivative(knots, table.span[k], t, &table.values[k * width],
                                     &table.derivatives[k * width]);
    }
    return table;
}

}  // namespace nurbslod
