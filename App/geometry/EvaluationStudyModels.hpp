#pragma once

#include <string>
#include <vector>

#include "geometry/BSplineSurface.hpp"

namespace nurbslod {

// A model of the evaluation study: one or more untrimmed surfaces.
struct EvaluationModel {
    std::string name;
    std::vector<BSplineSurface> surfaces;
    int vertexCount = 0;  // the vertex count the paper's Table 5 uses for it
};

// The models of the evaluation paper (section 4, figure 4) built here: the paper's own files
// are not public, so these have its degrees and Bezier patch counts with shapes of our own.
// Sup15x15: bi-degree 15, 8 x 8 spans (64 Bezier patches), rational wavy sheet.
EvaluationModel surface15x15();
// Sup10x10: bi-degree 10, 5 x 5 spans (25 patches).
EvaluationModel surface10x10();
// Sup5x5: bi-degree 5, 17 x 1 spans (17 patches).
EvaluationModel surface5x5();
// The Utah teapot: 28 bicubic patches.
EvaluationModel teapot();
// Goblet: a surface of revolution of degree 2 (the circle, 8 rational arcs) x 3 (the profile,
// 9 spans): 72 Bezier patches; the profile starts on the axis, so the base has a pole.
EvaluationModel goblet();
// Torus: rational biquadratic, 4 x 4 arcs (16 patches), radii 2 and 0.6.
EvaluationModel torus();

// The paper's models in Table 5's order.
std::vector<EvaluationModel> evaluationStudyModels();

// Two bicubic surfaces sharing the edge v = 1 of the first and v = 0 of the second (Table 1),
// joined with C1 (continuity 1) or C2 (continuity 2) continuity: the two Bezier pieces of one
// B-spline whose interior knot has multiplicity 3 - continuity.
std::vector<BSplineSurface> adjacentSurfaces(int continuity);

}  // namespace nurbslod
