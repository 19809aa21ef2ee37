#pragma once

#include "tessellate/TessellationOptions.hpp"

namespace nurbslod {

// How the tolerance is shared between the error sources of a tessellation.
//  - surface: kd-tree cells (paper section 5.2);
//  - lineApproximation + lineSimplification: trimming curves to chords, gamma = 3/4 of the
//    trimming share to the approximation and 1/4 to the loop simplification (section 5.1);
//  - shareGap: where the faces of a sloppy edge are at most this far apart, they share one
//    vertex midway (off each surface by half of it); farther apart, each keeps its own.
// Guaranteed: surface + trimming + shareGap/2 = 0.6 + 0.25 + 0.1 = 0.95 of the tolerance; the
// last 0.05 is slack for what the bounds round (curve ends moved onto their vertices, fans of
// faces too thin for a cell).
struct ErrorBudget {
    double surface = 0;
    double lineApproximation = 0;
    double lineSimplification = 0;
    double shareGap = 0;

    static ErrorBudget of(double tolerance, ErrorMode mode) {
        ErrorBudget b;
        if (mode == ErrorMode::Guaranteed) {
            b.surface = 0.6 * tolerance;
            b.lineApproximation = 0.75 * 0.25 * tolerance;
            b.lineSimplification = 0.25 * 0.25 * tolerance;
            b.shareGap = 0.2 * tolerance;
        } else {
            b.surface = tolerance;
            b.lineApproximation = 0.75 * 0.75 * tolerance;
            b.lineSimplification = 0.25 * 0.75 * tolerance;
            b.shareGap = 0.5 * tolerance;
        }
        return b;
    }
};

}  // namespace nurbslod
