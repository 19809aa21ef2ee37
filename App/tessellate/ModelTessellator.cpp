#include "tessellate/ModelTessellator.hpp"

#include <stdexcept>

namespace nurbslod {

TessellationResult tessellateModel(const Model&, const TessellationOptions&) {
    throw std::logic_error("tessellateModel: not written yet");
}

}  // namespace nurbslod
