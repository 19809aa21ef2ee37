#pragma once

#include "geometry/BSplineSurface.hpp"
#include "tessellate/Mesh.hpp"

namespace nurbslod::gui {

// The normal error a face's mesh shows, measured: the largest angle in degrees between a
// triangle's facet normal and the exact surface normals at its corners (the tessellator's
// per-vertex normals).
struct FacetNormalError {
    double maxDeg = 0;  // over every triangle not thinner than the tolerance
    // Over the interior triangles: no corner on the mesh's border (the trimming loops) and
    // every corner on the surface (within 1e-3 of the tolerance). The tessellator fills the
    // cells that a trimming loop cuts with triangles shaped by the loop, some long and thin,
    // whose plane a distance tolerance does not hold to the surface's; and it puts a vertex
    // where an edge's chord meets its kd-tree grid on the chord, up to the tolerance off the
    // surface, which next to a pole or a seam, where the triangles are tiny, tilts them more
    // than the curvature does. The curvature rule (ShadingTolerance) bounds the rest.
    double interiorMaxDeg = 0;
};

// Measures the mesh of one face of `surface` (mesh.parameters holds each vertex's (u, v)),
// tessellated within `tolerance`. Triangles thinner than the tolerance (smallest altitude)
// are left out: the tessellator fills a T-junction with a triangle of three nearly collinear
// vertices, whose plane is that of the iso-curve they lie on, not the surface's; drawn at a
// level of that tolerance it is narrower than the screen-space error, below half a pixel.
// Zeros for a mesh without triangles.
FacetNormalError measureFacetNormalError(const Mesh& mesh, const BSplineSurface& surface,
                                         double tolerance);

}  // namespace nurbslod::gui
