#pragma once

#include <optional>
#include <string>

namespace nurbslod {

// The tolerance a user asks for, in one of two ways: absolute (model units) or relative (a
// fraction of the model's bounding-box diagonal), never both. The command line and the Python
// module resolve it the same way, so the same request gives the same mesh through either door.
struct ToleranceRequest {
    std::optional<double> absolute = std::nullopt;
    std::optional<double> relative = std::nullopt;
};

// What the front doors use when neither is given.
inline constexpr double defaultRelativeTolerance = 1e-3;

// How a front door spells the two, for its messages ("--tolerance" on the command line).
struct ToleranceNames {
    std::string absolute = "tolerance";
    std::string relative = "relative";
};

// Throws std::invalid_argument naming the argument if both are given or if either is not a
// positive finite number. Cheap: the front doors call it before the slow reading of a model.
void checkToleranceRequest(const ToleranceRequest& request, const ToleranceNames& names = {});

// The absolute tolerance: the absolute one, or the relative one (defaultRelative where neither
// is given) times the diagonal. Throws std::invalid_argument where the request is bad or the
// model has no extent (a relative tolerance then means nothing).
double resolveTolerance(const ToleranceRequest& request, double diagonal,
                        double defaultRelative = defaultRelativeTolerance,
                        const ToleranceNames& names = {});

}  // namespace nurbslod
