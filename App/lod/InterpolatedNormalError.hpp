#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "tessellate/Mesh.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod::gui {

// The normal error of a face's mesh as the display shows it (paper appearance, section 4.1):
// the viewer draws the exact normals of the corners interpolated across each triangle
// (Gouraud or Phong shading), n_bilin = sum(lambda_i n_i) / |sum(lambda_i n_i)|, eq. (2),
// and the error is the angle between n_bilin and the exact normal n of the surface at the
// same (u, v), sum(lambda_i (u_i, v_i)).
//
// Why it is second order (the bound the level choice relies on): n(u, v) is smooth inside a
// face, so eq. (1), n'(d) = n + [n_u n_v] d, is exact to first order and the linear
// interpolation of n over a triangle of parameter corners p_i errs by
//     |n(p) - sum(lambda_i n(p_i))| <= 1/2 sum(lambda_i |p_i - p|^2) max|D^2 n|,
// the interpolation error of a linear element, and the angle between a unit vector n and a
// vector l is at most asin(|n - l|). A level of tolerance delta has triangles of size h with
// delta ~ kappa h^2 / 8 (the sagitta of a chord where the surface bends with curvature
// kappa), so the interpolated normal's error is proportional to delta: it halves from one
// level to the next, while the facet normal's (a difference quotient, first order in h)
// only shrinks by sqrt(2). In the paper's distance form the angle is eps_shading =
// |n - n_bilin| / max(c_u, c_v); the preference bounds the angle itself, which does not
// depend on the view.
struct InterpolatedNormalError {
    double maxDeg = 0;              // largest angle over the samples of every triangle with an area
    int triangles = 0;              // triangles measured (the ones with an area)
    std::size_t worstTriangle = 0;  // where maxDeg was measured (for a diagnosis)
    Point2 worstParameter = Point2::Zero();
};

// Measures the mesh of `face`: mesh.parameters holds each normal's (u, v), and mesh.normals
// the exact normals drawn at the corners (at a pole, the limit normal that
// BSplineSurface::normal takes), turned outwards like the tessellator's for a reversed face.
// Samples every triangle at its centroid and on a barycentric grid of `steps` steps per edge,
// corners left out: the drawn normal there is the exact one, or at a (nearly) collapsed
// corner the triangle's own (CollapsedCornerNormals), where the exact normal is that of a
// sliver far narrower than the triangle or has no limit at all. The error's maximum inside a
// triangle is not at a fixed point (it is where the second derivatives of n put it), so a
// few samples under-read it on large triangles: on the corpus (trj7) and the sample model,
// centroid and edge midpoints alone read up to 11 times low, 3 steps up to 1.5 times, 4
// steps (the default) up to 1.22 times, against 12 steps. Triangles without area (a pole's
// fan, a snapped cut) draw no pixel and are left out. Zeros for a mesh without triangles or
// without parameters.
//
// Where the tessellator's (u, v) of a corner do not place the triangle in parameter space,
// the corner's are mended first: on a closed surface a seam vertex carries one side's
// parameter (the triangle's corners are moved to one side), and a pole vertex one of the
// many parameters of the collapsed row (the sample takes the other corners' there).
InterpolatedNormalError measureInterpolatedNormalError(const Mesh& mesh, const TrimmedSurface& face,
                                                       int steps = 4);

// The samples of the measure, one triangle at a time (for choosing a corner's normal). Holds
// references to the mesh and the face; normals added to the mesh later (and changed) are read
// too.
class InterpolatedNormalSampler {
public:
    InterpolatedNormalSampler(const Mesh& mesh, const TrimmedSurface& face);
    // The angle in radians at barycentric `weights` of triangle t, with the (u, v) of the
    // sample (seams and poles mended as described above).
    double angle(std::size_t t, const std::array<double, 3>& weights, Point2* sample) const;
    // The largest angle in degrees over the samples of triangle t (centroid and the grid).
    double triangleMaxDeg(std::size_t t, int steps = 4) const;

private:
    int collapsedAt(std::uint32_t normal) const;
    const Mesh& mesh_;
    const TrimmedSurface& face_;
    double outwards_ = 1;
    std::array<double, 2> low_{}, period_{};
    std::array<bool, 2> closed_{};
    // by normal index, of the normals the mesh had when the sampler was made; -1: not yet known
    mutable std::vector<signed char> collapsed_;
};

}  // namespace nurbslod::gui
