#pragma once

#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/TessellationOptions.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {

// The surface error a face's triangles reach when the kd-tree splits it only at its Bezier
// span borders: the largest cell bound (CellErrorBound, the trimmed-cell bound in guaranteed
// mode, the paper's estimate in approximate mode) over the face's Bezier patches, each
// restricted to the bounding box of the trimming curves' control points (which holds the
// curves: positive weights). A plane gives 0; a face that the kd-tree has to split gives a value
// above `cap`, returned as soon as one patch shows it (the rest is not measured). ErrorBudget::
// forFace gives what a face does not need for its surface to its trimming curves.
// patches, where given, are the face's (FaceSurfaceCache); otherwise they are made here.
double faceSurfaceNeed(const TrimmedSurface& face, ErrorMode mode, double cap,
                       const BezierPatchGrid* patches = nullptr);

// About how many kd-tree cells the face's surface takes at surface share `share`: the bound
// falls with the square of a cell's sides (paper section 5.2), so a patch whose bound is e
// takes about e / share cells, at least one. Over the same patches as faceSurfaceNeed; 0 where
// they are not known. Only for comparing faces and shares, not a count.
double surfaceCellEstimate(const TrimmedSurface& face, ErrorMode mode, double share,
                           const BezierPatchGrid* patches = nullptr);

}  // namespace nurbslod
