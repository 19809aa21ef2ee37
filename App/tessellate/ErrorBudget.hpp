#pragma once

#include <algorithm>

#include "tessellate/TessellationOptions.hpp"

namespace nurbslod {

// How the tolerance is shared between the error sources of a tessellation.
//  - surface: kd-tree cells (paper section 5.2);
//  - lineApproximation + lineSimplification: trimming curves to chords, gamma = 3/4 of the
//    trimming share to the approximation and 1/4 to the loop simplification (section 5.1);
//  - shareGap: where the faces of a sloppy edge are at most this far apart, they share one
//    vertex midway (off each surface by half of it); an edge's faces may widen that gap for
//    it (withShareGap, below). Farther apart, they share a point where their surfaces meet or
//    come within the share gap (SurfaceMeeting), if one lies within the edge's tolerance of
//    each face's own point; otherwise each keeps its own.
//
// What the verifier measures, per face and both ways: how far the face's triangles are from
// the exact trimmed face (deviation), and how far the exact face is from its triangles (cover).
//  - Inside the face a triangle over a kd-tree cell is within the cell's bound of the surface
//    (CellErrorBound), both ways: the surface share.
//  - At the boundary the triangles end at the chords of the trimming curves, within the
//    trimming share of the exact curve; a triangle with a chord as a side is within the surface
//    share of the surface piece it spans, whose border is within the trimming share of the
//    chord. Deviation (a chord bulging past the curve) and cover (the curve bulging past the
//    chord) each take at most the sum of the two.
//  - The edge's points are off the surface by at most shareGap/2 (one vertex for two sloppy
//    faces; the face's own gap, which is the widest of its edges'), which moves their triangles
//    by no more.
//  - A point shared where the surfaces meet also moves the face's boundary inside its surface,
//    by up to the edge's tolerance: the chords then run between the meeting points instead of
//    the trimming curve's points. That is not bounded by the shares above; it is what the B-rep
//    itself leaves open (the true edge lies within its tolerance of each trimming curve), and
//    the verifier and meshjudge allow it: at a face's boundary they count the distance to the
//    trimmed face less the largest tolerance of its edges, both ways. The distance to the
//    untrimmed surface, which they count in full, stays within the shares: the meeting point is
//    within shareGap/2 of it, and the chords between meeting points follow the curve where the
//    surfaces meet, which the chords' parameters were chosen for only through the trimming
//    curves. The verifier measures that sag; it is not proven.
// So guaranteed mode keeps, for every face,
//     surface + trimming + shareGap / 2 + openChords <= (1 - slack) tolerance,
// slack = 0.05 for what the bounds round (curve ends moved onto their vertices, fans of faces
// too thin for a cell, the weld of points 1e-2 T apart).
//
// Only the sum is fixed, so it is shared per face (forFace): the fixed split (surface 0.6,
// trimming 0.25, shareGap/2 0.1) is for a face that the kd-tree has to split; a face whose
// Bezier patches are already within `surfaceNeed` of any triangles over them (a plane: 0) takes
// that for its surface and gives the rest to its trimming curves (a plane: 0.84). A B-rep edge
// is discretised once for all its faces, so its chords take the smallest of its faces' trimming
// shares (ModelTessellator); a free edge its face's own.
//
// One face of an edge need not limit it: where its trimming curve is a straight line in (u, v)
// (CurveOnSurface::straightInParameterPlane; a cylinder's or a cone's circles), the surface
// maps each (u, v) chord onto the curve itself, so a triangle with that chord as a side is
// within the cell's bound of the exact face, both ways, as long as its corners are on the
// surface: the points that cell sides add to the chord are then put onto that surface (on the
// curve) instead of onto the 3D chord, and the face's sum is its surface share alone. The other
// faces see the edge as a finer polygon with every point on the curve.
//
// The share gap, too, is per face (widenShareGap): a sloppy edge whose faces are g apart, with
// the fixed shareGap < g, gets one vertex midway, g/2 off each surface (ModelTessellator measures
// g along the edge, as it places those vertices). Each face of that edge then spends g/2 on its
// shared points instead of shareGap/2 and gives the difference out of its trimming and surface
// shares, so its sum above still holds. The kd-tree and the chords are then finer on those faces
// only. A face keeps at least half of the fixed split's surface and trimming shares (or what
// it had, if less), which bounds g (largestShareGap); a farther edge keeps one point per face.
//
// The other way, a face whose edges' faces all meet closer than the fixed share gap (measured
// at the same samples and at its vertices, then checked at every point of its edges) narrows
// its gap to what they need, at least 0.005 T, and gives the half gap it frees to its surface
// and trimming shares (withNarrowerShareGap). The sum is unchanged again.
struct ErrorBudget {
    double surface = 0;
    double lineApproximation = 0;
    double lineSimplification = 0;
    double shareGap = 0;
    // What dropping the points cell sides leave on free edges' chords may change the triangles
    // by, beyond the half share gap that the removal may also spend (withFreeEdges).
    double openChords = 0;

    bool operator==(const ErrorBudget&) const = default;

    // The trimming share: the chord approximation and the loop simplification together.
    double trimming() const { return lineApproximation + lineSimplification; }

    // gamma = 3/4 of a trimming share to the chords, the rest to the simplification (paper
    // section 5.1).
    void setTrimming(double share) {
        lineApproximation = 0.75 * share;
        lineSimplification = 0.25 * share;
    }

    // The fixed split, for a face whose surface needs the kd-tree.
    static ErrorBudget of(double tolerance, ErrorMode mode) {
        ErrorBudget b;
        if (mode == ErrorMode::Guaranteed) {
            b.surface = 0.6 * tolerance;
            b.setTrimming(0.25 * tolerance);
            b.shareGap = 0.2 * tolerance;
        } else {
            b.surface = tolerance;
            b.setTrimming(0.75 * tolerance);
            b.shareGap = 0.5 * tolerance;
        }
        return b;
    }

    // The most a face's trimming curves can take: all but the share gap and the slack. In
    // approximate mode the paper's measure is an estimate, not a sum of bounds; a plane's chords
    // are measured exactly, so they may come as close to the tolerance as guaranteed mode's.
    static double largestTrimming(double tolerance, ErrorMode mode) {
        const ErrorBudget fixed = of(tolerance, mode);
        return mode == ErrorMode::Guaranteed ? 0.95 * tolerance - 0.5 * fixed.shareGap
                                             : 0.95 * tolerance;
    }

    // The split for a face whose every trimming curve is a straight line in (u, v) and whose
    // edges' points all lie on its own surface (ModelTessellator: it is each edge's curve use,
    // or the edge is exact and another face is its curve use, or the edge is an exact pole): a
    // whole cylinder, cone, sphere or torus. Its loop is exactly the region, every chord in
    // (u, v) maps onto the curve itself (a pole's chords onto the pole), and each boundary
    // segment lies on the side of one kd-tree cell, so its triangles at the boundary are within
    // their cells' bound of the exact face, both ways, like the others: it has no trimming
    // error, spends all but the half gap and the slack on its surface, and does not limit its
    // edges' chords. A cell at a pole is triangulated with the pole side collapsed
    // (triangulateCellAtPole): its corners are still all on the cell's sides.
    static ErrorBudget forChordsOnSurface(double tolerance, ErrorMode mode) {
        ErrorBudget b = of(tolerance, mode);
        if (mode != ErrorMode::Guaranteed) return b;
        b.surface = 0.95 * tolerance - 0.5 * b.shareGap;
        b.setTrimming(0);
        return b;
    }

    // The share gap this face can take, giving out of its trimming and surface shares all but
    // the floors above (guaranteed mode; the approximate one keeps its fixed gap).
    double largestShareGap(double tolerance, ErrorMode mode) const {
        if (mode != ErrorMode::Guaranteed) return shareGap;
        const ErrorBudget fixed = of(tolerance, mode);
        const double room = std::max(0.0, surface - 0.5 * fixed.surface) +
                            std::max(0.0, trimming() - 0.5 * fixed.trimming());
        return shareGap + 2 * room;
    }

    // This face with share gap `gap` (at most largestShareGap): the extra half gap comes first
    // out of what the trimming got beyond the fixed split (a plane's widened chords), then out
    // of the surface and trimming shares in proportion to their room above the floors. The sum
    // surface + trimming + shareGap / 2 is unchanged.
    ErrorBudget withShareGap(double gap, double tolerance, ErrorMode mode) const {
        ErrorBudget b = *this;
        double extra = 0.5 * (gap - shareGap);
        if (!(extra > 0) || mode != ErrorMode::Guaranteed) return b;
        const ErrorBudget fixed = of(tolerance, mode);
        const double widened = std::min(extra, std::max(0.0, b.trimming() - fixed.trimming()));
        b.setTrimming(b.trimming() - widened);
        extra -= widened;
        const double surfaceRoom = std::max(0.0, b.surface - 0.5 * fixed.surface);
        const double trimmingRoom = std::max(0.0, b.trimming() - 0.5 * fixed.trimming());
        double given = widened;
        if (extra > 0 && surfaceRoom + trimmingRoom > 0) {
            // never below the floors: a gap beyond largestShareGap is cut to it
            const double take = std::min(1.0, extra / (surfaceRoom + trimmingRoom));
            b.surface -= take * surfaceRoom;
            b.setTrimming(b.trimming() - take * trimmingRoom);
            given += take * (surfaceRoom + trimmingRoom);
        }
        b.shareGap = shareGap + 2 * given;
        return b;
    }

    // This face with a share gap narrower than its own, `gap`: every shared point of its edges
    // and vertices is measured within gap/2 of the face's own points (ModelTessellator). The
    // half gap it no longer spends goes to its surface and trimming shares in proportion to
    // them, so the sum surface + trimming + shareGap / 2 is unchanged. Most edges of a file
    // meet far closer than the fixed share gap (trj7_b1-ec-214.stp at relative 1e-4: 312 of
    // its 415 faces under 0.05 T), which otherwise spend a tenth of the tolerance on it.
    // Guaranteed mode only: the approximate one keeps its fixed gap.
    ErrorBudget withNarrowerShareGap(double gap, ErrorMode mode) const {
        ErrorBudget b = *this;
        const double shares = surface + trimming();
        if (mode != ErrorMode::Guaranteed || !(gap >= 0) || !(gap < shareGap) || !(shares > 0))
            return b;
        const double freed = 0.5 * (shareGap - gap);
        b.surface += freed * surface / shares;
        b.setTrimming(trimming() + freed * trimming() / shares);
        b.shareGap = gap;
        return b;
    }

    // A face with a free edge (an edge of no other face) in guaranteed mode. Every chord of a
    // free edge is an open edge of the mesh, and so is every point that a kd-tree cell side
    // leaves on it and removeOpenBoundaryPoints cannot drop. Such a face moves surface share to
    // its trimming share, up to kFreeEdgeTrimming of the tolerance (longer chords, fewer open
    // edges), and then up to kOpenChords to the removal of those points (openChords), so that
    // the points the smaller cells leave on the longer chords still go. The sum is unchanged,
    // and the surface keeps at least half of the fixed split's share (the floor withShareGap
    // keeps too); a face below it gives nothing. wing.brep at relative 1e-4, whose four free
    // edges are all its open edges: 133 -> 98 (BRepMesh at the same deflection: 100), with
    // 4,439 -> 7,610 triangles (BRepMesh: 18,402).
    ErrorBudget withFreeEdges(double tolerance, ErrorMode mode) const {
        constexpr double kFreeEdgeTrimming = 0.45, kOpenChords = 0.05;
        ErrorBudget b = *this;
        if (mode != ErrorMode::Guaranteed) return b;
        const double floor = 0.5 * of(tolerance, mode).surface;
        const double toTrimming =
            std::min(std::max(0.0, b.surface - floor),
                     std::max(0.0, kFreeEdgeTrimming * tolerance - b.trimming()));
        b.surface -= toTrimming;
        b.setTrimming(b.trimming() + toTrimming);
        const double toOpenChords =
            std::min(kOpenChords * tolerance, std::max(0.0, b.surface - floor));
        b.surface -= toOpenChords;
        b.openChords += toOpenChords;
        return b;
    }

    // The split for one face whose triangles are within `surfaceNeed` of its surface without
    // any kd-tree split beyond the Bezier spans (faceSurfaceNeed; a plane: 0). In guaranteed
    // mode the surface share keeps a margin of 1e-2 of the tolerance over that need, so that
    // rounding never makes the kd-tree split a plane, and the rest goes to the chords. Where the
    // need is more than the fixed surface share, the kd-tree splits, and the fixed split holds.
    static ErrorBudget forFace(double tolerance, ErrorMode mode, double surfaceNeed) {
        ErrorBudget b = of(tolerance, mode);
        const double surface = surfaceNeed + 1e-2 * tolerance;
        if (!(surfaceNeed >= 0) || surface >= b.surface) return b;
        if (mode == ErrorMode::Guaranteed) {
            b.surface = surface;
            b.setTrimming(std::max(b.trimming(), largestTrimming(tolerance, mode) - surface));
        } else if (surfaceNeed <= 0.05 * tolerance) {
            // The approximate sources are not added (the surface share is the whole tolerance):
            // only a face whose surface is all but flat gives its chords the largest share, and
            // it keeps its surface share. Held to its need, such a face's kd-tree cut its cells
            // down to that need: the sides of the letters raised 0.002 mm on FreeCAD's IDF chip
            // packages (ruled faces along B-spline outlines) took four times guaranteed mode's
            // columns, 1206_SMD.stp at relative 1e-3 2,564 triangles instead of 1,180
            // (guaranteed mode: 1,196).
            b.setTrimming(largestTrimming(tolerance, mode));
        }
        return b;
    }
};

}  // namespace nurbslod
