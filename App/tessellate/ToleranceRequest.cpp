#include "tessellate/ToleranceRequest.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace nurbslod {

namespace {

void requirePositiveFinite(const std::optional<double>& value, const std::string& name) {
    if (!value || (std::isfinite(*value) && *value > 0)) return;
    std::ostringstream message;
    message << name << " must be a positive finite number, got " << *value;
    throw std::invalid_argument(message.str());
}

}  // namespace

void checkToleranceRequest(const ToleranceRequest& request, const ToleranceNames& names) {
    if (request.absolute && request.relative)
        throw std::invalid_argument("give either " + names.absolute +
                                    " (absolute, model units) or " + names.relative +
                                    " (fraction of the bounding box diagonal), not both");
    requirePositiveFinite(request.absolute, names.absolute);
    requirePositiveFinite(request.relative, names.relative);
}

double resolveTolerance(const ToleranceRequest& request, double diagonal, double defaultRelative,
                        const ToleranceNames& names) {
    checkToleranceRequest(request, names);
    if (request.absolute) return *request.absolute;
    const double tolerance = request.relative.value_or(defaultRelative) * diagonal;
    if (!(std::isfinite(diagonal) && diagonal > 0))
        throw std::invalid_argument("the model has no extent, so " + names.relative +
                                    " cannot be used; give " + names.absolute);
    if (!std::isfinite(tolerance)) {
        std::ostringstream message;
        message << names.relative << " " << request.relative.value_or(defaultRelative)
                << " times the model's diagonal (" << diagonal << ") is not a finite number";
        throw std::invalid_argument(message.str());
    }
    return tolerance;
}

}  // namespace nurbslod
